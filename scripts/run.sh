#!/usr/bin/env bash
# The main job: builds the examples and prints frames built at compile time, in candump form.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v g++ >/dev/null || ! command -v cmake >/dev/null; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends g++ cmake make
fi
cmake -S . -B build/run -DCMAKE_BUILD_TYPE=Release -DPOWERKEY_BUILD_TESTS=OFF >/dev/null
cmake --build build/run -j 2 --target powerkey_frames >/dev/null
./build/run/examples/powerkey_frames
