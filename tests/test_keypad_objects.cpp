// keypad/objects.hpp: what each object is (its value kind, and for an LED plane or a piece of an
// LED string the plane and bits it carries), and the names of the objects, the value kinds, the
// access rights and the dictionaries.
#include <doctest/doctest.h>

#include <powerkey/keypad/objects.hpp>
#include <powerkey/names.hpp>

#include "support.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace {
using namespace powerkey;
using namespace powerkey_tests;

// The value kind of the objects whose kind carries more (a plane, a piece of the LED string).
struct kind_row {
    std::string_view section;
    std::string_view frame;
    object id;
    value_kind kind;
    plane holds;
    std::uint8_t offset, width;
};
constexpr kind_row kind_rows[] = {
    {"PK1000 17: red plane", "", object::led_on_red, value_kind::led_plane, plane::red, 0, 0},
    {"PK1000 18: green plane", "", object::led_blink_green, value_kind::led_plane, plane::green, 0,
     0},
    {"MT 20 a: blue plane", "", object::led_on_blue, value_kind::led_plane, plane::blue, 0, 0},
    // PKP2600SI 17: red 1-12 and green 1-4 are bits 0..15 of the 36-bit string (stride 12),
    // green 5-12 bits 16..23, blue 1-12 bits 24..35.
    {"2600SI 17 sub 1", "", object::led_on_r1_12_g1_4, value_kind::led_part, plane::red, 0, 16},
    {"2600SI 17 sub 2", "", object::led_on_g5_12, value_kind::led_part, plane::red, 16, 8},
    {"2600SI 18 sub 3", "", object::led_blink_b1_12, value_kind::led_part, plane::red, 24, 12},
    {"MT 20 c", "", object::led_on_encoder, value_kind::ring, plane::red, 0, 0},
    {"MT 19 d", "", object::encoder2_direction_counter, value_kind::direction_counter, plane::red,
     0, 0},
    {"PK1000 31: 1001h aborts", "", object::error_register, value_kind::none, plane::red, 0, 0},
    {"PKP 13", "", object::command_module, value_kind::commands, plane::red, 0, 0},
    {"PK1000 28", "", object::consumer_heartbeat, value_kind::consumer_heartbeat, plane::red, 0, 0},
    {"PK1000 36", "", object::restore_defaults, value_kind::restore, plane::red, 0, 0},
};
constexpr bool kind_holds(const kind_row& r) {
    const auto k = info(r.id);
    return k.id == r.id && k.kind == r.kind && k.holds == r.holds && k.offset == r.offset &&
           k.width == r.width;
}
static_assert(
    powerkey_tests::all_rows_pass<first_failing(kind_rows, kind_holds), std::size(kind_rows)>);

// A value outside the enum keeps its number and has no kind and no name.
constexpr bool outside_the_enum() {
    for (const auto o : {static_cast<object>(object_count), static_cast<object>(0xFF)}) {
        const auto i = info(o);
        if (i.id != o || i.kind != value_kind::none || !i.name.empty()) return false;
    }
    return true;
}
static_assert(outside_the_enum());

// --- names ---------------------------------------------------------------------------------------

// The objects: a few pinned by name; the table has one name per object, in enum order.
struct object_name_row {
    object id;
    std::string_view name;
};
constexpr object_name_row object_name_rows[] = {
    {object::keys, "keys"},
    {object::led_on_red, "led_on_red"},
    {object::default_backlight_colour, "default_backlight_colour"},
    {object::command_module, "command_module"},
    {object::heartbeat_time, "heartbeat_time"},
    {object::restore_defaults, "restore_defaults"},
    {object::tpdo1_mapping_1, "tpdo1_mapping_1"},
    {object::led_on_r1_12_g1_4, "led_on_r1_12_g1_4"},
    {object::encoder2_direction_counter, "encoder2_direction_counter"},
    {object::analog_input_period, "analog_input_period"},
    {object::tpdo3_mapping_3, "tpdo3_mapping_3"},
};
constexpr bool objects_named() {
    for (const auto& r : object_name_rows)
        if (to_string(r.id) != r.name || from_string<object>(r.name) != std::optional(r.id) ||
            info(r.id).name != r.name)
            return false;
    const auto all = enum_values<object>();
    if (all.size() != object_count) return false;
    for (std::size_t i = 0; i < all.size(); ++i)
        if (static_cast<std::size_t>(all[i]) != i || !is_named(all[i])) return false;
    return !is_named(static_cast<object>(object_count)) && !from_string<object>("led_on_white");
}
static_assert(objects_named());

// The names come from POWERKEY_VALUE_KINDS, in enum order.
constexpr name_row value_kind_rows[] = {
    {"", 0, "number"},       {"", 1, "flag"},
    {"", 2, "brightness"},   {"", 3, "colour"},
    {"", 4, "baud"},         {"", 5, "show"},
    {"", 6, "node"},         {"", 7, "period"},
    {"", 8, "keys"},         {"", 9, "led_plane"},
    {"", 10, "led_map"},     {"", 11, "consumer_heartbeat"},
    {"", 12, "cob_id"},      {"", 13, "pdo_mapping"},
    {"", 14, "device_type"}, {"", 15, "string"},
    {"", 16, "restore"},     {"", 17, "led_part"},
    {"", 18, "ring"},        {"", 19, "direction_counter"},
    {"", 20, "none"},        {"", 21, "commands"},
};
static_assert(name_table_is<value_kind>(value_kind_rows, 22));

constexpr name_row access_rows[] = {
    {"ro", 0, "read_only"}, {"wo", 1, "write_only"}, {"rw", 2, "read_write"}};
static_assert(name_table_is<access>(access_rows, 3));

constexpr name_row dictionary_rows[] = {{"PK1000 16-49", 0, "pk1000"},
                                        {"PKP 13-32", 1, "pkp_li"},
                                        {"PKP2600SI 16-40", 2, "si_packed"},
                                        {"PKP3500-MT 19-56", 3, "si_mt"},
                                        {"si-family", 4, "si_per_colour"}};
static_assert(name_table_is<dictionary>(dictionary_rows, 5));
}  // namespace

TEST_CASE("what each object is: its kind, and the plane and bits it carries") {
    powerkey_tests::check_rows(kind_rows, kind_holds);
    CHECK(outside_the_enum());
}

TEST_CASE("the names of objects, value kinds, access rights and dictionaries") {
    CHECK(objects_named());
    CHECK(name_table_is<value_kind>(value_kind_rows, 22));
    CHECK(name_table_is<access>(access_rows, 3));
    CHECK(name_table_is<dictionary>(dictionary_rows, 5));
}
