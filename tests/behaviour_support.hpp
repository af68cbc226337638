// Test support shared by the behaviour tests: a level built at run time, a virtual keypad
// switched to J1939, what a virtual keypad sent, and a controller (CANopen or J1939) and a virtual
// keypad on one bus, stepped every millisecond, with every frame logged and every event kept.
#ifndef POWERKEY_TESTS_BEHAVIOUR_SUPPORT_HPP
#define POWERKEY_TESTS_BEHAVIOUR_SUPPORT_HPP

#include "support.hpp"

#include <powerkey/behaviour/controller.hpp>
#include <powerkey/behaviour/virtual_keypad.hpp>
#include <powerkey/can/candump.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace powerkey_tests {

// A level built with make(): clang 14 crashes generating code for the consteval literal
// constructor passed as an argument in test functions (level{0x10} inside CHECK).
inline powerkey::level lv(unsigned v) { return powerkey::level::make(v).value(); }

// Switches keypad k to J1939 by 20FFh/1 = 1 at t (its SDO reply at once: the J1939 start is at t
// too) and drains what it sent.
template <std::size_t N>
void switch_to_j1939(powerkey::behaviour::virtual_keypad<N>& k, powerkey::behaviour::millis t) {
    k.receive(frame_of("615#2BFF200101000000"), t);
    while (k.transmit()) {
    }
}

// What keypad k has sent since it was last drained, oldest first, in the candump form.
template <std::size_t N>
std::vector<std::string> drain(powerkey::behaviour::virtual_keypad<N>& k) {
    std::vector<std::string> out;
    while (const auto f = k.transmit()) out.emplace_back(powerkey::can::format_candump(*f).view());
    return out;
}

// A controller and a virtual keypad on one bus, stepped every millisecond.
template <class Controller, class Keypad = powerkey::behaviour::virtual_keypad<32>>
struct closed_loop {
    struct logged {
        powerkey::can::frame frame;
        std::uint32_t time;
    };

    template <class Config>
    closed_loop(powerkey::model m, Config cfg, powerkey::canopen::node_id node,
                powerkey::behaviour::keypad_options options = {})
        : keypad(m, node, options), ctl(with_model(cfg, m)) {}
    template <class Config>
    static Config with_model(Config c, powerkey::model m) {
        c.keypad_model = m;
        return c;
    }

    // `ms` milliseconds; `reply(frame)` may change each frame of the keypad before it is sent.
    template <class Reply>
    void run(std::uint32_t ms, Reply&& reply) {
        for (std::uint32_t i = 0; i < ms; ++i) {
            ++now;
            const powerkey::behaviour::millis t{now};
            keypad.advance(t);
            bool any = false;
            while (auto f = keypad.transmit()) {
                reply(*f);
                log.push_back({*f, now});
                ctl.step(*f, t);
                any = true;
            }
            if (!any) ctl.tick(t);
            while (const auto f = ctl.next_frame()) {
                log.push_back({*f, now});
                keypad.receive(*f, t);
            }
            while (const auto e = ctl.poll()) events.push_back(*e);
        }
    }
    void run(std::uint32_t ms) {
        run(ms, [](powerkey::can::frame&) {});
    }

    [[nodiscard]] std::size_t count(powerkey::behaviour::event_kind k) const {
        return static_cast<std::size_t>(std::count_if(events.begin(), events.end(),
                                                      [k](const auto& e) { return e.kind == k; }));
    }
    [[nodiscard]] bool saw(powerkey::behaviour::event_kind k, unsigned key) const {
        return std::any_of(events.begin(), events.end(),
                           [&](const auto& e) { return e.kind == k && e.key == key; });
    }
    [[nodiscard]] powerkey::behaviour::millis at() const {
        return powerkey::behaviour::millis{now};
    }
    // Every frame on the bus so far, in the candump form.
    [[nodiscard]] std::vector<std::string> candump() const {
        std::vector<std::string> out;
        for (const auto& l : log) out.emplace_back(powerkey::can::format_candump(l.frame).view());
        return out;
    }

    Keypad keypad;
    Controller ctl;
    std::uint32_t now = 0;
    std::vector<logged> log;
    std::vector<powerkey::behaviour::controller_event> events;
};

// Key 1 of bench b (a closed_loop, or a type made from one with its own run) held for a second,
// then released: the controller reports the press, the long press, three repeats (at 500, 700 and
// 900 ms) and the release.
template <class Bench>
void check_key_1_held(Bench& b) {
    using powerkey::behaviour::event_kind;
    b.keypad.press(1, b.at());
    b.run(1000);
    b.keypad.release(1, b.at());
    b.run(20);
    CHECK(b.saw(event_kind::key_pressed, 1));
    CHECK(b.saw(event_kind::key_long_press, 1));
    CHECK(b.count(event_kind::key_repeat) == 3);
    CHECK(b.saw(event_kind::key_released, 1));
}

}  // namespace powerkey_tests

#endif  // POWERKEY_TESTS_BEHAVIOUR_SUPPORT_HPP
