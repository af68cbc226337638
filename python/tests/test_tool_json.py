"""powerkey.Session and Message.to_dict() against the tool: `powerkey decode --json` of every
sample log (examples/logs/) gives, line by line, the same kind, fields, error, SDO pairing, node
change and string as the Python session. ctest passes the tool's path in POWERKEY_TOOL when the
examples are built; without it the test is skipped."""

import json
import subprocess

import pytest

import powerkey
from conftest import REPO, env_program, parse_candump

LOGS = sorted((REPO / "examples/logs").glob("*.log"))


def model_of(path):
    """The model a log's name names (pkp2400.log, session-pk1000.log, j1939-pkp1600si.log)."""
    named = [w for w in path.stem.split("-") if w in powerkey.names("model")]
    return named[0] if named else "pk1000"  # check-*.log: a PK1000


@pytest.mark.parametrize("log", LOGS, ids=lambda p: p.name)
def test_session_equals_tool_json(log):
    tool = env_program("POWERKEY_TOOL")
    model = model_of(log)
    out = subprocess.run([tool, "decode", "--json", "--model", model, str(log)],
                         check=True, capture_output=True, text=True).stdout
    frames = [parse_candump(l) for l in log.read_text().splitlines()
              if l.strip() and not l.startswith("#")]
    lines = [json.loads(l) for l in out.splitlines()]
    assert len(lines) == len(frames)
    s = powerkey.Session(model=model)
    for (ident, data, ext), j in zip(frames, lines):
        assert (int(j["id"], 16), bytes.fromhex(j["data"])) == (ident, data)
        e = s.step(ident, data, extended=ext)
        assert e.function == j["function"]
        if "kind" in j:
            assert e.message is not None and e.message.kind == j["kind"]
            assert e.message.to_dict() == j["fields"]
        else:
            assert e.message is None and e.error == j["error"]
        assert e.sdo == j.get("sdo", "none")
        assert e.new_node == j.get("new_node")
        assert e.new_address == j.get("new_address")
        if "text" in j:
            assert e.upload_done and e.text == j["text"]
        assert e.upload_error == j.get("upload_error")
