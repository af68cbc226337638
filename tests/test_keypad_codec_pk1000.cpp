// keypad/codec.hpp on the PK1000 manual: decode/encode(node, model::pk1000, ...) on every example
// frame both ways, the errata, the decoder's refusals, the encoder's refusals and edge values
// (tests/pk1000_rows.hpp). Each table has one runner, proved at compile time and run by doctest.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/keypad/codec.hpp>

#include <cstddef>
#include <iterator>
#include <string_view>
#include <variant>

#include "pk1000_rows.hpp"
#include "support.hpp"

namespace {
using namespace powerkey;
using namespace pk1000_rows;
using namespace powerkey_tests;
constexpr canopen::node_id node = 0x15;

static_assert(first_failing(pk1000_rows::rows, round_trips) == std::size(pk1000_rows::rows));
static_assert(first_failing(pk1000_rows::error_rows, refused) ==
              std::size(pk1000_rows::error_rows));
static_assert(first_failing(pk1000_rows::encode_error_rows, encode_refused) ==
              std::size(pk1000_rows::encode_error_rows));

// Values at the edges of their ranges: not in the manual, each round-trips.
constexpr row edge_rows[] = {
    {"19f level 00h", m1000, 0x15, "615#2F03200600000000",
     write(o::default_backlight_level, level_value(0))},
    {"19b level 3Fh", m1000, 0x15, "615#2F0320023F000000",
     write(o::backlight_level, level_value(0x3F))},
    {"19c red", m1000, 0x15, "615#2F03200301000000",
     write(o::backlight_colour, colour_value(backlight_colour::red))},
    {"19d yellow green", m1000, 0x15, "615#2F03200409000000",
     write(o::default_backlight_colour, colour_value(backlight_colour::yellow_green))},
    {"20 1000k", m1000, 0x15, "615#2F10200000000000",
     write(o::baud_rate, baud_value(baud_rate::kbit_1000))},
    {"20 20k", m1000, 0x15, "615#2F10200007000000",
     write(o::baud_rate, baud_value(baud_rate::kbit_20))},
    {"20 reserved 01h", m1000, 0x15, "615#2F10200001000000",
     write(o::baud_rate, baud_value(baud_rate::reserved_1))},
    {"23 node 01h", m1000, 0x15, "615#2F13200001000000", write(o::node_id, node_value(1))},
    {"23 node 7Fh", m1000, 0x15, "615#2F1320007F000000", write(o::node_id, node_value(0x7F))},
    {"28 10 ms from 7Fh", m1000, 0x15, "615#231610010A007F00",
     write(o::consumer_heartbeat, consumer_heartbeat_value(10, 0x7F))},
    {"28 FFFFh ms from 01h", m1000, 0x15, "615#23161001FFFF0100",
     write(o::consumer_heartbeat, consumer_heartbeat_value(0xFFFF, 1))},
    {"28 off, from 15h", m1000, 0x15, "615#2316100100001500",
     write(o::consumer_heartbeat, consumer_heartbeat_value(0, 0x15))},
    {"29 FFFFh ms (E-PK-8)", m1000, 0x15, "615#2B171000FFFF0000", write(o::heartbeat_time, 0xFFFF)},
    {"46b 10 ms", m1000, 0x15, "615#2B0018050A000000", write(o::tpdo1_event_timer, 10)},
    {"46b FEFFh ms", m1000, 0x15, "615#2B001805FFFE0000", write(o::tpdo1_event_timer, 0xFEFF)},
    {"39 type F0h (E-PK-9)", m1000, 0x15, "615#2F011402F0000000",
     write(o::rpdo2_transmission_type, 0xF0)},
    {"38 type FEh", m1000, 0x15, "615#2F001402FE000000", write(o::rpdo1_transmission_type, 0xFE)},
    {"46a type F0h", m1000, 0x15, "615#2F001802F0000000", write(o::tpdo1_transmission_type, 0xF0)},
    {"49 CANopen (E-PK-13)", m1000, 0x15, "615#2BFF200100000000",
     write(o::protocol_j1939, flag_value(false))},
    {"25 LED power on", m1000, 0x15, "615#2F15200001000000", write(o::led_power, flag_value(true))},
    {"26 demo off", m1000, 0x15, "595#4F00210000000000", reply(o::demo_mode, flag_value(false))},
    {"37 serial FFFFFFFFh", m1000, 0x15, "595#43181004FFFFFFFF",
     value(o::serial_number, 0xFFFF'FFFF)},
    {"35 one byte", m1000, 0x15, "595#4F0B100050000000",
     reply(o::model_name, string_value(1, {'P', 0, 0, 0}))},
    {"30 nothing", m1000, 0x15, "595#4300100000000000", value(o::device_type, 0)},
    {"46a invalid, RTR, 7FFh", m1000, 0x15, "595#43001801FF070080",
     value(o::tpdo1_cob_id, 0x8000'07FF)},
    {"14 3Fh", m1000, 0x15, "415#3F00000000000000", led_brightness{0x3F}},
    {"15 3Fh yellow green", m1000, 0x15, "515#3F09000000000000",
     backlight{0x3F, backlight_colour::yellow_green}},
    {"11 every key", m1000, 0x15, "195#FF030000FF",
     key_state{{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, 0xFF}},
    {"abort: no 2004h", m1000, 0x15, "595#8004200000000206",
     canopen::sdo_abort_response{{{0x2004, 0}, canopen::sdo_abort_code::object_does_not_exist}}},
    {"abort from the host", m1000, 0x15, "615#8008100000000008",
     canopen::sdo_abort_request{{{0x1008, 0}, canopen::sdo_abort_code::general_error}}},
    {"33 size not indicated", m1000, 0x15, "595#4009100000000000", initiate(0x1009, 0, false, 0)},
};
static_assert(first_failing(edge_rows, round_trips) == std::size(edge_rows));

// Each erratum of docs/errata.md (## PK1000) and the behaviour chosen: errc{} = the frame decodes
// (its meaning is pinned in pk1000_rows.hpp or edge_rows), otherwise the error decode returns.
constexpr error_row errata[] = {
    {"E-PK-1", m1000, 0x15, "215#0102040880402010", errc::reserved_not_zero},
    {"E-PK-1", m1000, 0x15, "215#0102040880402000", errc{}},
    {"E-PK-2", m1000, 0x15, "595#4F03200304000000", errc{}},
    {"E-PK-3", m1000, 0x15, "615#2F03200600160000", errc::reserved_not_zero},
    {"E-PK-3", m1000, 0x15, "595#4F03200600160000", errc::reserved_not_zero},
    {"E-PK-3", m1000, 0x15, "615#2F03200616000000", errc{}},
    {"E-PK-4", m1000, 0x15, "595#4311100100000000", errc{}},
    {"E-PK-5", m1000, 0x15, "595#4301160120020220", errc{}},
    {"E-PK-6", m1000, 0x15, "595#4300100091010B00", errc{}},
    {"E-PK-7", m1000, 0x15, "595#4300100091010B00", errc{}},
    {"E-PK-8", m1000, 0x15, "615#2B171000FFFF0000", errc{}},
    {"E-PK-8", m1000, 0x15, "615#2B171000FFFE0000", errc{}},
    {"E-PK-9", m1000, 0x15, "615#2F011402F0000000", errc{}},
    {"E-PK-9", m1000, 0x15, "615#2F011402FE000000", errc{}},
    {"E-PK-9", m1000, 0x15, "615#2F011402F1000000", errc::value_out_of_range},
    {"E-PK-9", m1000, 0x15, "615#2F011402FD000000", errc::value_out_of_range},
    {"E-PK-10", m1000, 0x15, "615#2BFF200101", errc::wrong_length},
    {"E-PK-10", m1000, 0x15, "615#2BFF200101000000", errc{}},
    {"E-PK-11", m1000, 0x15, "615#2F00180532000000", errc::size_mismatch},
    {"E-PK-11", m1000, 0x15, "615#2B00180532000000", errc{}},
    {"E-CORE-1", m1000, 0x15, "595#0046464646464646", errc{}},
    {"E-PK-12", m1000, 0x15, "195#0100", errc::wrong_length},
    {"E-PK-12", m1000, 0x15, "195#010000002A", errc{}},
    {"E-PK-13", m1000, 0x15, "615#2BFF200100000000", errc{}},
    {"E-PK-13", m1000, 0x15, "615#40FF200100000000", errc{}},
};
constexpr bool erratum_holds(const error_row& r) {
    const auto d = decode(frame_of(r.frame), node_of(r.node), model::pk1000, reading::strict);
    return r.error == errc{} ? d.has_value() : d == r.error;
}
static_assert(first_failing(errata, erratum_holds) == std::size(errata));

constexpr result<message> pk1000(std::string_view frame) {
    return decode(frame_of(frame), node, model::pk1000);
}
// The compile-time example: red LED #17 and green LED #28 on.
static_assert(encode(node, model::pk1000, led_on{rgb({17}, {28})}) ==
              can::candump("215#0000010000000008"));
static_assert(encode(node, model::pk1000, write(o::led_brightness, level_value(0x3F))) ==
              can::candump("615#2F0320013F000000"));
// E-PK-8: 1017h takes the full 16-bit range, as 1016h and CiA 301 do, not the 65279 ms printed.
static_assert(pk1000("615#2B171000FFFF0000") == result<message>{write(o::heartbeat_time, 0xFFFF)});
// E-PK-6 and E-PK-7: the bytes say profile 401 (0191h) and analogue output implemented.
static_assert(pk1000("595#4300100091010B00") ==
              result<message>{value(o::device_type, 0x000B'0191)});
// E-PK-5: the reply labelled sub-index 01h is decoded as sub-index 01h.
static_assert(pk1000("595#4301160120020220") ==
              result<message>{value(o::rpdo2_mapping_1, 0x2002'0220)});
}  // namespace

TEST_CASE("pk1000: every manual row decodes to its meaning and encodes to its printed frame") {
    check_rows(pk1000_rows::rows, round_trips);
}

TEST_CASE("pk1000: the printed frames the errata reject, and every refusal of the decoder") {
    check_rows(pk1000_rows::error_rows, refused);
}

TEST_CASE("pk1000: encode refuses what decode could never return") {
    check_rows(pk1000_rows::encode_error_rows, encode_refused);
}

TEST_CASE("pk1000: edge values round-trip") { check_rows(edge_rows, round_trips); }

TEST_CASE("pk1000: errata decisions (docs/errata.md, ## PK1000)") {
    check_rows(errata, erratum_holds);
}

TEST_CASE("pk1000: the acknowledgement of a node change comes from the new id (PK1000 23)") {
    CHECK(pk1000("5BA#6013200000000000") == errc::wrong_id);
    CHECK(decode(frame_of("5BA#6013200000000000"), 0x3A, model::pk1000).has_value());
}
