// The tables of include/ that the compiler builds (the codec's 8-byte rows, the table of distinct
// ranges, the address hash tables and their multiplier, the object -> row arrays, the SI
// dictionaries joined from shared and own rows) and the invariants the headers prove with
// static_assert, evaluated again by the running program and compared with what the compiler
// built. A constexpr function must give the same at run time; and llvm-cov, which counts only
// run time, sees these builders run (docs/quality.md).
#include <doctest/doctest.h>

#include <powerkey/behaviour/virtual_keypad.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/lookup.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/names.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace {
using namespace powerkey;

// A value the optimiser cannot see through, so that the builders below run at run time.
template <class T>
T opaque(T v) {
    volatile T keep = v;
    return keep;
}

bool same_row(const object_row& a, const object_row& b) {
    return a.id == b.id && a.address == b.address && a.size == b.size && a.access == b.access &&
           a.min == b.min && a.max == b.max && a.also == b.also && a.initial == b.initial;
}

template <std::size_t N, class Own, class Shared>
void check_join(const std::array<object_row, N>& built, const Own& own, const Shared& shared) {
    REQUIRE(detail::joined_size(own, shared) == N);
    const auto again = detail::join_rows<N>(own, shared);
    for (std::size_t i = 0; i < N; ++i) {
        CAPTURE(i);
        CHECK(same_row(again[i], built[i]));
    }
    // Own rows first, in their order; then every shared row that no own row replaces.
    for (std::size_t i = 0; i < std::size(own); ++i) CHECK(same_row(built[i], own[i]));
    std::size_t replaced = 0;
    for (const auto& c : shared) replaced += detail::replaced(own, c) ? 1u : 0u;
    CHECK(std::size(own) + std::size(shared) - replaced == N);
}
}  // namespace

TEST_CASE("the PK1000 and SI dictionaries are their own rows, then the shared ones not replaced") {
    check_join(detail::pk1000_rows, detail::pk1000_own_rows, detail::pk_shared_rows);
    check_join(detail::si_common_rows, detail::si_common_own_rows, detail::pk_shared_rows);
    check_join(detail::si_packed_rows, detail::si_packed_own_rows, detail::si_common_rows);
    check_join(detail::si_mt_rows, detail::si_mt_own_rows, detail::si_common_rows);
    check_join(detail::si_per_colour_rows, detail::si_per_colour_own_rows, detail::si_common_rows);
    // The PKP-3500-MT replaces shared rows with its own (docs/models.md): the TPDO1 event timer.
    CHECK(detail::replaced(detail::si_mt_own_rows,
                           *find_row(dictionary::si_mt, object::tpdo1_event_timer)));
    CHECK(!detail::replaced(detail::si_mt_own_rows, *find_row(dictionary::si_mt, object::keys)));
}

TEST_CASE("every dictionary is well formed: one row per object and per address, min <= max") {
    for (const auto d : enum_values<dictionary>()) {
        CAPTURE(to_string(d));
        CHECK(detail::rows_well_formed(rows_of(opaque(d))));
    }
    object_row twice[] = {rows_of(dictionary::pk1000)[0], rows_of(dictionary::pk1000)[0]};
    CHECK(!detail::rows_well_formed(twice));
    object_row upside_down[] = {rows_of(dictionary::pk1000)[0]};
    upside_down[0].min = 5;
    upside_down[0].max = 4;
    CHECK(!detail::rows_well_formed(upside_down));
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

TEST_CASE("the model table's invariants hold at run time too") { CHECK(detail::planes_apart()); }

TEST_CASE("enum_values counts each named value once, aliases not") {
    // backlight_colour: keep and red..yellow_green (ten values) and two alias names.
    CHECK(detail::distinct_values<backlight_colour>() == 10);
    CHECK(detail::distinct_values<backlight_colour>() <
          std::size(enum_names<backlight_colour>::entries));
    CHECK(detail::distinct_values<model>() == model_count);
    CHECK(detail::distinct_values<dictionary>() == 5);
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

TEST_CASE("the codec's compile-time checks and the LED-map bits, again at run time") {
    CHECK(opaque(&detail::commands_writable)());
    // The bits an LED-map object may carry: each model's LED bits of the planes the object keeps.
    const auto low_bits = opaque(&detail::low_bits);
    CHECK(low_bits(0) == 0);
    CHECK(low_bits(24) == 0xFF'FFFFu);
    CHECK(low_bits(64) == ~std::uint64_t{0});
    const auto layout_of = opaque(&detail::layout_of);
    for (const auto& m : detail::model_table) {
        CAPTURE(m.id);
        const auto leds = m.led_bits & low_bits(m.object_planes() * m.stride);
        CHECK(detail::layout(m.id).object_not_leds == static_cast<std::uint32_t>(~leds));
        // The codec's copy of the row, made again at run time, is the compiler's.
        const auto l = layout_of(m);
        CHECK(l.object_not_leds == detail::layout(m.id).object_not_leds);
        CHECK(l.led_bits == m.led_bits);
        CHECK(l.not_keys == m.not_keys);
        CHECK(l.object_planes() == m.object_planes());
    }
}

TEST_CASE("a keypad string keeps its NULs, and the reported name stops at the first") {
    const auto pk1000 = *info(opaque(model::pk1000));
    const auto s = pk1000.string_of(object::model_name);
    REQUIRE(s);
    CHECK(s->bytes == std::string_view("PK1000\0", 7));
    CHECK(pk1000.reported() == "PK1000");
    CHECK(info(opaque(model::pkp2400))->reported() == "PKU2400");
    CHECK(info(opaque(model::pkp2200))->reported().empty());  // inferred: no manual shows it
}
