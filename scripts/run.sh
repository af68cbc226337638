#!/usr/bin/env bash
# README command 1: installs what is missing (g++, cmake, make) on Debian 12, builds the powerkey
# tool and decodes a sample log made of the manual's example frames.
#   bash scripts/run.sh              the PK1000 log
#   bash scripts/run.sh pkp2400      another model: pk1000, pkp2200, pkp2400, pkp2600
set -euo pipefail
cd "$(dirname "$0")/.."
model=${1:-pk1000}
case "$model" in
  pk1000|pkp2200|pkp2400|pkp2600) ;;
  *) echo "run.sh: unknown model '$model' (pk1000, pkp2200, pkp2400, pkp2600)" >&2; exit 2 ;;
esac
missing=()
for tool in g++ cmake make; do
  command -v "$tool" >/dev/null || missing+=("$tool")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "run.sh: ${missing[*]} missing; run as root to install" >&2; exit 1; }
    sudo="sudo"
  fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends g++ cmake make >/dev/null
fi
cmake -S . -B build/run -DCMAKE_BUILD_TYPE=Release -DPOWERKEY_BUILD_TESTS=OFF >/dev/null
cmake --build build/run -j 2 --target powerkey_tool >/dev/null
echo "\$ powerkey decode --model $model examples/logs/$model.log"
./build/run/examples/powerkey decode --model "$model" "examples/logs/$model.log"
