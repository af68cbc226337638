#!/usr/bin/env bash
# README command 1: installs what is missing (g++, cmake, make) on Debian 12, builds the powerkey
# tool and decodes a sample log made of the manual's example frames.
#   bash scripts/run.sh              the PK1000 log
#   bash scripts/run.sh pkp3500mt    another model: any of the thirteen of examples/logs/
set -euo pipefail
cd "$(dirname "$0")/.."
model=${1:-pk1000}
models="pk1000 pkp2200 pkp2400 pkp2600 pkp2600si pkp3500mt pkp3500si pkp2500si pkp1500li pkp2200si pkp2300si pkp2400si pkp1600si"
case " $models " in
  *" $model "*) ;;
  *) echo "run.sh: unknown model '$model' (${models// /, })" >&2; exit 2 ;;
esac
missing=()
for tool in g++ cmake make; do
  command -v "$tool" >/dev/null || missing+=("$tool")
done
# The tool's options, JSON input and BLF containers: CLI11, nlohmann/json, zlib (docs/cli.md).
for p in libcli11-dev nlohmann-json3-dev zlib1g-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "run.sh: ${missing[*]} missing; run as root to install" >&2; exit 1; }
    sudo="sudo"
  fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends g++ cmake make libcli11-dev \
    nlohmann-json3-dev zlib1g-dev >/dev/null
fi
cmake -S . -B build/run -DCMAKE_BUILD_TYPE=Release -DPOWERKEY_BUILD_TESTS=OFF >/dev/null
cmake --build build/run -j 2 --target powerkey_tool >/dev/null
echo "\$ powerkey decode --model $model examples/logs/$model.log"
./build/run/examples/powerkey decode --model "$model" "examples/logs/$model.log"
