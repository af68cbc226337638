// Every row of the model table as docs/models.md and docs/si-family.md give it (from the manuals),
// and every name a model answers to: the tool's, the manual's (any case, with or without '-',
// '_' or spaces) and the model string the keypad reports in 100Bh.
#include <doctest/doctest.h>

#include <powerkey/keypad/models.hpp>
#include <powerkey/names.hpp>

#include "support.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {
using namespace powerkey;
using powerkey_tests::first_failing;

struct info_row {
    std::string_view section;
    std::string_view frame;  // the tool's name, as the row runner prints it
    model id;
    dictionary dict;
    std::uint8_t keys, leds, planes, stride;
    std::uint32_t led_mask;
    bool brightness_pdo, encoder_leds_pdo, backlight_pdo, backlight_colour, encoders, j1939,
        replies_from_new_id, backlight_zero_is_default;
    unsigned object_planes;  // planes a 4-byte LED object holds: those that fit 32 bits
};

constexpr auto pk = dictionary::pk1000, li = dictionary::pkp_li, packed = dictionary::si_packed,
               mt = dictionary::si_mt, per = dictionary::si_per_colour;
constexpr info_row info_rows[] = {
    // docs/models.md (PK1000 sections 11-15, 23, 49; PKP sections 10-13; docs/pkp.md)
    {"PK1000 11-15, 23, 49", "pk1000", model::pk1000, pk, 10, 28, 2, 32, 0x0FFF'FFFF, true, false,
     true, true, false, true, true, false, 1},
    {"PKP 10-13 h", "pkp2200", model::pkp2200, li, 4, 4, 3, 4, 0xF, false, false, false, false,
     false, false, false, false, 3},
    {"PKP 10-13 h", "pkp2400", model::pkp2400, li, 8, 8, 3, 8, 0xFF, false, false, false, false,
     false, false, false, false, 3},
    {"docs/pkp.md", "pkp2600", model::pkp2600, li, 12, 12, 3, 12, 0xFFF, false, false, false, false,
     false, false, false, false, 2},
    // docs/si-family.md, "The family" table; PKP2600SI manual section 15 (00h = default colour)
    {"PKP2600SI 12-15", "pkp2600si", model::pkp2600si, packed, 12, 12, 3, 12, 0xFFF, true, false,
     true, true, false, true, true, true, 2},
    // PKP3500-MT: keys 1 and 11 are the encoder pushes, without LED (sections 2, 15, 17)
    {"PKP3500-MT 12-18", "pkp3500mt", model::pkp3500mt, mt, 15, 15, 3, 16, 0x7BFE, false, true,
     true, true, true, true, true, false, 2},
    {"PKP3500SI 12-15", "pkp3500si", model::pkp3500si, per, 15, 15, 3, 16, 0x7FFF, true, false,
     true, false, false, true, true, false, 2},
    {"PKP2500SI 13-15", "pkp2500si", model::pkp2500si, per, 10, 10, 3, 16, 0x3FF, true, false, true,
     false, false, true, true, false, 2},
    {"PKP-1500-LI 12-13", "pkp1500li", model::pkp1500li, per, 5, 5, 3, 8, 0x1F, false, false, true,
     false, false, true, true, false, 3},
    {"SI generic (inferred S = 8; colour: bench log)", "pkp2200si", model::pkp2200si, per, 4, 4, 3,
     8, 0xF, false, false, true, true, false, true, true, false, 3},
    {"SI generic (inferred S = 8; colour: bench log)", "pkp2300si", model::pkp2300si, per, 6, 6, 3,
     8, 0x3F, false, false, true, true, false, true, true, false, 3},
    {"SI generic (inferred S = 8; colour: bench log)", "pkp2400si", model::pkp2400si, per, 8, 8, 3,
     8, 0xFF, false, false, true, true, false, true, true, false, 3},
    // Its CANopen side inferred: the SI rule for six keys, as the PKP-2300-SI (docs/si-family.md)
    {"PKP1600SI J1939, SI generic", "pkp1600si", model::pkp1600si, per, 6, 6, 3, 8, 0x3F, false,
     false, true, true, false, true, true, false, 3},
};
static_assert(std::size(info_rows) == model_count);

constexpr bool info_holds(const info_row& r) {
    const auto i = info(r.id);
    return i && i->id == r.id && i->dictionary == r.dict && i->keys == r.keys &&
           i->leds == r.leds && i->planes == r.planes && i->stride == r.stride &&
           i->led_mask == r.led_mask && i->brightness_pdo == r.brightness_pdo &&
           i->encoder_leds_pdo == r.encoder_leds_pdo && i->backlight_pdo == r.backlight_pdo &&
           i->backlight_colour == r.backlight_colour && i->encoders == r.encoders &&
           i->j1939 == r.j1939 && i->replies_from_new_id == r.replies_from_new_id &&
           i->backlight_zero_is_default == r.backlight_zero_is_default &&
           i->object_planes() == r.object_planes && to_string(r.id) == r.frame;
}
static_assert(
    powerkey_tests::all_rows_pass<first_failing(info_rows, info_holds), std::size(info_rows)>);
static_assert(info(static_cast<model>(model_count)) == errc::value_out_of_range);
static_assert(info(static_cast<model>(0xFF)) == errc::value_out_of_range);

// --- names ---------------------------------------------------------------------------------------

struct name_row {
    std::string_view section;
    std::string_view frame;  // the text
    result<model> expected;
};
constexpr name_row name_rows[] = {
    // the tool's names
    {"tool", "pk1000", model::pk1000},
    {"tool", "pkp2200", model::pkp2200},
    {"tool", "pkp2400", model::pkp2400},
    {"tool", "pkp2600", model::pkp2600},
    {"tool", "pkp2600si", model::pkp2600si},
    {"tool", "pkp3500mt", model::pkp3500mt},
    {"tool", "pkp3500si", model::pkp3500si},
    {"tool", "pkp2500si", model::pkp2500si},
    {"tool", "pkp1500li", model::pkp1500li},
    {"tool", "pkp2200si", model::pkp2200si},
    {"tool", "pkp2300si", model::pkp2300si},
    {"tool", "pkp2400si", model::pkp2400si},
    // the manuals' names (docs/models.md, docs/si-family.md)
    {"PK1000 manual", "PK1000", model::pk1000},
    {"PKP manual", "PKP-2200-LI", model::pkp2200},
    {"PKP manual", "PKP-2400-LI", model::pkp2400},
    {"docs/pkp.md", "PKP-2600", model::pkp2600},
    {"PKP2600SI manual", "PKP-2600-SI", model::pkp2600si},
    {"PKP3500-MT manual", "PKP-3500-MT", model::pkp3500mt},
    {"PKP3500SI manual", "PKP-3500-SI", model::pkp3500si},
    {"PKP2500SI manual", "PKP-2500-SI", model::pkp2500si},
    {"PKP-1500-LI manual", "PKP-1500-LI", model::pkp1500li},
    {"SI generic pages", "PKP-2200-SI", model::pkp2200si},
    {"SI generic pages", "PKP-2300-SI", model::pkp2300si},
    {"SI generic pages", "PKP-2400-SI", model::pkp2400si},
    // (the reported strings: report_rows; every_name_reads_back parses them too)
    // case, '-', '_' and spaces ignored
    {"spelling", "pkp 2400 li", model::pkp2400},
    {"spelling", "Pkp_3500_Mt", model::pkp3500mt},
    {"spelling", "pku-2400", model::pkp2400},
    {"spelling", "-pkp2600si-", model::pkp2600si},
    // nothing
    {"no such keypad", "PKP-2700-SI", errc::value_out_of_range},
    {"a prefix", "pkp35", errc::value_out_of_range},
    {"a longer name", "pkp2600sii", errc::value_out_of_range},
    {"separators only", "- _", errc::value_out_of_range},
    {"empty", "", errc::value_out_of_range},
};
constexpr bool parses(const name_row& r) { return parse_model(r.frame) == r.expected; }
static_assert(
    powerkey_tests::all_rows_pass<first_failing(name_rows, parses), std::size(name_rows)>);

// What a keypad reports (100Bh; PKP 6100h sub 2) is matched exactly, and only where a manual
// shows it.
constexpr name_row report_rows[] = {
    {"PK1000 35", "PK1000", model::pk1000},
    {"PKP 22", "PKU2400", model::pkp2400},
    {"PKP2600SI 33", "PKP2600SI", model::pkp2600si},
    {"PKP3500-MT 39", "PKP3500MT", model::pkp3500mt},
    {"PKP3500SI manual", "PKP3500SI", model::pkp3500si},
    {"PKP-1500-LI manual", "PKP1500LI", model::pkp1500li},
    {"not what a keypad sends", "pku2400", errc::value_out_of_range},
    {"not what a keypad sends", "PKP-3500-MT", errc::value_out_of_range},
    {"not what a keypad sends", "pkp2200", errc::value_out_of_range},
    {"no manual shows it", "PKP2500SI", errc::value_out_of_range},
    {"no manual shows it", "PKP2200SI", errc::value_out_of_range},
    {"empty", "", errc::value_out_of_range},
};
constexpr bool reported(const name_row& r) { return model_from_report(r.frame) == r.expected; }
static_assert(
    powerkey_tests::all_rows_pass<first_failing(report_rows, reported), std::size(report_rows)>);

// Every name in the tables reads back to its model.
constexpr bool every_name_reads_back() {
    for (const model m : enum_values<model>()) {
        const auto n = *info(m);
        if (n.id != m || to_string(m) != n.name) return false;
        if (parse_model(n.manual) != result<model>(n.id)) return false;
        if (parse_model(to_string(n.id)) != result<model>(n.id)) return false;
        if (!n.reported().empty() && (model_from_report(n.reported()) != result<model>(n.id) ||
                                      parse_model(n.reported()) != result<model>(n.id)))
            return false;
    }
    return enum_values<model>().size() == model_count;
}
static_assert(every_name_reads_back());

// --- the LED-map and key-map rule for the SI family
// ------------------------------------------------

// PKP3500-MT 15: S = 16, keys 1 and 11 have no LED; blue 15 is bit 2 * 16 + 14 = 46.
static_assert(pack_leds(info(model::pkp3500mt).value(), leds{{1, 2}, {11, 12}, {15}}, 3) ==
              ((std::uint64_t{1} << 1) | (std::uint64_t{1} << (16 + 11)) |
               (std::uint64_t{1} << 46)));
static_assert(unpack_leds(info(model::pkp3500mt).value(), 1, 3) == errc::reserved_not_zero);
static_assert(unpack_leds(info(model::pkp3500mt).value(), std::uint64_t{1} << 46, 3).value() ==
              leds{{}, {}, {15}});
// One plane (a per-colour object) and two (a PKP-2600 6001h): the planes past them are refused.
static_assert(unpack_leds(info(model::pkp2500si).value(), 0x03FF, 1).value() ==
              leds{led_set::from_mask(0x3FF), {}, {}});
static_assert(unpack_leds(info(model::pkp2500si).value(), 0x0400, 1) == errc::reserved_not_zero);
static_assert(unpack_leds(info(model::pkp2600).value(), std::uint64_t{1} << 24, 2) ==
              errc::reserved_not_zero);
static_assert(unpack_keys(info(model::pkp3500mt).value(), 0x4000).value() == key_set{15});
static_assert(unpack_keys(info(model::pkp3500mt).value(), 0x8000) == errc::reserved_not_zero);
static_assert(unpack_keys(info(model::pkp1500li).value(), 0x20) == errc::reserved_not_zero);
}  // namespace

TEST_CASE("every row of the model table") {
    powerkey_tests::check_rows(info_rows, info_holds);
    CHECK(info(static_cast<model>(model_count)) == errc::value_out_of_range);
}

TEST_CASE("every name of every model, and what names nothing") {
    powerkey_tests::check_rows(name_rows, parses);
    powerkey_tests::check_rows(report_rows, reported);
    CHECK(every_name_reads_back());
}

TEST_CASE("the LED-map rule of the SI family at run time") {
    const auto mt_info = info(model::pkp3500mt).value();
    CHECK(pack_leds(mt_info, leds{{1, 2}, {11, 12}, {15}}, 3) ==
          ((std::uint64_t{1} << 1) | (std::uint64_t{1} << 27) | (std::uint64_t{1} << 46)));
    CHECK(unpack_leds(mt_info, 1, 3) == errc::reserved_not_zero);
    CHECK(unpack_leds(info(model::pkp2500si).value(), 0x0400, 1) == errc::reserved_not_zero);
    CHECK(unpack_leds(info(model::pkp2600).value(), std::uint64_t{1} << 24, 2) ==
          errc::reserved_not_zero);
    CHECK(unpack_keys(mt_info, 0x8000) == errc::reserved_not_zero);
}
