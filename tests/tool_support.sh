# The setup the shell tests of the tool share, sourced after `set -uo pipefail`:
#   . "$(dirname "$0")/tool_support.sh"
# Arguments: POWERKEY_BINARY [SOURCE_DIR [SAMPLE_LOGS_BINARY]], as tools/powerkey/CMakeLists.txt
# passes them. Defines pk, src, gen, logs and tmp (removed at exit), and:
#   fail MESSAGE               FAIL: MESSAGE on stdout; the test's status becomes 1
#   frames_of LOG              the frames of a sample log, one per line
#   check_sample_log NAME M    examples/logs/NAME.log current, decoded by --model M without an
#                              error, one line per frame, and the same frames again through
#                              `decode --json | encode --json`, with and without id/data
#                              (decode's stderr is left in $tmp/err)
#   finish [WHAT]              "WHAT: all checks passed" when nothing failed; exits with the status
pk=$1
src=${2:-}
gen=${3:-}
logs=$src/examples/logs
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }
frames_of() { grep -v '^#' "$1" | awk 'NF { print $NF }'; }

check_sample_log() {
  local name=$1 m=$2 log=$logs/$1.log
  [ -s "$log" ] || { fail "$name: no sample log $log"; return; }
  # The committed log is what the generator writes from the manual rows.
  if [ -n "$gen" ]; then
    "$gen" "$name" > "$tmp/gen.log" && cmp -s "$tmp/gen.log" "$log" ||
      fail "$name: $log is stale; regenerate it with powerkey_sample_logs $name"
  fi
  "$pk" decode --model "$m" "$log" > "$tmp/text" 2> "$tmp/err" || fail "$name: decode exit status $?"
  grep -q "error:" "$tmp/text" && fail "$name: decode errors: $(grep -m3 'error:' "$tmp/text")"
  [ "$(wc -l < "$tmp/text")" -eq "$(frames_of "$log" | wc -l)" ] || fail "$name: not one line per frame"
  "$pk" decode --model "$m" --json "$log" > "$tmp/json" 2> /dev/null || fail "$name: decode --json exit status"
  grep -q '"error"' "$tmp/json" && fail "$name: JSON errors: $(grep -m3 '"error"' "$tmp/json")"
  # Every frame is rebuilt from its kind and fields, and checked against id/data.
  "$pk" encode --json < "$tmp/json" > "$tmp/frames" || fail "$name: encode --json exit status"
  frames_of "$log" | diff - "$tmp/frames" > /dev/null || fail "$name: round trip differs"
  # Without id/data (nothing to compare with or copy from) the frames come from the fields alone.
  sed -E 's/"id":"[0-9A-F]*","ext":(true|false),"data":"[0-9A-F]*",//' "$tmp/json" |
    "$pk" encode --json --model "$m" > "$tmp/frames2" || fail "$name: encode --json without id/data"
  frames_of "$log" | diff - "$tmp/frames2" > /dev/null || fail "$name: round trip from fields differs"
}

finish() {
  [ $failed -eq 0 ] && [ $# -gt 0 ] && echo "$1: all checks passed"
  exit $failed
}
