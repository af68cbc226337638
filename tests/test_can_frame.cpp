// can/frame.hpp: a classic CAN frame from an identifier and bytes (frame::make, make_frame, what a
// driver hands over), standard and extended identifiers told apart, and frame::make reading
// exactly the span it is given.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/can/frame.hpp>

#include "support.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace {
using namespace powerkey;
using can::candump;

// A named constant rather than a consteval call inside the loops and macros below: clang 14
// crashes generating code for an immediate invocation there.
constexpr can::standard_id sdo_rx_15 = 0x615;

static_assert(!candump("615#00").is_extended());
static_assert(candump("18EF2100#00").is_extended());
static_assert(candump("615#4000200100000000").size() == 8);
static_assert(candump("080#").size() == 0);
// Standard 615h and extended 00000615h are different frames; so are 1 byte and 2.
static_assert(candump("615#01") != candump("00000615#01"));
static_assert(candump("615#01") != candump("615#0100"));

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
}  // namespace

TEST_CASE("frames built from bytes") {
    constexpr can::standard_id nmt = 0x000;
    const std::array<std::uint8_t, 9> nine{};
    CHECK(can::frame::make(sdo_rx_15, nine).error() == errc::wrong_length);
    const std::array<std::uint8_t, 2> two{0x01, 0x15};
    const auto f = can::frame::make(nmt, two);
    REQUIRE(f.has_value());
    CHECK(*f == candump("000#0115"));
    CHECK(f->std_id().has_value());
    CHECK_FALSE(f->ext_id().has_value());
    CHECK(can::standard_id::make(0x800).error() == errc::value_out_of_range);
    CHECK(can::extended_id::make(0x2000'0000u).error() == errc::value_out_of_range);
}

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

TEST_CASE("frame::make reads exactly the span it is given (ASan: the span ends a heap block)") {
    for (std::size_t n = 0; n <= 8; ++n) {
        std::vector<std::uint8_t> bytes(n, 0xA5);  // exactly n bytes: a read past them traps
        const auto f = can::frame::make(sdo_rx_15, bytes);
        REQUIRE(f.has_value());
        CHECK(f->size() == n);
        for (std::size_t i = 0; i < 8; ++i) CHECK(f->bytes()[i] == (i < n ? 0xA5 : 0));
    }
}
