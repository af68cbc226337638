#!/usr/bin/env bash
# Tests of `powerkey check` (tools/powerkey/cmd_check.cpp), registered by tools/powerkey/CMakeLists.txt:
#   test_tool_check.sh POWERKEY_BINARY SOURCE_DIR
# The shipped clean session passes; the same session with planted problems gives exactly the
# lines below, each right after its `# planted: KIND` comment; --json, several files, bad lines
# and usage behave as documented (docs/cli.md, docs/checker.md). A controller's log merged with the
# virtual keypad's answers to it (powerkey simulate) passes too. The controller fault logs, the
# warnings and the JUnit report: tests/test_tool_check_faults.py.
set -uo pipefail
. "$(dirname "$0")/tool_support.sh"
check() { "$pk" check "$@"; }
sim() { "$pk" simulate "$@"; }

# The clean session: no output, status 0.
check --model pk1000 "$logs/check-clean.log" >"$tmp/out" 2>"$tmp/err"
status=$?
[ $status -eq 0 ] || fail "clean: exit status $status"
[ -s "$tmp/out" ] && fail "clean: output: $(cat "$tmp/out")"
[ -s "$tmp/err" ] && fail "clean: errors: $(cat "$tmp/err")"

# The planted problems: one line per problem, in line order, status 1.
check --model pk1000 "$logs/check-problems.log" >"$tmp/out" 2>"$tmp/err"
status=$?
[ $status -eq 1 ] || fail "problems: exit status $status"
cat >"$tmp/want" <<'OUT'
10: segment_size: segmented upload of 100Bh announced 9 bytes and sent 7
19: segment_toggle: segment response with toggle bit 0, expected 1: the keypad repeated or skipped a segment
22: sdo_overlap: SDO request sent while the request of line 20 (2014h/0) is unanswered: the keypad drops it (one request at a time)
27: pdo_not_operational: PDO 215h sent while the keypad is pre_operational: it ignores PDOs until an NMT start
38: sdo_no_reply: SDO request 2010h/0 never answered (200 ms without a reply)
47: sdo_abort: the keypad aborted 1001h/0 with 06020000h: object does not exist in the object dictionary
55: heartbeat_silence: no heartbeat for 406 ms since line 51, the configured period is 200 ms
70: key_state_silence: no key state for 902 ms since line 61, the configured period is 500 ms
77: old_node_traffic: frame 215h to the old node id 15h: the keypad moved to 3Ah and does not answer it
OUT
diff "$tmp/want" "$tmp/out" >"$tmp/diff" || fail "problems: output differs:
$(cat "$tmp/diff")"
[ -s "$tmp/err" ] && fail "problems: errors: $(cat "$tmp/err")"

# Each problem is reported on the line right after its comment, with the kind the comment names.
grep -n '^# planted: ' "$logs/check-problems.log" | while IFS=: read -r n _ kind _; do
  kind=${kind# }
  kind=${kind%% *}
  grep -q "^$((n + 1)): $kind: " "$tmp/out" || echo "planted $kind at line $n not reported at $((n + 1))"
done >"$tmp/planted"
[ -s "$tmp/planted" ] && fail "$(cat "$tmp/planted")"
[ "$(grep -c '^# planted: ' "$logs/check-problems.log")" -eq 9 ] || fail "not one plant per kind"

# --json: one object per problem.
check --model pk1000 --json "$logs/check-problems.log" >"$tmp/json"
[ "$(wc -l <"$tmp/json")" -eq 9 ] || fail "json: $(wc -l <"$tmp/json") lines"
head -1 "$tmp/json" | grep -qx '{"line":10,"severity":"problem","kind":"segment_size","detail":\[9,7,4107\],"text":"segmented upload of 100Bh announced 9 bytes and sent 7"}' ||
  fail "json: $(head -1 "$tmp/json")"

# Several files: FILE:LINE; standard input; bare frames (no time).
check --model pk1000 "$logs/check-clean.log" "$logs/check-problems.log" >"$tmp/out"
[ "$(wc -l <"$tmp/out")" -eq 9 ] && grep -q "^$logs/check-problems.log:10: segment_size: " "$tmp/out" ||
  fail "several files: $(head -2 "$tmp/out")"
printf '715#00\n215#0100000000000000\n' | check --model pkp2400 >"$tmp/out"
[ $? -eq 1 ] && grep -qx '2: pdo_not_operational: PDO 215h sent while the keypad is pre_operational: it ignores PDOs until an NMT start' "$tmp/out" ||
  fail "stdin: $(cat "$tmp/out")"
printf '715#00\n000#0116\n216#0100000000000000\n' | check --model pkp2400 --node 0x16 >"$tmp/out"
[ $? -eq 1 ] && grep -q '^1: ' "$tmp/out" && fail "--node 0x16: the boot-up of 15h is not ours"
[ -s "$tmp/out" ] && fail "--node: $(cat "$tmp/out")"

# Bad lines are reported on standard error and make the status 1; usage errors 2.
printf '(1700000000.000000) can0 715#00\nnonsense\n' | check --model pk1000 >/dev/null 2>"$tmp/err"
[ $? -eq 1 ] && grep -qx "powerkey: <stdin>:2: not a frame (expected ID#DATA or a candump line): 'nonsense'" "$tmp/err" ||
  fail "bad line: $(cat "$tmp/err")"
check "$logs/check-clean.log" >/dev/null 2>&1
[ $? -eq 2 ] || fail "no --model: not a usage error"
check --model pk9999 "$logs/check-clean.log" >/dev/null 2>&1
[ $? -eq 2 ] || fail "unknown model: not a usage error"
check --model pk1000 --node 200 "$logs/check-clean.log" >/dev/null 2>&1
[ $? -eq 2 ] || fail "node 200: not a usage error"

# A controller's log (the simulate sample) with the virtual keypad's answers merged in by time.
sim --model pk1000 "$logs/session-pk1000.log" >"$tmp/keypad" || fail "simulate failed"
grep -v '^#' "$logs/session-pk1000.log" | cat - "$tmp/keypad" | sort -s -k1,1 >"$tmp/merged"
check --model pk1000 "$tmp/merged" >"$tmp/out" || fail "controller + simulated keypad: $(cat "$tmp/out")"

finish check
