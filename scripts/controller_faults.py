#!/usr/bin/python3
"""The controller fault logs of examples/logs/faults/ (issue 22): one bus log per kind of fault a
controller of the keypads makes, written by python-can's candump writer (CanutilsLogWriter), each
with what `powerkey check` must say of it: its problems, its warnings and its exit status.

    controller_faults.py write DIR     writes DIR/NAME.log for every row of FAULTS
    controller_faults.py check DIR     exits 1 when a log in DIR differs from what `write` makes

tests/test_tool_check_faults.py runs `powerkey check` on each log and compares with the rows.
Run with Debian's /usr/bin/python3 (python3-can).
"""
import filecmp
import os
import sys
import tempfile

# A row: the log's name, the model and node it is checked under, what the controller did (one
# line, the log's purpose), the frames as (ms from the start, candump ID#DATA), the lines
# `powerkey check` prints, and its exit status. Node 15h, the keypads' factory node id.
FAULTS = [
    {
        "name": "sdo-write-4-bytes",
        "model": "pk1000",
        "what": "a 4-byte expedited write (23h) of the 1-byte object 2014h, which the keypad "
                "neither acts on nor answers",
        "frames": [
            (0, "715#00"),
            (10, "000#0115"),
            (20, "615#2314200002000000"),
            (520, "215#0100000000000000"),
        ],
        "expected": [
            "3: refused_frame: frame 615h of 8 bytes refused (size_mismatch): the keypad does not act on it",
            "3: sdo_no_reply: SDO request 2014h/0 never answered (500 ms without a reply)",
        ],
        "status": 1,
    },
    {
        "name": "led-reserved-bit",
        "model": "pk1000",
        "what": "an LED map with bit 28 set: the PK1000 has LEDs 1..28 in bits 0..27 of each plane",
        "frames": [
            (0, "715#00"),
            (10, "000#0115"),
            (20, "215#0100000000000000"),
            (30, "215#0000001000000000"),
            (40, "215#0000000000000000"),
        ],
        "expected": [
            "4: refused_frame: frame 215h of 8 bytes refused (reserved_not_zero): the keypad does not act on it",
        ],
        "status": 1,
    },
    {
        "name": "level-40h",
        "model": "pk1000",
        "what": "an LED brightness PDO of level 40h: the levels are 00h..3Fh (PK1000 section 14)",
        "frames": [
            (0, "715#00"),
            (10, "000#0115"),
            (20, "415#3F00000000000000"),
            (30, "415#4000000000000000"),
        ],
        "expected": [
            "4: refused_frame: frame 415h of 8 bytes refused (value_out_of_range): the keypad does not act on it",
        ],
        "status": 1,
    },
    {
        "name": "sdo-no-reply",
        "model": "pk1000",
        "what": "an SDO write sent trimmed to 6 bytes that the keypad never answers, after one "
                "it answered",
        "frames": [
            (0, "715#00"),
            (10, "615#4011200000000000"),
            (11, "595#4F11200001000000"),
            (20, "615#2B171000F401"),
            (300, "000#0115"),
        ],
        "expected": [
            "4: warning: not_manual_form: frame 615h of 6 bytes is trimmed, not the manual's form: read as the manual's form, as the keypads do",
            "4: sdo_no_reply: SDO request 1017h/0 never answered (280 ms without a reply)",
            "warnings: not_manual_form 1",
        ],
        "status": 1,
    },
    {
        "name": "trimmed",
        "model": "pk1000",
        "what": "a controller that sends frames only as long as their last used byte (and its NMT "
                "padded to 8 bytes): warnings, not problems",
        "frames": [
            (0, "715#00"),
            (10, "000#0115000000000000"),
            (20, "615#2B171000F401"),
            (21, "595#6017100000000000"),
            (30, "515#3F01"),
            (40, "415#20"),
        ],
        "expected": [
            "2: warning: not_manual_form: frame 000h of 8 bytes is padded, not the manual's form: read as the manual's form, as the keypads do",
            "3: warning: not_manual_form: frame 615h of 6 bytes is trimmed, not the manual's form: read as the manual's form, as the keypads do",
            "5: warning: not_manual_form: frame 515h of 2 bytes is trimmed, not the manual's form: read as the manual's form, as the keypads do",
            "warnings: not_manual_form 4 (3 of each shown; --json lists each)",
        ],
        "status": 0,
    },
    # J1939 (docs/checker.md, "J1939"): a PKP-2600-SI at address 21h, the frames of its J1939
    # manual (sections named) with the controller's mistakes.
    {
        "name": "j1939-bad-header",
        "model": "pkp2600si",
        "what": "J1939 commands to the keypad with the header bytes swapped, and with command 1Ch "
                "(a \"live backlight colour\" no manual has)",
        "frames": [
            (0, "18EEFF21#3F426F1A00823CC0"),
            (10, "18EF2100#041B0101010100FF"),
            (20, "18EF2100#1B040101010100FF"),
            (30, "18EF2100#041B1C06FFFFFFFF"),
            (40, "18EF2100#041B7D06FFFFFFFF"),
        ],
        "expected": [
            "3: j1939_bad_header: J1939 frame 18EF2100h to keypad 21h has header 1B04h, not 041Bh: the keypad does not act on it",
            "4: j1939_bad_header: J1939 frame 18EF2100h to keypad 21h has command byte 1Ch, which no keypad has: the keypad does not act on it",
        ],
        "status": 1,
    },
    {
        "name": "j1939-multiple-leds-off",
        "model": "pkp2600si",
        "what": "the multiple-LED command (A700h, A600h) before LED management 37h 02h, whose "
                "default is single LED only; then 37h 02h and the command again",
        "frames": [
            (0, "18EEFF21#3F426F1A00823CC0"),
            (10, "18A72100#222222222222FFFF"),
            (11, "18A62100#000000000000FFFF"),
            (20, "18EF2100#041B3702FFFFFFFF"),
            (30, "18A72100#222222222222FFFF"),
            (31, "18A62100#000000000000FFFF"),
        ],
        "expected": [
            "2: j1939_multiple_leds_off: J1939 frame 18A72100h (multiple LEDs) while LED management 37h is single LED only (the default): the keypad ignores it until 37h 02h",
        ],
        "status": 1,
    },
    {
        "name": "j1939-old-address",
        "model": "pkp2600si",
        "what": "after moving the keypad to address 02h (70h), an LED command still sent to 21h",
        "frames": [
            (0, "18EEFF21#3F426F1A00823CC0"),
            (10, "18EF2100#041B700201FFFFFF"),
            (20, "18EF2100#041B0101010100FF"),
            (30, "18EF0200#041B0101010100FF"),
        ],
        "expected": [
            "3: j1939_no_keypad: J1939 frame 18EF2100h to address 21h, which no keypad holds (the keypad is at 02h): nobody acts on it",
        ],
        "status": 1,
    },
    {
        "name": "j1939-address-conflict",
        "model": "pkp2600si",
        "what": "a controller that claims the keypad's address 21h (EE00h, section 20) with its own "
                "NAME after the keypad claimed it",
        "frames": [
            (0, "18EEFF21#3F426F1A00823CC0"),
            (10, "18EEFF21#0200000000010080"),
        ],
        "expected": [
            "2: j1939_address_conflict: J1939 frame 18EEFF21h claims address 21h, which line 1 claimed with another NAME: two devices want one address",
        ],
        "status": 1,
    },
    {
        "name": "j1939-bad-source",
        "model": "pkp2600si",
        "what": "a controller that sends its J1939 commands from the global address FFh and the "
                "null address FEh (J1939-81: no sender's); then from 00h, as the manuals do",
        "frames": [
            (0, "18EF21FF#041B0220FFFFFFFF"),
            (10, "18EF21FE#041B0310FFFFFFFF"),
            (20, "18EF2100#041B0220FFFFFFFF"),
        ],
        "expected": [
            "1: j1939_bad_source: J1939 frame 18EF21FFh is sent from FFh, the global address, which is no sender's (J1939-81)",
            "2: j1939_bad_source: J1939 frame 18EF21FEh is sent from FEh, the null address, which sends only the address claim of a device that cannot claim one (J1939-81)",
        ],
        "status": 1,
    },
    {
        "name": "j1939-refused",
        "model": "pkp2600si",
        "what": "J1939 frames to the keypad that the decoder refuses: LED 13 of a 12-key keypad, "
                "LED brightness (02h) cut to 4 bytes; then both as the manual has them",
        "frames": [
            (0, "18EF2100#041B010D010100FF"),
            (10, "18EF2100#041B0220"),
            (20, "18EF2100#041B010C010100FF"),
            (30, "18EF2100#041B0220FFFFFFFF"),
        ],
        "expected": [
            "1: refused_frame: frame 18EF2100h of 8 bytes refused (value_out_of_range): the keypad does not act on it",
            "2: refused_frame: frame 18EF2100h of 4 bytes refused (wrong_length): the keypad does not act on it",
        ],
        "status": 1,
    },
]


def write(directory):
    import can  # Debian's python3-can

    for row in FAULTS:
        path = os.path.join(directory, row["name"] + ".log")
        writer = can.CanutilsLogWriter(path, channel="can0")
        for ms, frame in row["frames"]:
            ident, data = frame.split("#")
            writer.on_message_received(
                can.Message(
                    timestamp=1700000000 + ms / 1000,
                    arbitration_id=int(ident, 16),
                    is_extended_id=len(ident) > 3,
                    data=bytes.fromhex(data),
                    channel="can0",
                )
            )
        writer.stop()


def check(directory):
    with tempfile.TemporaryDirectory() as fresh:
        write(fresh)
        stale = [r["name"] for r in FAULTS
                 if not filecmp.cmp(os.path.join(fresh, r["name"] + ".log"),
                                    os.path.join(directory, r["name"] + ".log"), shallow=False)]
    if stale:
        print("stale logs (scripts/controller_faults.py write DIR): " + ", ".join(stale))
        return 1
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in ("write", "check"):
        sys.exit(__doc__)
    sys.exit(write(sys.argv[2]) if sys.argv[1] == "write" else check(sys.argv[2]))
