// keypad/lookup.hpp: finding a dictionary row by address and by object. Every row of every
// dictionary is found both ways and is that row; and the tables the compiler builds for the
// decoder (the codec's 8-byte rows, the table of distinct ranges, the address hash tables and
// their multiplier, the object -> row arrays) are built again by the running program and
// compared with the compiler's: a constexpr function must give the same at run time, and
// llvm-cov, which counts only run time, sees these builders run (docs/quality.md).
#include <doctest/doctest.h>

#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/lookup.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/names.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

namespace {
using namespace powerkey;

// Every row of a dictionary is found by its address and by its object, and is that row.
constexpr bool same_row(const object_row& a, const object_row& b) {
    return a.id == b.id && a.address == b.address && a.size == b.size && a.access == b.access &&
           a.min == b.min && a.max == b.max && a.also == b.also && a.initial == b.initial;
}
constexpr bool every_row_found(dictionary d) {
    const auto rows = rows_of(d);
    if (rows.empty()) return false;
    for (const auto& r : rows) {
        const auto a = find_row(d, r.address);
        const auto o = find_row(d, r.id);
        if (!a || !o || !same_row(*a, r) || !same_row(*o, r)) return false;
    }
    return true;
}
constexpr bool every_dictionary() {
    for (const auto d : enum_values<dictionary>())
        if (!every_row_found(d)) return false;
    return enum_values<dictionary>().size() == dictionary_count;
}
static_assert(every_dictionary());

// A value the optimiser cannot see through, so that the builders below run at run time.
template <class T>
T opaque(T v) {
    volatile T keep = v;
    return keep;
}
}  // namespace

TEST_CASE("every row of every dictionary is found by address and by object") {
    for (const auto d : enum_values<dictionary>()) {
        CAPTURE(std::string(to_string(d)));
        CHECK(every_row_found(opaque(d)));
    }
}

TEST_CASE("the codec's rows and ranges, built again at run time, are the compiler's") {
    const auto ranges = detail::collect_ranges();
    REQUIRE(ranges.size == detail::value_ranges.size());
    for (std::size_t i = 0; i < ranges.size; ++i) CHECK(ranges.items[i] == detail::value_ranges[i]);
    CHECK(detail::part_widths_fit());

    const auto rows = detail::collect_codec_rows();
    REQUIRE(rows.size + 1 == detail::codec_rows.size());
    CHECK(detail::codec_rows[0].key == detail::no_codec_row.key);
    for (std::size_t i = 0; i < rows.size; ++i) {
        CAPTURE(i);
        CHECK(rows.items[i] == detail::all_codec_rows.items[i]);
        CHECK(detail::codec_rows[i + 1].key == (rows.items[i] & 0xFF'FFFF));
    }
    // Every full row of every dictionary has its codec row: same address, object, size, access.
    for (const auto d : enum_values<dictionary>())
        for (const auto& r : rows_of(d)) {
            CAPTURE(to_string(r.id));
            const auto& c = detail::codec_rows[detail::codec_row_number(r)];
            CHECK(c.address() == r.address);
            CHECK(c.id == r.id);
            CHECK(c.size() == r.size);
            CHECK(c.packed() == detail::codec_row_of(r).packed());
        }
}

TEST_CASE("the hash multiplier and the object -> row arrays, found again at run time") {
    CHECK(detail::find_multiplier() == detail::hash_multiplier);
    for (const auto d : enum_values<dictionary>()) {
        CAPTURE(to_string(d));
        CHECK(detail::max_probes(rows_of(d), opaque(detail::hash_multiplier)) <= 2);
    }
    // Called through opaque pointers: clang evaluates `auto x = f();` itself when f() is a
    // constant, even for a local that is not const.
    auto codec = opaque(&detail::by_object<false>)();
    auto full = opaque(&detail::by_object<true>)();
    CHECK(codec == detail::codec_rows_by_object);
    CHECK(full == detail::full_rows_by_object);
}

TEST_CASE("the address lookup: slot 0 is the sentinel no key matches; a key is its low 24 bits") {
    CHECK(detail::codec_rows[0].key == 0xFFFF'FFFFu);
    CHECK(detail::codec_rows[0].flags == 0);
    for (const auto d : enum_values<dictionary>()) {
        CAPTURE(to_string(d));
        // FFFFh sub FFh is no object of any manual: its key is the sentinel's low 24 bits.
        CHECK(detail::find_codec_row(d, opaque(0x00FF'FFFFu)) == 0);
        CHECK(detail::find_codec_row(d, opaque(0xFFFF'FFFFu)) == 0);
        for (const auto& r : rows_of(d)) {
            CAPTURE(to_string(r.id));
            const auto key = detail::wire_key(r.address);
            const auto i = detail::find_codec_row(d, opaque(key));
            REQUIRE(i != 0);
            CHECK(detail::codec_rows[i].id == r.id);
            CHECK(detail::find_codec_row(d, opaque(key | 0xAB00'0000u)) == i);
        }
    }
}

// Under -Os the address lookup scans the codec rows a dictionary has (scan_codec_row) and the
// command decoder scans the command table (scan_command_shape): the same answers as the hash
// slots and the byte table, for every key of every dictionary, every key one off a row's (index
// and subindex), keys of no row, and every command byte.
TEST_CASE("the firmware's lookups (-Os) answer as the hash slots and the byte table") {
    for (const auto d : enum_values<dictionary>()) {
        CAPTURE(to_string(d));
        std::size_t found = 0;
        for (const auto& other : detail::codec_rows) {
            for (const std::uint32_t delta : {0u, 1u, 0x100u, 0xFFFF'FFFFu, 0xFFFF'FF00u}) {
                const std::uint32_t key = opaque(other.key + delta);
                CAPTURE(key);
                const auto hashed = detail::find_codec_row(d, key);
                CHECK(detail::scan_codec_row(d, key) == hashed);
                found += hashed != 0 ? 1 : 0;
            }
        }
        CHECK(found >= rows_of(d).size());  // every row's own key at least
        CHECK(detail::scan_codec_row(d, opaque(0xFFFF'FFFFu)) == 0);
        CHECK(detail::scan_codec_row(d, opaque(0x0012'3456u)) ==
              detail::find_codec_row(d, opaque(0x0012'3456u)));
    }
    for (unsigned b = 0; b < 0x100; ++b) {
        CAPTURE(b);
        CHECK(detail::scan_command_shape(static_cast<std::uint8_t>(opaque(b))) ==
              detail::command_shape_index[b]);
    }
}
