#!/usr/bin/env bash
# Formats every C++ file of ours with the root .clang-format.
set -euo pipefail
cd "$(dirname "$0")/.."
find include tests examples bench fuzz \( -name '*.hpp' -o -name '*.cpp' \) -print0 |
  xargs -0 clang-format-14 -i
