#!/usr/bin/env bash
# Line and branch coverage of include/ (llvm-cov, clang source-based coverage), in two steps:
#   1. the test suite: the doctest suite and the freestanding checks;
#   2. the same plus a replay of every fuzz target's seeds, regressions and, when present, the
#      corpus of the long runs (fuzz/corpus-run/, see scripts/fuzz.sh).
# Prints both summaries and writes an HTML report to $BUILD_DIR/html. docs/quality.md records the
# figures.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build/fuzz-coverage}
llvm_ver=${LLVM_VERSION:-14}
profdata=$(command -v llvm-profdata-$llvm_ver || command -v llvm-profdata)
cov=$(command -v llvm-cov-$llvm_ver || command -v llvm-cov)

# The tool on: the suite's tests/test_tool_parts.cpp links the tool's log readers
# (powerkey_log_formats); only the targets below are built, not the tool itself.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS="-fprofile-instr-generate -fcoverage-mapping" \
  -DPOWERKEY_BUILD_FUZZ=ON -DPOWERKEY_FUZZ_LIBFUZZER=OFF -DPOWERKEY_BUILD_TOOL=ON >/dev/null
# The list may stand on one line or run over several: from its set( to the first ')'.
targets=($(awk '/^set\(POWERKEY_FUZZ_TARGETS/ {on = 1} on {print; if (/\)/) exit}' fuzz/CMakeLists.txt |
  sed -e 's/set(POWERKEY_FUZZ_TARGETS//' -e 's/)//' | tr -s ' \n' ' '))
cmake --build "$build" -j "${JOBS:-2}" --target powerkey_freestanding \
  powerkey_fuzz_seeds $(printf 'powerkey_fuzz_%s ' "${targets[@]}")
# The doctest suite last, and on its own: when it does not build (a compiler crash, a test being
# written), the fuzz corpora and the freestanding checks are still measured, and the report says so.
suite=1
cmake --build "$build" -j "${JOBS:-2}" --target powerkey_tests || {
  echo "note: powerkey_tests did not build; measuring the fuzz corpora and freestanding checks only"
  suite=0
}

profiles="$build/profiles"
rm -rf "$profiles" && mkdir -p "$profiles"
export LLVM_PROFILE_FILE="$profiles/%p.profraw"
[ $suite = 1 ] && "$build/tests/powerkey_tests" >/dev/null
"$build/tests/powerkey_freestanding" >/dev/null
"$profdata" merge -sparse "$profiles"/*.profraw -o "$build/tests.profdata"

"$build/fuzz/powerkey_fuzz_seeds" "$build/fuzz/seeds"
objects=()
[ $suite = 1 ] && objects+=(-object "$build/tests/powerkey_freestanding")
for t in "${targets[@]}"; do
  inputs=("$build/fuzz/seeds/$t")
  [ -d "fuzz/regressions/$t" ] && inputs+=("fuzz/regressions/$t")
  [ -d "fuzz/corpus-run/$t" ] && inputs+=("fuzz/corpus-run/$t")
  # A regression that still fails aborts its replay; the inputs before it still count.
  "$build/fuzz/powerkey_fuzz_$t" "${inputs[@]}" >/dev/null 2>&1 || echo "note: $t replay failed"
  objects+=(-object "$build/fuzz/powerkey_fuzz_$t")
done
"$profdata" merge -sparse "$profiles"/*.profraw -o "$build/all.profdata"

main_object="$build/tests/powerkey_freestanding"
if [ $suite = 1 ]; then
  main_object="$build/tests/powerkey_tests"
  echo "== include/, the test suite"
  "$cov" report "$build/tests/powerkey_tests" -object "$build/tests/powerkey_freestanding" \
    -instr-profile="$build/tests.profdata" include/powerkey | tee "$build/coverage-tests.txt"
fi
echo "== include/, the test suite and the fuzz corpora"
"$cov" report "$main_object" "${objects[@]}" \
  -instr-profile="$build/all.profdata" include/powerkey | tee "$build/coverage-all.txt"
"$cov" show "$main_object" "${objects[@]}" -instr-profile="$build/all.profdata" \
  -format=html -output-dir="$build/html" -show-branches=count include/powerkey >/dev/null
echo "HTML: $build/html/index.html"
