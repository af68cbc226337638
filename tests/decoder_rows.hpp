// Manual rows of the core messages, as the any-frame decoder sees them: every keypad speaks
// these (NMT, SYNC, boot-up, the SDO frames that carry no profile meaning, the J1939 switch).
// Shared by the decoder, describe and session tests.
#ifndef POWERKEY_TESTS_DECODER_ROWS_HPP
#define POWERKEY_TESTS_DECODER_ROWS_HPP

#include <powerkey/decoder.hpp>

#include <string_view>

namespace decoder_rows {
using namespace powerkey;

struct row {
    std::string_view section;
    std::string_view frame;
    core::message expected;
};

using canopen::nmt_command;
constexpr canopen::sdo_address dev_name{0x1008, 0};

inline constexpr row core_rows[] = {
    {"PK1000 4", "000#0115", canopen::nmt_message{nmt_command::start, 0x15}},
    {"PK1000 5", "000#8015", canopen::nmt_message{nmt_command::enter_pre_operational, 0x15}},
    {"PK1000 6", "000#8115", canopen::nmt_message{nmt_command::reset_node, 0x15}},
    {"PK1000 7", "000#0215", canopen::nmt_message{nmt_command::stop, 0x15}},
    {"PK1000 7 (old sw)", "000#0015", canopen::nmt_message{nmt_command::legacy_stop, 0x15}},
    {"PKP 4", "000#0100", canopen::nmt_message{nmt_command::start, 0}},
    {"PK1000 8", "715#00", canopen::heartbeat_message{canopen::nmt_state::boot_up}},
    {"PK1000 29", "715#7F", canopen::heartbeat_message{canopen::nmt_state::pre_operational}},
    {"PK1000 29", "715#05", canopen::heartbeat_message{canopen::nmt_state::operational}},
    {"PK1000 10", "080#", canopen::sync_message{}},
    {"PK1000 32", "615#4008100000000000", canopen::sdo_upload_request{dev_name}},
    {"PK1000 32", "595#410810000B000000",
     canopen::sdo_upload_initiate_response{dev_name, true, 11}},
    {"PK1000 32", "615#6000000000000000", canopen::sdo_segment_request{false}},
    {"PK1000 32", "595#00426C696E6B4D61",
     canopen::sdo_segment_response{false, 0, false, {0x42, 0x6C, 0x69, 0x6E, 0x6B, 0x4D, 0x61}}},
    {"PK1000 32", "615#7000000000000000", canopen::sdo_segment_request{true}},
    {"PK1000 32", "595#1772696E65000000",
     canopen::sdo_segment_response{true, 3, true, {0x72, 0x69, 0x6E, 0x65, 0, 0, 0}}},
    {"PK1000 29", "615#4017100000000000", canopen::sdo_upload_request{{0x1017, 0}}},
    {"PK1000 29", "615#2B17100032000000",
     canopen::sdo_download_request{{0x1017, 0}, canopen::expedited_data::u16(50)}},
    {"PK1000 29", "615#2B171000F4010000",
     canopen::sdo_download_request{{0x1017, 0}, canopen::expedited_data::u16(500)}},
    {"PK1000 29", "595#6017100000000000", canopen::sdo_download_response{{0x1017, 0}}},
    {"PK1000 29", "595#4B17100064000000",
     canopen::sdo_upload_response{{0x1017, 0}, canopen::expedited_data::u16(100)}},
    {"CiA 301 7.2.4.3.17 (PK1000 31: 1001h not implemented)", "595#8001100000000206",
     core::sdo_abort_response{{{0x1001, 0}, canopen::sdo_abort_code::object_does_not_exist}}},
    {"CiA 301 7.2.4.3.17", "615#8008100000000405",
     core::sdo_abort_request{{{0x1008, 0}, canopen::sdo_abort_code::timed_out}}},
    {"PK1000 49", "18EF2100#041B8000FFFFFFFF", j1939::switch_to_canopen{}},
};

// Frames that are not the keypad's (node 15h): classified, refused, never mis-decoded.
struct foreign_row {
    std::string_view frame;
    frame_class cls;
    errc error;
};

inline constexpr foreign_row foreign_rows[] = {
    {"616#4008100000000000", {bus_function::sdo_rx, 0x16}, errc::wrong_id},
    {"5BA#6013200000000000", {bus_function::sdo_tx, 0x3A}, errc::wrong_id},
    {"718#00", {bus_function::heartbeat, 0x18}, errc::wrong_id},
    {"196#0100000000", {bus_function::tpdo1, 0x16}, errc::wrong_id},
    {"081#00", {bus_function::other, 0}, errc::wrong_id},                // EMCY of node 1
    {"100#00", {bus_function::other, 0}, errc::wrong_id},                // TIME
    {"7E5#0400000000000000", {bus_function::other, 0}, errc::wrong_id},  // LSS
    {"280#0102", {bus_function::other, 0}, errc::wrong_id},              // TPDO2 base, no node
};

// Frames of the keypad that are malformed: the core decoder's precise error.
struct bad_row {
    std::string_view frame;
    errc error;
};

inline constexpr bad_row bad_rows[] = {
    {"000#01", errc::wrong_length},
    {"000#0315", errc::unknown_command},
    {"000#0180", errc::value_out_of_range},
    {"080#00", errc::wrong_length},
    {"715#01", errc::value_out_of_range},
    {"715#0000", errc::wrong_length},
    {"615#40081000", errc::wrong_length},
    {"615#4108100000000000", errc::reserved_not_zero},  // E-PKP: 6300h request printed 41h
    {"615#2008100000000000", errc::unknown_command},
    {"595#E008100000000000", errc::unknown_command},
    {"18EF2100#041B8000FFFFFF00", errc::unknown_command},
    {"18EE2100#041B8000FFFFFFFF", errc::wrong_id},
};

}  // namespace decoder_rows

#endif
