#!/usr/bin/env bash
# Installs what building and testing powerkey needs on Debian 12, if it is missing.
set -euo pipefail
packages=(g++ clang cmake make doctest-dev libbenchmark-dev clang-format-14 valgrind
          libclang-rt-14-dev gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib
          llvm python3 wireshark-dev tshark
          libcli11-dev nlohmann-json3-dev zlib1g-dev python3-can can-utils
          pybind11-dev python3-dev python3-pytest python3-canmatrix python3-junitparser)
# libcli11-dev, nlohmann-json3-dev, zlib1g-dev: the powerkey tool's options, JSON input and BLF
# containers. python3-can, can-utils: tests/test_tool_log_formats.sh writes its logs with them.
# pybind11-dev, python3-dev: the Python module (python/, docs/python.md); python3-pytest (with
# python3-can) runs its tests. python3-canmatrix: tests/test_dbc.py reads `powerkey export dbc`'s
# files with it. python3-junitparser: tests/test_tool_check_faults.py reads `powerkey check --junit`'s
# report with it.
# tshark (with wireshark-dev: the Wireshark plugin) is also what scripts/bench_cli.sh compares with.
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  # tshark's package asks whether non-root users may capture: keep its default (no).
  echo "wireshark-common wireshark-common/install-setuid boolean false" | debconf-set-selections
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
