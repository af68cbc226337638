#!/usr/bin/env bash
# Tests of the powerkey tool (registered by tools/powerkey/CMakeLists.txt):
#   test_tool.sh POWERKEY_BINARY SOURCE_DIR [SAMPLE_LOGS_BINARY]
# Every sample log (every manual frame, per model) decodes without an error and comes back byte
# for byte through `decode --json | encode --json`; bad input gets a one-line error naming the
# file and line and the rest is still decoded; the exit status says whether anything failed.
set -uo pipefail
. "$(dirname "$0")/tool_support.sh"

# Every model of the table (docs/models.md, docs/si-family.md) has its sample log.
models="pk1000 pkp2200 pkp2400 pkp2600 pkp2600si pkp3500mt pkp3500si pkp2500si pkp1500li pkp2200si pkp2300si pkp2400si pkp1600si"
for m in $models; do check_sample_log $m $m; done

# The three line forms read alike.
printf '%s\n' '(1700000000.000000) can0 215#0000010000000008' > "$tmp/a"
printf '%s\n' '215#0000010000000008' > "$tmp/b"
printf '%s\n' ' (1700000000.000000)  can0  215   [8]  00 00 01 00 00 00 00 08' > "$tmp/c"
for f in a b c; do "$pk" decode "$tmp/$f" | sed -E 's/.*215#0000010000000008 *//' > "$tmp/$f.out"; done
cmp -s "$tmp/a.out" "$tmp/b.out" && cmp -s "$tmp/a.out" "$tmp/c.out" || fail "line forms differ"
grep -q "LED on  red: 17  green: 28" "$tmp/a.out" || fail "PK1000 12 description: $(cat "$tmp/a.out")"

# Bad input: one line on stderr naming file and line, the other frames still decoded, status 1.
printf '%s\n' '000#0115' 'not a frame' '715#05' '615#40' > "$tmp/bad.log"
"$pk" decode "$tmp/bad.log" > "$tmp/out" 2> "$tmp/err"; rc=$?
[ $rc -eq 1 ] || fail "malformed line: exit status $rc"
grep -q "bad.log:2: " "$tmp/err" || fail "malformed line not named: $(cat "$tmp/err")"
# One line for the bad line, then the summary.
cat > "$tmp/want" <<EOF
powerkey: $tmp/bad.log:2: not a frame (expected ID#DATA or a candump line): 'not a frame'
powerkey: summary: 3 frames: 2 decoded, 0 of other nodes or no keypad, 1 refused (wrong_length 1); 1 bad line
EOF
diff "$tmp/want" "$tmp/err" > /dev/null || fail "bad line and summary: $(cat "$tmp/err")"
[ "$(wc -l < "$tmp/out")" -eq 3 ] || fail "the other lines were not decoded"
grep -q "615#40 .*error: wrong_length" "$tmp/out" || fail "short SDO: $(cat "$tmp/out")"

# Tolerant and strict reading (docs/cli.md): the switch to J1939 as the manuals print it (5 bytes)
# is the 8-byte write, trimmed; --strict refuses it; a padded NMT frame says so in JSON.
echo '615#2BFF200101' | "$pk" decode --model pk1000 > "$tmp/out" 2>/dev/null
grep -q "615#2BFF200101 .*SDO write  object: protocol_j1939  enabled: yes  form: trimmed" "$tmp/out" ||
  fail "trimmed switch: $(cat "$tmp/out")"
echo '615#2BFF200101' | "$pk" decode --model pk1000 --strict > "$tmp/out" 2>/dev/null
grep -q "615#2BFF200101 .*error: wrong_length" "$tmp/out" || fail "--strict: $(cat "$tmp/out")"
echo '000#0115000000000000' | "$pk" decode --model pk1000 --json > "$tmp/out" 2>/dev/null
grep -qx '{"id":"000","ext":false,"data":"0115000000000000","function":"nmt","node":21,"model":"pk1000","kind":"nmt_message","fields":{"command":"start","target":21},"form":"padded"}' "$tmp/out" ||
  fail "padded NMT in JSON: $(cat "$tmp/out")"
"$pk" decode "$tmp/missing.log" "$tmp/b" > "$tmp/out" 2> "$tmp/err"; rc=$?
[ $rc -eq 1 ] || fail "missing file: exit status $rc"
grep -q "missing.log" "$tmp/err" || fail "missing file not named"
grep -q "215#" "$tmp/out" || fail "the file after a missing one was not read"
"$pk" decode "$tmp" > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 1 ] && grep -q "Is a directory" "$tmp/err" || fail "a directory as log: $rc $(cat "$tmp/err")"
"$pk" decode --model pk2000 "$tmp/b" > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 2 ] && grep -q "unknown model" "$tmp/err" || fail "unknown model: $rc $(cat "$tmp/err")"
"$pk" decode --node 0 "$tmp/b" > /dev/null 2>&1 && fail "node 0 accepted"
"$pk" decode --node 0x3A "$tmp/b" > "$tmp/hex" && "$pk" decode --node 58 "$tmp/b" > "$tmp/dec" &&
  cmp -s "$tmp/hex" "$tmp/dec" || fail "--node 0x3A and 58 differ"
# A frame of another node says so once, without an error code that contradicts it.
grep -qx "215#0000010000000008       node 15h  rpdo1  another node's frame (keypad is 3Ah)" "$tmp/hex" ||
  fail "a frame of node 15h decoded for node 3Ah: $(cat "$tmp/hex")"

# --show draws the keypad when the log changes it (letters when not on a terminal).
printf '%s\n' '195#0100000010' '215#596A740000000000' '315#0100000000000000' > "$tmp/show.log"
"$pk" decode --model pkp2400 --show "$tmp/show.log" > "$tmp/out" || fail "--show exit status"
grep -qF '[ 1*.][ 2 .]' "$tmp/out" || fail "--show: key 1 pressed: $(cat "$tmp/out")"
grep -qF '[ 1*R][ 2 G][ 3 B][ 4 Y][ 5 M][ 6 C][ 7 W][ 8 .]' "$tmp/out" ||
  fail "--show: one colour per key: $(cat "$tmp/out")"
grep -qF '[ 1*r]' "$tmp/out" || fail "--show: blinking red: $(cat "$tmp/out")"
# PKP command 6500h/01h (one key) and PK1000 object 2001h (one colour plane) move the picture too.
printf '%s\n' '615#2300650101080700' > "$tmp/show.log"
"$pk" decode --model pkp2400 --show "$tmp/show.log" | grep -qF '[ 7 .][ 8 B]' ||
  fail "--show: 6500h/01h key 8 blue"
printf '%s\n' '615#2301200104000000' > "$tmp/show.log"
"$pk" decode --show "$tmp/show.log" | grep -qF '[ 2 .][ 3 R][ 4 .]' || fail "--show: 2001h red #3"

# encode from the command line (the issue's examples and manual rows).
check_encode() {
  local want=$1; shift
  local got
  got=$("$pk" encode "$@") || fail "encode $*: exit status"
  [ "$got" = "$want" ] || fail "encode $*: got '$got', want '$want'"
}
check_encode 215#4100040000000000 --model pkp2400 led-on red=1,7 blue=3
check_encode 215#0000010000000008 --model pk1000 led-on red=17 green=28
check_encode 215#596A740000000000 --model pkp2400 led-on red=1,4,5,7 green=2,4,6,7 blue=3,5,6,7
check_encode 000#0115 nmt command=start target=0x15
check_encode 63A#4008100000000000 --node 0x3A sdo-read object=device_name
"$pk" encode --model pkp2200 led-on red=5 > /dev/null 2>&1 && fail "key 5 on a PKP-2200 accepted"
"$pk" encode --model pk1000 led-on purple=1 > /dev/null 2>&1 && fail "unknown field accepted"
"$pk" encode --model pk1000 no-such-message > /dev/null 2>&1 && fail "unknown message accepted"

# encode --json checks the rebuilt frame against id/data.
echo '{"id":"000","ext":false,"data":"0215","model":"pk1000","node":21,"kind":"nmt","fields":{"command":"start","target":21}}' |
  "$pk" encode --json > /dev/null 2> "$tmp/err" && fail "a mismatching id/data accepted"
grep -q "<stdin>:1: rebuilt 000#0115 differs" "$tmp/err" || fail "mismatch message: $(cat "$tmp/err")"


# --- the bugs of issue 13, each with its check -----------------------------------------------------

# NMT encode goes to --node unless told to broadcast.
check_encode 000#813A --node 0x3A nmt command=reset_node
check_encode 000#8100 --node 0x3A --broadcast nmt command=reset_node
check_encode 000#8100 --node 0x3A nmt command=reset_node target=0
check_encode 000#0115 nmt command=start

# --show draws every model as the model table says: the PKP-3500-MT's 15 keys in three rows, keys 1
# and 11 without an LED, its two encoder rings (encoder_leds).
printf '%s\n' '195#0100000010' '415#0300000000000000' '215#0050000000000000' > "$tmp/show.log"
"$pk" decode --model pkp3500mt --show "$tmp/show.log" > "$tmp/out" || fail "--show pkp3500mt exit status"
grep -qxF '    [ 1* ][ 2 .][ 3 .][ 4 .][ 5 .]' "$tmp/out" || fail "--show pkp3500mt: key 1 (no LED): $(cat "$tmp/out")"
grep -qxF '    ring 1 **..............  ring 2 ................' "$tmp/out" || fail "--show pkp3500mt: rings: $(cat "$tmp/out")"
grep -qxF '    [11  ][12 .][13 R][14 .][15 R]' "$tmp/out" || fail "--show pkp3500mt: LEDs 13 15 red: $(cat "$tmp/out")"
printf '%s\n' '215#0001000000000000' > "$tmp/show.log"  # stride 8: LED 1 green
"$pk" decode --model pkp2400si --show "$tmp/show.log" | grep -qF '[ 1 G][ 2 .]' || fail "--show pkp2400si: stride 8"

# --model auto on the SI family: a reported model string (PKP3500MT), else the narrowest model
# that reads the log; a reported name whose model refuses frames does not win (pkp2600.log
# quotes the PKP manual's "PKU2400").
for m in pkp3500mt pkp2600si pkp2400si pkp2600; do
  "$pk" decode --model auto "$logs/$m.log" > /dev/null 2> "$tmp/err"
  head -1 "$tmp/err" | grep -q "^powerkey: --model auto: $m: " || fail "--model auto on $m.log: $(head -1 "$tmp/err")"
done

# --show never mixes into JSON: the combination is a usage error.
echo '195#01' | "$pk" decode --json --show > "$tmp/out" 2> "$tmp/err"; rc=$?
[ $rc -eq 2 ] && [ ! -s "$tmp/out" ] || fail "--json --show: status $rc, output $(cat "$tmp/out")"
grep -qx "powerkey: --show draws pictures for people and --json writes lines for programs: use one (powerkey help shows the usage)" "$tmp/err" ||
  fail "--json --show message: $(cat "$tmp/err")"

# Strings from the bus are escaped: an uploaded ESC ] 0 ; A BEL LF reaches no terminal.
printf '%s\n' '615#4008100000000000' '595#4108100007000000' '615#6000000000000000' '595#011B5D303B41070A' > "$tmp/esc.log"
"$pk" decode "$tmp/esc.log" > "$tmp/out" 2> /dev/null
grep -qF '[text: "\x1B]0;A\x07\x0A"]' "$tmp/out" || fail "uploaded text not escaped: $(tail -1 "$tmp/out")"
LC_ALL=C grep -q $'\x1b' "$tmp/out" && fail "an escape character reached the output"
"$pk" decode --json "$tmp/esc.log" 2> /dev/null | tail -1 | grep -qF '"text":"\u001B]0;A\u0007\u000A"' ||
  fail "uploaded text not escaped in JSON"
# ... and so is echoed input, shortened.
{ printf '195#01 \x1b[31m'; head -c 300 /dev/zero | tr '\0' 'x'; echo; } > "$tmp/esc2.log"
"$pk" decode "$tmp/esc2.log" > /dev/null 2> "$tmp/err"
LC_ALL=C grep -q $'\x1b' "$tmp/err" && fail "an escape character of the input reached stderr"
grep -qF "(line 1: unexpected text after the frame: '195#01 \x1B[31mxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...')" "$tmp/err" ||
  fail "echoed input not escaped and shortened: $(cat "$tmp/err")"

# The J1939 frame: decoded and applied under the PK1000 and the SI family; under a PKP-LI the J1939
# codec refuses it (no PKP source shows 80h) and it is not applied.
echo '18EF2100#041B8000FFFFFFFF' > "$tmp/j1939.log"
[ "$("$pk" decode "$tmp/j1939.log" 2> /dev/null)" = "18EF2100#041B8000FFFFFFFF  node 15h  J1939 switch to CANopen  priority: 6  destination: 21h  source: 00h  [protocol now canopen]" ] ||
  fail "J1939 switch under pk1000: $("$pk" decode "$tmp/j1939.log" 2>&1)"
for m in pkp2200 pkp2400 pkp2600; do
  [ "$("$pk" decode --model $m "$tmp/j1939.log" 2> /dev/null)" = "18EF2100#041B8000FFFFFFFF  j1939  error: undocumented" ] ||
    fail "J1939 frame under $m: $("$pk" decode --model $m "$tmp/j1939.log" 2>&1)"
  "$pk" decode --json --model $m "$tmp/j1939.log" 2> /dev/null | grep -q '"protocol"' && fail "J1939 under $m switches protocol in JSON"
done
for m in pkp2600si pkp3500mt pkp2400si; do
  "$pk" decode --model $m "$tmp/j1939.log" 2> /dev/null | grep -qF "J1939 switch to CANopen" ||
    fail "J1939 switch under $m: $("$pk" decode --model $m "$tmp/j1939.log" 2>&1)"
done

# A frame of no keypad says so once.
[ "$(echo '7E5#4C' | "$pk" decode 2> /dev/null)" = "7E5#4C                     unknown frame: no keypad uses COB-ID 7E5h" ] ||
  fail "7E5#4C: $(echo '7E5#4C' | "$pk" decode 2>&1)"

# Model names in any case and as the manuals write them; others are usage errors.
for m in PKP-2400 pkp-2400 PKP-2400-LI PKP2400 pkp2400; do
  [ "$(echo '195#0100000010' | "$pk" decode --model $m 2> /dev/null)" = "195#0100000010             node 15h  key state  keys: 1  tick: 16" ] ||
    fail "--model $m: $(echo '195#0100000010' | "$pk" decode --model $m 2>&1)"
done
for m in PK1000 pk-1000 Pk1000 PKP-3500-MT pkp3500mt PKP2600SI pkp_2400_si PKU2400; do
  echo 195#01 | "$pk" decode --model $m > /dev/null 2>&1 || fail "--model $m refused"
done

# Option errors are usage errors (2), never a missing file; list takes no arguments.
usage() {
  local want=$1; shift
  "$pk" "$@" > "$tmp/out" 2> "$tmp/err"; local rc=$?
  [ $rc -eq 2 ] || fail "$*: exit status $rc, want 2"
  [ "$(cat "$tmp/err")" = "$want" ] || fail "$*: '$(cat "$tmp/err")', want '$want'"
}
usage "powerkey: The following argument was not expected: --modle (powerkey help shows the usage)" decode "$tmp/b" --modle pkp2400
usage "powerkey: The following argument was not expected: -model (powerkey help shows the usage)" decode "$tmp/b" -model pkp2400
usage "powerkey: The following argument was not expected: extra (powerkey help shows the usage)" list extra
usage "powerkey: --model: unknown model 'pkp3000' (pk1000, pkp2200, pkp2400, pkp2600, pkp2600si, pkp3500mt, pkp3500si, pkp2500si, pkp1500li, pkp2200si, pkp2300si, pkp2400si, pkp1600si, auto) (powerkey help shows the usage)" decode --model pkp3000 "$tmp/b"
usage "powerkey: --node: expected a node id 1..127 (0x15, 15h or 21), got '128' (powerkey help shows the usage)" decode --node 128 "$tmp/b"
usage "powerkey: The following argument was not expected: frobnicate (powerkey help shows the usage)" frobnicate
# Options before the subcommand work as after it.
[ "$("$pk" --model pkp2400 encode led-on red=1)" = "215#0100000000000000" ] || fail "option before the subcommand"

# help says the exit codes and the input forms.
"$pk" help > "$tmp/help" || fail "help exit status"
for s in "Exit status (every subcommand):" "  0 all input read" "  1 bad input" "  2 usage" "powerkey simulate --model M" "powerkey check --model M" "Vector ASC, PEAK TRC 1.x and 2.x, python-can CSV, Vector BLF" "195#09.00.00.00.12"; do
  grep -qF "$s" "$tmp/help" || fail "help lacks '$s'"
done

# --- one way to write numbers; what the text prints, encode takes back ---------------------------
"$pk" decode "$logs/pk1000.log" > "$tmp/text" 2> /dev/null
grep -qF "node 15h  SDO write  object: node_id  node_id: 3Ah  [node id now 3Ah]" "$tmp/text" || fail "node id in hex: $(grep -m1 node_id "$tmp/text")"
grep -qF "SDO read reply  object: rpdo1_cob_id  invalid: no  no_rtr: yes  can_id: 215h" "$tmp/text" || fail "COB-ID in hex"
grep -qF "SDO read reply  object: vendor_id  value: 3E2h" "$tmp/text" || fail "identity word in hex"
grep -qF "destination: 21h  source: 00h" "$tmp/text" || fail "J1939 addresses in hex"
check_encode 215#FFFFFF0F00000000 --model pk1000 led-on red=1-28
check_encode 215#4100000000000008 --model pk1000 led-on "red=1 7" green=28
check_encode 000#013A nmt command=start target=3Ah
check_encode 615#2F1320003A000000 sdo-write object=node_id node_id=3Ah
check_encode 615#2F1320003A000000 sdo_write object=node_id node_id=0x3A
check_encode 595#011B5D303B41070A sdo-segment-response last=yes "data=1B 5D 30 3B 41 07 0A"
# Every decoded line of every sample log is encoded back from its own text (fields as printed).
for m in $models; do
  # "(t) can0 215#...  node 15h  LED on  red: 1 7  green: -  [..]" -> frame, node, kind, FIELD=VALUE
  "$pk" decode --model $m "$logs/$m.log" 2> /dev/null | grep -v "  error: \|another node\|unknown frame" |
    awk -F'  +' '{ split($1, w, " "); frame = w[3]; node = $2; sub(/^node /, "", node)
                   kind = tolower($3); gsub(/ /, "_", kind); out = frame "\t" node "\t" kind
                   for (i = 4; i <= NF; i++) { if ($i ~ /^\[/) break; f = $i; sub(/: /, "=", f); out = out "\t" f }
                   print out }' > "$tmp/lines"
  [ "$(wc -l < "$tmp/lines")" -gt 20 ] || fail "$m: too few lines to encode back"
  while IFS=$'\t' read -r -a a; do
    got=$("$pk" encode --model $m --node "${a[1]}" "${a[@]:2}" 2>&1) ||
      { fail "$m: '${a[*]}' does not encode back: $got"; continue; }
    [ "$got" = "${a[0]}" ] || fail "$m: '${a[*]}' encodes back to $got"
  done < "$tmp/lines"
done

# Encode errors name the field and the allowed values or range.
encode_error() {
  local want=$1; shift
  "$pk" encode "$@" > /dev/null 2> "$tmp/err" && fail "encode $* accepted"
  [ "$(cat "$tmp/err")" = "$want" ] || fail "encode $*: '$(cat "$tmp/err")', want '$want'"
}
encode_error "powerkey: encode: led_on: red: '5' is more than a pkp2200 takes (1..4)" --model pkp2200 led-on red=5
encode_error "powerkey: encode: led_brightness: level: 99 is outside 00h..3Fh" led-brightness level=99
encode_error "powerkey: encode: sdo_write: level: 99 is outside 00h..3Fh" sdo-write object=led_brightness level=99
encode_error "powerkey: encode: nmt_message: command: unknown name 'jump' (start, stop, pre_operational, reset_node, reset_communication, legacy_stop)" nmt command=jump
encode_error "powerkey: encode: no field 'purple' in led_on (fields: red, green, blue)" led-on purple=1
encode_error "powerkey: encode: led_on: red: '29' is more than a pk1000 takes (1..28)" led-on red=29
encode_error "powerkey: encode: encoder_state is not a message of a pk1000 (powerkey list --model pk1000 shows its messages)" encoder-state ticks=3
check_encode 2BA#8305000000000000 --model pkp3500mt --node 0x3A encoder-state counterclockwise=yes ticks=3 counter=5
encode_error "powerkey: encode: nmt_message: target: 128 is outside 00h..7Fh" nmt target=128

# encode --json --node N re-targets a logged message to node N (a log replayed to another keypad).
"$pk" decode --json "$logs/pk1000.log" 2> /dev/null | head -12 > "$tmp/json12"
"$pk" encode --json --node 0x3A < "$tmp/json12" > "$tmp/moved" || fail "encode --json --node: exit status"
cat > "$tmp/want" <<EOF
000#013A
000#803A
000#813A
000#023A
73A#00
080#
1BA#000000002A
1BA#010000002A
1BA#080000002A
1BA#090000002A
1BA#000100002A
1BA#000200002A
EOF
diff "$tmp/want" "$tmp/moved" > /dev/null || fail "encode --json --node 0x3A: $(paste -sd' ' "$tmp/moved")"

# Every decode ends with a summary; a log that decodes badly under the model ends with a hint.
"$pk" decode "$logs/pkp2400.log" > /dev/null 2> "$tmp/err"
tail -1 "$tmp/err" | grep -qx "powerkey: hint: [0-9]* of [0-9]* keypad frames refused as pk1000 frames; if the keypad is another model, try --model auto (or --model pk1000, pkp2200, pkp2400, pkp2600, pkp2600si, pkp3500mt, pkp3500si, pkp2500si, pkp1500li, pkp2200si, pkp2300si, pkp2400si, pkp1600si)" ||
  fail "no hint for a PKP log decoded as pk1000: $(cat "$tmp/err")"
# docs/cli.md shows this very run: its summary and hint are the tool's, word for word.
grep -A2 -xF '$ powerkey decode examples/logs/pkp2400.log > /dev/null' "$src/docs/cli.md" | tail -2 |
  diff - "$tmp/err" > /dev/null || fail "docs/cli.md's summary and hint of pkp2400.log are stale: $(cat "$tmp/err")"
# --model auto finds the model from the keypad's own name, or from what decodes.
"$pk" decode --model auto "$logs/pkp2400.log" > "$tmp/auto" 2> "$tmp/err" || fail "--model auto exit status"
head -1 "$tmp/err" | grep -qx 'powerkey: --model auto: pkp2400: the keypad names itself "PKP-2400-LI"\|powerkey: --model auto: pkp2400: .*' ||
  fail "--model auto on pkp2400.log: $(cat "$tmp/err")"
"$pk" decode --model pkp2400 "$logs/pkp2400.log" 2> /dev/null | cmp -s - "$tmp/auto" || fail "--model auto output differs from --model pkp2400"
printf '%s\n' '000#0115' '080#' > "$tmp/plain.log"
"$pk" decode --model auto "$tmp/plain.log" > /dev/null 2> "$tmp/err"
head -1 "$tmp/err" | grep -qx "powerkey: --model auto: cannot tell the model: no frame of the log decodes differently under the 13 models (no model string, no key or LED map); decoding as pk1000, give --model" ||
  fail "--model auto without clues: $(cat "$tmp/err")"
# --model auto counts a refused frame of the keypad's own COB-ID (a PDO the model lacks: wrong_id)
# as decode's summary does, so it never picks a model that refuses more than another: the LED
# brightness and backlight PDOs of faults/trimmed.log, which the PKP LI models lack, rule them out.
"$pk" decode --model auto "$logs/faults/trimmed.log" > /dev/null 2> "$tmp/err"
head -1 "$tmp/err" | grep -q "^powerkey: --model auto: pkp2200si: it refuses 0 of the keypad's frames (pk1000 0, pkp2200 2, " &&
  tail -1 "$tmp/err" | grep -qx "powerkey: summary: 6 frames: 6 decoded, 0 of other nodes or no keypad, 0 refused" ||
  fail "--model auto counts wrong_id of the keypad: $(cat "$tmp/err")"

# A file that is not a log gets one message saying what it looks like and what to do.
printf '\xd4\xc3\xb2\xa1\x02\x00\x04\x00' > "$tmp/cap.pcap"
"$pk" decode "$tmp/cap.pcap" > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 1 ] || fail "pcap: exit status $rc"
[ "$(head -1 "$tmp/err")" = "powerkey: $tmp/cap.pcap: looks like a pcap capture, not a CAN log powerkey reads; record the bus with candump -l, or export the capture's CAN frames as a candump log" ] ||
  fail "pcap message: $(cat "$tmp/err")"
seq 1 1000 | sed 's/^/garbage line /' > "$tmp/garbage.txt"
"$pk" decode "$tmp/garbage.txt" > /dev/null 2> "$tmp/err"
[ "$(wc -l < "$tmp/err")" -eq 2 ] || fail "a thousand bad lines gave $(wc -l < "$tmp/err") messages"
# Repeated errors after the first frames: three shown, the rest counted.
{ echo 195#01; seq 1 1000 | sed 's/^/garbage line /'; } > "$tmp/mixed.txt"
"$pk" decode "$tmp/mixed.txt" > /dev/null 2> "$tmp/err"
cat > "$tmp/want" <<EOF
powerkey: $tmp/mixed.txt:2: not a frame (expected ID#DATA or a candump line): 'garbage line 1'
powerkey: $tmp/mixed.txt:3: not a frame (expected ID#DATA or a candump line): 'garbage line 2'
powerkey: $tmp/mixed.txt:4: not a frame (expected ID#DATA or a candump line): 'garbage line 3'
powerkey: $tmp/mixed.txt: 997 more lines like that (not a frame (expected ID#DATA or a candump line))
powerkey: summary: 1 frame: 0 decoded, 0 of other nodes or no keypad, 1 refused (wrong_length 1); 1000 bad lines
EOF
diff "$tmp/want" "$tmp/err" > /dev/null || fail "repeated errors: $(cat "$tmp/err")"

# docs/cli.md lists every default as encode fills it: the blocks are powerkey list's output.
for m in pk1000 pkp2400 pkp3500mt; do
  awk -v m="<!-- list $m -->" '$0 == m { on = 1; next } on && /^```$/ { if (started) exit; started = 1; next } on && started' \
    "$src/docs/cli.md" > "$tmp/doc_list"
  [ -s "$tmp/doc_list" ] || fail "docs/cli.md has no list block for $m"
  "$pk" list --model $m | diff - "$tmp/doc_list" > /dev/null || fail "docs/cli.md: the defaults of $m differ from powerkey list"
done
for m in pkp2200 pkp2600; do
  cmp -s <("$pk" list --model $m) <("$pk" list --model pkp2400) || fail "list --model $m differs from pkp2400 (docs/cli.md says they match)"
done
# The other SI models list pkp3500mt's messages without its encoder messages, with
# led_brightness (all but the PKP-1500-LI) and j1939_multiple_leds (the three with the command),
# as docs/cli.md says under the pkp3500mt block.
"$pk" list --model pkp3500mt | grep -v '^encoder_state \|^analog_inputs \|^encoder_leds ' > "$tmp/si_list"
for m in pkp2600si pkp3500si pkp2500si pkp1500li pkp2200si pkp2300si pkp2400si pkp1600si; do
  case $m in pkp1500li) b=no ;; *) b=yes ;; esac
  case $m in pkp2600si | pkp3500si | pkp1600si) ml=yes ;; *) ml=no ;; esac
  "$pk" list --model $m | grep -v "^led_brightness \|^j1939_multiple_leds " | cmp -s - "$tmp/si_list" &&
    [ "$("$pk" list --model $m | grep -c '^led_brightness ')" = "$([ $b = yes ] && echo 1 || echo 0)" ] &&
    [ "$("$pk" list --model $m | grep -c '^j1939_multiple_leds ')" = "$([ $ml = yes ] && echo 1 || echo 0)" ] ||
    fail "list --model $m is not pkp3500mt's as docs/cli.md says (led_brightness $b, j1939_multiple_leds $ml)"
done
grep -qF 'encoder messages, with `led_brightness` but the PKP-1500-LI, and with `j1939_multiple_leds` the' "$src/docs/cli.md" ||
  fail "docs/cli.md: the SI models' list sentence is stale"

# --- one program: every subcommand reads, reports and ends alike -----------------------------------

# The table of docs/cli.md lists exactly the subcommands of powerkey help.
awk '/^<!-- subcommands -->$/ { on = 1; next } on && /^$/ { exit } on && /^\| `/ { print }' "$src/docs/cli.md" |
  sed -E 's/^\| `([a-z-]+)`.*/\1/' | sort > "$tmp/doc_subs"
"$pk" help | awk '/^$/ { block++; next } block == 1 { print $1 }' | sort > "$tmp/help_subs"
[ -s "$tmp/doc_subs" ] && diff "$tmp/help_subs" "$tmp/doc_subs" > /dev/null ||
  fail "docs/cli.md's table of subcommands differs from powerkey help: $(diff "$tmp/help_subs" "$tmp/doc_subs" | paste -sd' ')"
# Each subcommand that reads logs: the same words and statuses for the same input. (The docs
# table says which read logs; encode --json reads JSON lines through the same file reading.)
readers=$(awk '/^<!-- subcommands -->$/ { on = 1; next } on && /^$/ { exit } on && /^\| `[a-z]+` \| logs/ { print }' "$src/docs/cli.md" |
  sed -E 's/^\| `([a-z]+)`.*/\1/')
[ "$(echo $readers)" = "decode simulate check convert" ] || fail "the log readers of the table: $readers"
run_sub() {  # run_sub SUBCOMMAND ARGS... with the model a subcommand needs
  local sub=$1; shift
  case $sub in
    simulate | check) "$pk" $sub --model pk1000 "$@" ;;
    *) "$pk" $sub "$@" ;;
  esac
}
{ printf '\xef\xbb\xbf'; cat "$logs/check-clean.log"; } > "$tmp/bom.log"
printf '%s\n' '(1700000000.000000) can0 715#00' "$(printf '615#40 \x1b]0;pwned\x07')" > "$tmp/hostile.log"
{ echo '(1700000000.000000) can0 715#00'; seq 1 1000 | sed 's/^/garbage line /'; } > "$tmp/many.log"
for sub in $readers; do
  run_sub $sub "$tmp/missing.log" > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 1 ] && [ "$(head -1 "$tmp/err")" = "powerkey: $tmp/missing.log: No such file or directory" ] ||
    fail "$sub: a missing file: status $rc, '$(head -1 "$tmp/err")'"
  run_sub $sub "$tmp/bom.log" > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 0 ] && [ ! -s "$tmp/err" -o $sub = decode ] || fail "$sub: a byte-order mark: status $rc, $(head -2 "$tmp/err")"
  run_sub $sub "$tmp/hostile.log" > "$tmp/out" 2> "$tmp/err"; rc=$?
  [ $rc -eq 1 ] && grep -qxF "powerkey: $tmp/hostile.log:2: unexpected text after the frame: '615#40 \x1B]0;pwned\x07'" "$tmp/err" ||
    fail "$sub: a hostile line: status $rc, $(head -2 "$tmp/err")"
  LC_ALL=C grep -q $'\x1b' "$tmp/out" "$tmp/err" && fail "$sub: an escape character of the input reached the terminal"
  printf 'nonsense\n715#00\n' | run_sub $sub > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 1 ] && grep -qxF "powerkey: <stdin>:1: not a frame (expected ID#DATA or a candump line): 'nonsense'" "$tmp/err" ||
    fail "$sub: standard input: status $rc, $(head -2 "$tmp/err")"
  run_sub $sub "$tmp/many.log" > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 1 ] && [ "$(grep -c "garbage line" "$tmp/err")" -eq 3 ] &&
    grep -qxF "powerkey: $tmp/many.log: 997 more lines like that (not a frame (expected ID#DATA or a candump line))" "$tmp/err" ||
    fail "$sub: a thousand bad lines: status $rc, $(wc -l < "$tmp/err") lines"
  printf 'LOGG\x90\x00\x00\x00' | run_sub $sub > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 1 ] && [ "$(head -1 "$tmp/err")" = "powerkey: <stdin>: the BLF file ends inside its header (truncated?)" ] ||
    fail "$sub: a cut BLF file: status $rc, $(head -2 "$tmp/err")"
done
# The same model error for every subcommand that takes --model; none for those that do not.
want_model="powerkey: --model: unknown model 'pkp2401' (pk1000, pkp2200, pkp2400, pkp2600, pkp2600si, pkp3500mt, pkp3500si, pkp2500si, pkp1500li, pkp2200si, pkp2300si, pkp2400si, pkp1600si) (powerkey help shows the usage)"
for sub in "encode nmt" list simulate check; do
  "$pk" $sub --model pkp2401 < /dev/null > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 2 ] && [ "$(cat "$tmp/err")" = "$want_model" ] || fail "$sub --model pkp2401: status $rc, '$(cat "$tmp/err")'"
done
for sub in convert models; do
  "$pk" $sub --model pk1000 < /dev/null > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 2 ] && grep -q "^powerkey: $sub takes no --model or --node" "$tmp/err" || fail "$sub --model: status $rc, $(cat "$tmp/err")"
done
# decode --json --nlohmann-writer (a benchmark option, docs/cli.md) writes the same lines as the
# tool's own writer: the generic keys, J1939 identifier parts and upload errors included.
printf '%s\n' '18EFFF21#041B01110121FFFF' '18FEF100#FFFFFFFFFFFFFFFF' '615#4008100000000000' \
  '595#4108100020000000' '615#6000000000000000' '595#10FF225C0D0A7F00' > "$tmp/mixed.log"
for log in "$tmp/mixed.log" "$logs/switch-pkp2600si.log" "$logs/pk1000.log" "$logs/check-problems.log"; do
  "$pk" decode --model pkp2600si --json "$log" > "$tmp/own" 2> /dev/null
  "$pk" decode --model pkp2600si --json --nlohmann-writer "$log" 2> /dev/null | cmp -s - "$tmp/own" ||
    fail "--nlohmann-writer differs on $log: $("$pk" decode --model pkp2600si --json --nlohmann-writer "$log" 2> /dev/null | diff - "$tmp/own" | head -3)"
done
# The usage's input text says what becomes of remote and CAN FD frames as convert does: written.
printf '%s\n' '615#R' '615##1AABB' | "$pk" convert > "$tmp/out" 2> /dev/null
[ "$(awk '{print $3}' "$tmp/out" | tr '\n' ' ')" = "615#R 615##1AABB " ] || fail "convert of remote and CAN FD: $(cat "$tmp/out")"
"$pk" help > "$tmp/help"
grep -qxF "  Remote, CAN FD and error frames are counted, not decoded (convert writes the remote and" "$tmp/help" ||
  fail "the usage says remote and CAN FD frames are skipped by every subcommand: $(grep -A1 Remote "$tmp/help")"
# A subcommand that needs --model names no default model in its help; the others name pk1000's.
for sub in simulate check export; do
  "$pk" help $sub > "$tmp/help"
  grep -q "^  --model M    pk1000, pkp2200, " "$tmp/help" && ! grep -q "(default), pkp2200" "$tmp/help" ||
    fail "help $sub: --model is required, yet: $(grep -A1 -e '--model M  ' "$tmp/help")"
done
for sub in decode encode list; do
  "$pk" help $sub > "$tmp/help"
  grep -q "^  --model M    pk1000 (default), pkp2200, " "$tmp/help" || fail "help $sub: --model's default"
done
# Each says why in its own words: convert reads logs of any bus; models reads no log at all.
"$pk" convert --node 5 < /dev/null > /dev/null 2> "$tmp/err"
grep -qx "powerkey: convert takes no --model or --node or --address (it reads logs of any bus) (powerkey help shows the usage)" "$tmp/err" ||
  fail "convert --node: the reason: $(cat "$tmp/err")"
"$pk" models --model pk1000 > /dev/null 2> "$tmp/err"
grep -qx "powerkey: models takes no --model or --node or --address (the model is its argument: powerkey models NAME) (powerkey help shows the usage)" "$tmp/err" ||
  fail "models --model: the reason: $(cat "$tmp/err")"
for sub in simulate check; do
  "$pk" $sub < /dev/null > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 2 ] && grep -q "^powerkey: $sub needs --model M (pk1000, " "$tmp/err" || fail "$sub without --model: status $rc, $(cat "$tmp/err")"
done
# encode --json: the same file reading and the same cap.
"$pk" encode --json "$tmp/missing.log" > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 1 ] && [ "$(cat "$tmp/err")" = "powerkey: $tmp/missing.log: No such file or directory" ] || fail "encode --json: a missing file: $rc $(cat "$tmp/err")"
seq 1 1000 | sed 's/^/garbage line /' | "$pk" encode --json > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 1 ] && [ "$(wc -l < "$tmp/err")" -eq 4 ] && grep -qxF "powerkey: <stdin>: 997 more lines like that (not a JSON object)" "$tmp/err" ||
  fail "encode --json: a thousand bad lines: $rc $(tail -1 "$tmp/err")"
"$pk" decode --json "$logs/pk1000.log" 2> /dev/null > "$tmp/all.json"
{ printf '\xef\xbb\xbf'; head -3 "$tmp/all.json"; } > "$tmp/bom.json"
"$pk" encode --json "$tmp/bom.json" > "$tmp/out" 2> "$tmp/err" && [ "$(wc -l < "$tmp/out")" -eq 3 ] ||
  fail "encode --json: a byte-order mark: $(cat "$tmp/err")"
# Every subcommand has its help, and a help naming no subcommand is a usage error.
for sub in $(cat "$tmp/help_subs"); do
  "$pk" help $sub | head -1 | grep -q "^usage: powerkey $sub" || fail "powerkey help $sub"
  "$pk" $sub --help | head -1 | grep -q "^usage: powerkey $sub" || fail "powerkey $sub --help"
done
"$pk" help frobnicate > /dev/null 2>&1; [ $? -eq 2 ] || fail "help of an unknown subcommand"
# models: the model table, and the one name a name stands for.
[ "$("$pk" models | awk '{ print $1 }' | paste -sd' ')" = "$models" ] || fail "powerkey models: $("$pk" models | head -3)"
[ "$("$pk" models PKP-3500-MT)" = pkp3500mt ] || fail "powerkey models PKP-3500-MT"

# --- hostile input: bounded, loud, never silent (docs/security.md) ---------------------------------
# Each hostile file is made here, cut to the limit it tests: a line one byte over the cap, not
# gigabytes.
py=/usr/bin/python3
# A log line past logs::limits::text_line_bytes (65536): every subcommand stops reading there,
# names the line and the limit, status 1, and reads no more of it (an endless line ends at once).
{ echo '195#01'; head -c 65537 /dev/zero | tr '\0' A; echo; echo '195#02'; } > "$tmp/long.log"
{ echo '195#01'; head -c 65536 /dev/zero | tr '\0' A; echo; echo '195#02'; } > "$tmp/longest.log"
long_why="a line longer than 65536 bytes, the limit of a log line (the rest of the input is not read)"
sixty_a=$(printf 'A%.0s' $(seq 60))
for sub in $readers; do
  run_sub $sub "$tmp/long.log" > "$tmp/out" 2> "$tmp/err"; rc=$?
  [ $rc -eq 1 ] && grep -qxF "powerkey: $tmp/long.log:2: $long_why: '$sixty_a...'" "$tmp/err" ||
    fail "$sub: a line over the limit: status $rc, $(head -c 300 "$tmp/err")"
  grep -q "195#02" "$tmp/out" && fail "$sub: read past a line over the limit"
  run_sub $sub "$tmp/longest.log" > /dev/null 2> "$tmp/err"
  grep -q "limit of a log line" "$tmp/err" && fail "$sub: a line of exactly the limit refused"
  # Endless, through a pipe: it ends at once, at flat memory.
  tr '\0' A < /dev/zero | timeout 20 "$pk" $sub $([ $sub = simulate -o $sub = check ] && echo --model pk1000) > /dev/null 2> "$tmp/err"
  rc=${PIPESTATUS[1]}
  [ $rc -eq 1 ] && grep -qF "<stdin>:1: $long_why" "$tmp/err" || fail "$sub: an endless line: status $rc, $(head -c 200 "$tmp/err")"
  # A directory: status 1 and its name, in every subcommand.
  run_sub $sub "$tmp" > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 1 ] && grep -qxF "powerkey: $tmp: Is a directory" "$tmp/err" || fail "$sub: a directory: status $rc, $(cat "$tmp/err")"
done
# A bad frame holding an escape sequence, 60 KB long: escaped and cut to 60 bytes in every
# subcommand (simulate wrote its ESC ... BEL raw, and the whole line).
{ echo '000#0115'; printf '195#01\033]0;x\a'; head -c 60000 /dev/zero | tr '\0' A; echo; } > "$tmp/esc.log"
for sub in $readers; do
  run_sub $sub "$tmp/esc.log" > /dev/null 2> "$tmp/err"
  grep -qxF "powerkey: $tmp/esc.log:2: malformed frame (expected ID#DATA): '195#01\x1B]0;x\x07$(printf 'A%.0s' $(seq 48))...'" "$tmp/err" ||
    fail "$sub: a long bad frame with an escape sequence: $(head -c 300 "$tmp/err")"
done
# A binary file says so at once, whatever its length (decode /dev/zero read on to the end).
timeout 20 "$pk" decode /dev/zero > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 1 ] && grep -qxF "powerkey: /dev/zero: looks like a binary file that is not Vector BLF, not a CAN log powerkey reads; it reads candump and cansend lines, Vector ASC, PEAK TRC, python-can CSV and Vector BLF" "$tmp/err" ||
  fail "decode /dev/zero: status $rc, $(head -2 "$tmp/err")"
# ... the same from a file as through a pipe, whatever arrives first.
printf 'abcd\0\0\0\n195#0115\n' > "$tmp/nul.log"
"$pk" decode "$tmp/nul.log" > "$tmp/file.out" 2> /dev/null; rc1=$?
{ printf 'abcd'; sleep 0.3; printf '\0\0\0\n195#0115\n'; } | "$pk" decode > "$tmp/pipe.out" 2> /dev/null; rc2=$?
[ $rc1 -eq 1 ] && [ $rc2 -eq 1 ] && [ ! -s "$tmp/file.out" ] && [ ! -s "$tmp/pipe.out" ] ||
  fail "a NUL in the first line: file $rc1 '$(cat "$tmp/file.out")', pipe $rc2 '$(cat "$tmp/pipe.out")'"
# A JSON line past logs::limits::json_line_bytes: encode --json stops there.
{ head -c 65537 /dev/zero | tr '\0' '{'; echo; } > "$tmp/long.json"
"$pk" encode --json "$tmp/long.json" > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 1 ] && grep -qxF "powerkey: $tmp/long.json:1: a line longer than 65536 bytes, the limit of a JSON line (the rest of the input is not read): '$(printf '{%.0s' $(seq 60))...'" "$tmp/err" ||
  fail "encode --json: a JSON line over the limit: status $rc, $(head -c 300 "$tmp/err")"
tr '\0' x < /dev/zero | timeout 20 "$pk" encode --json > /dev/null 2> "$tmp/err"; rc=${PIPESTATUS[1]}
[ $rc -eq 1 ] && grep -qF "<stdin>:1: a line longer than 65536 bytes" "$tmp/err" || fail "encode --json: an endless line: $rc"

# TRC: a version, columns or a time the reader cannot use is an error, never 0 frames and 0.
printf ';$FILEVERSION=3.0\n     1)  0.0  Rx  0195  1  01\n' > "$tmp/v3.trc"
printf ';$FILEVERSION=2.1\n;$COLUMNS=\n      1      1.0 DT  1     0195 Rx -  1    01\n' > "$tmp/empty.trc"
printf ';$FILEVERSION=2.1\n;$COLUMNS=N,T,B,I,d,R,L,D\n      1  DT  1     0195 Rx -  1    01\n' > "$tmp/notime.trc"
printf ';$FILEVERSION=1.1\n     1)  1e308  Rx  0195  1  01\n' > "$tmp/time.trc"
for f in v3 empty notime time; do
  "$pk" decode "$tmp/$f.trc" > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 1 ] || fail "TRC $f: status $rc, $(cat "$tmp/err")"
done
grep -qxF "powerkey: $tmp/time.trc:2: malformed TRC line (time): '1)  1e308  Rx  0195  1  01'" "$tmp/err" || fail "TRC time: $(cat "$tmp/err")"
"$pk" decode "$tmp/v3.trc" > /dev/null 2> "$tmp/err"
grep -qxF "powerkey: $tmp/v3.trc:1: a TRC file version powerkey does not read (it reads 1.0 to 1.3, 2.0 and 2.1): ';\$FILEVERSION=3.0'" "$tmp/err" ||
  fail "TRC 3.0: $(cat "$tmp/err")"
for f in empty notime; do
  "$pk" decode "$tmp/$f.trc" > /dev/null 2> "$tmp/err"
  grep -qF "$f.trc:2: unusable TRC columns" "$tmp/err" || fail "TRC $f: $(cat "$tmp/err")"
done

# Hostile BLF files, made by python3's struct and zlib.
if [ -x "$py" ]; then
  cat > "$tmp/blf.py" <<'PY'
# The hostile BLF files of issue 26: blf.py KIND OUT
import struct, sys, zlib
kind, out = sys.argv[1], sys.argv[2]
header = b"LOGG" + struct.pack("<I", 144) + bytes(136)
def can(ident, size=48):  # CAN_MESSAGE: 32-byte header (10 us), channel 1, dlc 2, 8 bytes
    return (b"LOBJ" + struct.pack("<HHII", 32, 1, size, 1) + struct.pack("<IIQ", 1, 0, 100000)
            + struct.pack("<HBBI", 1, 0, 2, ident) + bytes([1, 0x15]) + bytes(6))
def container(data, method=2):
    payload = zlib.compress(data) if method == 2 else data
    obj = (b"LOBJ" + struct.pack("<HHII", 16, 1, 32 + len(payload), 10)
           + struct.pack("<H6xI4x", method, len(data)) + payload)
    return obj + bytes(-len(obj) % 4)
if kind == "tail":  # an object claiming 0xFFFFFFF0 bytes, then containers of 16 MiB of zeros
    body = container(can(0x195, 0xFFFFFFF0)) + container(bytes(16 << 20)) * 15
elif kind == "nested":  # 10,000 containers around one frame
    body = can(0x195)
    for level in range(10000):
        body = (b"LOBJ" + struct.pack("<HHII", 16, 1, 32 + len(body), 10)
                + struct.pack("<H6xI4x", 0, len(body)) + body)
elif kind == "cut":  # a message cut short inside the last compressed container
    body = container(can(0x195) + can(0x215)[:22])
open(out, "wb").write(header + body)
PY
  for k in tail nested cut; do "$py" "$tmp/blf.py" $k "$tmp/$k.blf" || fail "blf.py $k"; done
  [ "$(wc -c < "$tmp/tail.blf")" -lt 400000 ] || fail "tail.blf: $(wc -c < "$tmp/tail.blf") bytes"
  for sub in $readers; do
    run_sub $sub "$tmp/tail.blf" > /dev/null 2> "$tmp/err"; rc=$?
    [ $rc -eq 1 ] && grep -qxF "powerkey: $tmp/tail.blf: object 2: a BLF object of 4294967280 bytes inside a container, more than the 1048576 the reader takes (damaged file?)" "$tmp/err" ||
      fail "$sub: a BLF object claiming 4 GiB in a container: status $rc, $(cat "$tmp/err")"
    run_sub $sub "$tmp/nested.blf" > /dev/null 2> "$tmp/err"; rc=$?
    [ $rc -eq 1 ] && grep -qxF "powerkey: $tmp/nested.blf: object 2: a BLF container inside a container (no writer nests them; the reader takes containers at the top level only)" "$tmp/err" ||
      fail "$sub: nested BLF containers: status $rc, $(cat "$tmp/err")"
    run_sub $sub "$tmp/cut.blf" > /dev/null 2> "$tmp/err"; rc=$?
    [ $rc -eq 1 ] && grep -qxF "powerkey: $tmp/cut.blf: object 3: the BLF file ends inside this object, in its last container (truncated?)" "$tmp/err" ||
      fail "$sub: a message cut in the last container: status $rc, $(cat "$tmp/err")"
  done
  # A BLF file counts objects, never "line 0".
  "$pk" decode "$tmp/cut.blf" 2>&1 | grep -q "line 0\|:0:" && fail "a BLF error at line 0"
fi

# --model auto keeps at most limits::model_auto_bytes (64 MiB) of frames before it chooses: a log
# whose frames carry 60 KB times fills it after about 1,100 frames, and the rest is decoded as
# it comes (it kept every frame: 160 bytes a frame of a 2.8 million-frame BLF).
"$py" -c 'import sys; sys.stdout.write(("(1." + "0" * 60000 + ") can0 195#0100000010\n") * 1300)' |
  "$pk" decode --model auto > /dev/null 2> "$tmp/err"; rc=${PIPESTATUS[1]}
[ $rc -eq 0 ] && grep -qE "^powerkey: --model auto: the first 1[01][0-9][0-9] frames fill what it keeps \(64 MiB\): the model is chosen from them, the rest decoded as it comes$" "$tmp/err" &&
  grep -q "^powerkey: summary: 1300 frames: 1300 decoded" "$tmp/err" || fail "--model auto past its memory: status $rc, $(head -c 400 "$tmp/err")"

# check --json: a file name with control characters is JSON-escaped, every line valid JSON; the
# text escapes it as every message does.
odd="$tmp/a$(printf '\033')]0;x$(printf '\a').log"
cp "$logs/check-problems.log" "$odd"
"$pk" check --model pk1000 --json "$odd" "$logs/check-problems.log" > "$tmp/out" 2> /dev/null
[ -s "$tmp/out" ] && "$py" -c 'import json, sys
for line in open(sys.argv[1], encoding="ascii"): json.loads(line)' "$tmp/out" ||
  fail "check --json with an odd file name: not JSON lines: $(head -c 300 "$tmp/out")"
grep -qF '"file":"'"$tmp"'/a\u001B]0;x\u0007.log"' "$tmp/out" || fail "check --json file name: $(head -1 "$tmp/out")"
"$pk" check --model pk1000 "$odd" "$logs/check-problems.log" > "$tmp/out" 2> "$tmp/err"
LC_ALL=C grep -q $'\x1b' "$tmp/out" "$tmp/err" && fail "check: the file name's escape reached the terminal"
grep -qF 'a\x1B]0;x\x07.log:' "$tmp/out" || fail "check: file name not escaped: $(head -1 "$tmp/out")"
rm -f "$odd"

# An empty option value is a usage error, never the default (--node '' was taken as 15h).
for args in "decode --node" "decode --model" "simulate --model pk1000 --until" "check --model pk1000 --sdo-timeout" "convert --to"; do
  "$pk" $args '' < /dev/null > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 2 ] && [ "$(cat "$tmp/err")" = "powerkey: ${args##* }: an empty value (give one, or leave the option out for its default) (powerkey help shows the usage)" ] ||
    fail "$args '': status $rc, $(cat "$tmp/err")"
  # --opt= : CLI11 says the value is missing.
  "$pk" $args= < /dev/null > /dev/null 2>&1; rc=$?
  [ $rc -eq 2 ] || fail "$args=: status $rc"
done

# encode names the field that failed, and only it, with the range that applies.
encode_error "powerkey: encode: led_on: red: '99' is outside 1..32" led-on red=99 green=1
encode_error "powerkey: encode: sdo_write: period_ms: '65536' is more than a pk1000 takes (0..65535)" sdo-write object=heartbeat_time period_ms=65536
encode_error "powerkey: encode: nmt_message: command: '3' is not what a pk1000 takes (start, stop, pre_operational, reset_node, reset_communication, legacy_stop)" nmt command=3

# simulate: the keypad's clock is 32-bit milliseconds; a time past it is refused, never wrapped,
# and the loop to its last millisecond ends.
timeout 60 "$pk" simulate --model pk1000 --until 4294967.295 < /dev/null > "$tmp/out" 2> "$tmp/err"; rc=$?
[ $rc -eq 0 ] && [ "$(cat "$tmp/out")" = "(0.000000) can0 715#00" ] || fail "simulate --until 4294967.295: status $rc, $(head -3 "$tmp/out" "$tmp/err")"
for opt in "--until 4294967.296" "--press 4294967.296:1" "--release 5000000:1"; do
  "$pk" simulate --model pk1000 $opt < /dev/null > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 2 ] && grep -qF "s is past the keypad's clock (0..4294967.295 s, 32-bit milliseconds)" "$tmp/err" ||
    fail "simulate $opt: status $rc, $(cat "$tmp/err")"
done
for opt in "--until 1e30" "--until inf" "--until -1" "--press 1e3:1"; do
  "$pk" simulate --model pk1000 $opt < /dev/null > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 2 ] && grep -qF "expected" "$tmp/err" || fail "simulate $opt: status $rc, $(cat "$tmp/err")"
done
# A log whose last time is 4294967.295 s after its first (the loop never ended), and a frame one
# millisecond later: refused, and the simulation ends before it.
printf '%s\n' '(1.000000) can0 000#0115' '(4294968.295) can0 000#0115' '(4294968.296) can0 000#8115' > "$tmp/late.log"
timeout 60 "$pk" simulate --model pk1000 --press 4294967.000:1 "$tmp/late.log" > "$tmp/out" 2> "$tmp/err"; rc=$?
[ $rc -eq 1 ] && grep -qxF "powerkey: $tmp/late.log:3: this frame comes 4294967.296 s after the first, past the keypad's clock (0..4294967.295 s, 32-bit milliseconds): the simulation ends before it" "$tmp/err" ||
  fail "simulate past the clock: status $rc, $(cat "$tmp/err")"
tail -1 "$tmp/out" | grep -q "^(4294968\.000000) can0 195#01" || fail "simulate to the clock's end: $(tail -1 "$tmp/out")"

finish cli
