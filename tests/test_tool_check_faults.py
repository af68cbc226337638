#!/usr/bin/python3
"""`powerkey check` on controller faults and its JUnit report (registered by
tools/powerkey/CMakeLists.txt):

    test_tool_check_faults.py faults POWERKEY SOURCE_DIR   the logs of examples/logs/faults/
    test_tool_check_faults.py junit POWERKEY SOURCE_DIR    --junit FILE read by junitparser

`faults`: each log is what scripts/controller_faults.py writes with python-can, and `check`
prints exactly its row's lines with its row's exit status; a log checked under the wrong model
says so (wrong_model), and warnings never make the status 1.
`junit`: the report of several logs read by Debian's python3-junitparser: a test suite per log,
a test case per kind, a failure per problem line of the text output (its line and reason), the
warnings in system-out and counted in a property, the counts as junitparser recomputes them, and
file names with XML markup and control characters escaped.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

pk, src = sys.argv[2], sys.argv[3]
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(src, "scripts"))
import controller_faults  # noqa: E402

faults_dir = os.path.join(src, "examples", "logs", "faults")
logs_dir = os.path.join(src, "examples", "logs")
failed = []


def fail(what):
    failed.append(what)
    print("FAIL: " + what)


def check(*args):
    r = subprocess.run([pk, "check", *args], capture_output=True, text=True)
    return r.returncode, r.stdout.splitlines(), r.stderr


def faults():
    if controller_faults.check(faults_dir) != 0:
        fail("the logs of examples/logs/faults/ are not what scripts/controller_faults.py writes")
    names = {r["name"] + ".log" for r in controller_faults.FAULTS}
    if set(os.listdir(faults_dir)) != names:
        fail("examples/logs/faults/ holds other files: %s" % sorted(set(os.listdir(faults_dir)) - names))
    for row in controller_faults.FAULTS:
        path = os.path.join(faults_dir, row["name"] + ".log")
        status, out, err = check("--model", row["model"], path)
        if out != row["expected"]:
            fail("%s: output\n  got:  %s\n  want: %s" % (row["name"], "\n        ".join(out),
                                                        "\n        ".join(row["expected"])))
        if status != row["status"]:
            fail("%s: exit status %d, want %d" % (row["name"], status, row["status"]))
        if err:
            fail("%s: errors: %s" % (row["name"], err))
        # --json: one object per problem and per warning, each with its severity.
        status, out, _ = check("--model", row["model"], "--json", path)
        objects = [json.loads(line) for line in out]
        problems = [o for o in objects if o["severity"] == "problem"]
        warnings = [o for o in objects if o["severity"] == "warning"]
        want_problems = [l for l in row["expected"] if ": warning: " not in l and not l.startswith("warnings: ")]
        if ["%d: %s: %s" % (o["line"], o["kind"], o["text"]) for o in problems] != want_problems:
            fail("%s: --json problems %s" % (row["name"], problems))
        if any(o["kind"] != "not_manual_form" for o in warnings):
            fail("%s: --json warnings %s" % (row["name"], warnings))
        if status != row["status"]:
            fail("%s: --json exit status %d" % (row["name"], status))
    # The trimmed log lists every warning in JSON, and strictly read its frames are refused.
    _, out, _ = check("--model", "pk1000", "--json", os.path.join(faults_dir, "trimmed.log"))
    if [json.loads(l)["line"] for l in out] != [2, 3, 5, 6]:
        fail("trimmed --json: %s" % out)

    # The wrong model: the clean PK1000 session checked as a PKP-2400-LI.
    clean = os.path.join(logs_dir, "check-clean.log")
    status, out, _ = check("--model", "pkp2400", clean)
    wrong = [l for l in out if ": wrong_model: " in l]
    refused = [l for l in out if ": refused_frame: " in l]
    want = ("wrong_model: 13 of 58 keypad frames refused as pkp2400 frames: the keypad is likely "
            "another model; powerkey decode --model auto names the model that reads the log")
    if len(wrong) != 1 or not wrong[0].endswith(want) or status != 1:
        fail("wrong model: status %d, %s" % (status, wrong))
    if len(refused) != 11:  # the other 2 of the 13 are the keypad's replies
        fail("wrong model: %d refused_frame" % len(refused))
    # The refused frames are those decode refuses, its summary says how many.
    d = subprocess.run([pk, "decode", "--model", "pkp2400", clean], capture_output=True, text=True)
    if "13 refused" not in d.stderr:
        fail("wrong model: decode says %s" % d.stderr)
    status, out, _ = check("--model", "pk1000", clean)
    if out or status != 0:
        fail("clean under pk1000: status %d, %s" % (status, out))


def junit():
    from junitparser import Error, Failure, JUnitXml  # Debian's python3-junitparser

    tmp = tempfile.mkdtemp()
    try:
        # A file name with markup and a control character: escaped, never markup.
        odd = os.path.join(tmp, "a<b&\"c'\x01.log")
        shutil.copy(os.path.join(logs_dir, "check-problems.log"), odd)
        broken = os.path.join(tmp, "broken.log")
        with open(broken, "w") as f:
            f.write("(1700000000.000000) can0 715#00\nnonsense\n")
        inputs = [os.path.join(logs_dir, "check-problems.log"),
                  os.path.join(faults_dir, "trimmed.log"),
                  os.path.join(faults_dir, "sdo-write-4-bytes.log"), odd, broken,
                  os.path.join(tmp, "missing.log")]
        report = os.path.join(tmp, "report.xml")
        r = subprocess.run([pk, "check", "--model", "pk1000", "--junit", report, *inputs],
                           capture_output=True, text=True)
        if r.returncode != 1:
            fail("junit: exit status %d" % r.returncode)
        # The text of each log on its own, to compare with.
        texts = {}
        for path in inputs:
            _, out, _ = check("--model", "pk1000", path)
            texts[path] = out
        kinds_out = subprocess.run([pk, "check", "--model", "pk1000", "--junit", os.path.join(tmp, "k.xml"),
                                    os.path.join(logs_dir, "check-clean.log")], capture_output=True)
        if kinds_out.returncode != 0:
            fail("junit: a clean log is status %d" % kinds_out.returncode)
        xml = JUnitXml.fromfile(report)
        suites = list(xml)
        if [s.name for s in suites] != [p.replace("\x01", "\\x01") for p in inputs]:
            fail("junit: suite names %s" % [s.name for s in suites])
        kinds = None
        for suite, path in zip(suites, inputs):
            cases = list(suite)
            names = [c.name for c in cases if c.name != "input"]
            if kinds is None:
                kinds = names
            if names != kinds or len(kinds) != 17:
                fail("junit %s: test cases %s" % (path, names))
            props = {p.name: p.value for p in suite.properties()}
            if props.get("model") != "pk1000" or props.get("node") != "15h":
                fail("junit %s: properties %s" % (path, props))
            # Every problem line of the text output is one failure of its kind, and back.
            want = sorted(tuple(l.split(": ", 2)) for l in texts[path]
                          if ": warning: " not in l and not l.startswith("warnings: "))
            got = []
            warned = []
            for c in cases:
                for res in c.result:
                    if isinstance(res, Failure):
                        if res.type != c.name or not res.message.startswith("line "):
                            fail("junit %s: failure %s %s" % (path, res.type, res.message))
                        line, text = res.message[5:].split(": ", 1)
                        got.append((line, c.name, text))
                        if res.text != res.message:
                            fail("junit %s: failure text %s" % (path, res.text))
                    elif isinstance(res, Error):
                        if c.name != "input":
                            fail("junit %s: error in %s" % (path, c.name))
                if c.name == "not_manual_form" and c.system_out:
                    warned = c.system_out.splitlines()
            if sorted(got) != want:
                fail("junit %s: failures\n  got:  %s\n  want: %s" % (path, sorted(got), want))
            shown = [l for l in texts[path] if ": warning: " in l]
            if len(warned) != int(props.get("warnings.not_manual_form", -1)) or \
                    [w.split(": ", 1)[1] for w in warned[:len(shown)]] != [l.split(": warning: not_manual_form: ")[1] for l in shown]:
                fail("junit %s: warnings %s, property %s" % (path, warned, props.get("warnings.not_manual_form")))
            has_input = any(c.name == "input" for c in cases)
            if has_input != (path in (broken, inputs[-1])):
                fail("junit %s: input test case %s" % (path, has_input))
            # The counts written are the counts junitparser finds.
            written = (suite.tests, suite.failures, suite.errors)
            suite.update_statistics()
            if written != (suite.tests, suite.failures, suite.errors):
                fail("junit %s: counts %s, junitparser counts %s" %
                     (path, written, (suite.tests, suite.failures, suite.errors)))
        if suites and suites[0].failures != 9:
            fail("junit: check-problems.log has %d failures, not 9" % suites[0].failures)
        written = (xml.tests, xml.failures, xml.errors)
        xml.update_statistics()
        if written != (xml.tests, xml.failures, xml.errors):
            fail("junit: total counts %s, junitparser %s" % (written, (xml.tests, xml.failures, xml.errors)))
        # Many warnings: text shows 3 and counts them, JUnit lists 1000 and counts the rest.
        import can  # Debian's python3-can

        many = os.path.join(tmp, "many.log")
        writer = can.CanutilsLogWriter(many, channel="can0")
        writer.on_message_received(can.Message(timestamp=1700000000, arbitration_id=0x000,
                                               is_extended_id=False, data=bytes([1, 0x15])))
        for i in range(2500):
            writer.on_message_received(can.Message(timestamp=1700000000.001 + i / 1000,
                                                   arbitration_id=0x515, is_extended_id=False,
                                                   data=bytes([0x3F, 0x01])))
        writer.stop()
        status, out, _ = check("--model", "pk1000", many)
        if status != 0 or len(out) != 4 or \
                out[3] != "warnings: not_manual_form 2500 (3 of each shown; --json lists each)":
            fail("many warnings: status %d, %s" % (status, out[-2:]))
        report_many = os.path.join(tmp, "many.xml")
        subprocess.run([pk, "check", "--model", "pk1000", "--junit", report_many, many],
                       capture_output=True)
        suite = list(JUnitXml.fromfile(report_many))[0]
        case = [c for c in suite if c.name == "not_manual_form"][0]
        lines = case.system_out.splitlines()
        props = {p.name: p.value for p in suite.properties()}
        if len(lines) != 1001 or lines[-1] != "1500 more not listed" or \
                props.get("warnings.not_manual_form") != "2500" or suite.failures != 0:
            fail("many warnings, junit: %d lines, last %s, %s" % (len(lines), lines[-1:], props))
        # A report that cannot be written is an error.
        r = subprocess.run([pk, "check", "--model", "pk1000", "--junit", os.path.join(tmp, "no", "r.xml"),
                            os.path.join(logs_dir, "check-clean.log")], capture_output=True, text=True)
        if r.returncode != 1 or "No such file or directory" not in r.stderr:
            fail("junit: unwritable report: %d %s" % (r.returncode, r.stderr))
    finally:
        shutil.rmtree(tmp)


{"faults": faults, "junit": junit}[sys.argv[1]]()
if not failed:
    print("check %s: all tests passed" % sys.argv[1])
sys.exit(1 if failed else 0)
