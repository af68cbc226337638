// behaviour/j1939_controller.hpp: the J1939 controller in a closed loop with the virtual keypad
// switched to J1939 (behaviour/j1939_keypad.hpp), for every model that speaks J1939: it finds the
// keypad, sends its start-up settings, drives its LEDs and levels, turns its key states into
// events, notices its restart and its loss, and moves it to another address. Then the first
// frames it sends, byte for byte.
#include "behaviour_support.hpp"
#include "support.hpp"

#include <powerkey/behaviour/j1939_controller.hpp>
#include <powerkey/behaviour/virtual_keypad.hpp>
#include <powerkey/can/candump.hpp>
#include <powerkey/names.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

using namespace powerkey;
using namespace powerkey::behaviour;
using powerkey_tests::frame_of;
using powerkey_tests::lv;

namespace {

// A J1939 controller and a virtual keypad already switched to J1939, on one bus, stepped every
// millisecond.
struct bench : powerkey_tests::closed_loop<j1939_controller<16, 64>> {
    explicit bench(model m, j1939_controller_config cfg = {})
        : closed_loop(m, cfg, canopen::default_node_id, keypad_options{true, 0}) {
        keypad.power_on(millis{0});
        powerkey_tests::switch_to_j1939(keypad, millis{0});
    }
};

// The models that speak J1939 in the virtual keypad: those with 20FFh (the PKP LI models have
// none).
std::vector<model> j1939_models() {
    std::vector<model> out;
    for (const model m : enum_values<model>())
        if (info(m)->j1939) out.push_back(m);
    return out;
}

// An LED the model's J1939 LED command addresses (the PKP-3500-MT has none on key 1).
unsigned some_led(model m) {
    const auto r = j1939::row(m).value();
    for (unsigned k = 1; k <= 16; ++k)
        if (((r.leds >> (k - 1)) & 1u) != 0) return k;
    return 0;
}

}  // namespace

TEST_CASE("J1939 controller + virtual keypad: found, set up, LEDs, levels, keys, every model") {
    for (const model m : j1939_models()) {
        INFO("model " << std::string(to_string(m)));
        const j1939::command config[] = {
            {.code = j1939::command_code::set_led_acknowledgement, .enabled = true}};
        j1939_controller_config cfg;
        cfg.configuration = config;
        bench b(m, cfg);
        b.run(1100);  // found by its answer to 2Ah, or (no 2Ah answer) not at all
        const auto row = j1939::row(m).value();
        REQUIRE(row.frames.has(j1939::feature::software_revision));
        CHECK(b.ctl.state() == controller_state::running);
        CHECK(b.count(event_kind::found) == 1);
        CHECK(b.count(event_kind::ready) == 1);
        // The start-up settings and the list reached the keypad.
        const auto& s = b.keypad.j1939().settings();
        CHECK(s.heartbeat);
        CHECK(s.heartbeat_10ms == 20);
        CHECK(s.address_claim);
        CHECK(s.led_ack);
        // The shadow reaches the keypad, where the model has a known LED command.
        const unsigned led = some_led(m);
        const bool leds = row.frames.has(j1939::feature::led_command);
        CHECK(b.ctl.set_led(led, j1939::led_colour::amber) == leds);
        CHECK(b.ctl.set_led(led == 2 ? 3 : 2, j1939::led_colour::red, led_mode::alternate_blink,
                            j1939::led_colour::blue) == leds);
        b.ctl.set_brightness(lv(0x10));
        b.ctl.set_backlight(lv(0x20), backlight_colour::red);
        b.run(20);
        if (leds) {
            CHECK(b.keypad.j1939().led(led) == j1939::led_look{led_mode::on,
                                                               j1939::led_colour::amber,
                                                               j1939::led_colour::off, true});
            CHECK(b.keypad.j1939().led(led == 2 ? 3 : 2).mode == led_mode::alternate_blink);
        }
        CHECK(b.keypad.j1939().brightness() == lv(0x10));
        CHECK(b.keypad.j1939().backlight_level() == lv(0x20));
        CHECK(b.keypad.j1939().backlight_colour_now() == backlight_colour::red);
        // Key events from the key contact states: press, long press, repeats, release.
        powerkey_tests::check_key_1_held(b);
        CHECK(b.count(event_kind::lost) == 0);  // its heartbeat every 200 ms
        CHECK(b.ctl.events_dropped() == 0);
    }
}

TEST_CASE("J1939 controller: its first frames, byte for byte") {
    bench b(model::pkp1600si);
    b.run(1);
    // 2Ah to the keypad (section 11); its answer finds it; then 75h 01h 14h (200 ms, section 21),
    // 74h 01h (section 20) and the picture: every LED off, brightness 3Fh, backlight 00h.
    CHECK(b.candump() == std::vector<std::string>{"18EF2100#041B2AFFFFFFFFFF"});
    b.run(2);
    CHECK(b.candump() ==
          std::vector<std::string>{"18EF2100#041B2AFFFFFFFFFF", "18EFFF21#041B2A56322E3130",
                                   "18EF2100#041B750114FFFFFF", "18EF2100#041B7401FFFFFFFF",
                                   "18EF2100#041B0101000000FF", "18EF2100#041B0102000000FF",
                                   "18EF2100#041B0103000000FF", "18EF2100#041B0104000000FF",
                                   "18EF2100#041B0105000000FF", "18EF2100#041B0106000000FF"});
    CHECK(b.ctl.state() == controller_state::running);
    // A key press and the heartbeat: the events come from both.
    b.keypad.press(4, b.at());
    b.run(1);
    CHECK(b.candump().back() == "18EFFF21#041B01040121FFFF");
    CHECK(b.saw(event_kind::key_pressed, 4));
}

TEST_CASE("J1939 controller: a keypad restart is noticed by its address claim; everything again") {
    bench b(model::pkp2600si);
    b.run(100);
    CHECK(b.ctl.set_led(5, j1939::led_colour::green));
    b.ctl.set_brightness(lv(0x08));
    b.run(20);
    CHECK(b.keypad.j1939().led(5).colour == j1939::led_colour::green);
    b.keypad.press(2, b.at());
    b.run(10);
    CHECK(b.ctl.keys() == key_set{2});
    b.keypad.power_cycle(b.at());  // the key is still held: the restart releases it for the app
    b.keypad.release(2, b.at());
    CHECK(b.keypad.j1939().led(5).mode == led_mode::off);
    b.run(300);
    CHECK(b.count(event_kind::rebooted) == 1);
    CHECK(b.count(event_kind::ready) == 2);
    CHECK(b.saw(event_kind::key_released, 2));
    CHECK(b.keypad.j1939().led(5).colour == j1939::led_colour::green);
    CHECK(b.keypad.j1939().brightness() == lv(0x08));
    CHECK(b.count(event_kind::lost) == 0);
}

TEST_CASE("J1939 controller: a silent keypad is lost, then found again") {
    bench b(model::pkp1600si);
    b.run(100);
    b.keypad.press(3, b.at());
    b.run(10);
    b.keypad.silence(b.at(), duration_ms{2000});
    b.run(1000);
    CHECK(b.count(event_kind::lost) == 1);
    CHECK(b.ctl.state() == controller_state::searching);
    CHECK(b.saw(event_kind::key_released, 3));  // held keys are released for the application
    b.run(1500);
    CHECK(b.count(event_kind::found) == 2);
    CHECK(b.ctl.state() == controller_state::running);
}

TEST_CASE("J1939 controller: moves the keypad to another address (70h) and follows it") {
    bench b(model::pkp1600si);
    b.run(100);
    b.ctl.change_address(0x42);
    b.run(10);
    CHECK(b.count(event_kind::node_changed) == 1);
    CHECK(b.ctl.address() == 0x42);
    CHECK(b.keypad.j1939().address() == 0x42);
    const auto log = b.candump();
    CHECK(std::find(log.begin(), log.end(), "18EF2100#041B7042FFFFFFFF") != log.end());
    b.keypad.press(6, b.at());
    b.run(1);
    CHECK(b.candump().back() == "18EFFF42#041B01060121FFFF");
    CHECK(b.saw(event_kind::key_pressed, 6));
    CHECK(b.ctl.set_led(6, j1939::led_colour::blue));
    b.run(5);
    CHECK(b.candump().back() == "18EF4200#041B0106030100FF");
    CHECK(b.keypad.j1939().led(6).colour == j1939::led_colour::blue);
    b.run(1000);
    CHECK(b.count(event_kind::lost) == 0);
}

TEST_CASE("J1939 controller: what a model cannot carry is refused") {
    j1939_controller<> pk(j1939_controller_config{.keypad_model = model::pk1000});
    CHECK_FALSE(pk.set_led(1, j1939::led_colour::red));  // its LED command is unknown
    j1939_controller<> mt(j1939_controller_config{.keypad_model = model::pkp3500mt});
    CHECK_FALSE(mt.set_led(1, j1939::led_colour::red));  // no LED on the encoder push
    CHECK(mt.set_led(2, j1939::led_colour::red));
    CHECK_FALSE(mt.set_led(2, static_cast<j1939::led_colour>(0x0A)));
}

namespace {
// The pair at compile time: found, set up, an LED set by the application reaches the keypad.
constexpr bool j1939_pair_scenario() {
    virtual_keypad<16> k(model::pkp1600si, canopen::default_node_id, keypad_options{true, 0});
    k.power_on(millis{0});
    k.receive(frame_of("615#2BFF200101000000"), millis{0});
    while (k.transmit()) {
    }
    j1939_controller<16, 32> c(j1939_controller_config{});
    bool asked = false;
    for (std::uint32_t t = 1; t <= 20; ++t) {
        if (t == 10 && !c.set_led(4, j1939::led_colour::violet)) return false;
        bool any = false;
        while (const auto f = k.transmit()) {
            c.step(*f, millis{t});
            any = true;
        }
        if (!any) c.tick(millis{t});
        while (const auto f = c.next_frame()) {
            asked = asked || *f == frame_of("18EF2100#041B2AFFFFFFFFFF");
            k.receive(*f, millis{t});
        }
    }
    return asked && c.state() == controller_state::running &&
           k.j1939().led(4) == j1939::led_look{led_mode::on, j1939::led_colour::violet,
                                               j1939::led_colour::off, true};
}
static_assert(j1939_pair_scenario());
}  // namespace

TEST_CASE("the J1939 pair is a constant expression") { CHECK(j1939_pair_scenario()); }
