// keypad/commands.hpp: the command module of PKP section 13 (6500h sub 1): every command byte
// and its parameters, no other byte, the fields each command shows, and the names of the
// command codes.
#include <doctest/doctest.h>

#include <powerkey/keypad/commands.hpp>
#include <powerkey/names.hpp>

#include "support.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>

namespace {
using namespace powerkey;
using namespace powerkey_tests;

struct command_table_row {
    std::string_view section;
    std::string_view frame;  // unused
    std::uint8_t code;
    command_param p1, p2;
};
using cp = command_param;
constexpr command_table_row command_table_rows[] = {
    {"PKP 13 a: key, state", "", 0x01, cp::key, cp::state},
    {"PKP 13 b: LED level", "", 0x02, cp::brightness, cp::none},
    {"PKP 13 b: backlight level", "", 0x03, cp::brightness, cp::none},
    {"PKP 13 c: colour", "", 0x04, cp::colour, cp::none},
    {"PKP 13 d: on/off", "", 0x10, cp::flag, cp::none},
    {"PKP 13 e: baud", "", 0x11, cp::baud, cp::none},
    {"PKP 13 f: on/off, period", "", 0x12, cp::flag, cp::period_10ms},
    {"PKP 13 g: on/off", "", 0x13, cp::flag, cp::none},
    {"PKP 13 m: show", "", 0x50, cp::show, cp::none},
    {"PKP 13 h: node", "", 0x70, cp::node, cp::none},
    {"PKP 13 l: on/off", "", 0x7A, cp::flag, cp::none},
    {"PKP 13 j: level", "", 0x7B, cp::brightness, cp::none},
    {"PKP 13 i: level", "", 0x7C, cp::brightness, cp::none},
    {"PKP 13 k: colour", "", 0x7D, cp::colour, cp::none},
};
constexpr bool command_found(const command_table_row& r) {
    const auto row = find_command(r.code);
    return row && static_cast<std::uint8_t>(row->code) == r.code && row->p1 == r.p1 &&
           row->p2 == r.p2;
}
static_assert(powerkey_tests::all_rows_pass<first_failing(command_table_rows, command_found),
                                            std::size(command_table_rows)>);
// Bytes no command has: below, between and above the codes, and past the index (80h..FFh).
constexpr bool no_other_command() {
    for (unsigned c = 0; c < 256; ++c) {
        bool listed = false;
        for (const auto& r : command_table_rows) listed = listed || r.code == c;
        if (find_command(static_cast<std::uint8_t>(c)).has_value() != listed) return false;
    }
    return true;
}
static_assert(no_other_command());

// The fields each command shows: its code, then its row's parameters by name.
struct command_fields_row {
    std::string_view section;
    std::string_view frame;  // unused
    command_code code;
    std::string_view names;  // space-separated, after "command"
};
constexpr command_fields_row command_fields_rows[] = {
    {"PKP 13 a", "", command_code::set_led_state, "key state"},
    {"PKP 13 b", "", command_code::set_led_brightness, "level"},
    {"PKP 13 c", "", command_code::set_backlight_colour, "colour"},
    {"PKP 13 e", "", command_code::set_baud_rate, "baud_rate"},
    {"PKP 13 f", "", command_code::set_periodic_transmission, "enabled period_10ms"},
    {"PKP 13 h", "", command_code::set_node_id, "node_id"},
    {"PKP 13 m", "", command_code::set_startup_show, "startup_show"},
    {"no such command", "", static_cast<command_code>(0x99), ""},
};
constexpr bool shows_fields(const command_fields_row& r) {
    command c;
    c.code = r.code;
    std::array<std::string_view, 4> seen{};
    std::size_t n = 0;
    command::fields(std::as_const(c), [&](std::string_view name, const auto&) {
        if (n < seen.size()) seen[n] = name;
        ++n;
    });
    if (n == 0 || seen[0] != "command") return false;
    std::string_view rest = r.names;
    for (std::size_t i = 1; i < n; ++i) {
        const auto end = rest.find(' ');
        if (rest.substr(0, end) != seen[i]) return false;
        rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end + 1);
    }
    return rest.empty();
}
static_assert(powerkey_tests::all_rows_pass<first_failing(command_fields_rows, shows_fields),
                                            std::size(command_fields_rows)>);

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
static_assert(name_table_is<command_code>(command_code_rows, 0x00));
static_assert(!is_named(static_cast<command_code>(0x05)) &&
              !is_named(static_cast<command_code>(0x7E)));
}  // namespace

TEST_CASE("the command table: every command byte of PKP section 13 and no other") {
    powerkey_tests::check_rows(command_table_rows, command_found);
    powerkey_tests::check_rows(command_fields_rows, shows_fields);
    CHECK(no_other_command());
}

TEST_CASE("the names of the command codes") {
    CHECK(name_table_is<command_code>(command_code_rows, 0x00));
}
