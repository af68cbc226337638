#!/usr/bin/env bash
# Every log form reads like its candump equivalent, in every subcommand (registered by
# tools/powerkey/CMakeLists.txt as cli_log_formats):
#   test_tool_log_formats.sh POWERKEY_BINARY SOURCE_DIR
# The files are written at test time by the real writers: Debian's python3-can (ASC, BLF, TRC 1.0
# and 2.1, CSV, candump log; /usr/bin/python3, not a python on PATH that may lack the package)
# and can-utils' log2asc/asc2log. The frames are every frame of the sample logs, plus a remote, a
# CAN FD and an error frame that each file must name once, not decode. Hand-made samples cover
# the forms no installed program writes: candump's screen output with -x and -a, cansend's dotted
# form, TRC 1.1 and a UTF-8 byte-order mark.
set -uo pipefail
. "$(dirname "$0")/tool_support.sh"
py=/usr/bin/python3

# id, data and kind of every decoded frame: what must agree between two forms of one log.
kind_of_line='s/.*"id":"([0-9A-F]*)","ext":(true|false),"data":"([0-9A-F]*)".*"kind":"([a-z0-9_]*)".*/\1#\3 \4/; s/.*"id":"([0-9A-F]*)","ext":(true|false),"data":"([0-9A-F]*)".*"error":"([a-z_]*)".*/\1#\3 error:\4/'
kinds() { "$pk" decode --json --model "$2" "$1" 2> /dev/null | sed -E "$kind_of_line"; }

# The reference: the frames of every sample log, as candump -l lines, one log per model.
for m in pk1000 pkp2200 pkp2400 pkp2600; do
  grep -v '^#' "$src/examples/logs/$m.log" > "$tmp/$m.ref.log"
  kinds "$tmp/$m.ref.log" $m > "$tmp/$m.want"
  [ "$(wc -l < "$tmp/$m.want")" -gt 50 ] || fail "$m: reference decode too short"
done
# Two controller sessions of a PK1000, for check and simulate: one with a planted problem of
# each kind, and the controller's side of a session.
grep -v '^#' "$src/examples/logs/check-problems.log" > "$tmp/problems.ref.log"
grep -v '^#' "$src/examples/logs/session-pk1000.log" > "$tmp/session.ref.log"
model_of() { case $1 in problems | session) echo pk1000 ;; *) echo "$1" ;; esac; }

# What each subcommand makes of a log, in a form that does not depend on the form of the log:
# line numbers and the time origin differ between forms, the frames, kinds and problems do not.
#   decode    id#data and kind (or error) of every frame, and the exit status
#   check     the kind of every problem found, and the exit status
#   simulate  the keypad's frames with their time from its boot-up in ms, and the exit status
#   convert   the data frames of the candump log it writes, and the exit status
# Each file a real writer made must give the same verdict as its candump reference.
verdict() {
  local sub=$1 file=$2 model=$3
  case $sub in
    decode) "$pk" decode --json --model "$model" "$file" 2> /dev/null | sed -E "$kind_of_line" ;;
    check) "$pk" check --model "$model" "$file" 2> /dev/null | sed -E 's/^[0-9]+: ([a-z_]+): .*/\1/' ;;
    simulate) "$pk" simulate --model "$model" "$file" 2> /dev/null |
      awk '{ t = substr($1, 2, length($1) - 2); if (NR == 1) t0 = t; printf "%d %s\n", (t - t0) * 1000 + 0.5, $3 }' ;;
    convert) "$pk" convert "$file" 2> /dev/null | awk '$3 !~ /#R|##/ { print $3 }' ;;
  esac
  echo "status ${PIPESTATUS[0]}"
}
subcommands="decode check simulate convert"
same_verdicts() {  # same_verdicts FILE REF WRITER
  local file=$1 ref=$2 writer=$3 model sub
  model=$(model_of "$ref")
  for sub in $subcommands; do
    [ -s "$tmp/$ref.$sub.want" ] || verdict $sub "$tmp/$ref.ref.log" "$model" > "$tmp/$ref.$sub.want"
    verdict $sub "$file" "$model" > "$tmp/got.$sub"
    diff "$tmp/$ref.$sub.want" "$tmp/got.$sub" > "$tmp/diff" ||
      fail "$sub on $(basename "$file") ($writer) differs from its candump form: $(head -4 "$tmp/diff" | paste -sd' ')"
  done
}

# --- python-can -------------------------------------------------------------------------------
if [ -x "$py" ] && "$py" -c 'import can' 2> /dev/null; then
  cat > "$tmp/write.py" <<'EOF'
# Writes the frames of a candump log with python-can's writers, plus one remote, one CAN FD and
# one error frame where the writer can express them.
import sys, can
src, out = sys.argv[1], sys.argv[2]
msgs = []
with can.CanutilsLogReader(src) as r:
    for m in r:
        msgs.append(m)
extra = [
    can.Message(timestamp=msgs[-1].timestamp + 0.1, arbitration_id=0x615, is_extended_id=False,
                is_remote_frame=True, dlc=8, channel=0),
    can.Message(timestamp=msgs[-1].timestamp + 0.2, arbitration_id=0x615, is_extended_id=False,
                is_fd=True, data=bytes(range(12)), channel=0),
    can.Message(timestamp=msgs[-1].timestamp + 0.3, arbitration_id=0x20, is_extended_id=False,
                is_error_frame=True, dlc=8, data=bytes(8), channel=0),
]
msgs = msgs[:10] + extra + msgs[10:]
kind = out.rsplit('.', 1)[1]
if kind == 'trc10':
    w = can.TRCWriter(out)
    from can.io.trc import TRCFileVersion
    w.file_version = TRCFileVersion.V1_0
elif kind == 'log':
    w = can.CanutilsLogWriter(out, channel='can0')
else:
    w = can.Logger(out)
for m in msgs:
    w.on_message_received(m)
w.stop()
EOF
  for m in problems session; do
    for ext in asc blf trc trc10 csv log; do
      f="$tmp/$m.$ext"
      "$py" "$tmp/write.py" "$tmp/$m.ref.log" "$f" 2> "$tmp/py.err" || { fail "python-can $ext: $(cat "$tmp/py.err")"; continue; }
      same_verdicts "$f" $m "python-can"
    done
  done
  for m in pk1000 pkp2200 pkp2400 pkp2600; do
    for ext in asc blf trc trc10 csv log; do
      f="$tmp/$m.$ext"
      "$py" "$tmp/write.py" "$tmp/$m.ref.log" "$f" 2> "$tmp/py.err" || { fail "python-can $ext: $(cat "$tmp/py.err")"; continue; }
      same_verdicts "$f" $m "python-can"
      kinds "$f" $m > "$tmp/got"
      diff "$tmp/$m.want" "$tmp/got" > "$tmp/diff" || fail "$m.$ext (python-can) decodes differently: $(head -5 "$tmp/diff")"
      "$pk" decode --model $m "$f" > /dev/null 2> "$tmp/err"; rc=$?
      [ $rc -eq 0 ] || fail "$m.$ext: exit status $rc: $(head -3 "$tmp/err")"
      # The remote, FD and error frames: named once each, where the format carries them.
      case $ext in
        asc|blf|csv|log) unit=line; [ $ext = blf ] && unit=object  # a BLF file counts objects
                         grep -q "1 remote frame not decoded (not supported by powerkey), the first at $unit" "$tmp/err" ||
                           fail "$m.$ext: remote frame not named: $(cat "$tmp/err")" ;;
      esac
      case $ext in
        asc|blf|csv|log) grep -q "1 CAN FD frame not decoded (not supported by powerkey)" "$tmp/err" ||
                           fail "$m.$ext: CAN FD frame not named: $(cat "$tmp/err")" ;;
      esac
      [ "$(grep -c "not decoded" "$tmp/err")" -le 3 ] || fail "$m.$ext: skipped frames named more than once each"
    done
  done
  # The summary counts what was skipped.
  "$pk" decode "$tmp/pk1000.blf" > /dev/null 2> "$tmp/err"
  tail -1 "$tmp/err" | grep -qx "powerkey: summary: $(wc -l < "$tmp/pk1000.ref.log") frames: .*; 1 remote frame skipped; 1 CAN FD frame skipped; 1 error frame skipped" ||
    fail "BLF summary: $(tail -1 "$tmp/err")"
  # Read as it comes: the BLF file through a pipe in small pieces decodes the same.
  "$py" -c 'import sys, time
d = open(sys.argv[1], "rb").read()
for i in range(0, len(d), 997):
    sys.stdout.buffer.write(d[i:i + 997]); sys.stdout.flush()' "$tmp/pk1000.blf" |
    "$pk" decode --json 2> /dev/null | sed -E 's/"time":"[^"]*",//' > "$tmp/piped"
  "$pk" decode --json "$tmp/pk1000.blf" 2> /dev/null | sed -E 's/"time":"[^"]*",//' | cmp -s - "$tmp/piped" ||
    fail "BLF through a pipe differs"
else
  echo "SKIP: python-can is not installed for /usr/bin/python3 (apt-get install python3-can)"
fi

# --- can-utils log2asc and asc2log ------------------------------------------------------------------
# (No error frame here: log2asc -f of can-utils 2020.11 writes one as a data frame of id 80h.)
if command -v log2asc > /dev/null && command -v asc2log > /dev/null; then
  for m in problems session; do
    log2asc -I "$tmp/$m.ref.log" -O "$tmp/$m.l2a.asc" can0 2> /dev/null || fail "log2asc failed"
    log2asc -f -I "$tmp/$m.ref.log" -O "$tmp/$m.l2af.asc" can0 2> /dev/null || fail "log2asc -f failed"
    asc2log -I "$tmp/$m.l2a.asc" -O "$tmp/$m.a2l.log" 2> /dev/null || fail "asc2log failed"
    same_verdicts "$tmp/$m.l2a.asc" $m log2asc
    same_verdicts "$tmp/$m.l2af.asc" $m "log2asc -f"
    same_verdicts "$tmp/$m.a2l.log" $m asc2log
  done
  for m in pk1000 pkp2400; do
    { cat "$tmp/$m.ref.log"; echo "(1700000009.000000) can0 615#R"; echo "(1700000009.100000) can0 615##1000102030405060708090A0B"; } > "$tmp/$m.extra.log"
    log2asc -I "$tmp/$m.extra.log" -O "$tmp/$m.l2a.asc" can0 2> /dev/null || fail "log2asc failed"
    log2asc -f -I "$tmp/$m.extra.log" -O "$tmp/$m.l2af.asc" can0 2> /dev/null || fail "log2asc -f failed"
    for f in "$tmp/$m.l2a.asc" "$tmp/$m.l2af.asc"; do
      kinds "$f" $m > "$tmp/got"
      diff "$tmp/$m.want" "$tmp/got" > "$tmp/diff" || fail "$f (log2asc) decodes differently: $(head -5 "$tmp/diff")"
      "$pk" decode --model $m "$f" > /dev/null 2> "$tmp/err"
      grep -q "1 remote frame not decoded" "$tmp/err" && grep -q "1 CAN FD frame not decoded" "$tmp/err" ||
        fail "$f: remote and FD frames not named: $(cat "$tmp/err")"
    done
    # asc2log writes candump lines with the direction at the end (R or T).
    asc2log -I "$tmp/$m.l2a.asc" -O "$tmp/$m.a2l.log" 2> /dev/null || fail "asc2log failed"
    grep -q '#[0-9A-F]* R$' "$tmp/$m.a2l.log" || fail "asc2log wrote no direction: $(head -1 "$tmp/$m.a2l.log")"
    kinds "$tmp/$m.a2l.log" $m > "$tmp/got"
    diff "$tmp/$m.want" "$tmp/got" > "$tmp/diff" || fail "$m (asc2log) decodes differently: $(head -5 "$tmp/diff")"
    for f in l2a.asc l2af.asc a2l.log; do same_verdicts "$tmp/$m.$f" $m "${f%.*}"; done
  done
else
  echo "SKIP: can-utils' log2asc/asc2log are not installed (apt-get install can-utils)"
fi

# The references say something: a problem of each kind, the keypad's answers, every frame.
if [ -s "$tmp/problems.check.want" ]; then
  [ "$(grep -vc '^status' "$tmp/problems.check.want")" -eq 9 ] && grep -qx 'status 1' "$tmp/problems.check.want" ||
    fail "check on the problems log: $(paste -sd' ' "$tmp/problems.check.want")"
  [ "$(grep -vc '^status' "$tmp/session.simulate.want")" -gt 10 ] || fail "simulate on the session: $(cat "$tmp/session.simulate.want")"
  [ "$(grep -vc '^status' "$tmp/pk1000.convert.want")" -eq "$(wc -l < "$tmp/pk1000.ref.log")" ] ||
    fail "convert of the PK1000 log: $(wc -l < "$tmp/pk1000.convert.want") lines"
else
  fail "no verdicts were compared"
fi

# --- the forms no installed program writes (as candump prints them, from its source) ------------
# candump -x, -a, -t together; cansend's dotted form; TRC 1.1; a byte-order mark; CRLF.
printf '%s\n' '(1700000000.000000)  can0  RX - -  000   [2]  01 15' \
  '(1700000000.100000)  can0  TX - -  195   [5]  09 00 00 00 12                 '"'"'.....'"'" \
  '  can0  615   [8]  remote request' \
  '  can0  18EF2100   [8]  04 1B 80 00 FF FF FF FF   '"'"'........'"'" > "$tmp/screen.log"
printf '%s\n' '000#01.15' '195#09.00.00.00.12' '18EF2100#04.1B.80.00.FF.FF.FF.FF' > "$tmp/dotted.log"
printf '%s\n' '(1700000000.000000) can0 000#0115' '(1700000000.100000) can0 195#0900000012' \
  '(1700000000.200000) can0 18EF2100#041B8000FFFFFFFF' > "$tmp/plain.log"
printf '%s\r\n' ';$FILEVERSION=1.1' ';$STARTTIME=45000.0' ';   Message Number' ';   |         Time Offset (ms)' \
  '     1)         0.0  Rx         0000  2  01 15 ' '     2)       100.0  Tx         0195  5  09 00 00 00 12 ' \
  '     3)       150.0  Rx         0615  8  RTR ' '     4)       200.0  Rx     18EF2100  8  04 1B 80 00 FF FF FF FF ' > "$tmp/v11.trc"
{ printf '\xef\xbb\xbf'; cat "$tmp/plain.log"; } > "$tmp/bom.log"
kinds "$tmp/plain.log" pk1000 > "$tmp/want3"
[ "$(wc -l < "$tmp/want3")" -eq 3 ] || fail "plain reference"
for f in screen dotted v11.trc bom; do
  file=$tmp/$f; [ -e "$file" ] || file=$tmp/$f.log
  kinds "$file" pk1000 > "$tmp/got"
  diff "$tmp/want3" "$tmp/got" > "$tmp/diff" || fail "$f decodes differently: $(cat "$tmp/diff")"
done
"$pk" decode "$tmp/screen.log" > /dev/null 2> "$tmp/err"
[ "$(head -1 "$tmp/err")" = "powerkey: $tmp/screen.log: 1 remote frame not decoded (not supported by powerkey), the first at line 3" ] ||
  fail "screen form remote frame: $(cat "$tmp/err")"
"$pk" decode "$tmp/v11.trc" > /dev/null 2> "$tmp/err"
[ "$(head -1 "$tmp/err")" = "powerkey: $tmp/v11.trc: 1 remote frame not decoded (not supported by powerkey), the first at line 7" ] ||
  fail "TRC 1.1 remote frame: $(cat "$tmp/err")"
# Many remote frames: one line, not one per frame.
for i in $(seq 1 500); do echo "615#R"; done > "$tmp/remote.log"
"$pk" decode "$tmp/remote.log" > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 0 ] || fail "remote frames: exit status $rc"
cat > "$tmp/want" <<EOF
powerkey: $tmp/remote.log: 500 remote frames not decoded (not supported by powerkey), the first at line 1
powerkey: summary: 0 frames: 0 decoded, 0 of other nodes or no keypad, 0 refused; 500 remote frames skipped
EOF
diff "$tmp/want" "$tmp/err" > /dev/null || fail "500 remote frames: $(cat "$tmp/err")"

# A damaged BLF file: one message, no crash.
if [ -s "$tmp/pk1000.blf" ]; then
  head -c 300 "$tmp/pk1000.blf" > "$tmp/cut.blf"
  "$pk" decode "$tmp/cut.blf" > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 1 ] && grep -q "cut.blf:.*(damaged file?)\|cut.blf:.*(truncated?)" "$tmp/err" || fail "truncated BLF: $rc $(cat "$tmp/err")"
fi

finish "log formats"
