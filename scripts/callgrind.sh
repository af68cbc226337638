#!/usr/bin/env bash
# Instructions per call of every benchmarked operation, counted by callgrind (exact and stable,
# unlike time on a shared machine). Prints a Markdown table: instructions per call, the same
# net of the floor (reading the frame plus the loop and the barriers of bench/ops.hpp), and the
# ratio to the floor.
# Usage: scripts/callgrind.sh [build-dir] [name-prefix]   (default build dir: build/bench)
#        ICOUNT=/path/to/powerkey_icount scripts/callgrind.sh   measures a driver built elsewhere
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/bench}
prefix=${2:-}
calls=${CALLS:-10000}
icount=${ICOUNT:-}
if [ -z "$icount" ]; then
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=${CXX:-g++} \
      -DPOWERKEY_BUILD_BENCH=ON -DPOWERKEY_BUILD_TESTS=OFF -DPOWERKEY_BUILD_EXAMPLES=OFF >/dev/null
  fi
  cmake --build "$build" -j 2 --target powerkey_icount >/dev/null
  icount=$build/bench/powerkey_icount
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
valgrind --tool=callgrind --collect-atstart=no --dump-instr=no --dump-line=no \
  --callgrind-out-file="$out/cg.%p" "$icount" "$calls" "$prefix" \
  >/dev/null 2>"$out/valgrind.log" || { cat "$out/valgrind.log" >&2; exit 1; }
"$icount" --list >"$out/list"
# Each dump names its operation in "desc: Trigger: Client Request: <name> calls=<n>" and holds
# the instruction total in its "summary:" (or "totals:") line.
for f in "$out"/cg.*; do
  awk '/^desc: Trigger: Client Request:/ { sub(/^desc: Trigger: Client Request: /, ""); name = $1; n = $2; sub(/calls=/, "", n) }
       /^(summary|totals):/ { ir = $2 }
       END { if (name != "") printf "%s\t%s\t%s\n", name, n, ir }' "$f"
done >"$out/counts"
awk -F'\t' -v list="$out/list" '
  BEGIN { while ((getline line < list) > 0) { split(line, a, "\t"); order[++k] = a[1]; unit[a[1]] = a[2] } }
  { per[$1] = $3 / $2 }
  END {
    floor = per["floor/read_frame"]
    printf "| operation | one call is | instructions/call | net of floor | x floor |\n"
    printf "|---|---|---:|---:|---:|\n"
    for (i = 1; i <= k; ++i) {
      o = order[i]; if (!(o in per)) continue
      printf "| %s | %s | %.1f | %.1f | %.1f |\n", o, unit[o], per[o], per[o] - floor, per[o] / floor
    }
  }' "$out/counts"
