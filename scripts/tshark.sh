#!/usr/bin/env bash
# Runs the system's tshark with the PowerKey plugin from the build tree, building it if needed:
#   bash scripts/tshark.sh [tshark arguments...]
#   bash scripts/tshark.sh -r LOG.pcap -o powerkey.model:pk1000 -T fields -e powerkey.kind
# POWERKEY_BUILD_DIR picks the build tree (default build/tshark); POWERKEY_TSHARK_BUILD=0 uses
# the plugin already built there (the ctest tests, which build it beforehand). Nothing is installed: as a
# normal user WIRESHARK_PLUGIN_DIR points tshark at the build tree; as root Wireshark reads no
# plugin directory but the system's (it ignores WIRESHARK_PLUGIN_DIR and the per-user directory),
# so the plugin is loaded with LD_PRELOAD and registers itself (POWERKEY_WIRESHARK_PRELOAD).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${POWERKEY_BUILD_DIR:-$root/build/tshark}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
# Build output goes to a log, shown only on failure: tshark's output stays clean.
if [ "${POWERKEY_TSHARK_BUILD:-1}" != 0 ] && ! {
  bash "$root/scripts/deps.sh" &&
    { [ -f "$build/CMakeCache.txt" ] ||
      cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPOWERKEY_BUILD_TESTS=OFF \
        -DPOWERKEY_BUILD_EXAMPLES=OFF -DPOWERKEY_BUILD_WIRESHARK=ON; } &&
    cmake --build "$build" --target powerkey_wireshark -j "${JOBS:-2}"
} > "$log" 2>&1; then
  cat "$log" >&2
  echo "tshark.sh: could not build the Wireshark plugin in $build" >&2
  exit 1
fi
plugins=$build/wireshark/plugins
plugin=$(find "$plugins" -name powerkey.so -print -quit 2>/dev/null || true)
if [ -z "$plugin" ]; then
  echo "tshark.sh: no plugin in $plugins (is wireshark-dev installed?)" >&2
  exit 1
fi
# The build log is not needed past here: exec replaces this shell, and its EXIT trap with it.
rm -f "$log"
trap - EXIT
if [ "$(id -u)" -eq 0 ]; then
  export POWERKEY_WIRESHARK_PRELOAD=1
  export LD_PRELOAD="$plugin${LD_PRELOAD:+:$LD_PRELOAD}"
else
  export WIRESHARK_PLUGIN_DIR=$plugins
fi
exec tshark "$@"
