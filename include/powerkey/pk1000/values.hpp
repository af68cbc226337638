// powerkey PK1000: the value types of the profile, each with the range the manual documents
// (PK1000_CANopen_UM_rev1.13). Out-of-range literals do not compile; run-time values go through
// make(), and enumerations decode only the values the manual names.
#ifndef POWERKEY_PK1000_VALUES_HPP
#define POWERKEY_PK1000_VALUES_HPP

#include <powerkey/bounded.hpp>
#include <powerkey/index_set.hpp>

#include <cstdint>
#include <string_view>

namespace powerkey::pk1000 {

// Keys #1..#10 (sections 11, 16) and LEDs #1..#28 of one colour (sections 12, 13, 17, 18).
inline constexpr unsigned key_count = 10;
inline constexpr unsigned led_count = 28;
using key_set = index_set<key_count>;
using led_set = index_set<led_count>;

struct brightness_tag;
// LED indicator or backlight level, 00h..3Fh = minimum..100 % (sections 14, 15, 19).
using brightness = bounded<brightness_tag, std::uint8_t, 0, 0x3F>;

// Backlight colour, sections 15 and 19 c/d. Byte values are the manual's.
enum class backlight_colour : std::uint8_t {
    red = 0x01,
    green = 0x02,
    blue = 0x03,
    yellow = 0x04,
    cyan = 0x05,
    violet = 0x06,
    white_light_blue = 0x07,
    amber_orange = 0x08,  // the factory default (section 3)
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
        case backlight_colour::white_light_blue: return "white_light_blue";
        case backlight_colour::amber_orange: return "amber_orange";
        case backlight_colour::yellow_green: return "yellow_green";
    }
    return "";
}

[[nodiscard]] constexpr bool is_backlight_colour(std::uint8_t v) noexcept {
    return v >= 0x01 && v <= 0x09;
}

// The colour byte of the backlight PDO (section 15): a colour, or 00h, which the manual's own
// "turn off the backlight" example sends and which note 2 says keeps the stored colour.
enum class backlight_pdo_colour : std::uint8_t {
    keep = 0x00,
    red = 0x01,
    green = 0x02,
    blue = 0x03,
    yellow = 0x04,
    cyan = 0x05,
    violet = 0x06,
    white_light_blue = 0x07,
    amber_orange = 0x08,
    yellow_green = 0x09,
};

[[nodiscard]] constexpr std::string_view to_string(backlight_pdo_colour c) noexcept {
    if (c == backlight_pdo_colour::keep) return "keep";
    return to_string(static_cast<backlight_colour>(c));
}

// Which LED colour an SDO LED register addresses: the sub-index of 2001h and 2002h (section 17).
enum class led_colour : std::uint8_t { red = 0x01, green = 0x02 };

[[nodiscard]] constexpr std::string_view to_string(led_colour c) noexcept {
    switch (c) {
        case led_colour::red: return "red";
        case led_colour::green: return "green";
    }
    return "";
}

// Object 2010h, section 20. Codes 01h and 05h are reserved and make the keypad run at 125 kbit/s.
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

[[nodiscard]] constexpr std::string_view to_string(baud_rate b) noexcept {
    switch (b) {
        case baud_rate::kbit_1000: return "kbit_1000";
        case baud_rate::reserved_1: return "reserved_1";
        case baud_rate::kbit_500: return "kbit_500";
        case baud_rate::kbit_250: return "kbit_250";
        case baud_rate::kbit_125: return "kbit_125";
        case baud_rate::reserved_5: return "reserved_5";
        case baud_rate::kbit_50: return "kbit_50";
        case baud_rate::kbit_20: return "kbit_20";
    }
    return "";
}

// The bit rate the keypad runs at after the code is applied, in bit/s.
[[nodiscard]] constexpr std::uint32_t bits_per_second(baud_rate b) noexcept {
    switch (b) {
        case baud_rate::kbit_1000: return 1'000'000;
        case baud_rate::kbit_500: return 500'000;
        case baud_rate::kbit_250: return 250'000;
        case baud_rate::reserved_1:
        case baud_rate::kbit_125:
        case baud_rate::reserved_5: return 125'000;
        case baud_rate::kbit_50: return 50'000;
        case baud_rate::kbit_20: return 20'000;
    }
    return 125'000;
}

// Object 2014h, section 24.
enum class startup_show : std::uint8_t { disabled = 0x00, complete = 0x01, fast_flash = 0x02 };

[[nodiscard]] constexpr std::string_view to_string(startup_show s) noexcept {
    switch (s) {
        case startup_show::disabled: return "disabled";
        case startup_show::complete: return "complete";
        case startup_show::fast_flash: return "fast_flash";
    }
    return "";
}

struct heartbeat_ms_tag;
struct event_timer_ms_tag;
struct rpdo_sync_tag;
struct tpdo_sync_tag;
// Heartbeat period when enabled, 000Ah..FFFFh ms (sections 28, 29; 0 = disabled is a flag).
using heartbeat_ms = bounded<heartbeat_ms_tag, std::uint16_t, 10, 0xFFFF>;
// TPDO event timer when enabled, 000Ah..FEFFh ms (section 46 b; 0 = disabled is a flag).
using event_timer_ms = bounded<event_timer_ms_tag, std::uint16_t, 10, 0xFEFF>;
// RPDO synchronous transmission type 00h..F0h (section 38).
using rpdo_sync_type = bounded<rpdo_sync_tag, std::uint8_t, 0x00, 0xF0>;
// TPDO synchronous transmission type 01h..F0h: sent every n-th SYNC (section 46 a).
using tpdo_sync_type = bounded<tpdo_sync_tag, std::uint8_t, 0x01, 0xF0>;

// Transmission type FEh, event-driven (sections 38, 39, 46).
inline constexpr std::uint8_t event_driven_type = 0xFE;

}  // namespace powerkey::pk1000

#endif  // POWERKEY_PK1000_VALUES_HPP
