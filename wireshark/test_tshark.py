#!/usr/bin/env python3
"""The Wireshark plugin under tshark, frame for frame against the powerkey tool and against
Wireshark's own CANopen dissector (registered by wireshark/CMakeLists.txt as wireshark_tshark).

    test_tshark.py --build-dir BUILD --tool POWERKEY --source SOURCE_DIR --work DIR

For every sample log examples/logs/*.log, written as a SocketCAN pcap by `powerkey convert`, with the model its file
name names (pk1000.log, session-pk1000.log; one of `powerkey models`, the names powerkey.model
takes too), or the default model (pk1000) when the name names none:
  - tshark (scripts/tshark.sh, -o powerkey.model:MODEL) and `powerkey decode --model MODEL --json`
    agree on every frame: kind, error, function, node, SDO index and sub-index, the SDO pairing,
    the string of a segmented upload, the node-id and protocol changes, and every message field;
    the Info column is the tool's text output;
  - with the plugin disabled and "Decode As CANopen", Wireshark's CANopen dissector finds the
    same function, node, index and sub-index as powerkey;
  - a second pass (tshark -2, frames dissected again from the stored session state) shows the
    same fields as the first.
Then frames of other nodes stay with the generic dissectors, the node preference moves the
keypad, text from the bus is escaped, and filters select the frames the tool names.

The pcap captures are written by `powerkey convert --to pcap`, the tool's own log reader (so
tshark reads what the tool reads); without a working tool the script exits 77, which ctest
reports as skipped. Exits 1 naming every difference.
"""
import argparse
import glob
import json
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

# CiA 301 function codes (COB-ID bits 10..7) as Wireshark's canopen.function_code shows them.
FUNCTION_CODES = {"nmt": 0x0, "sync": 0x1, "tpdo1": 0x3, "rpdo1": 0x4, "tpdo2": 0x5,
                  "rpdo2": 0x6, "tpdo3": 0x7, "rpdo3": 0x8, "tpdo4": 0x9, "rpdo4": 0xA,
                  "sdo_tx": 0xB, "sdo_rx": 0xC, "heartbeat": 0xE}
PER_NODE = set(FUNCTION_CODES) - {"nmt", "sync"}
# The generic fields' names (wireshark/plugin.cpp, generic_name), and Wireshark's longest label.
GENERIC_NAMES = {"kind", "error", "function", "node", "model", "sdo", "session", "j1939"}
ITEM_LABEL_LENGTH = 240

failures = []
# The exit status without a working tool (ctest SKIP_RETURN_CODE).
SKIPPED = 77


def fail(where, what):
    failures.append(f"{where}: {what}")


class runner:
    def __init__(self, args):
        self.args = args
        # scripts/tshark.sh's temporary files go to a directory of their own, which must stay
        # empty (check_no_leftovers).
        self.tmp = os.path.join(args.work, "tmp")
        os.makedirs(self.tmp, exist_ok=True)
        for f in os.listdir(self.tmp):
            os.remove(os.path.join(self.tmp, f))
        self.env = dict(os.environ, POWERKEY_BUILD_DIR=args.build_dir, POWERKEY_TSHARK_BUILD="0",
                        TMPDIR=self.tmp)
        self.has_tool = self.tool_works()

    def tshark(self, *argv):
        cmd = ["bash", os.path.join(self.args.source, "scripts", "tshark.sh"), *argv]
        r = subprocess.run(cmd, env=self.env, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"{' '.join(cmd)}: exit status {r.returncode}\n{r.stderr}")
        return r.stdout

    def tool_works(self):
        """The tool decodes an NMT start as JSON with a kind (not just: the file exists)."""
        if not os.access(self.args.tool, os.X_OK):
            return False
        r = subprocess.run([self.args.tool, "decode", "--json", "-"], input="000#0115\n",
                           capture_output=True, text=True)
        try:
            return r.returncode == 0 and json.loads(r.stdout).get("kind") == "nmt_message"
        except ValueError:
            return False

    def tool(self, *argv):
        r = subprocess.run([self.args.tool, *argv], capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"powerkey {' '.join(argv)}: exit status {r.returncode}\n{r.stderr}")
        return r.stdout.splitlines()

    def pcap(self, log, name):
        out = os.path.join(self.args.work, name + ".pcap")
        self.tool("convert", "--to", "pcap", "-o", out, log)
        return out

    def models(self):
        """The models powerkey.model and --model take (the library's model table)."""
        return [line.split()[0] for line in self.tool("models")]


def pdml_frames(text):
    """Per frame: the powerkey fields as {name: [(show, showname)]}, the powerkey item's text,
    and the protocols in the frame."""
    frames = []
    for packet in ET.fromstring(text).iter("packet"):
        fields, title, protocols = {}, None, ""
        for proto in packet.iter("proto"):
            if proto.get("name") == "powerkey":
                title = proto.get("showname")
                for f in proto.iter("field"):
                    fields.setdefault(f.get("name"), []).append(
                        (f.get("show"), f.get("showname")))
        for f in packet.iter("field"):
            if f.get("name") == "frame.protocols":
                protocols = f.get("show")
        frames.append({"fields": fields, "title": title, "protocols": protocols})
    return frames


def one(frame, name):
    values = frame["fields"].get(name, [])
    return values[0][0] if len(values) == 1 else (None if not values else "several")


def set_text(numbers):
    """A key or LED set as describe() writes it: "1 7", "1-28", "-"."""
    parts, i, s = [], 0, sorted(numbers)
    while i < len(s):
        j = i
        while j + 1 < len(s) and s[j + 1] == s[j] + 1:
            j += 1
        if j - i >= 2:
            parts.append(f"{s[i]}-{s[j]}")
        else:
            parts.extend(str(n) for n in s[i:j + 1])
        i = j + 1
    return " ".join(parts) or "-"


def field_matches(name, want, show, showname):
    """A message field of `decode --json` against tshark's field (show and showname)."""
    if isinstance(want, bool):
        return show == ("1" if want else "0") and showname == f"{name}: {'yes' if want else 'no'}"
    if isinstance(want, int):
        try:
            return int(show, 0) == want
        except ValueError:
            return False
    if isinstance(want, list):
        return show == set_text(want)
    # A string: an enumerator's name (a text field, or a number field with value names), or
    # raw bytes in hex.
    return (show == want or showname == f"{name}: {want}" or
            show.replace(":", "").upper() == want)


def tool_text(line):
    """The tool's text output without the frame: "node 15h  ...", or "j1939  error: ..." for a
    J1939 frame refused (it has no node)."""
    at = line.find("node ")
    return line[at:] if at >= 0 else line[line.index("j1939  "):]


def model_of_log(path, models):
    """The model a log's file name names (the longest choice that is a word of its name:
    pkp2400.log, session-pk1000.log), or None for the default model."""
    words = re.split(r"[-_.]", os.path.basename(path)[:-len(".log")])
    named = [m for m in models if m in words]
    return max(named, key=len) if named else None


def compare_canopen(at, f, co):
    """powerkey's function, node, index and sub-index against Wireshark's CANopen dissector."""
    function = one(f, "powerkey.function")
    if function in (None, "several", "j1939"):
        return
    code, node, index, subindex = (co.split("\t") + ["", "", "", ""])[:4]
    if function not in FUNCTION_CODES:
        fail(at, f"powerkey.function {function} on a CANopen frame")
        return
    if int(code, 16) != FUNCTION_CODES[function]:
        fail(at, f"canopen.function_code {code}, powerkey.function {function}")
    want_node = int(one(f, "powerkey.node"), 0) if function in PER_NODE else 0
    if int(node, 16) != want_node:
        fail(at, f"canopen.node_id {node}, powerkey says {want_node}")
    ours = one(f, "powerkey.sdo.index"), one(f, "powerkey.sdo.subindex")
    theirs = (int(index, 16) if index else None), (int(subindex, 16) if subindex else None)
    ours = tuple(None if v is None else int(v, 0) for v in ours)
    if ours != theirs:
        fail(at, f"SDO index/sub-index {ours} in powerkey, {theirs} in canopen")


def compare_log(run, log, model):
    name = os.path.basename(log)[:-len(".log")]
    pcap = run.pcap(log, name)
    where = f"{name} ({model or 'default model'})"
    prefs = ["-o", f"powerkey.model:{model}"] if model else []
    frames = pdml_frames(run.tshark("-r", pcap, *prefs, "-T", "pdml"))
    infos = run.tshark("-r", pcap, *prefs, "-T", "fields", "-e", "_ws.col.Info").splitlines()
    canopen = run.tshark("-r", pcap, "--disable-protocol", "powerkey",
                         "-d", "can.subdissector,canopen", "-T", "fields",
                         "-e", "canopen.function_code", "-e", "canopen.node_id",
                         "-e", "canopen.sdo.main_idx", "-e", "canopen.sdo.sub_idx").splitlines()
    # A second pass dissects every frame again from the state the first pass stored.
    second = pdml_frames(run.tshark("-2", "-r", pcap, *prefs, "-T", "pdml"))
    if not (len(frames) == len(infos) == len(canopen) == len(second)) or not frames:
        fail(where, f"{len(frames)} frames in tshark, {len(infos)} Info lines, {len(canopen)} "
                    f"from the CANopen dissector, {len(second)} in the second pass")
        return
    for n, (f, info, co, f2) in enumerate(zip(frames, infos, canopen, second), 1):
        at = f"{where} frame {n}"
        if f["title"] is None:
            if f2["title"] is not None:
                fail(at, "dissected by powerkey in the second pass only")
            continue
        want = "Blink Marine PowerKey keypad, " + info
        # Wireshark cuts a tree item's label at ITEM_LABEL_LENGTH (a J1939 address claim's line
        # is longer): the label is then the beginning of the line.
        cut = len(f["title"]) == ITEM_LABEL_LENGTH - 1 and want.startswith(f["title"])
        if f["title"] != want and not cut:
            fail(at, f"tree item {f['title']!r}, Info column {info!r}")
        if (f2["title"], f2["fields"]) != (f["title"], f["fields"]):
            fail(at, f"the second pass shows {f2['title']!r}, the first {f['title']!r}")
        compare_canopen(at, f, co)
    model_args = ["--model", model] if model else []
    tool_json = [json.loads(l) for l in run.tool("decode", *model_args, "--json", log)]
    tool_lines = run.tool("decode", *model_args, log)
    if not (len(frames) == len(tool_json) == len(tool_lines)):
        fail(where, f"{len(frames)} frames in tshark, {len(tool_json)} JSON lines, "
                    f"{len(tool_lines)} text lines")
        return
    for n, (f, j, text, info) in enumerate(zip(frames, tool_json, tool_lines, infos), 1):
        at = f"{where} frame {n} ({j['id']}#{j['data']})"
        if f["title"] is None:
            # Only another node's frame (the keypad has moved away from its COB-ID) or an NMT
            # command for another node stays with the generic dissectors.
            other_nmt = j.get("kind") == "nmt_message" and j["fields"]["target"] not in (0, j["node"])
            if j.get("error") != "wrong_id" and not other_nmt:
                fail(at, f"not dissected by powerkey (protocols {f['protocols']}), the tool "
                         f"says {j.get('kind') or j.get('error')}")
            continue
        # The generic values, key by key as decode --json writes them.
        expect = {
            "powerkey.kind": j.get("kind"),
            "powerkey.error": j.get("error"),
            "powerkey.function": j["function"],
            "powerkey.node": j["node"],
            "powerkey.model": j["model"],
            "powerkey.sdo.index": j.get("index"),
            "powerkey.sdo.subindex": j.get("subindex"),
            "powerkey.sdo.pairing": j.get("sdo"),
            "powerkey.sdo.text": j.get("text"),
            "powerkey.sdo.upload_error": j.get("upload_error"),
            "powerkey.session.new_node": j.get("new_node"),
            "powerkey.session.protocol": j.get("protocol"),
            "powerkey.session.new_address": j.get("new_address"),
            "powerkey.j1939.pgn": j.get("pgn"),
        }
        for key, want in expect.items():
            got = one(f, key)
            if isinstance(want, int) and got not in (None, "several"):
                got = int(got, 0)
            if got != want:
                fail(at, f"{key} is {got!r}, decode --json says {want!r}")
        # The request a reply answers: the tool's "[reply to IIIIh sub S]".
        if j.get("sdo") == "reply":
            reply = f"[reply to {int(one(f, 'powerkey.sdo.reply_to.index'), 0):04X}h sub " \
                    f"{int(one(f, 'powerkey.sdo.reply_to.subindex'), 0)}]"
            if reply not in text:
                fail(at, f"{reply} is not in the tool's line: {text}")
        # Every message field, under its own filter name, and no other.
        extra = {k for k in f["fields"] if k.startswith("powerkey.") and k.count(".") == 1} - \
            set(expect) - \
            {f"powerkey.{field}" for field in j.get("fields", {})} - {"powerkey.refused"}
        if extra:
            fail(at, f"fields the message does not have: {sorted(extra)}")
        for field, want in j.get("fields", {}).items():
            # A message field named as a generic one is under powerkey.field. (the J1939 NAME's
            # "function"; plugin.cpp, generic_name).
            key = f"powerkey.field.{field}" if field in GENERIC_NAMES else f"powerkey.{field}"
            values = f["fields"].get(key, [])
            if len(values) != 1 or not field_matches(field, want, *values[0]):
                fail(at, f"powerkey.{field} is {values!r}, decode --json says {want!r}")
        # The tree and the Info column read like the tool's text output.
        if info != tool_text(text):
            fail(at, f"Info column {info!r}, the tool writes {tool_text(text)!r}")


def check_beside_j1939(run):
    """With Decode As J1939, Wireshark's J1939 dissector and the plugin both dissect the keypads'
    J1939 frames: the J1939 PGN and the keypad's kind on every frame of the switch log that the
    tool reads as a J1939 message."""
    log = os.path.join(run.args.source, "examples", "logs", "switch-pkp2600si.log")
    pcap = run.pcap(log, "beside-j1939")
    rows = run.tshark("-r", pcap, "-o", "powerkey.model:pkp2600si", "-d", "can.subdissector,j1939",
                      "-T", "fields", "-e", "j1939.pgn", "-e", "powerkey.kind").splitlines()
    tool = [json.loads(l) for l in run.tool("decode", "--model", "pkp2600si", "--json", log)]
    if len(rows) != len(tool):
        fail("beside J1939", f"{len(rows)} frames in tshark, {len(tool)} in the tool")
        return
    j1939 = 0
    for n, (row, j) in enumerate(zip(rows, tool), 1):
        if not j["ext"]:
            continue
        j1939 += 1
        pgn, kind = (row.split("\t") + [""])[:2]
        if pgn != str(j["pgn"]) or kind != j.get("kind"):
            fail(f"beside J1939 frame {n}", f"j1939.pgn {pgn!r}, powerkey.kind {kind!r}; the "
                                            f"tool says PGN {j['pgn']}, {j.get('kind')}")
    if j1939 == 0:
        fail("beside J1939", "no J1939 frame in the switch log")


def check_other_frames(run):
    """Frames the keypad does not own stay with the generic dissectors."""
    log = os.path.join(run.args.work, "other.log")
    rows = [
        # frame, what powerkey shows (kind or error:code) or None, protocols in the frame,
        # protocols with "Decode As CANopen"
        ("000#0115", "nmt_message", "can:powerkey", "can:powerkey"),
        ("000#0116", None, "can:autosar-nm", "can:canopen"),  # NMT for node 16h
        ("616#4008100000000000", None, "can:data", "can:canopen"),  # an SDO of node 16h
        ("196#0100000010", None, "can:data", "can:canopen"),  # a PDO of node 16h
        ("615#40", "error:wrong_length", "can:powerkey", "can:powerkey"),  # too short
        ("18EF2100#041B8000FFFFFFFF", "j1939_switch_to_canopen", "can:powerkey",
         "can:powerkey"),
        ("18FEF100#0000000000000000", None, "can:data", "can:data"),  # PGN FEF1h
        ("715#7F", "heartbeat_message", "can:powerkey", "can:powerkey"),
    ]
    with open(log, "w") as out:
        out.write("".join(r[0] + "\n" for r in rows))
    frames = pdml_frames(run.tshark("-r", run.pcap(log, "other"), "-T", "pdml"))
    tool_json = [json.loads(l) for l in run.tool("decode", "--json", log)]
    # The plugin comes before "Decode As CANopen" too, and leaves it the other nodes' frames.
    decode_as = run.tshark("-r", run.pcap(log, "other"), "-d", "can.subdissector,canopen",
                           "-T", "fields", "-e", "frame.protocols").splitlines()
    if decode_as != [r[3] for r in rows]:
        fail("other frames", f"with Decode As CANopen: {decode_as}")
    for (frame, want, protocols, _), f, j in zip(rows, frames, tool_json):
        at = f"other frames: {frame}"
        if f["protocols"] != protocols:
            fail(at, f"protocols {f['protocols']}, expected {protocols}")
        if want is None:
            if f["fields"]:
                fail(at, f"dissected by powerkey: {f['title']}")
            continue
        got = one(f, "powerkey.kind") or f"error:{one(f, 'powerkey.error')}"
        tool = want if j is None else (j.get("kind") or f"error:{j.get('error')}")
        if got != want or tool != want:
            fail(at, f"powerkey shows {got}, the tool {tool}, expected {want}")
    if len(frames) != len(rows):
        fail("other frames", f"{len(frames)} frames for {len(rows)} lines")
    # The refused frame of the keypad carries an expert warning; no other frame does.
    refused = run.tshark("-r", run.pcap(log, "other"), "-Y", "powerkey.refused",
                         "-T", "fields", "-e", "frame.number").split()
    if refused != ["5"]:
        fail("other frames", f"expert powerkey.refused on frames {refused}, expected ['5']")


def check_node_preference(run):
    """-o powerkey.node:3A (hex, as the tool's 3Ah) makes node 3Ah's frames the keypad's."""
    log = os.path.join(run.args.work, "node.log")
    with open(log, "w") as out:
        out.write("63A#4008100000000000\n615#4008100000000000\n")
    got = run.tshark("-r", run.pcap(log, "node"), "-o", "powerkey.node:3A", "-T", "fields",
                     "-e", "powerkey.kind", "-e", "powerkey.node").splitlines()
    if got != ["sdo_read\t0x3a", "\t"]:
        fail("node preference", f"got {got}")


def check_escaping(run):
    """A device name with a newline, a bell and a quote reaches the user escaped."""
    log = os.path.join(run.args.work, "escape.log")
    with open(log, "w") as out:
        out.write("615#4008100000000000\n"  # read 1008h
                  "595#4108100005000000\n"  # segmented, 5 bytes
                  "615#6000000000000000\n"  # first segment
                  "595#05410A420722FFFF\n")  # last segment: A \n B BEL "
    pcap = run.pcap(log, "escape")
    got = run.tshark("-r", pcap, "-T", "fields", "-e", "powerkey.sdo.text").splitlines()
    if got != ["", "", "", 'A\\nB\\a"']:
        fail("escaping", f"powerkey.sdo.text {got}")
    info = run.tshark("-r", pcap, "-T", "fields", "-e", "_ws.col.Info").splitlines()
    if not info or not info[-1].endswith('[text: "A\\nB\\a""]'):
        fail("escaping", f"Info column {info[-1:]}")


def check_filters(run):
    """Filters by field, by value name and by kind select the frames decode --json names (without
    the tool: the frames whose tree shows that value)."""
    log = os.path.join(run.args.source, "examples", "logs", "pkp2400.log")
    pcap = run.pcap(log, "pkp2400-filters")
    prefs = ["-o", "powerkey.model:pkp2400"]

    def frames(expr):
        out = run.tshark("-r", pcap, *prefs, "-Y", expr, "-T", "fields", "-e", "frame.number")
        return [int(n) for n in out.split()]

    tool_json = [json.loads(l) for l in run.tool("decode", "--model", "pkp2400", "--json", log)]
    lines = run.tool("decode", "--model", "pkp2400", log)

    def expect(test):
        return [n for n, j in enumerate(tool_json, 1) if test(j)]

    cases = [
        ('powerkey.kind == "led_on"', lambda j: j.get("kind") == "led_on"),
        ('powerkey.command == "start"',
         lambda j: j.get("kind") == "nmt_message" and j["fields"]["command"] == "start"),
        ('powerkey.red == "1 4 5 7"', lambda j: j.get("fields", {}).get("red") == [1, 4, 5, 7]),
        ("powerkey.sdo.pairing == \"unanswered\"", lambda j: j.get("sdo") == "unanswered"),
    ]
    for expr, test in cases:
        got, want = frames(expr), expect(test)
        if got != want or not want:
            fail(f"filter {expr}", f"frames {got}, expected {want}")
    # The replies to a read of 1008h: the frames the tool's text marks [reply to 1008h sub 0].
    got = frames("powerkey.sdo.reply_to.index == 0x1008")
    want = [n for n, l in enumerate(lines, 1) if "[reply to 1008h sub 0]" in l]
    if got != want or not want:
        fail("filter powerkey.sdo.reply_to.index == 0x1008", f"frames {got}, expected {want}")


def check_no_leftovers(run):
    """scripts/tshark.sh cleans up after itself: nothing is left in its TMPDIR."""
    left = os.listdir(run.tmp)
    if left:
        fail("scripts/tshark.sh", f"left {left} in its TMPDIR")


def check_model_preference(run):
    """powerkey.model takes the names --model takes, and says so when it does not know one."""
    log = os.path.join(run.args.work, "model.log")
    with open(log, "w") as out:
        out.write("195#0100000010\n")
    pcap = run.pcap(log, "model")
    for name in ("pkp2400", "PKP-2400-LI", "pkp-2400", "PKU2400"):
        got = run.tshark("-r", pcap, "-o", f"powerkey.model:{name}", "-T", "fields",
                         "-e", "powerkey.model").split()
        if got != ["pkp2400"]:
            fail("model preference", f"{name}: decoded as {got}")
    cmd = ["bash", os.path.join(run.args.source, "scripts", "tshark.sh"), "-r", pcap, "-o",
           "powerkey.model:pkp2401", "-T", "fields", "-e", "powerkey.model"]
    r = subprocess.run(cmd, env=run.env, capture_output=True, text=True)
    if "unknown model 'pkp2401'" not in r.stderr:
        fail("model preference", f"pkp2401: status {r.returncode}, {r.stderr.strip()!r}")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--build-dir", required=True)
    p.add_argument("--tool", required=True)
    p.add_argument("--source", required=True)
    p.add_argument("--work", required=True)
    args = p.parse_args()
    os.makedirs(args.work, exist_ok=True)
    run = runner(args)
    if not run.has_tool:
        print(f"SKIPPED: no working powerkey tool at {args.tool} (it writes the pcap captures)")
        return SKIPPED
    models = run.models()
    logs = sorted(glob.glob(os.path.join(args.source, "examples", "logs", "*.log")))
    for log in logs:
        compare_log(run, log, model_of_log(log, models))
    check_other_frames(run)
    check_beside_j1939(run)
    check_node_preference(run)
    check_escaping(run)
    check_filters(run)
    check_model_preference(run)
    check_no_leftovers(run)
    shown = {}
    for f in failures:  # at most 15 per check, so that each failing check shows
        section = f.split(" frame ")[0].split(":")[0]
        shown[section] = shown.get(section, 0) + 1
        if shown[section] <= 15:
            print("FAIL:", f)
    if failures:
        print(f"{len(failures)} differences")
        return 1
    print(f"wireshark: {len(logs)} sample logs ({', '.join(os.path.basename(l) for l in logs)}): "
          "every frame powerkey takes is the same in a second pass and as the CANopen dissector "
          "sees it")
    print("wireshark: every sample frame agrees with decode --json and with the CANopen dissector")
    return 0


if __name__ == "__main__":
    sys.exit(main())
