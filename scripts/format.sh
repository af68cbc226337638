#!/usr/bin/env bash
# Formats C++ files with the root .clang-format: the files given, or every file of ours.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -gt 0 ]; then
  clang-format-14 -i "$@"
else
  find include tests examples tools bench fuzz wireshark python \( -name '*.hpp' -o -name '*.cpp' \) -print0 |
    xargs -0 clang-format-14 -i
fi
