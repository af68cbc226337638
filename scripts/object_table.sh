#!/usr/bin/env bash
# Prints the object vocabulary of docs/models.md as a Markdown table, read from the headers
# (include/powerkey/keypad/objects.hpp): every object, its value kind, and for each dictionary the row's
# address, size, access, range and default. The columns are the dictionaries enum_values<dictionary>()
# names; an object of none of them is left out. Regenerate the table after changing the rows:
#   bash scripts/object_table.sh > /tmp/objects.md    (then paste it into docs/models.md)
# An argument names another include directory (e.g. a `git archive` of a commit's include/).
set -euo pipefail
cd "$(dirname "$0")/.."
include=$(realpath "${1:-include}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/object_table.cpp" <<'CPP'
#include <powerkey/keypad/objects.hpp>
#include <powerkey/names.hpp>

#include <cstdio>
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

static std::string cell(dictionary d, object o) {
    const auto r = find_row(d, o);
    if (!r) return "";
    char address[16];
    std::snprintf(address, sizeof address, "`%04Xh/%u`", r->address.index, r->address.subindex);
    std::string s = address;
    s += r->size == 0 ? " string" : " " + std::to_string(r->size) + " B";
    s += r->access == access::read_only ? " ro" : r->access == access::write_only ? " wo" : " rw";
    const bool ranged = r->min != 0 || r->max != 0xFFFF'FFFF || r->also != 0xFFFF'FFFF;
    if (ranged) {
        s += ", ";
        if (kind_of(o).kind == value_kind::period && r->min != 0) s += "0 or ";
        if (r->min != 0 || r->max != 0xFFFF'FFFF)
            s += hex(r->min) + ".." + hex(r->max);
        else
            s += "any";
        if (r->also != 0xFFFF'FFFF) s += " or " + hex(r->also);
    }
    if (ranged || r->initial != 0) s += ", default " + hex(r->initial);
    return s;
}

int main() {
    std::printf("| object | value kind |");
    for (const auto d : enum_values<dictionary>()) std::printf(" %s |", std::string(to_string(d)).c_str());
    std::printf("\n|---|---|");
    for (std::size_t i = 0; i < enum_values<dictionary>().size(); ++i) std::printf("---|");
    std::printf("\n");
    for (const auto o : enum_values<object>()) {
        bool anywhere = false;  // objects of no dictionary listed here (yet) are left out
        for (const auto d : enum_values<dictionary>()) anywhere = anywhere || find_row(d, o);
        if (!anywhere) continue;
        const auto k = kind_of(o);
        std::string kind(to_string(k.kind));
        if (k.kind == value_kind::led_plane) kind += " (" + std::string(to_string(k.holds)) + ")";
        std::printf("| `%s` | %s |", std::string(to_string(o)).c_str(), kind.c_str());
        for (const auto d : enum_values<dictionary>()) std::printf(" %s |", cell(d, o).c_str());
        std::printf("\n");
    }
}
CPP
"${CXX:-g++}" -std=c++20 -I"$include" "$tmp/object_table.cpp" -o "$tmp/object_table"
"$tmp/object_table"
