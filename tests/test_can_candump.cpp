// can/candump.hpp: the candump text form (can-utils' "ID#DATA"): the manuals' frames round-trip
// exactly as logs print them, malformed text is a clear error, and the text converts to a view.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>

#include "support.hpp"

#include <string_view>

namespace {
using namespace powerkey;
using can::candump;
using namespace powerkey_tests;

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
// Hex digits in either case.
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
}

TEST_CASE("malformed candump text is a clear error") { check_rows(bad_rows, fails); }

TEST_CASE("the candump text as a string_view of its buffer") {
    const auto text = can::format_candump(candump("615#2316100164007E00"));
    const std::string_view view = text;  // the conversion to a view of its buffer
    CHECK(view == "615#2316100164007E00");
    CHECK(text == std::string_view("615#2316100164007E00"));
}
