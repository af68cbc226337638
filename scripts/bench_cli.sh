#!/usr/bin/env bash
# Times the powerkey tool on a log of one million frames (docs/performance.md, "The powerkey
# tool"): the sample logs' frames repeated, as candump -l lines. Prints seconds for
#   read       reading and parsing the lines only (decode --parse-only)
#   decode     reading, parsing, decoding and following the session, no output (decode --quiet)
#   text       the whole decode, text output to /dev/null
#   json       the whole decode --json, output to /dev/null
#   nlohmann   decode --json with nlohmann::json writing each line (--nlohmann-writer)
#   roundtrip  decode --json | encode --json
#   tshark     when tshark is installed: the same frames as a SocketCAN pcap, decoded by
#              Wireshark's CANopen dissector, fields only; then the ratios tshark / powerkey
# Times are CPU seconds (user + system), the best of RUNS=3 runs.
# Usage: bash scripts/bench_cli.sh [BUILD_DIR] [FRAMES]; builds the tool in Release if needed
# (JOBS=1 by default: the build machine is shared).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/bench-cli}
frames=${2:-1000000}
if [ ! -x "$build/tools/powerkey/powerkey" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DPOWERKEY_BUILD_TESTS=OFF >/dev/null
  cmake --build "$build" -j "${JOBS:-1}" --target powerkey_tool >/dev/null
fi
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
  if [ ! -s "$pcap" ] || [ "$pcap" -ot "$log" ]; then
    # LINKTYPE_CAN_SOCKETCAN (227): per packet a 16-byte struct can_frame, id big-endian with
    # the extended-frame flag in bit 31.
    python3 - "$log" "$pcap" <<'EOF'
import struct, sys
out = open(sys.argv[2], 'wb')
out.write(struct.pack('<IHHiIII', 0xa1b2c3d4, 2, 4, 0, 0, 65535, 227))
for line in open(sys.argv[1]):
    t, _, frame = line.split()
    seconds = float(t.strip('()'))
    ident, data = frame.split('#')
    can_id = int(ident, 16) | (0x80000000 if len(ident) == 8 else 0)
    payload = bytes.fromhex(data)
    packet = struct.pack('>IBBBB', can_id, len(payload), 0, 0, 0) + payload.ljust(8, b'\0')
    out.write(struct.pack('<IIII', int(seconds), round((seconds % 1) * 1e6), 16, 16) + packet)
EOF
  fi
  tshark_s=$(seconds tshark -r "$pcap" -d can.subdissector,canopen -T fields -e frame.number \
    -e can.id -e canopen.function_code -e canopen.node_id -e canopen.nmt_ctrl.cd \
    -e canopen.sdo.main_idx -e canopen.sdo.sub_idx -e canopen.pdo.data.bytes)
  echo "tshark:    $tshark_s s  (tshark $(tshark --version 2>/dev/null | head -1 | awk '{ print $3 }'), CANopen dissector, -T fields)"
  awk -v t="$tshark_s" -v x="$text" -v j="$json" \
    'BEGIN { printf "tshark / text: %.1fx   tshark / json: %.1fx\n", t / x, t / j }'
else
  echo "tshark:    not installed (apt-get install tshark for the comparison)"
fi
