// powerkey: every J1939 frame of the keypads, as one variant (PKP1600SI and PKP2600SI J1939
// manuals; docs/j1939.md has the byte diagrams):
//
//   j1939::message = variant<key_contact, heartbeat, software_revision, led_ack, led_ack_code,
//                            address_claimed,                          keypad -> bus
//                            set_led, set_led_code, multiple_leds, command,
//                            switch_to_canopen>                        bus -> keypad
//
// Each struct follows the kind/fields convention (fields.hpp), whose fields start with the
// identifier's "priority", "destination" and "source" (the keypad's address is the source of what
// it sends and the destination of what it is sent; any address decodes). Its members are laid out
// as the frame is: `source` and `destination` (the identifier's bytes 0 and 1), `priority`, then
// the data fields in the order of their bytes, so that the decoder answers the frequent frames
// with a word or two (docs/performance.md); key_contact, led_ack and set_led are 4-aligned, 8
// bytes, built as one word. Name the members when building one (designated initialisers). Field
// names are CANopen's where the meaning is the same: "keys", "key", "level", "colour", "enabled",
// "startup_show", "baud_rate", "period_10ms", "identifier" (the keypad identifier of 70h).
#ifndef POWERKEY_KEYPAD_J1939_MESSAGES_HPP
#define POWERKEY_KEYPAD_J1939_MESSAGES_HPP

#include <powerkey/bounded.hpp>
#include <powerkey/detail/lookup.hpp>
#include <powerkey/detail/message.hpp>
#include <powerkey/detail/proxy.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/index_set.hpp>
#include <powerkey/j1939/id.hpp>
#include <powerkey/j1939/name.hpp>
#include <powerkey/j1939/protocol_switch.hpp>
#include <powerkey/keypad/j1939_models.hpp>
#include <powerkey/keypad/values.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <variant>

namespace powerkey::j1939 {

// The colour codes of the LED commands and the acknowledgement (sections 7a, 19): the backlight
// colour codes 01h..09h (backlight_colour, 7Dh) plus 00h off. 06h is "magenta" in the J1939
// manuals and "violet" in the CANopen ones: one colour, one name. `not_used` (FFh) is what some
// controllers send as the secondary colour when there is none (docs/j1939.md): accepted there
// only.
enum class led_colour : std::uint8_t {
    // clang-format off
    off = 0x00,
    POWERKEY_COLOUR_CODE_LIST(POWERKEY_DETAIL_ENUMERATOR)
    not_used = 0xFF,
    // clang-format on
};

namespace detail {
template <class Self, class F>
constexpr void route_fields(Self& self, F& f) {
    f("priority", self.priority);
    f("destination", self.destination);
    f("source", self.source);
}
}  // namespace detail

// --- keypad -> bus
// --------------------------------------------------------------------------------

// Key contact state (section 6): 04 1B 01 | key | 00h released, 01h pressed | identifier | FF FF.
// Sent on every press and release (72h), for every key periodically (71h, 77h) and at power-up
// (28h), to the destination set by 6Eh (FFh by default).
struct alignas(4) key_contact {
    POWERKEY_DETAIL_J1939_MESSAGE(key_contact);
    POWERKEY_DETAIL_FIELDS(detail::route_fields(self, f), f("key", self.key),
                           f("pressed", self.pressed), f("identifier", self.identifier));
    std::uint8_t source = keypad_default_address;
    std::uint8_t destination = global_address;
    j1939::priority priority = 6;
    std::uint8_t key = 1;  // 01h..10h: periodic traffic may name keys past the model's (docs)
    bool pressed = false;
    std::uint8_t identifier = keypad_default_address;  // the keypad identifier of 70h, 00h..FEh
};

// Heartbeat (section 21): 04 1B F9 | counter | keys 8..1 | keys 16..9 | FFh | identifier.
// Bits above the model's keys are 0.
struct heartbeat {
    POWERKEY_DETAIL_J1939_MESSAGE(heartbeat);
    POWERKEY_DETAIL_FIELDS(detail::route_fields(self, f), f("counter", self.counter),
                           f("keys", self.keys), f("identifier", self.identifier));
    std::uint8_t source = keypad_default_address;
    std::uint8_t destination = global_address;
    j1939::priority priority = 6;
    std::uint8_t counter = 0;  // +1 each message
    key_set keys;
    std::uint8_t identifier = keypad_default_address;  // any byte (LI manual: FFh)
};

// The answer to 2Ah (section 11): 04 1B 2A | bytes 3..7 ASCII, up to the first 00h (E-J1939-2).
// Each byte is 20h..7Eh or 00h, and only 00h follows a 00h.
struct software_revision {
    POWERKEY_DETAIL_J1939_MESSAGE(software_revision);
    POWERKEY_DETAIL_FIELDS(detail::route_fields(self, f), f("bytes", self.bytes));
    std::uint8_t source = keypad_default_address;
    std::uint8_t destination = global_address;
    j1939::priority priority = 6;
    std::array<std::uint8_t, 5> bytes{};
    // The characters of the revision: the bytes before the first 00h (5 for "V2.10").
    [[nodiscard]] constexpr std::size_t length() const noexcept {
        std::size_t n = 0;
        while (n < bytes.size() && bytes[n] != 0) ++n;
        return n;
    }
};

// LED acknowledgement, SI form (section 19), when 73h enabled it: after each single-LED command,
//   00h | state | LED | colour | secondary colour | FF FF FF
// (no 04 1B header; the same identifier as the keypad's other frames).
struct alignas(4) led_ack {
    POWERKEY_DETAIL_J1939_MESSAGE(led_ack);
    POWERKEY_DETAIL_FIELDS(detail::route_fields(self, f), f("key", self.key), f("mode", self.mode),
                           f("colour", self.colour), f("secondary", self.secondary));
    std::uint8_t source = keypad_default_address;
    std::uint8_t destination = global_address;
    j1939::priority priority = 6;
    led_mode mode = led_mode::off;
    std::uint8_t key = 1;  // the LED number
    led_colour colour = led_colour::off;
    led_colour secondary = led_colour::off;
};

// LED acknowledgement, LI form (PKP-2400-LI J1939 manual page 11):
//   00h | FFh | LED | code | FF FF FF FF
// The code repeats the LED command's byte 4; its table is in no source.
struct led_ack_code {
    POWERKEY_DETAIL_J1939_MESSAGE(led_ack_code);
    POWERKEY_DETAIL_FIELDS(detail::route_fields(self, f), f("key", self.key), f("code", self.code));
    std::uint8_t source = keypad_default_address;
    std::uint8_t destination = global_address;
    j1939::priority priority = 6;
    std::uint8_t key = 1;
    std::uint8_t code = 0;
};

// Address claimed (PGN EE00h, section 20): the NAME in the 8 data bytes, to the global address.
struct address_claimed {
    POWERKEY_DETAIL_J1939_MESSAGE(address_claimed);
    POWERKEY_DETAIL_FIELDS(detail::route_fields(self, f), j1939::name::fields(self.name, f));
    std::uint8_t source = keypad_default_address;
    std::uint8_t destination = global_address;
    j1939::priority priority = 6;
    j1939::name name;
};

// --- bus -> keypad
// --------------------------------------------------------------------------------

// Set single LED state, SI form (section 7a):
//   04 1B 01 | LED | colour | state | secondary colour (alternate blink) | FFh
struct alignas(4) set_led {
    POWERKEY_DETAIL_J1939_MESSAGE(set_led);
    POWERKEY_DETAIL_FIELDS(detail::route_fields(self, f), f("key", self.key),
                           f("colour", self.colour), f("mode", self.mode),
                           f("secondary", self.secondary));
    std::uint8_t source = 0x00;
    std::uint8_t destination = keypad_default_address;
    j1939::priority priority = 6;
    std::uint8_t key = 1;  // the LED number, one the model has
    led_colour colour = led_colour::off;
    led_mode mode = led_mode::off;
    led_colour secondary = led_colour::off;  // 00h..09h, or not_used (FFh)
};

// Set single LED state, LI form (inferred from the PKP-2400-LI's acknowledgement, docs):
//   04 1B 01 | LED | code | FF FF FF
struct set_led_code {
    POWERKEY_DETAIL_J1939_MESSAGE(set_led_code);
    POWERKEY_DETAIL_FIELDS(detail::route_fields(self, f), f("key", self.key), f("code", self.code));
    std::uint8_t source = 0x00;
    std::uint8_t destination = keypad_default_address;
    j1939::priority priority = 6;
    std::uint8_t key = 1;
    std::uint8_t code = 0;
};

struct colour_frame_tag;
// Which multiple-LED frame: 1 "color 1" (PGN A700h), 2 "color 2" (PGN A600h).
using colour_frame = bounded<colour_frame_tag, std::uint8_t, 1, 2>;

// Set multiple LED state (section 7b), PGN A700h ("color 1") or A600h ("color 2"), after 37h
// 02h: a 4-bit code per LED, LED 2k-1 in the low nibble and LED 2k in the high nibble of byte
// k-1; nibbles past the model's LEDs Fh ("Not used"). Codes: 0h none, 1h..9h the colours of
// led_colour, Fh blink; Ah..Eh not used. The keypad combines the two frames by the manual's
// TABLE 3 (combine() in codec.hpp). Stored as the nibbles; the fields are one LED set per code
// (led_set, LEDs 1..16), named as the colours ("red" ... "yellow_green") and "blink".
struct multiple_leds {
    POWERKEY_DETAIL_J1939_MESSAGE(multiple_leds);
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        detail::route_fields(self, f);
        f("frame", self.frame);
        for (std::size_t i = 0; i < std::size(code_names); ++i) {
            const auto code = static_cast<std::uint8_t>(i == 9 ? 0xF : i + 1);
            powerkey::detail::proxy_field<led_set>(
                self, f, code_names[i], [code](const auto& s) { return s.leds_of(code); },
                [code](auto& s, const led_set& leds) { s.set_leds(code, leds); });
        }
    }
    std::uint8_t source = 0x00;
    std::uint8_t destination = keypad_default_address;
    j1939::priority priority = 6;
    colour_frame frame = 1;
    // LED k's code in bits 4(k-1)..4k-1 of the data word, 0 past the model's LEDs: LEDs 1..8 in
    // nibbles[0], 9..16 in nibbles[1]. Two 32-bit halves, not one 64-bit word: an 8-byte member
    // would align powerkey::message to 8 bytes and make it 8 bytes larger.
    std::array<std::uint32_t, 2> nibbles{};

    // The data word of the nibbles (LED 1 in bits 0..3), and the nibbles of a data word.
    [[nodiscard]] constexpr std::uint64_t word() const noexcept {
        return nibbles[0] | (std::uint64_t{nibbles[1]} << 32);
    }
    [[nodiscard]] static constexpr std::array<std::uint32_t, 2> halves(std::uint64_t w) noexcept {
        return {static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(w >> 32)};
    }

    static constexpr std::string_view code_names[] = {"red",          "green",  "blue",  "yellow",
                                                      "cyan",         "violet", "white", "amber",
                                                      "yellow_green", "blink"};

    // LED k's code (0h..Fh), 0 outside 1..16.
    [[nodiscard]] constexpr std::uint8_t code_of(unsigned k) const noexcept {
        if (k < 1 || k > 16) return 0;
        return static_cast<std::uint8_t>((nibbles[(k - 1) / 8] >> (4 * ((k - 1) % 8))) & 0xF);
    }
    // LED k gets code c (0h none).
    constexpr multiple_leds& set(unsigned k, std::uint8_t c) noexcept {
        if (k >= 1 && k <= 16) {
            std::uint32_t& half = nibbles[(k - 1) / 8];
            const unsigned at = 4 * ((k - 1) % 8);
            half = (half & ~(std::uint32_t{0xF} << at)) | (std::uint32_t{c & 0xFu} << at);
        }
        return *this;
    }
    // The LEDs whose code is c.
    [[nodiscard]] constexpr led_set leds_of(std::uint8_t c) const noexcept {
        led_set s;
        for (unsigned k = 1; k <= 16; ++k)
            if (code_of(k) == c) s.insert(k);
        return s;
    }
    // The LEDs of `leds` get code c; the others that had c get none. A frame carries LEDs 1..16:
    // numbers above are ignored (no keypad has more than 15 LEDs).
    constexpr void set_leds(std::uint8_t c, const led_set& leds) noexcept {
        for (unsigned k = 1; k <= 16; ++k) {
            if (leds.contains(k))
                set(k, c);
            else if (code_of(k) == c)
                set(k, 0);
        }
    }
};

// --- the configuration commands (sections 8..26): 04 1B | command | byte 3 | byte 4 | FF.. -----

// clang-format off
#define POWERKEY_J1939_COMMAND_CODE_LIST(X) \
    X(set_led_brightness, 0x02)  /* 8: temporary, back to 7Ch at power-up */ \
    X(set_backlight_level, 0x03)  /* 9: temporary, back to 7Bh at power-up */ \
    X(set_startup_keys, 0x28)  /* 10: key states sent at power-up */ \
    X(get_software_revision, 0x2A)  /* 11: answered by software_revision */ \
    X(set_startup_show, 0x34)  /* 12 */ \
    X(set_led_management, 0x37)  /* 13: 02h lets the multiple-LED command in */ \
    X(set_destination_address, 0x6E)  /* 14: where the key contact states go */ \
    X(set_baud_rate, 0x6F)  /* 15 */ \
    X(set_source_address, 0x70)  /* 16: the keypad's address and identifier */ \
    X(set_periodic_transmission, 0x71)  /* 17 */ \
    X(set_event_transmission, 0x72)  /* 18 */ \
    X(set_led_acknowledgement, 0x73)  /* 19 */ \
    X(set_address_claim_at_boot, 0x74)  /* 20 */ \
    X(set_heartbeat, 0x75)  /* 21 */ \
    X(set_key_period, 0x77)  /* 22: the period of 71h */ \
    X(set_demo_mode, 0x7A)  /* 23 */ \
    X(set_default_backlight_level, 0x7B)  /* 24 */ \
    X(set_default_led_brightness, 0x7C)  /* 25 */ \
    X(set_default_backlight_colour, 0x7D)  /* 26 */
// clang-format on
enum class command_code : std::uint8_t {
    POWERKEY_J1939_COMMAND_CODE_LIST(POWERKEY_DETAIL_ENUMERATOR)
};

// What a command's byte 3 or byte 4 holds, and so which field of `command` carries it.
enum class command_param : std::uint8_t {
    none,            // FFh
    level,           // "level": 00h..3Fh
    flag,            // "enabled": 00h disabled, 01h enabled
    show,            // "startup_show": 00h off, 01h complete, 02h fast flash
    management,      // "multiple_leds": 00h single only, 02h single and multiple
    destination,     // "address": 00h..FFh but FEh (reserved); FFh broadcast
    baud,            // "baud_rate": 02h 500 kbit/s, 03h 250 kbit/s
    source,          // "address": 01h..FDh, FFh no change
    identifier,      // "identifier": 00h..FDh, FFh no change
    period,          // "period_10ms": 05h (50 ms)..FEh (2.54 s)
    heartbeat_time,  // "period_10ms": as period; FFh also when the heartbeat is disabled
    colour,          // "colour": backlight_colour 01h..09h
};

struct command_row {
    command_code code;
    feature what;      // its line of the model table (keypad/j1939_models.hpp)
    command_param p1;  // byte 3
    command_param p2;  // byte 4
};

namespace detail {
using cc = command_code;
using cp = command_param;
using ft = feature;
inline constexpr command_row command_table[] = {
    {cc::set_led_brightness, ft::led_brightness, cp::level, cp::none},
    {cc::set_backlight_level, ft::backlight_level, cp::level, cp::none},
    {cc::set_startup_keys, ft::startup_keys, cp::flag, cp::none},
    {cc::get_software_revision, ft::software_revision, cp::none, cp::none},
    {cc::set_startup_show, ft::startup_show, cp::show, cp::none},
    {cc::set_led_management, ft::led_management, cp::management, cp::none},
    {cc::set_destination_address, ft::destination_address, cp::destination, cp::none},
    {cc::set_baud_rate, ft::baud_rate, cp::baud, cp::none},
    {cc::set_source_address, ft::source_address, cp::source, cp::identifier},
    {cc::set_periodic_transmission, ft::periodic_transmission, cp::flag, cp::none},
    {cc::set_event_transmission, ft::event_transmission, cp::flag, cp::none},
    {cc::set_led_acknowledgement, ft::led_acknowledgement, cp::flag, cp::none},
    {cc::set_address_claim_at_boot, ft::address_claim_at_boot, cp::flag, cp::none},
    {cc::set_heartbeat, ft::heartbeat_setting, cp::flag, cp::heartbeat_time},
    {cc::set_key_period, ft::key_period, cp::period, cp::none},
    {cc::set_demo_mode, ft::demo_mode, cp::flag, cp::none},
    {cc::set_default_backlight_level, ft::default_backlight_level, cp::level, cp::none},
    {cc::set_default_led_brightness, ft::default_led_brightness, cp::level, cp::none},
    {cc::set_default_backlight_colour, ft::default_backlight_colour, cp::colour, cp::none},
};
inline constexpr auto command_index =
    powerkey::detail::index_by_code<0x80>(command_table, [](const auto& row) { return row.code; });
}  // namespace detail

// The row of a command byte; nullptr for a byte no configuration command has.
[[nodiscard]] constexpr const command_row* find_command(std::uint8_t code) noexcept {
    if (code >= detail::command_index.size() || detail::command_index[code] == 0) return nullptr;
    return &detail::command_table[detail::command_index[code] - 1u];
}

// One configuration command. `code` says which; its row says which other members it carries
// (the rest stay at their defaults, so that two equal commands compare equal).
struct command {
    POWERKEY_DETAIL_J1939_MESSAGE(command);
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        detail::route_fields(self, f);
        f("command", self.code);
        const command_row* row = find_command(static_cast<std::uint8_t>(self.code));
        if (row == nullptr) return;
        for (const auto p : {row->p1, row->p2}) {
            switch (p) {
                case command_param::level: f("level", self.level); break;
                case command_param::flag: f("enabled", self.enabled); break;
                case command_param::show: f("startup_show", self.show); break;
                case command_param::management: f("multiple_leds", self.multiple_leds); break;
                case command_param::destination:
                case command_param::source: f("address", self.address); break;
                case command_param::identifier: f("identifier", self.identifier); break;
                case command_param::baud: f("baud_rate", self.baud); break;
                case command_param::period:
                case command_param::heartbeat_time: f("period_10ms", self.period_10ms); break;
                case command_param::colour: f("colour", self.colour); break;
                case command_param::none: break;
            }
        }
    }
    std::uint8_t source = 0x00;
    std::uint8_t destination = keypad_default_address;
    j1939::priority priority = 6;
    command_code code = command_code::set_led_brightness;
    powerkey::level level = 0;
    bool enabled = false;
    startup_show show = startup_show::disabled;
    bool multiple_leds = false;
    std::uint8_t address = 0;     // 6Eh: the destination; 70h: the new source address
    std::uint8_t identifier = 0;  // 70h
    baud_rate baud = baud_rate::kbit_250;
    std::uint8_t period_10ms = 0;
    backlight_colour colour = backlight_colour::keep;
};

// Every J1939 frame of the keypads.
using message =
    std::variant<key_contact, heartbeat, software_revision, led_ack, led_ack_code, address_claimed,
                 set_led, set_led_code, multiple_leds, command, switch_to_canopen>;

// Whether the keypad sends T (the first six alternatives) rather than is sent it.
template <class T>
inline constexpr bool sent_by_keypad =
    std::is_same_v<T, key_contact> || std::is_same_v<T, heartbeat> ||
    std::is_same_v<T, software_revision> || std::is_same_v<T, led_ack> ||
    std::is_same_v<T, led_ack_code> || std::is_same_v<T, address_claimed>;
// The address of the keypad a message is of: the source of what it sends, the destination of
// what it is sent.
template <class T>
constexpr std::uint8_t keypad_address_of(const T& v) noexcept {
    if constexpr (sent_by_keypad<T>)
        return v.source;
    else
        return v.destination;
}

}  // namespace powerkey::j1939

namespace powerkey {

template <>
struct enum_names<j1939::led_colour> {
    using value_type = j1939::led_colour;
    static constexpr enum_name_entry<value_type> entries[] = {
        // clang-format off
        {value_type::off, "off"},
        POWERKEY_COLOUR_CODE_LIST(POWERKEY_DETAIL_ENUM_NAME)
        {value_type::not_used, "not_used"},
        {value_type::violet, "magenta"},  // the J1939 manuals
        POWERKEY_COLOUR_CODE_ALIAS_LIST(POWERKEY_DETAIL_ENUM_ALIAS)
        // clang-format on
    };
};

}  // namespace powerkey

POWERKEY_DETAIL_ENUM_NAMES(powerkey::j1939::command_code, POWERKEY_J1939_COMMAND_CODE_LIST);

#endif  // POWERKEY_KEYPAD_J1939_MESSAGES_HPP
