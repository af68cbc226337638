#!/usr/bin/env bash
# Live use (registered by tools/powerkey/CMakeLists.txt as cli_live): frames that arrive on a pipe
# seconds apart are each written as soon as they are decoded, in text, JSON and --show, not when
# the input ends.  test_tool_live.sh POWERKEY_BINARY
set -uo pipefail
. "$(dirname "$0")/tool_support.sh"

# Writes two frames 3 s apart into `powerkey decode ARGS`; stamps each output line with the
# milliseconds since the start.
stamped() {
  local start
  start=$(date +%s%3N)
  { echo '(1700000000.000000) can0 195#0100000010'; sleep 3; echo '(1700000003.000000) can0 195#0200000010'; } |
    "$pk" decode --model pkp2400 "$@" 2> /dev/null |
    while IFS= read -r line; do echo "$(( $(date +%s%3N) - start )) $line"; done
}
for mode in text --json --show; do
  args=()
  [ "$mode" = text ] || args=("$mode")
  stamped "${args[@]}" > "$tmp/out"
  first=$(head -1 "$tmp/out" | cut -d' ' -f1)
  last=$(tail -1 "$tmp/out" | cut -d' ' -f1)
  grep -q "0100000010" <(head -1 "$tmp/out") || fail "$mode: first line: $(head -1 "$tmp/out")"
  grep -q "0200000010\|\[ 2\*" <(tail -2 "$tmp/out") || fail "$mode: last lines: $(tail -2 "$tmp/out")"
  # The first frame's line came before the second frame was sent (3 s), the last after it.
  [ "$first" -lt 2500 ] || fail "$mode: the first line came after ${first} ms, not before the second frame"
  [ "$last" -ge 2900 ] || fail "$mode: the last line came after ${last} ms"
done
finish live
