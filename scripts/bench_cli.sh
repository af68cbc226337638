#!/usr/bin/env bash
# Times the powerkey tool on a log of one million frames (docs/performance.md, "The powerkey
# tool"): the sample logs' frames repeated, as candump -l lines. Prints seconds for
#   read    reading and parsing the lines only (decode --parse-only)
#   decode  reading, parsing, decoding and following the session, no output (decode --quiet)
#   text    the whole decode, text output to /dev/null
#   json    the whole decode --json, output to /dev/null
#   roundtrip  decode --json | encode --json
# Usage: bash scripts/bench_cli.sh [BUILD_DIR] [FRAMES]; builds the tool in Release if needed.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/bench-cli}
frames=${2:-1000000}
if [ ! -x "$build/examples/powerkey" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DPOWERKEY_BUILD_TESTS=OFF >/dev/null
  cmake --build "$build" -j 2 --target powerkey_tool >/dev/null
fi
pk=$build/examples/powerkey
log=$build/million.log
if [ ! -s "$log" ] || [ "$(wc -l < "$log")" -ne "$frames" ]; then
  grep -hv '^#' examples/logs/pk1000.log |
    awk -v n="$frames" '{ f[NR] = $3 } END { for (i = 0; i < n; i++) printf "(%d.%06d) can0 %s\n", 1700000000 + int(i / 100), (i % 100) * 10000, f[i % NR + 1] }' > "$log"
fi
seconds() {
  local s e
  s=$(date +%s%N)
  "$@" > /dev/null 2>&1
  e=$(date +%s%N)
  awk -v ns=$((e - s)) 'BEGIN { printf "%.2f", ns / 1e9 }'
}
echo "frames: $(wc -l < "$log") ($(du -h "$log" | cut -f1))"
echo "read:      $(seconds "$pk" decode --parse-only "$log") s"
echo "decode:    $(seconds "$pk" decode --quiet "$log") s"
echo "text:      $(seconds "$pk" decode "$log") s"
echo "json:      $(seconds "$pk" decode --json "$log") s"
echo "roundtrip: $(seconds bash -c "'$pk' decode --json '$log' | '$pk' encode --json") s"
