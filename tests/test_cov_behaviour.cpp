// The paths of the session, the behaviour layer and a few core helpers that the other suites do
// not take: the host aborting a transfer (CiA 301 7.2.4.3.17), NMT pre-operational and reset
// before a PDO, SDO command specifiers the keypad does not serve, a two-colour LED state, a
// controller whose event queue or outbox is too small, a configuration entry that is no SDO.
#include "support.hpp"

#include <powerkey/behaviour/checker.hpp>
#include <powerkey/behaviour/controller.hpp>
#include <powerkey/behaviour/virtual_keypad.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/canopen/sdo_upload.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/j1939/id.hpp>
#include <powerkey/session.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

using namespace powerkey;
using namespace powerkey::behaviour;
using powerkey_tests::frame_of;

namespace {

// --- the session ---------------------------------------------------------------------------------

TEST_CASE("session: the host aborts an upload; a late reply then answers nothing") {
    session<> s(model::pk1000, canopen::node_id::make(0x15).value());
    CHECK(s.step(frame_of("615#4008100000000000")).sdo == sdo_pairing::request);
    // CiA 301 7.2.4.3.17: the client's abort (here "timed out", 05040000h) ends the transfer.
    const auto abort = s.step(frame_of("615#8008100000000405"));
    CHECK(abort.sdo == sdo_pairing::request);
    CHECK(abort.decoded == result<message>(canopen::sdo_abort_request{
                               {{0x1008, 0}, canopen::sdo_abort_code::timed_out}}));
    const auto late = s.step(frame_of("595#410810000B000000"));
    CHECK(late.sdo == sdo_pairing::unanswered);
    CHECK_FALSE(late.upload_done);
}

// --- the checker ---------------------------------------------------------------------------------

struct entry {
    std::uint32_t ms;
    std::string_view frame;
};

std::vector<problem> check(model m, const std::vector<entry>& log) {
    checker_config cfg;
    cfg.keypad_model = m;
    checker<> c(cfg);
    std::vector<problem> out;
    std::uint32_t line = 0, last = 0;
    for (const auto& e : log) {
        for (const auto& p : c.step(frame_of(e.frame), millis{e.ms}, ++line)) out.push_back(p);
        last = e.ms;
    }
    for (const auto& p : c.finish(millis{last})) out.push_back(p);
    return out;
}

TEST_CASE("checker: NMT pre-operational, reset node and reset communication stop the PDOs") {
    // PK1000 5, 6 (CiA 301 reset communication 82h): the keypad is pre-operational afterwards
    // and ignores PDOs until the next NMT start (PK1000 11).
    for (const std::string_view nmt : {"000#8015", "000#8115", "000#8215", "000#8000"}) {
        CAPTURE(std::string(nmt));
        const auto ps =
            check(model::pk1000,
                  {{0, "715#00"}, {5, "000#0115"}, {10, nmt}, {20, "215#0100000000000000"}});
        REQUIRE(ps.size() == 1);
        CHECK(ps[0] == problem{4, problem_kind::pdo_not_operational, {0x215, 0x7F, 0}});
    }
    // An NMT command to another node changes nothing.
    CHECK(check(model::pk1000,
                {{0, "715#00"}, {5, "000#0115"}, {10, "000#8016"}, {20, "215#0100000000000000"}})
              .empty());
}

TEST_CASE("checker: after the host's abort the next request is no overlap and none is unanswered") {
    CHECK(check(model::pk1000, {{0, "715#00"},
                                {10, "615#4008100000000000"},
                                {11, "615#8008100000000405"},
                                {20, "615#4011200000000000"},
                                {21, "595#4F11200001000000"},
                                {900, "715#7F"}})
              .empty());
}

// --- the virtual keypad --------------------------------------------------------------------------

// The frames a powered keypad sends within 50 ms of receiving `in`.
template <std::size_t N>
std::vector<std::string> answer(virtual_keypad<N>& k, std::string_view in, std::uint32_t& now) {
    k.receive(frame_of(in), millis{now});
    now += 50;
    k.advance(millis{now});
    std::vector<std::string> out;
    while (const auto f = k.transmit()) out.emplace_back(can::format_candump(*f).view());
    return out;
}

TEST_CASE("virtual keypad: SDO command specifiers it does not serve, and the host's abort") {
    virtual_keypad<> k(model::pk1000);
    std::uint32_t now = 0;
    k.power_on(millis{now});
    while (k.transmit()) {
    }
    using v = std::vector<std::string>;
    // ccs 5 (block upload, CiA 301 7.2.4.3.13): abort 05040001h, command specifier not valid.
    CHECK(answer(k, "615#A008100000000000", now) == v{"595#8008100001000405"});
    // A segmented download (21h) to the writable 2013h: abort 06010000h, unsupported access
    // (every object of the keypads fits an expedited transfer).
    CHECK(answer(k, "615#2113200004000000", now) == v{"595#8013200000000106"});
    // The device name (PK1000 32): 41h, 11 bytes; the host aborts: nothing answers the abort,
    // and the next segment request finds no transfer.
    CHECK(answer(k, "615#4008100000000000", now) == v{"595#410810000B000000"});
    CHECK(answer(k, "615#8008100000000405", now).empty());
}

TEST_CASE("virtual keypad: the red/green blink of command 01h (PKP 13 a 0Ah, PKP 12)") {
    virtual_keypad<> k(model::pkp2400);
    std::uint32_t now = 0;
    k.power_on(millis{now});
    while (k.transmit()) {
    }
    // PKP 12: "Only LED #4 blinks red and green in alternate mode" is green on, red and green
    // blinking; command 01h state 0Ah sets LED 8 the same way.
    CHECK(answer(k, "615#2300650101080A00", now) ==
          std::vector<std::string>{"595#6000650100000000"});
    CHECK(k.led_on() == leds{{}, {8}, {}});
    CHECK(k.led_blink() == leds{{8}, {8}, {}});
}

TEST_CASE("virtual keypad: the strings each keypad reports") {
    const auto name = info(model::pk1000)->string_of(object::device_name);
    REQUIRE(name.has_value());
    CHECK(name->bytes == "BlinkMarine");
    CHECK(name->announced == 11);
    // The PK1000 has no 6100h sub 2 (a PKP object).
    CHECK_FALSE(info(model::pk1000)->string_of(object::device_model).has_value());
}

// --- the controller ------------------------------------------------------------------------------

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

TEST_CASE("controller: a full event queue keeps the first events and counts the rest") {
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

TEST_CASE("controller: with a one-frame outbox the setup still completes") {
    loop<1, 64> one({});
    one.keypad.power_on(millis{0});
    one.run(2000);
    bool ready = false;
    for (const auto& e : one.events) ready = ready || e.kind == event_kind::ready;
    CHECK(ready);
}

TEST_CASE("controller: a request that found the outbox full is sent at the next tick") {
    // PKP-2400: no brightness PDO, so the LED level goes by SDO (6201h sub 1, PKP 30) right
    // after the NMT start, which fills a one-frame outbox.
    loop<1, 64> l({}, model::pkp2400);
    l.ctl.set_brightness(level::make(0x10).value());
    l.keypad.power_on(millis{0});
    l.run(2000);
    CHECK(l.keypad.brightness() == level::make(0x10).value());
}

TEST_CASE("controller: replies for another object or out of turn do not end a read") {
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
    ctl.step(frame_of("715#00"), millis{now});
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
        ctl.step(frame_of(stray), millis{++now});
        CHECK(sent().empty());
        CHECK(events().empty());
    }
    // The reply: 7 bytes, "PK1000" and a NUL (PK1000 35, E-CORE-5), in one segment.
    ctl.step(frame_of("595#410B100007000000"), millis{++now});
    CHECK(sent() == std::vector<std::string>{"615#6000000000000000"});
    ctl.step(frame_of("595#01504B3130303000"), millis{++now});
    const auto done = events();
    REQUIRE_FALSE(done.empty());
    CHECK(done[0].kind == event_kind::sdo_done);
    CHECK(done[0].origin == sdo_origin::identify);
    CHECK(done[0].what == object::model_name);
}

TEST_CASE("controller: a configuration entry that is no SDO request is skipped") {
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

// --- core helpers --------------------------------------------------------------------------------

TEST_CASE("expedited data of 1, 2 and 4 bytes, and the candump text as a string") {
    const auto node = canopen::node_id::make(0x15).value();
    using canopen::expedited_data;
    using canopen::sdo_download_request;
    // PK1000 23: node id 3Ah in one byte; 29: 50 ms in two; 28: 100 ms, producer 7Eh in four.
    const auto one =
        canopen::encode(node, sdo_download_request{{0x2013, 0}, expedited_data::u8(0x3A)});
    const auto two =
        canopen::encode(node, sdo_download_request{{0x1017, 0}, expedited_data::u16(50)});
    const auto four =
        canopen::encode(node, sdo_download_request{{0x1016, 1}, expedited_data::u32(0x007E'0064)});
    CHECK(can::format_candump(one) == std::string_view("615#2F1320003A000000"));
    CHECK(can::format_candump(two) == std::string_view("615#2B17100032000000"));
    const auto four_text = can::format_candump(four);
    const std::string_view text = four_text;  // the conversion to a view of its buffer
    CHECK(text == "615#2316100164007E00");
}

TEST_CASE("a segment other than the last that carries fewer than 7 bytes is noted") {
    // CiA 301 7.2.4.3.7: only the last segment may leave bytes unused (n > 0).
    canopen::segmented_upload<32> u(canopen::node_id::make(0x15).value());
    CHECK(u.start({0x1008, 0}) == frame_of("615#4008100000000000"));
    REQUIRE(u.step(frame_of("595#410810000B000000")).has_value());
    const auto s = u.step(frame_of("595#02426C696E6B4D00"));  // "BlinkM", n = 1, not the last
    REQUIRE(s.has_value());
    CHECK(u.notes().short_segment);
    canopen::segmented_upload<32> strict(canopen::node_id::make(0x15).value(),
                                         canopen::upload_policy::strict);
    (void)strict.start({0x1008, 0});
    REQUIRE(strict.step(frame_of("595#410810000B000000")).has_value());
    CHECK(strict.step(frame_of("595#02426C696E6B4D00")) == errc::size_mismatch);
}

TEST_CASE("J1939 identifiers a PGN cannot have, and the COB-ID bases of functions per node") {
    // J1939-21: a PDU2 PGN (PF F0h and above) is broadcast, destination FFh only; a PDU1 PGN's
    // low byte is the destination field, 00h in the PGN (PK1000 49: PGN EF00h).
    j1939::identifier pdu2;
    pdu2.pgn = j1939::pgn::make(0xFEF1).value();
    pdu2.destination = 0x21;
    CHECK(j1939::make_id(pdu2) == errc::value_out_of_range);
    j1939::identifier pdu1;
    pdu1.pgn = j1939::pgn::make(0xEF21).value();
    CHECK(j1939::make_id(pdu1) == errc::value_out_of_range);
    // CiA 301 7.3.5: NMT and SYNC have no node, nor has another identifier: cob_id gives 000h
    // for them (use nmt_cob_id and sync_cob_id); SDO rx of node 15h is 615h.
    const auto node = canopen::node_id::make(0x15).value();
    for (const auto f : {canopen::function::nmt, canopen::function::sync, canopen::function::j1939,
                         canopen::function::other})
        CHECK(canopen::cob_id(f, node).value() == 0x000);
    CHECK(canopen::cob_id(canopen::function::sdo_rx, node).value() == 0x615);
}

TEST_CASE("descriptions of the PKP-3500-MT encoder objects (MT 19 b, 20 c)") {
    const auto node = canopen::node_id::make(0x15).value();
    std::array<char, 160> buf{};
    // 595#4F00200281000000: one tick counterclockwise; 615#2301200480000000: ring LED 8.
    CHECK(describe(message{sdo_read_reply{object::encoder1_direction_counter, number_value(0x81)}},
                   node, buf) ==
          result<std::string_view>("node 15h  SDO read reply  object: encoder1_direction_counter  "
                                   "counterclockwise: yes  ticks: 1"));
    CHECK(describe(message{sdo_write{object::led_on_encoder, number_value(0x80)}}, node, buf) ==
          result<std::string_view>("node 15h  SDO write  object: led_on_encoder  leds: 8"));
}

TEST_CASE("an SDO value of no kind and the command module show only their object") {
    auto names = [](const message& m) {
        std::string s;
        for_each_field(m, [&s](std::string_view n, const auto&) {
            s += std::string(n);
            s += ' ';
        });
        return s;
    };
    // 1001h has no value (PK1000 31: the keypad aborts); 6500h carries commands, not a value.
    CHECK(names(sdo_read_reply{object::error_register, {}}) == "object ");
    CHECK(names(sdo_write{object::command_module, {}}) == "object ");
    CHECK(names(sdo_read_reply{object::encoder1_direction_counter, {}}) ==
          "object counterclockwise ticks ");
    CHECK(names(sdo_write{object::led_on_encoder, {}}) == "object leds ");
}

}  // namespace
