// Freestanding check of the J1939 rows: every manual row decodes to its meaning and re-encodes
// byte for byte (any keypad and narrowed), every refused frame and message is refused, and the
// firmware loop (a key contact state in, an LED command out) runs, with no exceptions, no RTTI
// and no heap.
#include <powerkey/powerkey.hpp>

#include "../j1939_rows.hpp"
#include "check.hpp"

#include <array>
#include <variant>

namespace {
using namespace powerkey;

bool j1939_rows_both_ways() {
    bool ok = true;
    std::array<char, 320> buf{};  // the address claim needs 286
    const auto both_ways = [&](const auto& rows) {
        for (const auto& r : rows) {
            ok = ok && j1939_rows::round_trips(r);
            ok = ok && describe(r.expected, canopen::default_node_id, buf).has_value();
        }
    };
    both_ways(j1939_rows::pkp1600si_rows);
    both_ways(j1939_rows::pkp2600si_rows);
    both_ways(j1939_rows::other_rows);
    for (const auto& r : j1939_rows::error_rows) ok = ok && j1939_rows::refused(r);
    for (const auto& r : j1939_rows::encode_error_rows) ok = ok && j1939_rows::encode_refused(r);

    // The firmware loop: key 3 of the PKP-1600-SI at 21h pressed lights LED 3 green.
    const std::uint8_t rx[8] = {0x04, 0x1B, 0x01, 0x03, 0x01, 0x21, 0xFF, 0xFF};
    const auto f = can::make_frame(0x18EF'FF21, {rx, 8}, can::id_format::extended);
    const auto m = f ? j1939::decode(*f, model::pkp1600si, std::uint8_t{0x21})
                     : result<j1939::message>(errc::wrong_length);
    const auto* k = m ? std::get_if<j1939::key_contact>(&*m) : nullptr;
    ok = ok && k != nullptr && k->key == 3 && k->pressed;
    if (k == nullptr) return false;
    j1939::set_led led;
    led.key = k->key;
    led.colour = j1939::led_colour::green;
    led.mode = led_mode::on;
    ok = ok && j1939::encode(model::pkp1600si, led, std::uint8_t{0x21}) ==
                   result<can::frame>(can::candump("18EF2100#041B0103020100FF"));
    return ok;
}
const freestanding::registration reg("j1939", j1939_rows_both_ways);
}  // namespace
