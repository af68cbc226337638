"""The session follower, the virtual keypad and the controller, stepped from Python."""

import can
import pytest

import powerkey
from conftest import parse_candump


def _frames(path):
    for line in path.read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            yield parse_candump(line)


def test_session_decodes_like_decode(repo):
    # Every event's message is decode()'s for the node the session followed.
    s = powerkey.Session(model="pk1000")
    for ident, data, ext in _frames(repo / "examples/logs/check-clean.log"):
        e = s.step(ident, data, extended=ext)
        if e.message is not None:
            assert e.message == powerkey.decode(ident, data, model="pk1000", node=e.node,
                                                extended=ext)
        else:
            with pytest.raises(powerkey.DecodeError) as err:
                powerkey.decode(ident, data, model="pk1000", node=e.node, extended=ext)
            assert err.value.code == e.error
    assert s.model == powerkey.Model.pk1000


def run(start, steps, keypad, controller, until):
    """Both roles on one simulated bus, 1 ms a step from `start`, until until() holds; returns
    the controller's events and the time reached."""
    events = []
    t = start
    for t in range(start, start + steps):
        keypad.advance(t)
        for f in keypad.transmit_all():
            controller.step(f, t)
        controller.tick(t)
        for f in controller.frames():
            keypad.receive(f, t)
        for e in controller.events():
            events.append(e)
            if e.kind == "key_pressed":
                controller.set_led(e.key, "green")
        if until(events):
            break
    return events, t


@pytest.mark.parametrize("model", powerkey.names("model"))
def test_controller_sets_up_the_keypad_and_lights_a_pressed_key(model):
    keypad = powerkey.VirtualKeypad(model=model)
    controller = powerkey.Controller(
        model=model,
        configuration=[powerkey.message("sdo_write", object="led_brightness", level=0x30)],
    )
    keypad.power_on(0)
    events, t = run(0, 2000, keypad, controller, lambda ev: any(e.kind == "ready" for e in ev))
    assert controller.state == "running"
    events, t = run(t + 1, 50, keypad, controller, lambda ev: False)  # the NMT start arrives
    assert keypad.state == "operational" and keypad.brightness == 0x30

    assert keypad.press(3, t)
    events, t = run(t + 1, 500, keypad, controller, lambda ev: 3 in keypad.led_on["green"])
    assert [e.key for e in events if e.kind == "key_pressed"] == [3]
    assert keypad.led_on["green"] == [3] and controller.led_on["green"] == [3]


def test_keypad_alone():
    k = powerkey.VirtualKeypad(model="pkp2400", node=0x20)
    assert k.state == "off"
    k.power_on(0)
    boot = k.transmit_all()
    assert boot and powerkey.decode(boot[0], model="pkp2400", node=0x20).reported_nmt_state() == "boot_up"
    assert k.state == "pre_operational" and k.node == 0x20
    k.receive(powerkey.encode("nmt", model="pkp2400", node=0x20, command="start"), 1)
    assert k.state == "operational"
    k.receive(powerkey.encode("led_on", model="pkp2400", node=0x20, red=[1, 2]), 2)
    assert k.led_on["red"] == [1, 2]
    assert k.press(5, 3)
    sent = [powerkey.decode(f, model="pkp2400", node=0x20) for f in k.transmit_all()]
    assert [m.pressed_keys() for m in sent if m.kind == "key_state"] == [[5]]
    assert isinstance(k.read("led_brightness"), int)


def test_keypad_sold_as_j1939_at_another_address():
    # A PKP-2400-LI from power-on in J1939 at 30h (docs/virtual-keypad.md#j1939): its frames are
    # the J1939 manuals' with the source address 30h, the identifier byte staying 21h.
    k = powerkey.VirtualKeypad(model="pkp2400", start_in_j1939=True, j1939_address=0x30)
    k.power_on(0)
    assert k.state == "j1939"
    assert k.transmit_all() == []
    assert k.press(8, 50)
    sent = k.transmit_all()
    assert [(f.arbitration_id, f.is_extended_id, bytes(f.data).hex().upper()) for f in sent] == [
        (0x18EFFF30, True, "041B01080121FFFF")]
    m = powerkey.decode(sent[0], model="pkp2400", address=0x30)
    assert m.kind == "j1939_key_contact" and m.pressed_keys() == [8]
    for bad in (0, 0xFE, 0x100, "00h", "FEh", "x"):
        with pytest.raises(powerkey.ArgumentError):
            powerkey.VirtualKeypad(model="pkp2400", start_in_j1939=True, j1939_address=bad)
    # The tool's text of --address too, as node= takes --node's.
    k = powerkey.VirtualKeypad(model="pkp2400", start_in_j1939=True, j1939_address="30h")
    k.power_on(0)
    assert k.press(8, 50) and k.transmit_all()[0].arbitration_id == 0x18EFFF30


def test_keypad_in_j1939_shows_its_leds():
    # A PKP-2600-SI in J1939 at 30h: the single-LED command to it (PKP2600SI J1939 manual 7a's
    # layout: LED 3 green, on, no secondary colour) shows as its J1939 LED, not in led_on.
    k = powerkey.VirtualKeypad(model="pkp2600si", start_in_j1939=True, j1939_address=0x30)
    k.power_on(0)
    assert k.j1939_address == 0x30 and k.j1939_leds == {}
    k.receive(can.Message(arbitration_id=0x18EF3000, is_extended_id=True,
                          data=bytes.fromhex("041B0103020100FF")), 10)
    assert k.j1939_leds == {3: {"mode": "on", "colour": "green", "secondary": "off"}}
    assert k.led_on == {} or all(not v for v in k.led_on.values())
    # A command to another address is not this keypad's.
    k.receive(can.Message(arbitration_id=0x18EF2100, is_extended_id=True,
                          data=bytes.fromhex("041B0104010100FF")), 20)
    assert list(k.j1939_leds) == [3]
