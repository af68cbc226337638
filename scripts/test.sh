#!/usr/bin/env bash
# Installs what is missing, builds everything with g++ and with clang++ (ASan + UBSan), and runs
# the whole test suite. Ends with ctest's summary line.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
jobs=${JOBS:-2}

# clang++ with AddressSanitizer and UndefinedBehaviorSanitizer, fuzz targets with libFuzzer.
cmake -S . -B build/clang-asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ \
  -DPOWERKEY_SANITIZE=ON -DPOWERKEY_BUILD_FUZZ=ON -DPOWERKEY_FUZZ_SECONDS=${FUZZ_SECONDS:-8} >/dev/null
cmake --build build/clang-asan -j "$jobs"
ctest --test-dir build/clang-asan -j "$jobs" --output-on-failure

# g++, optimised, with everything: tests, examples, benchmarks (a short run) and fuzz replays.
cmake -S . -B build/gcc -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=g++ \
  -DPOWERKEY_BUILD_BENCH=ON -DPOWERKEY_BUILD_FUZZ=ON >/dev/null
cmake --build build/gcc -j "$jobs"
ctest --test-dir build/gcc -j "$jobs" --output-on-failure
