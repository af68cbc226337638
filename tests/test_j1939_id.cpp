// j1939/id.hpp: the 29-bit J1939 identifier (priority, PGN, destination, source) both ways, and the
// identifiers a PGN cannot have.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/j1939/id.hpp>

#include "support.hpp"

#include <string_view>

namespace {
using namespace powerkey;
using namespace powerkey::j1939;

using namespace powerkey_tests;

struct id_row {
    std::string_view section;
    std::string_view frame;  // the identifier, as a frame without data
    identifier fields;
};
constexpr id_row id_rows[] = {
    {"PK1000 49: switch back, PDU1 to the keypad", "18EF2100#", {6, 0xEF00, 0x21, 0x00}},
    {"PDU1 with the data page bit", "19EF2100#", {6, 0x1EF00, 0x21, 0x00}},
    {"PDU1, priority 0, global destination", "00EAFFFE#", {0, 0xEA00, 0xFF, 0xFE}},
    {"PDU2 (PGN FEF1h, CCVS), no destination", "18FEF100#", {6, 0xFEF1, global_address, 0x00}},
    {"priority 7, extended data page", "1EF00021#", {7, 0x2F000, global_address, 0x21}},
};
constexpr bool id_holds(const id_row& r) {
    const auto id = powerkey_tests::frame_of(r.frame).raw_id();
    const auto made = make_id(r.fields);
    if (!made || made->value() != id) return false;
    return parse_id(can::extended_id::make(id).value()) == r.fields &&
           parse_id(powerkey_tests::frame_of(r.frame)) == r.fields;
}
static_assert(first_failing(id_rows, id_holds) == std::size(id_rows));

// J1939-21: a PDU1 PGN's low byte is the destination field, 00h in the PGN (PK1000 49: PGN
// EF00h); a PDU2 PGN (PF F0h and above) is broadcast and has no destination.
// An 11-bit frame has no J1939 identifier.
constexpr bool refused_ids() {
    return make_id({6, 0xEF21, 0x21, 0}) == errc::value_out_of_range &&
           make_id({6, 0xFEF1, 0x21, 0}) == errc::value_out_of_range &&
           !parse_id(can::candump("615#00")).has_value();
}
static_assert(refused_ids());
}  // namespace

TEST_CASE("J1939 identifiers both ways, and those a PGN cannot have") {
    check_rows(id_rows, id_holds);
    CHECK(refused_ids());
}
