// j1939/protocol_switch.hpp: the keypad's switch back from J1939 to CANopen (PK1000 section 49),
// built for the default addresses and for others, and what its decoder refuses.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/j1939/protocol_switch.hpp>

#include "support.hpp"

namespace {
using namespace powerkey;
using namespace powerkey::j1939;

using namespace powerkey_tests;

// PK1000 49: priority 6, PGN EF00h to the keypad at 21h from the host at 00h.
static_assert(encode(switch_to_canopen{}) == can::candump("18EF2100#041B8000FFFFFFFF"));
static_assert(encode(switch_to_canopen{6, 0x30, 0xF9}) ==
              can::candump("18EF30F9#041B8000FFFFFFFF"));
static_assert(encode(switch_to_canopen{3, 0x21, 0x00}) ==
              can::candump("0CEF2100#041B8000FFFFFFFF"));

constexpr bool decodes_pk1000_49() {
    const auto m = decode_switch_to_canopen(can::candump("18EF2100#041B8000FFFFFFFF"));
    constexpr priority six = 6;
    return m && *m == switch_to_canopen{} && m->priority == six && m->destination == 0x21 &&
           m->source == 0x00;
}
static_assert(decodes_pk1000_49());

constexpr bad_row bad_rows[] = {
    {"an 11-bit id", "615#041B8000FFFFFFFF", errc::wrong_id_format},
    {"another PGN", "18EA2100#041B8000FFFFFFFF", errc::wrong_id},
    {"PDU2", "18FEF100#041B8000FFFFFFFF", errc::wrong_id},
    {"7 bytes", "18EF2100#041B8000FFFFFF", errc::wrong_length},
    {"other proprietary data", "18EF2100#041B8000FFFFFFFE", errc::unknown_command},
    // No source shows a keypad acting on a command to the global address (docs/j1939.md): the
    // keypad codec refuses it, and so does this decoder.
    {"to the global address", "18EFFF00#041B8000FFFFFFFF", errc::undocumented},
};
constexpr auto switch_refuses =
    refused_by([](const can::frame& f) { return decode_switch_to_canopen(f); });
static_assert(first_failing(bad_rows, switch_refuses) == std::size(bad_rows));
}  // namespace

TEST_CASE("the switch back to CANopen, PK1000 49") {
    CHECK(decodes_pk1000_49());
    check_rows(bad_rows, switch_refuses);
}
