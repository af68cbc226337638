// The J1939 frames of the keypads, one row each: every example frame of the two complete manuals
// (PKP1600SI_J1939_UM_rev1.0 "PKP1600SI n", PKP2600SI_J1939_UM_rev1.5 "PKP2600SI n", n the
// section), the identifier and bytes exactly as printed, the models the row applies to and the
// decoded meaning; then the frames of the other models that docs/j1939.md describes
// by field ("ref", with the source it names, and "inferred" where the layout is); the decoder's
// refusals (error_rows) and the encoder's (encode_error_rows). Where a manual prints a placeholder
// (the revision "V2.XX") the row puts 2Ah in its place, as tests/pk1000_rows.hpp does for the
// tick. Rows marked E-J1939-n are errata (docs/errata.md).
//
//   row               every model of `models` decodes `frame` to `expected`, with any keypad and
//                     narrowed to `keypad`, and encodes `expected` back to the same bytes
//   error_row         every model of `models` refuses `frame` with `error` (narrowed to `keypad`
//                     when it has one)
//   encode_error_row  encode refuses `msg` with `error` for every model of `models`; `frame` is
//                     what a field-by-field encoder would build (decode refuses it or reads
//                     another meaning)
#ifndef POWERKEY_TESTS_J1939_ROWS_HPP
#define POWERKEY_TESTS_J1939_ROWS_HPP

#include <powerkey/can/candump.hpp>
#include <powerkey/keypad/j1939_codec.hpp>
#include <powerkey/keypad/j1939_messages.hpp>
#include <powerkey/keypad/j1939_models.hpp>
#include <powerkey/keypad/models.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace j1939_rows {

using namespace powerkey::j1939;
using powerkey::backlight_colour;
using powerkey::baud_rate;
using powerkey::errc;
using powerkey::key_set;
using powerkey::led_mode;
using powerkey::model;
using powerkey::startup_show;
using cc = command_code;
using lc = led_colour;

// --- models --------------------------------------------------------------------------------------

// The models a row applies to (models.hpp's model_set, sized from the table).
using powerkey::model_set;
inline constexpr model_set m1000{model::pk1000}, m2200li{model::pkp2200}, m2400li{model::pkp2400},
    m2600li{model::pkp2600}, m2600si{model::pkp2600si}, m3500mt{model::pkp3500mt},
    m3500si{model::pkp3500si}, m2500si{model::pkp2500si}, m1500li{model::pkp1500li},
    m2200si{model::pkp2200si}, m2300si{model::pkp2300si}, m2400si{model::pkp2400si},
    m1600si{model::pkp1600si};
// The two complete manuals; the SI keypads without one; the LI keypads; every model.
inline constexpr model_set complete = m1600si | m2600si;
inline constexpr model_set si_others =
    m3500mt | m3500si | m2500si | m1500li | m2200si | m2300si | m2400si;
inline constexpr model_set li = m2200li | m2400li | m2600li;
inline constexpr model_set every = complete | si_others | li | m1000;
// The SI-form LED command and acknowledgement (every SI model; not the PK1000, not LI).
inline constexpr model_set si_leds = complete | si_others;

// Calls f(m) for every model of the set; false when the set names none or f fails once.
template <class F>
constexpr bool for_models(const model_set& models, F f) {
    bool any = false;
    for (std::size_t i = 0; i < model_row_count; ++i) {
        const auto m = static_cast<model>(i);
        if (!models.contains(m)) continue;
        any = true;
        if (!f(m)) return false;
    }
    return any;
}

// --- row types and their checks ------------------------------------------------------------------

struct row {
    std::string_view section;
    model_set models;
    std::string_view frame;
    message expected;
    std::uint8_t keypad = keypad_default_address;  // the keypad's address when the frame is sent
};

struct error_row {
    std::string_view section;
    model_set models;
    std::string_view frame;
    errc error;
    keypad_address keypad = std::nullopt;
};

struct encode_error_row {
    std::string_view section;
    model_set models;
    std::string_view frame;
    message msg;
    errc error;
    keypad_address keypad = std::nullopt;
};

// Decodes to its meaning and re-encodes byte for byte, for every model of the row, with any
// keypad and narrowed to the row's.
constexpr bool round_trips(const row& r) {
    const auto f = powerkey::can::parse_candump(r.frame);
    if (!f) return false;
    return for_models(r.models, [&](model m) {
        for (const keypad_address k : {keypad_address{}, keypad_address{r.keypad}}) {
            const auto d = decode(*f, m, k);
            if (!d || !(*d == r.expected)) return false;
            const auto e = encode(m, r.expected, k);
            if (!e || !(*e == *f)) return false;
        }
        return true;
    });
}

constexpr bool refused(const error_row& r) {
    const auto f = powerkey::can::parse_candump(r.frame);
    if (!f) return false;
    return for_models(r.models, [&](model m) { return decode(*f, m, r.keypad) == r.error; });
}

constexpr bool encode_refused(const encode_error_row& r) {
    return for_models(r.models, [&](model m) {
        if (!(encode(m, r.msg, r.keypad) == r.error)) return false;
        if (r.frame.empty()) return true;
        const auto f = powerkey::can::parse_candump(r.frame);
        if (!f) return false;
        const auto d = decode(*f, m, r.keypad);
        return !d || !(*d == r.msg);
    });
}

// --- builders ------------------------------------------------------------------------------------

// From keypad 21h to the global address, as every manual example.
constexpr message contact(std::uint8_t key, bool pressed, std::uint8_t identifier = 0x21) {
    return key_contact{.source = 0x21,
                       .destination = 0xFF,
                       .priority = 6,
                       .key = key,
                       .pressed = pressed,
                       .identifier = identifier};
}
constexpr message beat(std::uint8_t counter, key_set keys, std::uint8_t identifier = 0x21) {
    return heartbeat{.source = 0x21,
                     .destination = 0xFF,
                     .priority = 6,
                     .counter = counter,
                     .keys = keys,
                     .identifier = identifier};
}
constexpr message revision(std::string_view text) {
    software_revision r{.source = 0x21, .destination = 0xFF, .priority = 6, .bytes = {}};
    for (std::size_t i = 0; i < text.size() && i < 5; ++i)
        r.bytes[i] = static_cast<std::uint8_t>(text[i]);
    return r;
}
constexpr message ack(led_mode mode, std::uint8_t key, lc colour, lc secondary) {
    return led_ack{.source = 0x21,
                   .destination = 0xFF,
                   .priority = 6,
                   .mode = mode,
                   .key = key,
                   .colour = colour,
                   .secondary = secondary};
}
constexpr message ack_code(std::uint8_t key, std::uint8_t code) {
    return led_ack_code{
        .source = 0x21, .destination = 0xFF, .priority = 6, .key = key, .code = code};
}
// The NAME the manuals print (section 20), from keypad 21h.
constexpr name manual_name() { return name{999999, 211, 0, 0, 130, 30, 0, 4, true}; }
constexpr message claimed(name n = manual_name()) {
    return address_claimed{.source = 0x21, .destination = 0xFF, .priority = 6, .name = n};
}

// From 00h to keypad 21h, as every manual example.
constexpr message led(std::uint8_t key, lc colour, led_mode mode, lc secondary = lc::off) {
    return set_led{.source = 0x00,
                   .destination = 0x21,
                   .priority = 6,
                   .key = key,
                   .colour = colour,
                   .mode = mode,
                   .secondary = secondary};
}
constexpr message led_code(std::uint8_t key, std::uint8_t code) {
    return set_led_code{
        .source = 0x00, .destination = 0x21, .priority = 6, .key = key, .code = code};
}
// A multiple-LED frame: one hex digit per LED from LED 1 ("00F5": LED 3 Fh, LED 4 5h).
constexpr message leds(std::uint8_t frame, std::string_view codes) {
    multiple_leds m{.source = 0x00,
                    .destination = 0x21,
                    .priority = 6,
                    .frame = colour_frame::make(frame).value(),
                    .nibbles = {}};
    for (std::size_t i = 0; i < codes.size(); ++i) {
        const char c = codes[i];
        const int v = c >= 'A' ? c - 'A' + 10 : c - '0';
        m.set(static_cast<unsigned>(i + 1), static_cast<std::uint8_t>(v));
    }
    return m;
}
constexpr command cmd(cc code) {
    command c;
    c.code = code;
    return c;
}
constexpr message level_cmd(cc code, std::uint8_t l) {
    command c = cmd(code);
    c.level = powerkey::level::make(l).value();
    return c;
}
constexpr message flag_cmd(cc code, bool on) {
    command c = cmd(code);
    c.enabled = on;
    return c;
}
constexpr message show_cmd(startup_show s) {
    command c = cmd(cc::set_startup_show);
    c.show = s;
    return c;
}
constexpr message management_cmd(bool multiple) {
    command c = cmd(cc::set_led_management);
    c.multiple_leds = multiple;
    return c;
}
constexpr message destination_cmd(std::uint8_t address) {
    command c = cmd(cc::set_destination_address);
    c.address = address;
    return c;
}
constexpr message baud_cmd(baud_rate b) {
    command c = cmd(cc::set_baud_rate);
    c.baud = b;
    return c;
}
constexpr message source_cmd(std::uint8_t address, std::uint8_t identifier) {
    command c = cmd(cc::set_source_address);
    c.address = address;
    c.identifier = identifier;
    return c;
}
constexpr message heartbeat_cmd(bool on, std::uint8_t period_10ms) {
    command c = cmd(cc::set_heartbeat);
    c.enabled = on;
    c.period_10ms = period_10ms;
    return c;
}
constexpr message period_cmd(std::uint8_t period_10ms) {
    command c = cmd(cc::set_key_period);
    c.period_10ms = period_10ms;
    return c;
}
constexpr message colour_cmd(backlight_colour colour) {
    command c = cmd(cc::set_default_backlight_colour);
    c.colour = colour;
    return c;
}
constexpr message to_canopen() { return switch_to_canopen{}; }

// --- the two complete manuals --------------------------------------------------------------------

inline constexpr row pkp1600si_rows[] = {
    {"PKP1600SI 6", m1600si, "18EFFF21#041B01010121FFFF", contact(1, true)},
    {"PKP1600SI 6", m1600si, "18EFFF21#041B01010021FFFF", contact(1, false)},
    {"PKP1600SI 6", m1600si, "18EFFF21#041B01020121FFFF", contact(2, true)},
    {"PKP1600SI 6", m1600si, "18EFFF21#041B01020021FFFF", contact(2, false)},
    {"PKP1600SI 6", m1600si, "18EFFF21#041B01030121FFFF", contact(3, true)},
    {"PKP1600SI 6", m1600si, "18EFFF21#041B01030021FFFF", contact(3, false)},
    {"PKP1600SI 6", m1600si, "18EFFF21#041B01040121FFFF", contact(4, true)},
    {"PKP1600SI 6", m1600si, "18EFFF21#041B01040021FFFF", contact(4, false)},
    {"PKP1600SI 6", m1600si, "18EFFF21#041B01050121FFFF", contact(5, true)},
    {"PKP1600SI 6", m1600si, "18EFFF21#041B01050021FFFF", contact(5, false)},
    {"PKP1600SI 6", m1600si, "18EFFF21#041B01060121FFFF", contact(6, true)},
    {"PKP1600SI 6", m1600si, "18EFFF21#041B01060021FFFF", contact(6, false)},
    {"PKP1600SI 7a", m1600si, "18EF2100#041B0102010100FF", led(2, lc::red, led_mode::on)},
    {"PKP1600SI 7a", m1600si, "18EF2100#041B0101010000FF", led(1, lc::red, led_mode::off)},
    {"PKP1600SI 7a", m1600si, "18EF2100#041B0103030100FF", led(3, lc::blue, led_mode::on)},
    {"PKP1600SI 7a", m1600si, "18EF2100#041B0104050100FF", led(4, lc::cyan, led_mode::on)},
    {"PKP1600SI 7a", m1600si, "18EF2100#041B0105070200FF", led(5, lc::white, led_mode::blink)},
    {"PKP1600SI 7a", m1600si, "18EF2100#041B0106010302FF",
     led(6, lc::red, led_mode::alternate_blink, lc::green)},
    // E-J1939-3: these examples fill the LEDs they do not mean with Fh (the PKP2600SI's with 0h).
    {"PKP1600SI 7b E-J1939-3", m1600si, "18A72100#1101FFFFFFFFFFFF", leds(1, "1110FF")},
    {"PKP1600SI 7b E-J1939-3", m1600si, "18A62100#005FFFFFFFFFFFFF", leds(2, "00F5FF")},
    {"PKP1600SI 7b E-J1939-3", m1600si, "18A72100#0002FFFFFFFFFFFF", leds(1, "0020FF")},
    {"PKP1600SI 7b E-J1939-3", m1600si, "18A62100#0002FFFFFFFFFFFF", leds(2, "0020FF")},
    {"PKP1600SI 7b", m1600si, "18A72100#777777FFFFFFFFFF", leds(1, "777777")},
    {"PKP1600SI 8", m1600si, "18EF2100#041B021FFFFFFFFF", level_cmd(cc::set_led_brightness, 0x1F)},
    {"PKP1600SI 9", m1600si, "18EF2100#041B033FFFFFFFFF", level_cmd(cc::set_backlight_level, 0x3F)},
    {"PKP1600SI 10", m1600si, "18EF2100#041B2801FFFFFFFF", flag_cmd(cc::set_startup_keys, true)},
    {"PKP1600SI 11", m1600si, "18EF2100#041B2AFFFFFFFFFF", cmd(cc::get_software_revision)},
    {"PKP1600SI 11 E-J1939-2", m1600si, "18EFFF21#041B2A56322E3130", revision("V2.10")},
    {"PKP1600SI 12", m1600si, "18EF2100#041B3402FFFFFFFF", show_cmd(startup_show::fast_flash)},
    {"PKP1600SI 13 E-J1939-1", m1600si, "18EF2100#041B3702FFFFFFFF", management_cmd(true)},
    {"PKP1600SI 14", m1600si, "18EF2100#041B6E05FFFFFFFF", destination_cmd(0x05)},
    {"PKP1600SI 15", m1600si, "18EF2100#041B6F02FFFFFFFF", baud_cmd(baud_rate::kbit_500)},
    {"PKP1600SI 16", m1600si, "18EF2100#041B70FDFDFFFFFF", source_cmd(0xFD, 0xFD)},
    {"PKP1600SI 17", m1600si, "18EF2100#041B7101FFFFFFFF",
     flag_cmd(cc::set_periodic_transmission, true)},
    {"PKP1600SI 18", m1600si, "18EF2100#041B7200FFFFFFFF",
     flag_cmd(cc::set_event_transmission, false)},
    {"PKP1600SI 19", m1600si, "18EF2100#041B7301FFFFFFFF",
     flag_cmd(cc::set_led_acknowledgement, true)},
    {"PKP1600SI 19", m1600si, "18EF2100#041B0101040305FF",
     led(1, lc::yellow, led_mode::alternate_blink, lc::cyan)},
    {"PKP1600SI 19", m1600si, "18EFFF21#0003010405FFFFFF",
     ack(led_mode::alternate_blink, 1, lc::yellow, lc::cyan)},
    {"PKP1600SI 20", m1600si, "18EF2100#041B7401FFFFFFFF",
     flag_cmd(cc::set_address_claim_at_boot, true)},
    {"PKP1600SI 20", m1600si, "18EEFF21#3F426F1A00823CC0", claimed()},
    {"PKP1600SI 21", m1600si, "18EF2100#041B7501FEFFFFFF", heartbeat_cmd(true, 0xFE)},
    {"PKP1600SI 21", m1600si, "18EFFF21#041BF9030200FF21", beat(3, {2})},
    {"PKP1600SI 21", m1600si, "18EFFF21#041BF9030800FF21", beat(3, {4})},
    {"PKP1600SI 22", m1600si, "18EF2100#041B7764FFFFFFFF", period_cmd(0x64)},
    {"PKP1600SI 23", m1600si, "18EF2100#041B7A01FFFFFFFF", flag_cmd(cc::set_demo_mode, true)},
    {"PKP1600SI 24", m1600si, "18EF2100#041B7B1FFFFFFFFF",
     level_cmd(cc::set_default_backlight_level, 0x1F)},
    {"PKP1600SI 25", m1600si, "18EF2100#041B7C3FFFFFFFFF",
     level_cmd(cc::set_default_led_brightness, 0x3F)},
    {"PKP1600SI 26", m1600si, "18EF2100#041B7D06FFFFFFFF", colour_cmd(backlight_colour::violet)},
    {"PKP1600SI 27", m1600si, "18EF2100#041B8000FFFFFFFF", to_canopen()},
};

inline constexpr row pkp2600si_rows[] = {
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01010121FFFF", contact(1, true)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01010021FFFF", contact(1, false)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01020121FFFF", contact(2, true)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01020021FFFF", contact(2, false)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01030121FFFF", contact(3, true)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01030021FFFF", contact(3, false)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01040121FFFF", contact(4, true)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01040021FFFF", contact(4, false)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01050121FFFF", contact(5, true)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01050021FFFF", contact(5, false)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01060121FFFF", contact(6, true)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01060021FFFF", contact(6, false)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01070121FFFF", contact(7, true)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01070021FFFF", contact(7, false)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01080121FFFF", contact(8, true)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01080021FFFF", contact(8, false)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01090121FFFF", contact(9, true)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B01090021FFFF", contact(9, false)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B010A0121FFFF", contact(10, true)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B010A0021FFFF", contact(10, false)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B010B0121FFFF", contact(11, true)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B010B0021FFFF", contact(11, false)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B010C0121FFFF", contact(12, true)},
    {"PKP2600SI 6", m2600si, "18EFFF21#041B010C0021FFFF", contact(12, false)},
    {"PKP2600SI 7a", m2600si, "18EF2100#041B0101010100FF", led(1, lc::red, led_mode::on)},
    {"PKP2600SI 7a", m2600si, "18EF2100#041B0101000000FF", led(1, lc::off, led_mode::off)},
    {"PKP2600SI 7a", m2600si, "18EF2100#041B0102030200FF", led(2, lc::blue, led_mode::blink)},
    {"PKP2600SI 7a", m2600si, "18EF2100#041B0106010100FF", led(6, lc::red, led_mode::on)},
    {"PKP2600SI 7a", m2600si, "18EF2100#041B0108020100FF", led(8, lc::green, led_mode::on)},
    {"PKP2600SI 7a", m2600si, "18EF2100#041B010B010302FF",
     led(11, lc::red, led_mode::alternate_blink, lc::green)},
    {"PKP2600SI 7b", m2600si, "18A72100#110100000000FFFF", leds(1, "111")},
    {"PKP2600SI 7b", m2600si, "18A62100#000000000096FFFF", leds(2, "000000000069")},
    {"PKP2600SI 7b", m2600si, "18A72100#000200000000FFFF", leds(1, "002")},
    {"PKP2600SI 7b", m2600si, "18A62100#000200000000FFFF", leds(2, "002")},
    {"PKP2600SI 7b", m2600si, "18A72100#000000040000FFFF", leds(1, "0000004")},
    {"PKP2600SI 7b", m2600si, "18A62100#000000050000FFFF", leds(2, "0000005")},
    // The copy merged this example's two data cells; the split is the probable one.
    {"PKP2600SI 7b (cells split)", m2600si, "18A72100#000030000000FFFF", leds(1, "000003")},
    {"PKP2600SI 7b (cells split)", m2600si, "18A62100#0000F0000000FFFF", leds(2, "00000F")},
    {"PKP2600SI 7b", m2600si, "18A72100#00000000FF00FFFF", leds(1, "00000000FF")},
    {"PKP2600SI 7b", m2600si, "18A62100#000000007700FFFF", leds(2, "0000000077")},
    {"PKP2600SI 7b", m2600si, "18A72100#222222222222FFFF", leds(1, "222222222222")},
    {"PKP2600SI 8", m2600si, "18EF2100#041B0220FFFFFFFF", level_cmd(cc::set_led_brightness, 0x20)},
    {"PKP2600SI 9", m2600si, "18EF2100#041B0310FFFFFFFF", level_cmd(cc::set_backlight_level, 0x10)},
    {"PKP2600SI 10", m2600si, "18EF2100#041B2801FFFFFFFF", flag_cmd(cc::set_startup_keys, true)},
    {"PKP2600SI 11", m2600si, "18EF2100#041B2AFFFFFFFFFF", cmd(cc::get_software_revision)},
    {"PKP2600SI 11 E-J1939-2 (XX = 2Ah)", m2600si, "18EFFF21#041B2A56322E2A2A", revision("V2.**")},
    {"PKP2600SI 12", m2600si, "18EF2100#041B3402FFFFFFFF", show_cmd(startup_show::fast_flash)},
    {"PKP2600SI 13 E-J1939-1", m2600si, "18EF2100#041B3702FFFFFFFF", management_cmd(true)},
    {"PKP2600SI 14", m2600si, "18EF2100#041B6E00FFFFFFFF", destination_cmd(0x00)},
    {"PKP2600SI 15", m2600si, "18EF2100#041B6F02FFFFFFFF", baud_cmd(baud_rate::kbit_500)},
    {"PKP2600SI 16", m2600si, "18EF2100#041B700201FFFFFF", source_cmd(0x02, 0x01)},
    {"PKP2600SI 17", m2600si, "18EF2100#041B7101FFFFFFFF",
     flag_cmd(cc::set_periodic_transmission, true)},
    {"PKP2600SI 18", m2600si, "18EF2100#041B7200FFFFFFFF",
     flag_cmd(cc::set_event_transmission, false)},
    {"PKP2600SI 19", m2600si, "18EF2100#041B7301FFFFFFFF",
     flag_cmd(cc::set_led_acknowledgement, true)},
    {"PKP2600SI 19", m2600si, "18EF2100#041B0101010302FF",
     led(1, lc::red, led_mode::alternate_blink, lc::green)},
    {"PKP2600SI 19", m2600si, "18EFFF21#0003010102FFFFFF",
     ack(led_mode::alternate_blink, 1, lc::red, lc::green)},
    {"PKP2600SI 20", m2600si, "18EF2100#041B7401FFFFFFFF",
     flag_cmd(cc::set_address_claim_at_boot, true)},
    {"PKP2600SI 20", m2600si, "18EEFF21#3F426F1A00823CC0", claimed()},
    {"PKP2600SI 21", m2600si, "18EF2100#041B750132FFFFFF", heartbeat_cmd(true, 0x32)},
    {"PKP2600SI 21", m2600si, "18EFFF21#041BF9038000FF21", beat(3, {8})},
    {"PKP2600SI 21", m2600si, "18EFFF21#041BF9030008FF21", beat(3, {12})},
    {"PKP2600SI 22", m2600si, "18EF2100#041B770AFFFFFFFF", period_cmd(0x0A)},
    {"PKP2600SI 23", m2600si, "18EF2100#041B7A01FFFFFFFF", flag_cmd(cc::set_demo_mode, true)},
    {"PKP2600SI 24", m2600si, "18EF2100#041B7B20FFFFFFFF",
     level_cmd(cc::set_default_backlight_level, 0x20)},
    {"PKP2600SI 25", m2600si, "18EF2100#041B7C10FFFFFFFF",
     level_cmd(cc::set_default_led_brightness, 0x10)},
    {"PKP2600SI 26 E-J1939-1", m2600si, "18EF2100#041B7D02FFFFFFFF",
     colour_cmd(backlight_colour::green)},
    {"PKP2600SI 27", m2600si, "18EF2100#041B8000FFFFFFFF", to_canopen()},
};

// --- the other models (docs/j1939.md), and values at the edges -----------------------------------

inline constexpr row other_rows[] = {
    // Frames every manual shares, on every model that has them (documented or inferred).
    {"ref 5: key contact, key 1", every, "18EFFF21#041B01010121FFFF", contact(1, true)},
    {"ref 7: 02h", every, "18EF2100#041B0220FFFFFFFF", level_cmd(cc::set_led_brightness, 0x20)},
    {"ref 7: 03h", every, "18EF2100#041B0300FFFFFFFF", level_cmd(cc::set_backlight_level, 0)},
    {"ref 7: 28h", every, "18EF2100#041B2800FFFFFFFF", flag_cmd(cc::set_startup_keys, false)},
    {"ref 7: 2Ah", every, "18EF2100#041B2AFFFFFFFFFF", cmd(cc::get_software_revision)},
    {"ref 7: 2Ah answer (PK-1400, PKP-2400-LI: 4 characters and 00h)", every,
     "18EFFF21#041B2A56312E3300", revision("V1.3")},
    {"ref 7: 34h", every, "18EF2100#041B3400FFFFFFFF", show_cmd(startup_show::disabled)},
    {"ref 7: 34h", every, "18EF2100#041B3401FFFFFFFF", show_cmd(startup_show::complete)},
    {"ref 7: 6Fh", every, "18EF2100#041B6F03FFFFFFFF", baud_cmd(baud_rate::kbit_250)},
    {"ref 7: 70h identifier only", every, "18EF2100#041B70FF05FFFFFF", source_cmd(0xFF, 0x05)},
    {"ref 7: 70h address only", every, "18EF2100#041B7024FFFFFFFF", source_cmd(0x24, 0xFF)},
    {"ref 7: 71h", every, "18EF2100#041B7100FFFFFFFF",
     flag_cmd(cc::set_periodic_transmission, false)},
    {"ref 7: 72h", every, "18EF2100#041B7201FFFFFFFF", flag_cmd(cc::set_event_transmission, true)},
    {"ref 7: 73h", every, "18EF2100#041B7300FFFFFFFF",
     flag_cmd(cc::set_led_acknowledgement, false)},
    {"ref 7: 74h", every, "18EF2100#041B7400FFFFFFFF",
     flag_cmd(cc::set_address_claim_at_boot, false)},
    {"ref 8: 75h, disabled, period not used (inferred)", every, "18EF2100#041B7500FFFFFFFF",
     heartbeat_cmd(false, 0xFF)},
    {"ref 8: 75h, disabled, 50 ms", every, "18EF2100#041B750005FFFFFF", heartbeat_cmd(false, 5)},
    {"ref 7: 77h, 50 ms", every, "18EF2100#041B7705FFFFFFFF", period_cmd(0x05)},
    {"ref 7: 7Ah", every, "18EF2100#041B7A00FFFFFFFF", flag_cmd(cc::set_demo_mode, false)},
    {"ref 7: 7Bh", every, "18EF2100#041B7B3FFFFFFFFF",
     level_cmd(cc::set_default_backlight_level, 0x3F)},
    {"ref 7: 7Ch", every, "18EF2100#041B7C00FFFFFFFF",
     level_cmd(cc::set_default_led_brightness, 0)},
    {"ref 7: 7Dh", every, "18EF2100#041B7D01FFFFFFFF", colour_cmd(backlight_colour::red)},
    {"ref 7: 7Dh", every, "18EF2100#041B7D09FFFFFFFF", colour_cmd(backlight_colour::yellow_green)},
    {"ref 2.2: address claim", every, "18EEFF21#3F426F1A00823CC0", claimed()},
    {"ref 8: heartbeat, nothing pressed", every, "18EFFF21#041BF9000000FF21", beat(0, {})},
    {"ref 8: heartbeat counter FFh, key 1", every, "18EFFF21#041BF9FF0100FF21", beat(0xFF, {1})},
    // The switch back: the PK1000 and PKP-3500-MT CANopen manuals (49, 58), inferred for the SI.
    {"ref 10: 80h", complete | si_others | m1000, "18EF2100#041B8000FFFFFFFF", to_canopen()},
    // Key numbers past the physical keys: "the PKP2400 has 8 buttons but 11 messages are sent"
    // (PKP-2200-SI and PK-1400 J1939 manuals, 71h); accepted on every model up to 10h.
    {"ref 5: key 0Bh of a PKP-2400 (periodic)", every, "18EFFF21#041B010B0021FFFF",
     contact(11, false)},
    {"ref 5: key 10h", every, "18EFFF21#041B01100021FFFF", contact(16, false)},
    {"ref 5: identifier 00h", every, "18EFFF21#041B01010100FFFF", contact(1, true, 0x00)},
    {"ref 5: identifier FEh (before PKP2600SI rev 1.3)", every, "18EFFF21#041B010101FEFFFF",
     contact(1, true, 0xFE)},
    // PK1000 (J1939 UM REV1.0 page 5 summary: keys up to 0Ah); its heartbeat bits are inferred.
    {"ref 5: PK1000 key 10", m1000, "18EFFF21#041B010A0121FFFF", contact(10, true)},
    {"ref 8: PK1000 key 10 (inferred)", m1000 | m2500si | m2600si | m2600li | m3500si | m3500mt,
     "18EFFF21#041BF9050002FF21", beat(5, {10})},
    // PKP-2200-SI (J1939 UM REV1.0): LED command page 6 and acknowledgement page 10 in the SI
    // layout; its heartbeat (page 12 not seen) inferred. Key 4 is its last.
    {"ref 6.1: PKP-2200-SI LED 4 red on", si_leds, "18EF2100#041B0104010100FF",
     led(4, lc::red, led_mode::on)},
    {"ref 6.3: PKP-2200-SI acknowledgement", si_leds, "18EFFF21#0001040100FFFFFF",
     ack(led_mode::on, 4, lc::red, lc::off)},
    {"ref 8: PKP-2200-SI key 4 (inferred)", every, "18EFFF21#041BF9000800FF21", beat(0, {4})},
    // PKP-2400-LI (J1939 UM REV1.0): the acknowledgement's LI form (page 11, "Byte 2 LED number,
    // Byte 3 LED state, Byte 1,4,5,6,7 FFh"); its LED command inferred from it; its heartbeat
    // (page 13) byte 5 all 0, byte 7 FFh in the table and the identifier in the examples.
    {"ref 6.3: PKP-2400-LI acknowledgement", li, "18EFFF21#00FF0305FFFFFFFF", ack_code(3, 0x05)},
    {"ref 6.4: PKP-2400-LI LED command (inferred)", li, "18EF2100#041B010305FFFFFF",
     led_code(3, 0x05)},
    {"ref 8: PKP-2400-LI key 8",
     m2400li | m2600li | m2600si | m2400si | m2500si | m3500si | m3500mt | m1000,
     "18EFFF21#041BF9018000FF21", beat(1, {8})},
    {"ref 8: PKP-2400-LI byte 7 FFh (table)", every, "18EFFF21#041BF9010100FFFF",
     beat(1, {1}, 0xFF)},
    // 1500-LI (5 keys, as the 5-key J1939 manual page 12): key 5 its last.
    {"ref 8: 5 keys, key 5", every - (m2200si | m2200li), "18EFFF21#041BF9001000FF21",
     beat(0, {5})},
    // PKP-2400-SI driven by hobby code (r51-ecu): from its own address 19h to the keypad at 24h,
    // FFh as the unused secondary colour, 7Dh at run time.
    {"ref 6.1: hobby code, secondary FFh", si_leds, "18EF2419#041B01030101FFFF",
     set_led{.source = 0x19,
             .destination = 0x24,
             .priority = 6,
             .key = 3,
             .colour = lc::red,
             .mode = led_mode::on,
             .secondary = lc::not_used},
     0x24},
    {"ref 7: hobby code, 7Dh at run time", every, "18EF2419#041B7D02FFFFFFFF",
     [] {
         command c = cmd(cc::set_default_backlight_colour);
         c.destination = 0x24;
         c.source = 0x19;
         c.colour = backlight_colour::green;
         return c;
     }(),
     0x24},
    // PKP-3500-SI (table of contents only): 15 LEDs in the multiple-LED frames, the high nibble of
    // byte 7 not used (inferred).
    {"ref 6.2: PKP-3500-SI 15 LEDs red (inferred)", m3500si, "18A72100#11111111111111F1",
     leds(1, "111111111111111")},
    {"ref 6.2: PKP-3500-SI LED 15 blink (inferred)", m3500si, "18A62100#00000000000000FF",
     leds(2, "00000000000000F")},
    // Any sender, any keypad: a heartbeat from 00h to 21h is a heartbeat of the keypad at 00h.
    {"ref 2.1: F9h from 00h to 21h", every, "18EF2100#041BF9030200FF21",
     heartbeat{.source = 0x00,
               .destination = 0x21,
               .priority = 6,
               .counter = 3,
               .keys = {2},
               .identifier = 0x21},
     0x00},
    // PKP-3500-MT: key 2 has an LED (key 1, the encoder push, has none); 15 keys.
    {"ref 6.1: PKP-3500-MT LED 2 (inferred)", m3500mt, "18EF2100#041B0102020100FF",
     led(2, lc::green, led_mode::on)},
    {"ref 8: 15 keys (inferred)", m3500mt | m3500si, "18EFFF21#041BF9074040FF21", beat(7, {7, 15})},
};

// --- refusals ------------------------------------------------------------------------------------

// Frames of other devices: not keypad frames.
inline constexpr error_row error_rows[] = {
    {"an 11-bit frame", every, "615#041B0220FFFFFFFF", errc::wrong_id_format},
    {"PGN FEF1h (CCVS)", every, "18FEF100#041B0220FFFFFFFF", errc::wrong_id},
    {"PGN EA00h (request)", every, "18EA21F9#00EE00", errc::wrong_id},
    {"data page 1: PGN 1EF00h", every, "19EF2100#041B0220FFFFFFFF", errc::wrong_id},
    {"PGN EF00h to keypad 21h, narrowed to 22h", every, "18EF2100#041B0220FFFFFFFF", errc::wrong_id,
     0x22},
    {"key contact of keypad 21h, narrowed to 22h", every, "18EFFF21#041B01010121FFFF",
     errc::wrong_id, 0x22},
    {"a command from keypad 21h to 22h, narrowed to 21h", every, "18EF2221#041B0220FFFFFFFF",
     errc::wrong_id, 0x21},
    {"an LED command to 22h from 21h, narrowed to 21h: its key state", complete,
     "18EF2221#041B0102010100FF", errc::reserved_not_ff, 0x21},
    {"7 bytes", every, "18EF2100#041B0220FFFFFF", errc::wrong_length},
    {"no data", every, "18EF2100#", errc::wrong_length},
    {"address claim of 4 bytes", every, "18EEFF21#3F426F1A", errc::wrong_length},
    // The header and the command byte.
    {"header 05 1B", every, "18EF2100#051B0220FFFFFFFF", errc::unknown_command},
    {"header 04 00", every, "18EF2100#04000220FFFFFFFF", errc::unknown_command},
    {"byte 0 FFh", every, "18EFFF21#FF03010405FFFFFF", errc::unknown_command},
    {"command 05h", every, "18EF2100#041B0501FFFFFFFF", errc::unknown_command},
    {"command 1Ch (hobby code's 'live backlight colour')", every, "18EF2100#041B1C02FFFFFFFF",
     errc::unknown_command},
    {"command 81h", every, "18EF2100#041B8100FFFFFFFF", errc::unknown_command},
    // Commands to the global address: no source shows a keypad taking one.
    {"02h to FFh", every, "18EFFF00#041B0220FFFFFFFF", errc::undocumented},
    {"80h to FFh", every, "18EFFF00#041B8000FFFFFFFF", errc::undocumented},
    {"multiple LEDs to FFh", complete, "18A7FF00#1101FFFFFFFFFFFF", errc::undocumented},
    // "Not used" bytes that are not FFh.
    {"02h byte 7 00h", every, "18EF2100#041B0220FFFFFF00", errc::reserved_not_ff},
    {"02h byte 4 00h", every, "18EF2100#041B022000FFFFFF", errc::reserved_not_ff},
    {"2Ah request byte 7 00h: an answer sent to the keypad", every, "18EF2100#041B2AFFFFFFFF00",
     errc::value_out_of_range},
    {"70h byte 5 00h", every, "18EF2100#041B70020100FFFF", errc::reserved_not_ff},
    {"75h byte 5 00h", every, "18EF2100#041B75013200FFFF", errc::reserved_not_ff},
    {"80h byte 7 00h", complete, "18EF2100#041B8000FFFFFF00", errc::reserved_not_ff},
    {"key contact byte 7 00h", every, "18EFFF21#041B01010121FF00", errc::reserved_not_ff},
    {"key contact byte 6 00h, to FFh", every, "18EFFF21#041B0101012100FF", errc::reserved_not_ff},
    {"LED command byte 7 00h", si_leds, "18EF2100#041B010201010000", errc::reserved_not_ff},
    {"LED acknowledgement byte 7 00h", si_leds, "18EFFF21#0003010405FFFF00", errc::reserved_not_ff},
    {"LI acknowledgement byte 1 03h", li, "18EFFF21#00030305FFFFFFFF", errc::reserved_not_ff},
    {"LI acknowledgement byte 4 00h", li, "18EFFF21#00FF030500FFFFFF", errc::reserved_not_ff},
    {"LI LED command byte 7 00h", li, "18EF2100#041B010305FFFF00", errc::reserved_not_ff},
    {"heartbeat byte 6 00h", every, "18EFFF21#041BF90302000021", errc::reserved_not_ff},
    {"PKP-1600-SI multiple LEDs, byte 3 00h", m1600si, "18A72100#11010000FFFFFFFF",
     errc::reserved_not_ff},
    {"PKP-2600-SI multiple LEDs, byte 7 00h", m2600si, "18A72100#110100000000FF00",
     errc::reserved_not_ff},
    {"PKP-3500-SI multiple LEDs, byte 7's high nibble 0h", m3500si, "18A72100#1111111111111101",
     errc::reserved_not_ff},
    // Reserved zeros: heartbeat key bits past the keys, the NAME's bit 48.
    {"PKP-1600-SI heartbeat key 7", m1600si, "18EFFF21#041BF9034000FF21", errc::reserved_not_zero},
    {"PKP-1600-SI heartbeat byte 5 01h", m1600si, "18EFFF21#041BF9030201FF21",
     errc::reserved_not_zero},
    {"PKP-2600-SI heartbeat key 13", m2600si, "18EFFF21#041BF9030010FF21", errc::reserved_not_zero},
    {"PKP-2200-SI heartbeat key 5", m2200si | m2200li, "18EFFF21#041BF9031000FF21",
     errc::reserved_not_zero},
    {"NAME bit 48 set", every, "18EEFF21#3F426F1A00823DC0", errc::reserved_not_zero},
    // Values outside their range.
    {"02h level 40h", every, "18EF2100#041B0240FFFFFFFF", errc::value_out_of_range},
    {"7Bh level FFh", every, "18EF2100#041B7BFFFFFFFFFF", errc::value_out_of_range},
    {"28h 02h", every, "18EF2100#041B2802FFFFFFFF", errc::value_out_of_range},
    {"34h 03h", every, "18EF2100#041B3403FFFFFFFF", errc::value_out_of_range},
    {"37h 01h", complete, "18EF2100#041B3701FFFFFFFF", errc::value_out_of_range},
    {"6Eh FEh", complete, "18EF2100#041B6EFEFFFFFFFF", errc::value_out_of_range},
    {"6Fh 01h (hobby code's 250k)", every, "18EF2100#041B6F01FFFFFFFF", errc::value_out_of_range},
    {"6Fh 00h", every, "18EF2100#041B6F00FFFFFFFF", errc::value_out_of_range},
    {"6Fh 04h", every, "18EF2100#041B6F04FFFFFFFF", errc::value_out_of_range},
    {"70h source 00h", every, "18EF2100#041B7000FFFFFFFF", errc::value_out_of_range},
    {"70h source FEh (reserved since PKP2600SI rev 1.3)", every, "18EF2100#041B70FEFFFFFFFF",
     errc::value_out_of_range},
    {"70h identifier FEh", every, "18EF2100#041B70FFFEFFFFFF", errc::value_out_of_range},
    {"75h enabled, period 04h", every, "18EF2100#041B750104FFFFFF", errc::value_out_of_range},
    {"75h enabled, period FFh", every, "18EF2100#041B7501FFFFFFFF", errc::value_out_of_range},
    {"75h disabled, period 00h", every, "18EF2100#041B750000FFFFFF", errc::value_out_of_range},
    {"75h 02h", every, "18EF2100#041B750232FFFFFF", errc::value_out_of_range},
    {"77h 04h", every, "18EF2100#041B7704FFFFFFFF", errc::value_out_of_range},
    {"77h FFh", every, "18EF2100#041B77FFFFFFFFFF", errc::value_out_of_range},
    {"7Dh 00h", every, "18EF2100#041B7D00FFFFFFFF", errc::value_out_of_range},
    {"7Dh 0Ah", every, "18EF2100#041B7D0AFFFFFFFF", errc::value_out_of_range},
    {"80h 01h", complete, "18EF2100#041B8001FFFFFFFF", errc::value_out_of_range},
    {"key contact key 00h", every, "18EFFF21#041B01000121FFFF", errc::value_out_of_range},
    {"key contact key 11h", every, "18EFFF21#041B01110121FFFF", errc::value_out_of_range},
    {"key contact state 02h", every, "18EFFF21#041B01010221FFFF", errc::value_out_of_range},
    {"PKP-1600-SI LED 7", m1600si, "18EF2100#041B0107010100FF", errc::value_out_of_range},
    {"PKP-2600-SI LED 0", m2600si, "18EF2100#041B0100010100FF", errc::value_out_of_range},
    {"PKP-3500-MT LED 1 (the encoder push)", m3500mt, "18EF2100#041B0101010100FF",
     errc::value_out_of_range},
    {"LED colour 0Ah", si_leds, "18EF2100#041B01010A0100FF", errc::value_out_of_range},
    {"LED state 04h", si_leds, "18EF2100#041B0101010400FF", errc::value_out_of_range},
    {"LED secondary colour 0Ah", si_leds, "18EF2100#041B010101030AFF", errc::value_out_of_range},
    {"acknowledgement LED 7 of a PKP-1600-SI", m1600si, "18EFFF21#0001070100FFFFFF",
     errc::value_out_of_range},
    {"acknowledgement colour 0Ah", si_leds, "18EFFF21#0001010A00FFFFFF", errc::value_out_of_range},
    {"acknowledgement state FFh (the LI form) on an SI keypad", si_leds,
     "18EFFF21#00FF0305FFFFFFFF", errc::value_out_of_range},
    {"multiple LEDs code Ah", complete, "18A72100#A1FFFFFFFFFFFFFF", errc::value_out_of_range},
    {"multiple LEDs code Eh", m2600si, "18A62100#0000000000E0FFFF", errc::value_out_of_range},
    {"revision byte 4 FFh", every, "18EFFF21#041B2A56FF2E3130", errc::value_out_of_range},
    {"revision a character after 00h", every, "18EFFF21#041B2A5600323130",
     errc::value_out_of_range},
    {"revision byte 3 1Fh", every, "18EFFF21#041B2A1F322E3130", errc::value_out_of_range},
    // Frames a model's manual does not have, and frames no source shows on a model.
    {"PKP-2200-SI, PK1000, PKP-2400-LI: no multiple-LED command", m2200si | m1000 | m2400li,
     "18A72100#1101FFFFFFFFFFFF", errc::unknown_command},
    {"PKP-2200-SI, PK1000, PKP-2400-LI: no 37h", m2200si | m1000 | m2400li,
     "18EF2100#041B3702FFFFFFFF", errc::unknown_command},
    {"PKP-2200-SI, PK1000, PKP-2400-LI: no 6Eh", m2200si | m1000 | m2400li,
     "18EF2100#041B6E05FFFFFFFF", errc::unknown_command},
    {"multiple LEDs on the SI keypads without a manual",
     m2300si | m2400si | m2500si | m1500li | m3500mt | m2200li | m2600li,
     "18A72100#1101FFFFFFFFFFFF", errc::undocumented},
    {"6Eh on the SI keypads without a manual", (si_others - m2200si) | m2200li | m2600li,
     "18EF2100#041B6E05FFFFFFFF", errc::undocumented},
    {"PK1000: its LED command is not known", m1000, "18EF2100#041B0102010100FF",
     errc::undocumented},
    {"PK1000: its LED acknowledgement is not known", m1000, "18EFFF21#0003010405FFFFFF",
     errc::undocumented},
    {"LI: no source shows 80h", li, "18EF2100#041B8000FFFFFFFF", errc::undocumented},
};

// Messages encode refuses: the error, and what a field-by-field encoder would have sent.
inline constexpr encode_error_row encode_error_rows[] = {
    {"PKP-1600-SI LED 7", m1600si, "18EF2100#041B0107010100FF", led(7, lc::red, led_mode::on),
     errc::value_out_of_range},
    {"PKP-1600-SI heartbeat key 7", m1600si, "18EFFF21#041BF9034000FF21", beat(3, {7}),
     errc::reserved_not_zero},
    {"LED colour not_used (FFh is a secondary colour only)", si_leds, "18EF2100#041B0101FF0100FF",
     led(1, lc::not_used, led_mode::on), errc::value_out_of_range},
    {"LED state 04h", si_leds, "18EF2100#041B0101010400FF",
     led(1, lc::red, static_cast<led_mode>(4)), errc::value_out_of_range},
    {"key contact identifier FFh", every, "18EFFF21#041B010101FFFFFF", contact(1, true, 0xFF),
     errc::value_out_of_range},
    {"PKP-1600-SI multiple LEDs: LED 7 (not in its frame)", m1600si, "18A72100#111111F1FFFFFFFF",
     leds(1, "1111111"), errc::value_out_of_range},
    {"PK1000 LED command", m1000, "18EF2100#041B0102010100FF", led(2, lc::red, led_mode::on),
     errc::undocumented},
    {"SI LED command to an LI keypad", li, "18EF2100#041B0102010100FF",
     led(2, lc::red, led_mode::on), errc::reserved_not_ff},
    {"PKP-2200-SI multiple LEDs", m2200si, "", leds(1, "1"), errc::unknown_command},
    {"a command to the global address", every, "18EFFF00#041B0220FFFFFFFF",
     [] {
         command c = cmd(cc::set_led_brightness);
         c.destination = 0xFF;
         c.level = 0x20;
         return c;
     }(),
     errc::undocumented},
    {"02h with `enabled` set (a member 02h does not use)", every, "18EF2100#041B0220FFFFFFFF",
     [] {
         command c = cmd(cc::set_led_brightness);
         c.level = 0x20;
         c.enabled = true;
         return c;
     }(),
     errc::value_out_of_range},
    {"command 05h", every, "18EF2100#041B05FFFFFFFFFF", cmd(static_cast<cc>(0x05)),
     errc::unknown_command},
    {"6Fh at 125 kbit/s (no J1939 code)", every, "18EF2100#041B6F04FFFFFFFF",
     baud_cmd(baud_rate::kbit_125), errc::value_out_of_range},
    {"70h address FEh", every, "18EF2100#041B70FE01FFFFFF", source_cmd(0xFE, 0x01),
     errc::value_out_of_range},
    {"7Dh keep (00h)", every, "18EF2100#041B7D00FFFFFFFF", colour_cmd(backlight_colour::keep),
     errc::value_out_of_range},
    {"75h enabled with FFh", every, "18EF2100#041B7501FFFFFFFF", heartbeat_cmd(true, 0xFF),
     errc::value_out_of_range},
    // Addressed to 05h without narrowing, key 1 pressed by keypad 21h with identifier 02h reads
    // as an LED command from 21h to 05h (docs/j1939.md): narrowed to 21h it encodes (rows).
    {"a key contact whose bytes read as an LED command", complete, "18EF0521#041B01010102FFFF",
     key_contact{.source = 0x21,
                 .destination = 0x05,
                 .priority = 6,
                 .key = 1,
                 .pressed = true,
                 .identifier = 0x02},
     errc::value_out_of_range},
    {"an LED command narrowed to its sender", complete, "18EF2221#041B0102010100FF",
     set_led{.source = 0x21,
             .destination = 0x22,
             .priority = 6,
             .key = 2,
             .colour = lc::red,
             .mode = led_mode::on,
             .secondary = lc::off},
     errc::reserved_not_ff, 0x21},
};

}  // namespace j1939_rows

#endif  // POWERKEY_TESTS_J1939_ROWS_HPP
