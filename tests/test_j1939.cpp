// J1939: the 29-bit identifier both ways, and the keypad's switch-back frame (PK1000 49).
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/j1939/id.hpp>
#include <powerkey/j1939/protocol_switch.hpp>

#include <string_view>

namespace {
using namespace powerkey;
using namespace powerkey::j1939;

struct id_row {
    std::string_view what;
    std::uint32_t id;
    identifier fields;
};
constexpr id_row id_rows[] = {
    {"PK1000 49: switch back, PDU1 to the keypad", 0x18EF2100, {6, 0xEF00, 0x21, 0x00}},
    {"PDU1 with the data page bit", 0x19EF2100, {6, 0x1EF00, 0x21, 0x00}},
    {"PDU1, priority 0, global destination", 0x00EAFFFE, {0, 0xEA00, 0xFF, 0xFE}},
    {"PDU2 (PGN FEF1h, CCVS), no destination", 0x18FEF100, {6, 0xFEF1, global_address, 0x00}},
    {"priority 7, extended data page", 0x1EF00021, {7, 0x2F000, global_address, 0x21}},
};
constexpr bool ids_hold() {
    for (const auto& r : id_rows) {
        const auto made = make_id(r.fields);
        if (!made || made->value() != r.id) return false;
        if (parse_id(can::extended_id::make(r.id).value()) != r.fields) return false;
    }
    return true;
}
static_assert(ids_hold());

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
    std::string_view why;
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
constexpr bool all_refused() {
    for (const auto& r : bad_rows)
        if (decode_switch_to_canopen(can::parse_candump(r.frame).value()) != r.error) return false;
    return true;
}
static_assert(all_refused());
}  // namespace

TEST_CASE("J1939 identifiers both ways") {
    CHECK(ids_hold());
    for (const auto& r : id_rows) {
        CAPTURE(r.what);
        const auto made = make_id(r.fields);
        REQUIRE(made.has_value());
        CHECK(made->value() == r.id);
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
    for (const auto& r : bad_rows) {
        CAPTURE(r.why);
        CHECK(decode_switch_to_canopen(can::parse_candump(r.frame).value()).error() == r.error);
    }
}
