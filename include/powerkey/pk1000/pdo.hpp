// powerkey PK1000: the process data objects (manual sections 11 to 15).
//   180h + node  key state   5 bytes  K8..K1 | 0 0 0 0 0 0 K10 K9 | 00 | 00 | tick timer
//   200h + node  LED on      8 bytes  R8..R1 | R16..R9 | R24..R17 | 0000 R28..R25 | same for green
//   300h + node  LED blink   8 bytes  same layout; on and blink together = alternate blinking
//   400h + node  brightness  8 bytes  level 00h..3Fh | 00 x 7
//   500h + node  backlight   8 bytes  level 00h..3Fh | colour 00h..09h | 00 x 6
// Every bit the manual marks 0 or "not used" must be zero: reserved_not_zero otherwise, so a
// decoded message always re-encodes to the same bytes.
#ifndef POWERKEY_PK1000_PDO_HPP
#define POWERKEY_PK1000_PDO_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/detail/bytes.hpp>
#include <powerkey/detail/checks.hpp>
#include <powerkey/pk1000/values.hpp>

#include <array>
#include <cstdint>
#include <string_view>

namespace powerkey::pk1000 {

// Section 11, keypad -> host. `tick` counts up every 100 ms whatever the keys do.
struct key_state {
    static constexpr std::string_view kind = "pk1000_key_state";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("pressed", self.pressed);
        f("tick", self.tick);
    }
    key_set pressed;
    std::uint8_t tick = 0;
    friend constexpr bool operator==(const key_state&, const key_state&) noexcept = default;
};

// Sections 12 and 13, host -> keypad: which LEDs are on, and which blink.
struct led_on {
    static constexpr std::string_view kind = "pk1000_led_on";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("red", self.red);
        f("green", self.green);
    }
    led_set red;
    led_set green;
    friend constexpr bool operator==(const led_on&, const led_on&) noexcept = default;
};

struct led_blink {
    static constexpr std::string_view kind = "pk1000_led_blink";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("red", self.red);
        f("green", self.green);
    }
    led_set red;
    led_set green;
    friend constexpr bool operator==(const led_blink&, const led_blink&) noexcept = default;
};

// Section 14: LED indicator brightness, temporary (2003h sub 5 sets the default).
struct led_brightness {
    static constexpr std::string_view kind = "pk1000_led_brightness";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("level", self.level);
    }
    brightness level = 0x3F;
    friend constexpr bool operator==(const led_brightness&,
                                     const led_brightness&) noexcept = default;
};

// Section 15: backlight level and colour, temporary (2003h subs 4 and 6 set the defaults).
struct backlight {
    static constexpr std::string_view kind = "pk1000_backlight";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("level", self.level);
        f("colour", self.colour);
    }
    brightness level = 0;
    backlight_pdo_colour colour = backlight_pdo_colour::keep;
    friend constexpr bool operator==(const backlight&, const backlight&) noexcept = default;
};

namespace detail {
// Four bytes, LED #1 in bit 0 of the first; the top nibble of the last byte is reserved.
constexpr void store_leds(can::payload& p, std::size_t at, led_set s) noexcept {
    powerkey::detail::store_le_u32(p, at, static_cast<std::uint32_t>(s.mask()));
}
template <class Bytes>
constexpr bool load_leds(const Bytes& b, std::size_t at, led_set& out) noexcept {
    const std::uint32_t v = powerkey::detail::load_le_u32(b, at);
    if ((v >> led_count) != 0) return false;
    out = led_set::from_mask(v);
    return true;
}
constexpr can::payload led_payload(led_set red, led_set green) noexcept {
    can::payload p{};
    store_leds(p, 0, red);
    store_leds(p, 4, green);
    return p;
}
// errc{} and both sets, or reserved_not_zero for a bit above LED #28.
constexpr errc load_led_payload(const can::frame& f, led_set& red, led_set& green) noexcept {
    if (!load_leds(f.bytes(), 0, red) || !load_leds(f.bytes(), 4, green))
        return errc::reserved_not_zero;
    return errc{};
}
}  // namespace detail

[[nodiscard]] constexpr can::frame encode(canopen::node_id node, const key_state& m) noexcept {
    const auto keys = static_cast<std::uint16_t>(m.pressed.mask());
    return can::frame(
        canopen::cob_id(canopen::function::tpdo1, node),
        std::array<std::uint8_t, 5>{static_cast<std::uint8_t>(keys),
                                    static_cast<std::uint8_t>(keys >> 8), 0, 0, m.tick});
}
[[nodiscard]] constexpr can::frame encode(canopen::node_id node, const led_on& m) noexcept {
    return can::frame(canopen::cob_id(canopen::function::rpdo1, node), 8,
                      detail::led_payload(m.red, m.green));
}
[[nodiscard]] constexpr can::frame encode(canopen::node_id node, const led_blink& m) noexcept {
    return can::frame(canopen::cob_id(canopen::function::rpdo2, node), 8,
                      detail::led_payload(m.red, m.green));
}
[[nodiscard]] constexpr can::frame encode(canopen::node_id node, const led_brightness& m) noexcept {
    return can::frame(canopen::cob_id(canopen::function::rpdo3, node), 8,
                      can::payload{m.level.value(), 0, 0, 0, 0, 0, 0, 0});
}
[[nodiscard]] constexpr can::frame encode(canopen::node_id node, const backlight& m) noexcept {
    return can::frame(
        canopen::cob_id(canopen::function::rpdo4, node), 8,
        can::payload{m.level.value(), static_cast<std::uint8_t>(m.colour), 0, 0, 0, 0, 0, 0});
}

// Errors: wrong_id_format, wrong_id (not 180h + node), wrong_length (not 5 bytes),
// reserved_not_zero (a key bit above #10, or bytes 2..3 not zero).
[[nodiscard]] constexpr result<key_state> decode_key_state(const can::frame& f,
                                                           canopen::node_id node) noexcept {
    if (const auto e =
            powerkey::detail::check_frame(f, canopen::cob_id(canopen::function::tpdo1, node), 5);
        e != errc{})
        return e;
    if ((f[1] & 0xFC) != 0 || f[2] != 0 || f[3] != 0) return errc::reserved_not_zero;
    return key_state{key_set::from_mask(powerkey::detail::load_le_u16(f.bytes(), 0)), f[4]};
}

// Errors: wrong_id_format, wrong_id (not 200h + node), wrong_length (not 8 bytes),
// reserved_not_zero (a bit above LED #28 in byte 3 or byte 7).
[[nodiscard]] constexpr result<led_on> decode_led_on(const can::frame& f,
                                                     canopen::node_id node) noexcept {
    if (const auto e =
            powerkey::detail::check_frame(f, canopen::cob_id(canopen::function::rpdo1, node), 8);
        e != errc{})
        return e;
    led_on m;
    if (const auto e = detail::load_led_payload(f, m.red, m.green); e != errc{}) return e;
    return m;
}

// Errors: as decode_led_on, with 300h + node.
[[nodiscard]] constexpr result<led_blink> decode_led_blink(const can::frame& f,
                                                           canopen::node_id node) noexcept {
    if (const auto e =
            powerkey::detail::check_frame(f, canopen::cob_id(canopen::function::rpdo2, node), 8);
        e != errc{})
        return e;
    led_blink m;
    if (const auto e = detail::load_led_payload(f, m.red, m.green); e != errc{}) return e;
    return m;
}

// Errors: wrong_id_format, wrong_id (not 400h + node), wrong_length (not 8 bytes),
// reserved_not_zero (bytes 1..7 not zero), value_out_of_range (level above 3Fh).
[[nodiscard]] constexpr result<led_brightness> decode_led_brightness(
    const can::frame& f, canopen::node_id node) noexcept {
    if (const auto e =
            powerkey::detail::check_frame(f, canopen::cob_id(canopen::function::rpdo3, node), 8);
        e != errc{})
        return e;
    if (!powerkey::detail::all_zero(f.bytes(), 1, 8)) return errc::reserved_not_zero;
    const auto level = brightness::make(f[0]);
    if (!level) return level.error();
    return led_brightness{*level};
}

// Errors: wrong_id_format, wrong_id (not 500h + node), wrong_length (not 8 bytes),
// reserved_not_zero (bytes 2..7 not zero), value_out_of_range (level above 3Fh, colour above 09h;
// the keypad ignores such a level and keeps its colour, but the manual gives them no meaning).
[[nodiscard]] constexpr result<backlight> decode_backlight(const can::frame& f,
                                                           canopen::node_id node) noexcept {
    if (const auto e =
            powerkey::detail::check_frame(f, canopen::cob_id(canopen::function::rpdo4, node), 8);
        e != errc{})
        return e;
    if (!powerkey::detail::all_zero(f.bytes(), 2, 8)) return errc::reserved_not_zero;
    const auto level = brightness::make(f[0]);
    if (!level) return level.error();
    if (f[1] > 0x09) return errc::value_out_of_range;
    return backlight{*level, static_cast<backlight_pdo_colour>(f[1])};
}

}  // namespace powerkey::pk1000

#endif  // POWERKEY_PK1000_PDO_HPP
