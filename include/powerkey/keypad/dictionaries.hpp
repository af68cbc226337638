// powerkey: the object dictionaries as data, one table of rows per dictionary family: which
// keypads and manual each is, and what a row's columns mean, are docs/models.md's ("The object
// dictionaries"); what each object is, its row in objects.hpp.
#ifndef POWERKEY_KEYPAD_DICTIONARIES_HPP
#define POWERKEY_KEYPAD_DICTIONARIES_HPP

#include <powerkey/keypad/objects.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace powerkey {

namespace detail {
using obj = object;
constexpr auto ro = access::read_only;
constexpr auto rw = access::read_write;
constexpr auto wo = access::write_only;
constexpr std::uint32_t any = 0xFFFF'FFFF;
constexpr std::uint32_t none_else = 0xFFFF'FFFF;

// A dictionary written as its own rows, then the shared rows no own row replaces (same object).
template <class Own>
constexpr bool replaced(const Own& own, const object_row& c) noexcept {
    for (const auto& o : own)
        if (o.id == c.id) return true;
    return false;
}
template <class Own, class Shared>
constexpr std::size_t joined_size(const Own& own, const Shared& shared) noexcept {
    std::size_t n = std::size(own);
    for (const auto& c : shared)
        if (!replaced(own, c)) ++n;
    return n;
}
template <std::size_t N, class Own, class Shared>
constexpr std::array<object_row, N> join_rows(const Own& own, const Shared& shared) noexcept {
    std::array<object_row, N> rows{};
    std::size_t n = 0;
    for (const auto& o : own) rows[n++] = o;
    for (const auto& c : shared)
        if (!replaced(own, c)) rows[n++] = c;
    return rows;
}

// The rows the PK1000 manual and the SI manuals print alike (the CiA 301 objects, 2000h..2014h,
// 2200h), each fact once: PK1000_CANopen_UM_rev1.13 sections 16-48 (defaults from section 3 and
// the example replies) and docs/si-family.md.
inline constexpr object_row pk_shared_rows[] = {
    {obj::keys, {0x2000, 1}, 2, ro},
    {obj::led_brightness, {0x2003, 1}, 1, rw, 0, 0x3F, none_else, 0x3F},
    {obj::backlight_level, {0x2003, 2}, 1, rw, 0, 0x3F, none_else, 0x00},
    {obj::backlight_colour, {0x2003, 3}, 1, rw, 1, 9, none_else, 0x08},
    {obj::default_backlight_colour, {0x2003, 4}, 1, rw, 1, 9, none_else, 0x08},
    {obj::default_led_brightness, {0x2003, 5}, 1, rw, 0, 0x3F, none_else, 0x3F},
    {obj::default_backlight_level, {0x2003, 6}, 1, rw, 0, 0x3F, none_else, 0x00},
    {obj::baud_rate, {0x2010, 0}, 1, rw, 0, 7, none_else, 0x04},
    {obj::boot_up, {0x2011, 0}, 1, rw, 0, 1, none_else, 1},
    {obj::active_on_startup, {0x2012, 0}, 1, rw, 0, 1, none_else, 0},
    {obj::node_id, {0x2013, 0}, 1, rw, 1, 0x7F, none_else, 0x15},
    {obj::startup_show, {0x2014, 0}, 1, rw, 0, 2, none_else, 1},
    {obj::consumer_heartbeat_count, {0x1016, 0}, 1, ro, 0, any, none_else, 1},
    {obj::consumer_heartbeat, {0x1016, 1}, 4, rw, 10, 0xFFFF, none_else, 0x0001'0000},  // node 01h
    {obj::device_type, {0x1000, 0}, 4, ro, 0, any, none_else, 0x000B'0191},
    {obj::error_register, {0x1001, 0}, 1, ro},
    {obj::device_name, {0x1008, 0}, 0, ro},
    {obj::hardware_version, {0x1009, 0}, 0, ro},
    {obj::software_version, {0x100A, 0}, 0, ro},
    {obj::model_name, {0x100B, 0}, 0, ro},
    {obj::restore_count, {0x1011, 0}, 1, ro, 0, any, none_else, 1},
    {obj::restore_defaults, {0x1011, 1}, 4, rw},
    {obj::identity_count, {0x1018, 0}, 1, ro, 0, any, none_else, 4},
    {obj::vendor_id, {0x1018, 1}, 4, ro, 0, any, none_else, 0x3E2},
    {obj::serial_number, {0x1018, 4}, 4, ro},
    {obj::rpdo1_count, {0x1400, 0}, 1, ro, 0, any, none_else, 2},
    {obj::rpdo1_transmission_type, {0x1400, 2}, 1, rw, 0, 0xF0, 0xFE, 0xFE},
    {obj::rpdo2_count, {0x1401, 0}, 1, ro, 0, any, none_else, 2},
    {obj::rpdo2_transmission_type, {0x1401, 2}, 1, rw, 0, 0xF0, 0xFE, 0xFE},  // E-PK-9
    {obj::rpdo3_count, {0x1402, 0}, 1, ro, 0, any, none_else, 2},
    {obj::rpdo3_transmission_type, {0x1402, 2}, 1, ro, 0, 0xF0, 0xFE, 0xFE},
    {obj::rpdo4_count, {0x1403, 0}, 1, ro, 0, any, none_else, 2},
    {obj::rpdo4_transmission_type, {0x1403, 2}, 1, ro, 0, 0xF0, 0xFE, 0xFE},
    {obj::rpdo3_mapping_count, {0x1602, 0}, 1, ro, 0, any, none_else, 1},
    {obj::rpdo3_mapping_1, {0x1602, 1}, 4, ro, 0, any, none_else, 0x2003'0108},
    {obj::rpdo4_mapping_count, {0x1603, 0}, 1, ro, 0, any, none_else, 2},
    {obj::rpdo4_mapping_1, {0x1603, 1}, 4, ro, 0, any, none_else, 0x2003'0208},
    {obj::rpdo4_mapping_2, {0x1603, 2}, 4, ro, 0, any, none_else, 0x2003'0308},
    {obj::tpdo1_count, {0x1800, 0}, 1, ro, 0, any, none_else, 5},
    {obj::tpdo1_transmission_type, {0x1800, 2}, 1, rw, 1, 0xF0, 0xFE, 0xFE},  // E-PK-11
    {obj::tpdo1_event_timer, {0x1800, 5}, 2, rw, 10, 0xFEFF, none_else, 0},
    {obj::tpdo1_mapping_count, {0x1A00, 0}, 1, ro, 0, any, none_else, 1},
    {obj::tpdo1_mapping_1, {0x1A00, 1}, 4, ro, 0, any, none_else, 0x2000'0110},  // E-PK-12
    {obj::serial_number_string, {0x2200, 0}, 0, ro},
};

// PK1000_CANopen_UM_rev1.13: the rows that differ from the SI family's; the PK1000 dictionary is
// these, then pk_shared_rows.
inline constexpr object_row pk1000_own_rows[] = {
    {obj::led_on_red, {0x2001, 1}, 4, rw},
    {obj::led_on_green, {0x2001, 2}, 4, rw},
    {obj::led_blink_red, {0x2002, 1}, 4, rw},
    {obj::led_blink_green, {0x2002, 2}, 4, rw},
    {obj::led_power, {0x2015, 0}, 1, rw, 0, 1, none_else, 1},
    {obj::demo_mode, {0x2100, 0}, 1, rw, 0, 1, none_else, 0},
    {obj::protocol_j1939, {0x20FF, 1}, 2, rw, 0, 1, none_else, 0},
    {obj::protocol_rs485, {0x20FF, 2}, 2, rw, 0, 1, none_else, 0},
    {obj::heartbeat_time, {0x1017, 0}, 2, rw, 10, 0xFFFF, none_else, 0},  // E-PK-8
    {obj::rpdo1_cob_id, {0x1400, 1}, 4, ro, 0, any, none_else, 0x4000'0215},
    {obj::rpdo2_cob_id, {0x1401, 1}, 4, ro, 0, any, none_else, 0x4000'0315},
    {obj::rpdo3_cob_id, {0x1402, 1}, 4, ro, 0, any, none_else, 0x4000'0415},
    {obj::rpdo4_cob_id, {0x1403, 1}, 4, ro, 0, any, none_else, 0x4000'0515},
    {obj::rpdo1_mapping_count, {0x1600, 0}, 1, ro, 0, any, none_else, 2},
    {obj::rpdo1_mapping_1, {0x1600, 1}, 4, ro, 0, any, none_else, 0x2001'0120},
    {obj::rpdo1_mapping_2, {0x1600, 2}, 4, ro, 0, any, none_else, 0x2001'0220},
    {obj::rpdo2_mapping_count, {0x1601, 0}, 1, ro, 0, any, none_else, 2},
    {obj::rpdo2_mapping_1, {0x1601, 1}, 4, ro, 0, any, none_else, 0x2002'0120},
    {obj::rpdo2_mapping_2, {0x1601, 2}, 4, ro, 0, any, none_else, 0x2002'0220},  // E-PK-5
    {obj::tpdo1_cob_id, {0x1800, 1}, 4, ro, 0, any, none_else, 0x4000'0195},
};
inline constexpr auto pk1000_rows =
    join_rows<joined_size(pk1000_own_rows, pk_shared_rows)>(pk1000_own_rows, pk_shared_rows);

// PKP-2200-2400-LI_CANopen_UM_rev1.1: sections 13-32; the values of the example replies.
inline constexpr object_row pkp_li_rows[] = {
    {obj::device_type, {0x1000, 0}, 4, ro, 0, any, none_else, 0x0003'0191},
    {obj::device_name, {0x1008, 0}, 0, ro},
    {obj::hardware_version, {0x1009, 0}, 0, ro},
    {obj::software_version, {0x100A, 0}, 0, ro},
    {obj::model_name, {0x100B, 0}, 0, ro},
    {obj::heartbeat_time, {0x1017, 0}, 2, rw, 10, 0xFFFF, none_else, 0},  // E-PKP-7
    {obj::identity_count, {0x1018, 0}, 1, ro, 0, any, none_else, 4},
    {obj::vendor_id, {0x1018, 1}, 4, ro, 0, any, none_else, 0x35A},
    {obj::product_code, {0x1018, 2}, 4, ro},
    {obj::revision_number, {0x1018, 3}, 4, ro, 0, any, none_else, 0x0012'1610},
    {obj::firmware_checksum, {0x1018, 4}, 4, ro, 0, any, none_else, 0x002C'E5DE},
    {obj::rpdo1_count, {0x1400, 0}, 1, ro, 0, any, none_else, 2},       // E-PKP-6
    {obj::rpdo1_cob_id, {0x1400, 1}, 2, ro, 0, any, none_else, 0x200},  // E-PKP-5
    {obj::rpdo1_inhibit_time, {0x1400, 3}, 2, ro},
    {obj::rpdo2_count, {0x1401, 0}, 1, ro, 0, any, none_else, 2},
    {obj::rpdo2_cob_id, {0x1401, 1}, 2, ro, 0, any, none_else, 0x300},
    {obj::rpdo2_inhibit_time, {0x1401, 3}, 2, ro},
    {obj::rpdo1_mapping_count, {0x1600, 0}, 1, ro, 0, any, none_else, 2},
    {obj::rpdo1_mapping_1, {0x1600, 1}, 4, ro, 0, any, none_else, 0x6001'0020},
    {obj::rpdo1_mapping_2, {0x1600, 2}, 4, ro, 0, any, none_else, 0x6002'0020},
    {obj::tpdo1_count, {0x1800, 0}, 1, ro, 0, any, none_else, 2},
    {obj::tpdo1_cob_id, {0x1800, 1}, 2, ro, 0, any, none_else, 0x180},
    {obj::tpdo1_transmission_type, {0x1800, 2}, 2, ro, 0, any, none_else, 0xFD},
    {obj::tpdo1_inhibit_time, {0x1800, 3}, 2, ro},
    {obj::tpdo1_event_timer, {0x1800, 5}, 2, ro, 0, 0xFFFF, none_else, 0},
    {obj::tpdo1_mapping_count, {0x1A00, 0}, 1, ro, 0, any, none_else, 1},
    {obj::tpdo1_mapping_1, {0x1A00, 1}, 4, ro, 0, any, none_else, 0x6000'0020},
    {obj::keys, {0x6000, 0}, 4, ro},
    {obj::led_on, {0x6001, 0}, 4, rw},
    {obj::led_blink, {0x6002, 0}, 4, rw},
    {obj::firmware_spec_count, {0x6100, 0}, 1, ro, 0, any, none_else, 2},
    {obj::serial_number, {0x6100, 1}, 4, ro},
    {obj::device_model, {0x6100, 2}, 0, ro},
    {obj::brightness_count, {0x6201, 0}, 1, ro, 0, any, none_else, 2},
    {obj::led_brightness, {0x6201, 1}, 1, rw, 0, 0x3F, none_else, 0x3F},
    {obj::backlight_level, {0x6201, 2}, 1, rw, 0, 0x3F, none_else, 0x00},
    {obj::serial_number_string, {0x6300, 0}, 0, ro},
    {obj::bootloader_present, {0x6301, 0}, 1, ro, 0, 1, none_else, 0},
    {obj::key_led_count_count, {0x6302, 0}, 1, ro, 0, any, none_else, 2},  // E-PKP-6
    {obj::total_keys, {0x6302, 1}, 1, ro},
    {obj::external_keys, {0x6302, 2}, 1, ro},
    {obj::total_leds, {0x6302, 3}, 1, ro},
    {obj::external_leds, {0x6302, 4}, 1, ro},
    {obj::command_module, {0x6500, 1}, 4, wo},
};

// The SI family: the PK1000's dictionary with RGB LEDs (docs/si-family.md, "Object
// dictionary"; "2600SI n" and "MT n" are the sections of the PKP2600SI and PKP3500-MT manuals).
// The rows the three SI dictionaries share (these, then pk_shared_rows).
inline constexpr object_row si_common_own_rows[] = {
    {obj::demo_mode, {0x2100, 0}, 1, wo, 0, 1, none_else, 0},
    {obj::protocol_j1939, {0x20FF, 1}, 2, wo, 0, 1, none_else, 0},
    {obj::heartbeat_time, {0x1017, 0}, 2, rw, 10, 0xFEFF, none_else, 0},
    {obj::rpdo1_cob_id, {0x1400, 1}, 4, ro, 0, any, none_else, 0x215},
    {obj::rpdo2_cob_id, {0x1401, 1}, 4, ro, 0, any, none_else, 0x315},
    {obj::rpdo3_cob_id, {0x1402, 1}, 4, ro, 0, any, none_else, 0x415},
    {obj::rpdo4_cob_id, {0x1403, 1}, 4, ro, 0, any, none_else, 0x515},
    {obj::tpdo1_cob_id, {0x1800, 1}, 4, ro, 0, any, none_else, 0x195},
    {obj::rpdo1_mapping_count, {0x1600, 0}, 1, ro, 0, any, none_else, 3},
    {obj::rpdo2_mapping_count, {0x1601, 0}, 1, ro, 0, any, none_else, 3},
};
inline constexpr auto si_common_rows =
    join_rows<joined_size(si_common_own_rows, pk_shared_rows)>(si_common_own_rows, pk_shared_rows);

// PKP-2600-SI: 2001h/2002h carry the RPDO bit string in three pieces (2600SI 17, 18).
inline constexpr object_row si_packed_own_rows[] = {
    {obj::led_on_r1_12_g1_4, {0x2001, 1}, 2, rw},
    {obj::led_on_g5_12, {0x2001, 2}, 1, rw},
    {obj::led_on_b1_12, {0x2001, 3}, 2, rw},
    {obj::led_blink_r1_12_g1_4, {0x2002, 1}, 2, rw},
    {obj::led_blink_g5_12, {0x2002, 2}, 1, rw},
    {obj::led_blink_b1_12, {0x2002, 3}, 2, rw},
    {obj::rpdo1_mapping_1, {0x1600, 1}, 4, ro, 0, any, none_else, 0x2001'0110},
    {obj::rpdo1_mapping_2, {0x1600, 2}, 4, ro, 0, any, none_else, 0x2001'0208},
    {obj::rpdo1_mapping_3, {0x1600, 3}, 4, ro, 0, any, none_else, 0x2001'0310},
    {obj::rpdo2_mapping_1, {0x1601, 1}, 4, ro, 0, any, none_else, 0x2002'0110},
    {obj::rpdo2_mapping_2, {0x1601, 2}, 4, ro, 0, any, none_else, 0x2002'0208},
    {obj::rpdo2_mapping_3, {0x1601, 3}, 4, ro, 0, any, none_else, 0x2002'0310},
};

// PKP-3500-MT: per-colour planes of 16 bits, the encoder rings in sub 4, encoders and inputs.
inline constexpr object_row si_mt_own_rows[] = {
    {obj::encoder1_direction_counter, {0x2000, 2}, 1, ro},
    {obj::encoder1_tick_counter, {0x2000, 3}, 2, rw, 0, 0xFFFF, none_else, 0},
    {obj::encoder2_direction_counter, {0x2000, 4}, 1, ro},
    {obj::encoder2_tick_counter, {0x2000, 5}, 2, rw, 0, 0xFFFF, none_else, 0},
    {obj::encoder1_top_position, {0x2000, 6}, 1, rw, 2, 0x10, 0, 8},
    {obj::encoder2_top_position, {0x2000, 7}, 1, rw, 2, 0x10, 0, 8},
    {obj::led_on_red, {0x2001, 1}, 2, rw},
    {obj::led_on_green, {0x2001, 2}, 2, rw},
    {obj::led_on_blue, {0x2001, 3}, 2, rw},
    {obj::led_on_encoder, {0x2001, 4}, 4, rw},
    {obj::led_blink_red, {0x2002, 1}, 2, rw},
    {obj::led_blink_green, {0x2002, 2}, 2, rw},
    {obj::led_blink_blue, {0x2002, 3}, 2, rw},
    {obj::led_blink_encoder, {0x2002, 4}, 4, rw},
    {obj::digital_input_count, {0x2004, 0}, 1, ro, 0, any, none_else, 1},
    {obj::digital_inputs, {0x2004, 1}, 1, ro, 0, 0x0F},
    {obj::analog_input_count, {0x2005, 0}, 1, ro, 0, any, none_else, 4},
    {obj::analog_input_0, {0x2005, 1}, 1, ro},
    {obj::analog_input_1, {0x2005, 2}, 1, ro},
    {obj::analog_input_2, {0x2005, 3}, 1, ro},
    {obj::analog_input_3, {0x2005, 4}, 1, ro},
    {obj::analog_input_period, {0x2006, 0}, 1, rw, 0x08, 0xC8, none_else, 0x08},
    {obj::rpdo1_mapping_1, {0x1600, 1}, 4, ro, 0, any, none_else, 0x2001'0110},
    {obj::rpdo1_mapping_2, {0x1600, 2}, 4, ro, 0, any, none_else, 0x2001'0210},
    {obj::rpdo1_mapping_3, {0x1600, 3}, 4, ro, 0, any, none_else, 0x2001'0310},
    {obj::rpdo2_mapping_1, {0x1601, 1}, 4, ro, 0, any, none_else, 0x2002'0110},
    {obj::rpdo2_mapping_2, {0x1601, 2}, 4, ro, 0, any, none_else, 0x2002'0210},
    {obj::rpdo2_mapping_3, {0x1601, 3}, 4, ro, 0, any, none_else, 0x2002'0310},
    {obj::rpdo3_mapping_1, {0x1602, 1}, 4, ro, 0, any, none_else, 0x2001'0420},
    {obj::tpdo1_event_timer, {0x1800, 5}, 2, rw, 0x32, 0xFEFF, none_else, 0},  // MT 50 a
    {obj::tpdo2_count, {0x1801, 0}, 1, ro, 0, any, none_else, 5},
    {obj::tpdo2_cob_id, {0x1801, 1}, 4, ro, 0, any, none_else, 0x295},
    {obj::tpdo2_transmission_type, {0x1801, 2}, 1, ro, 1, 0xF0, 0xFE, 0xFE},
    {obj::tpdo2_event_timer, {0x1801, 5}, 2, ro, 0, 0xFEFF, none_else, 0},
    {obj::tpdo3_count, {0x1802, 0}, 1, ro, 0, any, none_else, 5},
    {obj::tpdo3_cob_id, {0x1802, 1}, 4, ro, 0, any, none_else, 0x395},
    {obj::tpdo3_transmission_type, {0x1802, 2}, 1, ro, 1, 0xF0, 0xFE, 0xFE},
    {obj::tpdo3_event_timer, {0x1802, 5}, 2, ro, 0, 0xFEFF, none_else, 0},
    {obj::tpdo4_count, {0x1803, 0}, 1, ro, 0, any, none_else, 2},
    {obj::tpdo4_cob_id, {0x1803, 1}, 4, ro, 0, any, none_else, 0x495},
    {obj::tpdo4_transmission_type, {0x1803, 2}, 1, ro, 0, any, none_else, 0x08},  // E-SI-15
    {obj::tpdo2_mapping_count, {0x1A01, 0}, 1, ro, 0, any, none_else, 3},
    {obj::tpdo2_mapping_1, {0x1A01, 1}, 4, ro, 0, any, none_else, 0x2000'0208},
    {obj::tpdo2_mapping_2, {0x1A01, 2}, 4, ro, 0, any, none_else, 0x2000'0310},
    {obj::tpdo2_mapping_3, {0x1A01, 3}, 4, ro, 0, any, none_else, 0x2000'0608},
    {obj::tpdo3_mapping_count, {0x1A02, 0}, 1, ro, 0, any, none_else, 3},
    {obj::tpdo3_mapping_1, {0x1A02, 1}, 4, ro, 0, any, none_else, 0x2000'0408},
    {obj::tpdo3_mapping_2, {0x1A02, 2}, 4, ro, 0, any, none_else, 0x2000'0510},
    {obj::tpdo3_mapping_3, {0x1A02, 3}, 4, ro, 0, any, none_else, 0x2000'0708},
};

// PKP-3500-SI, 2500-SI, 1500-LI and the 2200/2300/2400-SI: per-colour planes of the model's
// stride (2 bytes when 16, 1 when 8: size 0 below). Printed for the 2500-SI and 1500-LI;
// inferred for the others (docs/si-family.md says which fact is which). The mapping entries'
// values depend on the stride and are not given.
// 2000h sub 01h of size 0: 2 bytes, or 1 on a keypad of 8 keys or fewer (value_kinds::keys;
// inferred, docs/si-family.md "Evidence").
inline constexpr object_row si_per_colour_own_rows[] = {
    {obj::keys, {0x2000, 1}, 0, ro},
    {obj::led_on_red, {0x2001, 1}, 0, rw},
    {obj::led_on_green, {0x2001, 2}, 0, rw},
    {obj::led_on_blue, {0x2001, 3}, 0, rw},
    {obj::led_blink_red, {0x2002, 1}, 0, rw},
    {obj::led_blink_green, {0x2002, 2}, 0, rw},
    {obj::led_blink_blue, {0x2002, 3}, 0, rw},
    {obj::rpdo1_mapping_1, {0x1600, 1}, 4, ro},
    {obj::rpdo1_mapping_2, {0x1600, 2}, 4, ro},
    {obj::rpdo1_mapping_3, {0x1600, 3}, 4, ro},
    {obj::rpdo2_mapping_1, {0x1601, 1}, 4, ro},
    {obj::rpdo2_mapping_2, {0x1601, 2}, 4, ro},
    {obj::rpdo2_mapping_3, {0x1601, 3}, 4, ro},
};

inline constexpr auto si_packed_rows =
    join_rows<joined_size(si_packed_own_rows, si_common_rows)>(si_packed_own_rows, si_common_rows);
inline constexpr auto si_mt_rows =
    join_rows<joined_size(si_mt_own_rows, si_common_rows)>(si_mt_own_rows, si_common_rows);
inline constexpr auto si_per_colour_rows =
    join_rows<joined_size(si_per_colour_own_rows, si_common_rows)>(si_per_colour_own_rows,
                                                                   si_common_rows);
}  // namespace detail

// The rows of each dictionary, in the order of POWERKEY_DICTIONARIES.
namespace detail {
#define POWERKEY_DETAIL_DICTIONARY_ROWS(name) std::span<const object_row>{name##_rows},
inline constexpr std::span<const object_row> dictionary_rows[] = {
    POWERKEY_DICTIONARIES(POWERKEY_DETAIL_DICTIONARY_ROWS)};
#undef POWERKEY_DETAIL_DICTIONARY_ROWS
}  // namespace detail

[[nodiscard]] constexpr std::span<const object_row> rows_of(dictionary d) noexcept {
    const auto i = static_cast<std::size_t>(d);
    return i < dictionary_count ? detail::dictionary_rows[i] : std::span<const object_row>{};
}

namespace detail {
// Every object at most once per dictionary, every address once (the hash table needs it), and
// every range min <= max (value_range::contains needs it).
constexpr bool rows_well_formed(std::span<const object_row> rows) noexcept {
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (rows[i].max < rows[i].min) return false;
        for (std::size_t j = 0; j < i; ++j)
            if (rows[i].id == rows[j].id || rows[i].address == rows[j].address) return false;
    }
    return true;
}
constexpr bool dictionaries_well_formed() noexcept {
    for (const auto rows : dictionary_rows)
        if (!rows_well_formed(rows)) return false;
    return true;
}
static_assert(dictionaries_well_formed());
static_assert(std::size(dictionary_rows) == dictionary_count);
}  // namespace detail

}  // namespace powerkey

#endif  // POWERKEY_KEYPAD_DICTIONARIES_HPP
