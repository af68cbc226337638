// canopen/sdo.hpp: the expedited SDO frames of the manuals (PK1000 29, 30, 32, 36, 37, 49; PKP
// 17, 29, 30) and CiA 301's both ways through the CiA 301 decoders and encoders, the value of an
// expedited transfer, what the decoders refuse, and the names of the abort codes.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/names.hpp>

#include "support.hpp"

#include <string_view>
#include <variant>

namespace {
using namespace powerkey;
using namespace powerkey::canopen;

using namespace powerkey_tests;

constexpr node_id keypad = 0x15;

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
// One message kind at a time through canopen::encode. A client abort as a message of its own
// keeps its direction, 600h + node; the keypad's abort, 580h + node. The expedited data of 1, 2
// and 4 bytes: PK1000 23, node id 3Ah in one byte; 29, 50 ms in two; 28, 100 ms from producer
// 7Eh in four.
constexpr bool encodes_each_kind() {
    return encode(keypad, sdo_abort_request{{{0x2000, 1}, sdo_abort_code::timed_out}}) ==
               can::candump("615#8000200100000405") &&
           encode(keypad,
                  sdo_abort_response{{{0x2001, 0}, sdo_abort_code::object_does_not_exist}}) ==
               can::candump("595#8001200000000206") &&
           expedited_data::u32(0x000B0191).value() == 0x000B0191 &&
           encode(keypad, sdo_download_request{{0x2013, 0}, expedited_data::u8(0x3A)}) ==
               can::candump("615#2F1320003A000000") &&
           encode(keypad, sdo_download_request{{0x1017, 0}, expedited_data::u16(50)}) ==
               can::candump("615#2B17100032000000") &&
           encode(keypad, sdo_download_request{{0x1016, 1}, expedited_data::u32(0x007E'0064)}) ==
               can::candump("615#2316100164007E00");
}
static_assert(encodes_each_kind());

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

// --- what the decoders refuse --------------------------------------------------------------------
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

constexpr auto request_refuses =
    refused_by([](const can::frame& f) { return decode_sdo_request(f, keypad); });
constexpr auto response_refuses =
    refused_by([](const can::frame& f) { return decode_sdo_response(f, keypad); });
static_assert(first_failing(bad_sdo_request, request_refuses) == std::size(bad_sdo_request));
static_assert(first_failing(bad_sdo_response, response_refuses) == std::size(bad_sdo_response));

// The abort codes CiA 301 names have a name; another code has none (describe prints its number).
static_assert(to_string(sdo_abort_code::object_does_not_exist) == "object_does_not_exist");
static_assert(to_string(static_cast<sdo_abort_code>(0x12345678)).empty());
}  // namespace

TEST_CASE("SDO rows both ways") {
    check_rows(sdo_request_rows, request_both_ways);
    check_rows(sdo_response_rows, response_both_ways);
    CHECK(encodes_each_kind());
}

TEST_CASE("expedited_data::value counts the sized bytes, least significant first") {
    check_rows(expedited_rows, expedited_value_right);
}

TEST_CASE("the SDO decoders refuse malformed frames with the documented error") {
    check_rows(bad_sdo_request, request_refuses);
    check_rows(bad_sdo_response, response_refuses);
}
