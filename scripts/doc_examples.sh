#!/usr/bin/env bash
# Compiles every ```cpp block of README.md and docs/*.md against include/, so that the examples
# the docs show (and their static_asserts) stay true. Each file's blocks go into one translation
# unit, each block in a namespace of its own, after `#include <powerkey/powerkey.hpp>` and
# `using namespace powerkey;` (a block's main() is then no global main, hence -Wno-return-type).
# A ```cpp block must therefore be namespace-scope code (declarations, functions, static_asserts);
# show a fragment of statements in a plain ``` block, or inside a function.
# Usage: bash scripts/doc_examples.sh [FILE.md...]
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
[ $# -gt 0 ] || set -- README.md docs/*.md
status=0
for md in "$@"; do
  python3 - "$md" "$tmp/doc.cpp" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
blocks = re.findall(r"```cpp\n(.*?)```", text, re.S)
src = "#include <powerkey/powerkey.hpp>\n#include <cstdio>\nusing namespace powerkey;\n"
for i, b in enumerate(blocks):
    src += f"namespace doc_block_{i} {{\n#line 1 \"{sys.argv[1]} block {i + 1}\"\n{b}}}\n"
open(sys.argv[2], "w").write(src)
PY
  if "${CXX:-g++}" -std=c++20 -fsyntax-only -Wall -Wextra -Wno-return-type -Iinclude "$tmp/doc.cpp"; then
    echo "ok      $md"
  else
    echo "FAILED  $md"
    status=1
  fi
done
exit $status
