// powerkey: the values every keypad shares, one name and one type for each meaning whichever
// model or frame carries it. Byte values are the PK1000 manual's where the manuals differ; the PKP
// command module's own codes are mapped in commands.hpp.
#ifndef POWERKEY_KEYPAD_VALUES_HPP
#define POWERKEY_KEYPAD_VALUES_HPP

#include <powerkey/bounded.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/index_set.hpp>

#include <cstddef>
#include <cstdint>

namespace powerkey {

// Keys 1..16 (the key-state PDO carries 16 bits; the largest keypad has 15 keys) and the LEDs of
// one colour plane, 1..32 (the PK1000 has 28 per colour). Numbered from 1 as in the manuals.
using key_set = index_set<16>;
using led_set = index_set<32>;

struct level_tag;
// A brightness level of the key LEDs or the backlight: 00h (minimum, or off for the backlight)
// .. 3Fh (100 %). PK1000 sections 14, 15, 19; PKP sections 13 b, i, j and 30.
using level = bounded<level_tag, std::uint8_t, 0, 0x3F>;

// The colour codes of the keypads, the same for the backlight in CANopen and the LEDs and
// backlight in J1939 (j1939::led_colour): 01h..09h, amber the factory default (PK1000 section 3),
// and the manuals' longer names as second names.
// clang-format off
#define POWERKEY_COLOUR_CODE_LIST(X) \
    X(red, 0x01) \
    X(green, 0x02) \
    X(blue, 0x03) \
    X(yellow, 0x04) \
    X(cyan, 0x05) \
    X(violet, 0x06) \
    X(white, 0x07) \
    X(amber, 0x08) \
    X(yellow_green, 0x09)
#define POWERKEY_COLOUR_CODE_ALIAS_LIST(X) \
    X(white, "white_light_blue") \
    X(amber, "amber_orange")
// clang-format on

// Backlight colour (PK1000 sections 15, 19 c/d; PKP section 13 c, k; docs/pk1000.md). `keep` (00h)
// only in the backlight PDO (PK1000 15 note 2; model_info::backlight_zero_is_default).
enum class backlight_colour : std::uint8_t {
    keep = 0x00,
    POWERKEY_COLOUR_CODE_LIST(POWERKEY_DETAIL_ENUMERATOR)
};

// Bit rate (PK1000 object 2010h, section 20: these are its codes; PKP command 11h codes are
// mapped in commands.hpp). Codes 01h and 05h are reserved and make the keypad run at 125 kbit/s.
enum class baud_rate : std::uint8_t {
    kbit_1000 = 0x00,
    reserved_1 = 0x01,
    kbit_500 = 0x02,
    kbit_250 = 0x03,
    kbit_125 = 0x04,  // the factory default
    reserved_5 = 0x05,
    kbit_50 = 0x06,
    kbit_20 = 0x07,
};

// The bit rate the keypad runs at after the code is applied, in bit/s.
[[nodiscard]] constexpr std::uint32_t bits_per_second(baud_rate b) noexcept {
    constexpr std::uint32_t table[] = {1'000'000, 125'000, 500'000, 250'000,
                                       125'000,   125'000, 50'000,  20'000};
    const auto i = static_cast<std::size_t>(b);
    return i < 8 ? table[i] : 125'000;
}

// The LED show at power on (PK1000 object 2014h, section 24: these are its codes; PKP command
// 50h codes are mapped in commands.hpp).
enum class startup_show : std::uint8_t { disabled = 0x00, complete = 0x01, fast_flash = 0x02 };

// What one key LED does, PKP command 01h byte 6 (PKP section 13 a).
// clang-format off
#define POWERKEY_LED_STATE_LIST(X) \
    X(off, 0x00) \
    X(red_on, 0x01) \
    X(red_blink, 0x02) \
    X(red_alternate_blink, 0x03) \
    X(green_on, 0x04) \
    X(green_blink, 0x05) \
    X(green_alternate_blink, 0x06) \
    X(blue_on, 0x07) \
    X(blue_blink, 0x08) \
    X(blue_alternate_blink, 0x09) \
    X(red_green_blink, 0x0A) \
    X(amber_red_blink, 0x0C) \
    X(green_amber_blink, 0x0E)
// clang-format on
enum class led_state : std::uint8_t { POWERKEY_LED_STATE_LIST(POWERKEY_DETAIL_ENUMERATOR) };

// The colour planes of an LED map: 0 red, 1 green, 2 blue.
#define POWERKEY_PLANE_LIST(X) X(red) X(green) X(blue)
enum class plane : std::uint8_t { POWERKEY_PLANE_LIST(POWERKEY_DETAIL_ENUMERATOR) };

// What one key's LEDs show: a plane or a mix of planes (PKP sections 11, 12: amber = red + green,
// magenta = red + blue, cyan = green + blue, white = all three).
// clang-format off
#define POWERKEY_COLOUR_LIST(X) \
    X(off) \
    X(red) \
    X(green) \
    X(blue) \
    X(amber) \
    X(cyan) \
    X(magenta) \
    X(white)
// clang-format on
enum class colour : std::uint8_t { POWERKEY_COLOUR_LIST(POWERKEY_DETAIL_ENUMERATOR) };

// How an LED behaves given the LED-on and LED-blink maps: on and blink together blink in
// alternate mode (PK1000 sections 12, 13; PKP sections 12, 16).
// clang-format off
#define POWERKEY_LED_MODE_LIST(X) \
    X(off) \
    X(on) \
    X(blink) \
    X(alternate_blink)
// clang-format on
enum class led_mode : std::uint8_t { POWERKEY_LED_MODE_LIST(POWERKEY_DETAIL_ENUMERATOR) };

namespace detail {
// Planes of a colour as bits: 1 red, 2 green, 4 blue.
constexpr std::uint8_t planes_of(colour c) noexcept {
    constexpr std::uint8_t table[] = {0, 1, 2, 4, 3, 6, 5, 7};
    const auto i = static_cast<std::size_t>(c);
    return i < 8 ? table[i] : 0;
}
constexpr colour colour_of_planes(unsigned bits) noexcept {
    constexpr colour table[] = {colour::off,  colour::red,     colour::green, colour::amber,
                                colour::blue, colour::magenta, colour::cyan,  colour::white};
    return table[bits & 7u];
}
}  // namespace detail

// An LED map: the red, green and blue LED of every key (or the red and green LEDs of the PK1000),
// one set per plane. Carried by the LED-on and LED-blink PDOs and by the LED objects. Which LEDs a
// model has is the model's business (models.hpp): encoders refuse an LED the model lacks.
struct leds {
    led_set red;
    led_set green;
    led_set blue;

    [[nodiscard]] constexpr const led_set& of(plane c) const noexcept {
        return c == plane::red ? red : c == plane::green ? green : blue;
    }
    constexpr led_set& of(plane c) noexcept {
        return c == plane::red ? red : c == plane::green ? green : blue;
    }
    // LED k shows colour c (off clears all three planes); k is a run-time number, and a k outside
    // 1..32 changes nothing.
    constexpr leds& set(unsigned k, colour c) noexcept {
        const auto bits = detail::planes_of(c);
        for (unsigned p = 0; p < 3; ++p) {
            if ((bits >> p) & 1u)
                of(static_cast<plane>(p)).insert(k);
            else
                of(static_cast<plane>(p)).erase(k);
        }
        return *this;
    }
    // The colour LED k shows (the mix of its set planes).
    [[nodiscard]] constexpr colour colour_of(unsigned k) const noexcept {
        return detail::colour_of_planes((red.contains(k) ? 1u : 0u) |
                                        (green.contains(k) ? 2u : 0u) |
                                        (blue.contains(k) ? 4u : 0u));
    }
    [[nodiscard]] constexpr bool empty() const noexcept {
        return red.empty() && green.empty() && blue.empty();
    }
    friend constexpr bool operator==(const leds&, const leds&) noexcept = default;
};

// `base` with the LEDs of `covered` taken from `value`: how a keypad takes a value that states
// some of its LEDs (one plane, a piece of the bit string).
[[nodiscard]] constexpr leds merged(const leds& base, const leds& value,
                                    const leds& covered) noexcept {
    leds out;
    for (unsigned p = 0; p < 3; ++p) {
        const auto c = static_cast<plane>(p);
        out.of(c) = led_set::from_mask((base.of(c).mask() & ~covered.of(c).mask()) |
                                       (value.of(c).mask() & covered.of(c).mask()));
    }
    return out;
}

[[nodiscard]] constexpr led_mode mode_of(const leds& on, const leds& blink, plane c,
                                         unsigned k) noexcept {
    const bool o = on.of(c).contains(k);
    const bool b = blink.of(c).contains(k);
    return o && b ? led_mode::alternate_blink
           : b    ? led_mode::blink
           : o    ? led_mode::on
                  : led_mode::off;
}

// --- names ----------------------------------------------------------------------------------

template <>
struct enum_names<backlight_colour> {
    using value_type = backlight_colour;
    static constexpr enum_name_entry<value_type> entries[] = {
        // clang-format off
        {value_type::keep, "keep"},
        POWERKEY_COLOUR_CODE_LIST(POWERKEY_DETAIL_ENUM_NAME)
        POWERKEY_COLOUR_CODE_ALIAS_LIST(POWERKEY_DETAIL_ENUM_ALIAS)
        // clang-format on
    };
};

template <>
struct enum_names<baud_rate> {
    using b = baud_rate;
    static constexpr enum_name_entry<b> entries[] = {
        {b::kbit_1000, "kbit_1000"},   {b::kbit_500, "kbit_500"},     {b::kbit_250, "kbit_250"},
        {b::kbit_125, "kbit_125"},     {b::kbit_50, "kbit_50"},       {b::kbit_20, "kbit_20"},
        {b::reserved_1, "reserved_1"}, {b::reserved_5, "reserved_5"}, {b::kbit_1000, "1000k"},
        {b::kbit_500, "500k"},         {b::kbit_250, "250k"},         {b::kbit_125, "125k"},
        {b::kbit_50, "50k"},           {b::kbit_20, "20k"},
    };
};

template <>
struct enum_names<startup_show> {
    using s = startup_show;
    static constexpr enum_name_entry<s> entries[] = {
        {s::disabled, "disabled"},
        {s::complete, "complete"},
        {s::fast_flash, "fast_flash"},
        {s::fast_flash, "amber_fast_flash"},  // PKP manual, command 50h
    };
};

}  // namespace powerkey

POWERKEY_DETAIL_ENUM_NAMES(powerkey::led_state, POWERKEY_LED_STATE_LIST);
POWERKEY_DETAIL_ENUM_NAMES(powerkey::plane, POWERKEY_PLANE_LIST);
POWERKEY_DETAIL_ENUM_NAMES(powerkey::colour, POWERKEY_COLOUR_LIST);
POWERKEY_DETAIL_ENUM_NAMES(powerkey::led_mode, POWERKEY_LED_MODE_LIST);

#endif  // POWERKEY_KEYPAD_VALUES_HPP
