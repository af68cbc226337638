// canopen/heartbeat.hpp: the boot-up and heartbeat frames of PK1000 sections 8 and 29 and PKP
// sections 8 and 9 both ways, what the decoder refuses, and the names of the NMT states.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/names.hpp>

#include "support.hpp"

#include <string_view>

namespace {
using namespace powerkey;
using namespace powerkey::canopen;

using namespace powerkey_tests;

constexpr node_id keypad = 0x15;

struct heartbeat_row {
    std::string_view section;
    std::string_view frame;
    heartbeat_message expected;
};
constexpr heartbeat_row heartbeat_rows[] = {
    {"PK1000 8, 29, PKP 8, 9: boot-up", "715#00", {nmt_state::boot_up}},
    {"PK1000 29, PKP 9: pre-operational", "715#7F", {nmt_state::pre_operational}},
    {"PK1000 29, PKP 9: operational", "715#05", {nmt_state::operational}},
    {"PK1000 29 table: stop", "715#04", {nmt_state::stopped}},
};
constexpr bool heartbeat_both_ways(const heartbeat_row& r) {
    return encode(keypad, r.expected) == frame_of(r.frame) &&
           decode_heartbeat(frame_of(r.frame), keypad) == result<heartbeat_message>(r.expected);
}
static_assert(first_failing(heartbeat_rows, heartbeat_both_ways) == std::size(heartbeat_rows));

constexpr bad_row bad_heartbeat[] = {
    {"extended id", "00000715#05", errc::wrong_id_format},
    {"another node", "716#05", errc::wrong_id},
    {"no data", "715#", errc::wrong_length},
    {"two bytes", "715#0500", errc::wrong_length},
    {"unknown state 01h", "715#01", errc::value_out_of_range},
    {"node-guarding toggle bit", "715#85", errc::value_out_of_range},
};
constexpr auto heartbeat_refuses =
    refused_by([](const can::frame& f) { return decode_heartbeat(f, keypad); });
static_assert(first_failing(bad_heartbeat, heartbeat_refuses) == std::size(bad_heartbeat));

// PK1000 sections 8, 29: boot-up 00h, pre-operational 7Fh; CiA 301: stopped 04h, operational 05h.
constexpr name_row nmt_state_rows[] = {{"PK1000 8", 0x00, "boot_up"},
                                       {"CiA 301", 0x04, "stopped"},
                                       {"CiA 301", 0x05, "operational"},
                                       {"PK1000 29", 0x7F, "pre_operational"}};
static_assert(name_table_is<nmt_state>(nmt_state_rows, 0x01));
}  // namespace

TEST_CASE("boot-up and heartbeat rows both ways") {
    check_rows(heartbeat_rows, heartbeat_both_ways);
}

TEST_CASE("the heartbeat decoder refuses malformed frames with the documented error") {
    check_rows(bad_heartbeat, heartbeat_refuses);
}

TEST_CASE("the names of the NMT states") { CHECK(name_table_is<nmt_state>(nmt_state_rows, 0x01)); }
