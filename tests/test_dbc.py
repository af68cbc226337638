#!/usr/bin/env python3
"""The DBCs of `powerkey export dbc` read by a real DBC reader, canmatrix (Debian's
python3-canmatrix), and checked against the library (tests/test_dbc.sh runs this):

  test_dbc.py POWERKEY_BINARY SOURCE_DIR

1. Every model of the table (the list `export dbc` prints when --model is missing): canmatrix
   loads its DBC without a warning or error and with every message, signal and value table the
   file has (canmatrix prints some errors instead of logging them, and drops lines it cannot
   parse: both are caught).
2. Every frame of every sample log (examples/logs/MODEL.log) that `powerkey decode --json` reads
   as a frame of the keypad's node decodes in canmatrix to the same values: every key, every LED of
   every colour, level, colour, state, encoder, input, and the SDO objects' values. A frame the DBC
   does not describe (SDO segments, aborts, strings) must decode to no named SDO request or reply;
   J1939 frames, not in the files yet (docs/dbc.md), are counted.
3. Every key, LED and ring LED: the frame `powerkey encode` builds for that one key or LED decodes
   in canmatrix to exactly that one signal, and every key or LED the library refuses has no signal.
4. Another node id moves every per-node identifier.
"""
import contextlib
import io
import json
import logging
import os
import re
import subprocess
import sys
import tempfile

pk, src = sys.argv[1], sys.argv[2]
failures = []
NODE = 0x15  # the sample logs' node


def fail(what):
    failures.append(what)
    if len(failures) <= 40:
        print("FAIL: " + what)


class Collect(logging.Handler):
    def __init__(self):
        super().__init__(logging.WARNING)
        self.records = []

    def emit(self, record):
        self.records.append(record.getMessage())


# Importing canmatrix warns once per optional format whose library is missing ("arxml is not
# supported": lxml, xlrd, ...). That is about canmatrix's installation, not about a DBC: noted,
# not a failure. Loading a DBC must log nothing (load below).
_import_log = Collect()
logging.getLogger().addHandler(_import_log)
import canmatrix  # noqa: E402
import canmatrix.formats.dbc  # noqa: E402
logging.getLogger().removeHandler(_import_log)
if _import_log.records:
    print("note: canmatrix at import: " + "; ".join(_import_log.records))


def run(*args, stdin=None):
    return subprocess.run([pk, *args], input=stdin, capture_output=True, text=True)


def load(text, label):
    """The DBC text as canmatrix reads it; fails on any warning, printed error or lost line."""
    handler = Collect()
    root = logging.getLogger()
    root.addHandler(handler)
    printed = io.StringIO()
    try:
        with contextlib.redirect_stdout(printed):
            db = canmatrix.formats.dbc.load(io.BytesIO(text.encode("ascii")))
    finally:
        root.removeHandler(handler)
    for r in handler.records:
        fail(f"{label}: canmatrix logged: {r}")
    if printed.getvalue():
        fail(f"{label}: canmatrix printed: {printed.getvalue().strip()[:300]}")
    # Nothing dropped: every message, signal, comment and value table of the text is in db.
    lines = text.splitlines()
    count = lambda prefix: sum(1 for l in lines if l.startswith(prefix))
    signals = [s for f in db.frames for s in f.signals]
    checks = [
        ("messages", count("BO_ "), len(db.frames)),
        ("signals", count(" SG_ "), len(signals)),
        ("signal comments", count("CM_ SG_ "), sum(1 for s in signals if s.comment)),
        ("message comments", count("CM_ BO_ "), sum(1 for f in db.frames if f.comment)),
        ("value tables", count("VAL_ "), sum(1 for s in signals if s.values)),
        ("named value tables", count("VAL_TABLE_ "), len(db.value_tables)),
        ("nodes", 2, len(db.ecus)),
    ]
    for what, want, got in checks:
        if want != got:
            fail(f"{label}: canmatrix read {got} {what}, the file has {want}")
    if db.attributes.get("DBName") is None:
        fail(f"{label}: no DBName")
    return db


def export(model, node=None):
    args = ["export", "dbc", "--model", model] + (["--node", node] if node else [])
    r = run(*args)
    if r.returncode != 0:
        fail(f"export dbc --model {model}: exit status {r.returncode}: {r.stderr.strip()}")
    return r.stdout


# --- every model loads ---------------------------------------------------------------------------
r = run("export", "dbc")
m = re.search(r"needs --model M \(([^)]*)\)", r.stderr)
if r.returncode != 2 or not m:
    print(f"FAIL: export dbc without --model: status {r.returncode}, {r.stderr.strip()}")
    sys.exit(1)
models = [x.strip() for x in m.group(1).split(",")]
dbs = {model: load(export(model), model) for model in models}


def frame_of(db, ident, ext=False):
    return db.frame_by_id(canmatrix.ArbitrationId(ident, extended=ext))


def members(decoded, prefix):
    """{k: raw} of the signals named prefix + k."""
    out = {}
    for name, d in decoded.items():
        mm = re.fullmatch(re.escape(prefix) + r"(\d+)", name)
        if mm:
            out[int(mm.group(1))] = d.raw_value
    return out


def check_set(label, decoded, prefix, want):
    got = members(decoded, prefix)
    on = sorted(k for k, v in got.items() if v)
    if on != sorted(want):
        fail(f"{label}: {prefix}*: canmatrix {on}, powerkey {sorted(want)}")
    missing = [k for k in want if k not in got]
    if missing:
        fail(f"{label}: no signal for {prefix}{missing}")


SINGULAR = {"keys": "key", "leds": "led"}
SHORT = {"counterclockwise": "ccw"}  # dbc.cpp's object_signal: names stay within 32 characters


def check_value(label, decoded, name, value):
    """One field: a set, a flag, a number or a name, against the signal `name`."""
    if isinstance(value, list):
        check_set(label, decoded, name, value)
        return
    if name not in decoded:
        fail(f"{label}: no signal {name} (powerkey: {value})")
        return
    d = decoded[name]
    if isinstance(value, bool):
        ok = d.raw_value == int(value)
    elif isinstance(value, str):
        ok = d.named_value == value
    else:
        ok = d.phys_value == value
    if not ok:
        fail(f"{label}: {name}: canmatrix {d.raw_value} ({d.named_value}), powerkey {value}")


def object_signal(obj, field):
    s = obj + "_" + field
    return obj + "_" + SHORT[field] if len(s) > 32 and field in SHORT else s


def check_sdo(label, decoded, kind, fields, mux):
    named = decoded[mux].named_value
    obj = fields.get("object")
    if kind in ("sdo_read", "sdo_write", "sdo_read_reply", "sdo_write_reply", "command"):
        values = {k: v for k, v in fields.items() if k != "object"}
        if kind == "sdo_read_reply" and "bytes" in values:  # a string read expedited
            want = None
        elif kind == "sdo_read_reply" and "size" in values:  # keys in 1 byte (4Fh): the DBC
            want = None                                       # has the SI manuals' 2 bytes
        else:
            want = "command" if kind == "command" else f"{kind} {obj}"
    elif kind == "sdo_upload_initiate_response" and fields["size_indicated"]:
        if not (isinstance(named, str) and named.startswith(kind + " ")):
            fail(f"{label}: multiplexor {named!r}, powerkey {kind}")
        else:
            check_value(label, decoded, named.split(" ")[1] + "_size", fields["size"])
        return
    else:
        want = None  # segments and aborts: not described
    if want is None:
        if isinstance(named, str):
            fail(f"{label}: canmatrix names {named!r} a frame the DBC does not describe ({kind})")
        return
    if named != want:
        fail(f"{label}: multiplexor {named!r}, powerkey {want!r}")
        return
    if kind == "command":
        check_value(label, decoded, "command_module_command", fields["command"])
        # Numeric parameters in their byte (flags as 00h/01h); names use the command's own codes.
        params = [v for k, v in fields.items() if k != "command"]
        for i, v in enumerate(params, 1):
            if isinstance(v, (bool, int)):
                check_value(label, decoded, f"command_module_parameter{i}", v)
        return
    if kind in ("sdo_read", "sdo_write_reply"):
        extra = [n for n in decoded if n != mux]
        if extra:
            fail(f"{label}: {kind} decodes signals {extra}")
        return
    single = len(values) == 1
    for field, value in values.items():
        if isinstance(value, list):
            check_set(label, decoded, obj + "_" + SINGULAR.get(field, field), value)
        elif single:
            check_value(label, decoded, obj, value)
        else:
            check_value(label, decoded, object_signal(obj, field), value)


def check_j1939(label, db, j):
    """A J1939 frame, as canmatrix finds it by identifier (Matrix.decode; its fallback by PGN
    fails on a file that also has 11-bit messages: below)."""
    kind, fields = j["kind"], j["fields"]
    aid = canmatrix.ArbitrationId(int(j["id"], 16), extended=True)
    frame = db.frame_by_id(aid)
    if frame is None or not frame.is_j1939:
        fail(f"{label}: {kind}: no J1939PG message")
        return kind
    decoded = db.decode(aid, bytes.fromhex(j["data"]))
    command = decoded.get("command")
    if command is None or command.named_value != kind:
        fail(f"{label}: command {command.named_value if command else None!r}, powerkey {kind}")
    # The route: canmatrix reads the identifier as J1939 does.
    for field, got in (("priority", aid.j1939_priority), ("destination", aid.j1939_destination),
                       ("source", aid.j1939_source)):
        if fields.get(field) != got:
            fail(f"{label}: {field}: canmatrix {got}, powerkey {fields.get(field)}")
    if aid.pgn != j["pgn"]:
        fail(f"{label}: PGN: canmatrix {aid.pgn:#x}, powerkey {j['pgn']:#x}")
    return kind


def check_frame(model, db, j):
    label = f"{model}.log {j['id']}#{j['data']}"
    kind, fields = j["kind"], j["fields"]
    if j["ext"]:
        return check_j1939(label, db, j)
    frame = frame_of(db, int(j["id"], 16), j["ext"])
    if frame is None:
        fail(f"{label}: {kind} has no message in the DBC")
        return None
    decoded = frame.decode(bytes.fromhex(j["data"]))
    name = frame.name
    if kind in ("sdo_read", "sdo_write", "sdo_read_reply", "sdo_write_reply", "command",
                "sdo_upload_initiate_response", "sdo_segment_request", "sdo_segment_response",
                "sdo_abort_request", "sdo_abort_response"):
        mux = {"sdo_request": "request", "sdo_response": "response"}.get(name)
        if mux is None:
            fail(f"{label}: {kind} is message {name}")
        else:
            check_sdo(label, decoded, kind, fields, mux)
        return kind
    if kind == "encoder_state":
        want = f"encoder{fields['encoder']}_state"
        fields = {k: v for k, v in fields.items() if k != "encoder"}
    else:
        want = kind
    if name != want:
        fail(f"{label}: message {name}, powerkey {want}")
        return kind
    for field, value in fields.items():
        if isinstance(value, list):
            check_set(label, decoded, SINGULAR.get(field, field), value)
        elif kind == "backlight" and field == "colour" and "colour" not in decoded:
            if value != "keep":  # a level-only keypad: byte 1 is reserved (00h, keep)
                fail(f"{label}: colour {value} on a level-only backlight")
        else:
            check_value(label, decoded, field, value)
    return kind


# --- every frame of every sample log ------------------------------------------------------------
checked = {}
for model in models:
    r = run("decode", "--model", model, "--json", f"{src}/examples/logs/{model}.log")
    kinds = {}
    for line in r.stdout.splitlines():
        j = json.loads(line)
        # Frames of this node that decode (after a node-id change the log goes on at the new id,
        # which the DBC of node 15h does not describe).
        if "error" in j or "kind" not in j or j.get("node") != NODE:
            continue
        k = check_frame(model, dbs[model], j)
        if k:
            kinds[k] = kinds.get(k, 0) + 1
    # Every sample log has key states and LED maps; a test that checked none would pass on nothing.
    for k in ("key_state", "led_on"):
        if not kinds.get(k):
            fail(f"{model}.log: no {k} frame checked")
    for k, n in kinds.items():
        checked[k] = checked.get(k, 0) + n
    print(f"{model}.log: " + ", ".join(f"{k} {n}" for k, n in sorted(kinds.items())))
# ... and together the logs have every kind of frame the DBC describes, and those it does not.
for k in ("nmt_message", "sync_message", "heartbeat_message", "key_state", "led_on", "led_blink",
          "led_brightness", "backlight", "encoder_state", "analog_inputs", "encoder_leds",
          "sdo_read", "sdo_write", "sdo_read_reply", "sdo_write_reply", "command",
          "sdo_upload_initiate_response", "sdo_segment_request", "sdo_segment_response",
          "sdo_abort_response", "j1939_switch_to_canopen"):
    if not checked.get(k):
        fail(f"no {k} frame in the sample logs was checked")

# --- the J1939 frames the manuals print ------------------------------------------------------------
# powerkey decode reads no J1939 frame but the switch yet, so the manuals' examples (docs/j1939.md,
# the section of the PKP1600SI or PKP2600SI J1939 manual in each row) are checked here against
# what the manual says they mean; tests/test_dbc.cpp checks every J1939 row of the library's tests
# against the J1939 codec.
J1939_ROWS = [
    # model, section, frame, command, {signal: raw value}
    ("pkp1600si", "6", "18EFFF21#041B01010121FFFF", "j1939_key_contact",
     {"key": 1, "pressed": 1, "identifier": 0x21}),
    ("pkp1600si", "7a", "18EF2100#041B0106010302FF", "j1939_set_led",
     {"led_key": 6, "led_colour": "red", "led_mode": "alternate_blink", "led_secondary": "green"}),
    ("pkp1600si", "21", "18EFFF21#041BF9030200FF21", "j1939_heartbeat",
     {"heartbeat_counter": 3, "heartbeat_key2": 1, "heartbeat_key1": 0,
      "heartbeat_identifier": 0x21}),
    ("pkp2600si", "21", "18EFFF21#041BF9030008FF21", "j1939_heartbeat",
     {"heartbeat_counter": 3, "heartbeat_key12": 1, "heartbeat_key4": 0}),
    ("pkp1600si", "21", "18EF2100#041B7501FEFFFFFF", "set_heartbeat",
     {"heartbeat_enabled": 1, "heartbeat_period_ms": 254}),
    ("pkp1600si", "22", "18EF2100#041B7764FFFFFFFF", "set_key_period", {"key_period_ms": 100}),
    ("pkp1600si", "16", "18EF2100#041B70FDFDFFFFFF", "set_source_address",
     {"source_address": 0xFD, "source_address_identifier": 0xFD}),
    ("pkp1600si", "15", "18EF2100#041B6F02FFFFFFFF", "set_baud_rate", {"baud_rate": "kbit_500"}),
    ("pkp1600si", "26", "18EF2100#041B7D06FFFFFFFF", "set_default_backlight_colour",
     {"default_backlight_colour": "violet"}),
    ("pkp1600si", "8", "18EF2100#041B0220FFFFFFFF", "set_led_brightness",
     {"led_brightness_level": 0x20}),
    ("pkp2600si", "27", "18EF2100#041B8000FFFFFFFF", "j1939_switch_to_canopen",
     {"switch_to_canopen_byte3": 0}),
]
for model, section, text, command, want in J1939_ROWS:
    label = f"{model} J1939 section {section} {text}"
    ident, data = text.split("#")
    aid = canmatrix.ArbitrationId(int(ident, 16), extended=True)
    decoded = dbs[model].decode(aid, bytes.fromhex(data))
    got = decoded.get("command")
    if got is None or got.named_value != command:
        fail(f"{label}: command {got.named_value if got else None!r}, want {command}")
        continue
    for name, value in want.items():
        d = decoded.get(name)
        v = None if d is None else (d.named_value if isinstance(value, str) else d.raw_value)
        if v != value:
            fail(f"{label}: {name}: canmatrix {v!r}, the manual {value!r}")
# The attributes J1939 tools read: every J1939 message is J1939PG on PGN EF00h, the nodes have
# their addresses.
for model, db in dbs.items():
    j1939 = [f for f in db.frames if f.arbitration_id.extended]
    if not db.contains_j1939 or not j1939 or not all(f.is_j1939 for f in j1939):
        fail(f"{model}: canmatrix reads no J1939PG message")
    if any(f.pgn != 0xEF00 for f in j1939) or any(f.is_j1939 for f in db.frames if f not in j1939):
        fail(f"{model}: J1939 messages: PGNs {[hex(f.pgn) for f in j1939]}")
    addresses = {e.name: e.attributes.get("NmStationAddress") for e in db.ecus}
    if {k: int(v) for k, v in addresses.items()} != {"keypad": 0x21, "controller": 0x00}:
        fail(f"{model}: NmStationAddress {addresses}")
    if db.attributes.get("ProtocolType") != "J1939":
        fail(f"{model}: ProtocolType {db.attributes.get('ProtocolType')!r}")


# --- every key and LED, one at a time ------------------------------------------------------------
def one_at_a_time(model, db):
    cases = []  # (message name, signal name, JSON line)
    fields_of = {"led_on": ("red", "green", "blue"), "led_blink": ("red", "green", "blue")}
    for k in range(1, 17):
        cases.append(("key_state", f"key{k}", {"kind": "key_state",
                                                "fields": {"keys": [k], "tick": 0}}))
    for kind, planes in fields_of.items():
        for p in planes:
            for k in range(1, 33):
                f = {q: ([k] if q == p else []) for q in planes}
                cases.append((kind, f"{p}{k}", {"kind": kind, "fields": f}))
    if frame_of(db, 0x400 + NODE) is not None and frame_of(db, 0x400 + NODE).name == "encoder_leds":
        for k in range(1, 33):
            cases.append(("encoder_leds", f"led{k}", {"kind": "encoder_leds",
                                                      "fields": {"leds": [k]}}))
    # One file per case: the tool names at most three refused lines of a file (docs/cli.md), and
    # each refusal must be told from the others.
    with tempfile.TemporaryDirectory() as tmp:
        paths = []
        for i, (_, _, c) in enumerate(cases, 1):
            paths.append(os.path.join(tmp, f"{i}.json"))
            with open(paths[-1], "w") as out:
                out.write(json.dumps({"model": model, "node": NODE, **c}) + "\n")
        r = run("encode", "--json", *paths)
    refused = {int(x) for x in re.findall(r"/(\d+)\.json:1:", r.stderr)}
    frames = iter(r.stdout.split())
    by_name = {f.name: f for f in db.frames}
    for i, (message, signal, _) in enumerate(cases, 1):
        frame = by_name.get(message)
        has = frame is not None and frame.signal_by_name(signal) is not None
        if i in refused:
            if has:
                fail(f"{model}: {message}.{signal}: the library refuses it, the DBC has it")
            continue
        text = next(frames, None)
        if text is None:
            fail(f"{model}: encode --json wrote fewer frames than it accepted")
            return
        ident, data = text.split("#")
        if not has:
            fail(f"{model}: {message}.{signal}: the library encodes it ({text}), the DBC lacks it")
            continue
        decoded = frame_of(db, int(ident, 16)).decode(bytes.fromhex(data))
        on = sorted(n for n, d in decoded.items() if d.raw_value and n != "tick")
        if on != [signal]:
            fail(f"{model}: {text} ({message} {signal} alone) decodes to {on}")


for model in models:
    one_at_a_time(model, dbs[model])

# --- another node id -----------------------------------------------------------------------------
moved = load(export("pkp3500mt", "0x3A"), "pkp3500mt --node 0x3A")
base = dbs["pkp3500mt"]
for f in base.frames:
    ident = f.arbitration_id.id
    # NMT and SYNC are every node's; the J1939 messages are at the J1939 addresses (21h), which
    # the CANopen node id does not move.
    fixed = ident in (0x000, 0x080) or f.arbitration_id.extended
    want = ident if fixed else ident - NODE + 0x3A
    g = moved.frame_by_name(f.name)
    if g is None or g.arbitration_id.id != want:
        fail(f"--node 0x3A: {f.name} at {g.arbitration_id.id if g else None:#x}, want {want:#x}")
r = run("encode", "--model", "pkp3500mt", "--node", "0x3A", "led-on", "green=15", "blue=2")
ident, data = r.stdout.strip().split("#")
decoded = frame_of(moved, int(ident, 16)).decode(bytes.fromhex(data))
if sorted(n for n, d in decoded.items() if d.raw_value) != ["blue2", "green15"]:
    fail(f"--node 0x3A: {r.stdout.strip()} decodes to {decoded}")

# --- the example of docs/dbc.md runs and prints what the page shows -----------------------------
doc = open(f"{src}/docs/dbc.md").read()
blocks = re.findall(r"```python\n(.*?)```", doc, re.S)
shown = re.search(r"It prints the set signals of each frame:\n\n```\n(.*?)```", doc, re.S)
if len(blocks) != 1 or not shown:
    fail("docs/dbc.md: want one python block and the output it prints")
else:
    r = subprocess.run([sys.executable, "-c", blocks[0]], cwd=src, capture_output=True, text=True)
    printed = r.stdout.splitlines()
    if r.returncode != 0:
        fail(f"docs/dbc.md example: exit status {r.returncode}: {r.stderr.strip()[-300:]}")
    for line in shown.group(1).splitlines():
        if line not in printed:
            fail(f"docs/dbc.md example does not print {line!r}")

# --- where canmatrix and the DBC format differ (docs/dbc.md) --------------------------------------
# Each probe prints what canmatrix does; the files do not depend on it.
for model, db in dbs.items():
    keypad = db.ecu_by_name("keypad")
    if keypad is None or not keypad.comment or model not in keypad.comment:
        fail(f"{model}: the keypad node has no comment naming the model")
probe = ('VERSION ""\n\nNS_ :\n\nBS_:\n\nBU_: keypad controller\n\n'
         'BO_ 405 key_state: 5 keypad\n SG_ tick : 32|8@1+ (1,0) [0|255] "" controller\n\n'
         'CM_ "a comment on the whole database";\n')
with contextlib.redirect_stdout(io.StringIO()):
    db = canmatrix.formats.dbc.load(io.BytesIO(probe.encode("ascii")))
if "a comment on the whole database" not in repr(vars(db)):
    print("canmatrix differs from the DBC format: it drops a comment on the whole database "
          "(CM_ \"...\"); the files describe the keypad in its node's comment")
try:
    db.frame_by_name("key_state").decode(bytes(4))
    print("canmatrix decodes a frame shorter than its message's length")
except canmatrix.canmatrix.DecodingFrameLength:
    print("canmatrix refuses a frame whose length is not its message's (the DBC format leaves "
          "it to the tool); the library refuses it too (wrong_length)")

# With a J1939PG message in the file, Matrix.decode() looks only at 29-bit identifiers: an 11-bit
# frame decodes to nothing through it, while frame_by_id(...).decode() reads it (as the example
# of docs/dbc.md and these tests do).
db = dbs["pkp2400"]
if not db.decode(canmatrix.ArbitrationId(0x195, extended=False), bytes(5)):
    print("canmatrix differs from the DBC format: in a file with J1939 messages, Matrix.decode() "
          "decodes no 11-bit frame; frame_by_id(id).decode(data) does")
# A 29-bit identifier it does not know (other addresses) it looks up by PGN, through every
# message: an 11-bit one makes that raise.
try:
    unknown = db.decode(canmatrix.ArbitrationId(0x18EF2105, extended=True),
                        bytes.fromhex("041B0101020200FF"))
    print("canmatrix matches an unknown J1939 identifier by its PGN: "
          f"{'decoded' if unknown else 'nothing found'}")
except canmatrix.canmatrix.J1939needsExtendedIdetifier:
    print("canmatrix differs from the DBC format: Matrix.decode() of a J1939 identifier the file "
          "does not have raises J1939needsExtendedIdetifier (its search by PGN reads the PGN of "
          "the 11-bit messages too); the files' J1939 messages are found by their identifier")

if failures:
    print(f"{len(failures)} failures")
    sys.exit(1)
print(f"dbc: {len(models)} models: all checks passed")
