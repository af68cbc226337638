#!/usr/bin/env bash
# The two generated tables of docs/models.md, read from the headers: the model table (every row of
# POWERKEY_MODELS, include/powerkey/keypad/models.hpp) and the object vocabulary (every object,
# its value kind, and per dictionary the row's address, size, access, range and default:
# keypad/objects.hpp, keypad/dictionaries.hpp). In docs/models.md each table stands after its
# marker line, <!-- model table --> and <!-- object table -->.
#   bash scripts/doc_tables.sh            prints both tables
#   bash scripts/doc_tables.sh --write    writes them into docs/models.md
#   bash scripts/doc_tables.sh --check    fails when docs/models.md's tables are not what the
#                                         headers say (ctest docs_tables)
# CXX picks the compiler (default g++).
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/doc_tables.cpp" <<'CPP'
#include <powerkey/keypad/lookup.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/names.hpp>

#include <cstdio>
#include <cstring>
#include <string>

using namespace powerkey;

// Numbers as the manuals print them: 0..9 plain, then 0Ah, 3Fh, FFFFh, 40000215h.
static std::string hex(std::uint32_t v) {
    char b[16];
    if (v <= 9)
        std::snprintf(b, sizeof b, "%u", v);
    else if (v <= 0xFF)
        std::snprintf(b, sizeof b, "%02Xh", v);
    else if (v <= 0xFFFF)
        std::snprintf(b, sizeof b, "%Xh", v);
    else
        std::snprintf(b, sizeof b, "%08Xh", v);
    return b;
}

static std::string name(auto e) { return std::string(to_string(e)); }

static void model_table() {
    std::printf(
        "| `model` | `manual` | `dictionary` | `keys` | `leds` | `planes` | `stride` | `led_mask` "
        "| `brightness_pdo` | `encoder_leds_pdo` | `backlight_pdo` | `backlight_colour` | "
        "`backlight_zero_is_default` | `encoders` | `j1939` | `replies_from_new_id` | reports "
        "in 100Bh |\n|---|---|---|---:|---:|---:|---:|---:|---|---|---|---|---|---|---|---|---|\n");
    const auto yes = [](bool b) { return b ? "yes" : ""; };
    for (const auto m : enum_values<model>()) {
        const auto& r = *info(m);
        const auto s = r.string_of(object::model_name);
        std::string reports = r.reported().empty() ? "" : "`" + std::string(r.reported()) + "`";
        if (s && r.reported().empty()) {  // inferred: the string up to its first NUL
            reports = "*inferred* `" + std::string(s->bytes.substr(0, s->bytes.find('\0'))) + "`";
        }
        std::printf("| `%s` | %s | `%s` | %u | %u | %u | %u | %s | %s | %s | %s | %s | %s | %s | %s "
                    "| %s | %s |\n",
                    name(m).c_str(), std::string(r.manual).c_str(), name(r.dictionary).c_str(),
                    r.keys, r.leds, r.planes, r.stride, hex(r.led_mask).c_str(),
                    yes(r.brightness_pdo), yes(r.encoder_leds_pdo), yes(r.backlight_pdo),
                    yes(r.backlight_colour), yes(r.backlight_zero_is_default), yes(r.encoders),
                    yes(r.j1939), yes(r.replies_from_new_id), reports.c_str());
    }
}

static std::string cell(dictionary d, object o) {
    const auto r = find_row(d, o);
    if (!r) return "";
    char address[16];
    std::snprintf(address, sizeof address, "`%04Xh/%u`", r->address.index, r->address.subindex);
    std::string s = address;
    if (r->size != 0)
        s += " " + std::to_string(r->size) + " B";
    else
        s += info(o).kind == value_kind::string ? " string"
              : info(o).kind == value_kind::keys ? " 2 B (1 B up to 8 keys)"
                                                 : " stride/8 B";
    s += r->access == access::read_only ? " ro" : r->access == access::write_only ? " wo" : " rw";
    const bool ranged = r->min != 0 || r->max != 0xFFFF'FFFF || r->also != 0xFFFF'FFFF;
    if (ranged) {
        s += ", ";
        if (info(o).kind == value_kind::period && r->min != 0) s += "0 or ";
        if (r->min != 0 || r->max != 0xFFFF'FFFF)
            s += hex(r->min) + ".." + hex(r->max);
        else
            s += "any";
        if (r->also != 0xFFFF'FFFF) s += " or " + hex(r->also);
    }
    if (ranged || r->initial != 0) s += ", default " + hex(r->initial);
    return s;
}

static void object_table() {
    std::printf("| object | value kind |");
    for (const auto d : enum_values<dictionary>()) std::printf(" %s |", name(d).c_str());
    std::printf("\n|---|---|");
    for (std::size_t i = 0; i < enum_values<dictionary>().size(); ++i) std::printf("---|");
    std::printf("\n");
    for (const auto o : enum_values<object>()) {
        bool anywhere = false;  // an object of no dictionary is left out
        for (const auto d : enum_values<dictionary>()) anywhere = anywhere || find_row(d, o);
        if (!anywhere) continue;
        const auto k = info(o);
        std::string kind = name(k.kind);
        if (k.kind == value_kind::led_plane) kind += " (" + name(k.holds) + ")";
        std::printf("| `%s` | %s |", name(o).c_str(), kind.c_str());
        for (const auto d : enum_values<dictionary>()) std::printf(" %s |", cell(d, o).c_str());
        std::printf("\n");
    }
}

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "models") == 0)
        model_table();
    else
        object_table();
}
CPP
"${CXX:-g++}" -std=c++20 -Iinclude "$tmp/doc_tables.cpp" -o "$tmp/doc_tables"
"$tmp/doc_tables" models > "$tmp/model_table.md"
"$tmp/doc_tables" objects > "$tmp/object_table.md"
# docs/models.md with the table after each marker replaced by the generated one.
python3 - "$tmp" > "$tmp/models.md" <<'PY'
import sys
tmp = sys.argv[1]
lines = open("docs/models.md").read().split("\n")
out, i = [], 0
while i < len(lines):
    out.append(lines[i])
    for marker, table in (("<!-- model table -->", "model_table.md"),
                          ("<!-- object table -->", "object_table.md")):
        if lines[i] == marker:
            out += open(f"{tmp}/{table}").read().rstrip("\n").split("\n")
            while i + 1 < len(lines) and lines[i + 1].startswith("|"):
                i += 1
    i += 1
print("\n".join(out), end="")
PY
case $mode in
  --write) cp "$tmp/models.md" docs/models.md ;;
  --check)
    diff -u docs/models.md "$tmp/models.md" ||
      { echo "docs/models.md: a table differs from the headers; bash scripts/doc_tables.sh --write"; exit 1; } ;;
  *) cat "$tmp/model_table.md"; echo; cat "$tmp/object_table.md" ;;
esac
