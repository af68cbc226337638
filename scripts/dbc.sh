#!/usr/bin/env bash
# Writes the checked-in DBC files, examples/dbc/MODEL.dbc (one per file already there), with
# `powerkey export dbc --model MODEL` (node 15h; docs/dbc.md). Run it after a change of the model
# table, the dictionaries or the writer (tools/powerkey/dbc.cpp): the ctest `cli_dbc` fails while
# a file is stale.
#   bash scripts/dbc.sh [POWERKEY_BINARY]    (without one: builds powerkey_tool in build/dbc)
set -euo pipefail
cd "$(dirname "$0")/.."
pk=${1:-}
if [ -z "$pk" ]; then
  cmake -S . -B build/dbc -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build/dbc --target powerkey_tool -j "${JOBS:-2}" >/dev/null
  pk=build/dbc/tools/powerkey/powerkey
fi
for f in examples/dbc/*.dbc; do
  m=$(basename "$f" .dbc)
  "$pk" export dbc --model "$m" > "$f.new"
  mv "$f.new" "$f"
  echo "$f"
done
