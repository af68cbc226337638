#!/usr/bin/env bash
# cmake --install installs what was built, nothing more, and never fails for what was not built
# (registered by tests/CMakeLists.txt as install_what_was_built):
#   test_cmake_install.sh SOURCE_DIR WORK_DIR CXX
# A fresh configuration of the library alone (tests and examples off; the tool, the Wireshark
# plugin and the Python module on, as they are by default where their dependencies are found)
# is installed without building anything: the headers and the CMake package files, and no error
# for the plugin, the tool or the module that were not built.
set -uo pipefail
src=$1
work=$2
cxx=$3
rm -rf "$work"
mkdir -p "$work"
failed=0
fail() { echo "FAIL: $*"; failed=1; }
cmake -S "$src" -B "$work/build" -DCMAKE_CXX_COMPILER="$cxx" -DPOWERKEY_BUILD_TESTS=OFF \
  -DPOWERKEY_BUILD_EXAMPLES=OFF > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
# The configure output says what is built and what is skipped, and why.
for part in "the powerkey tool" "the Wireshark plugin" "the Python module"; do
  grep -q "powerkey: $part is \(built\|skipped: .\)" "$work/configure.log" ||
    fail "configure says nothing of $part: $(grep 'powerkey:' "$work/configure.log")"
done
cmake --install "$work/build" --prefix "$work/stage" > "$work/install.log" 2>&1 ||
  fail "cmake --install of a build that built nothing: $(tail -3 "$work/install.log")"
(cd "$work/stage" && find . -type f | sort) > "$work/files"
grep -v '^\./include/powerkey/\|^\./share/cmake/powerkey/' "$work/files" > "$work/other"
[ -s "$work/other" ] && fail "installed what was not built: $(head -5 "$work/other")"
grep -q '^\./include/powerkey/powerkey.hpp$' "$work/files" || fail "no headers installed"
grep -q '^\./share/cmake/powerkey/powerkey-config.cmake$' "$work/files" || fail "no package files"
[ $failed -eq 0 ] && echo "install: a library-only build installs the headers and package files, and nothing else"
rm -rf "$work"
exit $failed
