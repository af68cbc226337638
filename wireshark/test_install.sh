#!/usr/bin/env bash
# cmake --install puts the plugin where Wireshark looks for a user's plugins (registered by
# wireshark/CMakeLists.txt as wireshark_install):
#   test_install.sh BUILD_DIR ABI
# Installs with --prefix HOME/.local into a fresh HOME, then asks tshark which plugins it loads.
# Wireshark reads no per-user plugin directory when it runs as root, so as root tshark runs as
# nobody (setpriv), in a directory under /tmp that nobody can read.
set -uo pipefail
build=$1
abi=$2
home=$(mktemp -d /tmp/powerkey-wireshark-home.XXXXXX)
trap 'rm -rf "$home"' EXIT
chmod 755 "$home"
# The plugin's component only: the test needs no other target of the build tree built.
cmake --install "$build" --prefix "$home/.local" --component powerkey_wireshark > "$home/install.log" ||
  { cat "$home/install.log"; echo "FAIL: cmake --install"; exit 1; }
plugin=$home/.local/lib/wireshark/plugins/$abi/epan/powerkey.so
[ -f "$plugin" ] || { echo "FAIL: no $plugin after cmake --install"; exit 1; }
run=(env HOME="$home" tshark -G plugins)
[ "$(id -u)" -eq 0 ] && run=(setpriv --reuid=65534 --regid=65534 --clear-groups "${run[@]}")
listed=$("${run[@]}" 2>/dev/null | grep '^powerkey\.so')
case "$listed" in
  *"dissector"*"$plugin") echo "wireshark_install: tshark loads $plugin" ;;
  *) echo "FAIL: tshark does not list $plugin: '$listed'"; exit 1 ;;
esac
