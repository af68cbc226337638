#!/usr/bin/env python3
"""Writes tests/si_rows.hpp from tests/data/si_rows.txt: every example frame of the PKP2600SI and
PKP3500-MT manuals as rows of the types of tests/codec_rows.hpp; and from
tests/data/si_models.txt the facts of each SI size (keys, plane stride, 2001h/2002h scheme,
backlight PDO, reported 100Bh string) that tests/test_keypad_models.cpp checks against the model
table.

    scripts/si_rows.py            rewrite tests/si_rows.hpp
    scripts/si_rows.py --check    exit 1 when tests/si_rows.hpp is not what this script writes

The expected message of each row is written from the row's meaning in the data file (its own
`kind key=value` vocabulary, defined at the top of that file), translated into the library's
names: never from what the decoder makes of the frame, so that a test fails when the decoder's
meaning differs from the manual's. The translation checks the data as it goes (a segment's text
against its unused count, a device type's value against its fields, an 8-bit input against its
millivolts) and stops at anything it does not know.

The header is formatted with clang-format-14 (the root .clang-format), so that the format test
accepts it; --check needs the same clang-format.
"""
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "tests", "data", "si_rows.txt")
MODEL_DATA = os.path.join(ROOT, "tests", "data", "si_models.txt")
OUT = os.path.join(ROOT, "tests", "si_rows.hpp")

MODELS = {"pkp2600si": ("m2600si", "PKP2600SI"), "pkp3500mt": ("m3500mt", "PKP3500-MT")}

# The data file's object names that the library spells otherwise.
OBJECT_NAMES = {"bus_j1939": "protocol_j1939", "restore_all": "restore_defaults"}
# The string objects, for the segmented upload's initiate reply (index, sub-index).
STRING_ADDRESSES = {
    "device_name": (0x1008, 0),
    "hardware_version": (0x1009, 0),
    "software_version": (0x100A, 0),
    "model_name": (0x100B, 0),
    "serial_number_string": (0x2200, 0),
}
COLOURS = {
    "red": "red", "green": "green", "blue": "blue", "yellow": "yellow", "cyan": "cyan",
    "violet": "violet", "white_light_blue": "white", "amber_orange": "amber",
    "yellow_green": "yellow_green",
    # PKP2600SI 15: 00h names the default colour; the library's 00h of the backlight PDO.
    "default": "keep",
}
ERRC = {"reserved_not_zero", "wrong_length", "size_mismatch", "value_out_of_range",
        "unknown_command", "unknown_object", "wrong_id", "wrong_id_format"}


class DataError(Exception):
    pass


def hexnum(text):
    if not text.endswith("h"):
        raise DataError(f"not a hex number: {text}")
    return int(text[:-1], 16)


def num(text):
    return hexnum(text) if text.endswith("h") else int(text)


def numbers(text):
    return [int(x) for x in text.split(",")] if text else []


def led_list(text):
    return "{" + ", ".join(str(x) for x in numbers(text)) + "}"


def c_bytes(text, width):
    b = [ord(c) for c in text]
    if len(b) > width:
        raise DataError(f"text longer than {width}: {text}")
    b += [0] * (width - len(b))
    return "{" + ", ".join(f"0x{x:02X}" if 32 <= x < 127 else f"0x{x:02X}" for x in b) + "}"


def chars(text):
    """'V_01' -> {'V', '_', '0', '1'}"""
    return "{" + ", ".join("'" + c.replace("\\", "\\\\").replace("'", "\\'") + "'" for c in text) + "}"


def fields(words):
    out = {}
    for w in words:
        if "=" not in w:
            raise DataError(f"not key=value: {w}")
        k, v = w.split("=", 1)
        out[k] = v
    return out


def take(f, *keys):
    for k in keys:
        if k not in f:
            raise DataError(f"missing {k}")
    return [f.pop(k) for k in keys]


def sdo_value(obj, f):
    """The object_value expression of an SDO's value keys (the keys are consumed)."""
    if "keys" in f:
        return f"keys_value({led_list(f.pop('keys'))})"
    if any(k in f for k in ("red", "green", "blue")):
        r, g, b = (f.pop(k, "") for k in ("red", "green", "blue"))
        return f"leds_value(rgb({led_list(r)}, {led_list(g)}, {led_list(b)}))"
    if "leds" in f:
        return f"ring({led_list(f.pop('leds'))})"
    if "level" in f:
        return f"level_value(0x{hexnum(f.pop('level')):02X})"
    if "colour" in f:
        c = f.pop("colour")
        if c not in COLOURS or c == "default":
            raise DataError(f"colour {c}")
        return f"colour_value(backlight_colour::{COLOURS[c]})"
    if "kbit" in f:
        return f"baud_value(baud_rate::kbit_{int(f.pop('kbit'))})"
    if "enabled" in f:
        return "flag_value(" + {"0": "false", "1": "true"}[f.pop("enabled")] + ")"
    if "node_id" in f:
        return f"node_value(0x{hexnum(f.pop('node_id')):02X})"
    if "show" in f:
        return f"show_value(startup_show::{f.pop('show')})"
    if "producer" in f:
        period, producer = take(f, "period_ms", "producer")
        return f"consumer_heartbeat_value({int(period)}, 0x{hexnum(producer):02X})"
    if "period_ms" in f:
        ms = int(f.pop("period_ms"))
        if obj == "analog_input_period":  # 2006h counts 10 ms (PKP3500-MT 25)
            if ms % 10:
                raise DataError("2006h period not a multiple of 10 ms")
            return f"number_value({ms // 10})"
        return f"number_value({ms})"
    if "count" in f:
        return f"number_value({int(f.pop('count'))})"
    if "cob_id" in f:
        return f"number_value(0x{hexnum(f.pop('cob_id')):03X})"
    if "transmission_type" in f:
        return f"number_value(0x{hexnum(f.pop('transmission_type')):02X})"
    if "index" in f:
        index, sub, bits = take(f, "index", "sub", "bits")
        return f"mapping_value(0x{hexnum(index):04X}, 0x{hexnum(sub):02X}, {int(bits)})"
    if "profile" in f:  # 1000h: the value and its CiA 401 fields must agree
        value, profile, di, do, ai, ao = take(f, "value", "profile", "digital_input",
                                              "digital_output", "analogue_input",
                                              "analogue_output")
        v = hexnum(value)
        bits = [(v >> (16 + i)) & 1 for i in range(4)]
        if (v & 0xFFFF) != int(profile) or bits != [int(di), int(do), int(ai), int(ao)]:
            raise DataError(f"device type {value} and its fields disagree")
        return f"number_value(0x{v:08X})"
    if "value" in f:
        return f"number_value(0x{num(f.pop('value')):X})"
    if "text" in f:
        t = f.pop("text")
        if not 1 <= len(t) <= 4:
            raise DataError(f"expedited string of {len(t)} bytes")
        return f"string_value({len(t)}, {chars(t.ljust(4, chr(0)))})".replace("'\x00'", "0")
    if "signature" in f:
        if f.pop("signature") != "load":
            raise DataError("restore signature")
        return "number_value(load_signature)"
    if "direction" in f:
        d, ticks = take(f, "direction", "ticks")
        return f"direction_value({'true' if d == 'ccw' else 'false'}, {int(ticks)})"
    if "start_value" in f:
        return f"number_value({int(f.pop('start_value'))})"
    if "top" in f:
        return f"number_value({int(f.pop('top'))})"
    if "raw" in f:  # 2005h: 8 bits, Vin = raw x 5 V / 255
        raw, mv = take(f, "raw", "mv")
        r = hexnum(raw)
        if abs(r * 5000 / 255 - int(mv)) > 10:
            raise DataError(f"2005h {raw} is not {mv} mV")
        return f"number_value(0x{r:02X})"
    raise DataError(f"no value keys in {f}")


def message(kind, f):
    """The message expression of a meaning (the keys are consumed)."""
    if kind == "nmt":
        cmd, target = take(f, "command", "target")
        return f"nmt(nmt_command::{cmd}, 0x{hexnum(target):02X})"
    if kind == "sync":
        return "sync()"
    if kind == "heartbeat":
        return f"hb(nmt_state::{take(f, 'state')[0]})"
    if kind == "key_state":
        keys, tick = take(f, "keys", "tick")
        return f"key_state{{{led_list(keys)}, 0x{hexnum(tick):02X}}}"
    if kind in ("led_on", "led_blink"):
        r, g, b = take(f, "red", "green", "blue")
        return f"{kind}{{rgb({led_list(r)}, {led_list(g)}, {led_list(b)})}}"
    if kind == "led_brightness":
        return f"led_brightness{{0x{hexnum(take(f, 'level')[0]):02X}}}"
    if kind == "backlight":
        level, colour = take(f, "level", "colour")
        if colour in COLOURS:
            c = COLOURS[colour]
        elif colour == "00h":  # PKP3500-MT 18: not in the table, the current colour
            c = "keep"
        else:
            raise DataError(f"backlight colour {colour}")
        return f"backlight{{0x{hexnum(level):02X}, backlight_colour::{c}}}"
    if kind == "encoder_state":
        enc, d, ticks, counter, top = take(f, "encoder", "direction", "ticks", "tick_counter",
                                          "top")
        if d not in ("cw", "ccw"):
            raise DataError(f"direction {d}")
        ccw = "true" if d == "ccw" else "false"
        return f"encoder_state{{{int(enc)}, {ccw}, {int(ticks)}, {int(counter)}, {int(top)}}}"
    if kind == "analog_input":
        mv = take(f, "in0_mv", "in1_mv", "in2_mv", "in3_mv")
        return "analog_inputs{{" + ", ".join(str(int(x)) for x in mv) + "}}"
    if kind == "encoder_led_on":
        return f"encoder_leds{{{led_list(take(f, 'leds')[0])}}}"
    if kind in ("sdo_read", "sdo_write_reply", "sdo_read_reply", "sdo_write"):
        obj = take(f, "object")[0]
        name = OBJECT_NAMES.get(obj, obj)
        if kind == "sdo_read":
            return f"read(o::{name})"
        if kind == "sdo_write_reply":
            return f"written(o::{name})"
        fn = "reply" if kind == "sdo_read_reply" else "write"
        return f"{fn}(o::{name}, {sdo_value(obj, f)})"
    if kind == "sdo_read_reply_initiate":
        obj, size = take(f, "object", "size")
        index, sub = STRING_ADDRESSES[obj]
        return f"initiate(0x{index:04X}, {sub}, true, {int(size)})"
    if kind == "sdo_segment_request":
        return "next(" + {"0": "false", "1": "true"}[take(f, "toggle")[0]] + ")"
    if kind == "sdo_segment_reply":
        toggle, unused, last, text = take(f, "toggle", "unused", "last", "text")
        if len(text) != 7 - int(unused):
            raise DataError(f"segment text {text!r} and unused {unused} disagree")
        t = {"0": "false", "1": "true"}
        return (f"segment({t[toggle]}, {int(unused)}, {t[last]}, "
                f"{c_bytes(text, 7)})")
    if kind == "j1939_switch_to_canopen":
        dest, src = take(f, "destination", "source")
        return f"switch_back(0x{hexnum(dest):02X}, 0x{hexnum(src):02X})"
    raise DataError(f"unknown kind {kind}")


SCHEMES = {"packed": "si_packed", "per_colour_rings": "si_mt", "per_colour": "si_per_colour"}
BACKLIGHT = {"level_colour": "true", "level_only": "false"}


def model_facts():
    out = []
    with open(MODEL_DATA, encoding="utf-8") as fh:
        for lineno, line in enumerate(fh, 1):
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            try:
                name, keys, stride, scheme, backlight, reported, inferred, _source = line.split("\t")
                rep = "" if reported == "-" else reported
                out.append(f"{{model::{name}, {int(keys)}, {int(stride)}, dictionary::{SCHEMES[scheme]}, "
                           f"{BACKLIGHT[backlight]}, {c_string(rep)}, "
                           f"{ {'yes': 'true', 'no': 'false'}[inferred]}}},")
            except (KeyError, ValueError) as e:
                sys.exit(f"{MODEL_DATA}:{lineno}: {e}")
    return out


def c_string(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def generate():
    rows, errors, errata = [], [], []
    counts = {}
    with open(DATA, encoding="utf-8") as fh:
        for lineno, line in enumerate(fh, 1):
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            try:
                model, section, node, _direction, frame, meaning = line.split("\t")
                mask, manual = MODELS[model]
                sect = f"{manual} {section}"
                n = f"0x{int(node, 16):02X}"
                words = meaning.split()
                if words[0] == "ERRATUM":
                    erratum, err, corrected = words[1], words[2], fields(words[3:])
                    if err not in ERRC or "corrected" not in corrected:
                        raise DataError(f"erratum row {meaning}")
                    errors.append(f"{{{c_string(sect + ' ' + erratum)}, {mask}, {n}, "
                                  f"{c_string(frame)}, errc::{err}}},")
                    errata.append(f"{{{c_string(erratum)}, {mask}, {n}, {c_string(frame)}, "
                                  f"errc::{err}}},")
                    counts[model, "error"] = counts.get((model, "error"), 0) + 1
                    continue
                f = fields(words[1:])
                marker = ""
                if "erratum" in f:
                    e = f.pop("erratum")
                    marker = f" {e}"
                    errata.append(f"{{{c_string(e)}, {mask}, {n}, {c_string(frame)}, errc{{}}}},")
                if "corrects" in f:
                    e = f.pop("corrects")
                    marker = f" {e} corrected"
                    errata.append(f"{{{c_string(e)}, {mask}, {n}, {c_string(frame)}, errc{{}}}},")
                expected = message(words[0], f)
                if f:
                    raise DataError(f"keys not used: {f}")
                rows.append(f"{{{c_string(sect + marker)}, {mask}, {n}, {c_string(frame)}, "
                            f"{expected}}},")
                counts[model, "row"] = counts.get((model, "row"), 0) + 1
            except (DataError, KeyError, ValueError) as e:
                sys.exit(f"{DATA}:{lineno}: {e}")

    def table(lines):
        return "\n".join("    " + x for x in lines)

    summary = ", ".join(f"{m} {counts.get((m, 'row'), 0)} rows and "
                        f"{counts.get((m, 'error'), 0)} refused" for m in MODELS)
    return f"""// GENERATED by scripts/si_rows.py from tests/data/si_rows.txt: do not edit; rerun the script.
// Every example frame of the PKP2600SI (PKP-2600-SI CANopen UM rev 1.5) and PKP3500-MT
// (PKP-3500-MT CANopen UM rev 1.3) manuals (and the sizes of tests/data/si_models.txt), in the row types of tests/codec_rows.hpp, with the
// manual and section ("PKP2600SI 17 a") and the erratum a row belongs to (docs/errata.md, E-SI-n;
// "corrected": the frame the manual meant). The expected messages are the data file's meanings
// translated into the library's names, not the decoder's output. {summary}.
//   rows         decode to their meaning and re-encode byte for byte (round_trips)
//   error_rows   the printed frames the library refuses (the data file's ERRATUM rows)
//   errata_rows  every row the data file marks with an erratum: errc{{}} = it decodes
#ifndef POWERKEY_TESTS_SI_ROWS_HPP
#define POWERKEY_TESTS_SI_ROWS_HPP

#include "codec_rows.hpp"

#include <cstdint>
#include <string_view>

namespace si_rows {{

using namespace powerkey;
using namespace codec_rows;
using codec_rows::error_row;
using codec_rows::row;
using o = object;

// The encoder rings of 2001h/2002h sub 04h (ring LEDs 1..32).
constexpr object_value ring(led_set s) noexcept {{
    return number_value(static_cast<std::uint32_t>(s.mask()));
}}
// An encoder's direction counter (2000h sub 02h/04h): bit 7 counterclockwise, bits 0..6 ticks.
constexpr object_value direction_value(bool counterclockwise, std::uint8_t ticks) noexcept {{
    return number_value((counterclockwise ? 0x80u : 0u) | ticks);
}}
// A PDO mapping entry: index, sub-index, length in bits.
constexpr object_value mapping_value(std::uint32_t index, std::uint32_t sub,
                                     std::uint32_t bits) noexcept {{
    return number_value((index << 16) | (sub << 8) | bits);
}}
constexpr message switch_back(std::uint8_t destination, std::uint8_t source) noexcept {{
    j1939::switch_to_canopen s;
    s.destination = destination;
    s.source = source;
    return s;
}}

inline constexpr row rows[] = {{
{table(rows)}
}};

inline constexpr error_row error_rows[] = {{
{table(errors)}
}};

inline constexpr error_row errata_rows[] = {{
{table(errata)}
}};

// tests/data/si_models.txt: one line per SI size.
struct model_fact {{
    model id;
    std::uint8_t keys;         // keys 1..N
    std::uint8_t stride;       // S, the LED-map plane stride
    dictionary scheme;         // the 2001h/2002h scheme: packed, per colour with rings, per colour
    bool colour_byte;          // the backlight PDO carries the colour in byte 1
    std::string_view reported; // the 100Bh string, "" where no manual page gives it
    bool inferred;             // a column of the line is inferred (docs/si-family.md says which)
}};

inline constexpr model_fact model_facts[] = {{
{table(model_facts())}
}};

}}  // namespace si_rows

#endif  // POWERKEY_TESTS_SI_ROWS_HPP
"""


def formatted(text):
    cf = shutil.which("clang-format-14") or shutil.which("clang-format")
    if not cf:
        sys.exit("si_rows.py: clang-format-14 not found")
    return subprocess.run([cf, "--style=file", "--assume-filename=" + OUT], input=text,
                          capture_output=True, text=True, check=True, cwd=ROOT).stdout


def main():
    text = formatted(generate())
    if "--check" in sys.argv[1:]:
        with open(OUT, encoding="utf-8") as fh:
            if fh.read() != text:
                sys.exit("tests/si_rows.hpp is stale: run scripts/si_rows.py")
        return
    with open(OUT, "w", encoding="utf-8") as fh:
        fh.write(text)


if __name__ == "__main__":
    main()
