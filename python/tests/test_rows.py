"""Every manual row through powerkey.decode / powerkey.encode, equal to the C++ results.

The reference is python/tests/rows.cpp (ctest passes its path in POWERKEY_ROWS): the C++ decode
of every row of tests/*_rows.hpp for every model the row names, its fields written by the powerkey
tool's JSON writer, the accessors' answers, and the C++ encode of the result. Nothing expected is
written here.
"""

import json
import os
import subprocess

import pytest

import powerkey


if not os.environ.get("POWERKEY_ROWS"):
    pytest.skip("POWERKEY_ROWS not set (run through ctest)", allow_module_level=True)


def _reference_lines():
    path = os.environ["POWERKEY_ROWS"]
    out = subprocess.run([path], check=True, capture_output=True, text=True).stdout
    return [json.loads(line) for line in out.splitlines()]


LINES = _reference_lines()


def _id(r):
    return f"{r['table']}:{r['section']}:{r['model']}"


def test_reference_present():
    tables = {r["table"] for r in LINES}
    # Every table of the test suite is in the reference (a table left out would pass silently).
    for t in ("core_rows", "core_error_rows", "pk1000_rows", "pk1000_error_rows",
              "pk1000_encode_error_rows", "pkp_rows", "pkp_error_rows", "pkp_encode_error_rows",
              "si_rows", "si_error_rows", "si_errata_rows", "si_reference_rows",
              "si_reference_error_rows"):
        assert t in tables
    assert len({r["model"] for r in LINES}) == len(powerkey.names("model"))


FRAME_LINES = [r for r in LINES if "data" in r]
ENCODE_ERROR_LINES = [r for r in LINES if "data" not in r]


def _accessors(m, model):
    def update(u):
        return None if u is None else {"map": u.map, "covered": u.covered}

    b = powerkey.backlight_change(m)
    return {
        "pressed_keys": powerkey.pressed_keys(m),
        "led_on_map": update(powerkey.led_on_map(m)),
        "led_blink_map": update(powerkey.led_blink_map(m, model)),
        "led_brightness_level": powerkey.led_brightness_level(m),
        "backlight_change": None if b is None else {"level": b.level, "colour": b.colour},
        "node_id_change": powerkey.node_id_change(m),
        "reported_nmt_state": powerkey.reported_nmt_state(m),
    }


@pytest.mark.parametrize("r", FRAME_LINES, ids=_id)
def test_decode_and_encode(r):
    ident, data, ext = int(r["id"], 16), bytes.fromhex(r["data"]), r["ext"]
    if "error" in r:
        with pytest.raises(powerkey.DecodeError) as e:
            powerkey.decode(ident, data, model=r["model"], node=r["node"], extended=ext)
        assert e.value.code == r["error"]
        return
    m = powerkey.decode(ident, data, model=r["model"], node=r["node"], extended=ext)
    assert m.kind == r["kind"]
    assert m.to_dict() == r["fields"]
    for name, value in r["fields"].items():
        assert getattr(m, name) == value
    assert _accessors(m, r["model"]) == r["accessors"]

    # Built again from the kind and the JSON fields alone, as a bench would write it.
    if "encoded" in r:
        f = powerkey.encode(r["kind"], model=r["model"], node=r["node"], **r["fields"])
        assert (f.arbitration_id, f.is_extended_id) == (ident, ext)
        assert bytes(f.data).hex().upper() == r["encoded"]
        g = powerkey.encode(m)
        assert bytes(g.data) == bytes(f.data) and g.arbitration_id == f.arbitration_id
    else:
        with pytest.raises(powerkey.EncodeError) as e:
            powerkey.encode(r["kind"], model=r["model"], node=r["node"], **r["fields"])
        assert e.value.code == r["encode_error"]


@pytest.mark.parametrize("r", ENCODE_ERROR_LINES, ids=_id)
def test_encode_error_rows(r):
    # The message of the row's kind and fields (a few rows hold a raw value no field shows, then
    # the C++ reference encoded the message the fields describe: same_message false).
    if "encoded" in r:
        assert not r["same_message"], "the C++ encoder accepted an encode-error row"
        f = powerkey.encode(r["kind"], model=r["model"], node=r["node"], **r["fields"])
        assert bytes(f.data).hex().upper() == r["encoded"]
        return
    with pytest.raises(powerkey.EncodeError) as e:
        powerkey.encode(r["kind"], model=r["model"], node=r["node"], **r["fields"])
    assert e.value.code == r["encode_error"]
