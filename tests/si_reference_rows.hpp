// The SI sizes without a complete manual (PKP-3500-SI, 2500-SI, 1500-LI, 2200/2300/2400-SI), in
// the row types of tests/decoder_rows.hpp: the facts docs/si-family.md ("The other sizes")
// gives, one row each, and the check frames it proposes for what is inferred. The section names
// the source: "PKP3500SI manual 12" where a manual page prints it, "inferred: S = 8" where the
// layout is inferred (docs/si-family.md says why), "check" for a frame a user with the keypad
// should try. Shared by tests/test_si.cpp and examples/sample_logs.cpp (one log per model).
#ifndef POWERKEY_TESTS_SI_REFERENCE_ROWS_HPP
#define POWERKEY_TESTS_SI_REFERENCE_ROWS_HPP

#include "decoder_rows.hpp"
#include "si_rows.hpp"

#include <cstdint>

namespace si_reference_rows {

using namespace powerkey;
using namespace decoder_rows;
using decoder_rows::error_row;
using decoder_rows::row;
using o = object;
using si_rows::ring;

constexpr key_set key_span(unsigned from, unsigned to) noexcept {
    key_set s;
    for (unsigned k = from; k <= to; ++k) s.insert(k);
    return s;
}
constexpr message keys(key_set k) noexcept { return key_state{k, 0x2A}; }
constexpr message on(led_set r, led_set g = {}, led_set b = {}) noexcept {
    return led_on{rgb(r, g, b)};
}
constexpr message blink(led_set r, led_set g = {}, led_set b = {}) noexcept {
    return led_blink{rgb(r, g, b)};
}
constexpr object_value red(led_set s) noexcept { return leds_value(rgb(s)); }
constexpr object_value green(led_set s) noexcept { return leds_value(rgb({}, s)); }
constexpr object_value blue(led_set s) noexcept { return leds_value(rgb({}, {}, s)); }
// The level-only backlight PDO: byte 1 00h, the stored colour (PKP3500SI/PKP2500SI manuals).
constexpr message level_only(std::uint8_t l) noexcept {
    return backlight{level::make(l).value(), backlight_colour::keep};
}

inline constexpr row rows[] = {
    // --- PKP-3500-SI: 15 keys, every key with an LED, S = 16 (PKP3500SI manual rev 1.0) --------
    {"key state (every SI size; 15 keys)", m3500si, 0x15, "195#010000002A", keys({1})},
    {"key state (every SI size; 15 keys)", m3500si, 0x15, "195#000400002A", keys({11})},
    {"key state (every SI size; 15 keys)", m3500si, 0x15, "195#FF7F00002A", keys(key_span(1, 15))},
    {"PKP3500SI manual 12 (LED on, S = 16)", m3500si, 0x15, "215#0100000000000000", on({1})},
    {"PKP3500SI manual 12 (LED on, S = 16)", m3500si, 0x15, "215#0004000000000000", on({11})},
    {"PKP3500SI manual 12 (LED on, S = 16)", m3500si, 0x15, "215#0000010000000000", on({}, {1})},
    {"PKP3500SI manual 12 (LED on, S = 16)", m3500si, 0x15, "215#0000000000400000",
     on({}, {}, {15})},
    {"PKP3500SI manual 12 (LED on, S = 16)", m3500si, 0x15, "215#FF7FFF7FFF7F0000",
     on(span(1, 15), span(1, 15), span(1, 15))},
    {"PKP3500SI manual 13 (LED blink, S = 16)", m3500si, 0x15, "315#0000000001000000",
     blink({}, {}, {1})},
    {"PKP3500SI manual 13 (LED blink, S = 16)", m3500si, 0x15, "315#0000004000000000",
     blink({}, {15})},
    {"PKP3500SI manual (400h LED brightness)", m3500si, 0x15, "415#1000000000000000",
     led_brightness{0x10}},
    {"PKP3500SI manual (500h level only)", m3500si, 0x15, "515#2000000000000000", level_only(0x20)},
    {"PKP3500SI manual (500h level only)", m3500si, 0x15, "515#3F00000000000000", level_only(0x3F)},
    {"PKP3500SI manual (2000h sub 01h)", m3500si, 0x15, "615#4000200100000000", read(o::keys)},
    {"PKP3500SI manual (2000h sub 01h)", m3500si, 0x15, "595#4B00200100400000",
     reply(o::keys, keys_value({15}))},
    {"PKP3500SI manual (2000h sub 01h)", m3500si, 0x15, "595#4B002001FF7F0000",
     reply(o::keys, keys_value(key_span(1, 15)))},
    {"check (inferred: 2001h per colour, 2 bytes)", m3500si, 0x15, "615#2B01200102000000",
     write(o::led_on_red, red({2}))},
    {"check (inferred: 2001h per colour, 2 bytes)", m3500si, 0x15, "595#6001200100000000",
     written(o::led_on_red)},
    {"inferred: 2001h per colour, 2 bytes", m3500si, 0x15, "595#4B01200300400000",
     reply(o::led_on_blue, blue({15}))},
    {"inferred: 2002h per colour, 2 bytes", m3500si, 0x15, "615#2B02200201000000",
     write(o::led_blink_green, green({1}))},
    {"PKP3500SI manual (2003h sub 05h)", m3500si, 0x15, "615#2F03200513000000",
     write(o::default_led_brightness, level_value(0x13))},
    {"PKP3500SI manual (2003h sub 06h)", m3500si, 0x15, "595#4F03200616000000",
     reply(o::default_backlight_level, level_value(0x16))},
    {"PKP3500SI manual (2013h)", m3500si, 0x15, "615#2F1320003A000000",
     write(o::node_id, node_value(0x3A))},
    {"PKP3500SI manual (2013h: reply from the new id)", m3500si, 0x3A, "5BA#6013200000000000",
     written(o::node_id)},
    {"PKP3500SI manual (2013h)", m3500si, 0x3A, "63A#2F13200015000000",
     write(o::node_id, node_value(0x15))},
    {"PKP3500SI manual (2013h: reply from the new id)", m3500si, 0x15, "595#6013200000000000",
     written(o::node_id)},
    {"PKP3500SI manual (100Bh)", m3500si, 0x15, "615#400B100000000000", read(o::model_name)},
    {"PKP3500SI manual (100Bh)", m3500si, 0x15, "595#410B100009000000",
     initiate(0x100B, 0, true, 9)},
    {"PKP3500SI manual (100Bh)", m3500si, 0x15, "615#6000000000000000", next(false)},
    {"PKP3500SI manual (100Bh)", m3500si, 0x15, "595#00504B5033353030",
     segment(false, 0, false, {'P', 'K', 'P', '3', '5', '0', '0'})},
    {"PKP3500SI manual (100Bh)", m3500si, 0x15, "615#7000000000000000", next(true)},
    {"PKP3500SI manual (100Bh)", m3500si, 0x15, "595#1B53490000000000",
     segment(true, 5, true, {'S', 'I', 0, 0, 0, 0, 0})},
    {"PKP3500SI manual (1011h)", m3500si, 0x15, "615#231110016C6F6164",
     write(o::restore_defaults, load_signature)},
    {"PKP3500SI manual (1400h sub 02h)", m3500si, 0x15, "615#2F00140201000000",
     write(o::rpdo1_transmission_type, 1)},
    {"PKP3500SI manual (1400h sub 02h)", m3500si, 0x15, "595#4F001402FE000000",
     value(o::rpdo1_transmission_type, 0xFE)},

    // --- PKP-2500-SI: 10 keys, S = 16 (PKP2500SI manual rev 1.0) ------------------------------
    {"inferred: 10 keys (PKP2500SI LEDs 1-10)", m2500si, 0x15, "195#000200002A", keys({10})},
    {"inferred: 10 keys (PKP2500SI LEDs 1-10)", m2500si, 0x15, "195#FF0300002A",
     keys(key_span(1, 10))},
    {"check (inferred: LED on, S = 16)", m2500si, 0x15, "215#0002000000000000", on({10})},
    {"check (inferred: LED on, S = 16)", m2500si, 0x15, "215#0000000200000000", on({}, {10})},
    {"PKP2500SI manual 13 (LED blink, S = 16)", m2500si, 0x15, "315#0100000000000000", blink({1})},
    {"PKP2500SI manual 13 (LED blink, S = 16)", m2500si, 0x15, "315#0000000000020000",
     blink({}, {}, {10})},
    {"PKP2500SI manual 13 (alternate: the same string to both)", m2500si, 0x15,
     "215#0300030000000000", on({1, 2}, {1, 2})},
    {"PKP2500SI manual 13 (alternate: the same string to both)", m2500si, 0x15,
     "315#0300030000000000", blink({1, 2}, {1, 2})},
    {"PKP2500SI manual 13 (LED blink, S = 16)", m2500si, 0x15, "315#FF03FF03FF030000",
     blink(span(1, 10), span(1, 10), span(1, 10))},
    {"PKP2500SI manual (1402h: 400h LED brightness)", m2500si, 0x15, "415#0800000000000000",
     led_brightness{8}},
    {"PKP2500SI manual (1403h: 500h level only)", m2500si, 0x15, "515#1000000000000000",
     level_only(0x10)},
    {"PKP2500SI manual (2001h per colour, 2Bh)", m2500si, 0x15, "615#2B01200100020000",
     write(o::led_on_red, red({10}))},
    {"PKP2500SI manual (2001h per colour, 2Bh)", m2500si, 0x15, "595#6001200100000000",
     written(o::led_on_red)},
    {"PKP2500SI manual (2001h per colour, 4Bh)", m2500si, 0x15, "615#4001200200000000",
     read(o::led_on_green)},
    {"PKP2500SI manual (2001h per colour, 4Bh)", m2500si, 0x15, "595#4B01200210000000",
     reply(o::led_on_green, green({5}))},
    {"PKP2500SI manual (2002h per colour, 2Bh)", m2500si, 0x15, "615#2B02200301000000",
     write(o::led_blink_blue, blue({1}))},
    {"PKP2500SI manual (2002h per colour, 4Bh)", m2500si, 0x15, "595#4B022003FF030000",
     reply(o::led_blink_blue, blue(span(1, 10)))},
    {"PKP2500SI manual (2003h sub 03h)", m2500si, 0x15, "615#2F03200305000000",
     write(o::backlight_colour, colour_value(backlight_colour::cyan))},
    {"PKP2500SI manual (2003h sub 04h)", m2500si, 0x15, "595#4F03200408000000",
     reply(o::default_backlight_colour, colour_value(backlight_colour::amber))},
    {"PKP2500SI manual (1016h)", m2500si, 0x15, "615#2316100164007E00",
     write(o::consumer_heartbeat, consumer_heartbeat_value(100, 0x7E))},
    {"PKP2500SI manual (1017h, 2Bh)", m2500si, 0x15, "615#2B1710000A000000",
     write(o::heartbeat_time, 10)},
    {"PKP2500SI manual (1017h, FEFFh)", m2500si, 0x15, "615#2B171000FFFE0000",
     write(o::heartbeat_time, 0xFEFF)},
    {"PKP2500SI manual (1017h, 0 disables)", m2500si, 0x15, "615#2B17100000000000",
     write(o::heartbeat_time, 0)},
    {"PKP2500SI manual (1601h)", m2500si, 0x15, "595#4301160110010220",
     value(o::rpdo2_mapping_1, 0x2002'0110)},
    {"PKP2500SI manual (1601h)", m2500si, 0x15, "595#4301160310030220",
     value(o::rpdo2_mapping_3, 0x2002'0310)},
    {"PKP2500SI manual (1800h sub 05h, 2Bh)", m2500si, 0x15, "615#2B00180532000000",
     write(o::tpdo1_event_timer, 50)},
    {"PKP2500SI manual (1A00h)", m2500si, 0x15, "595#43001A0110010020",
     value(o::tpdo1_mapping_1, 0x2000'0110)},

    // --- PKP-1500-LI: 5 keys, S = 8 (PKP-1500-LI manual) --------------------------------------
    {"key state (every SI size; 5 keys)", m1500li, 0x15, "195#1F0000002A", keys(key_span(1, 5))},
    {"PKP1500LI manual 12 (LED on, S = 8)", m1500li, 0x15, "215#0100000000000000", on({1})},
    {"PKP1500LI manual 12 (LED on, S = 8)", m1500li, 0x15, "215#0001000000000000", on({}, {1})},
    {"PKP1500LI manual 12 (LED on, S = 8)", m1500li, 0x15, "215#0000100000000000", on({}, {}, {5})},
    {"PKP1500LI manual 12 (LED on, S = 8)", m1500li, 0x15, "215#1F1F1F0000000000",
     on(span(1, 5), span(1, 5), span(1, 5))},
    {"PKP1500LI manual 13 (LED blink, S = 8)", m1500li, 0x15, "315#0002040000000000",
     blink({}, {2}, {3})},
    {"PKP1500LI manual (2001h per colour, 2Fh)", m1500li, 0x15, "615#2F01200101000000",
     write(o::led_on_red, red({1}))},
    {"PKP1500LI manual (2001h per colour, 2Fh)", m1500li, 0x15, "595#6001200100000000",
     written(o::led_on_red)},
    {"PKP1500LI manual (2001h per colour, 4Fh)", m1500li, 0x15, "595#4F01200210000000",
     reply(o::led_on_green, green({5}))},
    {"PKP1500LI manual (2002h per colour, 2Fh)", m1500li, 0x15, "615#2F02200304000000",
     write(o::led_blink_blue, blue({3}))},
    {"PKP1500LI manual (2003h sub 01h)", m1500li, 0x15, "615#2F03200120000000",
     write(o::led_brightness, level_value(0x20))},
    {"PKP1500LI manual (2013h: reply from the new id)", m1500li, 0x15, "615#2F13200016000000",
     write(o::node_id, node_value(0x16))},
    {"PKP1500LI manual (2013h: reply from the new id)", m1500li, 0x16, "596#6013200000000000",
     written(o::node_id)},
    {"PKP1500LI manual (2013h)", m1500li, 0x16, "616#2F13200015000000",
     write(o::node_id, node_value(0x15))},
    {"PKP1500LI manual (2013h: reply from the new id)", m1500li, 0x15, "595#6013200000000000",
     written(o::node_id)},
    {"PKP1500LI manual (2014h)", m1500li, 0x15, "615#2F14200002000000",
     write(o::startup_show, show_value(startup_show::fast_flash))},
    {"PKP1500LI manual (1017h)", m1500li, 0x15, "615#2B17100064000000",
     write(o::heartbeat_time, 100)},
    {"PKP1500LI manual (100Ah, expedited)", m1500li, 0x15, "595#430A1000322E3130",
     reply(o::software_version, string_value(4, {'2', '.', '1', '0'}))},
    {"PKP1500LI manual (100Bh)", m1500li, 0x15, "595#410B100009000000",
     initiate(0x100B, 0, true, 9)},
    {"PKP1500LI manual (100Bh)", m1500li, 0x15, "595#00504B5031353030",
     segment(false, 0, false, {'P', 'K', 'P', '1', '5', '0', '0'})},
    {"PKP1500LI manual (100Bh)", m1500li, 0x15, "595#1B4C490000000000",
     segment(true, 5, true, {'L', 'I', 0, 0, 0, 0, 0})},
    {"inferred: 500h level only", m1500li, 0x15, "515#2000000000000000", level_only(0x20)},

    // --- PKP-2200-SI, 2300-SI, 2400-SI: 4, 6, 8 keys; S = 8 inferred (SI generic pages) ---------
    {"inferred: 4 keys (naming rule)", m2200si, 0x15, "195#0F0000002A", keys(key_span(1, 4))},
    {"inferred: 6 keys (naming rule)", m2300si, 0x15, "195#3F0000002A", keys(key_span(1, 6))},
    {"inferred: 8 keys (naming rule)", m2400si, 0x15, "195#FF0000002A", keys(key_span(1, 8))},
    {"check (inferred: S = 8, key 1 green)", si_s8, 0x15, "215#0001000000000000", on({}, {1})},
    {"inferred: S = 8", m2200si, 0x15, "215#0F0F0F0000000000",
     on(span(1, 4), span(1, 4), span(1, 4))},
    {"inferred: S = 8", m2300si, 0x15, "215#3F3F3F0000000000",
     on(span(1, 6), span(1, 6), span(1, 6))},
    {"inferred: S = 8", m2400si, 0x15, "215#FFFFFF0000000000",
     on(span(1, 8), span(1, 8), span(1, 8))},
    {"inferred: S = 8", m2400si, 0x15, "315#0000800000000000", blink({}, {}, {8})},
    {"check (inferred: 2001h per colour, 2Fh)", si_s8, 0x15, "615#2F01200101000000",
     write(o::led_on_red, red({1}))},
    {"inferred: 2001h per colour, 4Fh", m2400si, 0x15, "595#4F01200380000000",
     reply(o::led_on_blue, blue({8}))},
    {"check (inferred: 500h level only)", m2200si | m2300si | m2400si, 0x15, "515#2000000000000000",
     level_only(0x20)},
    {"SI generic pages (1800h)", m2200si | m2300si | m2400si, 0x15, "595#4F00180005000000",
     value(o::tpdo1_count, 5)},
    {"SI generic pages (1800h)", m2200si | m2300si | m2400si, 0x15, "595#4300180195010000",
     value(o::tpdo1_cob_id, 0x195)},
    {"SI generic pages (1800h)", m2200si | m2300si | m2400si, 0x15, "595#4F001802FE000000",
     value(o::tpdo1_transmission_type, 0xFE)},
    {"SI generic pages (1800h sub 05h)", m2200si | m2300si | m2400si, 0x15, "615#2B001805F4010000",
     write(o::tpdo1_event_timer, 500)},
    {"SI generic pages (2003h sub 04h)", m2200si | m2300si | m2400si, 0x15, "615#2F03200406000000",
     write(o::default_backlight_colour, colour_value(backlight_colour::violet))},
    {"SI generic pages (2003h sub 05h)", m2200si | m2300si | m2400si, 0x15, "615#2F0320053F000000",
     write(o::default_led_brightness, level_value(0x3F))},
    {"SI generic pages (2003h sub 06h)", m2200si | m2300si | m2400si, 0x15, "615#2F03200600000000",
     write(o::default_backlight_level, level_value(0))},
    {"SI generic pages (2010h)", m2200si | m2300si | m2400si, 0x15, "615#2F10200003000000",
     write(o::baud_rate, baud_value(baud_rate::kbit_250))},
    {"SI generic pages (2011h)", m2200si | m2300si | m2400si, 0x15, "615#2F11200000000000",
     write(o::boot_up, flag_value(false))},
    {"SI generic pages (2012h)", m2200si | m2300si | m2400si, 0x15, "615#2F12200001000000",
     write(o::active_on_startup, flag_value(true))},
    {"SI generic pages (2013h)", m2200si | m2300si | m2400si, 0x15, "615#4013200000000000",
     read(o::node_id)},
    {"SI generic pages (1000h)", m2200si | m2300si | m2400si, 0x15, "595#4300100091010B00",
     value(o::device_type, 0x000B'0191)},
    {"SI generic pages (1001h not implemented)", m2200si | m2300si | m2400si, 0x15,
     "595#8001100000000206",
     canopen::sdo_abort_response{{{0x1001, 0}, canopen::sdo_abort_code::object_does_not_exist}}},
    {"SI generic pages (1017h)", m2200si | m2300si | m2400si, 0x15, "615#2B17100032000000",
     write(o::heartbeat_time, 50)},
    {"SI generic pages (1403h)", m2200si | m2300si | m2400si, 0x15, "595#4303140115050000",
     value(o::rpdo4_cob_id, 0x515)},

    // --- every reference size: the frames the SI dictionaries share ------------------------------
    {"PK1000 dictionary (2003h sub 02h)", si, 0x15, "615#2F0320020D000000",
     write(o::backlight_level, level_value(0x0D))},
    {"PK1000 dictionary (20FFh sub 01h)", si, 0x15, "615#2BFF200101000000",
     write(o::protocol_j1939, flag_value(true))},
    {"PK1000 dictionary (J1939 to CANopen)", si, 0x15, "18EF2100#041B8000FFFFFFFF",
     j1939::switch_to_canopen{}},
    {"PK1000 dictionary (1018h sub 01h)", si, 0x15, "595#43181001E2030000",
     value(o::vendor_id, 0x3E2)},
};

// What the reference layouts refuse: bits past the keys and LEDs, the wrong object size, the
// PDOs a size does not have.
inline constexpr error_row error_rows[] = {
    {"PKP3500SI: no key 16", m3500si, 0x15, "195#008000002A", errc::reserved_not_zero},
    {"PKP3500SI: no red LED 16 (S = 16)", m3500si, 0x15, "215#0080000000000000",
     errc::reserved_not_zero},
    {"PKP3500SI: 500h level only, colour byte set", si_s16, 0x15, "515#2003000000000000",
     errc::reserved_not_zero},
    {"PKP3500SI: no encoders (280h)", m3500si, 0x15, "295#0101000000000000", errc::wrong_id},
    {"PKP3500SI: no analog inputs (480h)", m3500si, 0x15, "495#F401000000000000", errc::wrong_id},
    {"inferred: 2001h per colour is 2 bytes at S = 16", si_s16, 0x15, "615#2F01200102000000",
     errc::size_mismatch},
    {"PKP3500SI: no 2001h sub 04h (rings)", si_s16 | si_s8, 0x15, "615#4001200400000000",
     errc::unknown_object},
    {"PKP2500SI: no key 11", m2500si, 0x15, "195#000400002A", errc::reserved_not_zero},
    {"PKP2500SI: no LED 11 (S = 16)", m2500si, 0x15, "215#0004000000000000",
     errc::reserved_not_zero},
    {"PKP2500SI: no green LED 11", m2500si, 0x15, "315#0000000400000000", errc::reserved_not_zero},
    {"PKP2500SI: 2001h LED 11", m2500si, 0x15, "615#2B01200100040000", errc::reserved_not_zero},
    {"PKP2500SI: 1017h above FEFFh", m2500si, 0x15, "615#2B171000FFFF0000",
     errc::value_out_of_range},
    {"PKP2500SI: 1017h 9 ms (E-SI-23)", m2500si, 0x15, "615#2B17100009000000",
     errc::value_out_of_range},
    {"PKP1500LI: no key 6", m1500li, 0x15, "195#200000002A", errc::reserved_not_zero},
    {"PKP1500LI: no LED 6 (S = 8)", m1500li, 0x15, "215#2000000000000000", errc::reserved_not_zero},
    {"PKP1500LI: no 400h brightness PDO", m1500li, 0x15, "415#0800000000000000", errc::wrong_id},
    {"inferred: 2001h per colour is 1 byte at S = 8", si_s8, 0x15, "615#2B01200101000000",
     errc::size_mismatch},
    {"inferred: 500h level only, colour byte set", si_s8, 0x15, "515#2003000000000000",
     errc::reserved_not_zero},
    {"PKP2200SI: no key 5", m2200si, 0x15, "195#100000002A", errc::reserved_not_zero},
    {"PKP2200SI: no LED 5 (inferred S = 8)", m2200si, 0x15, "215#1000000000000000",
     errc::reserved_not_zero},
    {"PKP2300SI: no key 7", m2300si, 0x15, "195#400000002A", errc::reserved_not_zero},
    {"PKP2300SI: no blue LED 7 (inferred S = 8)", m2300si, 0x15, "215#0000400000000000",
     errc::reserved_not_zero},
    {"PKP2400SI: no key 9", m2400si, 0x15, "195#000100002A", errc::reserved_not_zero},
    {"PKP2400SI: byte 3 past blue (inferred S = 8)", m2400si, 0x15, "215#0000000100000000",
     errc::reserved_not_zero},
    {"PKP2200SI: 2001h LED 5 (1 byte)", m2200si, 0x15, "615#2F01200110000000",
     errc::reserved_not_zero},
    {"SI generic pages: no brightness PDO", m2200si | m2300si | m2400si, 0x15,
     "415#0800000000000000", errc::wrong_id},
    {"SI generic pages: backlight level 40h", si_s8, 0x15, "515#4000000000000000",
     errc::value_out_of_range},
};

}  // namespace si_reference_rows

#endif  // POWERKEY_TESTS_SI_REFERENCE_ROWS_HPP
