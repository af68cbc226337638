#!/usr/bin/env bash
# Tests of `powerkey export dbc` (registered by tools/powerkey/CMakeLists.txt):
#   test_dbc.sh POWERKEY_BINARY SOURCE_DIR
# The checked-in DBCs (examples/dbc/) are what the tool writes now; the output is the same bytes
# every time and whatever the order of the options; option errors are usage errors; and the files
# of every model are read by canmatrix and compared with the library (tests/test_dbc.py).
set -uo pipefail
. "$(dirname "$0")/tool_support.sh"

# The checked-in files are current.
count=0
for f in "$src"/examples/dbc/*.dbc; do
  [ -e "$f" ] || continue
  m=$(basename "$f" .dbc)
  "$pk" export dbc --model "$m" > "$tmp/$m.dbc" || fail "$m: export dbc exit status"
  cmp -s "$tmp/$m.dbc" "$f" || fail "$f is stale; regenerate it with bash scripts/dbc.sh"
  count=$((count + 1))
done
[ $count -ge 2 ] || fail "examples/dbc/ holds $count DBC files, want at least two"

# Deterministic, and the options read as everywhere else: before or after the subcommand, the
# node in any of its forms, the model under any of its names.
"$pk" export dbc --model pkp2400 --node 0x3A > "$tmp/a" || fail "export dbc --node 0x3A: exit status"
"$pk" export dbc --model pkp2400 --node 0x3A > "$tmp/b"
cmp -s "$tmp/a" "$tmp/b" || fail "two runs differ"
"$pk" --node 58 --model PKP-2400-LI export dbc > "$tmp/b"
cmp -s "$tmp/a" "$tmp/b" || fail "--node 58 --model PKP-2400-LI before the subcommand differs"
"$pk" export dbc --model pkp2400 --node 3Ah > "$tmp/b"
cmp -s "$tmp/a" "$tmp/b" || fail "--node 3Ah differs"
grep -qx "BO_ 442 key_state: 5 keypad" "$tmp/a" || fail "node 3Ah: no key state at 1BAh"
grep -qx 'BA_ "DBName" "pkp2400_3Ah";' "$tmp/a" || fail "node 3Ah: DBName"
cmp -s "$tmp/a" "$tmp/pkp2400.dbc" && fail "node 3Ah and 15h give the same file"

# Option errors are usage errors (2), with one line that says what to do.
usage() {
  local want=$1; shift
  "$pk" "$@" > "$tmp/out" 2> "$tmp/err"; local rc=$?
  [ $rc -eq 2 ] || fail "$*: exit status $rc, want 2"
  [ ! -s "$tmp/out" ] || fail "$*: wrote to standard output"
  [ "$(cat "$tmp/err")" = "$want" ] || fail "$*: '$(cat "$tmp/err")', want '$want'"
}
# Every model of the table, as decode lists them for an unknown model (without its "auto").
models=$("$pk" decode --model none /dev/null 2>&1 | sed -n 's/.*unknown model .none. (\(.*\), auto).*/\1/p')
[ -n "$models" ] || fail "decode --model none lists no models"
usage "powerkey: export needs --model M ($models) (powerkey help shows the usage)" export dbc
usage "powerkey: export: say what to export (dbc) (powerkey help shows the usage)" export --model pkp2400
usage "powerkey: The following argument was not expected: csv (powerkey help shows the usage)" export csv --model pkp2400
usage "powerkey: --model: unknown model 'auto' ($models) (powerkey help shows the usage)" export dbc --model auto
usage "powerkey: --node: expected a node id 1..127 (0x15, 15h or 21), got '128' (powerkey help shows the usage)" export dbc --model pkp2400 --node 128
usage "powerkey: The following argument was not expected: --json (powerkey help shows the usage)" export dbc --model pkp2400 --json
usage "powerkey: The following argument was not expected: out.dbc (powerkey help shows the usage)" export dbc --model pkp2400 out.dbc
"$pk" help | grep -qF "powerkey export dbc --model M [--node N]" || fail "help lacks export dbc"
"$pk" help export | grep -qF "usage: powerkey export dbc --model M [--node N]" || fail "help export"
"$pk" export dbc -h | cmp -s - <("$pk" help export) || fail "export dbc -h differs from help export"

# A real DBC reader: canmatrix, for /usr/bin/python3 (scripts/deps.sh installs python3-canmatrix).
py=/usr/bin/python3
if ! "$py" -c "import canmatrix" 2> /dev/null; then
  fail "canmatrix is not installed for $py (apt-get install python3-canmatrix, as scripts/deps.sh does)"
else
  "$py" "$src/tests/test_dbc.py" "$pk" "$src" || fail "canmatrix: tests/test_dbc.py"
fi

finish "dbc"
