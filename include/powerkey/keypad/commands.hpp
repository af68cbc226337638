// powerkey: the PKP command module, object 6500h sub 1 (PKP manual section 13), as data: one row
// per command names its parameters (23 00 65 01 | cc p1 p2 00, docs/pkp.md); one message type,
// `command`, carries any of them.
#ifndef POWERKEY_KEYPAD_COMMANDS_HPP
#define POWERKEY_KEYPAD_COMMANDS_HPP

#include <powerkey/canopen/node_id.hpp>
#include <powerkey/detail/lookup.hpp>
#include <powerkey/detail/message.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/frame_form.hpp>
#include <powerkey/keypad/values.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace powerkey {

// The command byte (byte 4) of each command, PKP section 13 a-m.
// clang-format off
#define POWERKEY_COMMAND_CODE_LIST(X) \
    X(set_led_state, 0x01)  /* 13 a: one key LED */ \
    X(set_led_brightness, 0x02)  /* 13 b */ \
    X(set_backlight_level, 0x03)  /* 13 b */ \
    X(set_backlight_colour, 0x04)  /* 13 c */ \
    X(set_active_on_startup, 0x10)  /* 13 d */ \
    X(set_baud_rate, 0x11)  /* 13 e */ \
    X(set_periodic_transmission, 0x12)  /* 13 f: key-state PDO every period_10ms x 10 ms */ \
    X(set_boot_up, 0x13)  /* 13 g: send the boot-up message at power on */ \
    X(set_startup_show, 0x50)  /* 13 m */ \
    X(set_node_id, 0x70)  /* 13 h: the reply comes from the old id */ \
    X(set_demo_mode, 0x7A)  /* 13 l: after the next power cycle */ \
    X(set_default_backlight_level, 0x7B)  /* 13 j */ \
    X(set_default_led_brightness, 0x7C)  /* 13 i */ \
    X(set_default_backlight_colour, 0x7D)  /* 13 k */
// clang-format on
enum class command_code : std::uint8_t { POWERKEY_COMMAND_CODE_LIST(POWERKEY_DETAIL_ENUMERATOR) };

// What a parameter byte holds, and so which field of `command` carries it.
enum class command_param : std::uint8_t {
    none,         // 00h
    key,          // "key": 1..the model's keys
    state,        // "state": led_state
    brightness,   // "level": 00h..3Fh
    colour,       // "colour": backlight_colour 01h..09h
    flag,         // "enabled": 00h or 01h
    baud,         // "baud_rate": 00h 125k, 01h 250k, 02h 500k
    period_10ms,  // "period_10ms": 00h..FFh, units of 10 ms
    node,         // "node_id": 01h..7Fh (E-PKP-3)
    show,         // "startup_show": 01h complete, 02h fast flash, 03h disabled
};

struct command_row {
    command_code code;
    command_param p1;  // byte 5
    command_param p2;  // byte 6
};

namespace detail {
using cc = command_code;
using cp = command_param;
inline constexpr command_row command_table[] = {
    {cc::set_led_state, cp::key, cp::state},
    {cc::set_led_brightness, cp::brightness, cp::none},
    {cc::set_backlight_level, cp::brightness, cp::none},
    {cc::set_backlight_colour, cp::colour, cp::none},
    {cc::set_active_on_startup, cp::flag, cp::none},
    {cc::set_baud_rate, cp::baud, cp::none},
    {cc::set_periodic_transmission, cp::flag, cp::period_10ms},
    {cc::set_boot_up, cp::flag, cp::none},
    {cc::set_startup_show, cp::show, cp::none},
    {cc::set_node_id, cp::node, cp::none},
    {cc::set_demo_mode, cp::flag, cp::none},
    {cc::set_default_backlight_level, cp::brightness, cp::none},
    {cc::set_default_led_brightness, cp::brightness, cp::none},
    {cc::set_default_backlight_colour, cp::colour, cp::none},
};

// The command module's own codes for the shared baud_rate and startup_show values.
inline constexpr baud_rate command_bauds[] = {baud_rate::kbit_125, baud_rate::kbit_250,
                                              baud_rate::kbit_500};
inline constexpr startup_show command_shows[] = {startup_show::complete, startup_show::fast_flash,
                                                 startup_show::disabled};
inline constexpr auto command_index =
    index_by_code<0x80>(command_table, [](const auto& row) { return row.code; });
}  // namespace detail

// The row of a command byte; nullopt for a byte no command has.
[[nodiscard]] constexpr std::optional<command_row> find_command(std::uint8_t code) noexcept {
    if (code >= detail::command_index.size() || detail::command_index[code] == 0)
        return std::nullopt;
    return detail::command_table[detail::command_index[code] - 1u];
}

// One command: `code` and the members its row carries, the rest at defaults (docs/decoder.md).
struct command {
    POWERKEY_DETAIL_MESSAGE(command);
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("command", self.code);
        const auto row = find_command(static_cast<std::uint8_t>(self.code));
        if (!row) return;
        for (const auto p : {row->p1, row->p2}) {
            switch (p) {
                case command_param::key: f("key", self.key); break;
                case command_param::state: f("state", self.state); break;
                case command_param::brightness: f("level", self.level); break;
                case command_param::colour: f("colour", self.colour); break;
                case command_param::flag: f("enabled", self.enabled); break;
                case command_param::baud: f("baud_rate", self.baud); break;
                case command_param::period_10ms: f("period_10ms", self.period_10ms); break;
                case command_param::node: f("node_id", self.node_id); break;
                case command_param::show: f("startup_show", self.show); break;
                case command_param::none: break;
            }
        }
    }
    command_code code = command_code::set_led_state;
    std::uint8_t key = 0;  // set_led_state: the key, 1..the model's keys
    led_state state = led_state::off;
    powerkey::level level = 0;
    backlight_colour colour = backlight_colour::keep;
    bool enabled = false;
    baud_rate baud = baud_rate::kbit_125;
    std::uint8_t period_10ms = 0;
    canopen::node_id node_id = canopen::default_node_id;
    startup_show show = startup_show::complete;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

}  // namespace powerkey

POWERKEY_DETAIL_ENUM_NAMES(powerkey::command_code, POWERKEY_COMMAND_CODE_LIST);

#endif  // POWERKEY_KEYPAD_COMMANDS_HPP
