#!/usr/bin/env bash
# The powerkey tool on J1939 frames (registered by tools/powerkey/CMakeLists.txt):
#   test_tool_j1939.sh POWERKEY_BINARY SOURCE_DIR [SAMPLE_LOGS_BINARY]
# The J1939 sample logs (a session of each model with a complete J1939 manual, a log crossing the
# switch both ways) decode without an error and come back byte for byte through
# `decode --json | encode --json`; frames to other PGNs are not keypad frames; --address narrows
# to one keypad; encode, list, --show and --model auto know the J1939 messages.
set -uo pipefail
. "$(dirname "$0")/tool_support.sh"

# The sample logs: current, every frame decoded, the round trip exact.
for name in j1939-pkp1600si j1939-pkp2600si switch-pkp2600si; do
  check_sample_log $name ${name#*-}
  grep -q " decoded, 0 of other nodes or no keypad, 0 refused$" "$tmp/err" ||
    fail "$name: summary: $(cat "$tmp/err")"
done

# The lines of a J1939 frame: the kind, the identifier's fields, the fields with CANopen's names.
echo '18EFFF21#041B01030121FFFF' | "$pk" decode --model pkp1600si > "$tmp/out" 2>/dev/null
grep -q "J1939 key contact  priority: 6  destination: FFh  source: 21h  key: 3  pressed: yes  identifier: 21h" "$tmp/out" ||
  fail "key contact text: $(cat "$tmp/out")"
echo '18EFFF21#041BF9030800FF21' | "$pk" decode --model pkp1600si --json > "$tmp/out" 2>/dev/null
grep -q '"kind":"j1939_heartbeat","fields":{"priority":6,"destination":255,"source":33,"counter":3,"keys":\[4\],"identifier":33}' "$tmp/out" ||
  fail "heartbeat JSON: $(cat "$tmp/out")"

# The switch, both ways: the session says so on the two frames that cross it.
"$pk" decode --model pkp2600si "$logs/switch-pkp2600si.log" > "$tmp/out" 2>/dev/null
grep -q "615#2BFF200101000000 .*\[protocol now j1939\]" "$tmp/out" || fail "switch to J1939: $(cat "$tmp/out")"
grep -q "18EF0200#041B8000FFFFFFFF .*\[protocol now canopen\]" "$tmp/out" || fail "switch back: $(cat "$tmp/out")"
# Its address change: 70h moves the keypad to 02h (the session follows it; JSON new_address), and
# from then on the keypad is at 02h only: 21h's frames are another keypad's, as under --address.
grep -q "18EF2100#041B700201FFFFFF .*set_source_address  address: 02h  identifier: 01h  \[J1939 address now 02h\]$" "$tmp/out" ||
  fail "address change: $(cat "$tmp/out")"
[ "$(grep -c "J1939 address now" "$tmp/out")" -eq 1 ] || fail "one address change: $(cat "$tmp/out")"
"$pk" decode --model pkp2600si --json "$logs/switch-pkp2600si.log" 2>/dev/null |
  grep '"new_address"' > "$tmp/out"
[ "$(wc -l < "$tmp/out")" -eq 1 ] && grep -q '"data":"041B700201FFFFFF".*"new_address":2[,}]' "$tmp/out" ||
  fail "address change in JSON: $(cat "$tmp/out")"
printf '%s\n' '18EF2100#041B700201FFFFFF' '18EFFF21#041B01030121FFFF' '18EFFF02#041B01030101FFFF' \
  '18EF2100#041B0101010100FF' > "$tmp/moved.log"
for narrow in "" "--address 21h"; do
  "$pk" decode --model pkp2600si $narrow "$tmp/moved.log" > "$tmp/out" 2> "$tmp/err"
  [ "$(grep -c "another keypad's frame (keypad is 02h)" "$tmp/out")" -eq 2 ] &&
    grep -q "18EFFF02#041B01030101FFFF .*key: 3  pressed: yes  identifier: 01h" "$tmp/out" ||
    fail "after the move ($narrow): $(cat "$tmp/out")"
done

# check on J1939 logs: the sample sessions pass; checked as a model without their frames, most
# are refused (wrong_model); --address narrows as in decode. (The J1939 faults are in
# examples/logs/faults/, tests/test_tool_check_faults.py.)
for name in j1939-pkp1600si j1939-pkp2600si switch-pkp2600si; do
  "$pk" check --model ${name#*-} "$logs/$name.log" > "$tmp/out" 2>&1 ||
    fail "check $name: status $? $(cat "$tmp/out")"
  [ -s "$tmp/out" ] && fail "check $name: $(cat "$tmp/out")"
done
"$pk" check --model pkp2400si "$logs/j1939-pkp2600si.log" > "$tmp/out" 2>&1 &&
  fail "check j1939-pkp2600si.log as pkp2400si: status 0"
grep -q "^[0-9]*: wrong_model: [0-9]* of [0-9]* keypad frames refused as pkp2400si frames" "$tmp/out" ||
  fail "check as pkp2400si: $(cat "$tmp/out")"
grep -q "^[0-9]*: refused_frame: frame 18A72100h of 8 bytes refused (undocumented)" "$tmp/out" ||
  fail "check as pkp2400si, the multiple-LED command: $(cat "$tmp/out")"
# Narrowed to 22h, commands to 21h go to an address no keypad holds: no keypad spoke from there.
printf '%s\n' '18EFFF22#041B01030122FFFF' '18EF2200#041B0101010100FF' '18EF2100#041B0101010100FF' \
  > "$tmp/narrow.log"
"$pk" check --model pkp2600si --address 22h "$tmp/narrow.log" > "$tmp/out" 2>&1
[ "$(cat "$tmp/out")" = "3: j1939_no_keypad: J1939 frame 18EF2100h to address 21h, which no keypad holds (the keypad is at 22h): nobody acts on it" ] ||
  fail "check --address 22h: $(cat "$tmp/out")"
"$pk" check --model pkp2600si "$tmp/narrow.log" > "$tmp/out" 2>&1 || fail "check without --address: $(cat "$tmp/out")"

# Another PGN is not a keypad frame, counted with the other nodes' frames; a keypad frame the
# model refuses is an error.
printf '%s\n' '18FEF100#FFFFFFFFFFFFFFFF' '18EFFF21#041B01030121FFFF' '18A72100#1101FFFFFFFFFFFF' \
  > "$tmp/mixed.log"
"$pk" decode --model pkp2400si "$tmp/mixed.log" > "$tmp/out" 2> "$tmp/err"
grep -q "18FEF100#FFFFFFFFFFFFFFFF .*j1939  not a keypad frame (PGN FEF1h)" "$tmp/out" ||
  fail "other PGN: $(cat "$tmp/out")"
grep -q "18A72100#1101FFFFFFFFFFFF .*error: undocumented" "$tmp/out" ||
  fail "multiple LEDs on a PKP-2400-SI (no source): $(cat "$tmp/out")"
grep -q "summary: 3 frames: 1 decoded, 1 of other nodes or no keypad, 1 refused (undocumented 1)" "$tmp/err" ||
  fail "mixed summary: $(cat "$tmp/err")"

# --address narrows to one keypad: keypad 22h's frames are another keypad's, commands to 21h too.
printf '%s\n' '18EFFF21#041B01030121FFFF' '18EFFF22#041B01030122FFFF' '18EF2100#041B021FFFFFFFFF' \
  > "$tmp/two.log"
"$pk" decode --model pkp1600si --address 22h "$tmp/two.log" > "$tmp/out" 2> "$tmp/err"
[ "$(grep -c "another keypad's frame (keypad is 22h)" "$tmp/out")" -eq 2 ] ||
  fail "--address 22h: $(cat "$tmp/out")"
grep -q "18EFFF22#041B01030122FFFF .*key: 3  pressed: yes  identifier: 22h" "$tmp/out" ||
  fail "--address 22h, its own frame: $(cat "$tmp/out")"
"$pk" decode --model pkp1600si "$tmp/two.log" 2> "$tmp/err" | grep -c "J1939" | grep -qx 3 ||
  fail "without --address every keypad decodes"
# A log of another keypad address gets the hint --node gets: most frames are of the keypad at 21h
# (its own frames from it, commands to it), none of 30h; a log mostly of 30h's gets none.
"$pk" decode --model pkp2600si --address 30h "$logs/j1939-pkp2600si.log" > /dev/null 2> "$tmp/err"
tail -1 "$tmp/err" | grep -qx "powerkey: hint: most J1939 frames are of the keypad at 21h, not of keypad 30h: try --address 21h" ||
  fail "--address 30h on 21h's log, the hint: $(cat "$tmp/err")"
"$pk" decode --model pkp1600si --address 22h "$tmp/two.log" > /dev/null 2> "$tmp/err"
grep -q "hint" "$tmp/err" && fail "--address 22h, a third of the frames its own: no hint: $(cat "$tmp/err")"
# 70h's range: 00h is the controllers', FEh the null address; a usage error in every subcommand.
for bad in 00h FEh 0x100 x; do
  "$pk" decode --address "$bad" "$tmp/two.log" > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 2 ] && grep -q "^powerkey: --address: expected a keypad's J1939 address 01h..FDh (70h's range" "$tmp/err" ||
    fail "--address $bad: status $rc $(cat "$tmp/err")"
done

# encode: a J1939 message by its kind and fields; an addressed key contact state reads as an LED
# command unless narrowed to the keypad that sends it.
"$pk" encode --model pkp1600si j1939_set_led key=2 colour=red mode=on > "$tmp/out" ||
  fail "encode j1939_set_led: status $?"
grep -qx '18EF2100#041B0102010100FF' "$tmp/out" || fail "encode j1939_set_led: $(cat "$tmp/out")"
"$pk" encode --model pkp1600si j1939_command command=set_led_brightness level=1Fh > "$tmp/out" ||
  fail "encode 02h: status $?"
grep -qx '18EF2100#041B021FFFFFFFFF' "$tmp/out" || fail "encode 02h: $(cat "$tmp/out")"
# (identifier 01h: bytes 4..6 00 01 FF are also LED 2 off, state 01h; docs/j1939.md)
"$pk" encode --model pkp1600si j1939_key_contact key=2 pressed=no identifier=1 destination=00h \
  > /dev/null 2> "$tmp/err" && fail "an addressed key contact state that reads as an LED command was encoded"
# ... and the error says what to do, not that the destination must be FFh.
grep -qx "powerkey: encode: j1939_key_contact: addressed to 00h with identifier 01h, its bytes read as an LED command too: give --address 21h (the keypad's address) to encode it" "$tmp/err" ||
  fail "the ambiguous key contact state's error: $(cat "$tmp/err")"
"$pk" encode --model pkp1600si --address 21h j1939_key_contact key=2 pressed=no identifier=1 \
  destination=00h > "$tmp/out" || fail "narrowed key contact: status $?"
grep -qx '18EF0021#041B01020001FFFF' "$tmp/out" || fail "narrowed key contact: $(cat "$tmp/out")"
# encode --address A: a J1939 message is of the keypad at A unless a field says otherwise (its
# source when the keypad sends it, its destination when it is sent it); a field that names another
# keypad is refused, and the field to blame is named.
"$pk" encode --model pkp2600si --address 22h j1939_set_led key=3 colour=red mode=on > "$tmp/out" ||
  fail "set_led under --address 22h: status $?"
[ "$(cat "$tmp/out")" = "18EF2200#041B0103010100FF" ] || fail "set_led under --address 22h: $(cat "$tmp/out")"
"$pk" encode --model pkp2600si --address 30h j1939_key_contact key=2 pressed=1 > "$tmp/out" ||
  fail "key contact under --address 30h: status $?"
[ "$(cat "$tmp/out")" = "18EFFF30#041B01020121FFFF" ] || fail "key contact under --address 30h: $(cat "$tmp/out")"
"$pk" encode --model pkp2600si --address 22h j1939_set_led key=3 colour=red mode=on destination=21h 2> "$tmp/err"
grep -qx "powerkey: encode: j1939_set_led: destination: '21h' is less than a pkp2600si takes (22h..22h)" "$tmp/err" ||
  fail "refusal under --address: $(cat "$tmp/err")"
# list and export dbc show the keypad at --address.
"$pk" list --model pkp2600si --address 30h > "$tmp/out"
grep -q "^j1939_key_contact priority=6 destination=FFh source=30h " "$tmp/out" &&
  grep -q "^j1939_set_led priority=6 destination=30h source=00h " "$tmp/out" ||
  fail "list --address 30h: $(grep j1939_ "$tmp/out" | head -3)"
"$pk" export dbc --model pkp2600si --address 30h > "$tmp/out"
# 18EF3000h and 18EFFF30h with the extended flag (bit 31) of a DBC identifier
grep -q "^BO_ $((0x98EF3000)) j1939_to_keypad: 8 controller" "$tmp/out" &&
  grep -q "^BO_ $((0x98EFFF30)) j1939_from_keypad: 8 keypad" "$tmp/out" ||
  fail "export dbc --address 30h: $(grep '^BO_ .*j1939' "$tmp/out")"

# list: the J1939 messages a model has (the multiple-LED command only where a manual gives it).
"$pk" list --model pkp1600si > "$tmp/out"
for k in j1939_key_contact j1939_heartbeat j1939_set_led j1939_multiple_leds j1939_command j1939_address_claimed; do
  grep -q "^$k " "$tmp/out" || fail "list pkp1600si: no $k"
done
"$pk" list --model pkp2400si | grep -q "^j1939_multiple_leds " && fail "list pkp2400si: multiple LEDs"

# --show: key contact states press and release one key, the heartbeat sets them all, an LED command
# colours one LED.
printf '%s\n' '18EFFF21#041B01020121FFFF' '18EFFF21#041B01030121FFFF' '18EFFF21#041B01020021FFFF' \
  '18EF2100#041B0105070200FF' > "$tmp/show.log"
"$pk" decode --model pkp1600si --show "$tmp/show.log" > "$tmp/out" 2>/dev/null || fail "--show exit status"
grep -qF '[ 1 .][ 2*.][ 3 .]' "$tmp/out" || fail "--show: key 2 down: $(cat "$tmp/out")"
grep -qF '[ 1 .][ 2 .][ 3*.]' "$tmp/out" || fail "--show: key 3 still down after key 2's release: $(cat "$tmp/out")"
grep -qF '[ 5 w]' "$tmp/out" || fail "--show: LED 5 blinking white: $(cat "$tmp/out")"
# Amber and yellow-green show as Y (docs/cli.md); the multiple-LED frames draw no picture.
printf '%s\n' '18EF2100#041B0101080100FF' '18EF2100#041B0102090100FF' '18A72100#222222FFFFFFFFFF' > "$tmp/show.log"
"$pk" decode --model pkp1600si --show "$tmp/show.log" > "$tmp/out" 2>/dev/null || fail "--show exit status"
grep -qF '[ 1 Y][ 2 Y][ 3 .]' "$tmp/out" && [ "$(grep -c '^    \[' "$tmp/out")" -eq 2 ] ||
  fail "--show: amber, yellow-green, multiple LEDs: $(cat "$tmp/out")"

# --model auto: the models with the multiple-LED command and 6 keys or more read the PKP-1600-SI
# session; the narrowest is taken.
"$pk" decode --model auto "$logs/j1939-pkp1600si.log" > /dev/null 2> "$tmp/err"
head -1 "$tmp/err" | grep -q "^powerkey: --model auto: pkp1600si: " ||
  fail "--model auto on j1939-pkp1600si.log: $(head -1 "$tmp/err")"
"$pk" decode --model auto "$logs/j1939-pkp2600si.log" > /dev/null 2> "$tmp/err"
head -1 "$tmp/err" | grep -q "^powerkey: --model auto: pkp2600si: " ||
  fail "--model auto on j1939-pkp2600si.log: $(head -1 "$tmp/err")"

# The tutorial's J1939 section (docs/tutorial.md, section 4): every `$ powerkey` command of its
# console blocks runs from the repository's root, and the lines it shows come out in that order
# ("..." stands for lines left out; no line shown and none left out: no output).
python3 - "$src/docs/tutorial.md" > "$tmp/tutorial" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
section = text[text.index("## 4. A J1939 log"):]
for block in re.findall(r"```console\n(.*?)```", section, re.S):
    for line in block.splitlines():
        print(("C " + line[2:]) if line.startswith("$ ") else ("O " + line))
PY
[ "$(grep -c '^C powerkey ' "$tmp/tutorial")" -ge 6 ] || fail "tutorial: its commands: $(cat "$tmp/tutorial")"
run_shown() {  # $1: the command, $2: the file of the lines shown
  local got="$tmp/tutorial.got" want="$2" elided=0
  (cd "$src" && eval "\"$pk\"${1#powerkey}") > "$got" 2>&1
  grep -qx '\.\.\.' "$want" && elided=1
  if [ $elided -eq 0 ]; then
    diff "$want" "$got" > /dev/null || fail "tutorial: $1: $(diff "$want" "$got" | head -5)"
  else
    awk 'NR == FNR { if ($0 != "...") want[++n] = $0; next } k < n && $0 == want[k + 1] { ++k }
         END { exit k == n ? 0 : 1 }' "$want" "$got" || fail "tutorial: $1: lines shown missing"
  fi
}
cmd=""
: > "$tmp/shown"
while IFS= read -r l; do
  case $l in
    "C "*) [ -n "$cmd" ] && run_shown "$cmd" "$tmp/shown"; cmd=${l#C }; : > "$tmp/shown" ;;
    "O "*) printf '%s\n' "${l#O }" >> "$tmp/shown" ;;
  esac
done < "$tmp/tutorial"
[ -n "$cmd" ] && run_shown "$cmd" "$tmp/shown"

finish
