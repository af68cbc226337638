// The CiA 301 layer: COB-IDs, NMT, SYNC, boot-up and heartbeat, expedited SDO; every frame from
// the manuals' sections for these services, both ways, and the decoders' errors.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/canopen/sync.hpp>
#include <powerkey/names.hpp>

#include "support.hpp"

#include <string_view>

namespace {
using namespace powerkey;
using namespace powerkey::canopen;

using powerkey_tests::check_rows;
using powerkey_tests::first_failing;
using powerkey_tests::frame_of;

constexpr node_id keypad = 0x15;

// --- COB-IDs ---------------------------------------------------------------------------------
static_assert(cob_id(function::tpdo1, keypad).value() == 0x195);
static_assert(cob_id(function::rpdo1, keypad).value() == 0x215);
static_assert(cob_id(function::rpdo2, keypad).value() == 0x315);
static_assert(cob_id(function::rpdo3, keypad).value() == 0x415);
static_assert(cob_id(function::rpdo4, keypad).value() == 0x515);
static_assert(cob_id(function::sdo_tx, keypad).value() == 0x595);
static_assert(cob_id(function::sdo_rx, keypad).value() == 0x615);
static_assert(cob_id(function::heartbeat, keypad).value() == 0x715);
static_assert(cob_id(function::sdo_rx, 0x7F).value() == 0x67F);
static_assert(cob_id(function::tpdo1, 1).value() == 0x181);
static_assert(cob_id(function::tpdo2, keypad).value() == 0x295);
static_assert(cob_id(function::tpdo3, keypad).value() == 0x395);
static_assert(cob_id(function::tpdo4, keypad).value() == 0x495);

struct cob_row {
    std::string_view section;
    std::string_view frame;  // the COB-ID, as a frame without data
    cob_info info;
};
constexpr cob_row cob_rows[] = {
    {"NMT", "000#", {function::nmt, 0}},
    {"SYNC", "080#", {function::sync, 0}},
    {"key state", "195#", {function::tpdo1, 0x15}},
    {"LED on", "215#", {function::rpdo1, 0x15}},
    {"LED blink", "315#", {function::rpdo2, 0x15}},
    {"LED brightness", "415#", {function::rpdo3, 0x15}},
    {"backlight", "515#", {function::rpdo4, 0x15}},
    {"SDO reply", "595#", {function::sdo_tx, 0x15}},
    {"SDO request", "615#", {function::sdo_rx, 0x15}},
    {"heartbeat", "715#", {function::heartbeat, 0x15}},
    {"key state of node 1", "181#", {function::tpdo1, 1}},
    {"heartbeat of node 7Fh", "77F#", {function::heartbeat, 0x7F}},
    {"EMCY 080h + node: not used by the keypads", "095#", {function::other, 0}},
    {"TIME", "100#", {function::other, 0}},
    {"TPDO2 base, no node", "280#", {function::other, 0}},
    {"TPDO2..4: the PKP-3500-MT's encoders and inputs", "295#", {function::tpdo2, 0x15}},
    {"TPDO3", "395#", {function::tpdo3, 0x15}},
    {"TPDO4", "495#", {function::tpdo4, 0x15}},
    {"SDO reply of node 7Fh", "5FF#", {function::sdo_tx, 0x7F}},
    {"SDO request base, no node", "600#", {function::other, 0}},
    {"LSS: past 77Fh, the last heartbeat COB-ID", "7E5#", {function::other, 0}},
};
constexpr bool classifies(const cob_row& r) {
    const auto f = frame_of(r.frame);
    if (classify(f) != r.info) return false;
    if (classify(f.std_id().value()) != r.info) return false;
    // The per-node functions give the id back.
    const auto node = node_id::make(r.info.node);
    if (node && r.info.fn != function::nmt && r.info.fn != function::sync &&
        r.info.fn != function::other)
        return cob_id(r.info.fn, *node).value() == f.raw_id();
    return true;
}
static_assert(first_failing(cob_rows, classifies) == std::size(cob_rows));
// Every 29-bit identifier is J1939 (where the keypads' protocol switch lives), with no node.
static_assert(classify(can::candump("18EF2100#041B8000FFFFFFFF")) == cob_info{function::j1939, 0});
static_assert(classify(can::candump("00000615#00")) == cob_info{function::j1939, 0});
static_assert(classify(can::candump("615#00")) == cob_info{function::sdo_rx, 0x15});

// Which frames concern a keypad: NMT, SYNC and J1939 every node, the per-node ids only their own.
struct concerns_row {
    std::string_view section;
    std::string_view frame;
    bool expected;
};
constexpr concerns_row concerns_rows[] = {
    {"NMT", "000#0115", true},
    {"SYNC", "080#", true},
    {"J1939", "18EF2100#041B8000FFFFFFFF", true},
    {"SDO request, this node", "615#4000100000000000", true},
    {"SDO request, node 16h", "616#4000100000000000", false},
    {"heartbeat, this node", "715#05", true},
    {"no predefined function", "7E5#00", false},
};
constexpr bool concerns_right(const concerns_row& r) {
    return concerns(classify(powerkey_tests::frame_of(r.frame)), keypad) == r.expected;
}
static_assert(first_failing(concerns_rows, concerns_right) == std::size(concerns_rows));
TEST_CASE("which frames concern a keypad") { check_rows(concerns_rows, concerns_right); }

// --- NMT ---------------------------------------------------------------------------------------
struct nmt_row {
    std::string_view section;
    std::string_view frame;
    nmt_message expected;
};
constexpr nmt_row nmt_rows[] = {
    {"PK1000 4, PKP 4: start node 15h", "000#0115", {nmt_command::start, 0x15}},
    {"PK1000 5, PKP 5: enter pre-operational",
     "000#8015",
     {nmt_command::enter_pre_operational, 0x15}},
    {"PK1000 6, PKP 6: reset node", "000#8115", {nmt_command::reset_node, 0x15}},
    {"PK1000 7, PKP 7: stop node", "000#0215", {nmt_command::stop, 0x15}},
    {"PK1000 7, PKP 7: stop, old sw compatibility", "000#0015", {nmt_command::legacy_stop, 0x15}},
    {"PK1000 4: 00h starts all the keypads", "000#0100", {nmt_command::start, 0}},
    {"PK1000 29: start keypad 15h (heartbeat example)", "000#0115", {nmt_command::start, 0x15}},
    {"CiA 301: reset communication", "000#8200", {nmt_command::reset_communication, 0}},
};
constexpr bool nmt_both_ways(const nmt_row& r) {
    return encode(r.expected) == frame_of(r.frame) &&
           decode_nmt(frame_of(r.frame)) == result<nmt_message>(r.expected);
}
static_assert(first_failing(nmt_rows, nmt_both_ways) == std::size(nmt_rows));

// --- SYNC, boot-up, heartbeat -------------------------------------------------------------------
static_assert(encode(sync_message{}) == can::candump("080#"));  // PK1000 10

struct heartbeat_row {
    std::string_view section;
    std::string_view frame;
    heartbeat_message expected;
};
constexpr heartbeat_row heartbeat_rows[] = {
    {"PK1000 8, PKP 8: boot-up", "715#00", {nmt_state::boot_up}},
    {"PK1000 29, PKP 9: boot up", "715#00", {nmt_state::boot_up}},
    {"PK1000 29, PKP 9: pre-operational", "715#7F", {nmt_state::pre_operational}},
    {"PK1000 29, PKP 9: operational", "715#05", {nmt_state::operational}},
    {"PK1000 29 table: stop", "715#04", {nmt_state::stopped}},
};
constexpr bool heartbeat_both_ways(const heartbeat_row& r) {
    return encode(keypad, r.expected) == frame_of(r.frame) &&
           decode_heartbeat(frame_of(r.frame), keypad) == result<heartbeat_message>(r.expected);
}
static_assert(first_failing(heartbeat_rows, heartbeat_both_ways) == std::size(heartbeat_rows));

// --- expedited SDO (PK1000 29 and PKP 17: object 1017h; PK1000 36: 1011h "load") ---------------
struct sdo_request_row {
    std::string_view section;
    std::string_view frame;
    sdo_request expected;
};
constexpr sdo_request_row sdo_request_rows[] = {
    {"PK1000 29: read heartbeat time", "615#4017100000000000", sdo_upload_request{{0x1017, 0}}},
    {"PK1000 29: switch off the heartbeat", "615#2B17100000000000",
     sdo_download_request{{0x1017, 0}, expedited_data::u16(0)}},
    {"PK1000 29: heartbeat 50 ms", "615#2B17100032000000",
     sdo_download_request{{0x1017, 0}, expedited_data::u16(50)}},
    {"PK1000 29: heartbeat 500 ms", "615#2B171000F4010000",
     sdo_download_request{{0x1017, 0}, expedited_data::u16(500)}},
    {"PK1000 36: restore defaults, 'load'", "615#231110016C6F6164",
     sdo_download_request{{0x1011, 1}, expedited_data::u32(0x64616F6C)}},
    {"PK1000 49: switch to J1939 (8 bytes; see E-PK)", "615#2BFF200101000000",
     sdo_download_request{{0x20FF, 1}, expedited_data::u16(1)}},
    {"PKP 30: key-LED brightness 25%", "615#2F01620110000000",
     sdo_download_request{{0x6201, 1}, expedited_data::u8(0x10)}},
    {"PK1000 32: segment request, toggle 0", "615#6000000000000000", sdo_segment_request{false}},
    {"PK1000 32: segment request, toggle 1", "615#7000000000000000", sdo_segment_request{true}},
    {"CiA 301: 3-byte download", "615#2700200101020300",
     sdo_download_request{{0x2000, 1}, {3, {1, 2, 3, 0}}}},
    {"CiA 301: abort from the client", "615#8000200100000405",
     sdo_abort{{0x2000, 1}, sdo_abort_code::timed_out}},
};

struct sdo_response_row {
    std::string_view section;
    std::string_view frame;
    sdo_response expected;
};
constexpr sdo_response_row sdo_response_rows[] = {
    {"PK1000 29: heartbeat time = 100 ms", "595#4B17100064000000",
     sdo_upload_response{{0x1017, 0}, expedited_data::u16(100)}},
    {"PK1000 29: write acknowledged", "595#6017100000000000", sdo_download_response{{0x1017, 0}}},
    {"PK1000 30: device type",
     "595#430010009101"
     "0B00",
     sdo_upload_response{{0x1000, 0}, expedited_data::u32(0x000B0191)}},
    {"PK1000 36: highest sub-index 1", "595#4F11100001000000",
     sdo_upload_response{{0x1011, 0}, expedited_data::u8(1)}},
    {"PK1000 37: vendor id", "595#43181001E2030000",
     sdo_upload_response{{0x1018, 1}, expedited_data::u32(0x3E2)}},
    {"PK1000 32: segmented upload of 11 bytes", "595#410810000B000000",
     sdo_upload_initiate_response{{0x1008, 0}, true, 11}},
    {"PKP 29: segmented upload, size not indicated (E-CORE-3)", "595#4000610208000000",
     sdo_upload_initiate_response{{0x6100, 2}, false, 8}},
    {"PK1000 32: first segment", "595#00426C696E6B4D61",
     sdo_segment_response{false, 0, false, {0x42, 0x6C, 0x69, 0x6E, 0x6B, 0x4D, 0x61}}},
    {"PK1000 32: last segment, 3 unused", "595#1772696E65000000",
     sdo_segment_response{true, 3, true, {0x72, 0x69, 0x6E, 0x65, 0, 0, 0}}},
    {"CiA 301: abort, object does not exist", "595#8001200000000206",
     sdo_abort{{0x2001, 0}, sdo_abort_code::object_does_not_exist}},
    {"CiA 301: abort with a code CiA 301 does not name", "595#8001200078563412",
     sdo_abort{{0x2001, 0}, static_cast<sdo_abort_code>(0x12345678)}},
};

constexpr bool request_both_ways(const sdo_request_row& r) {
    return encode_request(keypad, r.expected) == frame_of(r.frame) &&
           decode_sdo_request(frame_of(r.frame), keypad) == result<sdo_request>(r.expected);
}
constexpr bool response_both_ways(const sdo_response_row& r) {
    return encode_response(keypad, r.expected) == frame_of(r.frame) &&
           decode_sdo_response(frame_of(r.frame), keypad) == result<sdo_response>(r.expected);
}
static_assert(first_failing(sdo_request_rows, request_both_ways) == std::size(sdo_request_rows));
static_assert(first_failing(sdo_response_rows, response_both_ways) == std::size(sdo_response_rows));
// A client abort as a message of its own keeps its direction: 600h + node.
static_assert(encode(keypad, sdo_abort_request{{{0x2000, 1}, sdo_abort_code::timed_out}}) ==
              can::candump("615#8000200100000405"));
// And the keypad's abort: 580h + node.
static_assert(encode(keypad,
                     sdo_abort_response{{{0x2001, 0}, sdo_abort_code::object_does_not_exist}}) ==
              can::candump("595#8001200000000206"));
static_assert(expedited_data::u16(500).value() == 500);
static_assert(expedited_data::u32(0x000B0191).value() == 0x000B0191);
static_assert(expedited_data{3, {1, 2, 3, 0xFF}}.value() == 0x030201);

// --- what the decoders refuse -------------------------------------------------------------------
struct bad_row {
    std::string_view section;
    std::string_view frame;
    errc error;
};
constexpr bad_row bad_nmt[] = {
    {"extended id", "00000000#0115", errc::wrong_id_format},
    {"not 000h", "001#0115", errc::wrong_id},
    {"one byte", "000#01", errc::wrong_length},
    {"8 bytes (the manual's table lists bytes 2-7; see E-CORE-6)", "000#0115000000000000",
     errc::wrong_length},
    {"unknown command 03h", "000#0315", errc::unknown_command},
    {"target 80h", "000#0180", errc::value_out_of_range},
};
constexpr bad_row bad_sync[] = {
    {"extended id", "00000080#", errc::wrong_id_format},
    {"not 080h", "081#", errc::wrong_id},
    {"a counter byte", "080#01", errc::wrong_length},
};
constexpr bad_row bad_heartbeat[] = {
    {"extended id", "00000715#05", errc::wrong_id_format},
    {"another node", "716#05", errc::wrong_id},
    {"no data", "715#", errc::wrong_length},
    {"two bytes", "715#0500", errc::wrong_length},
    {"unknown state 01h", "715#01", errc::value_out_of_range},
    {"node-guarding toggle bit", "715#85", errc::value_out_of_range},
};
constexpr bad_row bad_sdo_request[] = {
    {"extended id", "00000615#4017100000000000", errc::wrong_id_format},
    {"another node", "616#4017100000000000", errc::wrong_id},
    {"the reply direction", "595#4017100000000000", errc::wrong_id},
    {"5 bytes, as PK1000 49 prints it", "615#2BFF200101", errc::wrong_length},
    {"segmented download 21h", "615#2117100002000000", errc::unknown_command},
    {"expedited without size 22h", "615#2217100002000000", errc::unknown_command},
    {"download with reserved bit 4", "615#3B17100000000000", errc::unknown_command},
    {"41h for 40h, as PKP 31 prints it (E-CORE-4)", "615#4100630000000000",
     errc::reserved_not_zero},
    {"upload request with data", "615#4017100001000000", errc::reserved_not_zero},
    {"segment request with data", "615#6000000000000001", errc::reserved_not_zero},
    {"segment request with low bits", "615#6100000000000000", errc::reserved_not_zero},
    {"abort with low bits", "615#8100200100000405", errc::reserved_not_zero},
    {"block upload A0h", "615#A000200100000000", errc::unknown_command},
    {"ccs 7", "615#E000000000000000", errc::unknown_command},
};
constexpr bad_row bad_sdo_response[] = {
    {"extended id", "00000595#4B17100064000000", errc::wrong_id_format},
    {"another node", "596#4B17100064000000", errc::wrong_id},
    {"7 bytes", "595#4B171000640000", errc::wrong_length},
    {"expedited without size 42h", "595#4217100064000000", errc::unknown_command},
    {"initiate with reserved bit 4", "595#5117100064000000", errc::reserved_not_zero},
    {"segmented upload with n bits", "595#4517100064000000", errc::reserved_not_zero},
    {"download response with data", "595#6017100001000000", errc::reserved_not_zero},
    {"download response with low bits", "595#6117100000000000", errc::reserved_not_zero},
    {"download segment response 20h", "595#2000000000000000", errc::unknown_command},
    {"abort with low bits", "595#8101200000000206", errc::reserved_not_zero},
    {"block download response A0h", "595#A000000000000000", errc::unknown_command},
};

template <class Decode>
constexpr auto refused_by(Decode decode) {
    return [decode](const bad_row& r) { return decode(frame_of(r.frame)) == r.error; };
}
template <class Decode, std::size_t N>
constexpr bool all_refused(const bad_row (&rows)[N], Decode decode) {
    return first_failing(rows, refused_by(decode)) == N;
}
constexpr auto nmt_decoder = [](const can::frame& f) { return decode_nmt(f); };
constexpr auto sync_decoder = [](const can::frame& f) { return decode_sync(f); };
constexpr auto heartbeat_decoder = [](const can::frame& f) { return decode_heartbeat(f, keypad); };
constexpr auto request_decoder = [](const can::frame& f) { return decode_sdo_request(f, keypad); };
constexpr auto response_decoder = [](const can::frame& f) {
    return decode_sdo_response(f, keypad);
};
static_assert(all_refused(bad_nmt, nmt_decoder));
static_assert(all_refused(bad_sync, sync_decoder));
static_assert(all_refused(bad_heartbeat, heartbeat_decoder));
static_assert(all_refused(bad_sdo_request, request_decoder));
static_assert(all_refused(bad_sdo_response, response_decoder));

template <class Decode, std::size_t N>
void check_refused(const bad_row (&rows)[N], Decode decode) {
    check_rows(rows, refused_by(decode));
    for (const auto& r : rows) {
        CAPTURE(r.section);
        CAPTURE(r.frame);
        const auto f = can::parse_candump(r.frame);
        REQUIRE(f.has_value());
        CHECK(decode(*f).error() == r.error);
    }
}
}  // namespace

TEST_CASE("COB-IDs both ways") { check_rows(cob_rows, classifies); }

// The value of an expedited transfer: its counted bytes, least significant first (CiA 301); the
// bytes past the size do not count. PK1000 29: 2B 17 10 00 | F4 01 00 00 is 500 ms.
struct expedited_row {
    std::string_view section;
    std::string_view frame;
    std::uint32_t expected;
};
constexpr expedited_row expedited_rows[] = {
    {"PK1000 29: heartbeat 500 ms (2 bytes)", "615#2B171000F4010000", 500},
    {"PK1000 36: 'load' (4 bytes)", "615#231110016C6F6164", 0x64616F6C},
    {"PKP 30: brightness 10h (1 byte)", "615#2F01620110000000", 0x10},
    {"CiA 301: 3 bytes, the fourth not counted", "615#27002001010203FF", 0x030201},
};
constexpr bool expedited_value_right(const expedited_row& r) {
    const auto m = decode_sdo_request(powerkey_tests::frame_of(r.frame), keypad);
    const auto* d = m ? std::get_if<sdo_download_request>(&*m) : nullptr;
    return d != nullptr && d->value.value() == r.expected;
}
static_assert(first_failing(expedited_rows, expedited_value_right) == std::size(expedited_rows));
TEST_CASE("expedited_data::value counts the sized bytes, least significant first") {
    check_rows(expedited_rows, expedited_value_right);
}

TEST_CASE("NMT rows both ways") {
    check_rows(nmt_rows, nmt_both_ways);
    for (const auto& r : nmt_rows) {
        CAPTURE(r.section);
        const auto f = can::parse_candump(r.frame);
        REQUIRE(f.has_value());
        CHECK(encode(r.expected) == *f);
        const auto m = decode_nmt(*f);
        REQUIRE(m.has_value());
        CHECK(*m == r.expected);
    }
    // 00h has a name of its own now, so that every name reads back to one value.
    CHECK(to_string(nmt_command::legacy_stop) == "legacy_stop");
    CHECK(from_string<nmt_command>("legacy_stop").value() == nmt_command::legacy_stop);
    CHECK(from_string<nmt_command>("stop").value() == nmt_command::stop);
    CHECK(to_string(nmt_command::enter_pre_operational) == "pre_operational");
}

TEST_CASE("SYNC, boot-up and heartbeat rows both ways") {
    CHECK(decode_sync(can::candump("080#")).has_value());
    check_rows(heartbeat_rows, heartbeat_both_ways);
    for (const auto& r : heartbeat_rows) {
        CAPTURE(r.section);
        const auto f = can::parse_candump(r.frame);
        REQUIRE(f.has_value());
        CHECK(encode(keypad, r.expected) == *f);
        const auto m = decode_heartbeat(*f, keypad);
        REQUIRE(m.has_value());
        CHECK(*m == r.expected);
    }
    CHECK(to_string(nmt_state::pre_operational) == "pre_operational");
}

TEST_CASE("SDO rows both ways") {
    check_rows(sdo_request_rows, request_both_ways);
    check_rows(sdo_response_rows, response_both_ways);
    for (const auto& r : sdo_request_rows) {
        CAPTURE(r.section);
        const auto f = can::parse_candump(r.frame);
        REQUIRE(f.has_value());
        CHECK(encode_request(keypad, r.expected) == *f);
        const auto m = decode_sdo_request(*f, keypad);
        REQUIRE(m.has_value());
        CHECK(*m == r.expected);
    }
    for (const auto& r : sdo_response_rows) {
        CAPTURE(r.section);
        const auto f = can::parse_candump(r.frame);
        REQUIRE(f.has_value());
        CHECK(encode_response(keypad, r.expected) == *f);
        const auto m = decode_sdo_response(*f, keypad);
        REQUIRE(m.has_value());
        CHECK(*m == r.expected);
    }
    CHECK(to_string(sdo_abort_code::object_does_not_exist) == "object_does_not_exist");
    CHECK(to_string(static_cast<sdo_abort_code>(0x12345678)).empty());
}

TEST_CASE("decoders refuse malformed frames with the documented error") {
    check_refused(bad_nmt, nmt_decoder);
    check_refused(bad_sync, sync_decoder);
    check_refused(bad_heartbeat, heartbeat_decoder);
    check_refused(bad_sdo_request, request_decoder);
    check_refused(bad_sdo_response, response_decoder);
}
