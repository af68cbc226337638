// behaviour/j1939_keypad.hpp through the virtual keypad: a keypad switched to J1939 speaks it as
// the PKP1600SI and PKP2600SI J1939 manuals describe (docs/virtual-keypad.md#j1939). Every frame
// it sends is compared byte for byte with the manual's example where one is printed; each timer
// is tested at the millisecond before, at and after its period.
#include "behaviour_support.hpp"
#include "support.hpp"

#include <powerkey/behaviour/virtual_keypad.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

using namespace powerkey;
using namespace powerkey::behaviour;
using powerkey_tests::drain;
using powerkey_tests::frame_of;
using powerkey_tests::lv;

namespace {

using strings = std::vector<std::string>;

// A keypad of model m at node 15h, powered on at 0 and switched to J1939 by 20FFh/1 = 1 at t
// (its SDO reply at once: the J1939 start is at t too), everything it sent drained.
virtual_keypad<> in_j1939(model m, millis t = {0}) {
    virtual_keypad<> k(m, canopen::default_node_id, behaviour::keypad_options{true, 0});
    k.power_on(millis{0});
    powerkey_tests::switch_to_j1939(k, t);
    return k;
}

// A keypad of model m sold as a J1939 one (keypad_options::start_in_j1939) at J1939 address
// `address`, powered on at 0.
virtual_keypad<> j1939_keypad_at(model m, std::uint8_t address = 0x21) {
    behaviour::keypad_options o{true, 0};
    o.start_in_j1939 = true;
    o.j1939_address = behaviour::j1939_source_address::make(address).value();
    virtual_keypad<> k(m, canopen::default_node_id, o);
    k.power_on(millis{0});
    return k;
}

// A frame to the keypad at t, and what it sends in answer.
strings hear(virtual_keypad<>& k, std::string_view frame, millis t) {
    k.receive(frame_of(frame), t);
    return drain(k);
}

// What the keypad sends when its timers run to t.
strings at(virtual_keypad<>& k, millis t) {
    k.advance(t);
    return drain(k);
}

}  // namespace

TEST_CASE("J1939: the switch in, at the J1939 default bit rate; a model without 20FFh stays") {
    virtual_keypad<> k(model::pkp1600si, canopen::default_node_id,
                       behaviour::keypad_options{true, 0});
    k.power_on(millis{0});
    CHECK(drain(k) == strings{"715#00"});
    CHECK(hear(k, "615#2BFF200101000000", {10}) == strings{"595#60FF200100000000"});
    CHECK(k.state() == run_state::j1939);
    CHECK(k.baud() == baud_rate::kbit_250);
    CHECK(k.j1939().address() == 0x21);
    CHECK(k.j1939().settings() == behaviour::j1939_settings{});  // section 5
    // CANopen frames are not heard any more
    CHECK(hear(k, "615#4010200000000000", {20}).empty());
    // The PKP LI models have no 20FFh (their CANopen manual): they never speak J1939.
    virtual_keypad<> li(model::pkp2400, canopen::default_node_id,
                        behaviour::keypad_options{true, 0});
    li.power_on(millis{0});
    (void)drain(li);
    CHECK(hear(li, "615#2BFF200101000000", {10}) == strings{"595#80FF200100000206"});
    CHECK(li.state() == run_state::pre_operational);
}

TEST_CASE("J1939 key contact state on every press and release (PKP1600SI section 6)") {
    auto k = in_j1939(model::pkp1600si);
    // Every example row of section 6, in order.
    const std::string_view rows[] = {
        "18EFFF21#041B01010121FFFF", "18EFFF21#041B01010021FFFF", "18EFFF21#041B01020121FFFF",
        "18EFFF21#041B01020021FFFF", "18EFFF21#041B01030121FFFF", "18EFFF21#041B01030021FFFF",
        "18EFFF21#041B01040121FFFF", "18EFFF21#041B01040021FFFF", "18EFFF21#041B01050121FFFF",
        "18EFFF21#041B01050021FFFF", "18EFFF21#041B01060121FFFF", "18EFFF21#041B01060021FFFF"};
    std::uint32_t t = 100;
    for (unsigned key = 1; key <= 6; ++key) {
        k.press(key, millis{t++});
        CHECK(drain(k) == strings{std::string(rows[2 * (key - 1)])});
        k.release(key, millis{t++});
        CHECK(drain(k) == strings{std::string(rows[2 * (key - 1) + 1])});
    }
    // Two keys at once: one frame per key, in key order.
    k.set_keys(key_set{2, 5}, millis{t++});
    CHECK(drain(k) == strings{"18EFFF21#041B01020121FFFF", "18EFFF21#041B01050121FFFF"});
    // 72h 00h: no event frames (section 18); 01h: again.
    CHECK(hear(k, "18EF2100#041B7200FFFFFFFF", millis{t++}).empty());
    k.release(2, millis{t++});
    CHECK(drain(k).empty());
    CHECK(hear(k, "18EF2100#041B7201FFFFFFFF", millis{t++}).empty());
    k.release(5, millis{t++});
    CHECK(drain(k) == strings{"18EFFF21#041B01050021FFFF"});
}

TEST_CASE("J1939 periodic key state: every key each 77h period while 71h enables it") {
    auto k = in_j1939(model::pkp1600si);
    k.press(3, millis{10});
    (void)drain(k);
    CHECK(at(k, millis{1000}).empty());                           // disabled by default (section 5)
    CHECK(hear(k, "18EF2100#041B7101FFFFFFFF", {1000}).empty());  // section 17
    const strings all = {"18EFFF21#041B01010021FFFF", "18EFFF21#041B01020021FFFF",
                         "18EFFF21#041B01030121FFFF", "18EFFF21#041B01040021FFFF",
                         "18EFFF21#041B01050021FFFF", "18EFFF21#041B01060021FFFF"};
    CHECK(at(k, millis{1099}).empty());  // the default period, 100 ms
    CHECK(at(k, millis{1100}) == all);
    CHECK(at(k, millis{1101}).empty());
    CHECK(at(k, millis{1199}).empty());
    CHECK(at(k, millis{1200}) == all);
    // 77h 64h: 1 s (section 22), from the command on.
    CHECK(hear(k, "18EF2100#041B7764FFFFFFFF", {1250}).empty());
    CHECK(at(k, millis{2249}).empty());
    CHECK(at(k, millis{2250}) == all);
    CHECK(at(k, millis{2251}).empty());
    REQUIRE(k.next_due());
    CHECK(*k.next_due() == millis{3250});
    // A late wake gets one round, and the period keeps its phase (as the CANopen timers).
    CHECK(at(k, millis{3500}) == all);
    CHECK(*k.next_due() == millis{4250});
    // 71h 00h: no more.
    CHECK(hear(k, "18EF2100#041B7100FFFFFFFF", {3600}).empty());
    CHECK(at(k, millis{6000}).empty());
    CHECK_FALSE(k.next_due());
}

TEST_CASE("J1939 heartbeat: F9h every 75h period with the counter and the key bits (section 21)") {
    auto k = in_j1939(model::pkp1600si);
    CHECK_FALSE(k.next_due());                                   // disabled by default
    CHECK(hear(k, "18EF2100#041B75010AFFFFFF", {100}).empty());  // 100 ms
    k.press(2, millis{101});
    (void)drain(k);
    CHECK(at(k, millis{199}).empty());
    CHECK(at(k, millis{200}) == strings{"18EFFF21#041BF9000200FF21"});
    CHECK(at(k, millis{201}).empty());
    CHECK(at(k, millis{299}).empty());
    CHECK(at(k, millis{300}) == strings{"18EFFF21#041BF9010200FF21"});
    CHECK(at(k, millis{400}) == strings{"18EFFF21#041BF9020200FF21"});
    // The manual's examples are the fourth heartbeat: counter 03h.
    CHECK(at(k, millis{500}) == strings{"18EFFF21#041BF9030200FF21"});  // key 2 pressed
    // 75h 01h FEh: 2.54 s, the manual's example.
    CHECK(hear(k, "18EF2100#041B7501FEFFFFFF", {510}).empty());
    k.set_keys(key_set{4}, millis{520});
    (void)drain(k);
    CHECK(at(k, millis{3049}).empty());
    CHECK(at(k, millis{3050}) == strings{"18EFFF21#041BF9040800FF21"});  // key 4 pressed
    CHECK(hear(k, "18EF2100#041B7500FFFFFFFF", {3100}).empty());         // disabled
    CHECK(at(k, millis{9000}).empty());
    // PKP-2600-SI: keys 9..12 in byte 5 (PKP2600SI section 21, "button 12 pressed").
    auto s = in_j1939(model::pkp2600si);
    CHECK(hear(s, "18EF2100#041B75010AFFFFFF", {0}).empty());
    s.press(12, millis{1});
    (void)drain(s);
    CHECK(at(s, millis{100}) == strings{"18EFFF21#041BF9000008FF21"});
    CHECK(at(s, millis{200}) == strings{"18EFFF21#041BF9010008FF21"});
    CHECK(at(s, millis{300}) == strings{"18EFFF21#041BF9020008FF21"});
    CHECK(at(s, millis{400}) == strings{"18EFFF21#041BF9030008FF21"});
}

TEST_CASE("J1939 single LED command and its acknowledgement after 73h (sections 7a, 19)") {
    auto k = in_j1939(model::pkp1600si);
    // Without 73h: no acknowledgement (disabled by default).
    CHECK(hear(k, "18EF2100#041B0102010100FF", {10}).empty());  // LED #2 red on
    CHECK(k.j1939().led(2) ==
          j1939::led_look{led_mode::on, j1939::led_colour::red, j1939::led_colour::off, true});
    // Section 19's example, frame by frame.
    CHECK(hear(k, "18EF2100#041B7301FFFFFFFF", {20}).empty());
    CHECK(hear(k, "18EF2100#041B0101040305FF", {30}) == strings{"18EFFF21#0003010405FFFFFF"});
    CHECK(k.j1939().led(1) == j1939::led_look{led_mode::alternate_blink, j1939::led_colour::yellow,
                                              j1939::led_colour::cyan, true});
    // Section 7a's examples: each acknowledged with what it set.
    CHECK(hear(k, "18EF2100#041B0101010000FF", {40}) == strings{"18EFFF21#0000010100FFFFFF"});
    CHECK(k.j1939().led(1).mode == led_mode::off);
    CHECK(hear(k, "18EF2100#041B0105070200FF", {50}) == strings{"18EFFF21#0002050700FFFFFF"});
    CHECK(hear(k, "18EF2100#041B0106010302FF", {60}) == strings{"18EFFF21#0003060102FFFFFF"});
    // From any sender; not to another address, nor to the global address.
    CHECK(hear(k, "18EF2133#041B0103030100FF", {70}) == strings{"18EFFF21#0001030300FFFFFF"});
    CHECK(hear(k, "18EF2200#041B0104050100FF", {80}).empty());
    CHECK(hear(k, "18EFFF00#041B0104050100FF", {90}).empty());
    CHECK(k.j1939().led(4).mode == led_mode::off);
    // An LED the model lacks is refused by the codec: not heard.
    CHECK(hear(k, "18EF2100#041B0107010100FF", {100}).empty());
    // 73h 00h: no more acknowledgements.
    CHECK(hear(k, "18EF2100#041B7300FFFFFFFF", {110}).empty());
    CHECK(hear(k, "18EF2100#041B0104050100FF", {120}).empty());
    CHECK(k.j1939().led(4) ==
          j1939::led_look{led_mode::on, j1939::led_colour::cyan, j1939::led_colour::off, true});
}

TEST_CASE("J1939 multiple LEDs: only after 37h 02h, combined by TABLE 3 (section 7b)") {
    auto k = in_j1939(model::pkp1600si);
    const auto look = [&](unsigned led) { return k.j1939().led(led); };
    constexpr j1939::led_look off{};
    // Single LED mode (the default): the frame is not heard.
    CHECK(hear(k, "18A72100#777777FFFFFFFFFF", {10}).empty());
    CHECK(look(1) == off);
    CHECK(hear(k, "18EF2100#041B3702FFFFFFFF", {20}).empty());
    // "All LED white ON"; no acknowledgement even with 73h (section 19: single LED only).
    CHECK(hear(k, "18EF2100#041B7301FFFFFFFF", {25}).empty());
    CHECK(hear(k, "18A72100#777777FFFFFFFFFF", {30}).empty());
    for (unsigned led = 1; led <= 6; ++led)
        CHECK(look(led) == j1939::led_look{led_mode::on, j1939::led_colour::white,
                                           j1939::led_colour::off, true});
    // "LED #3 alt blinks green": both frames; the other LEDs 0h in both, off.
    CHECK(hear(k, "18A72100#0002FFFFFFFFFFFF", {40}).empty());
    CHECK(hear(k, "18A62100#0002FFFFFFFFFFFF", {41}).empty());
    CHECK(look(3) == j1939::led_look{led_mode::alternate_blink, j1939::led_colour::green,
                                     j1939::led_colour::green, true});
    CHECK(look(1) == off);
    // A "color 2" frame alone combines with the "color 1" codes in force: LED 3 blinks green.
    CHECK(hear(k, "18A62100#000FFFFFFFFFFFFF", {50}).empty());
    CHECK(look(3) ==
          j1939::led_look{led_mode::blink, j1939::led_colour::green, j1939::led_colour::off, true});
    // A single LED command moves the codes too: LED 3 red on, then "color 2" blue on LED 3
    // alternates red and blue.
    CHECK(hear(k, "18EF2100#041B0103010100FF", {60}) == strings{"18EFFF21#0001030100FFFFFF"});
    CHECK(hear(k, "18A62100#0003FFFFFFFFFFFF", {70}).empty());
    CHECK(look(3) == j1939::led_look{led_mode::alternate_blink, j1939::led_colour::red,
                                     j1939::led_colour::blue, true});
    // 37h 00h: single LED only again.
    CHECK(hear(k, "18EF2100#041B3700FFFFFFFF", {80}).empty());
    CHECK(hear(k, "18A72100#000000FFFFFFFFFF", {90}).empty());
    CHECK(hear(k, "18A62100#000000FFFFFFFFFF", {91}).empty());
    CHECK(look(3).mode == led_mode::alternate_blink);
    // PKP-2600-SI: "every LED green on" (PKP2600SI section 7b).
    auto s = in_j1939(model::pkp2600si);
    CHECK(hear(s, "18EF2100#041B3702FFFFFFFF", {10}).empty());
    CHECK(hear(s, "18A72100#222222222222FFFF", {20}).empty());
    for (unsigned led = 1; led <= 12; ++led)
        CHECK(s.j1939().led(led).colour == j1939::led_colour::green);
}

TEST_CASE("J1939 multiple LEDs: the PKP1600SI examples as printed, Fh fill and all (E-J1939-3)") {
    auto k = in_j1939(model::pkp1600si);
    const auto look = [&](unsigned led) { return k.j1939().led(led); };
    CHECK(hear(k, "18EF2100#041B3702FFFFFFFF", {10}).empty());
    CHECK(hear(k, "18A72100#1101FFFFFFFFFFFF", {20}).empty());  // "LED #1,2,3 red ON"
    for (unsigned led = 1; led <= 3; ++led)
        CHECK(look(led) ==
              j1939::led_look{led_mode::on, j1939::led_colour::red, j1939::led_colour::off, true});
    CHECK(hear(k, "18A62100#005FFFFFFFFFFFFF", {30}).empty());  // "LED #4 ycyan"
    CHECK(look(3) ==
          j1939::led_look{led_mode::blink, j1939::led_colour::red, j1939::led_colour::off, true});
    CHECK(look(4) ==
          j1939::led_look{led_mode::on, j1939::led_colour::cyan, j1939::led_colour::off, true});
    // LEDs 5 and 6: Fh in both frames, which TABLE 3 does not define: they keep their look.
    CHECK(look(5) == j1939::led_look{});
    CHECK(look(6) == j1939::led_look{});
}

TEST_CASE("J1939 levels: 02h and 03h until the next start, 7Bh..7Dh at each start (8, 9, 24-26)") {
    auto k = in_j1939(model::pkp1600si);
    const auto& j = k.j1939();
    CHECK(j.brightness() == lv(0x3F));  // section 5
    CHECK(j.backlight_level() == lv(0));
    CHECK(j.backlight_colour_now() == backlight_colour::amber);
    CHECK(hear(k, "18EF2100#041B021FFFFFFFFF", {10}).empty());  // 50 %
    CHECK(hear(k, "18EF2100#041B033FFFFFFFFF", {20}).empty());  // 100 %
    CHECK(j.brightness() == lv(0x1F));
    CHECK(j.backlight_level() == lv(0x3F));
    CHECK(hear(k, "18EF2100#041B7B1FFFFFFFFF", {30}).empty());
    CHECK(hear(k, "18EF2100#041B7C20FFFFFFFF", {40}).empty());
    CHECK(j.brightness() == lv(0x1F));  // a default: from the next start
    CHECK(j.backlight_level() == lv(0x3F));
    CHECK(hear(k, "18EF2100#041B7D06FFFFFFFF", {50}).empty());  // magenta, at once (inferred)
    CHECK(j.backlight_colour_now() == backlight_colour::violet);
    k.power_cycle(millis{100});
    CHECK(k.state() == run_state::j1939);  // J1939 is stored
    CHECK(j.brightness() == lv(0x20));
    CHECK(j.backlight_level() == lv(0x1F));
    CHECK(j.backlight_colour_now() == backlight_colour::violet);
}

TEST_CASE("J1939 software revision: 2Ah answered with \"V2.10\" (section 11)") {
    auto k = in_j1939(model::pkp1600si);
    CHECK(hear(k, "18EF2100#041B2AFFFFFFFFFF", {10}) == strings{"18EFFF21#041B2A56322E3130"});
    CHECK(hear(k, "18EF2105#041B2AFFFFFFFFFF", {20}) == strings{"18EFFF21#041B2A56322E3130"});
}

TEST_CASE("J1939 addresses: 70h moves the keypad, 6Eh its key states (sections 14, 16)") {
    auto k = in_j1939(model::pkp1600si);
    // Section 16's example: source address and identifier FDh.
    CHECK(hear(k, "18EF2100#041B70FDFDFFFFFF", {10}).empty());
    CHECK(k.j1939().address() == 0xFD);
    k.press(1, millis{20});
    CHECK(drain(k) == strings{"18EFFFFD#041B010101FDFFFF"});
    // Commands to the old address are not its own now.
    CHECK(hear(k, "18EF2100#041B2AFFFFFFFFFF", {30}).empty());
    CHECK(hear(k, "18EFFD00#041B2AFFFFFFFFFF", {40}) == strings{"18EFFFFD#041B2A56322E3130"});
    // FFh: no change; the identifier alone.
    CHECK(hear(k, "18EFFD00#041B70FF21FFFFFF", {50}).empty());
    CHECK(k.j1939().address() == 0xFD);
    // Section 14's example: the key contact state to 05h.
    CHECK(hear(k, "18EFFD00#041B6E05FFFFFFFF", {60}).empty());
    k.release(1, millis{70});
    CHECK(drain(k) == strings{"18EF05FD#041B01010021FFFF"});
    // Stored: after a power cycle the keypad is still at FDh.
    k.power_cycle(millis{100});
    k.press(2, millis{110});
    CHECK(drain(k) == strings{"18EF05FD#041B01020121FFFF"});
    // The switch back goes to the current address (section 27: "18EFXX00h").
    CHECK(hear(k, "18EF2100#041B8000FFFFFFFF", {120}).empty());
    CHECK(k.state() == run_state::j1939);
    CHECK(hear(k, "18EFFD00#041B8000FFFFFFFF", {130}) == strings{"715#00"});
    CHECK(k.state() == run_state::pre_operational);
}

TEST_CASE("J1939 address claim at power-up after 74h, 250 ms before anything else (section 20)") {
    auto k = in_j1939(model::pkp1600si);
    CHECK(hear(k, "18EF2100#041B7401FFFFFFFF", {10}).empty());
    CHECK(hear(k, "18EF2100#041B2801FFFFFFFF", {20}).empty());  // start-up keys (section 10)
    CHECK(hear(k, "18EF2100#041B75010AFFFFFF", {30}).empty());
    k.press(6, millis{40});
    (void)drain(k);
    k.power_cycle(millis{1000});
    CHECK(drain(k) == strings{"18EEFF21#3F426F1A00823CC0"});  // the manuals' example
    CHECK(k.j1939().claiming());
    // Nothing else before the address is claimed: a key event, a revision request.
    k.release(6, millis{1100});
    CHECK(hear(k, "18EF2100#041B2AFFFFFFFFFF", {1200}).empty());
    CHECK(at(k, millis{1249}).empty());
    REQUIRE(k.next_due());
    CHECK(*k.next_due() == millis{1250});
    // At 250 ms: the key states of 28h; the heartbeat a period later.
    CHECK(at(k, millis{1250}) == strings{"18EFFF21#041B01010021FFFF", "18EFFF21#041B01020021FFFF",
                                         "18EFFF21#041B01030021FFFF", "18EFFF21#041B01040021FFFF",
                                         "18EFFF21#041B01050021FFFF", "18EFFF21#041B01060021FFFF"});
    CHECK_FALSE(k.j1939().claiming());
    CHECK(at(k, millis{1349}).empty());
    CHECK(at(k, millis{1350}) == strings{"18EFFF21#041BF9000000FF21"});
    SUBCASE("a claim of its address with a higher NAME: the keypad claims again") {
        CHECK(hear(k, "18EEFF21#FFFFFFFFFFFFFEFF", {1400}) == strings{"18EEFF21#3F426F1A00823CC0"});
        CHECK(at(k, millis{1450}) == strings{"18EFFF21#041BF9010000FF21"});
    }
    SUBCASE("a claim of its address with a lower NAME: the keypad falls silent") {
        CHECK(hear(k, "18EEFF21#0000000000000000", {1400}).empty());
        CHECK(k.j1939().lost_address());
        CHECK(at(k, millis{5000}).empty());
        CHECK_FALSE(k.next_due());
        k.press(1, millis{5001});
        CHECK(drain(k).empty());
    }
    SUBCASE("its own claim heard back, and another address's claim, change nothing") {
        CHECK(hear(k, "18EEFF21#3F426F1A00823CC0", {1400}).empty());
        CHECK(hear(k, "18EEFF22#0000000000000000", {1401}).empty());
        CHECK(at(k, millis{1450}) == strings{"18EFFF21#041BF9010000FF21"});
    }
}

TEST_CASE("J1939 settings across the switches: kept, but the bit rate (docs/j1939.md)") {
    auto k = in_j1939(model::pkp2600si);
    CHECK(hear(k, "18EF2100#041B6F02FFFFFFFF", {10}).empty());  // 500 kbit/s (section 15)
    CHECK(k.baud() == baud_rate::kbit_500);
    CHECK(hear(k, "18EF2100#041B7101FFFFFFFF", {20}).empty());
    CHECK(hear(k, "18EF2100#041B7301FFFFFFFF", {30}).empty());
    k.power_cycle(millis{100});
    CHECK(k.baud() == baud_rate::kbit_500);  // stored
    // Back to CANopen (section 27) and the boot-up; then to J1939 again.
    CHECK(hear(k, "18EF2100#041B8000FFFFFFFF", {150}) == strings{"715#00"});
    CHECK(k.baud() == baud_rate::kbit_125);
    CHECK(hear(k, "615#2BFF200101000000", {300}) == strings{"595#60FF200100000000"});
    CHECK(k.baud() == baud_rate::kbit_250);  // the switch: the J1939 default
    auto s = k.j1939().settings();
    CHECK(s.periodic);
    CHECK(s.led_ack);
    CHECK(at(k, millis{400}).size() == 12);  // the periodic key states, every key
    // The switch back from the global address is not a keypad's (docs/j1939.md).
    CHECK(hear(k, "18EFFF00#041B8000FFFFFFFF", {410}).empty());
    CHECK(k.state() == run_state::j1939);
}

TEST_CASE("J1939 per model: what the model's J1939 row does not have is neither heard nor sent") {
    // PK1000: its LED command and acknowledgement are unknown (docs/j1939.md): no LED, no ack.
    auto k = in_j1939(model::pk1000);
    CHECK(hear(k, "18EF2100#041B7301FFFFFFFF", {10}).empty());
    CHECK(hear(k, "18EF2100#041B0101010100FF", {20}).empty());
    CHECK(k.j1939().led(1).mode == led_mode::off);
    // 37h is absent from its manual: multiple-LED frames are not heard.
    CHECK(hear(k, "18EF2100#041B3702FFFFFFFF", {30}).empty());
    CHECK_FALSE(k.j1939().settings().multiple_leds);
    // Its key contact state (keys up to 0Ah) and heartbeat (K10, K9 in byte 5, inferred).
    k.press(10, millis{40});
    CHECK(drain(k) == strings{"18EFFF21#041B010A0121FFFF"});
    CHECK(hear(k, "18EF2100#041B75010AFFFFFF", {50}).empty());
    CHECK(at(k, millis{150}) == strings{"18EFFF21#041BF9000002FF21"});
    // PKP-2200-SI: the multiple-LED command and 6Eh are absent from its manual.
    auto s = in_j1939(model::pkp2200si);
    CHECK(hear(s, "18EF2100#041B6E05FFFFFFFF", {10}).empty());
    CHECK(s.j1939().settings().destination == j1939::global_address);
    s.press(4, millis{20});
    CHECK(drain(s) == strings{"18EFFF21#041B01040121FFFF"});
}

TEST_CASE("J1939 faults: silence and lost frames apply to the J1939 frames too") {
    auto k = in_j1939(model::pkp1600si);
    k.silence(millis{10}, duration_ms{100});
    k.press(1, millis{20});
    CHECK(drain(k).empty());
    k.drop_transmitted(1);
    k.release(1, millis{200});
    CHECK(drain(k).empty());
    k.press(1, millis{210});
    CHECK(drain(k) == strings{"18EFFF21#041B01010121FFFF"});
    k.drop_received(1);
    CHECK(hear(k, "18EF2100#041B2AFFFFFFFFFF", {220}).empty());
    CHECK(hear(k, "18EF2100#041B2AFFFFFFFFFF", {230}) == strings{"18EFFF21#041B2A56322E3130"});
}

// The PKP LI keypads sold as J1939 keypads (issue 21): their J1939 row (docs/j1939.md, the
// PKP-2400-LI J1939 manual's pages and its layout inferred for the PKP-2200-LI and PKP-2600)
// from power-on, the LED command and acknowledgement in the LI (code) form, and no switch back.
struct li_case {
    model m;
    std::string_view last_key_pressed;  // its last key's key contact state, pressed
    std::string_view beat_last_key;     // the heartbeat (counter 00h) with its last key held
    std::string_view led_beyond;        // an LI LED command to the LED after its last
};
constexpr li_case li_cases[] = {
    {model::pkp2200, "18EFFF21#041B01040121FFFF", "18EFFF21#041BF9000800FF21",
     "18EF2100#041B010505FFFFFF"},
    {model::pkp2400, "18EFFF21#041B01080121FFFF", "18EFFF21#041BF9008000FF21",
     "18EF2100#041B010905FFFFFF"},
    {model::pkp2600, "18EFFF21#041B010C0121FFFF", "18EFFF21#041BF9000008FF21",
     "18EF2100#041B010D05FFFFFF"},
};

TEST_CASE("J1939 from power-on: the PKP LI keypads, their LI frames, no switch back") {
    for (const auto& c : li_cases) {
        CAPTURE(c.m);
        REQUIRE(behaviour::speaks_j1939(c.m));
        REQUIRE_FALSE(info(c.m)->j1939);  // no 20FFh on their CANopen side
        const unsigned last = info(c.m)->keys;
        auto k = j1939_keypad_at(c.m);
        CHECK(k.state() == run_state::j1939);
        CHECK(drain(k).empty());  // no boot-up, no address claim (74h off, section 5)
        CHECK(k.baud() == baud_rate::kbit_250);
        CHECK(k.j1939().settings() == behaviour::j1939_settings{});
        CHECK(k.read(object::protocol_j1939) == std::nullopt);  // not in their dictionary
        // The key contact state (ref 5, inferred layout).
        k.press(last, millis{10});
        CHECK(drain(k) == strings{std::string(c.last_key_pressed)});
        // The LI LED command (ref 6.4, inferred): the code kept as it came, no look; without
        // 73h no acknowledgement; with it the LI acknowledgement (ref 6.3, page 11).
        CHECK_FALSE(k.j1939().led_code(3));
        CHECK(hear(k, "18EF2100#041B010305FFFFFF", {20}).empty());
        CHECK(k.j1939().led_code(3) == std::optional<std::uint8_t>{0x05});
        CHECK(k.j1939().led(3) == j1939::led_look{});
        CHECK(hear(k, "18EF2100#041B7301FFFFFFFF", {30}).empty());
        CHECK(hear(k, "18EF2100#041B010305FFFFFF", {40}) == strings{"18EFFF21#00FF0305FFFFFFFF"});
        CHECK(hear(k, "18EF2100#041B0101A7FFFFFF", {45}) == strings{"18EFFF21#00FF01A7FFFFFFFF"});
        CHECK(k.j1939().led_code(1) == std::optional<std::uint8_t>{0xA7});
        // The SI form is not an LI keypad's (reserved_not_ff): not heard; nor an LED it lacks.
        CHECK(hear(k, "18EF2100#041B0102010100FF", {50}).empty());
        CHECK_FALSE(k.j1939().led_code(2));
        CHECK(hear(k, c.led_beyond, {55}).empty());
        // Levels (ref 7: 02h, 03h).
        CHECK(hear(k, "18EF2100#041B0220FFFFFFFF", {60}).empty());
        CHECK(hear(k, "18EF2100#041B033FFFFFFFFF", {70}).empty());
        CHECK(k.j1939().brightness() == lv(0x20));
        CHECK(k.j1939().backlight_level() == lv(0x3F));
        // The heartbeat (75h, 100 ms; ref 8: the PKP-2400-LI's byte 5, its key bits).
        CHECK(hear(k, "18EF2100#041B75010AFFFFFF", {100}).empty());
        CHECK(at(k, millis{199}).empty());
        CHECK(at(k, millis{200}) == strings{std::string(c.beat_last_key)});
        // The switch back is unknown on an LI keypad (the codec: undocumented): ignored.
        CHECK(
            j1939::decode(frame_of("18EF2100#041B8000FFFFFFFF"), c.m, std::uint8_t{0x21}).error() ==
            errc::undocumented);
        CHECK(hear(k, "18EF2100#041B8000FFFFFFFF", {210}).empty());
        CHECK(k.state() == run_state::j1939);
        // 70h (ref 7): it sends from and answers at the new address; the identifier stays.
        CHECK(hear(k, "18EF2100#041B7030FFFFFFFF", {220}).empty());
        CHECK(k.j1939().address() == 0x30);
        k.release(last, millis{230});
        CHECK(drain(k) == strings{"18EFFF30#041B01" +
                                  std::string(c.last_key_pressed.substr(15, 2)) + "0021FFFF"});
        CHECK(hear(k, "18EF2100#041B2AFFFFFFFFFF", {240}).empty());
        CHECK(hear(k, "18EF3000#041B2AFFFFFFFFFF", {250}) == strings{"18EFFF30#041B2A56322E3130"});
        // A power cycle: J1939 and the address stored, the LED codes gone with the LEDs.
        k.power_cycle(millis{1000});
        CHECK(k.state() == run_state::j1939);
        CHECK(k.j1939().address() == 0x30);
        CHECK_FALSE(k.j1939().led_code(1));
        CHECK(hear(k, "18EF3000#041B010105FFFFFF", {1010}) == strings{"18EFFF30#00FF0105FFFFFFFF"});
    }
}

TEST_CASE("J1939 from power-on at any address: keypad_options::j1939_address") {
    // An SI keypad at 30h: its frames from 30h, commands to 30h its own, to 21h not.
    auto k = j1939_keypad_at(model::pkp1600si, 0x30);
    CHECK(k.state() == run_state::j1939);
    CHECK(drain(k).empty());
    CHECK(k.j1939().address() == 0x30);
    CHECK(k.j1939().settings().identifier == 0x21);  // 70h byte 4 keeps its default
    k.press(1, millis{10});
    CHECK(drain(k) == strings{"18EFFF30#041B01010121FFFF"});
    CHECK(hear(k, "18EF2100#041B2AFFFFFFFFFF", {20}).empty());
    CHECK(hear(k, "18EF3000#041B2AFFFFFFFFFF", {30}) == strings{"18EFFF30#041B2A56322E3130"});
    CHECK(hear(k, "18EF3000#041B7301FFFFFFFF", {40}).empty());
    CHECK(hear(k, "18EF3000#041B0101040305FF", {50}) == strings{"18EFFF30#0003010405FFFFFF"});
    // The switch back goes to its address; in CANopen the address changes nothing.
    CHECK(hear(k, "18EF2100#041B8000FFFFFFFF", {60}).empty());
    CHECK(hear(k, "18EF3000#041B8000FFFFFFFF", {70}) == strings{"715#00"});
    CHECK(k.state() == run_state::pre_operational);
    // A keypad switched by 20FFh starts at the given address too (it is its stored one).
    behaviour::keypad_options o{true, 0};
    o.j1939_address = behaviour::j1939_source_address::make(0xFD).value();
    virtual_keypad<> s(model::pkp2600si, canopen::default_node_id, o);
    s.power_on(millis{0});
    CHECK(drain(s) == strings{"715#00"});
    powerkey_tests::switch_to_j1939(s, millis{10});
    s.press(12, millis{20});
    CHECK(drain(s) == strings{"18EFFFFD#041B010C0121FFFF"});
    // The address claim from the given address (section 20's NAME).
    auto c = j1939_keypad_at(model::pkp2400, 0x42);
    CHECK(hear(c, "18EF4200#041B7401FFFFFFFF", {10}).empty());
    c.power_cycle(millis{100});
    CHECK(drain(c) == strings{"18EEFF42#3F426F1A00823CC0"});
    // The default: 21h; an address 70h refuses is no j1939_source_address.
    CHECK(behaviour::keypad_options{}.j1939_address.value() == 0x21);
    CHECK_FALSE(behaviour::j1939_source_address::make(0x00));
    CHECK_FALSE(behaviour::j1939_source_address::make(0xFE));
    CHECK(behaviour::j1939_source_address::make(0x01));
    CHECK(behaviour::j1939_source_address::make(0xFD));
}

TEST_CASE("J1939 from power-on: every model whose key contact state a source shows") {
    for (const auto m : enum_values<model>()) {
        CAPTURE(m);
        REQUIRE(j1939::row(m)->frames.has(j1939::feature::key_contact));  // every model today
        CHECK(behaviour::speaks_j1939(m));
        auto k = j1939_keypad_at(m, 0x22);
        CHECK(k.state() == run_state::j1939);
        (void)drain(k);
        k.press(1, millis{10});
        CHECK(drain(k) == strings{"18EFFF22#041B01010121FFFF"});
    }
}

namespace {
// A J1939 session in a constant expression: switch, LED with acknowledgement, key, switch back.
constexpr bool j1939_scenario() {
    virtual_keypad<8> k(model::pkp1600si);
    k.power_on(millis{0});
    k.receive(frame_of("615#2BFF200101000000"), millis{1});
    k.advance(millis{2});
    if (k.transmit() != frame_of("715#00") || k.transmit() != frame_of("595#60FF200100000000"))
        return false;
    k.receive(frame_of("18EF2100#041B7301FFFFFFFF"), millis{3});
    k.receive(frame_of("18EF2100#041B0101040305FF"), millis{4});
    if (k.transmit() != frame_of("18EFFF21#0003010405FFFFFF")) return false;
    k.press(2, millis{5});
    if (k.transmit() != frame_of("18EFFF21#041B01020121FFFF")) return false;
    k.receive(frame_of("18EF2100#041B8000FFFFFFFF"), millis{6});
    return k.transmit() == frame_of("715#00") && k.state() == run_state::pre_operational;
}
static_assert(j1939_scenario());
}  // namespace

TEST_CASE("a J1939 session is a constant expression") { CHECK(j1939_scenario()); }
