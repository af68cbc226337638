"""Hostile arguments (issue 26): TypeError for the wrong type, a ValueError naming the real range
for a value outside it, however large; colours the keypad has not got refused; times modulo 2^32
as docs/python.md says."""

import pytest

import powerkey


@pytest.mark.parametrize("ident", [2**64, 2**29, -1])
def test_a_frame_id_outside_29_bits_is_a_decode_error(ident):
    with pytest.raises(powerkey.DecodeError, match=r"outside 0\.\.0x1FFFFFFF"):
        powerkey.decode((ident, b"\x01"), model="pk1000")


class Msg:  # what python-can's can.Message looks like to the module
    def __init__(self, arbitration_id, data=b"\x01", **flags):
        self.arbitration_id = arbitration_id
        self.data = data
        for k, v in flags.items():
            setattr(self, k, v)


@pytest.mark.parametrize(
    "frame",
    [
        Msg("0x195"),
        Msg(0x195, is_extended_id="yes"),
        Msg(0x195, is_remote_frame=2),
        Msg(0x195, is_fd=None),
        (0x195, b"\x01", "no"),
        (0x195, 5),
        (0x195, "ab"),
    ],
)
def test_odd_types_in_a_frame_are_type_errors(frame):
    with pytest.raises(TypeError):
        powerkey.decode(frame, model="pk1000")


def test_a_flag_may_be_0_or_1():
    assert powerkey.decode(Msg(0x195, b"\x01\x00\x00\x00\x00", is_extended_id=0),
                           model="pk1000").pressed_keys() == [1]


def test_field_ranges_are_the_real_ones():
    with pytest.raises(powerkey.EncodeError) as e:
        powerkey.encode("sdo_write", model="pk1000", object="heartbeat_time", period_ms=2**64)
    # The field's own range (a 32-bit number), not 0..2**64-1; in it, the model's range.
    assert str(e.value).endswith("period_ms: 18446744073709551616 is outside 0..4294967295")
    with pytest.raises(powerkey.EncodeError, match=r"period_ms: 65536 is more than a pk1000 takes \(0\.\.65535\)"):
        powerkey.encode("sdo_write", model="pk1000", object="heartbeat_time", period_ms=65536)
    with pytest.raises(powerkey.EncodeError, match=r"command: .* is not what a pk1000 takes \(start, stop"):
        powerkey.encode("nmt", model="pk1000", command=3)
    with pytest.raises(powerkey.EncodeError, match=r"red: .*outside 1\.\.32"):
        powerkey.encode("led_on", model="pk1000", red=[99], green=[1])


def test_ints_of_any_size_in_the_roles():
    k = powerkey.VirtualKeypad(model="pk1000")
    k.power_on(2**64 + 5)  # modulo 2^32, as documented
    assert k.state == "pre_operational"
    k.advance(-1)  # 2^32 - 1
    assert k.press(2**64, 1) is False  # a key the model lacks: False, as in C++
    with pytest.raises(TypeError):
        k.advance("1")
    with pytest.raises(TypeError):
        k.press(1.0, 1)
    with pytest.raises(powerkey.ArgumentError, match=r"outside 0\.\.2147483647 ms"):
        k.silence(0, 2**31)
    with pytest.raises(powerkey.ArgumentError, match=r"outside 0\.\.4294967295"):
        k.drop_received(2**64)
    with pytest.raises(powerkey.ArgumentError, match=r"outside 0\.\.65535 ms"):
        powerkey.Controller(model="pk1000", keypad_heartbeat=65536)
    with pytest.raises(powerkey.ArgumentError, match=r"outside 0\.\.255"):
        powerkey.Controller(model="pk1000", sdo_retries=256)
    with pytest.raises(TypeError):
        powerkey.Controller(model="pk1000", lost_after=1.5)


def test_colours_the_keypad_has_not_got_are_refused():
    c = powerkey.Controller(model="pk1000")  # red and green planes
    assert c.set_led(1, "amber")
    assert c.led_on["red"] == [1] and c.led_on["green"] == [1]
    for no in ("blue", "white", "cyan"):
        with pytest.raises(powerkey.ArgumentError, match=r"shows no .*\(off, red, green, amber\)"):
            c.set_led(1, no)
    with pytest.raises(powerkey.ArgumentError, match=r"names none of"):
        c.set_led(1, 99)  # it returned True and turned the LED off
    with pytest.raises(powerkey.ArgumentError):
        c.set_led(1, 2**64)
    assert c.led_on["red"] == [1]  # unchanged
    with pytest.raises(powerkey.ArgumentError, match=r"has no blue LEDs"):
        c.set_leds({"blue": [1]})
    with pytest.raises(powerkey.ArgumentError, match=r"has no LED 29"):
        c.set_leds({"red": [29]})
    assert c.set_led(99, "red") is False  # an LED it lacks: False, as in C++


def test_a_long_configuration_numbers_every_entry():
    # 300 entries: step wrapped at 256; every entry is a refusal event here (2014h is not a
    # PKP-2400's), numbered 0..299.
    entry = powerkey.message("sdo_write", object="startup_show", startup_show="disabled")
    c = powerkey.Controller(model="pkp2400", identify=False, keypad_heartbeat=0, lost_after=0,
                            configuration=[entry] * 300)
    steps = []
    c.step((0x715, b"\x00"), 0)
    for t in range(1, 50):
        steps += [e.step for e in c.events() if e.kind == "sdo_refused"]
        c.tick(t)
    steps += [e.step for e in c.events() if e.kind == "sdo_refused"]
    assert steps == list(range(300))
    with pytest.raises(powerkey.ArgumentError, match=r"65535"):
        powerkey.Controller(model="pk1000", configuration=[entry] * 65536)
