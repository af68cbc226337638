// j1939/id.hpp: the 29-bit J1939 identifier (priority, PGN, destination, source) both ways, and the
// identifiers a PGN cannot have.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/j1939/id.hpp>
#include <powerkey/j1939/name.hpp>

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
           make_id({6, 0xFEF1, 0xFE, 0}) == errc::value_out_of_range &&  // FEh: not FFh either
           !parse_id(can::candump("615#00")).has_value();
}
static_assert(refused_ids());
}  // namespace

TEST_CASE("J1939 identifiers both ways, and those a PGN cannot have") {
    check_rows(id_rows, id_holds);
    CHECK(refused_ids());
}

// The NAME (SAE J1939-81; the keypads' address claim, PKP2600SI J1939 manual 20): each of its 64
// bits alone. Bit 48 is reserved (reserved_not_zero); any other lands in its field, at the field's
// first bit as 1, and packs back to the same bit. The fields' bits, from bit 0: identity number
// 21, manufacturer code 11, ECU instance 3, function instance 5, function 8, reserved 1,
// vehicle system 7, vehicle system instance 4, industry group 3, arbitrary address capable 1.
namespace {
struct name_field {
    unsigned at, width;
};
constexpr name_field name_fields[] = {{0, 21}, {21, 11}, {32, 3}, {35, 5}, {40, 8},
                                      {49, 7}, {56, 4},  {60, 3}, {63, 1}};
constexpr std::uint64_t field_value(const powerkey::j1939::name& n, std::size_t i) {
    switch (i) {
        case 0: return n.identity_number.value();
        case 1: return n.manufacturer_code.value();
        case 2: return n.ecu_instance.value();
        case 3: return n.function_instance.value();
        case 4: return n.function;
        case 5: return n.vehicle_system.value();
        case 6: return n.vehicle_system_instance.value();
        case 7: return n.industry_group.value();
        default: return n.arbitrary_address_capable ? 1 : 0;
    }
}
constexpr bool every_name_bit_alone() {
    using namespace powerkey::j1939;
    for (unsigned b = 0; b < 64; ++b) {
        const std::uint64_t v = std::uint64_t{1} << b;
        const auto n = unpack_name(v);
        if (b == 48) {
            if (n || n.error() != powerkey::errc::reserved_not_zero) return false;
            continue;
        }
        if (!n || pack_name(*n) != v) return false;
        for (std::size_t i = 0; i < std::size(name_fields); ++i) {
            const auto [at, width] = name_fields[i];
            const bool here = b >= at && b < at + width;
            if (field_value(*n, i) != (here ? std::uint64_t{1} << (b - at) : 0)) return false;
        }
    }
    return true;
}
static_assert(every_name_bit_alone());
}  // namespace

TEST_CASE("J1939 NAME: each of its 64 bits alone, bit 48 reserved") {
    CHECK(every_name_bit_alone());
}

// make_id at the PDU1/PDU2 border: a PDU1 PGN (PF below F0h) carries no low byte (it is the
// destination): EF00h takes any destination, EF01h none; a PDU2 PGN (F000h) goes to FFh only.
TEST_CASE("J1939 identifiers: the PGN's low byte at the PDU1 and PDU2 border") {
    using namespace powerkey::j1939;
    identifier id{};
    id.priority = priority::make(6).value();
    id.source = 0x00;
    id.destination = 0x21;
    id.pgn = pgn::make(0xEF00).value();
    CHECK(make_id(id).has_value());
    id.pgn = pgn::make(0xEF01).value();
    CHECK(make_id(id) == powerkey::errc::value_out_of_range);
    id.pgn = pgn::make(0xEF80).value();
    CHECK(make_id(id) == powerkey::errc::value_out_of_range);
    id.pgn = pgn::make(0xF000).value();
    CHECK(make_id(id) == powerkey::errc::value_out_of_range);  // PDU2: only to FFh
    id.destination = global_address;
    CHECK(make_id(id).has_value());
    CHECK(parse_id(*make_id(id)).pgn.value() == 0xF000);
    id.pgn = pgn::make(0xEFFF).value();
    CHECK(make_id(id) == powerkey::errc::value_out_of_range);  // PDU1: EFh is below F0h
}
