#!/usr/bin/env bash
# Tests of `powerkey simulate` (tools/powerkey/cmd_simulate.cpp), registered by
# tools/powerkey/CMakeLists.txt:  test_tool_simulate.sh POWERKEY_BINARY SOURCE_DIR
# The shipped session log (examples/logs/session-pk1000.log) gives exactly the keypad's frames
# below; bare frames on stdin, --node, bad lines and usage errors behave as documented.
set -uo pipefail
. "$(dirname "$0")/tool_support.sh"
sim() { "$pk" simulate "$@"; }

# The session: boot-up first, one reply per request 1 ms after it, heartbeats every 100 ms from
# the 1017h write, the scripted key 3 press and release as key-state PDOs (tick = 100 ms units).
sim --model pk1000 --press 0.42:3 --release 0.47:3 "$src/examples/logs/session-pk1000.log" \
  > "$tmp/out" || fail "session: exit status $?"
cat > "$tmp/want" <<'OUT'
(1700000000.000000) can0 715#00
(1700000000.101000) can0 595#43181001E2030000
(1700000000.111000) can0 595#410B100007000000
(1700000000.121000) can0 595#01504B3130303000
(1700000000.131000) can0 595#6017100000000000
(1700000000.141000) can0 595#6003200100000000
(1700000000.151000) can0 595#6000140200000000
(1700000000.230000) can0 715#05
(1700000000.330000) can0 715#05
(1700000000.420000) can0 195#0400000004
(1700000000.430000) can0 715#05
(1700000000.470000) can0 195#0000000004
(1700000000.530000) can0 715#05
OUT
diff "$tmp/want" "$tmp/out" || fail "session output differs"

# Bare frames on stdin, another node, a PKP model: lines without a time come 10 ms apart, so the
# second request meets an idle keypad and is answered too.
printf '621#4017100000000000\n621#4000100000000000\n' |
  sim --model pkp2400 --node 0x21 > "$tmp/out" 2> "$tmp/err" || fail "stdin: exit status $?"
printf '(0.000000) can0 721#00\n(0.001000) can0 5A1#4B17100000000000\n(0.011000) can0 5A1#4300100091010300\n' > "$tmp/want"
diff "$tmp/want" "$tmp/out" || fail "stdin output differs"
[ -s "$tmp/err" ] && fail "stdin: $(cat "$tmp/err")"
# A request that comes while the keypad is still answering (timed 0.4 ms apart: the same millisecond) is dropped, as
# real keypads do, and said on standard error with the request it was busy with.
printf '(1.0000) can0 621#4017100000000000\n(1.0004) can0 621#4000100000000000\n' |
  sim --model pkp2400 --node 0x21 > "$tmp/out" 2> "$tmp/err" || fail "dropped: exit status $?"
printf '(1.000000) can0 721#00\n(1.001000) can0 5A1#4B17100000000000\n' > "$tmp/want"
diff "$tmp/want" "$tmp/out" || fail "dropped: output differs"
[ "$(cat "$tmp/err")" = "powerkey: <stdin>:2: the keypad drops this SDO request: the request of <stdin>:1 (1017h sub 0) is not answered yet" ] ||
  fail "dropped request not said: $(cat "$tmp/err")"
# Many dropped requests: three said, the others counted, as problems are.
for i in $(seq 1 50); do echo "(1.0000) can0 621#4017100000000000"; done |
  sim --model pkp2400 --node 0x21 > /dev/null 2> "$tmp/err" || fail "many dropped: exit status $?"
[ "$(wc -l < "$tmp/err")" -eq 4 ] && tail -1 "$tmp/err" | grep -qx "powerkey: <stdin>: 46 more lines like that (the keypad drops an SDO request)" ||
  fail "many dropped requests: $(cat "$tmp/err")"
# Many dropped requests: three said, the others counted, as problems are.
for i in $(seq 1 50); do echo "(1.0000) can0 621#4017100000000000"; done |
  sim --model pkp2400 --node 0x21 > /dev/null 2> "$tmp/err" || fail "many dropped: exit status $?"
[ "$(wc -l < "$tmp/err")" -eq 4 ] && tail -1 "$tmp/err" | grep -qx "powerkey: <stdin>: 46 more lines like that (the keypad drops an SDO request)" ||
  fail "many dropped requests: $(cat "$tmp/err")"

# A node change on the PKP: the reply from the old id, then the boot-up from the new one.
echo '(5.000000) can0 615#2300650170180000' | sim --model PKP-2200-LI > "$tmp/out"
printf '(5.000000) can0 715#00\n(5.001000) can0 595#6000650100000000\n(5.001000) can0 718#00\n' \
  > "$tmp/want"
diff "$tmp/want" "$tmp/out" || fail "node change output differs"

# candump's screen form (with -t a timestamps) reads like the log form.
echo '(1700000000.000000)  can0  615   [8]  40 10 20 00 00 00 00 00' |
  sim --model pk1000 > "$tmp/out" || fail "screen form: exit status $?"
printf '(1700000000.000000) can0 715#00\n(1700000000.001000) can0 595#4F10200004000000\n' > "$tmp/want"
diff "$tmp/want" "$tmp/out" || fail "screen form output differs"

# A bad line: reported with file and line on stderr, exit status 1, the rest still simulated.
printf '615#4010200000000000\nnot a frame\n' > "$tmp/bad.log"
sim --model pk1000 "$tmp/bad.log" > "$tmp/out" 2> "$tmp/err"
[ $? -eq 1 ] || fail "bad line: exit status not 1"
grep -qx "powerkey: $tmp/bad.log:2: not a frame (expected ID#DATA or a candump line): 'not a frame'" "$tmp/err" ||
  fail "bad line: no file:line error: $(cat "$tmp/err")"
grep -q "595#4F10200004000000" "$tmp/out" || fail "bad line: the good line was not answered"

# Every shipped sample log (both directions of the manual's frames, per model): read without an
# error, the boot-up first, every line a candump log line.
for log in "$src"/examples/logs/*.log; do
  m=$(basename "$log" .log)
  case $m in pk1000 | pkp*) ;; *) continue ;; esac
  sim --model "$m" "$log" > "$tmp/out" 2> "$tmp/err" || fail "$m: exit status $? $(head -3 "$tmp/err")"
  head -1 "$tmp/out" | grep -Eq '^\([0-9.]+\) can0 715#00$' || fail "$m: no boot-up first"
  grep -Evq '^\([0-9.]+\) can0 [0-9A-F]{3}#([0-9A-F]{2}){0,8}$' "$tmp/out" && fail "$m: a line not in candump log form"
done

# J1939 (--j1939): the keypad is in J1939 from power-on, no boot-up. A controller's J1939 frames
# are answered as the PKP1600SI J1939 manual prints: the LED acknowledgement after 73h (section
# 19), the revision (11), heartbeats every 100 ms from the 75h (21, counter from 00h), the
# scripted key 2 as key contact states (6).
cat > "$tmp/j1939-ctl.log" <<'IN'
(0.000000) can0 18EF2100#041B7301FFFFFFFF
(0.010000) can0 18EF2100#041B0101040305FF
(0.020000) can0 18EF2100#041B2AFFFFFFFFFF
(0.030000) can0 18EF2100#041B75010AFFFFFF
IN
sim --model pkp1600si --j1939 --press 0.05:2 --release 0.07:2 --until 0.25 "$tmp/j1939-ctl.log" \
  > "$tmp/out" 2> "$tmp/err" || fail "j1939: exit status $?"
cat > "$tmp/want" <<'OUT'
(0.010000) can0 18EFFF21#0003010405FFFFFF
(0.020000) can0 18EFFF21#041B2A56322E3130
(0.050000) can0 18EFFF21#041B01020121FFFF
(0.070000) can0 18EFFF21#041B01020021FFFF
(0.130000) can0 18EFFF21#041BF9000000FF21
(0.230000) can0 18EFFF21#041BF9010000FF21
OUT
diff "$tmp/want" "$tmp/out" || fail "j1939 output differs"
[ -s "$tmp/err" ] && fail "j1939: $(cat "$tmp/err")"
# The whole conversation decodes back: every frame a J1939 keypad frame of the model.
sort -m "$tmp/j1939-ctl.log" "$tmp/out" | "$pk" decode --model pkp1600si > "$tmp/text" 2> "$tmp/err"
grep -q "error:" "$tmp/text" && fail "j1939 decode: $(grep -m3 'error:' "$tmp/text")"
grep -qx "powerkey: summary: 10 frames: 10 decoded, 0 of other nodes or no keypad, 0 refused" "$tmp/err" ||
  fail "j1939 decode summary: $(cat "$tmp/err")"
grep -q "18EFFF21#041B01020121FFFF .*J1939 key contact .*key: 2  pressed: yes  identifier: 21h" "$tmp/text" ||
  fail "j1939 decode: no key 2 press: $(cat "$tmp/text")"
grep -q "18EFFF21#0003010405FFFFFF .*J1939 LED ack .*key: 1  mode: alternate_blink  colour: yellow  secondary: cyan$" "$tmp/text" ||
  fail "j1939 decode: no acknowledgement: $(cat "$tmp/text")"
# The J1939 sample logs of the complete manuals, fed to a keypad in J1939: read without an error,
# every line a candump log line with a 29-bit identifier until the log's last frame (04 1B 80h 00h,
# the switch back to CANopen), after which the keypad boots up in CANopen at its default node 15h.
for m in pkp1600si pkp2600si; do
  sim --model $m --j1939 "$src/examples/logs/j1939-$m.log" > "$tmp/out" 2> "$tmp/err" ||
    fail "j1939-$m: exit status $? $(head -3 "$tmp/err")"
  [ -s "$tmp/out" ] || fail "j1939-$m: the keypad sent nothing"
  sed '$d' "$tmp/out" | grep -Evq '^\([0-9.]+\) can0 [0-9A-F]{8}#([0-9A-F]{2}){8}$' &&
    fail "j1939-$m: a line before the switch not a J1939 frame"
  tail -n 1 "$tmp/out" | grep -Eq '^\([0-9.]+\) can0 715#00$' ||
    fail "j1939-$m: no CANopen boot-up after the switch: $(tail -n 1 "$tmp/out")"
  "$pk" decode --model $m "$tmp/out" > "$tmp/text" 2>/dev/null
  grep -q "error:" "$tmp/text" && fail "j1939-$m: decode: $(grep -m3 'error:' "$tmp/text")"
done
# An LI keypad sold as a J1939 one (issue 21), at --address 0x30: its LI frames (docs/j1939.md:
# the acknowledgement of the PKP-2400-LI J1939 manual page 11, its LED command inferred), from
# 30h, commands to 21h not its own, and the switch back (80h, unknown on an LI keypad: decode
# refuses it, undocumented) ignored: no boot-up, the heartbeats go on.
cat > "$tmp/li-ctl.log" <<'IN'
(0.000000) can0 18EF3000#041B7301FFFFFFFF
(0.010000) can0 18EF3000#041B010305FFFFFF
(0.020000) can0 18EF3000#041B2AFFFFFFFFFF
(0.030000) can0 18EF3000#041B75010AFFFFFF
(0.040000) can0 18EF2100#041B2AFFFFFFFFFF
(0.090000) can0 18EF3000#041B8000FFFFFFFF
IN
sim --model pkp2400 --j1939 --address 0x30 --press 0.05:8 --release 0.07:8 --until 0.25 \
  "$tmp/li-ctl.log" > "$tmp/out" 2> "$tmp/err" || fail "j1939 LI: exit status $?"
cat > "$tmp/want" <<'OUT'
(0.010000) can0 18EFFF30#00FF0305FFFFFFFF
(0.020000) can0 18EFFF30#041B2A56322E3130
(0.050000) can0 18EFFF30#041B01080121FFFF
(0.070000) can0 18EFFF30#041B01080021FFFF
(0.130000) can0 18EFFF30#041BF9000000FF21
(0.230000) can0 18EFFF30#041BF9010000FF21
OUT
diff "$tmp/want" "$tmp/out" || fail "j1939 LI output differs"
[ -s "$tmp/err" ] && fail "j1939 LI: $(cat "$tmp/err")"
sort -m "$tmp/li-ctl.log" "$tmp/out" | "$pk" decode --model pkp2400 --address 0x30 > "$tmp/text" 2> "$tmp/err"
grep -qx "powerkey: summary: 12 frames: 10 decoded, 1 of other nodes or no keypad, 1 refused (undocumented 1)" "$tmp/err" ||
  fail "j1939 LI decode summary: $(cat "$tmp/err")"
grep -q "18EFFF30#00FF0305FFFFFFFF .*J1939 LED ack code .*source: 30h  key: 3  code: 05h$" "$tmp/text" ||
  fail "j1939 LI decode: no LI acknowledgement: $(cat "$tmp/text")"
# Every model speaks J1939 from power-on (its key contact state documented or inferred): key 1.
for m in $("$pk" models | awk '{ print $1 }'); do
  sim --model "$m" --j1939 --address 0x22 --press 0.01:1 --until 0.02 < /dev/null > "$tmp/out" 2> "$tmp/err" ||
    fail "j1939 $m: exit status $? $(cat "$tmp/err")"
  [ "$(cat "$tmp/out")" = "(0.010000) can0 18EFFF22#041B01010121FFFF" ] || fail "j1939 $m: $(cat "$tmp/out")"
done
# --address: with --j1939 only; 00h is no keypad's (70h's range 01h..FDh), FEh and FFh no one's.
sim --model pkp1600si --address 0x30 < /dev/null > /dev/null 2> "$tmp/err"; [ $? -eq 2 ] ||
  fail "--address without --j1939: exit status not 2"
grep -q "^powerkey: --address: the J1939 address the keypad starts at, with --j1939 only" "$tmp/err" ||
  fail "--address without --j1939: $(cat "$tmp/err")"
sim --model pkp2400 --j1939 --address 0 < /dev/null > /dev/null 2> "$tmp/err"; [ $? -eq 2 ] ||
  fail "--address 0: exit status not 2"
grep -q "^powerkey: --address: expected a keypad's J1939 address 01h..FDh (70h's range: 0x21, 21h or 33), got '0'" "$tmp/err" ||
  fail "--address 0: $(cat "$tmp/err")"
sim --model pkp2400 --j1939 --address 0xFE < /dev/null > /dev/null 2>&1; [ $? -eq 2 ] ||
  fail "--address 0xFE: exit status not 2"

# Usage errors: exit status 2.
sim > /dev/null 2>&1; [ $? -eq 2 ] || fail "no --model: exit status not 2"
sim --model pk9999 > /dev/null 2>&1; [ $? -eq 2 ] || fail "unknown model: exit status not 2"
sim --model pk1000 --press 1:11 > /dev/null 2>&1; [ $? -eq 2 ] || fail "key 11: exit status not 2"

finish
