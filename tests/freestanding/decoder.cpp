// Freestanding checks of the keypad decoder on the core rows, the session follower and the
// description writer: no exceptions, no RTTI, no heap.
#include <powerkey/can/candump.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/keypad/accessors.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/session.hpp>

#include "../codec_rows.hpp"
#include "check.hpp"

#include <array>

namespace {
using namespace powerkey;

bool decoder() {
    bool ok = true;
    auto expect = [&ok](bool b) { ok = ok && b; };
    std::array<char, 160> buf{};
    for (const auto& r : codec_rows::core_rows) {
        expect(codec_rows::round_trips(r));
        const auto node = codec_rows::node_of(r.node);
        expect(describe(r.expected, node, buf).has_value());
    }
    for (const auto& r : codec_rows::core_error_rows) expect(codec_rows::refused(r));
    for (const auto& r : codec_rows::foreign_rows) {
        const auto f = can::parse_candump(r.frame).value();
        expect(canopen::classify(f) == r.cls);
        for (const model m : enum_values<model>())
            expect(decode(f, canopen::default_node_id, m) == r.error);
    }
    // The firmware loop: key 3 pressed lights key 3 green.
    const std::uint8_t rx[5] = {0x04, 0x00, 0x00, 0x00, 0x2A};
    const auto f = can::make_frame(0x195, {rx, 5});
    expect(f.has_value());
    if (!f) return false;
    const auto msg = decode(*f, canopen::default_node_id, model::pkp2400);
    const auto keys = msg ? pressed_keys(*msg) : std::nullopt;
    expect(keys.has_value() && keys->contains(3));
    leds map;
    map.set(3, colour::green);
    expect(encode(canopen::default_node_id, model::pkp2400, led_on{map}) ==
           result<can::frame>(can::candump("215#0004000000000000")));
    return ok;
}

bool session_follows() {
    session<> s(model::pk1000, canopen::default_node_id);
    bool done = false;
    for (auto text : {"615#4008100000000000", "595#410810000B000000", "615#6000000000000000",
                      "595#00426C696E6B4D61", "615#7000000000000000", "595#1772696E65000000",
                      "615#2F1320003A000000", "5BA#6013200000000000"})
        done = s.step(can::parse_candump(text).value()).upload_done || done;
    return done && s.text() == "BlinkMarine" && s.node() == canopen::node_id(0x3A);
}

const freestanding::registration reg_decoder("decoder", decoder);
const freestanding::registration reg_session("session", session_follows);
}  // namespace
