// canopen/nmt.hpp: the NMT node control frames of PK1000 and PKP sections 4-7 both ways, what
// the decoder refuses, and the names of the commands.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/names.hpp>

#include "support.hpp"

#include <string_view>

namespace {
using namespace powerkey;
using namespace powerkey::canopen;

using namespace powerkey_tests;

struct nmt_row {
    std::string_view section;
    std::string_view frame;
    nmt_message expected;
};
constexpr nmt_row nmt_rows[] = {
    {"PK1000 4, 29, PKP 4: start node 15h", "000#0115", {nmt_command::start, 0x15}},
    {"PK1000 5, PKP 5: enter pre-operational",
     "000#8015",
     {nmt_command::enter_pre_operational, 0x15}},
    {"PK1000 6, PKP 6: reset node", "000#8115", {nmt_command::reset_node, 0x15}},
    {"PK1000 7, PKP 7: stop node", "000#0215", {nmt_command::stop, 0x15}},
    {"PK1000 7, PKP 7: stop, old sw compatibility", "000#0015", {nmt_command::legacy_stop, 0x15}},
    {"PK1000 4: 00h starts all the keypads", "000#0100", {nmt_command::start, 0}},
    {"CiA 301: reset communication", "000#8200", {nmt_command::reset_communication, 0}},
};
constexpr bool nmt_both_ways(const nmt_row& r) {
    return encode(r.expected) == frame_of(r.frame) &&
           decode_nmt(frame_of(r.frame)) == result<nmt_message>(r.expected);
}
static_assert(first_failing(nmt_rows, nmt_both_ways) == std::size(nmt_rows));

constexpr bad_row bad_nmt[] = {
    {"extended id", "00000000#0115", errc::wrong_id_format},
    {"not 000h", "001#0115", errc::wrong_id},
    {"one byte", "000#01", errc::wrong_length},
    {"8 bytes (the manual's table lists bytes 2-7; see E-CORE-6)", "000#0115000000000000",
     errc::wrong_length},
    {"unknown command 03h", "000#0315", errc::unknown_command},
    {"target 80h", "000#0180", errc::value_out_of_range},
};
constexpr auto nmt_refuses = refused_by([](const can::frame& f) { return decode_nmt(f); });
static_assert(first_failing(bad_nmt, nmt_refuses) == std::size(bad_nmt));

// PK1000 sections 4-7 (byte 0), 00h the old software's stop (section 7), which has a name of its
// own so that every name reads back to one value; 82h from CiA 301.
constexpr name_row nmt_command_rows[] = {
    {"PK1000 4", 0x01, "start"},
    {"PK1000 7", 0x02, "stop"},
    {"PK1000 5", 0x80, "pre_operational"},
    {"PK1000 6", 0x81, "reset_node"},
    {"CiA 301", 0x82, "reset_communication"},
    {"PK1000 7", 0x00, "legacy_stop"},
};
static_assert(name_table_is<nmt_command>(nmt_command_rows, 0x03));
}  // namespace

TEST_CASE("NMT rows both ways") { check_rows(nmt_rows, nmt_both_ways); }

TEST_CASE("the NMT decoder refuses malformed frames with the documented error") {
    check_rows(bad_nmt, nmt_refuses);
}

TEST_CASE("the names of the NMT commands") {
    CHECK(name_table_is<nmt_command>(nmt_command_rows, 0x03));
}
