#!/usr/bin/env bash
# Times the powerkey tool on a log of one million frames (docs/performance.md, "The powerkey
# tool"): the sample logs' frames repeated, as candump -l lines. Prints seconds for
#   read       reading and parsing the lines only (decode --parse-only)
#   decode     reading, parsing, decoding and following the session, no output (decode --quiet)
#   text       the whole decode, text output to /dev/null
#   json       the whole decode --json, output to /dev/null
#   nlohmann   decode --json with nlohmann::json writing each line (--nlohmann-writer)
#   roundtrip  decode --json | encode --json
#   tshark     when tshark is installed: the same frames as a SocketCAN pcap (powerkey convert),
#              decoded by Wireshark's CANopen dissector printing four fields (function code,
#              node id, SDO index and sub-index) and eight; then the ratios tshark / powerkey
# Times are CPU seconds (user + system), the best of RUNS=3 runs.
# Usage: bash scripts/bench_cli.sh [BUILD_DIR] [FRAMES]; builds the tool in Release (brings it up to date)
# (JOBS=1 by default: the build machine is shared).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/bench-cli}
frames=${2:-1000000}
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DPOWERKEY_BUILD_TESTS=OFF \
    -DPOWERKEY_BUILD_EXAMPLES=OFF -DPOWERKEY_BUILD_WIRESHARK=OFF -DPOWERKEY_BUILD_PYTHON=OFF >/dev/null
fi
cmake --build "$build" -j "${JOBS:-1}" --target powerkey_tool >/dev/null  # up to date with the sources
pk=$build/tools/powerkey/powerkey
log=$build/million.log
if [ ! -s "$log" ] || [ "$(wc -l < "$log")" -ne "$frames" ]; then
  grep -hv '^#' examples/logs/pk1000.log |
    awk -v n="$frames" '{ f[NR] = $3 } END { for (i = 0; i < n; i++) printf "(%d.%06d) can0 %s\n", 1700000000 + int(i / 100), (i % 100) * 10000, f[i % NR + 1] }' > "$log"
fi
# CPU seconds (user + system) of a command and its children: on the shared build machine the
# wall-clock time depends on what else runs, the CPU time much less. Best of RUNS runs (3).
seconds() {
  local best="" t
  for _ in $(seq "${RUNS:-3}"); do
    t=$( { TIMEFORMAT='%U %S'; time "$@" > /dev/null 2>&1; } 2>&1 | awk '{ printf "%.2f", $1 + $2 }')
    if [ -z "$best" ] || awk -v a="$t" -v b="$best" 'BEGIN { exit !(a < b) }'; then best=$t; fi
  done
  echo "$best"
}
echo "frames: $(wc -l < "$log") ($(du -h "$log" | cut -f1))"
echo "read:      $(seconds "$pk" decode --parse-only "$log") s"
echo "decode:    $(seconds "$pk" decode --quiet "$log") s"
text=$(seconds "$pk" decode "$log")
echo "text:      $text s"
json=$(seconds "$pk" decode --json "$log")
echo "json:      $json s"
echo "nlohmann:  $(seconds "$pk" decode --json --nlohmann-writer "$log") s"
echo "roundtrip: $(seconds bash -c "'$pk' decode --json '$log' | '$pk' encode --json") s"
if command -v tshark > /dev/null; then
  pcap=$build/million.pcap
  # The same frames as a SocketCAN pcap, written by the tool (powerkey convert).
  if [ ! -s "$pcap" ] || [ "$pcap" -ot "$log" ]; then
    "$pk" convert --to pcap -o "$pcap" "$log"
  fi
  # tshark with its CANopen dissector printing the four CANopen fields decode --json writes at
  # the top level of a frame (function code, node id, SDO index and sub-index), and the heavier
  # list (frame number, COB-ID, NMT command, PDO bytes too).
  four=$(seconds tshark -r "$pcap" -d can.subdissector,canopen -T fields -e canopen.function_code \
    -e canopen.node_id -e canopen.sdo.main_idx -e canopen.sdo.sub_idx)
  heavy=$(seconds tshark -r "$pcap" -d can.subdissector,canopen -T fields -e frame.number \
    -e can.id -e canopen.function_code -e canopen.node_id -e canopen.nmt_ctrl.cd \
    -e canopen.sdo.main_idx -e canopen.sdo.sub_idx -e canopen.pdo.data.bytes)
  echo "tshark:    $four s four fields, $heavy s eight fields  (tshark $(tshark --version 2>/dev/null | head -1 | awk '{ print $3 }'), CANopen dissector, -T fields)"
  awk -v t="$four" -v h="$heavy" -v x="$text" -v j="$json" \
    'BEGIN { printf "tshark / text: %.1fx (eight fields %.1fx)   tshark / json: %.1fx (eight fields %.1fx)\n", t / x, h / x, t / j, h / j }'
else
  echo "tshark:    not installed (apt-get install tshark for the comparison)"
fi
