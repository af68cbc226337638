// J1939: the 29-bit identifier both ways, and the keypad's switch-back frame (PK1000 49).
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/j1939/id.hpp>
#include <powerkey/j1939/protocol_switch.hpp>

#include "support.hpp"

#include <string_view>

namespace {
using namespace powerkey;
using namespace powerkey::j1939;

using powerkey_tests::check_rows;
using powerkey_tests::first_failing;

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

// PDU1 PGNs keep the destination in its own field; a PDU2 message has none.
static_assert(make_id({6, 0xEF21, 0x21, 0}) == errc::value_out_of_range);
static_assert(make_id({6, 0xFEF1, 0x21, 0}) == errc::value_out_of_range);
static_assert(!parse_id(can::candump("615#00")).has_value());

// The switch-back frame, built for the default addresses and for others.
static_assert(encode(switch_to_canopen{}) == can::candump("18EF2100#041B8000FFFFFFFF"));
static_assert(encode(switch_to_canopen{6, 0x30, 0xF9}) ==
              can::candump("18EF30F9#041B8000FFFFFFFF"));
static_assert(encode(switch_to_canopen{3, 0x21, 0x00}) ==
              can::candump("0CEF2100#041B8000FFFFFFFF"));
static_assert(decode_switch_to_canopen(can::candump("18EF2100#041B8000FFFFFFFF")).value() ==
              switch_to_canopen{});

struct bad_row {
    std::string_view section;
    std::string_view frame;
    errc error;
};
constexpr bad_row bad_rows[] = {
    {"an 11-bit id", "615#041B8000FFFFFFFF", errc::wrong_id_format},
    {"another PGN", "18EE2100#041B8000FFFFFFFF", errc::wrong_id},
    {"PDU2", "18FEF100#041B8000FFFFFFFF", errc::wrong_id},
    {"7 bytes", "18EF2100#041B8000FFFFFF", errc::wrong_length},
    {"other proprietary data", "18EF2100#041B8000FFFFFFFE", errc::unknown_command},
};
constexpr bool refused(const bad_row& r) {
    return decode_switch_to_canopen(powerkey_tests::frame_of(r.frame)) == r.error;
}
static_assert(first_failing(bad_rows, refused) == std::size(bad_rows));
}  // namespace

TEST_CASE("J1939 identifiers both ways") {
    check_rows(id_rows, id_holds);
    for (const auto& r : id_rows) {
        CAPTURE(r.section);
        const auto made = make_id(r.fields);
        REQUIRE(made.has_value());
        CHECK(made->value() == powerkey_tests::frame_of(r.frame).raw_id());
        CHECK(parse_id(*made) == r.fields);
    }
}

TEST_CASE("the switch back to CANopen, PK1000 49") {
    const auto f = can::parse_candump("18EF2100#041B8000FFFFFFFF");
    REQUIRE(f.has_value());
    CHECK(encode(switch_to_canopen{}) == *f);
    const auto m = decode_switch_to_canopen(*f);
    REQUIRE(m.has_value());
    constexpr priority six = 6;
    CHECK(m->priority == six);
    CHECK(m->destination == 0x21);
    CHECK(m->source == 0x00);
    check_rows(bad_rows, refused);
    for (const auto& r : bad_rows) {
        CAPTURE(r.section);
        CHECK(decode_switch_to_canopen(can::parse_candump(r.frame).value()).error() == r.error);
    }
}
