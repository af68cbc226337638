// behaviour/controller.hpp: the controller in a closed loop with the virtual keypad
// (behaviour/virtual_keypad.hpp), for every model, with the faults of issue 12: the keypad reboots
// mid-session, goes silent, loses frames, aborts an SDO, changes node id. Every session's bus log
// is also handed to the checker (behaviour/checker.hpp): a controller session has no problem
// except those the fault itself causes. Then small queues and outboxes, the controller alone
// against scripted replies, the key modes (behaviour/key_modes.hpp), and the same session at
// compile time.
#include "behaviour_support.hpp"
#include "support.hpp"

#include <powerkey/behaviour/checker.hpp>
#include <powerkey/behaviour/controller.hpp>
#include <powerkey/behaviour/key_modes.hpp>
#include <powerkey/behaviour/virtual_keypad.hpp>
#include <powerkey/names.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

using namespace powerkey;
using namespace powerkey::behaviour;
using powerkey::canopen::node_id;

using powerkey_tests::lv;

// Node ids below are built with make() rather than the consteval literal constructor: clang 14
// crashes generating code for a consteval temporary passed as an argument in these test functions.

namespace {

// A controller and a virtual keypad on one bus, stepped every millisecond, with the fault below.
struct bench : powerkey_tests::closed_loop<controller<16, 64>> {
    explicit bench(model m, controller_config cfg = {}, node_id node = canopen::default_node_id)
        : closed_loop(m, cfg, node) {}

    void run(std::uint32_t ms) {
        closed_loop::run(ms, [this](can::frame& f) {
            if (abort_next && f.raw_id() == 0x580u + keypad.node().value() &&
                f[1] == (abort_next->index & 0xFF) && f[2] == (abort_next->index >> 8) &&
                f[3] == abort_next->subindex) {
                f = canopen::encode(keypad.node(),
                                    canopen::sdo_abort_response{{*abort_next, abort_code}});
                abort_next.reset();
            }
        });
    }

    // The keypad powered on, and the session run for `ms` (200: found, set up and started).
    void start(std::uint32_t ms = 200) {
        keypad.power_on(at());
        run(ms);
    }

    // The checker's view of the whole session: the problem kinds, in order.
    std::vector<problem> check(model m, node_id start = canopen::default_node_id) const {
        checker_config cc;
        cc.keypad_model = m;
        cc.node = start;
        checker<> c(cc);
        std::vector<problem> out;
        std::uint32_t line = 0;
        for (const auto& l : log)
            for (const auto& p : c.step(l.frame, millis{l.time}, ++line)) out.push_back(p);
        for (const auto& p : c.finish(millis{now})) out.push_back(p);
        return out;
    }

    // Fault injection for a keypad whose refusals the codec cannot provoke: its next reply for
    // this object becomes an abort with abort_code.
    std::optional<canopen::sdo_address> abort_next;
    canopen::sdo_abort_code abort_code = canopen::sdo_abort_code::general_error;
};

std::string kinds(const std::vector<problem>& ps) {
    std::string s;
    for (const auto& p : ps) {
        if (!s.empty()) s += ' ';
        s += std::string(to_string(p.kind));
    }
    return s;
}

bool only(const std::vector<problem>& ps, std::initializer_list<problem_kind> allowed) {
    return std::all_of(ps.begin(), ps.end(), [&](const problem& p) {
        return std::find(allowed.begin(), allowed.end(), p.kind) != allowed.end();
    });
}

// The virtual keypad reports 100Bh for the models whose manuals print it; for the others it aborts
// the controller's identify read (the controller then keeps the configured model), the one
// problem the checker may see in an otherwise clean session.
bool identify_aborts(model m) { return !info(m)->string_of(object::model_name).has_value(); }
std::vector<problem> without_identify(model m, std::vector<problem> ps) {
    if (!identify_aborts(m)) return ps;
    ps.erase(std::remove_if(ps.begin(), ps.end(),
                            [](const problem& p) {
                                return p.kind == problem_kind::sdo_abort && p.detail[1] == 0x100B;
                            }),
             ps.end());
    return ps;
}

// An LED every model has (LED 2 is there on all of them, the PKP-3500-MT lacks LED 1).
constexpr unsigned some_led = 2;

}  // namespace

TEST_CASE("controller + virtual keypad: start, configure, LEDs, levels, keys, for every model") {
    for (const model m : enum_values<model>()) {
        INFO("model " << std::string(to_string(m)));
        const message config[] = {sdo_read{object::device_type}, sdo_read{object::heartbeat_time}};
        controller_config cfg;
        cfg.configuration = config;
        bench b(m, cfg);
        b.start();
        CHECK(b.ctl.state() == controller_state::running);
        CHECK(b.keypad.state() == run_state::operational);
        CHECK(b.count(event_kind::found) == 1);
        CHECK(b.count(event_kind::ready) == 1);
        CHECK(b.ctl.model() == m);
        // The configuration list ran in order, one request at a time, and read back what was set.
        std::vector<controller_event> done;
        for (const auto& e : b.events)
            if (e.kind == event_kind::sdo_done && e.origin == sdo_origin::configuration)
                done.push_back(e);
        REQUIRE(done.size() == 2);
        CHECK(done[0].what == object::device_type);
        CHECK(done[1].what == object::heartbeat_time);
        CHECK(done[1].value == 200);  // the controller's keypad_heartbeat, written before the list

        // The shadow reaches the keypad.
        CHECK(b.ctl.set_led(some_led, colour::red));
        CHECK(b.ctl.set_led(3, colour::green, true));
        b.run(20);
        CHECK(b.keypad.led_on().red.contains(some_led));
        CHECK(b.keypad.led_blink().green.contains(3));
        b.ctl.set_brightness(lv(0x10));
        b.ctl.set_backlight(lv(0x20), backlight_colour::red);
        b.run(50);
        CHECK(b.keypad.brightness() == lv(0x10));
        CHECK(b.keypad.backlight().level == lv(0x20));

        // Key events: press, long press, repeats, release.
        powerkey_tests::check_key_1_held(b);
        CHECK(b.ctl.events_dropped() == 0);

        // A controller session is clean for the checker.
        const auto problems = without_identify(m, b.check(m));
        CHECK_MESSAGE(problems.empty(), kinds(problems));
    }
}

TEST_CASE("controller + virtual keypad: the keypad reboots mid-session, everything is sent again") {
    for (const model m : enum_values<model>()) {
        INFO("model " << std::string(to_string(m)));
        bench b(m);
        b.start();
        b.ctl.set_led(some_led, colour::green);
        b.ctl.set_brightness(lv(0x08));
        b.run(50);
        REQUIRE(b.keypad.led_on().green.contains(some_led));
        b.keypad.power_cycle(b.at());
        CHECK(b.keypad.led_on().empty());  // a rebooted keypad shows its defaults
        b.run(200);
        CHECK(b.count(event_kind::rebooted) == 1);
        CHECK(b.count(event_kind::ready) == 2);
        CHECK(b.keypad.state() == run_state::operational);
        CHECK(b.keypad.led_on().green.contains(some_led));
        CHECK(b.keypad.brightness() == lv(0x08));
        CHECK(b.count(event_kind::lost) == 0);
        const auto problems = without_identify(m, b.check(m));
        CHECK_MESSAGE(problems.empty(), kinds(problems));
    }
}

TEST_CASE("controller + virtual keypad: the keypad goes silent, is reported lost, and comes back") {
    for (const model m : enum_values<model>()) {
        INFO("model " << std::string(to_string(m)));
        bench b(m);
        b.start();
        b.ctl.set_led(some_led, colour::red);
        b.keypad.press(2, b.at());
        b.run(50);
        b.keypad.silence(b.at(), duration_ms{1000});
        b.run(900);
        CHECK(b.count(event_kind::lost) == 1);
        CHECK(b.ctl.state() == controller_state::searching);
        CHECK(b.saw(event_kind::key_released, 2));  // a held key is released on loss (safe state)
        b.run(400);                                 // silence over: its heartbeat again
        CHECK(b.count(event_kind::found) == 2);
        CHECK(b.count(event_kind::ready) == 2);
        CHECK(b.ctl.state() == controller_state::running);
        CHECK(b.keypad.led_on().red.contains(some_led));
        // The checker sees the silence too, and the controller's probe (an SDO read of 1000h
        // while the keypad was lost) that the silent keypad could not answer; nothing else.
        const auto problems = without_identify(m, b.check(m));
        CHECK_MESSAGE(only(problems, {problem_kind::heartbeat_silence, problem_kind::sdo_no_reply}),
                      kinds(problems));
        CHECK(!problems.empty());
    }
}

TEST_CASE("controller + virtual keypad: lost frames (an SDO request, a reply, the NMT start)") {
    for (const model m : enum_values<model>()) {
        INFO("model " << std::string(to_string(m)));
        const message config[] = {sdo_read{object::device_type}};
        controller_config cfg;
        cfg.configuration = config;
        bench b(m, cfg);
        b.start(1);                 // boot-up seen; the 100Bh read is on its way
        b.keypad.drop_received(1);  // ... and the keypad never hears it
        b.run(400);
        CHECK(b.count(event_kind::ready) == 1);  // the retry after 300 ms went through
        CHECK(b.count(event_kind::sdo_timed_out) == 0);

        // The keypad's reply to the next request is lost: the controller asks again.
        b.ctl.set_brightness(lv(0x21));
        b.keypad.drop_transmitted(1);
        b.run(20);
        b.keypad.drop_transmitted(0);
        b.run(400);
        CHECK(b.keypad.brightness() == lv(0x21));

        // The NMT start after a reboot is lost: the keypad's heartbeat says pre-operational and
        // the controller starts it again.
        b.keypad.power_cycle(b.at());
        for (std::size_t guard = 0; guard < 2000; ++guard) {
            ++b.now;
            const millis t{b.now};
            b.keypad.advance(t);
            while (const auto f = b.keypad.transmit()) {
                b.log.push_back({*f, b.now});
                b.ctl.step(*f, t);
            }
            b.ctl.tick(t);
            bool start = false;
            while (const auto f = b.ctl.next_frame()) {
                b.log.push_back({*f, b.now});
                if (f->raw_id() == 0 && !start) {
                    start = true;  // lost on the way
                    continue;
                }
                b.keypad.receive(*f, t);
            }
            while (const auto e = b.ctl.poll()) b.events.push_back(*e);
            if (start) break;
        }
        CHECK(b.keypad.state() == run_state::pre_operational);
        b.run(500);
        CHECK(b.keypad.state() == run_state::operational);
        CHECK(b.count(event_kind::lost) == 0);
        // For the checker the lost frames are requests never answered, and LEDs sent to a keypad
        // that its heartbeat shows pre-operational (the NMT start never arrived).
        const auto problems = without_identify(m, b.check(m));
        CHECK_MESSAGE(
            only(problems, {problem_kind::sdo_no_reply, problem_kind::pdo_not_operational}),
            kinds(problems));
    }
}

namespace {
// Whether a fresh virtual keypad of model m aborts request r.
bool keypad_aborts(model m, const message& r) {
    const auto f = encode(canopen::default_node_id, m, r);
    if (!f) return false;
    virtual_keypad<8> k(m);
    k.power_on(millis{0});
    while (k.transmit()) {
    }
    k.receive(*f, millis{1});
    k.advance(millis{5});
    while (const auto reply = k.transmit())
        if ((*reply)[0] == 0x80) return true;
    return false;
}

// A request the virtual keypad of model m aborts although the codec builds it: a read of the
// error register 1001h (PK1000 31), of a string the keypad does not report, a write the keypad
// refuses, a command it does not take ... found by asking a scratch keypad.
std::optional<message> aborted_request(model m) {
    const auto mi = info(m).value();
    for (const auto& r : rows_of(mi.dictionary)) {
        if (r.readable() && keypad_aborts(m, sdo_read{r.id})) return sdo_read{r.id};
        if (r.writable() && info(r.id).kind != value_kind::commands) {
            for (const std::uint32_t v : {r.min, r.max, r.initial}) {
                const message w = sdo_write{r.id, number_value(v)};
                if (keypad_aborts(m, w)) return w;
            }
        }
    }
    for (const auto& row : powerkey::detail::command_table) {
        command c;
        c.code = row.code;
        if (row.p1 == command_param::key) c.key = 1;
        if (row.p1 == command_param::colour) c.colour = backlight_colour::red;
        if (keypad_aborts(m, c)) return message{c};
    }
    return std::nullopt;
}
}  // namespace

TEST_CASE("controller + virtual keypad: an SDO abort is reported and the list goes on") {
    for (const model m : enum_values<model>()) {
        INFO("model " << std::string(to_string(m)));
        // A request the virtual keypad aborts; where there is none that the codec builds (the
        // PKP-LI keypads take every value the codec lets through), the keypad's reply to a read
        // of 1018h sub 1 is turned into an abort on its way.
        const auto found_bad = aborted_request(m);
        const message bad = found_bad.value_or(message{sdo_read{object::vendor_id}});
        const message config[] = {bad, sdo_read{object::device_type}};
        controller_config cfg;
        cfg.configuration = config;
        cfg.identify = false;
        bench b(m, cfg);
        if (!found_bad) {
            b.abort_next = canopen::sdo_address{0x1018, 1};
            b.abort_code = canopen::sdo_abort_code::hardware_error;
        }
        b.start();
        REQUIRE(b.count(event_kind::sdo_aborted) == 1);
        const auto e = *std::find_if(b.events.begin(), b.events.end(), [](const auto& x) {
            return x.kind == event_kind::sdo_aborted;
        });
        object asked = object::command_module;
        if (const auto* r = std::get_if<sdo_read>(&bad)) asked = r->object;
        if (const auto* w = std::get_if<sdo_write>(&bad)) asked = w->object;
        CHECK(e.what == asked);
        CHECK(e.step == 0);
        CHECK(abort_meaning_of(e.value) != "");
        CHECK(b.count(event_kind::ready) == 1);  // the next entry ran, and the keypad started
        const auto problems = without_identify(m, b.check(m));
        REQUIRE(problems.size() == 1);
        CHECK(problems[0].kind == problem_kind::sdo_abort);
        CHECK(problems[0].detail[0] == e.value);
    }
}

TEST_CASE("controller + virtual keypad: the keypad changes node id") {
    for (const model m : enum_values<model>()) {
        INFO("model " << std::string(to_string(m)));
        const auto mi = info(m).value();
        if (!find_row(mi.dictionary, object::node_id) &&
            !find_row(mi.dictionary, object::command_module)) {
            MESSAGE("no node-id change on this model");
            continue;
        }
        bench b(m);
        b.start();
        b.ctl.change_node(node_id::make(0x3A).value());
        b.run(300);
        CHECK(b.count(event_kind::node_changed) == 1);
        CHECK(b.ctl.node() == node_id::make(0x3A).value());
        CHECK(b.keypad.node() == node_id::make(0x3A).value());
        CHECK(b.keypad.state() == run_state::operational);
        CHECK(b.count(event_kind::rebooted) == 0);  // the PKP's boot-up from the new id is expected
        CHECK(b.count(event_kind::lost) == 0);
        b.ctl.set_led(some_led, colour::blue);
        b.run(20);
        if (mi.planes > 2) {
            CHECK(b.keypad.led_on().blue.contains(some_led));
        }
        b.keypad.press(1, b.at());
        b.run(20);
        CHECK(b.saw(event_kind::key_pressed, 1));
        const auto problems = without_identify(m, b.check(m));
        CHECK_MESSAGE(problems.empty(), kinds(problems));
        // Only the boot-up of the change was expected: a power cycle after it is a reboot.
        b.keypad.power_cycle(b.at());
        b.run(200);
        CHECK(b.count(event_kind::rebooted) == 1);
        CHECK(b.count(event_kind::lost) == 0);
    }
}

TEST_CASE("controller + virtual keypad: a keypad that booted before the host is found by probing") {
    for (const model m : {model::pk1000, model::pkp2400}) {
        controller_config cfg;
        cfg.keypad_heartbeat = duration_ms{0};  // the keypad sends no heartbeat
        cfg.lost_after = duration_ms{0};        // ... so silence means nothing
        bench b(m, cfg);
        b.keypad.power_on(millis{0});
        while (b.keypad.transmit()) {
        }  // its boot-up went out before the controller listened
        b.run(1500);
        CHECK(b.count(event_kind::found) == 1);
        CHECK(b.ctl.state() == controller_state::running);
        CHECK(b.keypad.state() == run_state::operational);
    }
}

TEST_CASE("controller + virtual keypad: any node adopts a keypad at another node id") {
    for (const model m : {model::pk1000, model::pkp2200, model::pkp2600si}) {
        INFO("model " << std::string(to_string(m)));
        controller_config cfg;
        cfg.any_node = true;
        bench b(m, cfg, node_id::make(0x30).value());
        b.start();
        CHECK(b.ctl.node() == node_id::make(0x30).value());
        CHECK(b.ctl.state() == controller_state::running);
        CHECK(b.keypad.state() == run_state::operational);
        b.ctl.set_led(some_led, colour::red);
        b.run(10);
        CHECK(b.keypad.led_on().red.contains(some_led));
    }
}

TEST_CASE("controller + virtual keypad: active on startup") {
    for (const model m : {model::pk1000, model::pkp2400}) {
        controller_config cfg;
        cfg.start = start_mode::active_on_startup;
        bench b(m, cfg);
        b.start();
        b.keypad.power_cycle(b.at());
        CHECK(b.keypad.state() == run_state::operational);  // by itself after the power cycle
        b.run(200);
        CHECK(b.count(event_kind::ready) == 2);
        const auto problems = without_identify(m, b.check(m));
        CHECK_MESSAGE(problems.empty(), kinds(problems));
    }
}

// --- small queues and outboxes, configuration entries --------------------------------------------

namespace {
// A controller and a virtual keypad on one bus, stepped every millisecond; `poll` false leaves
// the events in the controller's queue.
template <std::size_t Outbox, std::size_t Events>
struct loop {
    explicit loop(controller_config cfg, model m = model::pk1000)
        : keypad(m), ctl(with_model(cfg, m)) {}
    static controller_config with_model(controller_config c, model m) {
        c.keypad_model = m;
        return c;
    }
    void run(std::uint32_t ms, bool poll = true) {
        for (std::uint32_t i = 0; i < ms; ++i) {
            const millis t{++now};
            keypad.advance(t);
            bool any = false;
            while (const auto f = keypad.transmit()) {
                ctl.step(*f, t);
                any = true;
            }
            if (!any) ctl.tick(t);
            while (const auto f = ctl.next_frame()) keypad.receive(*f, t);
            while (poll)
                if (const auto e = ctl.poll())
                    events.push_back(*e);
                else
                    break;
        }
    }
    void drain() {
        while (const auto e = ctl.poll()) events.push_back(*e);
    }
    virtual_keypad<32> keypad;
    controller<Outbox, Events> ctl;
    std::uint32_t now = 0;
    std::vector<controller_event> events;
};
}  // namespace

TEST_CASE(
    "controller + virtual keypad: a full event queue keeps the first events and counts the rest") {
    loop<16, 64> big({});
    big.keypad.power_on(millis{0});
    big.run(300);
    REQUIRE(big.events.size() > 2);
    loop<16, 2> small({});
    small.keypad.power_on(millis{0});
    small.run(300, false);
    small.drain();
    REQUIRE(small.events.size() == 2);
    CHECK(small.events[0] == big.events[0]);
    CHECK(small.events[1] == big.events[1]);
    // ready waits for room (controller.hpp): never polled, the setup does not end, and the
    // events between the first two and the ready are dropped and counted.
    const auto ready = std::find_if(big.events.begin(), big.events.end(),
                                    [](const auto& e) { return e.kind == event_kind::ready; });
    REQUIRE(ready != big.events.end());
    REQUIRE(ready - big.events.begin() >= 2);
    CHECK(small.ctl.state() == controller_state::setting_up);
    CHECK(small.ctl.events_dropped() == static_cast<std::size_t>(ready - big.events.begin()) - 2);
    // Polled, it ends: the ready comes at the next call.
    while (small.ctl.poll()) {
    }
    small.ctl.tick(millis{small.now});
    CHECK(small.ctl.poll()->kind == event_kind::ready);
    CHECK(small.ctl.state() == controller_state::running);
}

TEST_CASE("controller + virtual keypad: with a one-frame outbox the setup still completes") {
    loop<1, 64> one({});
    one.keypad.power_on(millis{0});
    one.run(2000);
    bool ready = false;
    for (const auto& e : one.events) ready = ready || e.kind == event_kind::ready;
    CHECK(ready);
}

TEST_CASE(
    "controller + virtual keypad: a request that found the outbox full is sent at the next tick") {
    // PKP-2400: no brightness PDO, so the LED level goes by SDO (6201h sub 1, PKP 30) right
    // after the NMT start, which fills a one-frame outbox.
    loop<1, 64> l({}, model::pkp2400);
    l.ctl.set_brightness(lv(0x10));
    l.keypad.power_on(millis{0});
    l.run(2000);
    CHECK(l.keypad.brightness() == lv(0x10));
}

TEST_CASE("controller, scripted: replies for another object or out of turn do not end a read") {
    controller<16, 64> ctl{controller_config{}};
    std::uint32_t now = 0;
    auto sent = [&ctl] {
        std::vector<std::string> out;
        while (const auto f = ctl.next_frame()) out.emplace_back(can::format_candump(*f).view());
        return out;
    };
    auto events = [&ctl] {
        std::vector<controller_event> out;
        while (const auto e = ctl.poll()) out.push_back(*e);
        return out;
    };
    ctl.step(powerkey_tests::frame_of("715#00"), millis{now});
    // Found: the setup starts by reading the model id, 100Bh (PK1000 35).
    const auto first = sent();
    REQUIRE_FALSE(first.empty());
    CHECK(first.back() == "615#400B100000000000");
    (void)events();
    // A late reply to a read of 2011h, an initiate reply for 1008h, and a segment before any
    // initiate reply: none answers the read of 100Bh.
    for (const std::string_view stray :
         {"595#4F11200001000000", "595#410810000B000000", "595#00504B3130303000"}) {
        CAPTURE(std::string(stray));
        ctl.step(powerkey_tests::frame_of(stray), millis{++now});
        CHECK(sent().empty());
        CHECK(events().empty());
    }
    // The reply: 7 bytes, "PK1000" and a NUL (PK1000 35, E-CORE-5), in one segment.
    ctl.step(powerkey_tests::frame_of("595#410B100007000000"), millis{++now});
    CHECK(sent() == std::vector<std::string>{"615#6000000000000000"});
    ctl.step(powerkey_tests::frame_of("595#01504B3130303000"), millis{++now});
    const auto done = events();
    REQUIRE_FALSE(done.empty());
    CHECK(done[0].kind == event_kind::sdo_done);
    CHECK(done[0].origin == sdo_origin::identify);
    CHECK(done[0].what == object::model_name);
}

TEST_CASE("controller + virtual keypad: a configuration entry that is no SDO request is skipped") {
    // Entry 0 is a PDO (not an SDO request: skipped, no event); entry 1 reads 1000h, which the
    // PK1000 answers with 000B0191h (PK1000 30).
    const message configuration[] = {led_on{leds{{1}, {}, {}}}, sdo_read{object::device_type}};
    controller_config cfg;
    cfg.configuration = configuration;
    loop<16, 64> l(cfg);
    l.keypad.power_on(millis{0});
    l.run(500);
    std::vector<controller_event> config;
    for (const auto& e : l.events)
        if (e.origin == sdo_origin::configuration &&
            (e.kind == event_kind::sdo_done || e.kind == event_kind::sdo_refused))
            config.push_back(e);
    REQUIRE(config.size() == 1);
    CHECK(config[0].kind == event_kind::sdo_done);
    CHECK(config[0].step == 1);
    CHECK(config[0].what == object::device_type);
    CHECK(config[0].value == 0x000B'0191u);
}

// A keypad whose boot-up and first reply are lost, and that misses a request: the controller
// retries until it is set up.
TEST_CASE("controller + virtual keypad: the boot-up and a reply lost, then a request") {
    bench b(model::pkp2400);
    b.keypad.power_on(b.at());
    b.keypad.drop_transmitted(2);  // the boot-up and a reply
    b.run(45);
    b.keypad.drop_received(1);
    b.run(3955);
    CHECK(b.count(event_kind::ready) == 1);
    CHECK(b.count(event_kind::sdo_timed_out) == 0);
}

// A configuration read of 1001h: the keypad aborts it (PK1000 31), object does not exist.
TEST_CASE("controller + virtual keypad: the abort of 1001h is reported with its code") {
    const message config[] = {sdo_read{object::error_register}};
    controller_config cfg;
    cfg.configuration = config;
    bench b(model::pk1000, cfg);
    b.start(3000);
    REQUIRE(b.count(event_kind::sdo_aborted) == 1);
    const auto e = *std::find_if(b.events.begin(), b.events.end(),
                                 [](const auto& x) { return x.kind == event_kind::sdo_aborted; });
    CHECK(e.value == 0x0602'0000);
    CHECK(b.count(event_kind::ready) == 1);
}

// --- the controller alone, against scripted keypad replies --------------------------------------

namespace {
constexpr can::frame f_(std::string_view s) { return can::parse_candump(s).value(); }

struct scripted {
    explicit scripted(controller_config c) : ctl(c) {}
    std::vector<std::string> sent() {
        std::vector<std::string> out;
        while (const auto f = ctl.next_frame()) out.emplace_back(can::format_candump(*f).view());
        return out;
    }
    std::vector<controller_event> events() {
        std::vector<controller_event> out;
        while (const auto e = ctl.poll()) out.push_back(*e);
        return out;
    }
    controller<16, 32> ctl;
};
}  // namespace

TEST_CASE("controller, scripted: one SDO request at a time, timeout, retry, abort") {
    const message config[] = {sdo_write{object::startup_show, show_value(startup_show::fast_flash)},
                              sdo_read{object::boot_up}};
    controller_config cfg;
    cfg.configuration = config;
    cfg.identify = false;
    cfg.keypad_heartbeat = duration_ms{0};
    cfg.sdo_retries = 1;
    scripted s(cfg);
    s.ctl.step(f_("715#00"), millis{10});  // boot-up of node 15h (PK1000 8)
    CHECK(s.sent() == std::vector<std::string>{"615#2F14200002000000"});
    s.ctl.tick(millis{100});
    CHECK(s.sent().empty());  // nothing else while it is outstanding
    s.ctl.tick(millis{310});  // timed out: the one retry
    CHECK(s.sent() == std::vector<std::string>{"615#2F14200002000000"});
    s.ctl.tick(millis{610});  // no reply again: reported, the list goes on
    CHECK(s.sent() == std::vector<std::string>{"615#4011200000000000"});
    auto ev = s.events();
    REQUIRE(ev.size() == 2);
    CHECK(ev[0].kind == event_kind::found);
    CHECK(ev[1].kind == event_kind::sdo_timed_out);
    CHECK(ev[1].what == object::startup_show);
    s.ctl.step(f_("595#8011200000000206"), millis{612});  // aborted: 06020000h
    ev = s.events();
    REQUIRE(ev.size() == 2);
    CHECK(ev[0].kind == event_kind::sdo_aborted);
    CHECK(ev[0].value == 0x0602'0000);
    CHECK(ev[0].step == 1);
    CHECK(ev[1].kind == event_kind::ready);
    // Started, then the LED picture (all off) and no other PDO: nothing else was set.
    CHECK(s.sent() ==
          std::vector<std::string>{"000#0115", "215#0000000000000000", "315#0000000000000000"});
}

TEST_CASE("controller, scripted: identify reads 100Bh and takes the model it reports") {
    controller_config cfg;
    cfg.keypad_model = model::pkp2200;  // configured wrongly: the keypad is a PKP-2400
    cfg.keypad_heartbeat = duration_ms{0};
    scripted s(cfg);
    s.ctl.step(f_("715#00"), millis{0});
    CHECK(s.sent() == std::vector<std::string>{"615#400B100000000000"});
    s.ctl.step(f_("595#410B100007000000"), millis{1});  // PKP 22, as the manual prints it
    CHECK(s.sent() == std::vector<std::string>{"615#6000000000000000"});
    s.ctl.step(f_("595#00504B5532343030"), millis{2});
    CHECK(s.sent() == std::vector<std::string>{"615#7000000000000000"});
    s.ctl.step(f_("595#1D00000000000000"), millis{3});
    CHECK(s.ctl.model() == model::pkp2400);
    CHECK(s.ctl.text() == "PKU2400");
    CHECK(s.ctl.state() == controller_state::running);
}

TEST_CASE(
    "controller, scripted: heartbeat says pre-operational -> NMT start and the picture again") {
    controller_config cfg;
    cfg.identify = false;
    cfg.keypad_heartbeat = duration_ms{0};
    cfg.refresh_period = duration_ms{0};
    scripted s(cfg);
    s.ctl.step(f_("715#00"), millis{0});
    (void)s.sent();
    s.ctl.step(f_("795#05"), millis{5});  // another node's heartbeat: not ours
    CHECK(s.sent().empty());
    s.ctl.set_led(1, colour::red);
    s.ctl.tick(millis{6});
    CHECK(s.sent() == std::vector<std::string>{"215#0100000000000000"});
    s.ctl.tick(millis{7});
    CHECK(s.sent().empty());  // only on change (refresh off)
    // PK1000 28 note 2: its consumer heartbeat timed out, LEDs off, pre-operational.
    s.ctl.step(f_("715#7F"), millis{100});
    CHECK(s.sent() ==
          std::vector<std::string>{"000#0115", "215#0100000000000000", "315#0000000000000000"});
}

TEST_CASE("controller, scripted: lost after the configured silence; a key held is released") {
    controller_config cfg;
    cfg.identify = false;
    cfg.keypad_heartbeat = duration_ms{0};
    cfg.lost_after = duration_ms{500};
    cfg.repeat_delay = duration_ms{0};
    scripted s(cfg);
    s.ctl.step(f_("715#00"), millis{0});
    s.ctl.step(f_("195#0400000001"), millis{100});  // key 3 pressed
    (void)s.sent();
    auto ev = s.events();
    CHECK(ev.back() == controller_event{event_kind::key_pressed, 3});
    s.ctl.tick(millis{600});
    CHECK(s.events().empty());  // exactly 500 ms: not yet
    s.ctl.tick(millis{601});
    ev = s.events();
    REQUIRE(ev.size() == 2);
    CHECK(ev[0].kind == event_kind::lost);
    CHECK(ev[1] == controller_event{event_kind::key_released, 3});
    CHECK(s.ctl.state() == controller_state::searching);
}

TEST_CASE("controller, scripted: key times are the caller's") {
    controller_config cfg;
    cfg.identify = false;
    cfg.keypad_heartbeat = duration_ms{0};
    cfg.lost_after = duration_ms{0};
    cfg.long_press = duration_ms{300};
    cfg.repeat_delay = duration_ms{0};  // no repeats
    scripted s(cfg);
    s.ctl.step(f_("715#00"), millis{0});
    (void)s.events();
    s.ctl.step(f_("195#0100000001"), millis{1000});
    s.ctl.tick(millis{1299});
    s.ctl.tick(millis{1300});
    s.ctl.tick(millis{5000});
    s.ctl.step(f_("195#0000000001"), millis{5001});
    const auto ev = s.events();
    REQUIRE(ev.size() == 3);
    CHECK(ev[0] == controller_event{event_kind::key_pressed, 1});
    CHECK(ev[1] == controller_event{event_kind::key_long_press, 1});
    CHECK(ev[2] == controller_event{event_kind::key_released, 1});
}

TEST_CASE("controller, scripted: any node, a refused entry, the refresh") {
    const message config[] = {sdo_write{object::startup_show, show_value(startup_show::disabled)},
                              sdo_read{object::device_type}};
    controller_config cfg;
    cfg.keypad_model = model::pkp2400;  // no 2014h in its dictionary: refused, not sent
    cfg.any_node = true;
    cfg.identify = false;
    cfg.keypad_heartbeat = duration_ms{0};
    cfg.lost_after = duration_ms{0};
    cfg.refresh_period = duration_ms{100};
    cfg.configuration = config;
    scripted s(cfg);
    s.ctl.step(f_("795#05"), millis{0});  // a heartbeat of another node: not adopted
    CHECK(s.ctl.state() == controller_state::searching);
    CHECK(s.sent() == std::vector<std::string>{"615#4000100000000000"});  // the probe of 15h
    s.ctl.step(f_("720#00"), millis{1});                                  // a boot-up: node 20h
    CHECK(s.ctl.node() == canopen::node_id::make(0x20).value());
    CHECK(s.sent() == std::vector<std::string>{"620#4000100000000000"});
    auto ev = s.events();
    REQUIRE(ev.size() == 2);
    CHECK(ev[0].kind == event_kind::found);
    CHECK(ev[1].kind == event_kind::sdo_refused);
    CHECK(ev[1].what == object::startup_show);
    CHECK(ev[1].value == static_cast<std::uint32_t>(errc::unknown_object));
    s.ctl.step(f_("5A0#4300100091010300"), millis{2});
    CHECK(s.sent() ==
          std::vector<std::string>{"000#0120", "220#0000000000000000", "320#0000000000000000"});
    ev = s.events();
    REQUIRE(ev.size() == 2);
    CHECK(ev[0].kind == event_kind::sdo_done);
    CHECK(ev[0].value == 0x0003'0191);
    CHECK(ev[1].kind == event_kind::ready);
    s.ctl.tick(millis{101});
    CHECK(s.sent().empty());
    s.ctl.tick(millis{102});  // the refresh, 100 ms after the first picture
    CHECK(s.sent() == std::vector<std::string>{"220#0000000000000000", "320#0000000000000000"});
}

TEST_CASE("controller, scripted: a string longer than the controller keeps is refused") {
    const message config[] = {sdo_read{object::device_name}};
    controller_config cfg;
    cfg.identify = false;
    cfg.keypad_heartbeat = duration_ms{0};
    cfg.configuration = config;
    scripted s(cfg);
    s.ctl.step(f_("715#00"), millis{0});
    CHECK(s.sent() == std::vector<std::string>{"615#4008100000000000"});
    s.ctl.step(f_("595#4108100014000000"), millis{1});  // 20 bytes announced
    s.ctl.step(f_("595#0041424344454647"), millis{2});
    s.ctl.step(f_("595#1041424344454647"), millis{3});
    s.ctl.step(f_("595#0041424344454647"), millis{4});  // 21 bytes: past the 16 it keeps
    const auto ev = s.events();
    REQUIRE(ev.size() == 3);
    CHECK(ev[1].kind == event_kind::sdo_refused);
    CHECK(ev[1].value == static_cast<std::uint32_t>(errc::buffer_too_small));
    CHECK(ev[2].kind == event_kind::ready);
}

TEST_CASE("controller: an LED the model lacks is refused") {
    controller_config cfg;
    cfg.keypad_model = model::pkp2200;
    controller<> c(cfg);
    CHECK(c.set_led(4, colour::white));
    CHECK(!c.set_led(5, colour::white));
    CHECK(!c.set_led(0, colour::white));
    // The PKP-3500-MT has no LED 1 and no LED 11 (its led_mask): each hole refused, its
    // neighbours and its last LED taken.
    controller_config mt;
    mt.keypad_model = model::pkp3500mt;
    controller<> m(mt);
    CHECK(!m.set_led(1, colour::red));
    CHECK(!m.set_led(1, colour::off));  // off too: the LED is not there to turn off
    CHECK(!m.set_led(11, colour::off));
    CHECK(m.set_led(2, colour::red));
    CHECK(m.set_led(10, colour::red));
    CHECK(!m.set_led(11, colour::red));
    CHECK(m.set_led(12, colour::red));
    CHECK(m.set_led(15, colour::red));
    CHECK(!m.set_led(16, colour::red));
}

TEST_CASE("controller: a colour the keypad cannot show, or no colour, is refused") {
    controller_config cfg;  // a PK1000: red and green planes
    controller<> c(cfg);
    CHECK(c.set_led(1, colour::amber));
    CHECK(c.led_on().red.contains(1));
    for (const colour no :
         {colour::blue, colour::cyan, colour::magenta, colour::white, static_cast<colour>(99)}) {
        CAPTURE(static_cast<int>(no));
        CHECK(!c.set_led(1, no));
        CHECK(c.led_on().red.contains(1));  // unchanged
    }
    leds blue;
    blue.blue.insert(1);
    CHECK(!c.set_leds(blue, {}));
    leds led29;
    led29.red.insert(29);
    CHECK(!c.set_leds(led29, {}));
    CHECK(c.set_leds({}, {}));
    CHECK(c.led_on() == leds{});
}

TEST_CASE("controller: one call's events fit the default queue (events_per_call)") {
    // Issue 26: 10 keys held past the long press and the repeat delay, one tick: 20 events, of
    // which a queue of 16 dropped 4 although the application polled after every call.
    static_assert(events_per_call(10) == 33 && default_event_capacity == events_per_call(16));
    static_assert(controller<>::event_capacity() >= events_per_call(15));
    controller_config cfg;
    cfg.identify = false;
    cfg.keypad_heartbeat = duration_ms{0};
    cfg.lost_after = duration_ms{0};
    auto run = []<std::size_t Events>(controller<8, Events>& c) {
        c.step(f_("715#00"), millis{0});
        while (c.poll()) {
        }
        while (c.next_frame()) {
        }
        c.step(f_("195#FF03000001"), millis{10});  // keys 1..10 pressed
        std::size_t n = 0;
        while (c.poll()) ++n;
        CHECK(n == 10);
        c.tick(millis{1000});  // past 800 ms (long press) and 500 ms (repeat): one call
        n = 0;
        while (const auto e = c.poll())
            n += e->kind == event_kind::key_long_press || e->kind == event_kind::key_repeat;
        return n;
    };
    controller<8> big(cfg);
    CHECK(run(big) == 20);
    CHECK(big.events_dropped() == 0);
    // A queue smaller than events_per_call drops what one call reports past it, and counts it.
    controller<8, 16> small(cfg);
    CHECK(run(small) == 16);
    CHECK(small.events_dropped() == 4);
}

TEST_CASE("controller: refused configuration entries wait for room in the queue") {
    // 2014h is not in a PKP-2400's dictionary: every entry is refused, each an event. With a
    // queue of 2, the setup goes on at each call as the application polls; none is dropped.
    const message refused = sdo_write{object::startup_show, show_value(startup_show::disabled)};
    const std::array<message, 7> config{refused, refused, refused, refused,
                                        refused, refused, refused};
    controller_config cfg;
    cfg.keypad_model = model::pkp2400;
    cfg.identify = false;
    cfg.keypad_heartbeat = duration_ms{0};
    cfg.lost_after = duration_ms{0};
    cfg.configuration = config;
    controller<16, 2> c(cfg);
    c.step(f_("715#00"), millis{0});
    std::vector<std::uint16_t> steps;
    bool ready = false;
    for (std::uint32_t t = 1; t < 20 && !ready; ++t) {
        while (const auto e = c.poll()) {
            if (e->kind == event_kind::sdo_refused) steps.push_back(e->step);
            ready = ready || e->kind == event_kind::ready;
        }
        c.tick(millis{t});
    }
    while (const auto e = c.poll()) ready = ready || e->kind == event_kind::ready;
    CHECK(ready);
    CHECK(steps == std::vector<std::uint16_t>{0, 1, 2, 3, 4, 5, 6});
    CHECK(c.events_dropped() == 0);
}

TEST_CASE("controller: a setup ended by a timeout is ready once, started once") {
    const message config[] = {sdo_read{object::device_type}};
    controller_config cfg;
    cfg.configuration = config;
    cfg.identify = false;
    cfg.keypad_heartbeat = duration_ms{0};
    cfg.lost_after = duration_ms{0};
    cfg.sdo_retries = 0;
    scripted s(cfg);
    s.ctl.step(f_("715#00"), millis{0});
    CHECK(s.sent() == std::vector<std::string>{"615#4000100000000000"});
    (void)s.events();
    s.ctl.tick(millis{300});  // no reply: timed out, and the setup ends in the same call
    const auto ev = s.events();
    REQUIRE(ev.size() == 2);
    CHECK(ev[0].kind == event_kind::sdo_timed_out);
    CHECK(ev[1].kind == event_kind::ready);
    CHECK(s.sent() ==
          std::vector<std::string>{"000#0115", "215#0000000000000000", "315#0000000000000000"});
}

TEST_CASE("controller: a list longer than max_configuration is cut, and says so") {
    static_assert(max_configuration == 65535);
    std::vector<message> config(max_configuration + 2, message{led_on{}});  // no SDO: skipped
    controller_config cfg;
    cfg.configuration = config;
    cfg.identify = false;
    cfg.keypad_heartbeat = duration_ms{0};
    scripted s(cfg);
    s.ctl.step(f_("715#00"), millis{0});
    const auto ev = s.events();
    REQUIRE(ev.size() == 3);
    CHECK(ev[0].kind == event_kind::found);
    CHECK(ev[1].kind == event_kind::sdo_refused);
    CHECK(ev[1].step == max_configuration);
    CHECK(ev[1].value == static_cast<std::uint32_t>(errc::value_out_of_range));
    CHECK(ev[2].kind == event_kind::ready);
}

// --- key modes ------------------------------------------------------------------------------

TEST_CASE("key modes: momentary, toggle, cycle") {
    key_modes<> k;
    // Each setting in turn; each bound at its end and one step outside: keys 1..16, a cycle of
    // 2 states or more (the default states, 2, are ignored but by cycle).
    struct set_row {
        unsigned key;
        key_mode mode;
        std::uint8_t states;
        bool taken;
    };
    const set_row settings[] = {
        {1, key_mode::momentary, 2, true}, {2, key_mode::toggle, 2, true},
        {3, key_mode::cycle, 3, true},     {4, key_mode::cycle, 1, false},
        {17, key_mode::toggle, 2, false},  {0, key_mode::toggle, 2, false},
        {16, key_mode::toggle, 2, true},   {4, key_mode::cycle, 0, false},
        {4, key_mode::cycle, 2, true},     {6, key_mode::cycle, 255, true},
    };
    for (const auto& r : settings) {
        CAPTURE(r.key);
        CHECK(k.set(r.key, r.mode, r.states) == r.taken);
    }
    CHECK(k.state(16) == 0);
    CHECK(k.state(17) == 0);
    CHECK(k.mode(17) == key_mode::momentary);
    // A cycle of 255 counts to 254, then wraps.
    const controller_event p6{event_kind::key_pressed, 6};
    for (unsigned s = 1; s < 255; ++s)
        CHECK(k.on_event(p6) == key_mode_change{6, static_cast<std::uint8_t>(s)});
    CHECK(k.on_event(p6) == key_mode_change{6, 0});
    const auto press = [](unsigned n) {
        return controller_event{event_kind::key_pressed, static_cast<std::uint8_t>(n)};
    };
    const auto release = [](unsigned n) {
        return controller_event{event_kind::key_released, static_cast<std::uint8_t>(n)};
    };
    struct row {
        controller_event e;
        std::optional<key_mode_change> change;
    };
    const row rows[] = {
        {press(1), key_mode_change{1, 1}},
        {release(1), key_mode_change{1, 0}},
        {press(2), key_mode_change{2, 1}},
        {release(2), std::nullopt},
        {press(2), key_mode_change{2, 0}},
        {press(3), key_mode_change{3, 1}},
        {press(3), key_mode_change{3, 2}},
        {release(3), std::nullopt},
        {press(3), key_mode_change{3, 0}},
        {controller_event{event_kind::key_long_press, 2}, std::nullopt},
        {press(5), key_mode_change{5, 1}},  // unset keys are momentary
        {press(4), key_mode_change{4, 1}},  // a cycle of 2 wraps after state 1
        {press(4), key_mode_change{4, 0}},
        {press(17), std::nullopt},  // a key past Keys changes nothing
    };
    for (const auto& r : rows) CHECK(k.on_event(r.e) == r.change);
    k.reset();
    CHECK(k.state(2) == 0);
    CHECK(k.mode(2) == key_mode::toggle);
}

// --- at compile time ----------------------------------------------------------------------------

namespace {
// The controller against the virtual keypad, in a constant expression: found, configured,
// started, and a key press lights the LED through the key modes.
constexpr bool closed_loop_session() {
    controller_config cfg;
    cfg.keypad_model = model::pkp2400;
    controller<8, 16> c(cfg);
    virtual_keypad<16> k(model::pkp2400);
    key_modes<8> modes;
    modes.set(3, key_mode::toggle);
    k.power_on(millis{0});
    for (std::uint32_t ms = 1; ms < 60; ++ms) {
        const millis t{ms};
        if (ms == 30) k.press(3, t);
        k.advance(t);
        while (const auto f = k.transmit()) c.step(*f, t);
        c.tick(t);
        while (const auto f = c.next_frame()) k.receive(*f, t);
        while (const auto e = c.poll())
            if (const auto change = modes.on_event(*e))
                c.set_led(change->key, change->state != 0 ? colour::green : colour::off);
    }
    return c.state() == controller_state::running && k.state() == run_state::operational &&
           c.model() == model::pkp2400 && k.led_on().green.contains(3) &&
           !k.led_on().green.contains(2);
}
static_assert(closed_loop_session());
}  // namespace

TEST_CASE("controller + virtual keypad: the same session at compile time and at run time") {
    CHECK(closed_loop_session());
}

// Each timer of the controller the millisecond before its deadline and at it (every deadline is
// reached at its millisecond: behaviour/clock.hpp's reached), from the defaults, which are pinned
// here (docs/controller.md).
TEST_CASE("controller, scripted: every timer the millisecond before and at its deadline") {
    const controller_config defaults;
    CHECK(defaults.keypad_heartbeat.value == 200);
    CHECK(defaults.lost_after.value == 600);
    CHECK(defaults.sdo_timeout.value == 300);
    CHECK(defaults.sdo_retries == 2);
    CHECK(defaults.probe_period.value == 1000);
    CHECK(defaults.refresh_period.value == 1000);
    CHECK(defaults.long_press.value == 800);
    CHECK(defaults.repeat_delay.value == 500);
    CHECK(defaults.repeat_period.value == 200);

    SUBCASE("a key held: the first repeat at 500 ms, then every 200 ms; the long press at 800") {
        controller_config cfg;
        cfg.identify = false;
        cfg.keypad_heartbeat = duration_ms{0};
        cfg.lost_after = duration_ms{0};
        scripted s(cfg);
        s.ctl.step(f_("715#00"), millis{0});
        (void)s.events();
        s.ctl.step(f_("195#0100000001"), millis{1000});
        CHECK(s.events() == std::vector<controller_event>{{event_kind::key_pressed, 1}});
        const auto at = [&s](std::uint32_t t) {
            s.ctl.tick(millis{t});
            return s.events();
        };
        const std::vector<controller_event> none;
        const std::vector<controller_event> repeat{{event_kind::key_repeat, 1}};
        const std::vector<controller_event> long_press{{event_kind::key_long_press, 1}};
        // Each tick in turn and what it brings. Woken late (at 2400, due 2100): one repeat, then
        // the period from then.
        const struct {
            std::uint32_t t;
            const std::vector<controller_event>& events;
        } ticks[] = {{1499, none},   {1500, repeat},     {1699, none},  {1700, repeat},
                     {1799, none},   {1800, long_press}, {1899, none},  {1900, repeat},
                     {2400, repeat}, {2599, none},       {2600, repeat}};
        for (const auto& tick : ticks) {
            CAPTURE(tick.t);
            CHECK(at(tick.t) == tick.events);
        }
        // repeat_period 0: the repeats come every repeat_delay; long_press 0: none.
        cfg.repeat_period = duration_ms{0};
        cfg.long_press = duration_ms{0};  // off
        scripted z(cfg);
        z.ctl.step(f_("715#00"), millis{0});
        z.ctl.step(f_("195#0100000001"), millis{1000});
        (void)z.events();
        z.ctl.tick(millis{1500});
        CHECK(z.events() == repeat);
        z.ctl.tick(millis{1999});
        CHECK(z.events().empty());
        z.ctl.tick(millis{2000});
        CHECK(z.events() == repeat);
    }
    SUBCASE("an SDO request: retried at 300 ms, twice by default, then timed out") {
        const message config[] = {sdo_read{object::boot_up}};
        controller_config cfg;
        cfg.configuration = config;
        cfg.identify = false;
        cfg.keypad_heartbeat = duration_ms{0};
        cfg.lost_after = duration_ms{0};
        scripted s(cfg);
        s.ctl.step(f_("715#00"), millis{10});
        const std::vector<std::string> request{"615#4011200000000000"};
        CHECK(s.sent() == request);
        for (const std::uint32_t sent : {10u, 310u}) {
            s.ctl.tick(millis{sent + 299});
            CHECK(s.sent().empty());
            s.ctl.tick(millis{sent + 300});
            CHECK(s.sent() == request);
        }
        (void)s.events();
        s.ctl.tick(millis{909});
        CHECK(s.events().empty());
        s.ctl.tick(millis{910});
        const auto ev = s.events();
        REQUIRE_FALSE(ev.empty());
        CHECK(ev[0].kind == event_kind::sdo_timed_out);
    }
    SUBCASE("searching: the probe every 1000 ms") {
        controller_config cfg;
        cfg.identify = false;
        scripted s(cfg);
        const std::vector<std::string> probe{"615#4000100000000000"};
        s.ctl.tick(millis{0});
        CHECK(s.sent() == probe);
        s.ctl.tick(millis{999});
        CHECK(s.sent().empty());
        s.ctl.tick(millis{1000});
        CHECK(s.sent() == probe);
    }
    SUBCASE("lost after 600 ms of silence: not at 600, at 601") {
        controller_config cfg;
        cfg.identify = false;
        cfg.keypad_heartbeat = duration_ms{0};
        scripted s(cfg);
        s.ctl.step(f_("715#00"), millis{0});
        (void)s.events();
        s.ctl.tick(millis{600});
        CHECK(s.events().empty());
        s.ctl.tick(millis{601});
        const auto ev = s.events();
        REQUIRE_FALSE(ev.empty());
        CHECK(ev[0].kind == event_kind::lost);
    }
    SUBCASE("the LED picture again every 1000 ms") {
        controller_config cfg;
        cfg.identify = false;
        cfg.keypad_heartbeat = duration_ms{0};
        cfg.lost_after = duration_ms{0};
        scripted s(cfg);
        s.ctl.step(f_("715#00"), millis{0});
        (void)s.sent();
        s.ctl.tick(millis{999});
        CHECK(s.sent().empty());
        s.ctl.tick(millis{1000});
        CHECK(s.sent() == std::vector<std::string>{"215#0000000000000000", "315#0000000000000000"});
    }
}

// --- the model known when the program is built ------------------------------------------------

namespace {
// One session of every behaviour the controller has (setup with a configuration list and active
// on startup, LEDs, levels, keys held, a node change, a reboot, a silence), as the bus and the
// events show it, for controller<16, 64, Keypad> and virtual_keypad<32, KeypadOfKeypad>.
template <class Keypad, class KeypadOfKeypad = any_model>
std::pair<std::vector<std::string>, std::vector<controller_event>> whole_session(model m) {
    const message config[] = {sdo_read{object::device_type}, sdo_read{object::heartbeat_time},
                              sdo_write{object::led_brightness, level_value(lv(0x21))},
                              sdo_read{object::model_name}};
    // controller<>: the messages; of model_constant<M>: the entries made from them.
    using ctl = controller<16, 64, Keypad>;
    const std::vector<typename ctl::entry> entries(std::begin(config), std::end(config));
    typename ctl::config cfg;
    cfg.configuration = entries;
    cfg.start = start_mode::active_on_startup;
    powerkey_tests::closed_loop<controller<16, 64, Keypad>, virtual_keypad<32, KeypadOfKeypad>> b(
        m, cfg, canopen::default_node_id);
    b.keypad.power_on(b.at());
    b.run(200);
    b.ctl.set_led(some_led, colour::red);
    b.ctl.set_led(3, colour::green, true);
    b.ctl.set_brightness(lv(0x10));
    b.ctl.set_backlight(lv(0x20), backlight_colour::red);
    b.run(50);
    b.keypad.press(1, b.at());
    b.run(1000);
    b.keypad.release(1, b.at());
    b.ctl.change_node(node_id::make(0x3A).value());
    b.run(300);
    b.keypad.power_off();
    b.keypad.power_on(b.at());
    b.run(300);
    b.keypad.silence(b.at(), duration_ms{1000});
    b.run(1500);
    return {b.candump(), b.events};
}

template <std::size_t... I>
void compile_time_controllers_agree(std::index_sequence<I...>) {
    (
        [] {
            constexpr model m = static_cast<model>(I);
            INFO("model " << std::string(to_string(m)));
            const auto run_time = whole_session<any_model>(m);
            const auto compile_time = whole_session<model_constant<m>>(m);
            CHECK(run_time.first == compile_time.first);
            CHECK(run_time.second == compile_time.second);
            // ... and so does the virtual keypad of one model (both at compile time).
            const auto both = whole_session<model_constant<m>, model_constant<m>>(m);
            CHECK(run_time.first == both.first);
            CHECK(run_time.second == both.second);
            // The session ran: set up twice (the reboot), a long press, lost once.
            const auto count = [&](event_kind k) {
                return std::count_if(compile_time.second.begin(), compile_time.second.end(),
                                     [k](const controller_event& e) { return e.kind == k; });
            };
            CHECK(count(event_kind::ready) >= 2);
            CHECK(count(event_kind::key_long_press) == 1);
            CHECK(count(event_kind::lost) == 1);
        }(),
        ...);
}
}  // namespace

// controller<..., model_constant<M>> (M's rows alone: firmware (c)) sends the same frames and
// reports the same events as the run-time controller of M, for every model; with
// virtual_keypad<..., model_constant<M>> too.
TEST_CASE("controller and virtual keypad: a model known at compile time behaves as at run time") {
    compile_time_controllers_agree(std::make_index_sequence<model_count>{});
}

// --- the requests of a controller of one model -----------------------------------------------

namespace {
// Every request a configuration list may hold: a read and a write (of 1) of every object, every
// command with its default parameters and with the largest,
// and a message that is no request (skipped).
std::vector<message> every_request() {
    std::vector<message> list;
    for (std::size_t i = 0; i < object_count; ++i) {
        const auto o = static_cast<object>(i);
        list.push_back(sdo_read{o});
        list.push_back(sdo_write{o, number_value(1)});
    }
    for (const auto& e : enum_names<command_code>::entries) {
        command c;
        c.code = e.value;
        list.push_back(c);
        c.level = lv(0x3F);
        c.colour = backlight_colour::yellow_green;
        c.node_id = node_id::make(0x7F).value();
        c.enabled = true;
        list.push_back(c);
    }
    list.push_back(led_on{});
    return list;
}

// The bus and the events of a setup whose configuration list is `entry` alone (no identify, no
// heartbeat write: the entry is all the setup sends), for a second.
template <class Keypad>
std::pair<std::vector<std::string>, std::vector<controller_event>> run_entry(model m,
                                                                             const message& entry) {
    using ctl = controller<16, 64, Keypad>;
    const typename ctl::entry entries[] = {entry};
    typename ctl::config cfg;
    cfg.configuration = entries;
    cfg.identify = false;
    cfg.keypad_heartbeat = duration_ms{0};
    powerkey_tests::closed_loop<ctl> b(m, cfg, canopen::default_node_id);
    b.keypad.power_on(b.at());
    b.run(1000);
    return {b.candump(), b.events};
}

template <std::size_t... I>
void configuration_entries_agree(std::index_sequence<I...>) {
    const auto list = every_request();
    (
        [&list] {
            constexpr model m = static_cast<model>(I);
            INFO("model " << std::string(to_string(m)));
            std::size_t answered = 0, refused = 0;
            for (const auto& entry : list) {
                const auto run_time = run_entry<any_model>(m, entry);
                const auto compile_time = run_entry<model_constant<m>>(m, entry);
                CHECK(run_time.first == compile_time.first);
                CHECK(run_time.second == compile_time.second);
                for (const auto& e : compile_time.second) {
                    if (e.origin != sdo_origin::configuration) continue;
                    if (e.kind == event_kind::sdo_refused) ++refused;
                    if (e.kind == event_kind::sdo_done || e.kind == event_kind::sdo_aborted)
                        ++answered;
                }
            }
            // Both kinds of entry were met: those the model carries, and those it refuses.
            CHECK(answered > 0);
            CHECK(refused > 0);
        }(),
        ...);
}

// Each value's frame of an own request, where it is proven (behaviour::detail::own_proof),
// against the encoder's own checks (powerkey::detail::own_frame) with the model's run-time layout,
// to three nodes.
template <model M, auto Make, class V>
void own_request_agrees() {
    using values = behaviour::detail::small_values<V>;
    constexpr auto proof = behaviour::detail::own_proof<M, Make, V>;
    for (unsigned r = values::first; r <= values::last; ++r) {
        const V v = values::of(r);
        for (const auto n : {0x01, 0x15, 0x7F}) {
            const auto node = node_id::make(n).value();
            const auto want =
                powerkey::detail::own_frame(powerkey::detail::layout(M), node, Make(v));
            if (!proof.proven) continue;
            const auto got = proof.frame(node, behaviour::detail::raw_of(v));
            REQUIRE(got.has_value() == want.has_value());
            if (want)
                CHECK(*got == *want);
            else
                CHECK(got.error() == want.error());
        }
    }
}

template <std::size_t... I>
void own_requests_agree(std::index_sequence<I...>) {
    (
        [] {
            constexpr model m = static_cast<model>(I);
            INFO("model " << std::string(to_string(m)));
            own_request_agrees<m, &behaviour::detail::read_of<object::model_name>,
                               std::monostate>();
            own_request_agrees<m, &behaviour::detail::write_of<object::active_on_startup, bool>,
                               bool>();
            own_request_agrees<m, &behaviour::detail::write_of<object::led_brightness, level>,
                               level>();
            own_request_agrees<m, &behaviour::detail::write_of<object::backlight_level, level>,
                               level>();
            own_request_agrees<
                m, &behaviour::detail::write_of<object::backlight_colour, backlight_colour>,
                backlight_colour>();
            own_request_agrees<m, &behaviour::detail::write_of<object::node_id, node_id>,
                               node_id>();
            own_request_agrees<
                m, &behaviour::detail::command_of<command_code::set_active_on_startup, bool>,
                bool>();
            own_request_agrees<m,
                               &behaviour::detail::command_of<command_code::set_backlight_colour,
                                                              backlight_colour>,
                               backlight_colour>();
            own_request_agrees<
                m, &behaviour::detail::command_of<command_code::set_node_id, node_id>, node_id>();
        }(),
        ...);
}

// Builds that are not one request with the value's byte in one place.
constexpr result<can::frame> two_bytes(level l) {
    can::payload p{0x2B, 0x00, 0x62, 0x01, l.value(), l.value(), 0, 0};
    return can::frame(canopen::cob_id(canopen::function::sdo_rx, canopen::default_node_id),
                      can::dlc::make(8).value(), p);
}
constexpr result<can::frame> one_range(level l);
constexpr result<can::frame> two_refusals(level l) {
    if (l.value() < 0x10) return errc::unknown_command;
    return one_range(l);
}
constexpr result<can::frame> not_one_range(level l) {
    can::payload p{0x2F, 0x00, 0x62, 0x01, l.value(), 0, 0, 0};
    if (l.value() == 0x20) return errc::value_out_of_range;
    return can::frame(canopen::cob_id(canopen::function::sdo_rx, canopen::default_node_id),
                      can::dlc::make(8).value(), p);
}
constexpr result<can::frame> one_range(level l) {
    if (l.value() > 0x30) return errc::value_out_of_range;
    can::payload p{0x2F, 0x00, 0x62, 0x01, l.value(), 0, 0, 0};
    return can::frame(canopen::cob_id(canopen::function::sdo_rx, canopen::default_node_id),
                      can::dlc::make(8).value(), p);
}
}  // namespace

// controller<..., model_constant<M>> takes its configuration list as configuration_entry<M>:
// the same frames and refusals as controller<> sends for the same messages, for every object,
// every command and every model.
TEST_CASE("controller of one model: configuration entries send what controller<> sends") {
    configuration_entries_agree(std::make_index_sequence<model_count>{});
}

// Its own requests (identify, active on startup, levels, colour, node change) proven when the
// program is built are the frames and refusals the encoder's checks give, to any node.
TEST_CASE("controller of one model: its proven own requests are the checked ones") {
    own_requests_agree(std::make_index_sequence<model_count>{});
    // Firmware (c)'s PKP-2400: every request of its own but the heartbeat period is proven.
    constexpr model pkp = model::pkp2400;
    static_assert(behaviour::detail::own_proof<pkp, &behaviour::detail::read_of<object::model_name>, std::monostate>
                      .proven);
    static_assert(
        behaviour::detail::own_proof<pkp, &behaviour::detail::command_of<command_code::set_backlight_colour,
                                                   backlight_colour>,
                          backlight_colour>
            .proven);
    static_assert(
        behaviour::detail::own_proof<pkp, &behaviour::detail::command_of<command_code::set_node_id, node_id>, node_id>
            .proven);
    static_assert(!behaviour::detail::own_proof<pkp, &behaviour::detail::write_of<object::heartbeat_time, duration_ms>,
                                     duration_ms>
                       .proven);
    // A proof takes one request with the value's byte in one place, the values taken one range
    // and one refusal for the others.
    static_assert(!behaviour::detail::prove<level>(two_bytes).proven);
    static_assert(!behaviour::detail::prove<level>(two_refusals).proven);
    static_assert(!behaviour::detail::prove<level>(not_one_range).proven);
    constexpr auto taken = behaviour::detail::prove<level>(one_range);
    static_assert(taken.proven && taken.lo == 0 && taken.hi == 0x30 && taken.at == 4 &&
                  taken.refused == errc::value_out_of_range);
}
