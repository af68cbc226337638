// The PK1000 profile against its manual: every example frame both ways, the errata, and the
// decoder's refusals (wrong id, length, command, object, size, reserved bits, range).
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/pk1000/profile.hpp>

#include <cstddef>
#include <string_view>

#include "pk1000_rows.hpp"

namespace {
using namespace powerkey;
using namespace powerkey::pk1000;
using message = pk1000::message;
using pk1000_rows::bad_rows;
using pk1000_rows::rows;
constexpr canopen::node_id node = 0x15;

constexpr can::frame frame_of(std::string_view text) { return can::parse_candump(text).value(); }

// Index of the first row whose encoding differs from the printed frame; the row count if none.
constexpr std::size_t first_bad_encode() {
    for (std::size_t i = 0; i < std::size(rows); ++i)
        if (encode(rows[i].node, rows[i].expected) != frame_of(rows[i].frame)) return i;
    return std::size(rows);
}
static_assert(first_bad_encode() == std::size(rows));

constexpr std::size_t first_bad_decode() {
    for (std::size_t i = 0; i < std::size(rows); ++i)
        if (decode(frame_of(rows[i].frame), rows[i].node) != rows[i].expected) return i;
    return std::size(rows);
}
static_assert(first_bad_decode() == std::size(rows));

constexpr std::size_t first_bad_refusal() {
    for (std::size_t i = 0; i < std::size(bad_rows); ++i)
        if (decode(frame_of(bad_rows[i].frame), bad_rows[i].node) != bad_rows[i].error) return i;
    return std::size(bad_rows);
}
static_assert(first_bad_refusal() == std::size(bad_rows));

// The compile-time example: red LED #17 and green LED #28 on.
static_assert(encode(node, led_on{{17}, {28}}) == can::candump("215#0000010000000008"));
static_assert(encode(node, message{led_on{{17}, {28}}}) == can::candump("215#0000010000000008"));
// Construction of SDO writes from typed values.
static_assert(encode(node, message{set_request<brightness_value>{{level_setting::led, 0x3F}}}) ==
              can::candump("615#2F0320013F000000"));
static_assert(encode(node, message{set_request<node_id_value>{{0x7F}}}) ==
              can::candump("615#2F1320007F000000"));
static_assert(new_node_id(set_request<node_id_value>{{0x3A}}) == canopen::node_id{0x3A});
static_assert(!new_node_id(read_request{entry::node_id}).has_value());
static_assert(bits_per_second(baud_rate::reserved_5) == 125'000);
static_assert(to_string(entry::serial_string) == "serial_string");
static_assert(find_entry({0x1001, 0}) == result<entry>{entry::error_register});
static_assert(find_entry({0x1018, 2}) == errc::unknown_object);

// Refusals: every check the decoder makes, one row each.
struct refusal {
    std::string_view what;
    std::string_view frame;
    errc error;
};
constexpr refusal refusals[] = {
    // identifiers and lengths
    {"another node's SDO", "616#4000200100000000", errc::wrong_id},
    {"another node's reply", "596#4B00200100000000", errc::wrong_id},
    {"another node's LED PDO", "216#0000000000000000", errc::wrong_id},
    {"another node's heartbeat", "716#05", errc::wrong_id},
    {"an EMCY COB-ID", "095#0000000000000000", errc::wrong_id},
    {"TPDO2, unused", "295#0000000000000000", errc::wrong_id},
    {"another PGN", "18EE2100#041B8000FFFFFFFF", errc::wrong_id},
    {"other proprietary data", "18EF2100#051B8000FFFFFFFF", errc::unknown_command},
    {"short SDO", "615#40002001000000", errc::wrong_length},
    {"short key state", "195#00000000", errc::wrong_length},
    {"long key state", "195#000000002A00", errc::wrong_length},
    {"key-state byte 2", "195#000001002A", errc::reserved_not_zero},
    {"short LED PDO", "215#00000000000000", errc::wrong_length},
    {"short brightness PDO", "415#08", errc::wrong_length},
    {"SYNC with a counter", "080#01", errc::wrong_length},
    {"NMT command 03h", "000#0315", errc::unknown_command},
    // command bytes
    {"segmented download", "615#2100200100000000", errc::unknown_command},
    {"block upload", "615#A000200100000000", errc::unknown_command},
    {"upload request 41h", "615#4100200100000000", errc::reserved_not_zero},
    {"write to read-only 2000h", "615#2B00200101000000", errc::unknown_command},
    {"write to read-only 1000h", "615#2300100091010B00", errc::unknown_command},
    {"write to read-only 1402h/02", "615#2F021402FE000000", errc::unknown_command},
    {"ack of read-only 1018h/01", "595#6018100100000000", errc::unknown_command},
    // objects
    {"undefined 2004h", "615#4004200000000000", errc::unknown_object},
    {"undefined 2001h/03", "615#4001200300000000", errc::unknown_object},
    {"undefined 1602h/02", "615#4002160200000000", errc::unknown_object},
    {"undefined 1018h/02", "595#4318100200000000", errc::unknown_object},
    {"1001h reply: not implemented", "595#4F01100000000000", errc::unknown_object},
    {"segmented 2000h", "595#4100200102000000", errc::unknown_object},
    {"write undefined 2020h", "615#2F20200001000000", errc::unknown_object},
    // sizes
    {"2003h written with 2Bh", "615#2B03200109000000", errc::size_mismatch},
    {"2001h written with 2Fh", "615#2F01200104000000", errc::size_mismatch},
    {"20FFh written with 2Fh", "615#2FFF200201000000", errc::size_mismatch},
    {"1017h read as 4 bytes", "595#4317100064000000", errc::size_mismatch},
    // reserved bits
    {"key #11", "195#000400002A", errc::reserved_not_zero},
    {"key-state byte 3", "195#000000012A", errc::reserved_not_zero},
    {"red LED #29", "215#0000001000000000", errc::reserved_not_zero},
    {"blink green LED #29", "315#0000000000000010", errc::reserved_not_zero},
    {"brightness PDO byte 1", "415#0801000000000000", errc::reserved_not_zero},
    {"backlight PDO byte 2", "515#2003010000000000", errc::reserved_not_zero},
    {"LED register bit 28", "615#2301200100000010", errc::reserved_not_zero},
    {"key register bit 10", "595#4B00200100040000", errc::reserved_not_zero},
    {"byte past a 1-byte value", "615#2F03200109000001", errc::reserved_not_zero},
    {"consumer heartbeat byte 7", "615#23161001F4010101", errc::reserved_not_zero},
    {"COB-ID bit 29", "595#4300140115020060", errc::reserved_not_zero},
    {"device type bit 20", "595#4300100091011B00", errc::reserved_not_zero},
    {"ack with data", "595#6003200101000000", errc::reserved_not_zero},
    // values
    {"brightness PDO 40h", "415#4000000000000000", errc::value_out_of_range},
    {"backlight PDO level 40h", "515#4003000000000000", errc::value_out_of_range},
    {"backlight PDO colour 0Ah", "515#200A000000000000", errc::value_out_of_range},
    {"2003h/01 level 40h", "615#2F03200140000000", errc::value_out_of_range},
    {"2003h/03 colour 00h", "615#2F03200300000000", errc::value_out_of_range},
    {"2003h/04 colour 0Ah", "595#4F0320040A000000", errc::value_out_of_range},
    {"baud code 08h", "615#2F10200008000000", errc::value_out_of_range},
    {"boot-up 02h", "615#2F11200002000000", errc::value_out_of_range},
    {"RS485 0100h", "615#2BFF200200010000", errc::value_out_of_range},
    {"node id 00h", "615#2F13200000000000", errc::value_out_of_range},
    {"node id 80h", "615#2F13200080000000", errc::value_out_of_range},
    {"startup show 03h", "615#2F14200003000000", errc::value_out_of_range},
    {"consumer heartbeat 9 ms", "615#2316100109000100", errc::value_out_of_range},
    {"consumer heartbeat node 00h", "615#23161001F4010000", errc::value_out_of_range},
    {"consumer heartbeat node 80h", "615#23161001F4018000", errc::value_out_of_range},
    {"producer heartbeat 9 ms", "615#2B17100009000000", errc::value_out_of_range},
    {"event timer FF00h", "615#2B00180500FF0000", errc::value_out_of_range},
    {"event timer 1 ms", "615#2B00180501000000", errc::value_out_of_range},
    {"RPDO type F1h", "615#2F001402F1000000", errc::value_out_of_range},
    {"RPDO type FFh", "615#2F001402FF000000", errc::value_out_of_range},
    {"TPDO type 00h", "615#2F00180200000000", errc::value_out_of_range},
    {"TPDO type F1h", "615#2F001802F1000000", errc::value_out_of_range},
    {"restore without load", "615#231110016C6F6165", errc::value_out_of_range},
    {"heartbeat state 01h", "715#01", errc::value_out_of_range},
};

constexpr std::size_t first_bad_refusal_row() {
    for (std::size_t i = 0; i < std::size(refusals); ++i) {
        const auto f = can::parse_candump(refusals[i].frame);
        const errc got = f ? decode(*f, node).error() : f.error();
        if (got != refusals[i].error) return i;
    }
    return std::size(refusals);
}
static_assert(first_bad_refusal_row() == std::size(refusals));

// Values at the edges of their ranges encode and decode.
constexpr message edges[] = {
    set_request<brightness_value>{{level_setting::default_backlight, 0}},
    set_request<brightness_value>{{level_setting::backlight, 0x3F}},
    set_request<colour_value>{{colour_setting::current, backlight_colour::red}},
    set_request<colour_value>{{colour_setting::power_on, backlight_colour::yellow_green}},
    set_request<baud_rate_value>{{baud_rate::kbit_1000}},
    set_request<baud_rate_value>{{baud_rate::kbit_20}},
    set_request<baud_rate_value>{{baud_rate::reserved_1}},
    set_request<node_id_value>{{1}},
    set_request<node_id_value>{{0x7F}},
    set_request<consumer_heartbeat_value>{{true, 10, 0x7F}},
    set_request<consumer_heartbeat_value>{{true, 0xFFFF, 1}},
    set_request<consumer_heartbeat_value>{{false, {}, 0x15}},
    set_request<producer_heartbeat_value>{{true, 0xFFFF}},
    set_request<event_timer_value>{{true, 10}},
    set_request<event_timer_value>{{true, 0xFEFF}},
    set_request<rpdo_transmission_value>{{rpdo::rpdo2, false, 0xF0}},
    set_request<rpdo_transmission_value>{{rpdo::rpdo1, true, {}}},
    set_request<tpdo_transmission_value>{{false, 0xF0}},
    set_request<flag_value>{{flag::j1939, false}},
    set_request<flag_value>{{flag::led_power, true}},
    value_reply<flag_value>{{flag::demo_mode, false}},
    value_reply<identity_value>{{identity_item::serial_number, 0xFFFF'FFFF}},
    value_reply<string_value>{{string_object::model_id, 1, {'P', 0, 0, 0}}},
    value_reply<device_type_value>{},
    value_reply<pdo_cob_id_value>{{pdo::tpdo1, true, false, 0x7FF}},
    led_brightness{0x3F},
    backlight{0x3F, backlight_pdo_colour::yellow_green},
    key_state{{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, 0xFF},
    canopen::sdo_abort{{0x2004, 0}, canopen::sdo_abort_code::object_does_not_exist},
    sdo_abort_request{{{0x1008, 0}, canopen::sdo_abort_code::general_error}},
    canopen::sdo_upload_initiate_response{{0x1009, 0}, false, 0},
};

constexpr bool edges_round_trip() {
    for (const auto& m : edges)
        if (const auto f = encode(node, m); !f || decode(*f, node) != m) return false;
    return true;
}
static_assert(edges_round_trip());

// Messages decode() can never return, which encode() therefore refuses: each was found by the
// pk1000_encode fuzz target (fuzz/regressions/pk1000_encode/) as a frame its decoder rejected or
// read back differently.
struct encode_refusal {
    std::string_view what;
    message m;
    errc error;
};
constexpr encode_refusal encode_refusals[] = {
    {"write ack of read-only 2000h/01", set_ack{entry::keys}, errc::unknown_command},
    {"rpdo value 4 has no name", value_reply<rpdo_transmission_value>{{static_cast<rpdo>(4)}},
     errc::value_out_of_range},
    {"write of read-only 1402h/02", set_request<rpdo_transmission_value>{{rpdo::rpdo3}},
     errc::unknown_command},
    {"segmented upload of a number (2003h/01)",
     canopen::sdo_upload_initiate_response{{0x2003, 1}, true, 4}, errc::unknown_object},
    {"heartbeat off with a period", set_request<producer_heartbeat_value>{{false, 500}},
     errc::value_out_of_range},
    {"consumer heartbeat off with a period",
     value_reply<consumer_heartbeat_value>{{false, 100, 0x15}}, errc::value_out_of_range},
    {"event timer off with a period", set_request<event_timer_value>{{false, 100}},
     errc::value_out_of_range},
    {"event-driven RPDO with a sync type",
     set_request<rpdo_transmission_value>{{rpdo::rpdo1, true, 5}}, errc::value_out_of_range},
    {"event-driven TPDO with a sync type", set_request<tpdo_transmission_value>{{true, 5}},
     errc::value_out_of_range},
    {"string bytes past its size",
     value_reply<string_value>{{string_object::hardware_version, 2, {0x56, 0x5F, 0x30, 0}}},
     errc::value_out_of_range},
};
constexpr bool encode_refuses() {
    for (const auto& r : encode_refusals)
        if (encode(node, r.m) != r.error) return false;
    return true;
}
static_assert(encode_refuses());

// Each erratum of docs/errata.md (## PK1000) and the behaviour chosen: errc{} = the frame decodes
// (its meaning is pinned in pk1000_rows.hpp), otherwise the error the decoder returns.
struct erratum_check {
    std::string_view id;
    std::string_view frame;
    errc error;
};
constexpr erratum_check errata[] = {
    {"E-PK-1", "215#0102040880402010", errc::reserved_not_zero},
    {"E-PK-1", "215#0102040880402000", errc{}},
    {"E-PK-2", "595#4F03200304000000", errc{}},
    {"E-PK-3", "615#2F03200600160000", errc::reserved_not_zero},
    {"E-PK-3", "595#4F03200600160000", errc::reserved_not_zero},
    {"E-PK-3", "615#2F03200616000000", errc{}},
    {"E-PK-4", "595#4311100100000000", errc{}},
    {"E-PK-5", "595#4301160120020220", errc{}},
    {"E-PK-6", "595#4300100091010B00", errc{}},
    {"E-PK-7", "595#4300100091010B00", errc{}},
    {"E-PK-8", "615#2B171000FFFF0000", errc{}},
    {"E-PK-8", "615#2B171000FFFE0000", errc{}},
    {"E-PK-9", "615#2F011402F0000000", errc{}},
    {"E-PK-9", "615#2F011402FE000000", errc{}},
    {"E-PK-9", "615#2F011402F1000000", errc::value_out_of_range},
    {"E-PK-9", "615#2F011402FD000000", errc::value_out_of_range},
    {"E-PK-10", "615#2BFF200101", errc::wrong_length},
    {"E-PK-10", "615#2BFF200101000000", errc{}},
    {"E-PK-11", "615#2F00180532000000", errc::size_mismatch},
    {"E-PK-11", "615#2B00180532000000", errc{}},
    {"E-CORE-1", "595#0046464646464646", errc{}},
    {"E-PK-12", "195#0100", errc::wrong_length},
    {"E-PK-12", "195#010000002A", errc{}},
    {"E-PK-13", "615#2BFF200100000000", errc{}},
    {"E-PK-13", "615#40FF200100000000", errc{}},
};

constexpr std::size_t first_bad_erratum() {
    for (std::size_t i = 0; i < std::size(errata); ++i) {
        const auto r = decode(frame_of(errata[i].frame), node);
        if (errata[i].error == errc{} ? !r.has_value() : r != errata[i].error) return i;
    }
    return std::size(errata);
}
static_assert(first_bad_erratum() == std::size(errata));

// E-PK-8: 1017h takes the full 16-bit range, as 1016h and CiA 301 do, not the 65279 ms printed.
static_assert(decode(can::candump("615#2B171000FFFF0000"), node) ==
              result<message>{set_request<producer_heartbeat_value>{{true, 0xFFFF}}});
// E-PK-6 and E-PK-7: the bytes say profile 401 (0191h) and analogue output implemented.
static_assert(decode(can::candump("595#4300100091010B00"), node) ==
              result<message>{value_reply<device_type_value>{{401, true, true, false, true}}});
// E-PK-5: the reply labelled sub-index 01h is decoded as sub-index 01h.
static_assert(decode(can::candump("595#4301160120020220"), node) ==
              result<message>{
                  value_reply<pdo_mapping_value>{{mapping_entry::rpdo2_1, 0x2002, 2, 0x20}}});
}  // namespace

TEST_CASE("pk1000: every manual row encodes to its printed frame and decodes to its meaning") {
    for (const auto& r : rows) {
        CAPTURE(r.section);
        CAPTURE(r.frame);
        const auto f = can::parse_candump(r.frame);
        REQUIRE(f.has_value());
        CHECK(encode(r.node, r.expected) == *f);
        const auto m = decode(*f, r.node);
        REQUIRE(m.has_value());
        CHECK(*m == r.expected);
        CHECK(encode(r.node, *m) == *f);
        CHECK(can::format_candump(encode(r.node, *m).value()).view() == r.frame);
    }
}

TEST_CASE("pk1000: printed frames the errata reject") {
    for (const auto& r : bad_rows) {
        CAPTURE(r.section);
        CAPTURE(r.frame);
        const auto f = can::parse_candump(r.frame);
        REQUIRE(f.has_value());
        CHECK(decode(*f, r.node) == r.error);
    }
}

TEST_CASE("pk1000: refusals") {
    for (const auto& r : refusals) {
        CAPTURE(r.what);
        CAPTURE(r.frame);
        const auto f = can::parse_candump(r.frame);
        const errc got = f ? decode(*f, node).error() : f.error();
        CHECK(to_string(got) == to_string(r.error));
    }
}

TEST_CASE("pk1000: encode refuses what decode could never return") {
    for (const auto& r : encode_refusals) {
        CAPTURE(r.what);
        CHECK(to_string(encode(node, r.m).error()) == to_string(r.error));
    }
}

TEST_CASE("pk1000: edge values round-trip") {
    for (const auto& m : edges) {
        const auto f = encode(node, m);
        REQUIRE(f.has_value());
        const auto back = decode(*f, node);
        REQUIRE(back.has_value());
        CHECK(*back == m);
    }
}

TEST_CASE("pk1000: node change, E-PK-3 and E-PK-2 decisions") {
    // 2013h: the request on the old id, the acknowledgement from the new one.
    const auto request = decode(frame_of("615#2F1320003A000000"), node);
    REQUIRE(request.has_value());
    const auto moved = new_node_id(*request);
    REQUIRE(moved.has_value());
    CHECK(moved->value() == 0x3A);
    CHECK(decode(frame_of("5BA#6013200000000000"), node) == errc::wrong_id);
    CHECK(decode(frame_of("5BA#6013200000000000"), *moved).has_value());
    // E-PK-3: the manual's byte-5 value is not silently read as level 0.
    CHECK(decode(frame_of("615#2F03200600160000"), node) == errc::reserved_not_zero);
    // E-PK-2: the reply labelled cyan carries 04h, yellow; the bytes win.
    const auto colour = decode(frame_of("595#4F03200304000000"), node);
    REQUIRE(colour.has_value());
    const auto* v = std::get_if<value_reply<colour_value>>(&*colour);
    REQUIRE(v != nullptr);
    CHECK(v->value.colour == backlight_colour::yellow);
}

TEST_CASE("pk1000: errata decisions (docs/errata.md, ## PK1000)") {
    for (const auto& e : errata) {
        CAPTURE(e.id);
        CAPTURE(e.frame);
        const auto r = decode(frame_of(e.frame), node);
        if (e.error == errc{}) {
            CHECK(r.has_value());
        } else {
            CHECK(to_string(r.error()) == to_string(e.error));
        }
    }
}
