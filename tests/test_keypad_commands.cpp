// keypad/commands.hpp: the command module of PKP section 13 (6500h sub 1): every command byte
// and its parameters, no other byte, the fields each command shows, and the names of the
// command codes.
#include <doctest/doctest.h>

#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/commands.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/names.hpp>

#include "support.hpp"

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

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

// --- every parameter byte of every command, and every reserved bit on its own ----------------
// Walked from the command table for every model with the command module: each command with each
// of its parameters at every byte 00h..FFh (the other at its lowest valid byte), accepted exactly
// when the manual's range for the parameter's kind holds (PKP 13 a-m, below), else
// value_out_of_range; each bit of byte 7, and of byte 6 of a one-parameter command, alone:
// reserved_not_zero; every command byte no row has: unknown_command; a size other than 4 bytes:
// size_mismatch.
namespace {
// The manual's range of a parameter's byte on a keypad with `keys` keys.
constexpr bool param_accepts(command_param p, unsigned b, unsigned keys) {
    switch (p) {
        case command_param::none: return b == 0;
        case command_param::key: return b >= 1 && b <= keys;   // 13 a: key 1..N
        case command_param::state:                             // 13 a: TABLE of states
            return b <= 0x0A || b == 0x0C || b == 0x0E;        //   (0Bh, 0Dh unused)
        case command_param::brightness: return b <= 0x3F;      // 13 b, i, j
        case command_param::colour: return b >= 1 && b <= 9;   // 13 c, k
        case command_param::flag: return b <= 1;               // 13 d, f, g, l
        case command_param::baud: return b <= 2;               // 13 e: 125k, 250k, 500k
        case command_param::period_10ms: return true;          // 13 f: 00h..FFh x 10 ms
        case command_param::node: return b >= 1 && b <= 0x7F;  // 13 h
        case command_param::show: return b >= 1 && b <= 3;     // 13 m
    }
    return false;
}
constexpr unsigned lowest_valid(command_param p, unsigned keys) {
    for (unsigned b = 0; b < 0x100; ++b)
        if (param_accepts(p, b, keys)) return b;
    return 0;
}
constexpr canopen::node_id command_node = canopen::default_node_id;
result<message> command_frame(model m, std::uint8_t size, unsigned code, unsigned p1, unsigned p2,
                              unsigned b7) {
    const auto row = find_row(info(m)->dictionary, object::command_module);
    REQUIRE(row.has_value());
    return decode(powerkey_tests::expedited_frame(command_node, row->address, size,
                                                  code | p1 << 8 | p2 << 16 | b7 << 24, true),
                  command_node, m);
}
}  // namespace

TEST_CASE("every parameter byte of every command and every reserved bit, in every model") {
    std::size_t models = 0;
    for (const model m : enum_values<model>()) {
        if (!find_row(info(m)->dictionary, object::command_module)) continue;
        ++models;
        const unsigned keys = info(m)->keys;
        CAPTURE(std::string(to_string(m)));
        for (unsigned code = 0; code < 0x100; ++code) {
            CAPTURE(code);
            const auto row = find_command(static_cast<std::uint8_t>(code));
            if (!row) {
                CHECK(command_frame(m, 4, code, 0, 0, 0) == errc::unknown_command);
                continue;
            }
            const unsigned v1 = lowest_valid(row->p1, keys), v2 = lowest_valid(row->p2, keys);
            for (unsigned b = 0; b < 0x100; ++b) {
                CAPTURE(b);
                const auto first = command_frame(m, 4, code, b, v2, 0);
                if (param_accepts(row->p1, b, keys)) {
                    REQUIRE(first.has_value());
                    const auto* c = std::get_if<command>(&*first);
                    REQUIRE(c != nullptr);
                    CHECK(static_cast<unsigned>(c->code) == code);
                    CHECK(encode(command_node, m, *first) ==
                          powerkey_tests::expedited_frame(
                              command_node,
                              find_row(info(m)->dictionary, object::command_module)->address, 4,
                              code | b << 8 | v2 << 16, true));
                } else {
                    CHECK(first == errc::value_out_of_range);
                }
                const auto second = command_frame(m, 4, code, v1, b, 0);
                if (row->p2 == command_param::none)
                    CHECK(second == (b == 0 ? result<message>(*command_frame(m, 4, code, v1, 0, 0))
                                            : result<message>(errc::reserved_not_zero)));
                else if (param_accepts(row->p2, b, keys))
                    CHECK(second.has_value());
                else
                    CHECK(second == errc::value_out_of_range);
            }
            for (unsigned bit = 0; bit < 8; ++bit) {
                CAPTURE(bit);
                CHECK(command_frame(m, 4, code, v1, v2, 1u << bit) == errc::reserved_not_zero);
            }
            for (const std::uint8_t size : {std::uint8_t{1}, std::uint8_t{2}})
                CHECK(command_frame(m, size, code, 0, 0, 0) == errc::size_mismatch);
        }
    }
    CHECK(models >= 3);  // the PKP-2200, 2400 and 2600-LI
}

// codec.hpp's own check of a command compares its members as one word (detail::command_word)
// outside the bytes its parameters own (detail::command_word_bits): the two lists must agree.
// For the parameters of every command: every byte read_param accepts moves command_word within
// the parameter's bits alone (one byte), some byte moves it, and `enabled` (flag, tested apart)
// and none move nothing.
TEST_CASE("each parameter's byte in the command word is the one command_word_bits names") {
    const auto keypad = detail::layout_of(*info(model::pkp2400));
    const std::uint64_t defaults = detail::command_word(command{});
    std::size_t params = 0;
    for (const command_row& row : detail::command_table)
        for (const command_param p : {row.p1, row.p2}) {
            ++params;
            CAPTURE(static_cast<unsigned>(p));
            const std::uint64_t bits = detail::command_word_bits(p);
            std::uint64_t moved = 0;
            for (unsigned b = 0; b < 0x100; ++b) {
                command c{};
                if (detail::read_param(keypad, p, static_cast<std::uint8_t>(b), c) != errc{})
                    continue;
                const std::uint64_t diff = detail::command_word(c) ^ defaults;
                CAPTURE(b);
                CHECK((diff & ~bits) == 0);
                moved |= diff;
            }
            const bool outside = p == command_param::none || p == command_param::flag;
            CHECK(bits == (outside ? 0 : 0xFFull << (std::countr_zero(bits) & ~7)));
            CHECK((moved != 0) == !outside);
        }
    CHECK(params == 2 * std::size(detail::command_table));
}

// The command module's own codes of the shared values: PKP 13 e (baud rate: 00h 125k, 01h 250k,
// 02h 500k) and 13 m (start-up show: 01h complete, 02h fast flash, 03h disabled), each both ways.
TEST_CASE("the command module's codes of the baud rate and the start-up show, both ways") {
    const auto row = find_row(info(model::pkp2400)->dictionary, object::command_module);
    REQUIRE(row.has_value());
    const baud_rate bauds[] = {baud_rate::kbit_125, baud_rate::kbit_250, baud_rate::kbit_500};
    const startup_show shows[] = {startup_show::complete, startup_show::fast_flash,
                                  startup_show::disabled};
    for (unsigned b = 0; b < 3; ++b) {
        CAPTURE(b);
        const auto baud = command_frame(model::pkp2400, 4, 0x11, b, 0, 0);
        REQUIRE(baud.has_value());
        CHECK(std::get<command>(*baud).baud == bauds[b]);
        const auto show = command_frame(model::pkp2400, 4, 0x50, b + 1, 0, 0);
        REQUIRE(show.has_value());
        CHECK(std::get<command>(*show).show == shows[b]);
        CHECK(encode(command_node, model::pkp2400, *baud) ==
              powerkey_tests::expedited_frame(command_node, row->address, 4, 0x11 | b << 8, true));
        CHECK(encode(command_node, model::pkp2400, *show) ==
              powerkey_tests::expedited_frame(command_node, row->address, 4, 0x50 | (b + 1) << 8,
                                              true));
    }
}
