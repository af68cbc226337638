#!/usr/bin/env python3
"""The Wireshark plugin under tshark, frame for frame against the powerkey tool and against
Wireshark's own CANopen dissector (registered by wireshark/CMakeLists.txt as wireshark_tshark).

    test_tshark.py --build-dir BUILD --tool POWERKEY --source SOURCE_DIR --work DIR

For every sample log examples/logs/MODEL.log, written as a SocketCAN pcap:
  - tshark (scripts/tshark.sh, -o powerkey.model:MODEL) and `powerkey decode --model MODEL --json`
    agree on every frame: kind, error, function, node, SDO index and sub-index, the SDO pairing,
    the string of a segmented upload, the node-id and protocol changes, and every message field;
    the Info column is the tool's text output;
  - with the plugin disabled and "Decode As CANopen", Wireshark's CANopen dissector finds the
    same function, node, index and sub-index;
  - a second pass (tshark -2, frames dissected again from the stored session state) shows the
    same.
Then frames of other nodes stay with the generic dissectors, the node preference moves the
keypad, and text from the bus is escaped. Exits 1 naming every difference.
"""
import argparse
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
MODELS = ["pk1000", "pkp2200", "pkp2400", "pkp2600"]
# CiA 301 function codes (COB-ID bits 10..7) as Wireshark's canopen.function_code shows them.
FUNCTION_CODES = {"nmt": 0x0, "sync": 0x1, "tpdo1": 0x3, "rpdo1": 0x4, "rpdo2": 0x6,
                  "rpdo3": 0x8, "rpdo4": 0xA, "sdo_tx": 0xB, "sdo_rx": 0xC, "heartbeat": 0xE}
PER_NODE = {"tpdo1", "rpdo1", "rpdo2", "rpdo3", "rpdo4", "sdo_tx", "sdo_rx", "heartbeat"}

failures = []


def fail(where, what):
    failures.append(f"{where}: {what}")


class runner:
    def __init__(self, args):
        self.args = args
        self.env = dict(os.environ, POWERKEY_BUILD_DIR=args.build_dir, POWERKEY_TSHARK_BUILD="0")

    def tshark(self, *argv):
        cmd = ["bash", os.path.join(self.args.source, "scripts", "tshark.sh"), *argv]
        r = subprocess.run(cmd, env=self.env, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"{' '.join(cmd)}: exit status {r.returncode}\n{r.stderr}")
        return r.stdout

    def tool(self, *argv):
        r = subprocess.run([self.args.tool, *argv], capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"powerkey {' '.join(argv)}: exit status {r.returncode}\n{r.stderr}")
        return r.stdout.splitlines()

    def pcap(self, log, name):
        out = os.path.join(self.args.work, name + ".pcap")
        subprocess.run([sys.executable, os.path.join(HERE, "candump2pcap.py"), log, out],
                       check=True)
        return out


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
    return (show == want or showname.startswith(f"{name}: {want} (") or
            show.replace(":", "").upper() == want)


def tool_text(line):
    """The tool's text output without the frame: "node 15h  ..."."""
    return line[line.index("node "):]


def compare_model(run, model, two_pass=False):
    log = os.path.join(run.args.source, "examples", "logs", model + ".log")
    pcap = run.pcap(log, model)
    where = f"{model}{' (tshark -2)' if two_pass else ''}"
    frames = pdml_frames(run.tshark(*(["-2"] if two_pass else []), "-r", pcap,
                                    "-o", f"powerkey.model:{model}", "-T", "pdml"))
    infos = run.tshark(*(["-2"] if two_pass else []), "-r", pcap, "-o", f"powerkey.model:{model}",
                       "-T", "fields", "-e", "_ws.col.Info").splitlines()
    tool_json = [json.loads(l) for l in run.tool("decode", "--model", model, "--json", log)]
    tool_lines = run.tool("decode", "--model", model, log)
    if not (len(frames) == len(tool_json) == len(tool_lines) == len(infos)):
        fail(where, f"{len(frames)} frames in tshark, {len(infos)} Info lines, "
                    f"{len(tool_json)} JSON lines, {len(tool_lines)} text lines")
        return
    canopen = run.tshark("-r", pcap, "--disable-protocol", "powerkey",
                         "-d", "can.subdissector,canopen", "-T", "fields",
                         "-e", "canopen.function_code", "-e", "canopen.node_id",
                         "-e", "canopen.sdo.main_idx", "-e", "canopen.sdo.sub_idx").splitlines()
    if len(canopen) != len(frames):
        fail(where, f"{len(canopen)} frames from the CANopen dissector")
        return
    for n, (f, j, text, info, co) in enumerate(
            zip(frames, tool_json, tool_lines, infos, canopen), 1):
        at = f"{where} frame {n} ({j['id']}#{j['data']})"
        if f["title"] is None:
            fail(at, f"not dissected by powerkey (protocols {f['protocols']})")
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
            "powerkey.j1939.pgn": j.get("pgn"),
        }
        for name, want in expect.items():
            got = one(f, name)
            if isinstance(want, int) and got not in (None, "several"):
                got = int(got, 0)
            if got != want:
                fail(at, f"{name} is {got!r}, decode --json says {want!r}")
        # The request a reply answers: the tool's "[reply to IIIIh sub S]".
        if j.get("sdo") == "reply":
            reply = f"[reply to {int(one(f, 'powerkey.sdo.reply_to.index'), 0):04X}h sub " \
                    f"{int(one(f, 'powerkey.sdo.reply_to.subindex'), 0)}]"
            if reply not in text:
                fail(at, f"{reply} is not in the tool's line: {text}")
        # Every message field, under its own filter name, and no other.
        extra = {k for k in f["fields"] if k.startswith("powerkey.") and k.count(".") == 1} - \
            set(expect) - \
            {f"powerkey.{name}" for name in j.get("fields", {})} - {"powerkey.refused"}
        if extra:
            fail(at, f"fields the message does not have: {sorted(extra)}")
        for name, want in j.get("fields", {}).items():
            values = f["fields"].get(f"powerkey.{name}", [])
            if len(values) != 1 or not field_matches(name, want, *values[0]):
                fail(at, f"powerkey.{name} is {values!r}, decode --json says {want!r}")
        # The tree and the Info column read like the tool's text output.
        if info != tool_text(text):
            fail(at, f"Info column {info!r}, the tool writes {tool_text(text)!r}")
        if f["title"] != "Blink Marine PowerKey keypad, " + tool_text(text):
            fail(at, f"tree item {f['title']!r}")
        # Wireshark's CANopen dissector on the same frame.
        if j["function"] == "j1939":
            continue
        code, node, index, subindex = (co.split("\t") + ["", "", "", ""])[:4]
        if int(code, 16) != FUNCTION_CODES[j["function"]]:
            fail(at, f"canopen.function_code {code}, powerkey.function {j['function']}")
        want_node = j["node"] if j["function"] in PER_NODE else 0
        if int(node, 16) != want_node:
            fail(at, f"canopen.node_id {node}, powerkey says {want_node}")
        ours = one(f, "powerkey.sdo.index"), one(f, "powerkey.sdo.subindex")
        theirs = (int(index, 16) if index else None), (int(subindex, 16) if subindex else None)
        ours = tuple(None if v is None else int(v, 0) for v in ours)
        if ours != theirs:
            fail(at, f"SDO index/sub-index {ours} in powerkey, {theirs} in canopen")


def check_other_frames(run):
    """Frames the keypad does not own stay with the generic dissectors."""
    log = os.path.join(run.args.work, "other.log")
    rows = [
        # frame, what powerkey shows (kind or error:code) or None, protocols in the frame,
        # protocols with "Decode As CANopen"
        ("000#0115", "nmt", "can:powerkey", "can:powerkey"),
        ("000#0116", None, "can:autosar-nm", "can:canopen"),  # NMT for node 16h
        ("616#4008100000000000", None, "can:data", "can:canopen"),  # an SDO of node 16h
        ("196#0100000010", None, "can:data", "can:canopen"),  # a PDO of node 16h
        ("615#40", "error:wrong_length", "can:powerkey", "can:powerkey"),  # too short
        ("18EF2100#041B8000FFFFFFFF", "j1939_switch_to_canopen", "can:powerkey",
         "can:powerkey"),
        ("18FEF100#0000000000000000", None, "can:data", "can:data"),  # PGN FEF1h
        ("715#7F", "heartbeat", "can:powerkey", "can:powerkey"),
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
        tool = j.get("kind") or f"error:{j.get('error')}"
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
    if got != ["pk1000_read\t0x3a", "\t"]:
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
    """Filters by field, by value name and by kind select the frames decode --json names."""
    log = os.path.join(run.args.source, "examples", "logs", "pkp2400.log")
    pcap = run.pcap(log, "pkp2400-filters")
    tool_json = [json.loads(l) for l in run.tool("decode", "--model", "pkp2400", "--json", log)]

    def frames(expr):
        out = run.tshark("-r", pcap, "-o", "powerkey.model:pkp2400", "-Y", expr,
                         "-T", "fields", "-e", "frame.number")
        return [int(n) for n in out.split()]

    def expect(test):
        return [n for n, j in enumerate(tool_json, 1) if test(j)]

    cases = [
        ('powerkey.kind == "pkp_led_on"', lambda j: j.get("kind") == "pkp_led_on"),
        ('powerkey.command == "start"',
         lambda j: j.get("kind") == "nmt" and j["fields"]["command"] == "start"),
        ('powerkey.red == "1 4 5 7"', lambda j: j.get("fields", {}).get("red") == [1, 4, 5, 7]),
        ("powerkey.sdo.pairing == \"unanswered\"", lambda j: j.get("sdo") == "unanswered"),
    ]
    for expr, test in cases:
        got, want = frames(expr), expect(test)
        if got != want or not want:
            fail(f"filter {expr}", f"frames {got}, expected {want}")
    # The replies to a read of 1008h: the frames the tool's text marks [reply to 1008h sub 0].
    lines = run.tool("decode", "--model", "pkp2400", log)
    got = frames("powerkey.sdo.reply_to.index == 0x1008")
    want = [n for n, l in enumerate(lines, 1) if "[reply to 1008h sub 0]" in l]
    if got != want or not want:
        fail("filter powerkey.sdo.reply_to.index == 0x1008", f"frames {got}, expected {want}")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--build-dir", required=True)
    p.add_argument("--tool", required=True)
    p.add_argument("--source", required=True)
    p.add_argument("--work", required=True)
    args = p.parse_args()
    os.makedirs(args.work, exist_ok=True)
    run = runner(args)
    for model in MODELS:
        compare_model(run, model)
    compare_model(run, "pk1000", two_pass=True)
    check_other_frames(run)
    check_node_preference(run)
    check_escaping(run)
    check_filters(run)
    shown = {}
    for f in failures:  # at most 15 per check, so that each failing check shows
        section = f.split(" frame ")[0].split(":")[0]
        shown[section] = shown.get(section, 0) + 1
        if shown[section] <= 15:
            print("FAIL:", f)
    if failures:
        print(f"{len(failures)} differences")
        return 1
    print("wireshark: every sample frame agrees with decode --json and with the CANopen dissector")
    return 0


if __name__ == "__main__":
    sys.exit(main())
