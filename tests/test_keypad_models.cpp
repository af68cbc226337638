// The model table and the object dictionaries as data: each keypad's keys, LEDs, planes and
// stride as the manuals give them; the names a user or a keypad gives a model; every dictionary
// row named, typed, ranged and found both ways.
#include <doctest/doctest.h>

#include <powerkey/keypad/lookup.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/names.hpp>

#include "support.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace {
using namespace powerkey;
using powerkey_tests::first_failing;

// --- the model table ------------------------------------------------------------------------

struct model_row {
    std::string_view section;
    std::string_view frame;  // unused: the row runner prints it
    model id;
    std::uint8_t keys, leds, planes, stride;
    dictionary dict;
    bool pdos_brightness_backlight, j1939, replies_from_new_id;
    unsigned object_planes;
};
constexpr model_row model_rows[] = {
    // PK1000 sections 11-13: 10 keys, 28 LEDs per colour (red and green), red in bytes 0..3,
    // green in 4..7; 400h/500h PDOs (14, 15); J1939 (49); the reply from the new id (23). Its
    // LED objects hold one plane each (2001h sub 1 red, sub 2 green, section 17).
    {"PK1000 11-15, 23, 49", "", model::pk1000, 10, 28, 2, 32, dictionary::pk1000, true, true, true,
     1},
    // PKP sections 10-12: one RGB LED per key, the planes one after the other (stride = keys).
    {"PKP-2200 10-12", "", model::pkp2200, 4, 4, 3, 4, dictionary::pkp_li, false, false, false, 3},
    {"PKP-2400 10-12", "", model::pkp2400, 8, 8, 3, 8, dictionary::pkp_li, false, false, false, 3},
    // docs/pkp.md: 12 keys, 36 bits; a 4-byte LED object holds two planes.
    {"PKP-2600 docs/pkp.md", "", model::pkp2600, 12, 12, 3, 12, dictionary::pkp_li, false, false,
     false, 2},
};

constexpr bool model_holds(const model_row& r) {
    const auto i = info(r.id);
    if (!i) return false;
    return i->id == r.id && i->keys == r.keys && i->leds == r.leds && i->planes == r.planes &&
           i->stride == r.stride && i->dictionary == r.dict &&
           i->brightness_pdo == r.pdos_brightness_backlight &&
           i->backlight_pdo == r.pdos_brightness_backlight && i->j1939 == r.j1939 &&
           i->replies_from_new_id == r.replies_from_new_id && i->object_planes() == r.object_planes;
}
static_assert(first_failing(model_rows, model_holds) == std::size(model_rows));
// The four keypads of the two manuals are rows of the table (others follow as rows of their own).
static_assert(std::size(model_rows) <= model_count);
static_assert(enum_values<model>().size() == model_count);
static_assert(info(static_cast<model>(model_count)) == errc::value_out_of_range);

// --- names ------------------------------------------------------------------------------------

struct name_row {
    std::string_view section;
    std::string_view frame;  // the text
    result<model> expected;
};
constexpr name_row name_rows[] = {
    {"tool name", "pk1000", model::pk1000},
    {"manual name", "PK1000", model::pk1000},
    {"manual name without suffix", "PKP-2400", model::pkp2400},
    {"manual name, lower case", "pkp-2400-li", model::pkp2400},
    {"underscore", "PKP_2200", model::pkp2200},
    {"tool name", "pkp2600", model::pkp2600},
    {"manual name", "PKP-2600", model::pkp2600},
    {"PKP 22: the reported model id", "PKU2400", model::pkp2400},
    {"no such keypad", "pkp9999", errc::value_out_of_range},
    {"empty", "", errc::value_out_of_range},
    {"a prefix only", "pkp", errc::value_out_of_range},
};
constexpr bool parses(const name_row& r) { return parse_model(r.frame) == r.expected; }
static_assert(first_failing(name_rows, parses) == std::size(name_rows));

// Every model's own names read back.
constexpr bool names_read_back() {
    for (const model m : enum_values<model>()) {
        if (parse_model(to_string(m)) != result<model>(m)) return false;
        if (from_string<model>(to_string(m)) != std::optional<model>(m)) return false;
    }
    for (const model m : enum_values<model>()) {
        const auto n = *info(m);
        if (parse_model(n.manual) != result<model>(m)) return false;
        if (!n.reported().empty() && model_from_report(n.reported()) != result<model>(m))
            return false;
    }
    return true;
}
static_assert(names_read_back());

// What the keypad reports is matched exactly (the reported string, not a user's spelling).
static_assert(model_from_report("PKU2400") == result<model>(model::pkp2400));
static_assert(model_from_report("PK1000") == result<model>(model::pk1000));
static_assert(model_from_report("pku2400") == errc::value_out_of_range);
static_assert(model_from_report("PKP-2400-LI") == errc::value_out_of_range);
static_assert(model_from_report("") == errc::value_out_of_range);

// --- the LED-map and key-map rule ---------------------------------------------------------------

// PK1000 12: red 1 is bit 0, green 28 is bit 59; PKP-2400: blue 3 is bit 18.
static_assert(pack_leds(info(model::pk1000).value(), leds{{1}, {28}, {}}, 2) ==
              ((std::uint64_t{1} << 59) | 1));
static_assert(pack_leds(info(model::pkp2400).value(), leds{{}, {}, {3}}, 3) ==
              (std::uint64_t{1} << 18));
static_assert(unpack_leds(info(model::pkp2600).value(), std::uint64_t{1} << 35, 3).value() ==
              leds{{}, {}, {12}});
// A bit that names no LED: PK1000 bits 28..31 (red 29..32), a PKP-2200's bit 12.
static_assert(unpack_leds(info(model::pk1000).value(), std::uint64_t{1} << 28, 2) ==
              errc::reserved_not_zero);
static_assert(unpack_leds(info(model::pkp2200).value(), std::uint64_t{1} << 12, 3) ==
              errc::reserved_not_zero);
static_assert(unpack_keys(info(model::pk1000).value(), 0x0200).value() == key_set{10});
static_assert(unpack_keys(info(model::pk1000).value(), 0x0400) == errc::reserved_not_zero);
static_assert(unpack_keys(info(model::pkp2200).value(), 0x10) == errc::reserved_not_zero);

// --- the dictionaries -------------------------------------------------------------------------

constexpr dictionary dictionaries[] = {dictionary::pk1000, dictionary::pkp_li};

// Every row's object has a kind and a name; find_row by address and by object give the row.
constexpr bool rows_agree(dictionary d) {
    for (const auto& r : rows_of(d)) {
        if (info(r.id).id != r.id) return false;
        if (info(r.id).kind == value_kind::none && r.id != object::error_register) return false;
        if (to_string(r.id).empty() || to_string(info(r.id).kind).empty()) return false;
        const auto by_address = find_row(d, r.address);
        const auto by_object = find_row(d, r.id);
        if (!by_address || !by_object) return false;
        if (by_address->id != r.id || by_object->address != r.address) return false;
        if (by_address->size != r.size || by_address->access != r.access) return false;
        if (by_object->id != by_address->id) return false;
    }
    return true;
}
static_assert(rows_agree(dictionary::pk1000));
static_assert(rows_agree(dictionary::pkp_li));

// Every writable level, colour and node row has the manual's range; the default is in range.
constexpr bool ranges_hold(dictionary d) {
    for (const auto& r : rows_of(d)) {
        if (!r.writable()) continue;
        const auto k = info(r.id).kind;
        if (k == value_kind::brightness &&
            !(r.min == 0 && r.max == 0x3F && !r.in_range(0x40) && r.in_range(r.initial)))
            return false;
        if (k == value_kind::colour &&  // 01h..09h; keep (00h) is only for the PDO
            !(r.min == 1 && r.max == 9 && !r.in_range(0) && !r.in_range(10) &&
              r.in_range(r.initial)))
            return false;
        if (k == value_kind::node && !(r.min == 1 && r.max == 0x7F && !r.in_range(0) &&
                                       !r.in_range(0x80) && r.initial == 0x15))
            return false;
        if (k == value_kind::flag && !(r.min == 0 && r.max == 1 && !r.in_range(2))) return false;
    }
    return true;
}
static_assert(ranges_hold(dictionary::pk1000));
static_assert(ranges_hold(dictionary::pkp_li));

// The same meaning has the same object in both dictionaries, at each one's address.
static_assert(find_row(dictionary::pk1000, object::led_brightness)->address ==
              canopen::sdo_address{0x2003, 1});
static_assert(find_row(dictionary::pkp_li, object::led_brightness)->address ==
              canopen::sdo_address{0x6201, 1});
static_assert(find_row(dictionary::pk1000, canopen::sdo_address{0x2013, 0})->id == object::node_id);
static_assert(find_row(dictionary::pkp_li, canopen::sdo_address{0x6500, 1})->id ==
              object::command_module);
static_assert(find_row(dictionary::pkp_li, canopen::sdo_address{0x6500, 1})->access ==
              access::write_only);
// What a dictionary lacks.
static_assert(!find_row(dictionary::pkp_li, object::protocol_j1939).has_value());
static_assert(!find_row(dictionary::pk1000, object::command_module).has_value());
static_assert(!find_row(dictionary::pk1000, canopen::sdo_address{0x6000, 0}).has_value());
static_assert(!find_row(dictionary::pk1000, canopen::sdo_address{0x2003, 7}).has_value());
static_assert(!find_row(dictionary::pk1000, static_cast<object>(object_count)).has_value());
static_assert(info(static_cast<object>(object_count)).kind == value_kind::none);

// Access and defaults pinned from the manuals.
static_assert(find_row(dictionary::pk1000, object::keys)->access == access::read_only);
static_assert(find_row(dictionary::pk1000, object::baud_rate)->initial == 0x04);  // 125 kbit/s
static_assert(find_row(dictionary::pk1000, object::backlight_colour)->initial == 0x08);  // amber
static_assert(find_row(dictionary::pk1000, object::tpdo1_transmission_type)->in_range(0xFE));
static_assert(find_row(dictionary::pk1000, object::restore_defaults)->writable());
static_assert(load_signature == 0x6461'6F6C);  // "load", little endian
}  // namespace

TEST_CASE("the model table holds what the manuals give") {
    powerkey_tests::check_rows(model_rows, model_holds);
}

TEST_CASE("models by name: tool, manual and reported names, case and separators ignored") {
    powerkey_tests::check_rows(name_rows, parses);
    CHECK(names_read_back());
    CHECK(parse_model("pkp9999") == errc::value_out_of_range);
    CHECK(parse_model("") == errc::value_out_of_range);
    CHECK(model_from_report("PKU2400") == result<model>(model::pkp2400));
}

TEST_CASE("every dictionary row: kind, name, range, and found by address and by object") {
    for (const dictionary d : dictionaries) {
        CAPTURE(to_string(d));
        CHECK(rows_agree(d));
        CHECK(ranges_hold(d));
        for (const auto& r : rows_of(d)) {
            CAPTURE(to_string(r.id));
            const auto by_address = find_row(d, r.address);
            const auto by_object = find_row(d, r.id);
            REQUIRE(by_address.has_value());
            REQUIRE(by_object.has_value());
            CHECK(by_address->id == r.id);
            CHECK(by_object->address == r.address);
            CHECK_FALSE(to_string(r.id).empty());
            CHECK_FALSE(to_string(info(r.id).kind).empty());
        }
    }
    // Every object is in at least one dictionary (of the two manuals or of a later keypad).
    for (const object o : enum_values<object>()) {
        CAPTURE(to_string(o));
        bool somewhere = false;
        for (const dictionary d : enum_values<dictionary>())
            somewhere = somewhere || find_row(d, o).has_value();
        CHECK(somewhere);
    }
    CHECK(enum_values<object>().size() == object_count);
}
