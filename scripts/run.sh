#!/usr/bin/env bash
# README command 1: installs what is missing (g++, cmake, make and the tool's libraries) on
# Debian 12, builds the powerkey tool and decodes a sample log made of the manual's example frames.
#   bash scripts/run.sh              the PK1000 log
#   bash scripts/run.sh pkp3500mt    another model: any name --model takes (PKP-3500-MT too);
#                                    `powerkey models` lists them
#   bash scripts/run.sh j1939-pkp2600si   a J1939 log (j1939-pkp1600si too), or the log that
#   bash scripts/run.sh switch-pkp2600si  crosses the switch both ways: examples/logs/NAME.log
#                                         under the model its name ends with
# JOBS=N sets the build's parallel jobs (default: every processor).
set -euo pipefail
cd "$(dirname "$0")/.."
name=${1:-pk1000}
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
  echo "run.sh: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends g++ cmake make libcli11-dev \
    nlohmann-json3-dev zlib1g-dev
fi
# The tool alone: no tests, examples or plugins to configure.
configure_log=$(mktemp)
trap 'rm -f "$configure_log"' EXIT
cmake -S . -B build/run -DCMAKE_BUILD_TYPE=Release -DPOWERKEY_BUILD_TESTS=OFF \
  -DPOWERKEY_BUILD_EXAMPLES=OFF -DPOWERKEY_BUILD_WIRESHARK=OFF -DPOWERKEY_BUILD_PYTHON=OFF \
  > "$configure_log" 2>&1 || { cat "$configure_log" >&2; exit 1; }
echo "run.sh: building the powerkey tool in build/run (a few minutes the first time)"
cmake --build build/run --target powerkey_tool --parallel "${JOBS:-$(nproc)}"
pk=./build/run/tools/powerkey/powerkey
# The J1939 and switch logs: examples/logs/NAME.log, of the model after the prefix.
log=""
case "$name" in
  j1939-* | switch-*) log=examples/logs/$name.log; name=${name#*-} ;;
esac
# The model's own name, as the tool reads --model (its error lists the models).
model=$("$pk" models "$name") || exit 2
log=${log:-examples/logs/$model.log}
[ -f "$log" ] || { echo "run.sh: no sample log $log (ls examples/logs)" >&2; exit 2; }
echo "\$ powerkey decode --model $model $log"
"$pk" decode --model "$model" "$log"
