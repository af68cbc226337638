// Every name table of the keypad vocabulary, row by row: the byte each manual gives a value, the
// name the library prints for it, the aliases from_string also accepts (the other manual's
// wording), the order enum_values lists them in, and what happens to text and values that name
// nothing. One constexpr check per table, proved by a static_assert and run again under doctest
// so that coverage and the sanitizers see it (zpp_bits style).
#include <doctest/doctest.h>

#include <powerkey/powerkey.hpp>

#include "support.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace {
using namespace powerkey;

struct name_row {
    std::string_view section;  // where the value's byte comes from
    std::uint8_t byte;         // the value on the wire (or the enumerator's number)
    std::string_view name;     // what to_string prints; for an alias, what from_string accepts
    bool alias = false;        // a second name of the same value: from_string only
};

// The table of E, checked against rows written in the table's order:
//   - every row's name reads back to its value (aliases too), and a non-alias row's value prints
//     as its name and is_named;
//   - enum_values<E>() lists the non-alias rows' values, in that order, once each;
//   - `unnamed` (a value with no row) prints "" and is not named; text that names nothing (an
//     unknown name, the empty string, a name in upper case) reads back as nullopt.
template <class E, std::size_t N>
constexpr bool table_is(const name_row (&rows)[N], std::uint8_t unnamed) {
    std::size_t values = 0;
    for (const auto& r : rows) {
        const auto v = static_cast<E>(r.byte);
        if (from_string<E>(r.name) != std::optional<E>(v)) return false;
        if (r.alias) {
            if (to_string(v) == r.name) return false;
            continue;
        }
        if (to_string(v) != r.name || !is_named(v)) return false;
        const auto listed = enum_values<E>();
        if (values >= listed.size() || listed[values] != v) return false;
        ++values;
    }
    if (enum_values<E>().size() != values) return false;
    const auto u = static_cast<E>(unnamed);
    if (!to_string(u).empty() || is_named(u)) return false;
    return !from_string<E>("no_such_name") && !from_string<E>("") && !from_string<E>("RED") &&
           !from_string<E>(" red");
}

// --- keypad values (values.hpp) ------------------------------------------------------------------

// PK1000 sections 15, 19 c/d (2003h sub 3, 4): 01h..09h; the manual's "white/light blue" and
// "amber/orange" are aliases; 00h only in the backlight PDO, where it keeps the colour (15 note 2).
constexpr name_row backlight_colour_rows[] = {
    {"PK1000 15 note 2", 0x00, "keep"},
    {"PK1000 19 c", 0x01, "red"},
    {"PK1000 19 c", 0x02, "green"},
    {"PK1000 19 c", 0x03, "blue"},
    {"PK1000 19 c", 0x04, "yellow"},
    {"PK1000 19 c", 0x05, "cyan"},
    {"PK1000 19 c", 0x06, "violet"},
    {"PKP 13 c (white)", 0x07, "white"},
    {"PKP 13 c (amber)", 0x08, "amber"},
    {"PK1000 19 c (yellow/green)", 0x09, "yellow_green"},
    {"PK1000 19 c white/light blue", 0x07, "white_light_blue", true},
    {"PK1000 19 c amber/orange", 0x08, "amber_orange", true},
};
static_assert(table_is<backlight_colour>(backlight_colour_rows, 0x0A));

// PK1000 section 20 (2010h): the codes and the bit rate each gives; 01h and 05h are reserved and
// force 125k. The "1000k" .. "20k" spellings are the manual's, accepted as aliases.
constexpr name_row baud_rate_rows[] = {
    {"PK1000 20", 0x00, "kbit_1000"},   {"PK1000 20", 0x02, "kbit_500"},
    {"PK1000 20", 0x03, "kbit_250"},    {"PK1000 20", 0x04, "kbit_125"},
    {"PK1000 20", 0x06, "kbit_50"},     {"PK1000 20", 0x07, "kbit_20"},
    {"PK1000 20", 0x01, "reserved_1"},  {"PK1000 20", 0x05, "reserved_5"},
    {"PK1000 20", 0x00, "1000k", true}, {"PK1000 20", 0x02, "500k", true},
    {"PK1000 20", 0x03, "250k", true},  {"PK1000 20", 0x04, "125k", true},
    {"PK1000 20", 0x06, "50k", true},   {"PK1000 20", 0x07, "20k", true},
};
static_assert(table_is<baud_rate>(baud_rate_rows, 0x08));

struct rate_row {
    std::uint8_t code;
    std::uint32_t bits_per_second;
};
// PK1000 section 20: "01h Reserved (force to 125k)", "05h Reserved (force to 125k)".
constexpr rate_row rate_rows[] = {{0x00, 1'000'000}, {0x01, 125'000}, {0x02, 500'000},
                                  {0x03, 250'000},   {0x04, 125'000}, {0x05, 125'000},
                                  {0x06, 50'000},    {0x07, 20'000}};
constexpr bool rates_hold() {
    for (const auto& r : rate_rows)
        if (bits_per_second(static_cast<baud_rate>(r.code)) != r.bits_per_second) return false;
    // A code outside the table: the keypad's fallback, 125k.
    return bits_per_second(static_cast<baud_rate>(0x08)) == 125'000 &&
           bits_per_second(static_cast<baud_rate>(0xFF)) == 125'000;
}
static_assert(rates_hold());

// PK1000 section 24 (2014h): 00h disable, 01h complete show, 02h fast flash; the PKP manual's
// command 50h calls the last "Amber fast flash" (PKP 13 m).
constexpr name_row startup_show_rows[] = {
    {"PK1000 24", 0x00, "disabled"},
    {"PK1000 24", 0x01, "complete"},
    {"PK1000 24", 0x02, "fast_flash"},
    {"PKP 13 m", 0x02, "amber_fast_flash", true},
};
static_assert(table_is<startup_show>(startup_show_rows, 0x03));

// PKP section 13 a, byte 6: 00h off, 01h..09h red/green/blue on, blink, alternate blink, 0Ah
// red/green, 0Ch amber/red, 0Eh green/amber blink (0Bh and 0Dh are not states).
constexpr name_row led_state_rows[] = {
    {"PKP 13 a", 0x00, "off"},
    {"PKP 13 a", 0x01, "red_on"},
    {"PKP 13 a", 0x02, "red_blink"},
    {"PKP 13 a", 0x03, "red_alternate_blink"},
    {"PKP 13 a", 0x04, "green_on"},
    {"PKP 13 a", 0x05, "green_blink"},
    {"PKP 13 a", 0x06, "green_alternate_blink"},
    {"PKP 13 a", 0x07, "blue_on"},
    {"PKP 13 a", 0x08, "blue_blink"},
    {"PKP 13 a", 0x09, "blue_alternate_blink"},
    {"PKP 13 a", 0x0A, "red_green_blink"},
    {"PKP 13 a", 0x0C, "amber_red_blink"},
    {"PKP 13 a", 0x0E, "green_amber_blink"},
};
static_assert(table_is<led_state>(led_state_rows, 0x0B));
static_assert(!is_named(static_cast<led_state>(0x0D)) && !is_named(static_cast<led_state>(0x0F)));

// The planes of an LED map in the one LED-map rule (models.hpp): red 0, green 1, blue 2.
constexpr name_row plane_rows[] = {
    {"PK1000 12", 0, "red"}, {"PK1000 12", 1, "green"}, {"PKP 11", 2, "blue"}};
static_assert(table_is<plane>(plane_rows, 3));

// The colours of one key's LEDs (PKP sections 11, 12: amber = red + green, magenta = red + blue,
// cyan = green + blue, white = all three).
constexpr name_row colour_rows[] = {
    {"PKP 11", 0, "off"},   {"PKP 11", 1, "red"},  {"PKP 11", 2, "green"},   {"PKP 11", 3, "blue"},
    {"PKP 11", 4, "amber"}, {"PKP 11", 5, "cyan"}, {"PKP 11", 6, "magenta"}, {"PKP 11", 7, "white"},
};
static_assert(table_is<colour>(colour_rows, 8));

// PK1000 sections 12, 13; PKP sections 12, 16: on, blink, and on + blink = alternate blink.
constexpr name_row led_mode_rows[] = {{"PK1000 12", 0, "off"},
                                      {"PK1000 12", 1, "on"},
                                      {"PK1000 13", 2, "blink"},
                                      {"PK1000 13", 3, "alternate_blink"}};
static_assert(table_is<led_mode>(led_mode_rows, 4));

// --- the command module (commands.hpp) -----------------------------------------------------------

// PKP section 13 a-m: the command byte (byte 4) of each command.
constexpr name_row command_code_rows[] = {
    {"PKP 13 a", 0x01, "set_led_state"},
    {"PKP 13 b", 0x02, "set_led_brightness"},
    {"PKP 13 b", 0x03, "set_backlight_level"},
    {"PKP 13 c", 0x04, "set_backlight_colour"},
    {"PKP 13 d", 0x10, "set_active_on_startup"},
    {"PKP 13 e", 0x11, "set_baud_rate"},
    {"PKP 13 f", 0x12, "set_periodic_transmission"},
    {"PKP 13 g", 0x13, "set_boot_up"},
    {"PKP 13 m", 0x50, "set_startup_show"},
    {"PKP 13 h", 0x70, "set_node_id"},
    {"PKP 13 l", 0x7A, "set_demo_mode"},
    {"PKP 13 j", 0x7B, "set_default_backlight_level"},
    {"PKP 13 i", 0x7C, "set_default_led_brightness"},
    {"PKP 13 k", 0x7D, "set_default_backlight_colour"},
};
static_assert(table_is<command_code>(command_code_rows, 0x00));
static_assert(!is_named(static_cast<command_code>(0x05)) &&
              !is_named(static_cast<command_code>(0x7E)));

// --- the model table and the dictionaries (models.hpp, objects.hpp) ------------------------------

constexpr name_row model_rows[] = {
    {"PK1000", 0, "pk1000"},
    {"PKP-2200-LI", 1, "pkp2200"},
    {"PKP-2400-LI", 2, "pkp2400"},
    {"docs/pkp.md", 3, "pkp2600"},
    {"PKP2600SI", 4, "pkp2600si"},
    {"PKP3500-MT", 5, "pkp3500mt"},
    {"si-family", 6, "pkp3500si"},
    {"si-family", 7, "pkp2500si"},
    {"si-family", 8, "pkp1500li"},
    {"si-family", 9, "pkp2200si"},
    {"si-family", 10, "pkp2300si"},
    {"si-family", 11, "pkp2400si"},
    {"PKP1600SI J1939", 12, "pkp1600si"},
};
static_assert(table_is<model>(model_rows, 13));

constexpr name_row dictionary_rows[] = {{"PK1000 16-49", 0, "pk1000"},
                                        {"PKP 13-32", 1, "pkp_li"},
                                        {"PKP2600SI 16-40", 2, "si_packed"},
                                        {"PKP3500-MT 19-56", 3, "si_mt"},
                                        {"si-family", 4, "si_per_colour"}};
static_assert(table_is<dictionary>(dictionary_rows, 5));

constexpr name_row access_rows[] = {
    {"ro", 0, "read_only"}, {"wo", 1, "write_only"}, {"rw", 2, "read_write"}};
static_assert(table_is<access>(access_rows, 3));

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
static_assert(table_is<value_kind>(value_kind_rows, 22));

// The objects: a few pinned by name (the table has one name per object, in enum order).
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
        if (to_string(r.id) != r.name || from_string<object>(r.name) != std::optional(r.id))
            return false;
    const auto all = enum_values<object>();
    if (all.size() != object_count) return false;
    for (std::size_t i = 0; i < all.size(); ++i)
        if (static_cast<std::size_t>(all[i]) != i || !is_named(all[i])) return false;
    return !is_named(static_cast<object>(object_count)) && !from_string<object>("led_on_white");
}
static_assert(objects_named());

// --- errors and the session (error.hpp, session.hpp) ---------------------------------------------

// docs/errors.md: the codes, numbered from 1 (0 is no error and has no name).
constexpr name_row errc_rows[] = {
    {"errors.md", 1, "wrong_id_format"},   {"errors.md", 2, "wrong_id"},
    {"errors.md", 3, "wrong_length"},      {"errors.md", 4, "unknown_command"},
    {"errors.md", 5, "index_mismatch"},    {"errors.md", 6, "value_out_of_range"},
    {"errors.md", 7, "reserved_not_zero"}, {"errors.md", 8, "toggle_error"},
    {"errors.md", 9, "size_mismatch"},     {"errors.md", 10, "buffer_too_small"},
    {"errors.md", 11, "sdo_aborted"},      {"errors.md", 12, "unexpected_frame"},
    {"errors.md", 13, "syntax_error"},     {"errors.md", 14, "unknown_object"},
    {"errors.md", 15, "reserved_not_ff"},  {"errors.md", 16, "undocumented"},
};
static_assert(table_is<errc>(errc_rows, 0));
static_assert(!is_named(static_cast<errc>(17)));

constexpr name_row bus_protocol_rows[] = {{"PK1000 49", 0, "canopen"}, {"PK1000 49", 1, "j1939"}};
static_assert(table_is<bus_protocol>(bus_protocol_rows, 2));

constexpr name_row sdo_pairing_rows[] = {
    {"session.hpp", 0, "none"},
    {"session.hpp", 1, "request"},
    {"session.hpp", 2, "reply"},
    {"session.hpp", 3, "unanswered"},
};
static_assert(table_is<sdo_pairing>(sdo_pairing_rows, 4));

// --- CiA 301 (canopen/)
// ----------------------------------------------------------------------------

// PK1000 sections 4-7 (NMT byte 0), 00h the old software's stop (section 7).
constexpr name_row nmt_command_rows[] = {
    {"PK1000 4", 0x01, "start"},
    {"PK1000 7", 0x02, "stop"},
    {"PK1000 5", 0x80, "pre_operational"},
    {"PK1000 6", 0x81, "reset_node"},
    {"CiA 301", 0x82, "reset_communication"},
    {"PK1000 7", 0x00, "legacy_stop"},
};
static_assert(table_is<canopen::nmt_command>(nmt_command_rows, 0x03));

// PK1000 sections 8, 29: boot-up 00h, pre-operational 7Fh; CiA 301: stopped 04h, operational 05h.
constexpr name_row nmt_state_rows[] = {{"PK1000 8", 0x00, "boot_up"},
                                       {"CiA 301", 0x04, "stopped"},
                                       {"CiA 301", 0x05, "operational"},
                                       {"PK1000 29", 0x7F, "pre_operational"}};
static_assert(table_is<canopen::nmt_state>(nmt_state_rows, 0x01));
}  // namespace

TEST_CASE("the name tables of the keypad values, row by row, with their aliases") {
    CHECK(table_is<backlight_colour>(backlight_colour_rows, 0x0A));
    CHECK(table_is<baud_rate>(baud_rate_rows, 0x08));
    CHECK(table_is<startup_show>(startup_show_rows, 0x03));
    CHECK(table_is<led_state>(led_state_rows, 0x0B));
    CHECK(table_is<plane>(plane_rows, 3));
    CHECK(table_is<colour>(colour_rows, 8));
    CHECK(table_is<led_mode>(led_mode_rows, 4));
    CHECK(table_is<command_code>(command_code_rows, 0x00));
    // The alias is accepted, never printed.
    CHECK(to_string(*from_string<backlight_colour>("white_light_blue")) == "white");
    CHECK(to_string(*from_string<baud_rate>("250k")) == "kbit_250");
    CHECK(to_string(*from_string<startup_show>("amber_fast_flash")) == "fast_flash");
}

TEST_CASE("bits per second of every PK1000 baud-rate code, reserved codes forced to 125k") {
    CHECK(rates_hold());
    for (const auto& r : rate_rows) {
        CAPTURE(r.code);
        CHECK(bits_per_second(static_cast<baud_rate>(r.code)) == r.bits_per_second);
    }
}

TEST_CASE("the name tables of models, dictionaries, objects and value kinds") {
    CHECK(table_is<model>(model_rows, 13));
    CHECK(table_is<dictionary>(dictionary_rows, 5));
    CHECK(table_is<access>(access_rows, 3));
    CHECK(table_is<value_kind>(value_kind_rows, 22));
    CHECK(objects_named());
    for (const auto& r : object_name_rows) {
        CAPTURE(std::string(r.name));
        CHECK(to_string(r.id) == r.name);
    }
}

TEST_CASE("the name tables of errors, the session and CiA 301") {
    CHECK(table_is<errc>(errc_rows, 0));
    CHECK(table_is<bus_protocol>(bus_protocol_rows, 2));
    CHECK(table_is<sdo_pairing>(sdo_pairing_rows, 4));
    CHECK(table_is<canopen::nmt_command>(nmt_command_rows, 0x03));
    CHECK(table_is<canopen::nmt_state>(nmt_state_rows, 0x01));
}
