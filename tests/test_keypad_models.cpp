// keypad/models.hpp: the model table, one pinned row per model with every fact of its row as the
// manuals give it (docs/models.md, docs/si-family.md); the SI sizes' rows against the data file
// tests/data/si_models.txt; every name a model answers to (the tool's, the manual's in any
// spelling, the string the keypad reports in 100Bh); the strings a keypad reports; and the
// LED-map and key-map rule.
#include <doctest/doctest.h>

#include <powerkey/keypad/models.hpp>
#include <powerkey/names.hpp>

#include "si_rows.hpp"
#include "support.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace {
using namespace powerkey;
using powerkey_tests::first_failing;

// Flags default to false, so a row names only what its keypad has (as the model table does).
struct info_row {
    std::string_view section;
    std::string_view frame;   // the tool's name, as the row runner prints it
    std::string_view manual;  // how its manual names it
    model id;
    dictionary dict;
    std::uint8_t keys, leds, planes, stride;
    std::uint32_t led_mask;
    unsigned object_planes;     // planes a 4-byte LED object holds: those that fit 32 bits
    std::string_view reported;  // the model string it reports in 100Bh, "" where no manual shows it
    bool brightness_pdo = false, encoder_leds_pdo = false, backlight_pdo = false,
         backlight_colour = false, encoders = false, j1939 = false, replies_from_new_id = false,
         backlight_zero_is_default = false;
};

constexpr auto pk = dictionary::pk1000, li = dictionary::pkp_li, packed = dictionary::si_packed,
               mt = dictionary::si_mt, per = dictionary::si_per_colour;
// clang-format off
constexpr info_row info_rows[] = {
    // PK1000 sections 11-13: 10 keys, 28 LEDs per colour (red and green), red in bytes 0..3,
    // green in 4..7; 400h/500h PDOs (14, 15); J1939 (49); the reply from the new id (23). Its
    // LED objects hold one plane each (2001h sub 1 red, sub 2 green, section 17).
    {.section = "PK1000 11-15, 23, 35, 49", .frame = "pk1000", .manual = "PK1000",
     .id = model::pk1000, .dict = pk, .keys = 10, .leds = 28, .planes = 2, .stride = 32,
     .led_mask = 0x0FFF'FFFF, .object_planes = 1, .reported = "PK1000", .brightness_pdo = true,
     .backlight_pdo = true, .backlight_colour = true, .j1939 = true, .replies_from_new_id = true},
    // PKP sections 10-12: one RGB LED per key, the planes one after the other (stride = keys);
    // the reply from the old id, then the boot-up from the new one (13 h). Only the PKP-2400's
    // model string is printed (22).
    {.section = "PKP 10-13 h", .frame = "pkp2200", .manual = "PKP-2200-LI", .id = model::pkp2200,
     .dict = li, .keys = 4, .leds = 4, .planes = 3, .stride = 4, .led_mask = 0xF,
     .object_planes = 3, .reported = ""},
    {.section = "PKP 10-13 h, 22", .frame = "pkp2400", .manual = "PKP-2400-LI",
     .id = model::pkp2400, .dict = li, .keys = 8, .leds = 8, .planes = 3, .stride = 8,
     .led_mask = 0xFF, .object_planes = 3, .reported = "PKU2400"},
    // docs/pkp.md: 12 keys, 36 bits; a 4-byte LED object holds two planes (E-PKP-8).
    {.section = "docs/pkp.md", .frame = "pkp2600", .manual = "PKP-2600", .id = model::pkp2600,
     .dict = li, .keys = 12, .leds = 12, .planes = 3, .stride = 12, .led_mask = 0xFFF,
     .object_planes = 2, .reported = ""},
    // docs/si-family.md, "The family" table; PKP2600SI manual section 15 (00h = default colour)
    {.section = "PKP2600SI 12-15, 33", .frame = "pkp2600si", .manual = "PKP-2600-SI",
     .id = model::pkp2600si, .dict = packed, .keys = 12, .leds = 12, .planes = 3, .stride = 12,
     .led_mask = 0xFFF, .object_planes = 2, .reported = "PKP2600SI", .brightness_pdo = true,
     .backlight_pdo = true, .backlight_colour = true, .j1939 = true, .replies_from_new_id = true,
     .backlight_zero_is_default = true},
    // PKP3500-MT: keys 1 and 11 are the encoder pushes, without LED (sections 2, 15, 17)
    {.section = "PKP3500-MT 12-18, 39", .frame = "pkp3500mt", .manual = "PKP-3500-MT",
     .id = model::pkp3500mt, .dict = mt, .keys = 15, .leds = 15, .planes = 3, .stride = 16,
     .led_mask = 0x7BFE, .object_planes = 2, .reported = "PKP3500MT", .encoder_leds_pdo = true,
     .backlight_pdo = true, .backlight_colour = true, .encoders = true, .j1939 = true,
     .replies_from_new_id = true},
    {.section = "PKP3500SI 12-15", .frame = "pkp3500si", .manual = "PKP-3500-SI",
     .id = model::pkp3500si, .dict = per, .keys = 15, .leds = 15, .planes = 3, .stride = 16,
     .led_mask = 0x7FFF, .object_planes = 2, .reported = "PKP3500SI", .brightness_pdo = true,
     .backlight_pdo = true, .j1939 = true, .replies_from_new_id = true},
    {.section = "PKP2500SI 13-15", .frame = "pkp2500si", .manual = "PKP-2500-SI",
     .id = model::pkp2500si, .dict = per, .keys = 10, .leds = 10, .planes = 3, .stride = 16,
     .led_mask = 0x3FF, .object_planes = 2, .reported = "", .brightness_pdo = true,
     .backlight_pdo = true, .j1939 = true, .replies_from_new_id = true},
    {.section = "PKP-1500-LI 12-13", .frame = "pkp1500li", .manual = "PKP-1500-LI",
     .id = model::pkp1500li, .dict = per, .keys = 5, .leds = 5, .planes = 3, .stride = 8,
     .led_mask = 0x1F, .object_planes = 3, .reported = "PKP1500LI", .backlight_pdo = true,
     .j1939 = true, .replies_from_new_id = true},
    {.section = "SI generic (inferred S = 8, 400h; colour: bench log)",
     .frame = "pkp2200si", .manual = "PKP-2200-SI", .id = model::pkp2200si, .dict = per, .keys = 4,
     .leds = 4, .planes = 3, .stride = 8, .led_mask = 0xF, .object_planes = 3, .reported = "",
     .brightness_pdo = true, .backlight_pdo = true, .backlight_colour = true, .j1939 = true,
     .replies_from_new_id = true},
    {.section = "SI generic (inferred S = 8, 400h; colour: bench log)",
     .frame = "pkp2300si", .manual = "PKP-2300-SI", .id = model::pkp2300si, .dict = per, .keys = 6,
     .leds = 6, .planes = 3, .stride = 8, .led_mask = 0x3F, .object_planes = 3, .reported = "",
     .brightness_pdo = true, .backlight_pdo = true, .backlight_colour = true, .j1939 = true,
     .replies_from_new_id = true},
    {.section = "SI generic (inferred S = 8, 400h; colour: bench log)",
     .frame = "pkp2400si", .manual = "PKP-2400-SI", .id = model::pkp2400si, .dict = per, .keys = 8,
     .leds = 8, .planes = 3, .stride = 8, .led_mask = 0xFF, .object_planes = 3, .reported = "",
     .brightness_pdo = true, .backlight_pdo = true, .backlight_colour = true, .j1939 = true,
     .replies_from_new_id = true},
    // Its CANopen side inferred: the SI rule for six keys, as the PKP-2300-SI (docs/si-family.md)
    {.section = "PKP1600SI J1939, SI generic",
     .frame = "pkp1600si", .manual = "PKP-1600-SI", .id = model::pkp1600si, .dict = per, .keys = 6,
     .leds = 6, .planes = 3, .stride = 8, .led_mask = 0x3F, .object_planes = 3, .reported = "",
     .brightness_pdo = true, .backlight_pdo = true, .backlight_colour = true, .j1939 = true,
     .replies_from_new_id = true},
};
// clang-format on
static_assert(std::size(info_rows) == model_count);

// The row as the table holds it, found by every name it gives: the tool's (also the enum's
// name), the manual's and the reported one.
constexpr bool info_holds(const info_row& r) {
    const auto i = info(r.id);
    return i && i->id == r.id && i->name == r.frame && to_string(r.id) == r.frame &&
           i->manual == r.manual && i->dictionary == r.dict && i->keys == r.keys &&
           i->leds == r.leds && i->planes == r.planes && i->stride == r.stride &&
           i->led_mask == r.led_mask && i->brightness_pdo == r.brightness_pdo &&
           i->encoder_leds_pdo == r.encoder_leds_pdo && i->backlight_pdo == r.backlight_pdo &&
           i->backlight_colour == r.backlight_colour && i->encoders == r.encoders &&
           i->j1939 == r.j1939 && i->replies_from_new_id == r.replies_from_new_id &&
           i->backlight_zero_is_default == r.backlight_zero_is_default &&
           i->object_planes() == r.object_planes && i->reported() == r.reported &&
           from_string<model>(r.frame) == std::optional<model>(r.id) &&
           parse_model(r.frame) == result<model>(r.id) &&
           parse_model(r.manual) == result<model>(r.id) &&
           (r.reported.empty() || (model_from_report(r.reported) == result<model>(r.id) &&
                                   parse_model(r.reported) == result<model>(r.id)));
}
static_assert(
    powerkey_tests::all_rows_pass<first_failing(info_rows, info_holds), std::size(info_rows)>);

// The rows above are the table's, in its order, and nothing past it is a model.
constexpr bool table_in_order() {
    const auto listed = enum_values<model>();
    if (listed.size() != std::size(info_rows)) return false;
    for (std::size_t i = 0; i < listed.size(); ++i)
        if (listed[i] != info_rows[i].id || static_cast<std::size_t>(listed[i]) != i) return false;
    const auto past = static_cast<model>(model_count);
    return info(past) == errc::value_out_of_range &&
           info(static_cast<model>(0xFF)) == errc::value_out_of_range && to_string(past).empty() &&
           !is_named(past);
}
static_assert(table_in_order());

// The SI sizes of the data file tests/data/si_models.txt (scripts/si_rows.py: si_rows::model_facts)
// are the rows above: keys, stride, 2001h/2002h scheme, the backlight PDO's colour byte, the
// reported string.
constexpr bool data_file_is_the_table() {
    for (const auto& f : si_rows::model_facts) {
        const auto& r = info_rows[static_cast<std::size_t>(f.id)];
        if (r.id != f.id || r.keys != f.keys || r.leds != f.keys || r.stride != f.stride ||
            r.dict != f.scheme || r.backlight_colour != f.colour_byte || r.reported != f.reported)
            return false;
    }
    return std::size(si_rows::model_facts) == 8;
}
static_assert(data_file_is_the_table());

// --- names ---------------------------------------------------------------------------------------

// Names beyond the rows' own: other spellings (case, '-', '_' and spaces ignored) and what names
// nothing.
struct name_row {
    std::string_view section;
    std::string_view frame;  // the text
    result<model> expected;
};
constexpr name_row name_rows[] = {
    {"manual name without suffix", "PKP-2400", model::pkp2400},
    {"lower case", "pkp-2400-li", model::pkp2400},
    {"underscore", "PKP_2200", model::pkp2200},
    {"spaces", "pkp 2400 li", model::pkp2400},
    {"mixed case", "Pkp_3500_Mt", model::pkp3500mt},
    {"underscores", "pkp_2400_si", model::pkp2400si},
    {"the reported string with '-'", "pku-2400", model::pkp2400},
    {"leading and trailing '-'", "-pkp2600si-", model::pkp2600si},
    {"no such keypad", "pkp9999", errc::value_out_of_range},
    {"no such keypad", "PKP-2700-SI", errc::value_out_of_range},
    {"a prefix of a name", "pkp", errc::value_out_of_range},
    {"a prefix of a name", "pkp35", errc::value_out_of_range},
    {"a prefix of a name", "pkp2500", errc::value_out_of_range},
    {"a longer name", "pkp2600sii", errc::value_out_of_range},
    {"separators only", "- _", errc::value_out_of_range},
    {"empty", "", errc::value_out_of_range},
};
constexpr bool parses(const name_row& r) { return parse_model(r.frame) == r.expected; }
static_assert(
    powerkey_tests::all_rows_pass<first_failing(name_rows, parses), std::size(name_rows)>);

// What a keypad reports (100Bh; PKP 6100h sub 2) is matched exactly, and only where a manual
// shows it: no other spelling, no manual or tool name, no string no manual prints.
constexpr name_row not_reported_rows[] = {
    {"not what a keypad sends", "pku2400", errc::value_out_of_range},
    {"not what a keypad sends", "PKP-2400-LI", errc::value_out_of_range},
    {"not what a keypad sends", "PKP-3500-MT", errc::value_out_of_range},
    {"not what a keypad sends", "pkp2200", errc::value_out_of_range},
    {"no manual shows it", "PKP2500SI", errc::value_out_of_range},
    {"no manual shows it", "PKP2200SI", errc::value_out_of_range},
    {"no manual shows it", "PKU2200", errc::value_out_of_range},
    {"empty", "", errc::value_out_of_range},
};
constexpr bool reported(const name_row& r) { return model_from_report(r.frame) == r.expected; }
static_assert(powerkey_tests::all_rows_pass<first_failing(not_reported_rows, reported),
                                            std::size(not_reported_rows)>);

// --- the strings a keypad reports ----------------------------------------------------------------

// As the keypad sends them: the bytes exactly as printed (NULs kept, E-CORE-5) and the size the
// initiate reply announces; none where the keypad has no such object.
struct string_row {
    std::string_view section;
    std::string_view frame;  // unused
    model id;
    object o;
    std::optional<std::string_view> bytes;
    std::uint32_t announced;
    bool size_indicated;
};
using namespace std::string_view_literals;
constexpr string_row string_rows[] = {
    {"PK1000 32", "", model::pk1000, object::device_name, "BlinkMarine"sv, 11, true},
    {"PK1000 34", "", model::pk1000, object::software_version, "V2.8"sv, 4, true},
    {"PK1000 35 (E-CORE-5)", "", model::pk1000, object::model_name, "PK1000\0"sv, 7, true},
    {"PK1000: no 6100h sub 2", "", model::pk1000, object::device_model, std::nullopt, 0, false},
    {"PKP 22 (E-CORE-2)", "", model::pkp2400, object::model_name, "PKU2400\0"sv, 7, true},
    {"PKP 29 (E-CORE-3)", "", model::pkp2400, object::device_model, "PKU2400\0"sv, 8, false},
};
constexpr bool string_holds(const string_row& r) {
    const auto s = info(r.id)->string_of(r.o);
    if (!r.bytes) return !s;
    return s && s->id == r.o && s->bytes == *r.bytes && s->announced == r.announced &&
           s->size_indicated == r.size_indicated;
}
static_assert(powerkey_tests::all_rows_pass<first_failing(string_rows, string_holds),
                                            std::size(string_rows)>);

// --- the LED-map and key-map rule ----------------------------------------------------------------

constexpr bool led_rule_holds() {
    const auto pk1000 = info(model::pk1000).value();
    const auto p2200 = info(model::pkp2200).value();
    const auto p2400 = info(model::pkp2400).value();
    const auto p2600 = info(model::pkp2600).value();
    const auto mt3500 = info(model::pkp3500mt).value();
    const auto si2500 = info(model::pkp2500si).value();
    const auto li1500 = info(model::pkp1500li).value();
    constexpr std::uint64_t one = 1;
    return
        // PK1000 12: red 1 is bit 0, green 28 is bit 59; PKP-2400: blue 3 is bit 18.
        pack_leds(pk1000, leds{{1}, {28}, {}}, 2) == ((one << 59) | 1) &&
        pack_leds(p2400, leds{{}, {}, {3}}, 3) == (one << 18) &&
        unpack_leds(p2600, one << 35, 3).value() == leds{{}, {}, {12}} &&
        // PKP3500-MT 15: S = 16, keys 1 and 11 have no LED; blue 15 is bit 2 * 16 + 14 = 46.
        pack_leds(mt3500, leds{{1, 2}, {11, 12}, {15}}, 3) ==
            ((one << 1) | (one << (16 + 11)) | (one << 46)) &&
        unpack_leds(mt3500, one << 46, 3).value() == leds{{}, {}, {15}} &&
        // A bit that names no LED: PK1000 bits 28..31 (red 29..32), a PKP-2200's bit 12, the
        // PKP3500-MT's red 1.
        unpack_leds(pk1000, one << 28, 2) == errc::reserved_not_zero &&
        unpack_leds(p2200, one << 12, 3) == errc::reserved_not_zero &&
        unpack_leds(mt3500, 1, 3) == errc::reserved_not_zero &&
        // One plane (a per-colour object) and two (a PKP-2600 6001h): the planes past them are
        // refused.
        unpack_leds(si2500, 0x03FF, 1).value() == leds{led_set::from_mask(0x3FF), {}, {}} &&
        unpack_leds(si2500, 0x0400, 1) == errc::reserved_not_zero &&
        unpack_leds(p2600, one << 24, 2) == errc::reserved_not_zero &&
        // Keys 1..N as bits 0..N-1; a bit above the model's keys is refused.
        unpack_keys(pk1000, 0x0200).value() == key_set{10} &&
        unpack_keys(pk1000, 0x0400) == errc::reserved_not_zero &&
        unpack_keys(p2200, 0x10) == errc::reserved_not_zero &&
        unpack_keys(mt3500, 0x4000).value() == key_set{15} &&
        unpack_keys(mt3500, 0x8000) == errc::reserved_not_zero &&
        unpack_keys(li1500, 0x20) == errc::reserved_not_zero;
}
static_assert(led_rule_holds());
}  // namespace

TEST_CASE("every row of the model table, and every name it gives") {
    powerkey_tests::check_rows(info_rows, info_holds);
    CHECK(table_in_order());
}

TEST_CASE("the SI sizes of tests/data/si_models.txt are the model table's rows") {
    CHECK(data_file_is_the_table());
}

TEST_CASE("models by name: other spellings, and what names nothing") {
    powerkey_tests::check_rows(name_rows, parses);
    powerkey_tests::check_rows(not_reported_rows, reported);
}

TEST_CASE("the strings a keypad reports, NULs kept") {
    powerkey_tests::check_rows(string_rows, string_holds);
}

TEST_CASE("the LED-map and key-map rule, and the table's invariants, at run time too") {
    CHECK(led_rule_holds());
    CHECK(detail::planes_apart());
}

namespace {
// A value the optimiser cannot see through, so that the builders below run at run time.
template <class T>
T opaque(T v) {
    volatile T keep = v;
    return keep;
}
}  // namespace

TEST_CASE("the decoders' copy of each row (model_layout), made again at run time, is the table's") {
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
        const auto l = layout_of(m);
        CHECK(l.object_not_leds == detail::layout(m.id).object_not_leds);
        CHECK(l.led_bits == m.led_bits);
        CHECK(l.not_keys == m.not_keys);
        CHECK(l.object_planes() == m.object_planes());
    }
}

// The LED-map and key-map rule bit by bit, for every model: each of the 64 bits alone through
// unpack_leds (with 1, 2 and the model's planes) and unpack_keys. A bit is an LED when its plane
// (bit / stride) is one of the planes asked for and its place in the plane (bit % stride) is in
// led_mask; a key when it is below the model's keys. Any other bit is reserved_not_zero; pack_leds
// gives each LED bit back.
TEST_CASE("the LED-map and key-map rule, each of 64 bits alone, in every model") {
    for (const model m : enum_values<model>()) {
        const model_info k = *info(m);
        CAPTURE(std::string(to_string(m)));
        for (unsigned planes = 1; planes <= k.planes; ++planes) {
            for (unsigned b = 0; b < 64; ++b) {
                CAPTURE(planes);
                CAPTURE(b);
                const std::uint64_t v = std::uint64_t{1} << b;
                const bool led = b / k.stride < planes && b % k.stride < 32 &&
                                 ((k.led_mask >> (b % k.stride)) & 1u) != 0;
                const auto l = unpack_leds(k, v, planes);
                if (led) {
                    REQUIRE(l.has_value());
                    CHECK(pack_leds(k, *l, planes) == v);
                } else {
                    CHECK(l == errc::reserved_not_zero);
                }
            }
        }
        for (unsigned b = 0; b < 64; ++b) {
            CAPTURE(b);
            const auto keys = unpack_keys(k, std::uint64_t{1} << b);
            if (b < k.keys)
                CHECK((keys.has_value() && keys->contains(b + 1)));
            else
                CHECK(keys == errc::reserved_not_zero);
        }
    }
}

// A model set holds models of the table only: every value of the enum's byte, at compile time.
namespace {
constexpr bool model_set_bounds() {
    model_set s = model_set::all();
    for (unsigned v = 0; v < 256; ++v) {
        const auto m = static_cast<model>(v);
        if (s.contains(m) != (v < model_count)) return false;
        model_set one;
        one.insert(m);
        if (one.empty() != (v >= model_count)) return false;
    }
    return true;
}
static_assert(model_set_bounds());
}  // namespace

TEST_CASE("a model set holds models of the table only") { CHECK(model_set_bounds()); }
