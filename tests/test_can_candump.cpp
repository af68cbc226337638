// The frame vocabulary and the candump text form.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>

#include "support.hpp"

#include <array>
#include <string_view>

namespace {
using namespace powerkey;
using can::candump;
using powerkey_tests::check_rows;
using powerkey_tests::first_failing;

struct text_row {
    std::string_view section;
    std::string_view frame;
};
// Text that round-trips exactly, as logs print it.
constexpr text_row round_trip_rows[] = {
    {"PK1000 16, read key states", "615#4000200100000000"},
    {"PK1000 49, switch back to CANopen", "18EF2100#041B8000FFFFFFFF"},
    {"PK1000 10, SYNC", "080#"},
    {"PK1000 8, boot-up", "715#00"},
    {"PK1000 4, start node 15h", "000#0115"},
};

constexpr bool round_trips(const text_row& r) {
    const auto f = can::parse_candump(r.frame);
    return f && can::format_candump(*f).view() == r.frame;
}
static_assert(first_failing(round_trip_rows, round_trips) == std::size(round_trip_rows));

static_assert(!candump("615#00").is_extended());
static_assert(candump("18EF2100#00").is_extended());
static_assert(candump("615#4000200100000000").size() == 8);
static_assert(candump("080#").size() == 0);
// Standard 615h and extended 00000615h are different frames.
static_assert(candump("615#01") != candump("00000615#01"));
static_assert(candump("615#01") != candump("615#0100"));
static_assert(candump("615#0a") == candump("615#0A"));

struct bad_text {
    std::string_view section;
    std::string_view frame;  // the text
    errc error;
};
constexpr bad_text bad_rows[] = {
    {"empty", "", errc::syntax_error},
    {"no #", "615", errc::syntax_error},
    {"2-digit id", "61#00", errc::syntax_error},
    {"4-digit id", "6150#00", errc::syntax_error},
    {"odd digits", "615#0", errc::syntax_error},
    {"non-hex data", "615#0G", errc::syntax_error},
    {"non-hex id", "G15#00", errc::syntax_error},
    {"remote frame", "615#R", errc::syntax_error},
    {"11-bit id above 7FFh", "800#00", errc::value_out_of_range},
    {"29-bit id above 1FFFFFFFh", "20000000#00", errc::value_out_of_range},
    {"9 bytes", "615#000000000000000000", errc::wrong_length},
};

constexpr bool fails(const bad_text& r) { return can::parse_candump(r.frame) == r.error; }
static_assert(first_failing(bad_rows, fails) == std::size(bad_rows));
}  // namespace

TEST_CASE("candump text round-trips the manual frames") {
    check_rows(round_trip_rows, round_trips);
    for (const auto& r : round_trip_rows) {
        const auto f = can::parse_candump(r.frame);
        REQUIRE(f.has_value());
        CHECK(can::format_candump(*f).view() == r.frame);
    }
}

TEST_CASE("malformed candump text is a clear error") {
    check_rows(bad_rows, fails);
    for (const auto& r : bad_rows) {
        CAPTURE(r.frame);
        CHECK(can::parse_candump(r.frame).error() == r.error);
    }
}

TEST_CASE("frames built from bytes") {
    // Ids as constants: clang 14 crashes on a consteval conversion inside a doctest macro.
    constexpr can::standard_id sdo_rx = 0x615;
    constexpr can::standard_id nmt = 0x000;
    const std::array<std::uint8_t, 9> nine{};
    CHECK(can::frame::make(sdo_rx, nine).error() == errc::wrong_length);
    const std::array<std::uint8_t, 2> two{0x01, 0x15};
    const auto f = can::frame::make(nmt, two);
    REQUIRE(f.has_value());
    CHECK(*f == candump("000#0115"));
    CHECK(f->std_id().has_value());
    CHECK_FALSE(f->ext_id().has_value());
    CHECK(can::standard_id::make(0x800).error() == errc::value_out_of_range);
    CHECK(can::extended_id::make(0x2000'0000u).error() == errc::value_out_of_range);
}

// What a CAN driver hands over (an id, a format and bytes) to a frame in one call.
constexpr std::array<std::uint8_t, 5> key_bytes{0x04, 0x00, 0x00, 0x00, 0x2A};
static_assert(can::make_frame(0x195, key_bytes).value() == candump("195#040000002A"));
static_assert(can::make_frame(0x18EF2100,
                              std::array<std::uint8_t, 8>{0x04, 0x1B, 0x80, 0x00, 0xFF, 0xFF, 0xFF,
                                                          0xFF},
                              can::id_format::extended)
                  .value() == candump("18EF2100#041B8000FFFFFFFF"));
static_assert(can::make_frame(0x080, {}).value() == candump("080#"));
static_assert(can::make_frame(0x615, key_bytes, can::id_format::extended).value() ==
              candump("00000615#040000002A"));
static_assert(can::make_frame(0x800, key_bytes) == errc::value_out_of_range);
static_assert(can::make_frame(0x2000'0000, key_bytes, can::id_format::extended) ==
              errc::value_out_of_range);
static_assert(can::make_frame(0x615, std::array<std::uint8_t, 9>{}) == errc::wrong_length);

TEST_CASE("make_frame: a driver's id and bytes in one call") {
    const std::uint8_t rx[8] = {0x2F, 0x01, 0x62, 0x01, 0x10, 0x00, 0x00, 0x00};
    const auto f = can::make_frame(0x615, {rx, 8});
    REQUIRE(f.has_value());
    CHECK(*f == candump("615#2F01620110000000"));
    const auto short_one = can::make_frame(0x715, {rx, 1});
    REQUIRE(short_one.has_value());
    CHECK(*short_one == candump("715#2F"));
    CHECK(can::make_frame(0x7FF, {rx, 0}).has_value());
    CHECK(can::make_frame(0x800, {rx, 0}).error() == errc::value_out_of_range);
    CHECK(can::make_frame(0x1FFF'FFFF, {rx, 8}, can::id_format::extended).has_value());
    const std::uint8_t nine[9]{};
    CHECK(can::make_frame(0x615, {nine, 9}).error() == errc::wrong_length);
}
