#!/usr/bin/env bash
# Cortex-M0+ footprint of the firmwares in bench/firmware: builds each fw_<name>.cpp with the
# start-up code and the size-optimised memory functions, links with --gc-sections, and prints
#   1. the sections: .text (with the 64-byte vector table), .rodata, .data, .bss, and flash used;
#   2. the worst stack use of each call the firmware makes (every function of namespace `calls`,
#      with everything it calls, from -fcallgraph-info=su), and of the whole firmware.
# Usage: scripts/footprint.sh [--check] [out-dir] [name...]      (names: a b core; default all)
# --check fails when a firmware has .data or .bss (the library promises none), when a firmware
# needs more flash than its limit (flash_limit below: 1 KiB for (a), for j1939, issue 21, and for
# a_codec, issue 24; 8 KiB for c and 6 KiB for b_strict, issue 24; 7,750 bytes for b, issue 20),
# more stack than its limit (stack_limit: 1 KiB for c, issue 24), or when a
# stack bound cannot be computed.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
check=0
if [ "${1:-}" = "--check" ]; then check=1; shift; fi
out=${1:-$root/build/bench/firmware}
shift || true
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  for f in "$root"/bench/firmware/fw_*.cpp; do n=$(basename "$f" .cpp); names+=("${n#fw_}"); done
fi
CXX=${ARM_CXX:-arm-none-eabi-g++}
prefix=${CXX%g++}
flags=(-std=c++20 -mcpu=cortex-m0plus -mthumb -Os -fno-exceptions -fno-rtti -ffunction-sections
       -fdata-sections -Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion -Wshadow -Werror
       -fstack-usage -fcallgraph-info=su
       -I"$root/include")
mkdir -p "$out"
status=0
printf '| firmware | .text | .rodata | .data | .bss | flash | worst stack | stack per call |\n'
printf '|---|---:|---:|---:|---:|---:|---:|---|\n'
for n in "${names[@]}"; do
  dir=$out/$n
  rm -rf "$dir"; mkdir -p "$dir"
  ( cd "$dir"
    "$CXX" "${flags[@]}" -c "$root/bench/firmware/fw_$n.cpp" -o fw.o
    "$CXX" "${flags[@]}" -c "$root/bench/firmware/startup.cpp" -o startup.o
    "$CXX" "${flags[@]}" -fno-tree-loop-distribute-patterns -c "$root/bench/firmware/libc_min.cpp" -o libc_min.o
    "$CXX" -mcpu=cortex-m0plus -mthumb -nostartfiles -nostdlib -Wl,--gc-sections \
      -T "$root/bench/firmware/link.ld" -Wl,-Map=fw.map fw.o startup.o libc_min.o -lgcc -o fw.elf
    "${prefix}size" -A fw.elf >sections.txt
    "${prefix}objdump" -d fw.elf >fw.dis
    "${prefix}nm" -S --size-sort -C fw.elf >symbols.txt
    "${prefix}nm" fw.elf >names.txt )
  python3 - "$dir" "$n" "$check" <<'PY' || status=1
import re, sys, glob, os
d, name, check = sys.argv[1], sys.argv[2], sys.argv[3] == "1"
sec = {}
for line in open(os.path.join(d, "sections.txt")):
    p = line.split()
    if len(p) == 3 and p[0].startswith("."):
        sec[p[0]] = int(p[1])
text, rodata = sec.get(".text", 0), sec.get(".rodata", 0) + sec.get(".ARM.exidx", 0)
data, bss = sec.get(".data", 0), sec.get(".bss", 0)
flash = text + rodata + data

# Call graph with the static frame size of every function GCC compiled.
frame, label, edges, dynamic = {}, {}, {}, set()
for ci in glob.glob(os.path.join(d, "*.ci")):
    for line in open(ci):
        m = re.match(r'node: \{ title: "([^"]+)" label: "([^"]*)"', line)
        if m:
            title, lab = m.group(1), m.group(2)
            label[title] = lab.split("\\n")[0]
            s = re.search(r"\\n(\d+) bytes \(([^)]*)\)", lab)
            if s:
                frame[title] = int(s.group(1))
                if s.group(2) != "static":
                    dynamic.add(title)
            continue
        m = re.match(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"', line)
        if m:
            edges.setdefault(m.group(1), set()).add(m.group(2))

# Functions GCC did not compile here (libgcc helpers): read their pushes from the disassembly.
dis = open(os.path.join(d, "fw.dis")).read()
# Aliases: libgcc's __aeabi_idiv is __divsi3 under another name (the disassembly labels one).
aliases = {}
for line in open(os.path.join(d, "names.txt")):
    p = line.split()
    if len(p) == 3:
        aliases.setdefault(p[0], []).append(p[2])
def asm_frame(sym):
    m = re.search(r"<" + re.escape(sym) + r">:\n(.*?)(?:\n\n|\Z)", dis, re.S)
    if not m:
        for names in aliases.values():
            if sym in names:
                for other in names:
                    if other != sym:
                        m = re.search(r"<" + re.escape(other) + r">:\n(.*?)(?:\n\n|\Z)", dis, re.S)
                        if m:
                            break
    if not m:
        return None
    total = 0
    for ins in m.group(1).splitlines():
        p = re.search(r"\tpush\t\{([^}]*)\}", ins)
        if p:
            total += 4 * len(p.group(1).split(","))
        s = re.search(r"\tsub\tsp, #(\d+)", ins)
        if s:
            total += int(s.group(1))
    return total

unknown = set()
def own(t):
    if t in frame:
        return frame[t]
    sym = t.split(":")[-1]
    for cand in [sym] + [k for k in frame if k.endswith(":" + sym)]:
        if cand in frame:
            return frame[cand]
    if not any(sym in names for names in aliases.values()):
        return 0  # in GCC's call graph but not linked: the call was optimised away
    f = asm_frame(sym)
    if f is None:
        unknown.add(sym)
        return 0
    return f

def resolve(t):
    # A callee named without its file prefix may be defined in another object file.
    if t in edges or t in frame:
        return t
    for k in frame:
        if k.endswith(":" + t):
            return k
    return t

# An indirect call (GCC's __indirect_call node) is, in this library, std::visit calling through
# its table: its targets are the __gen_vtable_impl entries. Any of them may be called, so the
# bound takes the worst; with no such entry every function is a possible target (still a bound).
visit_entries = [k for k in frame if "__gen_vtable_impl" in k or "__visit_invoke" in k]
indirect_targets = visit_entries or [k for k in frame if k != "reset_handler"]

memo, cyclic = {}, set()
def worst(t, stack=()):
    if t == "__indirect_call":
        return max([worst(c, stack) for c in indirect_targets if c not in stack] or [0])
    t = resolve(t)
    if t in stack:
        cyclic.add(t)
        return 0
    if t in memo:
        return memo[t]
    w = own(t) + max([worst(c, stack + (t,)) for c in edges.get(t, ())] or [0])
    memo[t] = w
    return w

total = worst("reset_handler")
per_call = []
for t, lab in sorted(label.items(), key=lambda kv: kv[1]):
    m = re.search(r"calls::(\w+)\(", lab)
    if m and t in frame:
        per_call.append(f"{m.group(1)} {worst(t)}")
notes = []
if dynamic & set(memo):
    notes.append("dynamic stack in " + ", ".join(sorted(label.get(x, x) for x in dynamic & set(memo))))
if cyclic:
    notes.append("recursion: " + ", ".join(sorted(cyclic)))
if unknown:
    notes.append("no stack data for " + ", ".join(sorted(unknown)))
print(f"| {name} | {text} | {rodata} | {data} | {bss} | {flash} | {total} | "
      + ", ".join(per_call) + (" (" + "; ".join(notes) + ")" if notes else "") + " |")
bad = []
if data or bss:
    bad.append(f".data {data} / .bss {bss}: the library must add none")
# The flash each firmware promises (bytes): a, the hand-rolled PK1000 program; j1939, a J1939
# keypad's key states in and LED commands out through the library (issue 21); a_codec, (a)'s
# program through the library with the model a template argument (issue 24); c, the controller
# of one model (issue 24); b_strict, every model's decoder reading strictly (issue 24's 6 KiB),
# and b, reading tolerantly (issue 20's 7,750 bytes).
flash_limit = {"a": 1024, "j1939": 1024, "a_codec": 1024, "c": 8192, "b_strict": 6144, "b": 7750}
if name in flash_limit and flash > flash_limit[name]:
    bad.append(f"flash {flash} > {flash_limit[name]} bytes")
# The worst stack each firmware promises (bytes): c, the controller of one model with the
# controller object on the loop's stack (issue 24).
stack_limit = {"c": 1024}
if name in stack_limit and total > stack_limit[name]:
    bad.append(f"worst stack {total} > {stack_limit[name]} bytes")
if notes:
    bad.append("stack bound not computable: " + "; ".join(notes))
if check and bad:
    print(f"FAIL {name}: " + "; ".join(bad), file=sys.stderr)
    sys.exit(1)
PY
done
exit $status
