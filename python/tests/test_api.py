"""The Python surface: arguments, errors, messages, the Listener. The codec's answers themselves
are checked against the C++ library in test_rows.py and test_tool_json.py."""

import time

import can
import pytest

import powerkey

KEY3 = (0x195, bytes.fromhex("040000002A"))  # the README's key state: key 3 of a PKP-2400


def test_can_message_and_id_bytes_agree():
    msg = can.Message(arbitration_id=KEY3[0], data=KEY3[1], is_extended_id=False)
    a = powerkey.decode(msg, model="pkp2400")
    b = powerkey.decode(*KEY3, model="pkp2400")
    assert a == b and a.kind == b.kind and a.to_dict() == b.to_dict()
    assert a.model == powerkey.Model.pkp2400 and a.node == 0x15


def test_model_by_name_enum_and_manual_name():
    ms = [powerkey.decode(*KEY3, model=m)
          for m in ("pkp2400", powerkey.Model.pkp2400, "PKP-2400-LI", "PKP-2400")]
    assert all(m == ms[0] for m in ms)
    enum_names = [m.name for m in powerkey.Model.__members__.values()]
    assert powerkey.names("model") == enum_names
    assert powerkey.parse_model("PKP-2400-LI") == powerkey.Model.pkp2400
    assert powerkey.model_info("pkp2400")["model"] == "pkp2400"


def test_names_of_every_listed_enum():
    # Values the manuals name, one per enum: the table behind names() lists each enum whole.
    expect = {"model": "pkp3500mt", "object": "led_brightness", "errc": "unknown_object",
              "colour": "green", "backlight_colour": "white", "led_state": "red_on",
              "baud_rate": "kbit_125", "nmt_command": "start", "nmt_state": "operational",
              "command_code": "set_led_state", "event_kind": "key_pressed"}
    for enum, name in expect.items():
        names = powerkey.names(enum)
        assert name in names, enum
        assert len(names) == len(set(names)), enum
    with pytest.raises(powerkey.ArgumentError) as e:
        powerkey.names("colours")
    assert "'colours'" in str(e.value) and "backlight_colour" in str(e.value)


def test_unknown_model_is_an_argument_error():
    with pytest.raises(powerkey.ArgumentError) as e:
        powerkey.decode(*KEY3, model="pkp9999")
    assert isinstance(e.value, powerkey.Error) and isinstance(e.value, ValueError)
    assert e.value.code == "value_out_of_range"
    with pytest.raises(TypeError):
        powerkey.decode(*KEY3, model=3.5)


def test_decode_errors_name_the_errc():
    with pytest.raises(powerkey.DecodeError) as e:
        powerkey.decode(KEY3[0], KEY3[1][:2], model="pkp2400")
    assert isinstance(e.value, powerkey.Error)
    assert e.value.code in powerkey.names("errc")
    assert e.value.code in str(e.value)


def test_node():
    other = powerkey.decode(0x196, KEY3[1], model="pkp2400", node=0x16)
    assert other.keys == powerkey.decode(*KEY3, model="pkp2400").keys
    with pytest.raises(powerkey.DecodeError) as e:
        powerkey.decode(0x196, KEY3[1], model="pkp2400")  # another node's frame
    assert e.value.code in powerkey.names("errc")
    with pytest.raises(powerkey.ArgumentError):
        powerkey.decode(*KEY3, model="pkp2400", node=0x80)


def test_remote_fd_and_error_frames_carry_no_message():
    frames = {
        "remote frame": can.Message(arbitration_id=0x195, is_remote_frame=True,
                                    is_extended_id=False, dlc=5),
        "CAN FD frame": can.Message(arbitration_id=0x195, is_fd=True, is_extended_id=False,
                                    data=KEY3[1]),
        "error frame": can.Message(arbitration_id=0x195, is_error_frame=True,
                                   is_extended_id=False, data=bytes(8)),
    }
    for kind, msg in frames.items():
        assert powerkey.skipped_kind(msg) == kind
        with pytest.raises(powerkey.DecodeError) as e:
            powerkey.decode(msg, model="pkp2400")
        assert e.value.code == "unexpected_frame"
        with pytest.raises(powerkey.DecodeError):
            powerkey.Session(model="pkp2400").step(msg)
    # The Listener counts them by kind, as the tool does, and decodes the rest.
    got = []
    listener = powerkey.Listener(model="pkp2400", callback=lambda m, e: got.append(e))
    for msg in [*frames.values(), frames["remote frame"],
                can.Message(arbitration_id=KEY3[0], data=KEY3[1], is_extended_id=False)]:
        listener.on_message_received(msg)
    assert listener.skipped == {"remote frame": 2, "CAN FD frame": 1, "error frame": 1}
    assert [e.message.kind for e in got] == ["key_state"]


def test_fields_attributes_and_dict():
    m = powerkey.decode(*KEY3, model="pkp2400")
    assert m.kind == "key_state"
    assert {name: getattr(m, name) for name in m.to_dict()} == m.to_dict()
    assert set(m.to_dict()) <= set(dir(m))
    with pytest.raises(AttributeError):
        m.no_such_field
    assert m.pressed_keys() == powerkey.pressed_keys(m) == m.keys
    assert "key_state" in repr(m)
    assert isinstance(m.describe(), str)


def test_encode_round_trip_and_message_objects():
    m = powerkey.decode(*KEY3, model="pkp2400")
    f = powerkey.encode(m.kind, model="pkp2400", **m.to_dict())
    assert isinstance(f, can.Message) and not f.is_extended_id
    assert (f.arbitration_id, bytes(f.data)) == KEY3
    assert powerkey.encode_frame(m) == (KEY3[0], KEY3[1], False)
    built = powerkey.message("key_state", **m.to_dict())
    assert built == m
    assert bytes(powerkey.encode(built, model="pkp2400").data) == KEY3[1]
    with pytest.raises(powerkey.ArgumentError):
        powerkey.encode(built)  # a built message has no model: give model=


def test_encode_argument_errors():
    with pytest.raises(powerkey.ArgumentError):
        powerkey.encode("no_such_kind", model="pkp2400")
    with pytest.raises(powerkey.ArgumentError):
        powerkey.encode("led_on", model="pkp2400", purple=[1])
    with pytest.raises(powerkey.EncodeError) as e:
        powerkey.encode("led_brightness", model="pk1000", level=64)
    assert e.value.code == "value_out_of_range"
    with pytest.raises(powerkey.EncodeError) as e:
        powerkey.encode("led_on", model="pkp2400", green=[33])
    assert e.value.code == "value_out_of_range"
    with pytest.raises(powerkey.ArgumentError):
        powerkey.encode("nmt", model="pkp2400", command="jump")
    with pytest.raises(powerkey.ArgumentError):
        powerkey.encode("led_on", model="pkp2400", green="a")


def tool_error(code="value_out_of_range", **kw):
    """The text of the EncodeError of encode(**kw); its code is the errc encode() returned."""
    with pytest.raises(powerkey.EncodeError) as e:
        powerkey.encode(**kw)
    assert e.value.code == code
    return str(e.value)


def test_encode_errors_speak_as_the_tool():
    # The tool: powerkey: encode: led_on: red: '5' is more than a pkp2200 takes (1..4)
    assert tool_error(kind="led_on", model="pkp2200", red=[5]) == \
        "led_on: red: [5] is more than a pkp2200 takes (1..4)"
    assert tool_error(kind="led_on", model="pk1000", red="29") == \
        "led_on: red: [29] is more than a pk1000 takes (1..28)"
    # The tool: powerkey: encode: led_brightness: level: 99 is outside 00h..3Fh
    assert tool_error(kind="led_brightness", model="pk1000", level=99) == \
        "led_brightness: level: 99 is outside 00h..3Fh"
    assert tool_error(kind="sdo_write", model="pk1000", object="led_brightness", level="99") == \
        "sdo_write: level: 99 is outside 00h..3Fh"
    assert tool_error(kind="nmt", model="pk1000", target=128) == "nmt_message: target: 128 is outside 00h..7Fh"
    assert tool_error(kind="encoder_state", model="pk1000", ticks=3, code="wrong_id") == \
        "encoder_state is not a message of a pk1000"


def test_kind_and_number_spellings_of_the_tool():
    want = powerkey.encode("led_on", model="pkp2400", red=[1, 7], blue=[3])
    for kw in ({"red": "1,7", "blue": "3"}, {"red": "1 7", "blue": [3]}):
        got = powerkey.encode("led-on", model="pkp2400", **kw)
        assert bytes(got.data) == bytes(want.data)
    assert bytes(powerkey.encode("led_on", model="pk1000", red="1-28").data) == \
        bytes.fromhex("FFFFFF0F00000000")
    for node in (0x3A, "3Ah", "0x3A", "58"):
        f = powerkey.encode("sdo_write", model="pk1000", node=node, object="node_id",
                            node_id="3Ah")
        assert (f.arbitration_id, bytes(f.data)) == (0x63A, bytes.fromhex("2F1320003A000000"))
    assert powerkey.decode(0x195, KEY3[1], model="pkp2400", node="15h").keys == [3]
    with pytest.raises(powerkey.DecodeError):
        powerkey.decode(*KEY3, model="pkp2400", node="15")  # decimal, as the tool reads it: 0Fh
    with pytest.raises(powerkey.ArgumentError):
        powerkey.decode(*KEY3, model="pkp2400", node="fifteen")
    with pytest.raises(powerkey.ArgumentError):
        powerkey.decode(*KEY3, model="pkp2400", node="80h")


def test_extended_id_hint():
    # python-can makes a frame extended unless told otherwise.
    msg = can.Message(arbitration_id=KEY3[0], data=KEY3[1])
    assert msg.is_extended_id
    with pytest.raises(powerkey.DecodeError) as e:
        powerkey.decode(msg, model="pkp2400")
    assert e.value.code == "wrong_id"  # a J1939 frame on PGN 0000h: not a keypad frame
    assert "is_extended_id=False" in str(e.value) and "195h is key_state" in str(e.value)
    # No hint for a frame that would not decode as standard either.
    with pytest.raises(powerkey.DecodeError) as e:
        powerkey.decode(can.Message(arbitration_id=0x7E5, data=b"\x4c"), model="pkp2400")
    assert "is_extended_id" not in str(e.value)


def test_enum_fields_take_names_and_numbers():
    by_name = powerkey.encode("nmt", model="pk1000", command="start")
    by_number = powerkey.encode("nmt", model="pk1000", command=1)
    assert bytes(by_name.data) == bytes(by_number.data)
    # the NMT target defaults to the node, as the tool's encode
    assert bytes(powerkey.encode("nmt", model="pk1000", node=0x20, command="start").data)[1] == 0x20


def test_every_kind_builds_with_defaults():
    for kind in powerkey.kinds():
        assert powerkey.message(kind).kind == kind


def test_listener_on_a_notifier():
    channel = f"powerkey-test-{time.monotonic_ns()}"
    sender = can.Bus(interface="virtual", channel=channel)
    receiver = can.Bus(interface="virtual", channel=channel)
    listener = powerkey.Listener(model="pkp2400")
    notifier = can.Notifier(receiver, [listener])
    try:
        sender.send(can.Message(arbitration_id=KEY3[0], data=KEY3[1], is_extended_id=False))
        sender.send(can.Message(arbitration_id=0x195, data=b"\x04", is_extended_id=False))
        msg, event = listener.get_message(timeout=2.0)
        assert msg.arbitration_id == KEY3[0]
        assert event.message == powerkey.decode(*KEY3, model="pkp2400")
        assert event.error is None and event.function == "tpdo1" and event.node == 0x15
        msg, event = listener.get_message(timeout=2.0)
        assert event.message is None and event.error in powerkey.names("errc")
        assert listener.get_message(timeout=0.05) is None
    finally:
        notifier.stop()
        sender.shutdown()
        receiver.shutdown()


def test_listener_callback():
    got = []
    listener = powerkey.Listener(model="pkp2400", callback=lambda m, e: got.append(e))
    listener.on_message_received(can.Message(arbitration_id=KEY3[0], data=KEY3[1],
                                             is_extended_id=False))
    assert got[0].message.kind == "key_state"


# --- J1939: can.Message with is_extended_id=True (docs/j1939.md, PKP1600SI J1939 manual) ---------

def test_j1939_key_contact_from_a_can_message():
    msg = can.Message(arbitration_id=0x18EFFF21, data=bytes.fromhex("041B01030121FFFF"),
                      is_extended_id=True)
    m = powerkey.decode(msg, model="pkp1600si")
    assert m.kind == "j1939_key_contact"
    assert m.to_dict() == {"priority": 6, "destination": 0xFF, "source": 0x21, "key": 3,
                           "pressed": True, "identifier": 0x21}
    assert m.pressed_keys() == [3] and powerkey.pressed_keys(m) == [3]
    assert powerkey.key_change(m) == {"pressed": [3], "covered": [3]}
    assert m.describe() == ("node 15h  J1939 key contact  priority: 6  destination: FFh  "
                            "source: 21h  key: 3  pressed: yes  identifier: 21h")
    # The frame back, extended, byte for byte.
    f = powerkey.encode(m)
    assert f.is_extended_id and f.arbitration_id == 0x18EFFF21
    assert bytes(f.data) == bytes.fromhex("041B01030121FFFF")


def test_j1939_heartbeat_and_commands_answer_the_accessors():
    beat = powerkey.decode(0x18EFFF21, bytes.fromhex("041BF9030800FF21"), model="pkp1600si")
    assert beat.kind == "j1939_heartbeat" and beat.pressed_keys() == [4]
    assert powerkey.key_change(beat)["covered"] == [1, 2, 3, 4, 5, 6]
    brightness = powerkey.decode(0x18EF2100, bytes.fromhex("041B021FFFFFFFFF"), model="pkp1600si")
    assert brightness.led_brightness_level() == 0x1F
    moved = powerkey.decode(0x18EF2100, bytes.fromhex("041B70FDFDFFFFFF"), model="pkp1600si")
    assert powerkey.address_change(moved) == 0xFD and moved.node_id_change() is None


def test_j1939_address_narrows_and_other_pgns_are_not_keypad_frames():
    key = (0x18EFFF21, bytes.fromhex("041B01030121FFFF"))
    assert powerkey.decode(*key, model="pkp1600si", address=0x21).kind == "j1939_key_contact"
    with pytest.raises(powerkey.DecodeError) as e:
        powerkey.decode(*key, model="pkp1600si", address=0x22)
    assert e.value.code == "wrong_id"
    with pytest.raises(powerkey.DecodeError) as e:
        powerkey.decode(0x18FEF100, bytes(8 * [0xFF]), model="pkp1600si")
    assert e.value.code == "wrong_id"
    with pytest.raises(powerkey.ArgumentError):
        powerkey.decode(*key, model="pkp1600si", address=0xFE)
    # As node: the tool's text of --address, "21h", "0x21" or "33".
    for text in ("21h", "0x21", "33"):
        assert powerkey.decode(*key, model="pkp1600si", address=text).kind == "j1939_key_contact"
    for text in ("FEh", "00h", "nope", ""):
        with pytest.raises(powerkey.ArgumentError) as e:
            powerkey.decode(*key, model="pkp1600si", address=text)
        assert "01h..FDh" in str(e.value)
    with pytest.raises(powerkey.ArgumentError):  # 70h's range: 00h is the controllers'
        powerkey.decode(*key, model="pkp1600si", address=0)


def test_j1939_identifier_sent_as_standard_names_the_range():
    # A J1939 identifier in a can.Message given is_extended_id=False: no 11-bit identifier.
    msg = can.Message(arbitration_id=0x18EFFF21, data=bytes.fromhex("041B01030121FFFF"),
                      is_extended_id=False)
    with pytest.raises(powerkey.DecodeError) as e:
        powerkey.decode(msg, model="pkp1600si")
    assert e.value.code == "value_out_of_range"
    assert str(e.value) == ("frame: arbitration_id: 0x18efff21 is outside 0..0x7FF (11 bits: "
                            "is_extended_id=False)")


def test_j1939_encode_by_kind_and_address():
    f = powerkey.encode("j1939_set_led", model="pkp1600si", key=2, colour="red", mode="on")
    assert (f.arbitration_id, bytes(f.data), f.is_extended_id) == (
        0x18EF2100, bytes.fromhex("041B0102010100FF"), True)
    # An addressed key contact state whose bytes 4..6 read as an LED command too (identifier
    # 01h: LED 2 off, state 01h) needs narrowing to its sender.
    with pytest.raises(powerkey.EncodeError) as e:
        powerkey.encode("j1939_key_contact", model="pkp1600si", key=2, identifier=1,
                        destination=0)
    assert str(e.value) == ("j1939_key_contact: addressed to 00h with identifier 01h, its bytes "
                            "read as an LED command too: give address=0x21 (the keypad's address) "
                            "to encode it")
    f = powerkey.encode("j1939_key_contact", model="pkp1600si", key=2, identifier=1,
                        destination=0, address=0x21)
    assert (f.arbitration_id, bytes(f.data)) == (0x18EF0021, bytes.fromhex("041B01020001FFFF"))
    # Refused under address=, explained under it: the destination, not the priority, is to blame.
    with pytest.raises(powerkey.EncodeError) as e:
        powerkey.encode("j1939_set_led", model="pkp2600si", key=3, colour="red", mode="on",
                        address=0x22)
    assert str(e.value).startswith("j1939_set_led: destination: 33 is less than a pkp2600si "
                                   "takes (22h..22h)")


def test_session_follows_the_switch_both_ways():
    s = powerkey.Session(model="pkp2600si")
    assert s.step(0x615, bytes.fromhex("2BFF200101000000")).new_protocol == "j1939"
    e = s.step(0x18EFFF21, bytes.fromhex("041B01010121FFFF"), extended=True)
    assert e.function == "j1939" and e.message.kind == "j1939_key_contact"
    e = s.step(can.Message(arbitration_id=0x18EF2100, data=bytes.fromhex("041B8000FFFFFFFF")))
    assert e.message.kind == "j1939_switch_to_canopen" and e.new_protocol == "canopen"
    narrowed = powerkey.Session(model="pkp2600si", address=0x22)
    assert narrowed.step(0x18EFFF21, bytes.fromhex("041B01010121FFFF")).error == "wrong_id"
