#!/usr/bin/env bash
# Long fuzzing runs: builds every libFuzzer target (clang, ASan + UBSan) and fuzzes each in turn
# for SECONDS_PER_TARGET seconds (default 300), starting from the seed corpus, the regressions and
# what earlier runs found (kept in fuzz/corpus-run/<target>, ignored by git). Crash inputs land in
# $BUILD_DIR/artifacts/. Each target runs under its memory limit (fuzz/rss_limit_mb.txt, 2048 MB
# when not listed). Ends with a table of executions and peak memory per target; exits non-zero if
# any target failed.
#   scripts/fuzz.sh                      every target
#   scripts/fuzz.sh decode encode
#   SECONDS_PER_TARGET=3600 JOBS=2 scripts/fuzz.sh
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${SECONDS_PER_TARGET:-300}
build=${BUILD_DIR:-build/fuzz-clang}
jobs=${JOBS:-1}

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DPOWERKEY_SANITIZE=ON -DPOWERKEY_BUILD_FUZZ=ON -DPOWERKEY_FUZZ_LIBFUZZER=ON >/dev/null
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=($(sed -n '/^set(POWERKEY_FUZZ_TARGETS/,/)/p' fuzz/CMakeLists.txt |
    sed -e 's/set(POWERKEY_FUZZ_TARGETS//' -e 's/)//' | tr -s ' \n' ' '))
fi
cmake --build "$build" -j 2 --target powerkey_fuzz_seeds $(printf 'powerkey_fuzz_%s ' "${targets[@]}")
"$build/fuzz/powerkey_fuzz_seeds" "$build/fuzz/seeds"
mkdir -p "$build/artifacts"

summary="$build/fuzz-summary.txt"
printf '%-16s %12s %10s %8s %8s %s\n' target executions exec/s cov "peak MB" result | tee "$summary"
status=0
for t in "${targets[@]}"; do
  corpus=fuzz/corpus-run/$t
  mkdir -p "$corpus"
  inputs=()
  [ -d "$build/fuzz/seeds/$t" ] && inputs+=("$build/fuzz/seeds/$t")
  [ -d "fuzz/regressions/$t" ] && inputs+=("fuzz/regressions/$t")
  log="$build/fuzz-$t.log"
  result=ok
  parallel=()
  # With -jobs, libFuzzer writes each job's log to fuzz-<n>.log in the working directory.
  [ "$jobs" -gt 1 ] && parallel=(-jobs="$jobs" -workers="$jobs")
  rm -f fuzz-[0-9]*.log
  rss=$(awk -v t="$t" '$1 == t { print $2 }' fuzz/rss_limit_mb.txt)
  if ! "$build/fuzz/powerkey_fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb="${rss:-2048}" \
      "${parallel[@]}" -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" \
      "$corpus" "${inputs[@]}" >"$log" 2>&1; then
    result="FAILED (see $log)"
    status=1
  fi
  if [ "$jobs" -gt 1 ]; then cat fuzz-[0-9]*.log >>"$log" 2>/dev/null || true; rm -f fuzz-[0-9]*.log; fi
  execs=$(grep -h 'stat::number_of_executed_units' "$log" | awk '{s += $2} END {print s + 0}' || true)
  rate=$(( execs / (seconds > 0 ? seconds : 1) ))
  cov=$(grep -hoE 'cov: [0-9]+' "$log" | tail -1 | awk '{print $2}' || true)
  peak=$(grep -h 'stat::peak_rss_mb' "$log" | awk '$2 > m { m = $2 } END { print m + 0 }' || true)
  printf '%-16s %12s %10s %8s %8s %s\n' "$t" "$execs" "$rate" "${cov:-?}" "${peak:-?}" "$result" | tee -a "$summary"
done
exit $status
