// Freestanding checks of the any-frame decoder, the session follower and the description writer:
// no exceptions, no RTTI, no heap.
#include <powerkey/can/candump.hpp>
#include <powerkey/decoder.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/session.hpp>

#include "../decoder_rows.hpp"
#include "../pk1000_rows.hpp"
#include "../pkp_rows.hpp"
#include "check.hpp"

#include <array>

namespace {
using namespace powerkey;

bool decoder() {
    bool ok = true;
    auto expect = [&ok](bool b) { ok = ok && b; };
    std::array<char, 160> buf{};
    for (const auto& r : pk1000_rows::rows) {
        const auto f = can::parse_candump(r.frame).value();
        const auto d = decode(f, r.node, model::pk1000);
        expect(d.has_value() && encode(r.node, model::pk1000, *d) == result<can::frame>(f));
        expect(d.has_value() && describe(*d, r.node, buf).has_value());
    }
    for (model m : {model::pkp2200, model::pkp2400, model::pkp2600}) {
        for (const auto& r : pkp_rows::rows) {
            if (!pkp_rows::applies(r.models, *pkp_model(m))) continue;
            const auto node = canopen::node_id::make(r.node).value();
            const auto f = can::parse_candump(r.frame).value();
            const auto d = decode(f, node, m);
            expect(d.has_value() && encode(node, m, *d) == result<can::frame>(f));
            expect(d.has_value() && describe(*d, node, buf).has_value());
        }
    }
    for (const auto& r : decoder_rows::foreign_rows)
        expect(decode(can::parse_candump(r.frame).value(), canopen::default_node_id,
                      model::pk1000) == r.error);
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
