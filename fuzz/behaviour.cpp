// The behaviour layer on one bus: a virtual keypad, a controller and a checker that hears every
// frame, stepped with times, keys, faults, application calls and third parties' frames drawn
// from the input. Properties, each a promise of the headers (docs/security.md):
//   - no event is dropped: the application polls after every call, and the controller's default
//     queue holds what one call can report (events_per_call);
//   - no outbox overflows: each role's frames are taken off after every call;
//   - every frame a role sends decodes under its model (the keypad's and the controller's), for
//     the node its COB-ID names;
//   - the checker names no line past the one it is given, returns every problem it finds
//     (problems_dropped() stays 0) and explains each in 200 characters;
//   - events name what they may: a key of the model, a configuration entry of the list.
// Everything runs in fixed-size objects; the queue of frames on the bus is the harness's.
#include "fuzz.hpp"

#include <powerkey/behaviour/checker.hpp>
#include <powerkey/behaviour/controller.hpp>
#include <powerkey/behaviour/virtual_keypad.hpp>

#include <deque>
#include <utility>

namespace {
using namespace powerkey;
using namespace powerkey_fuzz;
namespace pb = powerkey::behaviour;

// What a configuration list may hold: reads, writes and commands, some of which a model refuses
// (2014h on a PKP, a command on a PK1000) and one that is no SDO request at all.
const message pool[] = {
    sdo_write{object::led_brightness, level_value(level{0x30})},
    sdo_read{object::device_type},
    sdo_write{object::startup_show, show_value(startup_show::disabled)},
    sdo_read{object::device_name},
    sdo_write{object::heartbeat_time, number_value(150)},
    sdo_write{object::tpdo1_event_timer, number_value(100)},
    sdo_write{object::active_on_startup, flag_value(true)},
    [] {
        command c;
        c.code = command_code::set_periodic_transmission;
        c.enabled = true;
        c.period_10ms = 10;
        return message{c};
    }(),
    message{led_on{}},
};

pb::duration_ms take_duration(input& in) {
    const std::uint8_t b = in.u8();
    return pb::duration_ms{(b & 0x80) != 0 ? 0u : std::uint32_t{b} * 10u};
}

// The node a frame's COB-ID names (the broadcast ones: `fallback`).
canopen::node_id node_of(const can::frame& f, canopen::node_id fallback) {
    const auto c = canopen::classify(f);
    if (const auto n = canopen::node_id::make(c.node)) return *n;
    return fallback;
}

enum class sender : std::uint8_t { keypad, controller, other };

struct bus {
    pb::virtual_keypad<64> keypad;
    pb::controller<8> controller;
    pb::checker<> checker;
    std::size_t entries;
    std::deque<std::pair<can::frame, sender>> wire;
    pb::millis now{};
    std::uint32_t line = 0;

    bus(model m, canopen::node_id node, pb::keypad_options ko, const pb::controller_config& cc,
        std::size_t entries_)
        : keypad(m, node, ko),
          controller(cc),
          checker(pb::checker_config{m, node}),
          entries(entries_) {}

    // After every call: the events polled, the outboxes emptied onto the wire.
    void after_call() {
        POWERKEY_FUZZ_CHECK(controller.events_dropped() == 0);
        while (const auto e = controller.poll()) {
            POWERKEY_FUZZ_CHECK(is_named(e->kind));
            if (e->kind == pb::event_kind::key_pressed || e->kind == pb::event_kind::key_released ||
                e->kind == pb::event_kind::key_long_press || e->kind == pb::event_kind::key_repeat)
                POWERKEY_FUZZ_CHECK(e->key >= 1 && e->key <= key_set::max);
            if ((e->kind == pb::event_kind::sdo_done || e->kind == pb::event_kind::sdo_refused ||
                 e->kind == pb::event_kind::sdo_aborted ||
                 e->kind == pb::event_kind::sdo_timed_out) &&
                e->origin == pb::sdo_origin::configuration)
                POWERKEY_FUZZ_CHECK(e->step < entries || e->step == pb::max_configuration);
        }
        POWERKEY_FUZZ_CHECK(keypad.overflowed() == 0);
        POWERKEY_FUZZ_CHECK(controller.outbox().dropped() == 0);
        while (const auto f = keypad.transmit()) {
            const auto d = decode(*f, node_of(*f, keypad.node()), keypad.model());
            POWERKEY_FUZZ_CHECK_FRAME(d.has_value(), *f);
            wire.emplace_back(*f, sender::keypad);
        }
        while (const auto f = controller.next_frame()) {
            const auto d = decode(*f, node_of(*f, controller.node()), controller.model());
            POWERKEY_FUZZ_CHECK_FRAME(d.has_value(), *f);
            wire.emplace_back(*f, sender::controller);
        }
    }

    // One frame on the bus: the checker hears it, the other roles receive it.
    void deliver(const can::frame& f, sender from) {
        ++line;
        for (const auto& p : checker.step(f, now, line)) {
            POWERKEY_FUZZ_CHECK_FRAME(p.line <= line, f);
            std::array<char, 200> text{};
            POWERKEY_FUZZ_CHECK_FRAME(pb::explain(p, text).has_value(), f);
        }
        POWERKEY_FUZZ_CHECK_FRAME(checker.problems_dropped() == 0, f);
        if (from != sender::keypad) keypad.receive(f, now);
        after_call();
        if (from != sender::controller) controller.step(f, now);
        after_call();
    }

    // Time passes to `now`: the timers of both roles, then the frames until the bus is quiet.
    void run() {
        keypad.advance(now);
        after_call();
        controller.tick(now);
        after_call();
        for (int i = 0; i < 256 && !wire.empty(); ++i) {
            const auto [f, from] = wire.front();
            wire.pop_front();
            deliver(f, from);
        }
        wire.clear();  // a bus that never goes quiet: the rest is lost, as frames can be
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    input in(data, size);
    const auto m = static_cast<model>(in.u8() % model_count);
    const auto node = take_node(in);
    const std::uint8_t flags = in.u8();
    pb::keypad_options ko;
    ko.drop_sdo_while_busy = (flags & 1) == 0;
    ko.sdo_response_ms = in.u8() % 8;
    pb::controller_config cc;
    cc.keypad_model = (flags & 2) != 0 ? static_cast<model>(in.u8() % model_count) : m;
    cc.node = (flags & 4) != 0 ? take_node(in) : node;
    cc.any_node = (flags & 8) != 0;
    cc.identify = (flags & 16) == 0;
    cc.start = (flags & 32) != 0 ? pb::start_mode::active_on_startup : pb::start_mode::nmt_start;
    cc.keypad_heartbeat = take_duration(in);
    cc.lost_after = take_duration(in);
    cc.sdo_timeout = take_duration(in);
    cc.sdo_retries = in.u8() % 4;
    cc.probe_period = take_duration(in);
    cc.refresh_period = take_duration(in);
    cc.long_press = take_duration(in);
    cc.repeat_delay = take_duration(in);
    cc.repeat_period = take_duration(in);
    std::array<message, 8> list{};
    const std::size_t entries = in.u8() % (list.size() + 1);
    for (std::size_t i = 0; i < entries; ++i) list[i] = pool[in.u8() % std::size(pool)];
    cc.configuration = std::span<const message>(list.data(), entries);

    bus b(m, node, ko, cc, entries);
    if ((flags & 64) == 0) b.keypad.power_on(b.now);
    b.after_call();
    for (int i = 0; i < 300 && !in.empty(); ++i) {
        const std::uint8_t op = in.u8();
        switch (op % 12) {
            case 0: b.now = b.now + pb::duration_ms{in.u8()}; break;
            case 1: b.now = b.now + pb::duration_ms{in.integer<std::uint16_t>()}; break;
            case 2: b.now = b.now + pb::duration_ms{in.integer<std::uint32_t>()}; break;
            case 3: b.wire.emplace_back(take_frame(in), sender::other); break;
            case 4: {
                const unsigned key = in.u8() % (key_set::max + 2);
                (void)((op & 0x80) != 0 ? b.keypad.release(key, b.now)
                                        : b.keypad.press(key, b.now));
                b.after_call();
                break;
            }
            case 5:
                b.keypad.set_keys(key_set::from_mask(in.integer<std::uint16_t>()), b.now);
                b.after_call();
                break;
            case 6:
                switch (in.u8() % 6) {
                    case 0: b.keypad.power_cycle(b.now); break;
                    case 1: b.keypad.power_off(); break;
                    case 2: b.keypad.power_on(b.now); break;
                    case 3:
                        b.keypad.silence(b.now, pb::duration_ms{in.integer<std::uint16_t>()});
                        break;
                    case 4: b.keypad.drop_received(in.u8() % 4); break;
                    default: b.keypad.drop_transmitted(in.u8() % 4); break;
                }
                b.after_call();
                break;
            case 7:
                switch (in.u8() % 5) {
                    case 0: {  // (the arguments read in order: a call's are in no set order)
                        const unsigned led = in.u8() % 34;
                        const auto c = static_cast<colour>(in.u8() % 10);
                        (void)b.controller.set_led(led, c, (op & 0x80) != 0);
                        break;
                    }
                    case 1: {
                        leds on, blink;
                        fill_value(in, on);
                        fill_value(in, blink);
                        (void)b.controller.set_leds(on, blink);
                        break;
                    }
                    case 2: b.controller.set_brightness(level::make(in.u8() % 64).value()); break;
                    case 3: {
                        const auto l = level::make(in.u8() % 64).value();
                        b.controller.set_backlight(l, static_cast<backlight_colour>(in.u8() % 8));
                    } break;
                    default: b.controller.change_node(take_node(in)); break;
                }
                b.after_call();
                break;
            default: break;
        }
        b.run();
    }
    for (const auto& p : b.checker.finish(b.now)) POWERKEY_FUZZ_CHECK(p.line <= b.line);
    POWERKEY_FUZZ_CHECK(b.checker.problems_dropped() == 0);
    return 0;
}
