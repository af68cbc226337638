// powerkey PKP: the command module, object 6500h sub 1 (PKP manual section 13). Every command is
// an expedited 4-byte download to 600h + node:
//   23 00 65 01 | cc p1 p2 00      cc command, p1 p2 its parameters (00h where unused)
// and the keypad answers 60 00 65 01 00 00 00 00 from 580h + node (objects.hpp, write_response).
#ifndef POWERKEY_PKP_COMMAND_HPP
#define POWERKEY_PKP_COMMAND_HPP

#include <powerkey/bounded.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/pkp/model.hpp>
#include <powerkey/result.hpp>

#include <array>
#include <cstdint>
#include <string_view>
#include <variant>

namespace powerkey::pkp {

inline constexpr canopen::sdo_address command_address{0x6500, 0x01};

struct level_tag;
// A brightness level, 00h..3Fh (00h minimum or off, 3Fh = 100 %); commands 02h, 03h, 7Bh, 7Ch and
// object 6201h.
using level = bounded<level_tag, std::uint8_t, 0, 0x3F>;

// Command 01h byte 6: what one key LED does.
enum class led_state : std::uint8_t {
    off = 0x00,
    red_on = 0x01,
    red_blink = 0x02,
    red_alternate_blink = 0x03,
    green_on = 0x04,
    green_blink = 0x05,
    green_alternate_blink = 0x06,
    blue_on = 0x07,
    blue_blink = 0x08,
    blue_alternate_blink = 0x09,
    red_green_blink = 0x0A,
    amber_red_blink = 0x0C,
    green_amber_blink = 0x0E,
};

[[nodiscard]] constexpr std::string_view to_string(led_state s) noexcept {
    switch (s) {
        case led_state::off: return "off";
        case led_state::red_on: return "red_on";
        case led_state::red_blink: return "red_blink";
        case led_state::red_alternate_blink: return "red_alternate_blink";
        case led_state::green_on: return "green_on";
        case led_state::green_blink: return "green_blink";
        case led_state::green_alternate_blink: return "green_alternate_blink";
        case led_state::blue_on: return "blue_on";
        case led_state::blue_blink: return "blue_blink";
        case led_state::blue_alternate_blink: return "blue_alternate_blink";
        case led_state::red_green_blink: return "red_green_blink";
        case led_state::amber_red_blink: return "amber_red_blink";
        case led_state::green_amber_blink: return "green_amber_blink";
    }
    return "unknown";
}

// Commands 04h and 7Dh byte 5: the backlight colour.
enum class backlight_colour : std::uint8_t {
    red = 0x01,
    green = 0x02,
    blue = 0x03,
    yellow = 0x04,
    cyan = 0x05,
    violet = 0x06,
    white = 0x07,
    amber = 0x08,  // "amber/orange"
    yellow_green = 0x09,
};

[[nodiscard]] constexpr std::string_view to_string(backlight_colour c) noexcept {
    switch (c) {
        case backlight_colour::red: return "red";
        case backlight_colour::green: return "green";
        case backlight_colour::blue: return "blue";
        case backlight_colour::yellow: return "yellow";
        case backlight_colour::cyan: return "cyan";
        case backlight_colour::violet: return "violet";
        case backlight_colour::white: return "white";
        case backlight_colour::amber: return "amber";
        case backlight_colour::yellow_green: return "yellow_green";
    }
    return "unknown";
}

// Command 11h byte 5.
enum class baud_rate : std::uint8_t { k125 = 0x00, k250 = 0x01, k500 = 0x02 };

[[nodiscard]] constexpr std::string_view to_string(baud_rate b) noexcept {
    switch (b) {
        case baud_rate::k125: return "125k";
        case baud_rate::k250: return "250k";
        case baud_rate::k500: return "500k";
    }
    return "unknown";
}

// Command 50h byte 5.
enum class startup_show : std::uint8_t {
    complete = 0x01,
    amber_fast_flash = 0x02,
    disabled = 0x03
};

[[nodiscard]] constexpr std::string_view to_string(startup_show s) noexcept {
    switch (s) {
        case startup_show::complete: return "complete";
        case startup_show::amber_fast_flash: return "amber_fast_flash";
        case startup_show::disabled: return "disabled";
    }
    return "unknown";
}

// --- the commands -------------------------------------------------------------------------------
// Each has `code` (byte 4) and the kind/fields convention; parameters are bytes 5 and 6.

// 13a, 01h: set one key LED. key 1..key_count(model).
struct set_led_state {
    static constexpr std::uint8_t code = 0x01;
    static constexpr std::string_view kind = "pkp_set_led_state";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("key", self.led);
        f("state", self.state);
    }
    key led = 1;
    led_state state = led_state::off;
    friend constexpr bool operator==(const set_led_state&, const set_led_state&) noexcept = default;
};

// 13b, 02h: key LED brightness, 00h..3Fh (minimum .. 100 %).
struct set_led_brightness {
    static constexpr std::uint8_t code = 0x02;
    static constexpr std::string_view kind = "pkp_set_led_brightness";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("level", self.value);
    }
    level value = 0x3F;
    friend constexpr bool operator==(const set_led_brightness&,
                                     const set_led_brightness&) noexcept = default;
};

// 13b, 03h: backlight brightness, 00h..3Fh (off .. 100 %).
struct set_backlight_brightness {
    static constexpr std::uint8_t code = 0x03;
    static constexpr std::string_view kind = "pkp_set_backlight_brightness";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("level", self.value);
    }
    level value = 0;
    friend constexpr bool operator==(const set_backlight_brightness&,
                                     const set_backlight_brightness&) noexcept = default;
};

// 13c, 04h: backlight colour.
struct set_backlight_colour {
    static constexpr std::uint8_t code = 0x04;
    static constexpr std::string_view kind = "pkp_set_backlight_colour";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("colour", self.value);
    }
    backlight_colour value = backlight_colour::amber;
    friend constexpr bool operator==(const set_backlight_colour&,
                                     const set_backlight_colour&) noexcept = default;
};

// 13d, 10h: start operational without an NMT start.
struct set_active_on_startup {
    static constexpr std::uint8_t code = 0x10;
    static constexpr std::string_view kind = "pkp_set_active_on_startup";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("active", self.active);
    }
    bool active = false;
    friend constexpr bool operator==(const set_active_on_startup&,
                                     const set_active_on_startup&) noexcept = default;
};

// 13e, 11h: bit rate.
struct set_baud_rate {
    static constexpr std::uint8_t code = 0x11;
    static constexpr std::string_view kind = "pkp_set_baud_rate";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("baud", self.baud);
    }
    baud_rate baud = baud_rate::k125;
    friend constexpr bool operator==(const set_baud_rate&, const set_baud_rate&) noexcept = default;
};

// 13f, 12h: periodic key-state PDO; period in units of 10 ms (32h = 500 ms), 00h..FFh.
struct set_periodic_transmission {
    static constexpr std::uint8_t code = 0x12;
    static constexpr std::string_view kind = "pkp_set_periodic_transmission";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("enabled", self.enabled);
        f("period_10ms", self.period_10ms);
    }
    bool enabled = false;
    std::uint8_t period_10ms = 0;
    friend constexpr bool operator==(const set_periodic_transmission&,
                                     const set_periodic_transmission&) noexcept = default;
};

// 13g, 13h: send the boot-up message (700h + node, 00h) on start-up.
struct set_boot_up_service {
    static constexpr std::uint8_t code = 0x13;
    static constexpr std::string_view kind = "pkp_set_boot_up_service";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("active", self.active);
    }
    bool active = true;
    friend constexpr bool operator==(const set_boot_up_service&,
                                     const set_boot_up_service&) noexcept = default;
};

// 13h, 70h: new node id, 01h..7Fh (E-PKP-3: the manual's 00h is no node id). The keypad answers
// from the old id, then sends a boot-up from the new one: a session follower moves to new_node.
struct set_node_id {
    static constexpr std::uint8_t code = 0x70;
    static constexpr std::string_view kind = "pkp_set_node_id";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("new_node", self.new_node);
    }
    canopen::node_id new_node = canopen::default_node_id;
    friend constexpr bool operator==(const set_node_id&, const set_node_id&) noexcept = default;
};

// 13l, 7Ah: demo mode (takes effect after a power cycle).
struct set_demo_mode {
    static constexpr std::uint8_t code = 0x7A;
    static constexpr std::string_view kind = "pkp_set_demo_mode";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("on", self.on);
    }
    bool on = false;
    friend constexpr bool operator==(const set_demo_mode&, const set_demo_mode&) noexcept = default;
};

// 13j, 7Bh: backlight level at start-up, 00h..3Fh.
struct set_default_backlight_level {
    static constexpr std::uint8_t code = 0x7B;
    static constexpr std::string_view kind = "pkp_set_default_backlight_level";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("level", self.value);
    }
    level value = 0;
    friend constexpr bool operator==(const set_default_backlight_level&,
                                     const set_default_backlight_level&) noexcept = default;
};

// 13i, 7Ch: key LED level at start-up, 00h..3Fh.
struct set_default_led_level {
    static constexpr std::uint8_t code = 0x7C;
    static constexpr std::string_view kind = "pkp_set_default_led_level";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("level", self.value);
    }
    level value = 0x3F;
    friend constexpr bool operator==(const set_default_led_level&,
                                     const set_default_led_level&) noexcept = default;
};

// 13k, 7Dh: backlight colour at start-up.
struct set_default_backlight_colour {
    static constexpr std::uint8_t code = 0x7D;
    static constexpr std::string_view kind = "pkp_set_default_backlight_colour";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("colour", self.value);
    }
    backlight_colour value = backlight_colour::amber;
    friend constexpr bool operator==(const set_default_backlight_colour&,
                                     const set_default_backlight_colour&) noexcept = default;
};

// 13m, 50h: the start-up LED show.
struct set_startup_show {
    static constexpr std::uint8_t code = 0x50;
    static constexpr std::string_view kind = "pkp_set_startup_show";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("show", self.show);
    }
    startup_show show = startup_show::complete;
    friend constexpr bool operator==(const set_startup_show&,
                                     const set_startup_show&) noexcept = default;
};

using command =
    std::variant<set_led_state, set_led_brightness, set_backlight_brightness, set_backlight_colour,
                 set_active_on_startup, set_baud_rate, set_periodic_transmission,
                 set_boot_up_service, set_node_id, set_demo_mode, set_default_backlight_level,
                 set_default_led_level, set_default_backlight_colour, set_startup_show>;

// --- encoding ---------------------------------------------------------------------------------

namespace detail {
constexpr std::uint8_t byte_of(bool b) noexcept { return b ? 1 : 0; }
template <class E>
constexpr std::uint8_t byte_of(E e) noexcept {
    return static_cast<std::uint8_t>(e);
}

// Bytes 5 and 6 of each command.
constexpr std::array<std::uint8_t, 2> params(const set_led_state& c) noexcept {
    return {c.led.value(), byte_of(c.state)};
}
template <class C>
requires requires(const C& c) { c.value.value(); }
constexpr std::array<std::uint8_t, 2> params(const C& c) noexcept { return {c.value.value(), 0}; }
constexpr std::array<std::uint8_t, 2> params(const set_backlight_colour& c) noexcept {
    return {byte_of(c.value), 0};
}
constexpr std::array<std::uint8_t, 2> params(const set_default_backlight_colour& c) noexcept {
    return {byte_of(c.value), 0};
}
constexpr std::array<std::uint8_t, 2> params(const set_active_on_startup& c) noexcept {
    return {byte_of(c.active), 0};
}
constexpr std::array<std::uint8_t, 2> params(const set_baud_rate& c) noexcept {
    return {byte_of(c.baud), 0};
}
constexpr std::array<std::uint8_t, 2> params(const set_periodic_transmission& c) noexcept {
    return {byte_of(c.enabled), c.period_10ms};
}
constexpr std::array<std::uint8_t, 2> params(const set_boot_up_service& c) noexcept {
    return {byte_of(c.active), 0};
}
constexpr std::array<std::uint8_t, 2> params(const set_node_id& c) noexcept {
    return {c.new_node.value(), 0};
}
constexpr std::array<std::uint8_t, 2> params(const set_demo_mode& c) noexcept {
    return {byte_of(c.on), 0};
}
constexpr std::array<std::uint8_t, 2> params(const set_startup_show& c) noexcept {
    return {byte_of(c.show), 0};
}

// The download request that carries command c.
template <class C>
constexpr canopen::sdo_download_request command_request(const C& c) noexcept {
    const auto p = params(c);
    return {command_address, {4, {C::code, p[0], p[1], 0}}};
}
}  // namespace detail

// The download request of a command. Errors: value_out_of_range (set_led_state naming a key the
// model lacks).
[[nodiscard]] constexpr result<canopen::sdo_download_request> command_request(
    model m, const command& c) noexcept {
    if (std::holds_alternative<set_led_state>(c) &&
        std::get<set_led_state>(c).led.value() > key_count(m))
        return errc::value_out_of_range;
    return std::visit([](const auto& v) { return detail::command_request(v); }, c);
}

// --- decoding ---------------------------------------------------------------------------------

namespace detail {
constexpr result<bool> bool_of(std::uint8_t b) noexcept {
    if (b > 1) return errc::value_out_of_range;
    return b == 1;
}
constexpr bool is_led_state(std::uint8_t b) noexcept { return b <= 0x0A || b == 0x0C || b == 0x0E; }
constexpr bool is_backlight_colour(std::uint8_t b) noexcept { return b >= 0x01 && b <= 0x09; }
}  // namespace detail

// The command carried by a download request to 6500h sub 1 (the caller has checked the address).
// Errors: size_mismatch (not a 4-byte transfer, 23h), unknown_command (byte 4 names no command),
// value_out_of_range (a parameter outside its range, a key the model lacks, node id 00h),
// reserved_not_zero (byte 7, or byte 6 of a one-parameter command, not 00h).
[[nodiscard]] constexpr result<command> decode_command(const canopen::sdo_download_request& r,
                                                       model m) noexcept {
    if (r.value.size.value() != 4) return errc::size_mismatch;
    const auto& b = r.value.bytes;
    const std::uint8_t p1 = b[1];
    // The command byte first, then the reserved bytes, then the values (docs/errors.md).
    bool two_parameters = false;
    switch (b[0]) {
        case set_led_state::code:
        case set_periodic_transmission::code: two_parameters = true; break;
        case set_led_brightness::code:
        case set_backlight_brightness::code:
        case set_backlight_colour::code:
        case set_active_on_startup::code:
        case set_baud_rate::code:
        case set_boot_up_service::code:
        case set_node_id::code:
        case set_demo_mode::code:
        case set_default_backlight_level::code:
        case set_default_led_level::code:
        case set_default_backlight_colour::code:
        case set_startup_show::code: break;
        default: return errc::unknown_command;
    }
    if (b[3] != 0 || (!two_parameters && b[2] != 0)) return errc::reserved_not_zero;
    if (b[0] == set_led_state::code) {
        if (p1 < 1 || p1 > key_count(m) || !detail::is_led_state(b[2]))
            return errc::value_out_of_range;
        return command{set_led_state{key::make(p1).value(), static_cast<led_state>(b[2])}};
    }
    if (b[0] == set_periodic_transmission::code) {
        const auto on = detail::bool_of(p1);
        if (!on) return on.error();
        return command{set_periodic_transmission{*on, b[2]}};
    }
    const auto lv = level::make(p1);
    const auto on = detail::bool_of(p1);
    switch (b[0]) {
        case set_led_brightness::code:
            if (!lv) return lv.error();
            return command{set_led_brightness{*lv}};
        case set_backlight_brightness::code:
            if (!lv) return lv.error();
            return command{set_backlight_brightness{*lv}};
        case set_default_backlight_level::code:
            if (!lv) return lv.error();
            return command{set_default_backlight_level{*lv}};
        case set_default_led_level::code:
            if (!lv) return lv.error();
            return command{set_default_led_level{*lv}};
        case set_backlight_colour::code:
            if (!detail::is_backlight_colour(p1)) return errc::value_out_of_range;
            return command{set_backlight_colour{static_cast<backlight_colour>(p1)}};
        case set_default_backlight_colour::code:
            if (!detail::is_backlight_colour(p1)) return errc::value_out_of_range;
            return command{set_default_backlight_colour{static_cast<backlight_colour>(p1)}};
        case set_active_on_startup::code:
            if (!on) return on.error();
            return command{set_active_on_startup{*on}};
        case set_boot_up_service::code:
            if (!on) return on.error();
            return command{set_boot_up_service{*on}};
        case set_demo_mode::code:
            if (!on) return on.error();
            return command{set_demo_mode{*on}};
        case set_baud_rate::code:
            if (p1 > 2) return errc::value_out_of_range;
            return command{set_baud_rate{static_cast<baud_rate>(p1)}};
        case set_startup_show::code:
            if (p1 < 1 || p1 > 3) return errc::value_out_of_range;
            return command{set_startup_show{static_cast<startup_show>(p1)}};
        default: {  // set_node_id, the last one left
            const auto n = canopen::node_id::make(p1);
            if (!n) return n.error();
            return command{set_node_id{*n}};
        }
    }
}

}  // namespace powerkey::pkp

#endif  // POWERKEY_PKP_COMMAND_HPP
