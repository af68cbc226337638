// Every example frame of the PKP manual (PKP-2200-2400-LI_CANopen_UM_rev1.1, "PKP n" = section n)
// and the PKP-2600 rows of docs/pkp.md ("ref"), with the models each row applies to, the keypad's
// node id and the decoded meaning, in the row types of tests/codec_rows.hpp. Shared by the
// doctest suite, the freestanding check, and any tool that wants sample logs or fuzz seeds.
//
// Where the manual prints XX for the tick timer of the key-state PDO (section 10), the rows put a
// chosen byte in its place and say so. Frames the manual prints wrongly are in error_rows, named by
// their erratum (docs/errata.md), next to the corrected frame in rows.
#ifndef POWERKEY_TESTS_PKP_ROWS_HPP
#define POWERKEY_TESTS_PKP_ROWS_HPP

#include "codec_rows.hpp"

#include <cstdint>
#include <initializer_list>
#include <variant>

namespace pkp_rows {

using namespace powerkey;
using namespace codec_rows;
using codec_rows::encode_error_row;
using codec_rows::error_row;
using codec_rows::row;
using cc = command_code;

// --- builders ---------------------------------------------------------------------------------

// Keys or LEDs by number (an LED map plane, or the keys of a key map).
constexpr led_set keys(std::initializer_list<unsigned> k) noexcept { return led_set(k); }
constexpr key_set key_map(led_set k) noexcept { return key_set::from_mask(k.mask()); }
constexpr message pressed(led_set k, std::uint8_t tick) noexcept {
    return key_state{key_map(k), tick};
}
constexpr message key_reply(led_set k) noexcept {
    return reply(object::keys, keys_value(key_map(k)));
}
constexpr message write_on(leds l) noexcept { return write(object::led_on, leds_value(l)); }
constexpr message reply_on(leds l) noexcept { return reply(object::led_on, leds_value(l)); }
constexpr message write_blink(leds l) noexcept { return write(object::led_blink, leds_value(l)); }
constexpr message reply_blink(leds l) noexcept { return reply(object::led_blink, leds_value(l)); }
constexpr message command_ok = sdo_write_reply{object::command_module};

// The commands of 6500h (PKP 13): each sets its code and the members of its row.
constexpr command cmd(cc code) noexcept {
    command c;
    c.code = code;
    return c;
}
constexpr message state(std::uint8_t key, led_state s) noexcept {
    auto c = cmd(cc::set_led_state);
    c.key = key;
    c.state = s;
    return c;
}
constexpr message cmd_level(cc code, std::uint8_t l) noexcept {
    auto c = cmd(code);
    c.level = level::make(l).value();
    return c;
}
constexpr message cmd_colour(cc code, backlight_colour b) noexcept {
    auto c = cmd(code);
    c.colour = b;
    return c;
}
constexpr message cmd_flag(cc code, bool on) noexcept {
    auto c = cmd(code);
    c.enabled = on;
    return c;
}
constexpr message cmd_baud(baud_rate b) noexcept {
    auto c = cmd(cc::set_baud_rate);
    c.baud = b;
    return c;
}
constexpr message periodic(bool on, std::uint8_t period_10ms) noexcept {
    auto c = cmd(cc::set_periodic_transmission);
    c.enabled = on;
    c.period_10ms = period_10ms;
    return c;
}
constexpr message new_node(std::uint8_t n) noexcept {
    auto c = cmd(cc::set_node_id);
    c.node_id = node_of(n);
    return c;
}
constexpr message show(startup_show s) noexcept {
    auto c = cmd(cc::set_startup_show);
    c.show = s;
    return c;
}

// --- the manual, section by section ------------------------------------------------------------

inline constexpr row rows[] = {
    // 4-7: NMT
    {"PKP 4 start node", pkp, 0x15, "000#0115", nmt(nmt_command::start, 0x15)},
    {"PKP 5 enter pre-operational", pkp, 0x15, "000#8015",
     nmt(nmt_command::enter_pre_operational, 0x15)},
    {"PKP 6 reset node", pkp, 0x15, "000#8115", nmt(nmt_command::reset_node, 0x15)},
    {"PKP 7 stop node", pkp, 0x15, "000#0215", nmt(nmt_command::stop, 0x15)},
    // 8-9: boot-up and heartbeat
    {"PKP 8 boot-up", pkp, 0x15, "715#00", hb(nmt_state::boot_up)},
    {"PKP 9 boot up", pkp, 0x15, "715#00", hb(nmt_state::boot_up)},
    {"PKP 9 pre-operational", pkp, 0x15, "715#7F", hb(nmt_state::pre_operational)},
    {"PKP 9 start keypad 15h", pkp, 0x15, "000#0115", nmt(nmt_command::start, 0x15)},
    {"PKP 9 operational", pkp, 0x15, "715#05", hb(nmt_state::operational)},

    // 10: key state (XX = the tick byte chosen here)
    {"PKP 10 PKP-2200 no key (XX=00)", m2200, 0x15, "195#0000000000", pressed({}, 0x00)},
    {"PKP 10 PKP-2200 key 3 (XX=2A)", m2200, 0x15, "195#040000002A", pressed(keys({3}), 0x2A)},
    {"PKP 10 PKP-2200 key 2 (XX=7F)", m2200, 0x15, "195#020000007F", pressed(keys({2}), 0x7F)},
    {"PKP 10 PKP-2200 keys 1, 3 (XX=FF)", m2200, 0x15, "195#05000000FF",
     pressed(keys({1, 3}), 0xFF)},
    {"PKP 10 PKP-2400 no key (XX=01)", m2400, 0x15, "195#0000000001", pressed({}, 0x01)},
    {"PKP 10 PKP-2400 key 1 (XX=10)", m2400, 0x15, "195#0100000010", pressed(keys({1}), 0x10)},
    {"PKP 10 PKP-2400 key 2 (XX=80)", m2400, 0x15, "195#0200000080", pressed(keys({2}), 0x80)},
    {"PKP 10 PKP-2400 keys 7, 2 (XX=FE)", m2400, 0x15, "195#42000000FE",
     pressed(keys({2, 7}), 0xFE)},
    {"ref key state PKP-2600 key 12 (layout)", m2600, 0x15, "195#0008000033",
     pressed(keys({12}), 0x33)},
    {"ref key state PKP-2600 keys 1, 8, 9 (layout)", m2600, 0x15, "195#8101000000",
     pressed(keys({1, 8, 9}), 0x00)},
    {"ref key state PKP-2600 all keys (layout)", m2600, 0x15, "195#FF0F0000C8",
     pressed(span(1, 12), 0xC8)},

    // 11: LED on
    {"PKP 11 PKP-2200 all off", m2200, 0x15, "215#0000000000000000", led_on{}},
    {"PKP 11 PKP-2200 red 1", m2200, 0x15, "215#0100000000000000", led_on{rgb(keys({1}))}},
    {"PKP 11 PKP-2200 red 1, 2", m2200, 0x15, "215#0300000000000000", led_on{rgb(keys({1, 2}))}},
    {"PKP 11 PKP-2200 green 4", m2200, 0x15, "215#8000000000000000", led_on{rgb({}, keys({4}))}},
    {"PKP 11 PKP-2200 blue 1", m2200, 0x15, "215#0001000000000000", led_on{rgb({}, {}, keys({1}))}},
    {"PKP 11 PKP-2200 amber 1, 2, 3", m2200, 0x15, "215#7700000000000000",
     led_on{rgb(span(1, 3), span(1, 3))}},
    {"PKP 11 PKP-2200 white 1, 2", m2200, 0x15, "215#3303000000000000",
     led_on{rgb(span(1, 2), span(1, 2), span(1, 2))}},
    {"PKP 11 PKP-2400 all off", m2400, 0x15, "215#0000000000000000", led_on{}},
    {"PKP 11 PKP-2400 red 1", m2400, 0x15, "215#0100000000000000", led_on{rgb(keys({1}))}},
    {"PKP 11 PKP-2400 red 2, 7", m2400, 0x15, "215#4200000000000000", led_on{rgb(keys({2, 7}))}},
    {"PKP 11 PKP-2400 red 8", m2400, 0x15, "215#8000000000000000", led_on{rgb(keys({8}))}},
    {"PKP 11 PKP-2400 green 5", m2400, 0x15, "215#0010000000000000", led_on{rgb({}, keys({5}))}},
    {"PKP 11 PKP-2400 green 1, 5", m2400, 0x15, "215#0011000000000000",
     led_on{rgb({}, keys({1, 5}))}},
    {"PKP 11 PKP-2400 blue 2, 3", m2400, 0x15, "215#0000060000000000",
     led_on{rgb({}, {}, keys({2, 3}))}},
    {"PKP 11 PKP-2400 one colour per key 1..7", m2400, 0x15, "215#596A740000000000",
     led_on{leds{}
                .set(1, colour::red)
                .set(2, colour::green)
                .set(3, colour::blue)
                .set(4, colour::amber)
                .set(5, colour::magenta)
                .set(6, colour::cyan)
                .set(7, colour::white)}},
    {"PKP 11 PKP-2400 amber 1-4, white 5-8", m2400, 0x15, "215#FFFFF00000000000",
     led_on{rgb(span(1, 8), span(1, 8), span(5, 8))}},
    {"ref LED on PKP-2600 red 12 (layout)", m2600, 0x15, "215#0008000000000000",
     led_on{rgb(keys({12}))}},
    {"ref LED on PKP-2600 green 1 (layout)", m2600, 0x15, "215#0010000000000000",
     led_on{rgb({}, keys({1}))}},
    {"ref LED on PKP-2600 blue 12 (layout)", m2600, 0x15, "215#0000000008000000",
     led_on{rgb({}, {}, keys({12}))}},
    {"ref LED on PKP-2600 white 1 (layout)", m2600, 0x15, "215#0110000100000000",
     led_on{leds{}.set(1, colour::white)}},
    {"ref LED on PKP-2600 all (layout)", m2600, 0x15, "215#FFFFFFFF0F000000",
     led_on{rgb(span(1, 12), span(1, 12), span(1, 12))}},

    // 12: LED blink
    {"PKP 12 PKP-2200 none", m2200, 0x15, "315#0000000000000000", led_blink{}},
    {"PKP 12 PKP-2200 red 1", m2200, 0x15, "315#0100000000000000", led_blink{rgb(keys({1}))}},
    {"PKP 12 PKP-2200 amber 1", m2200, 0x15, "315#1100000000000000",
     led_blink{rgb(keys({1}), keys({1}))}},
    {"PKP 12 PKP-2200 green 4", m2200, 0x15, "315#8000000000000000", led_blink{rgb({}, keys({4}))}},
    {"PKP 12 PKP-2200 blue 1", m2200, 0x15, "315#0001000000000000",
     led_blink{rgb({}, {}, keys({1}))}},
    {"PKP 12 PKP-2200 all magenta", m2200, 0x15, "315#0F0F000000000000",
     led_blink{rgb(span(1, 4), {}, span(1, 4))}},
    {"PKP 12 PKP-2200 white 1", m2200, 0x15, "315#1101000000000000",
     led_blink{leds{}.set(1, colour::white)}},
    {"PKP 12 PKP-2200 alternate 4: on", m2200, 0x15, "215#8000000000000000",
     led_on{rgb({}, keys({4}))}},
    {"PKP 12 PKP-2200 alternate 4: blink", m2200, 0x15, "315#8800000000000000",
     led_blink{rgb(keys({4}), keys({4}))}},
    {"PKP 12 PKP-2400 none", m2400, 0x15, "315#0000000000000000", led_blink{}},
    {"PKP 12 PKP-2400 red 1", m2400, 0x15, "315#0100000000000000", led_blink{rgb(keys({1}))}},
    {"PKP 12 PKP-2400 red 2, 7", m2400, 0x15, "315#4200000000000000", led_blink{rgb(keys({2, 7}))}},
    {"PKP 12 PKP-2400 red 5-8", m2400, 0x15, "315#F000000000000000", led_blink{rgb(span(5, 8))}},
    {"PKP 12 PKP-2400 red 8", m2400, 0x15, "315#8000000000000000", led_blink{rgb(keys({8}))}},
    {"PKP 12 PKP-2400 green 5", m2400, 0x15, "315#0010000000000000", led_blink{rgb({}, keys({5}))}},
    {"PKP 12 PKP-2400 green 1, 5", m2400, 0x15, "315#0011000000000000",
     led_blink{rgb({}, keys({1, 5}))}},
    {"PKP 12 PKP-2400 blue 2, 3", m2400, 0x15, "315#0000060000000000",
     led_blink{rgb({}, {}, keys({2, 3}))}},
    {"PKP 12 PKP-2400 cyan 1, 2, 3", m2400, 0x15, "315#0007070000000000",
     led_blink{rgb({}, span(1, 3), span(1, 3))}},
    {"PKP 12 PKP-2400 alternate 1-6: on", m2400, 0x15, "215#3F00000000000000",
     led_on{rgb(span(1, 6))}},
    {"PKP 12 PKP-2400 alternate 1-6: blink", m2400, 0x15, "315#3F3F000000000000",
     led_blink{rgb(span(1, 6), span(1, 6))}},
    {"ref LED blink PKP-2600 blue 9 (layout)", m2600, 0x15, "315#0000000001000000",
     led_blink{rgb({}, {}, keys({9}))}},

    // 13a: command 01h, set single LED state
    {"PKP 13a LED 8 red", m2400 | m2600, 0x15, "615#2300650101080100", state(8, led_state::red_on)},
    {"PKP 13a reply", pkp, 0x15, "595#6000650100000000", command_ok},
    {"PKP 13a LED 9 green", m2600, 0x15, "615#2300650101090400", state(9, led_state::green_on)},
    {"PKP 13a LED 9 blue (E-PKP-1 corrected)", m2600, 0x15, "615#2300650101090700",
     state(9, led_state::blue_on)},
    {"PKP 13a LED 12 green blink", m2600, 0x15, "615#23006501010C0500",
     state(12, led_state::green_blink)},
    {"PKP 13a LED 12 blue alternate blink", m2600, 0x15, "615#23006501010C0900",
     state(12, led_state::blue_alternate_blink)},
    // 13b: 02h, 03h
    {"PKP 13b LED brightness 25 %", pkp, 0x15, "615#2300650102100000",
     cmd_level(cc::set_led_brightness, 0x10)},
    {"PKP 13b reply", pkp, 0x15, "595#6000650100000000", command_ok},
    {"PKP 13b backlight brightness 75 %", pkp, 0x15, "615#23006501032F0000",
     cmd_level(cc::set_backlight_level, 0x2F)},
    {"PKP 13b reply", pkp, 0x15, "595#6000650100000000", command_ok},
    // 13c-13g
    {"PKP 13c backlight red", pkp, 0x15, "615#2300650104010000",
     cmd_colour(cc::set_backlight_colour, backlight_colour::red)},
    {"PKP 13c reply", pkp, 0x15, "595#6000650100000000", command_ok},
    {"PKP 13d active on start-up", pkp, 0x15, "615#2300650110010000",
     cmd_flag(cc::set_active_on_startup, true)},
    {"PKP 13d reply", pkp, 0x15, "595#6000650100000000", command_ok},
    {"PKP 13e baud 250k", pkp, 0x15, "615#2300650111010000", cmd_baud(baud_rate::kbit_250)},
    {"PKP 13e reply", pkp, 0x15, "595#6000650100000000", command_ok},
    {"PKP 13f periodic 500 ms", pkp, 0x15, "615#2300650112013200", periodic(true, 0x32)},
    {"PKP 13f reply (E-PKP-2 corrected: 595h)", pkp, 0x15, "595#6000650100000000", command_ok},
    {"PKP 13g boot-up service off", pkp, 0x15, "615#2300650113000000",
     cmd_flag(cc::set_boot_up, false)},
    {"PKP 13g reply", pkp, 0x15, "595#6000650100000000", command_ok},
    // 13h: node id 15h -> 18h; the reply from the old id, the boot-up from the new one
    {"PKP 13h new id 18h", pkp, 0x15, "615#2300650170180000", new_node(0x18)},
    {"PKP 13h reply from the old id", pkp, 0x15, "595#6000650100000000", command_ok},
    {"PKP 13h boot-up from the new id", pkp, 0x18, "718#00", hb(nmt_state::boot_up)},
    // 13i-13m
    {"PKP 13i start-up LED level 100 %", pkp, 0x15, "615#230065017C3F0000",
     cmd_level(cc::set_default_led_brightness, 0x3F)},
    {"PKP 13i reply", pkp, 0x15, "595#6000650100000000", command_ok},
    {"PKP 13j start-up backlight off", pkp, 0x15, "615#230065017B000000",
     cmd_level(cc::set_default_backlight_level, 0)},
    {"PKP 13j reply", pkp, 0x15, "595#6000650100000000", command_ok},
    {"PKP 13k start-up backlight red", pkp, 0x15, "615#230065017D010000",
     cmd_colour(cc::set_default_backlight_colour, backlight_colour::red)},
    {"PKP 13k reply", pkp, 0x15, "595#6000650100000000", command_ok},
    {"PKP 13l demo mode on", pkp, 0x15, "615#230065017A010000", cmd_flag(cc::set_demo_mode, true)},
    {"PKP 13l reply", pkp, 0x15, "595#6000650100000000", command_ok},
    {"PKP 13m start-up show disabled", pkp, 0x15, "615#2300650150030000",
     show(startup_show::disabled)},
    {"PKP 13m reply", pkp, 0x15, "595#6000650100000000", command_ok},

    // 14: 6000h key states
    {"PKP 14 PKP-2200 read", m2200, 0x15, "615#4000600000000000", read(object::keys)},
    {"PKP 14 PKP-2200 no key", m2200, 0x15, "595#4300600000000000", key_reply({})},
    {"PKP 14 PKP-2200 key 1", m2200, 0x15, "595#4300600001000000", key_reply(keys({1}))},
    {"PKP 14 PKP-2200 key 2", m2200, 0x15, "595#4300600002000000", key_reply(keys({2}))},
    {"PKP 14 PKP-2200 key 3", m2200, 0x15, "595#4300600004000000", key_reply(keys({3}))},
    {"PKP 14 PKP-2200 key 4", m2200, 0x15, "595#4300600008000000", key_reply(keys({4}))},
    {"PKP 14 PKP-2200 keys 1, 2", m2200, 0x15, "595#4300600003000000", key_reply(keys({1, 2}))},
    {"PKP 14 PKP-2200 keys 2, 4", m2200, 0x15, "595#430060000A000000", key_reply(keys({2, 4}))},
    {"PKP 14 PKP-2200 keys 1, 2, 3", m2200, 0x15, "595#4300600007000000", key_reply(span(1, 3))},
    {"PKP 14 PKP-2200 all keys", m2200, 0x15, "595#430060000F000000", key_reply(span(1, 4))},
    {"PKP 14 PKP-2400 read", m2400, 0x15, "615#4000600000000000", read(object::keys)},
    {"PKP 14 PKP-2400 no key", m2400, 0x15, "595#4300600000000000", key_reply({})},
    {"PKP 14 PKP-2400 key 1", m2400, 0x15, "595#4300600001000000", key_reply(keys({1}))},
    {"PKP 14 PKP-2400 key 2", m2400, 0x15, "595#4300600002000000", key_reply(keys({2}))},
    {"PKP 14 PKP-2400 key 3", m2400, 0x15, "595#4300600004000000", key_reply(keys({3}))},
    {"PKP 14 PKP-2400 key 4", m2400, 0x15, "595#4300600008000000", key_reply(keys({4}))},
    {"PKP 14 PKP-2400 key 5", m2400, 0x15, "595#4300600010000000", key_reply(keys({5}))},
    {"PKP 14 PKP-2400 key 6", m2400, 0x15, "595#4300600020000000", key_reply(keys({6}))},
    {"PKP 14 PKP-2400 key 7", m2400, 0x15, "595#4300600040000000", key_reply(keys({7}))},
    {"PKP 14 PKP-2400 key 8", m2400, 0x15, "595#4300600080000000", key_reply(keys({8}))},
    {"PKP 14 PKP-2400 keys 1, 2", m2400, 0x15, "595#4300600003000000", key_reply(keys({1, 2}))},
    {"PKP 14 PKP-2400 keys 1, 8", m2400, 0x15, "595#4300600081000000", key_reply(keys({1, 8}))},
    {"PKP 14 PKP-2400 keys 2, 6", m2400, 0x15, "595#4300600022000000", key_reply(keys({2, 6}))},
    {"PKP 14 PKP-2400 all keys", m2400, 0x15, "595#43006000FF000000", key_reply(span(1, 8))},
    {"ref 6000h PKP-2600 read", m2600, 0x15, "615#4000600000000000", read(object::keys)},
    {"ref 6000h PKP-2600 keys 9, 12 (bytes 4-5)", m2600, 0x15, "595#4300600000090000",
     key_reply(keys({9, 12}))},
    {"ref 6000h PKP-2600 all keys (bytes 4-5)", m2600, 0x15, "595#43006000FF0F0000",
     key_reply(span(1, 12))},

    // 15: 6001h LED on
    {"PKP 15a PKP-2200 all off", m2200, 0x15, "615#2301600000000000", write_on({})},
    {"PKP 15a PKP-2200 reply", m2200, 0x15, "595#6001600000000000", written(object::led_on)},
    {"PKP 15a PKP-2200 green 4", m2200, 0x15, "615#2301600080000000", write_on(rgb({}, keys({4})))},
    {"PKP 15a PKP-2200 reply", m2200, 0x15, "595#6001600000000000", written(object::led_on)},
    {"PKP 15a PKP-2200 red 3", m2200, 0x15, "615#2301600004000000", write_on(rgb(keys({3})))},
    {"PKP 15a PKP-2200 reply", m2200, 0x15, "595#6001600000000000", written(object::led_on)},
    {"PKP 15a PKP-2400 all off", m2400, 0x15, "615#2301600000000000", write_on({})},
    {"PKP 15a PKP-2400 reply", m2400, 0x15, "595#6001600000000000", written(object::led_on)},
    {"PKP 15a PKP-2400 green 1", m2400, 0x15, "615#2301600000010000", write_on(rgb({}, keys({1})))},
    {"PKP 15a PKP-2400 reply", m2400, 0x15, "595#6001600000000000", written(object::led_on)},
    {"PKP 15b PKP-2200 read", m2200, 0x15, "615#4001600000000000", read(object::led_on)},
    {"PKP 15b PKP-2200 all red", m2200, 0x15, "595#430160000F000000", reply_on(rgb(span(1, 4)))},
    {"PKP 15b PKP-2200 read", m2200, 0x15, "615#4001600000000000", read(object::led_on)},
    {"PKP 15b PKP-2200 red 4", m2200, 0x15, "595#4301600008000000", reply_on(rgb(keys({4})))},
    {"PKP 15b PKP-2200 read", m2200, 0x15, "615#4001600000000000", read(object::led_on)},
    {"PKP 15b PKP-2200 green 2", m2200, 0x15, "595#4301600020000000", reply_on(rgb({}, keys({2})))},
    {"PKP 15b PKP-2200 read", m2200, 0x15, "615#4001600000000000", read(object::led_on)},
    {"PKP 15b PKP-2200 all green", m2200, 0x15, "595#43016000F0000000",
     reply_on(rgb({}, span(1, 4)))},
    {"PKP 15b PKP-2200 read", m2200, 0x15, "615#4001600000000000", read(object::led_on)},
    {"PKP 15b PKP-2200 all blue", m2200, 0x15, "595#43016000000F0000",
     reply_on(rgb({}, {}, span(1, 4)))},
    {"PKP 15b PKP-2400 read", m2400, 0x15, "615#4001600000000000", read(object::led_on)},
    {"PKP 15b PKP-2400 all red", m2400, 0x15, "595#43016000FF000000", reply_on(rgb(span(1, 8)))},
    {"PKP 15b PKP-2400 read", m2400, 0x15, "615#4001600000000000", read(object::led_on)},
    {"PKP 15b PKP-2400 red 1", m2400, 0x15, "595#4301600001000000", reply_on(rgb(keys({1})))},
    {"PKP 15b PKP-2400 read", m2400, 0x15, "615#4001600000000000", read(object::led_on)},
    {"PKP 15b PKP-2400 red 2", m2400, 0x15, "595#4301600002000000", reply_on(rgb(keys({2})))},
    {"PKP 15b PKP-2400 read", m2400, 0x15, "615#4001600000000000", read(object::led_on)},
    {"PKP 15b PKP-2400 all green", m2400, 0x15, "595#4301600000FF0000",
     reply_on(rgb({}, span(1, 8)))},
    {"PKP 15b PKP-2400 read", m2400, 0x15, "615#4001600000000000", read(object::led_on)},
    {"PKP 15b PKP-2400 all blue", m2400, 0x15, "595#430160000000FF00",
     reply_on(rgb({}, {}, span(1, 8)))},
    {"ref 6001h PKP-2600 all off", m2600, 0x15, "615#2301600000000000", write_on({})},
    {"ref 6001h PKP-2600 reply", m2600, 0x15, "595#6001600000000000", written(object::led_on)},
    {"ref 6001h PKP-2600 red 8", m2600, 0x15, "615#2301600080000000", write_on(rgb(keys({8})))},
    {"ref 6001h PKP-2600 red 7, green 3, green 11", m2600, 0x15, "615#2301600040404000",
     write_on(rgb(keys({7}), keys({3, 11})))},
    {"ref 6001h PKP-2600 read", m2600, 0x15, "615#4001600000000000", read(object::led_on)},
    {"ref 6001h PKP-2600 read reply red 12, green 1 (layout)", m2600, 0x15, "595#4301600000180000",
     reply_on(rgb(keys({12}), keys({1})))},

    // 16: 6002h LED blink
    {"PKP 16a PKP-2200 none", m2200, 0x15, "615#2302600000000000", write_blink({})},
    {"PKP 16a PKP-2200 reply", m2200, 0x15, "595#6002600000000000", written(object::led_blink)},
    {"PKP 16a PKP-2200 red 4", m2200, 0x15, "615#2302600008000000", write_blink(rgb(keys({4})))},
    {"PKP 16a PKP-2200 reply", m2200, 0x15, "595#6002600000000000", written(object::led_blink)},
    {"PKP 16a PKP-2200 green 1", m2200, 0x15, "615#2302600010000000",
     write_blink(rgb({}, keys({1})))},
    {"PKP 16a PKP-2200 reply", m2200, 0x15, "595#6002600000000000", written(object::led_blink)},
    {"PKP 16a PKP-2400 none", m2400, 0x15, "615#2302600000000000", write_blink({})},
    {"PKP 16a PKP-2400 reply", m2400, 0x15, "595#6002600000000000", written(object::led_blink)},
    {"PKP 16a PKP-2400 red 1", m2400, 0x15, "615#2302600001000000", write_blink(rgb(keys({1})))},
    {"PKP 16a PKP-2400 reply", m2400, 0x15, "595#6002600000000000", written(object::led_blink)},
    {"PKP 16a PKP-2400 all green", m2400, 0x15, "615#2302600000FF0000",
     write_blink(rgb({}, span(1, 8)))},
    {"PKP 16a PKP-2400 reply", m2400, 0x15, "595#6002600000000000", written(object::led_blink)},
    {"PKP 16b PKP-2200 read", m2200, 0x15, "615#4002600000000000", read(object::led_blink)},
    {"PKP 16b PKP-2200 all amber", m2200, 0x15, "595#43026000FF000000",
     reply_blink(rgb(span(1, 4), span(1, 4)))},
    {"PKP 16b PKP-2200 read", m2200, 0x15, "615#4002600000000000", read(object::led_blink)},
    {"PKP 16b PKP-2200 red 1, green 4", m2200, 0x15, "595#4302600081000000",
     reply_blink(rgb(keys({1}), keys({4})))},
    {"PKP 16b PKP-2200 read", m2200, 0x15, "615#4002600000000000", read(object::led_blink)},
    {"PKP 16b PKP-2200 red 4", m2200, 0x15, "595#4302600008000000", reply_blink(rgb(keys({4})))},
    {"PKP 16b PKP-2400 read", m2400, 0x15, "615#4002600000000000", read(object::led_blink)},
    {"PKP 16b PKP-2400 all red", m2400, 0x15, "595#43026000FF000000", reply_blink(rgb(span(1, 8)))},
    {"PKP 16b PKP-2400 read", m2400, 0x15, "615#4002600000000000", read(object::led_blink)},
    {"PKP 16b PKP-2400 all green", m2400, 0x15, "595#4302600000FF0000",
     reply_blink(rgb({}, span(1, 8)))},
    {"PKP 16b PKP-2400 read", m2400, 0x15, "615#4002600000000000", read(object::led_blink)},
    {"PKP 16b PKP-2400 green 1", m2400, 0x15, "595#4302600000010000",
     reply_blink(rgb({}, keys({1})))},
    {"ref 6002h PKP-2600 red 5, green 2, green 11", m2600, 0x15, "615#2302600010204000",
     write_blink(rgb(keys({5}), keys({2, 11})))},
    {"ref 6002h PKP-2600 reply", m2600, 0x15, "595#6002600000000000", written(object::led_blink)},
    {"ref 6002h PKP-2600 green 5, 7", m2600, 0x15, "615#2302600000000500",
     write_blink(rgb({}, keys({5, 7})))},
    {"ref 6002h PKP-2600 reply", m2600, 0x15, "595#6002600000000000", written(object::led_blink)},

    // 17: 1017h heartbeat time
    {"PKP 17 read", pkp, 0x15, "615#4017100000000000", read(object::heartbeat_time)},
    {"PKP 17 100 ms", pkp, 0x15, "595#4B17100064000000", value(object::heartbeat_time, 100)},
    {"PKP 17 off", pkp, 0x15, "615#2B17100000000000", write(object::heartbeat_time, 0)},
    {"PKP 17 reply", pkp, 0x15, "595#6017100000000000", written(object::heartbeat_time)},
    {"PKP 17 50 ms", pkp, 0x15, "615#2B17100032000000", write(object::heartbeat_time, 50)},
    {"PKP 17 reply", pkp, 0x15, "595#6017100000000000", written(object::heartbeat_time)},
    {"PKP 17 500 ms", pkp, 0x15, "615#2B171000F4010000", write(object::heartbeat_time, 500)},
    {"PKP 17 reply", pkp, 0x15, "595#6017100000000000", written(object::heartbeat_time)},

    // 18: 1000h device type
    {"PKP 18 read", pkp, 0x15, "615#4000100000000000", read(object::device_type)},
    {"PKP 18 profile 30191h", pkp, 0x15, "595#4300100091010300",
     value(object::device_type, 0x30191)},

    // 19-22: strings, frame by frame (the core reader joins them)
    {"PKP 19 read 1008h", pkp, 0x15, "615#4008100000000000", read(object::device_name)},
    {"PKP 19 11 bytes", pkp, 0x15, "595#410810000B000000", initiate(0x1008, 0, true, 11)},
    {"PKP 19 next (toggle 0)", pkp, 0x15, "615#6000000000000000", next(false)},
    {"PKP 19 BlinkMa", pkp, 0x15, "595#00426C696E6B4D61",
     segment(false, 0, false, {0x42, 0x6C, 0x69, 0x6E, 0x6B, 0x4D, 0x61})},
    {"PKP 19 next (toggle 1)", pkp, 0x15, "615#7000000000000000", next(true)},
    {"PKP 19 rine, last", pkp, 0x15, "595#1772696E65000000",
     segment(true, 3, true, {0x72, 0x69, 0x6E, 0x65, 0, 0, 0})},
    {"PKP 20 read 1009h", pkp, 0x15, "615#4009100000000000", read(object::hardware_version)},
    {"PKP 20 10 bytes", pkp, 0x15, "595#410910000A000000", initiate(0x1009, 0, true, 10)},
    {"PKP 20 next", pkp, 0x15, "615#6000000000000000", next(false)},
    {"PKP 20 Rev 1.0", pkp, 0x15, "595#0052657620312E30",
     segment(false, 0, false, {0x52, 0x65, 0x76, 0x20, 0x31, 0x2E, 0x30})},
    {"PKP 20 next", pkp, 0x15, "615#7000000000000000", next(true)},
    {"PKP 20 NUL D NUL, last (E-CORE-5)", pkp, 0x15, "595#1900440000000000",
     segment(true, 4, true, {0x00, 0x44, 0x00, 0, 0, 0, 0})},
    {"PKP 21 read 100Ah", pkp, 0x15, "615#400A100000000000", read(object::software_version)},
    {"PKP 21 10 bytes", pkp, 0x15, "595#410A10000A000000", initiate(0x100A, 0, true, 10)},
    {"PKP 21 next", pkp, 0x15, "615#6000000000000000", next(false)},
    {"PKP 21 Rev 1.0", pkp, 0x15, "595#0052657620312E30",
     segment(false, 0, false, {0x52, 0x65, 0x76, 0x20, 0x31, 0x2E, 0x30})},
    {"PKP 21 next", pkp, 0x15, "615#7000000000000000", next(true)},
    {"PKP 21 NUL R NUL, last (E-CORE-5)", pkp, 0x15, "595#1900520000000000",
     segment(true, 4, true, {0x00, 0x52, 0x00, 0, 0, 0, 0})},
    {"PKP 22 read 100Bh", pkp, 0x15, "615#400B100000000000", read(object::model_name)},
    {"PKP 22 7 bytes (E-CORE-2)", pkp, 0x15, "595#410B100007000000", initiate(0x100B, 0, true, 7)},
    {"PKP 22 next", pkp, 0x15, "615#6000000000000000", next(false)},
    {"PKP 22 PKU2400", pkp, 0x15, "595#00504B5532343030",
     segment(false, 0, false, {0x50, 0x4B, 0x55, 0x32, 0x34, 0x30, 0x30})},
    {"PKP 22 next", pkp, 0x15, "615#7000000000000000", next(true)},
    {"PKP 22 NUL, last (E-CORE-2)", pkp, 0x15, "595#1D00000000000000",
     segment(true, 6, true, {0, 0, 0, 0, 0, 0, 0})},

    // 23: 1018h identity
    {"PKP 23 read sub 0", pkp, 0x15, "615#4018100000000000", read(object::identity_count)},
    {"PKP 23 4 entries", pkp, 0x15, "595#4F18100004000000", value(object::identity_count, 4)},
    {"PKP 23 read vendor id", pkp, 0x15, "615#4018100100000000", read(object::vendor_id)},
    {"PKP 23 vendor 35Ah", pkp, 0x15, "595#431810015A030000", value(object::vendor_id, 0x35A)},
    {"PKP 23 read product code", pkp, 0x15, "615#4018100200000000", read(object::product_code)},
    {"PKP 23 product code 0", pkp, 0x15, "595#4318100200000000", value(object::product_code, 0)},
    {"PKP 23 read revision", pkp, 0x15, "615#4018100300000000", read(object::revision_number)},
    {"PKP 23 app 10h, com 16h, hw 12h", pkp, 0x15, "595#4318100310161200",
     value(object::revision_number, 0x00121610)},
    {"PKP 23 read checksum", pkp, 0x15, "615#4018100400000000", read(object::firmware_checksum)},
    {"PKP 23 checksum 002CE5DEh", pkp, 0x15, "595#43181004DEE52C00",
     value(object::firmware_checksum, 0x002CE5DE)},

    // 24-28: PDO parameters (E-PKP-5: sizes and values as printed)
    {"PKP 24 read 1400h/0", pkp, 0x15, "615#4000140000000000", read(object::rpdo1_count)},
    {"PKP 24 2", pkp, 0x15, "595#4F00140002000000", value(object::rpdo1_count, 2)},
    {"PKP 24 read 1400h/1", pkp, 0x15, "615#4000140100000000", read(object::rpdo1_cob_id)},
    {"PKP 24 200h", pkp, 0x15, "595#4B00140100020000", value(object::rpdo1_cob_id, 0x200)},
    {"PKP 24 read 1400h/3", pkp, 0x15, "615#4000140300000000", read(object::rpdo1_inhibit_time)},
    {"PKP 24 0", pkp, 0x15, "595#4B00140300000000", value(object::rpdo1_inhibit_time, 0)},
    {"PKP 25 read 1401h/0", pkp, 0x15, "615#4001140000000000", read(object::rpdo2_count)},
    {"PKP 25 2", pkp, 0x15, "595#4F01140002000000", value(object::rpdo2_count, 2)},
    {"PKP 25 read 1401h/1", pkp, 0x15, "615#4001140100000000", read(object::rpdo2_cob_id)},
    {"PKP 25 300h", pkp, 0x15, "595#4B01140100030000", value(object::rpdo2_cob_id, 0x300)},
    {"PKP 25 read 1401h/3", pkp, 0x15, "615#4001140300000000", read(object::rpdo2_inhibit_time)},
    {"PKP 25 0", pkp, 0x15, "595#4B01140300000000", value(object::rpdo2_inhibit_time, 0)},
    {"PKP 26 read 1600h/0", pkp, 0x15, "615#4000160000000000", read(object::rpdo1_mapping_count)},
    {"PKP 26 2", pkp, 0x15, "595#4F00160002000000", value(object::rpdo1_mapping_count, 2)},
    {"PKP 26 read 1600h/1", pkp, 0x15, "615#4000160100000000", read(object::rpdo1_mapping_1)},
    {"PKP 26 6001 00 20h", pkp, 0x15, "595#4300160120000160",
     value(object::rpdo1_mapping_1, 0x60010020)},
    {"PKP 26 read 1600h/2", pkp, 0x15, "615#4000160200000000", read(object::rpdo1_mapping_2)},
    {"PKP 26 6002 00 20h", pkp, 0x15, "595#4300160220000260",
     value(object::rpdo1_mapping_2, 0x60020020)},
    {"PKP 27 read 1800h/0", pkp, 0x15, "615#4000180000000000", read(object::tpdo1_count)},
    {"PKP 27 2", pkp, 0x15, "595#4F00180002000000", value(object::tpdo1_count, 2)},
    {"PKP 27 read 1800h/1", pkp, 0x15, "615#4000180100000000", read(object::tpdo1_cob_id)},
    {"PKP 27 180h", pkp, 0x15, "595#4B00180180010000", value(object::tpdo1_cob_id, 0x180)},
    {"PKP 27 read 1800h/2", pkp, 0x15, "615#4000180200000000",
     read(object::tpdo1_transmission_type)},
    {"PKP 27 async RTR only", pkp, 0x15, "595#4B001802FD000000",
     value(object::tpdo1_transmission_type, 0xFD)},
    {"PKP 27 read 1800h/3", pkp, 0x15, "615#4000180300000000", read(object::tpdo1_inhibit_time)},
    {"PKP 27 0", pkp, 0x15, "595#4B00180300000000", value(object::tpdo1_inhibit_time, 0)},
    {"PKP 27 read 1800h/5", pkp, 0x15, "615#4000180500000000", read(object::tpdo1_event_timer)},
    {"PKP 27 event timer off", pkp, 0x15, "595#4B00180500000000",
     value(object::tpdo1_event_timer, 0)},
    {"PKP 28 read 1A00h/0", pkp, 0x15, "615#40001A0000000000", read(object::tpdo1_mapping_count)},
    {"PKP 28 1", pkp, 0x15, "595#4F001A0001000000", value(object::tpdo1_mapping_count, 1)},
    {"PKP 28 read 1A00h/1", pkp, 0x15, "615#40001A0100000000", read(object::tpdo1_mapping_1)},
    {"PKP 28 6000 00 20h", pkp, 0x15, "595#43001A0120000060",
     value(object::tpdo1_mapping_1, 0x60000020)},

    // 29: 6100h
    {"PKP 29 read sub 0", pkp, 0x15, "615#4000610000000000", read(object::firmware_spec_count)},
    {"PKP 29 2", pkp, 0x15, "595#4F00610002000000", value(object::firmware_spec_count, 2)},
    {"PKP 29 read serial", pkp, 0x15, "615#4000610100000000", read(object::serial_number)},
    {"PKP 29 serial 0", pkp, 0x15, "595#4300610100000000", value(object::serial_number, 0)},
    {"PKP 29 read model id", pkp, 0x15, "615#4000610200000000", read(object::device_model)},
    {"PKP 29 40h, size not indicated (E-CORE-3)", pkp, 0x15, "595#4000610208000000",
     initiate(0x6100, 2, false, 8)},
    {"PKP 29 next", pkp, 0x15, "615#6000000000000000", next(false)},
    {"PKP 29 PKU2400", pkp, 0x15, "595#00504B5532343030",
     segment(false, 0, false, {0x50, 0x4B, 0x55, 0x32, 0x34, 0x30, 0x30})},
    {"PKP 29 next", pkp, 0x15, "615#7000000000000000", next(true)},
    {"PKP 29 NUL, last", pkp, 0x15, "595#1D00000000000000",
     segment(true, 6, true, {0, 0, 0, 0, 0, 0, 0})},

    // 30: 6201h brightness
    {"PKP 30 read key-LED level", pkp, 0x15, "615#4001620100000000", read(object::led_brightness)},
    {"PKP 30 3Fh", pkp, 0x15, "595#4F0162013F000000", value(object::led_brightness, 0x3F)},
    {"PKP 30 read backlight level", pkp, 0x15, "615#4001620200000000",
     read(object::backlight_level)},
    {"PKP 30 0", pkp, 0x15, "595#4F01620200000000", value(object::backlight_level, 0)},
    {"PKP 30 set key-LED 25 %", pkp, 0x15, "615#2F01620110000000",
     write(object::led_brightness, 0x10)},
    {"PKP 30 reply", pkp, 0x15, "595#6001620100000000", written(object::led_brightness)},
    {"PKP 30 set backlight 50 %", pkp, 0x15, "615#2F01620220000000",
     write(object::backlight_level, 0x20)},
    {"PKP 30 reply", pkp, 0x15, "595#6001620200000000", written(object::backlight_level)},

    // 31: 6300h serial number string
    {"PKP 31 read (E-CORE-4 corrected: 40h)", pkp, 0x15, "615#4000630000000000",
     read(object::serial_number_string)},
    {"PKP 31 6 bytes (E-CORE-4)", pkp, 0x15, "595#4100630006000000", initiate(0x6300, 0, true, 6)},
    {"PKP 31 next", pkp, 0x15, "615#6000000000000000", next(false)},
    {"PKP 31 000000 NUL", pkp, 0x15, "595#0030303030303000",
     segment(false, 0, false, {0x30, 0x30, 0x30, 0x30, 0x30, 0x30, 0x00})},
    {"PKP 31 next", pkp, 0x15, "615#7000000000000000", next(true)},
    {"PKP 31 NUL, last", pkp, 0x15, "595#1D00000000000000",
     segment(true, 6, true, {0, 0, 0, 0, 0, 0, 0})},

    // 32: 6301h, 6302h
    {"PKP 32 read bootloader", pkp, 0x15, "615#4001630000000000", read(object::bootloader_present)},
    {"PKP 32 not present", pkp, 0x15, "595#4F01630000000000", value(object::bootloader_present, 0)},
    {"PKP 32 read bootloader", pkp, 0x15, "615#4001630000000000", read(object::bootloader_present)},
    {"PKP 32 present", pkp, 0x15, "595#4F01630001000000", value(object::bootloader_present, 1)},
    {"PKP 32 6302h read sub 0", pkp, 0x15, "615#4002630000000000",
     read(object::key_led_count_count)},
    {"PKP 32 6302h 2 (E-PKP-6)", pkp, 0x15, "595#4F02630002000000",
     value(object::key_led_count_count, 2)},
    {"PKP 32 6302h read keys", pkp, 0x15, "615#4002630100000000", read(object::total_keys)},
    {"PKP 32 6302h 4 keys", pkp, 0x15, "595#4F02630104000000", value(object::total_keys, 4)},
    {"PKP 32 6302h read external keys", pkp, 0x15, "615#4002630200000000",
     read(object::external_keys)},
    {"PKP 32 6302h 0 external keys", pkp, 0x15, "595#4F02630200000000",
     value(object::external_keys, 0)},
    {"PKP 32 6302h read LEDs", pkp, 0x15, "615#4002630300000000", read(object::total_leds)},
    {"PKP 32 6302h 12 LEDs", pkp, 0x15, "595#4F0263030C000000", value(object::total_leds, 12)},
    {"PKP 32 6302h read external LEDs", pkp, 0x15, "615#4002630400000000",
     read(object::external_leds)},
    {"PKP 32 6302h 6 external LEDs", pkp, 0x15, "595#4F02630406000000",
     value(object::external_leds, 6)},
};

// --- frames that must be refused -----------------------------------------------------------------

inline constexpr error_row error_rows[] = {
    // errata: the frames as the manual prints them
    {"E-PKP-1 PKP 13a reply printed with data", pkp, 0x15, "595#6000650100090700",
     errc::reserved_not_zero},
    {"E-PKP-2 PKP 13f reply printed on 195h", pkp, 0x15, "195#6000650100000000",
     errc::wrong_length},
    {"E-PKP-3 PKP 13h node id 00h", pkp, 0x15, "615#2300650170000000", errc::value_out_of_range},
    {"E-CORE-4 PKP 31 request printed 41h", pkp, 0x15, "615#4100630000000000",
     errc::reserved_not_zero},
    // a key the model lacks (PKP 13a)
    {"PKP 13a LED 8 on a PKP-2200", m2200, 0x15, "615#2300650101080100", errc::value_out_of_range},
    {"PKP 13a LED 9 on a PKP-2200/2400", m2200 | m2400, 0x15, "615#2300650101090400",
     errc::value_out_of_range},
    {"PKP 13a LED 12 on a PKP-2200/2400", m2200 | m2400, 0x15, "615#23006501010C0500",
     errc::value_out_of_range},
    {"PKP 13a LED 0", pkp, 0x15, "615#2300650101000100", errc::value_out_of_range},
    {"PKP 13a LED 13", m2600, 0x15, "615#23006501010D0100", errc::value_out_of_range},
    // command parameters outside their ranges
    {"PKP 13a state 0Bh", pkp, 0x15, "615#2300650101010B00", errc::value_out_of_range},
    {"PKP 13a state 0Fh", pkp, 0x15, "615#2300650101010F00", errc::value_out_of_range},
    {"PKP 13b level 40h", pkp, 0x15, "615#2300650102400000", errc::value_out_of_range},
    {"PKP 13b backlight level 40h", pkp, 0x15, "615#2300650103400000", errc::value_out_of_range},
    {"PKP 13c colour 00h", pkp, 0x15, "615#2300650104000000", errc::value_out_of_range},
    {"PKP 13c colour 0Ah", pkp, 0x15, "615#23006501040A0000", errc::value_out_of_range},
    {"PKP 13d 02h", pkp, 0x15, "615#2300650110020000", errc::value_out_of_range},
    {"PKP 13e baud 03h", pkp, 0x15, "615#2300650111030000", errc::value_out_of_range},
    {"PKP 13f on 02h", pkp, 0x15, "615#2300650112023200", errc::value_out_of_range},
    {"PKP 13h node 80h", pkp, 0x15, "615#2300650170800000", errc::value_out_of_range},
    {"PKP 13m show 00h", pkp, 0x15, "615#2300650150000000", errc::value_out_of_range},
    {"PKP 13m show 04h", pkp, 0x15, "615#2300650150040000", errc::value_out_of_range},
    {"PKP 13k colour 0Ah", pkp, 0x15, "615#230065017D0A0000", errc::value_out_of_range},
    // command bytes and sizes
    {"PKP 13 command 99h", pkp, 0x15, "615#2300650199000000", errc::unknown_command},
    {"PKP 13 command 00h", pkp, 0x15, "615#2300650100000000", errc::unknown_command},
    {"PKP 13 command 99h, byte 7 set: the command is checked first", pkp, 0x15,
     "615#2300650199000001", errc::unknown_command},
    {"PKP 13 byte 7 not 00h", pkp, 0x15, "615#2300650102100001", errc::reserved_not_zero},
    {"PKP 13 byte 6 of a one-parameter command", pkp, 0x15, "615#2300650102100100",
     errc::reserved_not_zero},
    {"PKP 13 a 3-byte download (27h)", pkp, 0x15, "615#2700650101010100", errc::size_mismatch},
    {"PKP 13 read of 6500h/1", pkp, 0x15, "615#4000650100000000", errc::unknown_command},
    {"PKP 13 6500h sub 2", pkp, 0x15, "615#2300650201010100", errc::unknown_object},
    // objects
    {"unknown object 7000h", pkp, 0x15, "615#4000700000000000", errc::unknown_object},
    {"unknown sub-index 1018h/5", pkp, 0x15, "615#4018100500000000", errc::unknown_object},
    {"write to read-only 1000h", pkp, 0x15, "615#2300100091010300", errc::unknown_command},
    {"write reply for read-only 1000h", pkp, 0x15, "595#6000100000000000", errc::unknown_command},
    // (an expedited reply of string 1008h, 595#4308100042000000, was refused here before issue 10:
    // one rule for both dictionaries now accepts it, tests/test_keypad_codec_pkp.cpp)
    {"segmented reply for number 1000h", pkp, 0x15, "595#4100100004000000", errc::unknown_object},
    {"PKP 17 heartbeat 5 ms", pkp, 0x15, "615#2B17100005000000", errc::value_out_of_range},
    {"PKP 17 heartbeat in 4 bytes", pkp, 0x15, "615#2317100064000000", errc::size_mismatch},
    {"PKP 17 reply in 1 byte", pkp, 0x15, "595#4F17100064000000", errc::size_mismatch},
    {"PKP 17 byte past the size", pkp, 0x15, "595#4B17100064000100", errc::reserved_not_zero},
    {"PKP 30 level 40h", pkp, 0x15, "615#2F01620140000000", errc::value_out_of_range},
    {"PKP 32 bootloader 02h", pkp, 0x15, "595#4F01630002000000", errc::value_out_of_range},
    {"PKP 14 a 2-byte keys reply", pkp, 0x15, "595#4B00600001000000", errc::size_mismatch},
    {"PKP 15 a 3-byte LED write", pkp, 0x15, "615#2701600001000000", errc::size_mismatch},
    // bits that name no key or LED of the model
    {"PKP 14 PKP-2200 key 5", m2200, 0x15, "595#4300600010000000", errc::reserved_not_zero},
    {"PKP 14 PKP-2400 key 9", m2400, 0x15, "595#4300600000010000", errc::reserved_not_zero},
    {"ref 6000h PKP-2600 key 13", m2600, 0x15, "595#4300600000100000", errc::reserved_not_zero},
    {"PKP 15 PKP-2200 byte 5 high nibble", m2200, 0x15, "615#2301600000100000",
     errc::reserved_not_zero},
    {"PKP 15 PKP-2200/2400 byte 7", m2200 | m2400, 0x15, "615#2301600000000001",
     errc::reserved_not_zero},
    {"ref 6001h PKP-2600 byte 7 (no blue)", m2600, 0x15, "615#2301600000000001",
     errc::reserved_not_zero},
    {"PKP 10 PKP-2200 key 5", m2200, 0x15, "195#1000000000", errc::reserved_not_zero},
    {"PKP 10 PKP-2400 byte 1", m2400, 0x15, "195#0001000000", errc::reserved_not_zero},
    {"PKP 10 byte 2", pkp, 0x15, "195#0000010000", errc::reserved_not_zero},
    {"PKP 11 PKP-2200 byte 1 high nibble", m2200, 0x15, "215#0010000000000000",
     errc::reserved_not_zero},
    {"PKP 11 PKP-2200 byte 2", m2200, 0x15, "215#0000010000000000", errc::reserved_not_zero},
    {"PKP 11 PKP-2400 byte 3", m2400, 0x15, "215#0000000100000000", errc::reserved_not_zero},
    {"ref PKP-2600 byte 4 high nibble", m2600, 0x15, "215#0000000010000000",
     errc::reserved_not_zero},
    {"PKP 12 byte 7", pkp, 0x15, "315#0000000000000001", errc::reserved_not_zero},
    // identifiers and lengths
    {"another node's SDO", pkp, 0x15, "616#4000100000000000", errc::wrong_id},
    {"another node's PDO", pkp, 0x15, "216#0000000000000000", errc::wrong_id},
    {"another node's heartbeat", pkp, 0x15, "716#05", errc::wrong_id},
    {"RPDO3, not used by the PKP", pkp, 0x15, "415#0000000000000000", errc::wrong_id},
    {"EMCY 080h + node", pkp, 0x15, "095#0000000000000000", errc::wrong_id},
    {"a 29-bit identifier (a PGN no keypad uses)", pkp, 0x15, "00000615#4000100000000000",
     errc::wrong_id},
    {"key state of 4 bytes", pkp, 0x15, "195#00000000", errc::wrong_length},
    {"LED on of 3 bytes", pkp, 0x15, "215#000000", errc::wrong_length},
    {"LED blink of 1 byte", pkp, 0x15, "315#00", errc::wrong_length},
    {"SDO of 7 bytes", pkp, 0x15, "615#40001000000000", errc::wrong_length},
    {"NMT of 8 bytes (E-CORE-6)", pkp, 0x15, "000#0115000000000000", errc::wrong_length},
    {"NMT command 03h", pkp, 0x15, "000#0315", errc::unknown_command},
    {"heartbeat 01h", pkp, 0x15, "715#01", errc::value_out_of_range},
    {"SYNC with data", pkp, 0x15, "080#00", errc::wrong_length},
};

// --- messages that must not encode ------------------------------------------------------------
// Issue 10: an encoder never builds a frame its decoder refuses. Each row: the message, the frame
// its raw fields would give (decode refuses it or reads another meaning; "" for no frame), the
// error encode returns (the one decode gives that frame, value_out_of_range when the frame reads
// back as another meaning, unknown_object for an object the dictionary lacks).

// A command with a raw parameter byte, and members its row does not carry.
constexpr message raw_state(std::uint8_t key, std::uint8_t s) noexcept {
    return state(key, static_cast<led_state>(s));
}
constexpr message with_key(message m, std::uint8_t key) noexcept {
    auto c = std::get<command>(m);
    c.key = key;
    return c;
}

inline constexpr encode_error_row encode_error_rows[] = {
    // keys and LEDs the model lacks
    {"LED 9 on a PKP-2400", m2400, 0x15, "615#2300650101090100", state(9, led_state::red_on),
     errc::value_out_of_range},
    {"LED 5 on a PKP-2200", m2200, 0x15, "615#2300650101050100", state(5, led_state::red_on),
     errc::value_out_of_range},
    {"LED 13 on a PKP-2600", m2600, 0x15, "615#23006501010D0100", state(13, led_state::red_on),
     errc::value_out_of_range},
    {"LED 0", pkp, 0x15, "615#2300650101000100", state(0, led_state::red_on),
     errc::value_out_of_range},
    {"green 5 on a PKP-2200", m2200, 0x15, "215#0000000000000000", led_on{rgb({}, keys({5}))},
     errc::value_out_of_range},
    {"blue 9 blinking on a PKP-2400", m2400, 0x15, "315#0000000000000000",
     led_blink{rgb({}, {}, keys({9}))}, errc::value_out_of_range},
    {"key 9 pressed on a PKP-2400", m2400, 0x15, "195#0001000000", pressed(keys({9}), 0),
     errc::reserved_not_zero},
    {"key 13 pressed on a PKP-2600", m2600, 0x15, "195#0010000000", pressed(keys({13}), 0),
     errc::reserved_not_zero},
    {"key 5 in 6000h on a PKP-2200", m2200, 0x15, "595#4300600010000000", key_reply(keys({5})),
     errc::reserved_not_zero},
    {"blue in 6001h on a PKP-2600", m2600, 0x15, "615#2301600000000000",
     write_on(rgb({}, {}, keys({1}))), errc::value_out_of_range},
    {"blue in 6002h reply on a PKP-2600", m2600, 0x15, "595#4302600000000000",
     reply_blink(rgb({}, {}, keys({1}))), errc::value_out_of_range},
    {"green 5 in 6001h on a PKP-2200", m2200, 0x15, "615#2301600000000000",
     write_on(rgb({}, keys({5}))), errc::value_out_of_range},
    // command parameters outside their ranges (raw values cast into the enums)
    {"baud rate FAh", pkp, 0x15, "615#2300650111FF0000", cmd_baud(static_cast<baud_rate>(0xFA)),
     errc::value_out_of_range},
    {"baud rate 1000k: no command code", pkp, 0x15, "615#2300650111FF0000",
     cmd_baud(baud_rate::kbit_1000), errc::value_out_of_range},
    {"backlight colour FAh", pkp, 0x15, "615#2300650104FA0000",
     cmd_colour(cc::set_backlight_colour, static_cast<backlight_colour>(0xFA)),
     errc::value_out_of_range},
    {"backlight colour keep", pkp, 0x15, "615#2300650104000000",
     cmd_colour(cc::set_backlight_colour, backlight_colour::keep), errc::value_out_of_range},
    {"start-up backlight colour FAh", pkp, 0x15, "615#230065017DFA0000",
     cmd_colour(cc::set_default_backlight_colour, static_cast<backlight_colour>(0xFA)),
     errc::value_out_of_range},
    {"LED state 0Bh", pkp, 0x15, "615#2300650101010B00", raw_state(1, 0x0B),
     errc::value_out_of_range},
    {"LED state 0Fh", pkp, 0x15, "615#2300650101010F00", raw_state(1, 0x0F),
     errc::value_out_of_range},
    {"start-up show 7", pkp, 0x15, "615#2300650150FF0000", show(static_cast<startup_show>(7)),
     errc::value_out_of_range},
    {"command 99h", pkp, 0x15, "615#2300650199000000", cmd(static_cast<cc>(0x99)),
     errc::unknown_command},
    {"a key on a brightness command", pkp, 0x15, "615#2300650102100000",
     with_key(cmd_level(cc::set_led_brightness, 0x10), 3), errc::value_out_of_range},
    // objects: ranges, accesses, kinds
    {"heartbeat 5 ms", m2400, 0x15, "615#2B17100005000000", write(object::heartbeat_time, 5),
     errc::value_out_of_range},
    {"heartbeat 10000h ms", m2400, 0x15, "595#4B17100000000100",
     value(object::heartbeat_time, 0x10000), errc::reserved_not_zero},
    {"256 identity entries", m2400, 0x15, "595#4F18100000010000",
     value(object::identity_count, 256), errc::reserved_not_zero},
    {"key-LED level 40h", m2400, 0x15, "615#2F01620140000000", write(object::led_brightness, 0x40),
     errc::value_out_of_range},
    {"bootloader 02h", pkp, 0x15, "595#4F01630002000000", value(object::bootloader_present, 2),
     errc::value_out_of_range},
    {"write to read-only 1000h", m2400, 0x15, "615#2300100001000000", write(object::device_type, 1),
     errc::unknown_command},
    {"write to read-only 6000h", pkp, 0x15, "615#2300600001000000",
     write(object::keys, keys_value({1})), errc::unknown_command},
    {"write reply of read-only 1000h", m2400, 0x15, "595#6000100000000000",
     written(object::device_type), errc::unknown_command},
    {"number reply of string 1008h: a string piece has a size", m2400, 0x15, "595#4308100001000000",
     value(object::device_name, 1), errc::value_out_of_range},
    {"read of write-only 6500h", m2400, 0x15, "615#4000650100000000", read(object::command_module),
     errc::unknown_command},
    {"a command as a write of 6500h", pkp, 0x15, "615#2300650102100000",
     write(object::command_module, 0x1002), errc::unknown_object},
    {"segmented reply for number 1000h", m2400, 0x15, "595#4100100004000000",
     initiate(0x1000, 0, true, 4), errc::unknown_object},
    // objects and PDOs the PKP dictionary lacks
    {"read of PK1000 2010h (baud rate)", pkp, 0x15, "", read(object::baud_rate),
     errc::unknown_object},
    {"write of PK1000 2001h/1", pkp, 0x15, "",
     write(object::led_on_red, leds_value(rgb(keys({1})))), errc::unknown_object},
    {"write of PK1000 2100h (demo mode)", pkp, 0x15, "", write(object::demo_mode, flag_value(true)),
     errc::unknown_object},
    {"LED brightness PDO (PK1000 only)", pkp, 0x15, "415#1000000000000000", led_brightness{0x10},
     errc::wrong_id},
    {"backlight PDO (PK1000 only)", pkp, 0x15, "515#2003000000000000",
     backlight{0x20, backlight_colour::blue}, errc::wrong_id},
    {"J1939 switch (no PKP source shows it)", pkp, 0x15, "18EF2100#041B8000FFFFFFFF",
     j1939::switch_to_canopen{}, errc::undocumented},
};

}  // namespace pkp_rows

#endif  // POWERKEY_TESTS_PKP_ROWS_HPP
