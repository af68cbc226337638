// keypad/dictionaries.hpp: the five object dictionaries as the manuals give them, read through
// their public lookups only (rows_of, find_row), so that the rows' storage may change underneath:
// rows pinned from the manuals in every dictionary, what each dictionary lacks, access, ranges
// and the range rules of every dictionary; how the PK1000 and SI dictionaries are joined from
// their own and shared rows; and every row well formed, of an object with a kind and a name.
#include <doctest/doctest.h>

#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/dictionaries.hpp>
#include <powerkey/keypad/lookup.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/names.hpp>

#include "support.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace {
using namespace powerkey;
using powerkey_tests::first_failing;

constexpr std::uint32_t any = 0xFFFF'FFFF;  // no bound / no extra value

struct dict_row {
    std::string_view section;
    std::string_view frame;  // the address, as the row runner prints it
    dictionary dict;
    object id;
    std::uint16_t index;
    std::uint8_t sub;
    std::uint8_t size;
    access acc;
    std::uint32_t min, max, also, initial;
};

constexpr auto ro = access::read_only, rw = access::read_write, wo = access::write_only;
constexpr auto pk = dictionary::pk1000, li = dictionary::pkp_li, packed = dictionary::si_packed,
               mt = dictionary::si_mt, per = dictionary::si_per_colour;
constexpr dictionary all_dictionaries[] = {pk, li, packed, mt, per};

// Size: expedited bytes (2Bh = 2, 2Fh = 1, 23h = 4 in the manuals' writes), 0 for strings and for
// the per-colour planes whose size is the model's stride. Range and default: the manual's.
constexpr dict_row dict_rows[] = {
    // PK1000_CANopen_UM_rev1.13
    {"PK1000 16", "2000h/1", pk, object::keys, 0x2000, 1, 2, ro, 0, any, any, 0},
    {"PK1000 17", "2001h/1", pk, object::led_on_red, 0x2001, 1, 4, rw, 0, any, any, 0},
    {"PK1000 18", "2002h/2", pk, object::led_blink_green, 0x2002, 2, 4, rw, 0, any, any, 0},
    {"PK1000 19 a", "2003h/1", pk, object::led_brightness, 0x2003, 1, 1, rw, 0, 0x3F, any, 0x3F},
    {"PK1000 19 c, 3", "2003h/3", pk, object::backlight_colour, 0x2003, 3, 1, rw, 1, 9, any, 0x08},
    {"PK1000 20", "2010h/0", pk, object::baud_rate, 0x2010, 0, 1, rw, 0, 7, any, 0x04},
    {"PK1000 23", "2013h/0", pk, object::node_id, 0x2013, 0, 1, rw, 1, 0x7F, any, 0x15},
    {"PK1000 24", "2014h/0", pk, object::startup_show, 0x2014, 0, 1, rw, 0, 2, any, 1},
    {"PK1000 27, 49", "20FFh/1", pk, object::protocol_j1939, 0x20FF, 1, 2, rw, 0, 1, any, 0},
    {"PK1000 36", "1011h/1", pk, object::restore_defaults, 0x1011, 1, 4, rw, 0, any, any, 0},
    {"PK1000 37", "1018h/1", pk, object::vendor_id, 0x1018, 1, 4, ro, 0, any, any, 0x3E2},
    {"PK1000 40", "1402h/2", pk, object::rpdo3_transmission_type, 0x1402, 2, 1, ro, 0, 0xF0, 0xFE,
     0xFE},
    {"PK1000 46, E-PK-11", "1800h/2", pk, object::tpdo1_transmission_type, 0x1800, 2, 1, rw, 1,
     0xF0, 0xFE, 0xFE},
    {"PK1000 48", "2200h/0", pk, object::serial_number_string, 0x2200, 0, 0, ro, 0, any, any, 0},
    // Every other writable row with a range: both ends and the default (section 3's table)
    {"PK1000 19 b, 3", "2003h/2", pk, object::backlight_level, 0x2003, 2, 1, rw, 0, 0x3F, any, 0},
    {"PK1000 19 d, 3", "2003h/4", pk, object::default_backlight_colour, 0x2003, 4, 1, rw, 1, 9, any,
     0x08},
    {"PK1000 19 e, 3", "2003h/5", pk, object::default_led_brightness, 0x2003, 5, 1, rw, 0, 0x3F,
     any, 0x3F},
    {"PK1000 19 f, 3", "2003h/6", pk, object::default_backlight_level, 0x2003, 6, 1, rw, 0, 0x3F,
     any, 0},
    {"PK1000 21, 3: boot-up active", "2011h/0", pk, object::boot_up, 0x2011, 0, 1, rw, 0, 1, any,
     1},
    {"PK1000 22, 3: not active", "2012h/0", pk, object::active_on_startup, 0x2012, 0, 1, rw, 0, 1,
     any, 0},
    {"PK1000 25: enabled", "2015h/0", pk, object::led_power, 0x2015, 0, 1, rw, 0, 1, any, 1},
    {"PK1000 26, 3: disabled", "2100h/0", pk, object::demo_mode, 0x2100, 0, 1, rw, 0, 1, any, 0},
    {"PK1000 27", "20FFh/2", pk, object::protocol_rs485, 0x20FF, 2, 2, rw, 0, 1, any, 0},
    {"PK1000 28, 3: off, node 01h", "1016h/1", pk, object::consumer_heartbeat, 0x1016, 1, 4, rw, 10,
     0xFFFF, any, 0x0001'0000},
    {"PK1000 29, 3, E-PK-8: 10 ms..", "1017h/0", pk, object::heartbeat_time, 0x1017, 0, 2, rw, 10,
     0xFFFF, any, 0},
    {"PK1000 38, 3: asynchronous", "1400h/2", pk, object::rpdo1_transmission_type, 0x1400, 2, 1, rw,
     0, 0xF0, 0xFE, 0xFE},
    {"PK1000 39, E-PK-9", "1401h/2", pk, object::rpdo2_transmission_type, 0x1401, 2, 1, rw, 0, 0xF0,
     0xFE, 0xFE},
    {"PK1000 46 b: 000Ah..FEFFh, 3: off", "1800h/5", pk, object::tpdo1_event_timer, 0x1800, 5, 2,
     rw, 10, 0xFEFF, any, 0},
    // The read-only rows of the PDO objects: the values of the examples' replies (38-47)
    {"PK1000 38", "1400h/0", pk, object::rpdo1_count, 0x1400, 0, 1, ro, 0, any, any, 2},
    {"PK1000 38", "1400h/1", pk, object::rpdo1_cob_id, 0x1400, 1, 4, ro, 0, any, any, 0x4000'0215},
    {"PK1000 39", "1401h/0", pk, object::rpdo2_count, 0x1401, 0, 1, ro, 0, any, any, 2},
    {"PK1000 39", "1401h/1", pk, object::rpdo2_cob_id, 0x1401, 1, 4, ro, 0, any, any, 0x4000'0315},
    {"PK1000 40", "1402h/0", pk, object::rpdo3_count, 0x1402, 0, 1, ro, 0, any, any, 2},
    {"PK1000 40", "1402h/1", pk, object::rpdo3_cob_id, 0x1402, 1, 4, ro, 0, any, any, 0x4000'0415},
    {"PK1000 41", "1403h/0", pk, object::rpdo4_count, 0x1403, 0, 1, ro, 0, any, any, 2},
    {"PK1000 41", "1403h/1", pk, object::rpdo4_cob_id, 0x1403, 1, 4, ro, 0, any, any, 0x4000'0515},
    {"PK1000 42", "1600h/0", pk, object::rpdo1_mapping_count, 0x1600, 0, 1, ro, 0, any, any, 2},
    {"PK1000 42", "1600h/1", pk, object::rpdo1_mapping_1, 0x1600, 1, 4, ro, 0, any, any,
     0x2001'0120},
    {"PK1000 42", "1600h/2", pk, object::rpdo1_mapping_2, 0x1600, 2, 4, ro, 0, any, any,
     0x2001'0220},
    {"PK1000 43", "1601h/0", pk, object::rpdo2_mapping_count, 0x1601, 0, 1, ro, 0, any, any, 2},
    {"PK1000 43", "1601h/1", pk, object::rpdo2_mapping_1, 0x1601, 1, 4, ro, 0, any, any,
     0x2002'0120},
    {"PK1000 43, E-PK-5", "1601h/2", pk, object::rpdo2_mapping_2, 0x1601, 2, 4, ro, 0, any, any,
     0x2002'0220},
    {"PK1000 44", "1602h/0", pk, object::rpdo3_mapping_count, 0x1602, 0, 1, ro, 0, any, any, 1},
    {"PK1000 44", "1602h/1", pk, object::rpdo3_mapping_1, 0x1602, 1, 4, ro, 0, any, any,
     0x2003'0108},
    {"PK1000 45", "1603h/0", pk, object::rpdo4_mapping_count, 0x1603, 0, 1, ro, 0, any, any, 2},
    {"PK1000 45", "1603h/1", pk, object::rpdo4_mapping_1, 0x1603, 1, 4, ro, 0, any, any,
     0x2003'0208},
    {"PK1000 45", "1603h/2", pk, object::rpdo4_mapping_2, 0x1603, 2, 4, ro, 0, any, any,
     0x2003'0308},
    {"PK1000 46", "1800h/0", pk, object::tpdo1_count, 0x1800, 0, 1, ro, 0, any, any, 5},
    {"PK1000 46", "1800h/1", pk, object::tpdo1_cob_id, 0x1800, 1, 4, ro, 0, any, any, 0x4000'0195},
    {"PK1000 47", "1A00h/0", pk, object::tpdo1_mapping_count, 0x1A00, 0, 1, ro, 0, any, any, 1},
    {"PK1000 47, E-PK-12", "1A00h/1", pk, object::tpdo1_mapping_1, 0x1A00, 1, 4, ro, 0, any, any,
     0x2000'0110},
    {"PK1000 40: FEh", "1402h/2", pk, object::rpdo3_transmission_type, 0x1402, 2, 1, ro, 0, 0xF0,
     0xFE, 0xFE},
    // PKP-2200-2400-LI_CANopen_UM_rev1.1
    {"PKP 13", "6500h/1", li, object::command_module, 0x6500, 1, 4, wo, 0, any, any, 0},
    {"PKP 14", "6000h/0", li, object::keys, 0x6000, 0, 4, ro, 0, any, any, 0},
    {"PKP 15", "6001h/0", li, object::led_on, 0x6001, 0, 4, rw, 0, any, any, 0},
    {"PKP 16", "6002h/0", li, object::led_blink, 0x6002, 0, 4, rw, 0, any, any, 0},
    {"PKP 17, E-PKP-7", "1017h/0", li, object::heartbeat_time, 0x1017, 0, 2, rw, 10, 0xFFFF, any,
     0},
    {"PKP 23", "1018h/1", li, object::vendor_id, 0x1018, 1, 4, ro, 0, any, any, 0x35A},
    {"PKP 30", "6201h/1", li, object::led_brightness, 0x6201, 1, 1, rw, 0, 0x3F, any, 0x3F},
    {"PKP 30", "6201h/2", li, object::backlight_level, 0x6201, 2, 1, rw, 0, 0x3F, any, 0},
    {"PKP 27: 1800h/2 FDh (RTR only)", "1800h/2", li, object::tpdo1_transmission_type, 0x1800, 2, 2,
     ro, 0, any, any, 0xFD},
    {"PKP 24, E-PKP-5: 200h", "1400h/1", li, object::rpdo1_cob_id, 0x1400, 1, 2, ro, 0, any, any,
     0x200},
    {"PKP 32", "6301h/0", li, object::bootloader_present, 0x6301, 0, 1, ro, 0, 1, any, 0},
    {"PKP 27, E-PKP-10: read only, 0 = off", "1800h/5", li, object::tpdo1_event_timer, 0x1800, 5, 2,
     ro, 0, 0xFFFF, any, 0},
    // PKP2600SI_CANopen_UM_rev1.5: 2001h/2002h in three pieces (17, 18)
    {"2600SI 17 a sub 1 (2Bh)", "2001h/1", packed, object::led_on_r1_12_g1_4, 0x2001, 1, 2, rw, 0,
     any, any, 0},
    {"2600SI 17 a sub 2 (2Fh)", "2001h/2", packed, object::led_on_g5_12, 0x2001, 2, 1, rw, 0, any,
     any, 0},
    {"2600SI 17 a sub 3 (2Bh)", "2001h/3", packed, object::led_on_b1_12, 0x2001, 3, 2, rw, 0, any,
     any, 0},
    {"2600SI 18", "2002h/3", packed, object::led_blink_b1_12, 0x2002, 3, 2, rw, 0, any, any, 0},
    {"2600SI 19 a", "2003h/1", packed, object::led_brightness, 0x2003, 1, 1, rw, 0, 0x3F, any,
     0x3F},
    {"2600SI 26 (write only)", "2100h/0", packed, object::demo_mode, 0x2100, 0, 1, wo, 0, 1, any,
     0},
    {"2600SI, 1017h 000Ah..FEFFh", "1017h/0", packed, object::heartbeat_time, 0x1017, 0, 2, rw, 10,
     0xFEFF, any, 0},
    // The read-only rows: identity, counts, COB-IDs and PDO mappings, the values of the examples'
    // replies (2600SI 26, 28, 34-45). Sub-index 00h is the highest sub-index (E-SI-21).
    {"2600SI 26: 01h", "1016h/0", packed, object::consumer_heartbeat_count, 0x1016, 0, 1, ro, 0,
     any, any, 1},
    {"2600SI 28, E-SI-16", "1000h/0", packed, object::device_type, 0x1000, 0, 4, ro, 0, any, any,
     0x000B'0191},
    {"2600SI 34: 01h", "1011h/0", packed, object::restore_count, 0x1011, 0, 1, ro, 0, any, any, 1},
    {"2600SI 35: 04h", "1018h/0", packed, object::identity_count, 0x1018, 0, 1, ro, 0, any, any, 4},
    {"2600SI 35: 000003E2h", "1018h/1", packed, object::vendor_id, 0x1018, 1, 4, ro, 0, any, any,
     0x3E2},
    {"2600SI 35: no example", "1018h/4", packed, object::serial_number, 0x1018, 4, 4, ro, 0, any,
     any, 0},
    {"2600SI 36: 02h", "1400h/0", packed, object::rpdo1_count, 0x1400, 0, 1, ro, 0, any, any, 2},
    {"2600SI 36: 0000 0215h", "1400h/1", packed, object::rpdo1_cob_id, 0x1400, 1, 4, ro, 0, any,
     any, 0x215},
    {"2600SI 36: 00h-F0h, FEh", "1400h/2", packed, object::rpdo1_transmission_type, 0x1400, 2, 1,
     rw, 0, 0xF0, 0xFE, 0xFE},
    {"2600SI 37: 02h", "1401h/0", packed, object::rpdo2_count, 0x1401, 0, 1, ro, 0, any, any, 2},
    {"2600SI 37: 0000 0315h", "1401h/1", packed, object::rpdo2_cob_id, 0x1401, 1, 4, ro, 0, any,
     any, 0x315},
    {"2600SI 37: 00h-F0h, FEh", "1401h/2", packed, object::rpdo2_transmission_type, 0x1401, 2, 1,
     rw, 0, 0xF0, 0xFE, 0xFE},
    {"2600SI 38: 02h", "1402h/0", packed, object::rpdo3_count, 0x1402, 0, 1, ro, 0, any, any, 2},
    {"2600SI 38: 0000 0415h", "1402h/1", packed, object::rpdo3_cob_id, 0x1402, 1, 4, ro, 0, any,
     any, 0x415},
    {"2600SI 38: FEh (read only)", "1402h/2", packed, object::rpdo3_transmission_type, 0x1402, 2, 1,
     ro, 0, 0xF0, 0xFE, 0xFE},
    {"2600SI 39: 02h", "1403h/0", packed, object::rpdo4_count, 0x1403, 0, 1, ro, 0, any, any, 2},
    {"2600SI 39: 0000 0515h", "1403h/1", packed, object::rpdo4_cob_id, 0x1403, 1, 4, ro, 0, any,
     any, 0x515},
    {"2600SI 39: FEh (read only)", "1403h/2", packed, object::rpdo4_transmission_type, 0x1403, 2, 1,
     ro, 0, 0xF0, 0xFE, 0xFE},
    {"2600SI 40: 3", "1600h/0", packed, object::rpdo1_mapping_count, 0x1600, 0, 1, ro, 0, any, any,
     3},
    {"2600SI 40: 2001 01 10", "1600h/1", packed, object::rpdo1_mapping_1, 0x1600, 1, 4, ro, 0, any,
     any, 0x2001'0110},
    {"2600SI 40: 2001 02 08", "1600h/2", packed, object::rpdo1_mapping_2, 0x1600, 2, 4, ro, 0, any,
     any, 0x2001'0208},
    {"2600SI 40: 2001 03 10", "1600h/3", packed, object::rpdo1_mapping_3, 0x1600, 3, 4, ro, 0, any,
     any, 0x2001'0310},
    {"2600SI 41: 3", "1601h/0", packed, object::rpdo2_mapping_count, 0x1601, 0, 1, ro, 0, any, any,
     3},
    {"2600SI 41: 2002 01 10", "1601h/1", packed, object::rpdo2_mapping_1, 0x1601, 1, 4, ro, 0, any,
     any, 0x2002'0110},
    {"2600SI 41: 2002 02 08", "1601h/2", packed, object::rpdo2_mapping_2, 0x1601, 2, 4, ro, 0, any,
     any, 0x2002'0208},
    {"2600SI 41: 2002 03 10", "1601h/3", packed, object::rpdo2_mapping_3, 0x1601, 3, 4, ro, 0, any,
     any, 0x2002'0310},
    {"2600SI 42: 1", "1602h/0", packed, object::rpdo3_mapping_count, 0x1602, 0, 1, ro, 0, any, any,
     1},
    {"2600SI 42: 2003 01 08", "1602h/1", packed, object::rpdo3_mapping_1, 0x1602, 1, 4, ro, 0, any,
     any, 0x2003'0108},
    {"2600SI 43: 2 (rev 1.5)", "1603h/0", packed, object::rpdo4_mapping_count, 0x1603, 0, 1, ro, 0,
     any, any, 2},
    {"2600SI 43: 2003 02 08", "1603h/1", packed, object::rpdo4_mapping_1, 0x1603, 1, 4, ro, 0, any,
     any, 0x2003'0208},
    {"2600SI 43: 2003 03 08", "1603h/2", packed, object::rpdo4_mapping_2, 0x1603, 2, 4, ro, 0, any,
     any, 0x2003'0308},
    {"2600SI 44 a: 5", "1800h/0", packed, object::tpdo1_count, 0x1800, 0, 1, ro, 0, any, any, 5},
    {"2600SI 44 a: 0000 0195h", "1800h/1", packed, object::tpdo1_cob_id, 0x1800, 1, 4, ro, 0, any,
     any, 0x195},
    {"2600SI 44 a: 01h..F0h, FEh (default)", "1800h/2", packed, object::tpdo1_transmission_type,
     0x1800, 2, 1, rw, 1, 0xF0, 0xFE, 0xFE},
    {"2600SI 44 b, E-SI-18: 000Ah..FEFFh, 0000h off", "1800h/5", packed, object::tpdo1_event_timer,
     0x1800, 5, 2, rw, 10, 0xFEFF, any, 0},
    {"2600SI 45: 1", "1A00h/0", packed, object::tpdo1_mapping_count, 0x1A00, 0, 1, ro, 0, any, any,
     1},
    {"2600SI 45, E-SI-19: 2000 01 10", "1A00h/1", packed, object::tpdo1_mapping_1, 0x1A00, 1, 4, ro,
     0, any, any, 0x2000'0110},
    // PKP3500-MT_CANopen_UM_rev1.3
    {"MT 19 b", "2000h/2", mt, object::encoder1_direction_counter, 0x2000, 2, 1, ro, 0, any, any,
     0},
    {"MT 19 f: 00h off, 02h..10h, default 08h", "2000h/6", mt, object::encoder1_top_position,
     0x2000, 6, 1, rw, 2, 0x10, 0, 8},
    {"MT 19 g", "2000h/7", mt, object::encoder2_top_position, 0x2000, 7, 1, rw, 2, 0x10, 0, 8},
    {"MT 20 a", "2001h/3", mt, object::led_on_blue, 0x2001, 3, 2, rw, 0, any, any, 0},
    {"MT 20 c", "2001h/4", mt, object::led_on_encoder, 0x2001, 4, 4, rw, 0, any, any, 0},
    {"MT 21 c", "2002h/4", mt, object::led_blink_encoder, 0x2002, 4, 4, rw, 0, any, any, 0},
    {"MT 25: 08h (80 ms)..C8h (2 s)", "2006h/0", mt, object::analog_input_period, 0x2006, 0, 1, rw,
     0x08, 0xC8, any, 0x08},
    {"MT 50: 0032h..FEFFh ms", "1800h/5", mt, object::tpdo1_event_timer, 0x1800, 5, 2, rw, 0x32,
     0xFEFF, any, 0},
    // The read-only rows: identity, counts, COB-IDs and PDO mappings, the values of the examples'
    // replies (MT 23, 24, 32, 34, 40-56). Sub-index 00h is the highest sub-index (E-SI-21).
    {"MT 23: 01h", "2004h/0", mt, object::digital_input_count, 0x2004, 0, 1, ro, 0, any, any, 1},
    {"MT 23: bits 0..3", "2004h/1", mt, object::digital_inputs, 0x2004, 1, 1, ro, 0, 0x0F, any, 0},
    {"MT 24, E-SI-10: 04h", "2005h/0", mt, object::analog_input_count, 0x2005, 0, 1, ro, 0, any,
     any, 4},
    {"MT 24: IN0", "2005h/1", mt, object::analog_input_0, 0x2005, 1, 1, ro, 0, any, any, 0},
    {"MT 24: IN3", "2005h/4", mt, object::analog_input_3, 0x2005, 4, 1, ro, 0, any, any, 0},
    {"MT 32: 01h", "1016h/0", mt, object::consumer_heartbeat_count, 0x1016, 0, 1, ro, 0, any, any,
     1},
    {"MT 34, E-SI-16", "1000h/0", mt, object::device_type, 0x1000, 0, 4, ro, 0, any, any,
     0x000B'0191},
    {"MT 40: 1", "1011h/0", mt, object::restore_count, 0x1011, 0, 1, ro, 0, any, any, 1},
    {"MT 41: 4", "1018h/0", mt, object::identity_count, 0x1018, 0, 1, ro, 0, any, any, 4},
    {"MT 41: 000003E2h", "1018h/1", mt, object::vendor_id, 0x1018, 1, 4, ro, 0, any, any, 0x3E2},
    {"MT 41: no example", "1018h/4", mt, object::serial_number, 0x1018, 4, 4, ro, 0, any, any, 0},
    {"MT 42: 2", "1400h/0", mt, object::rpdo1_count, 0x1400, 0, 1, ro, 0, any, any, 2},
    {"MT 42: 0000 0215h", "1400h/1", mt, object::rpdo1_cob_id, 0x1400, 1, 4, ro, 0, any, any,
     0x215},
    {"MT 42: 00h-F0h, FEh", "1400h/2", mt, object::rpdo1_transmission_type, 0x1400, 2, 1, rw, 0,
     0xF0, 0xFE, 0xFE},
    {"MT 43: 2", "1401h/0", mt, object::rpdo2_count, 0x1401, 0, 1, ro, 0, any, any, 2},
    {"MT 43: 0000 0315h", "1401h/1", mt, object::rpdo2_cob_id, 0x1401, 1, 4, ro, 0, any, any,
     0x315},
    {"MT 43: 00h-F0h, FEh", "1401h/2", mt, object::rpdo2_transmission_type, 0x1401, 2, 1, rw, 0,
     0xF0, 0xFE, 0xFE},
    {"MT 44: 2", "1402h/0", mt, object::rpdo3_count, 0x1402, 0, 1, ro, 0, any, any, 2},
    {"MT 44: 0000 415h", "1402h/1", mt, object::rpdo3_cob_id, 0x1402, 1, 4, ro, 0, any, any, 0x415},
    {"MT 44: FEh (read only)", "1402h/2", mt, object::rpdo3_transmission_type, 0x1402, 2, 1, ro, 0,
     0xF0, 0xFE, 0xFE},
    {"MT 45: 2", "1403h/0", mt, object::rpdo4_count, 0x1403, 0, 1, ro, 0, any, any, 2},
    {"MT 45: 0000 0515h", "1403h/1", mt, object::rpdo4_cob_id, 0x1403, 1, 4, ro, 0, any, any,
     0x515},
    {"MT 45: FEh (read only)", "1403h/2", mt, object::rpdo4_transmission_type, 0x1403, 2, 1, ro, 0,
     0xF0, 0xFE, 0xFE},
    {"MT 46: 3", "1600h/0", mt, object::rpdo1_mapping_count, 0x1600, 0, 1, ro, 0, any, any, 3},
    {"MT 46: 2001 01 10", "1600h/1", mt, object::rpdo1_mapping_1, 0x1600, 1, 4, ro, 0, any, any,
     0x2001'0110},
    {"MT 46: 2001 02 10", "1600h/2", mt, object::rpdo1_mapping_2, 0x1600, 2, 4, ro, 0, any, any,
     0x2001'0210},
    {"MT 46: 2001 03 10", "1600h/3", mt, object::rpdo1_mapping_3, 0x1600, 3, 4, ro, 0, any, any,
     0x2001'0310},
    {"MT 47: 3", "1601h/0", mt, object::rpdo2_mapping_count, 0x1601, 0, 1, ro, 0, any, any, 3},
    {"MT 47: 2002 01 10", "1601h/1", mt, object::rpdo2_mapping_1, 0x1601, 1, 4, ro, 0, any, any,
     0x2002'0110},
    {"MT 47: 2002 02 10", "1601h/2", mt, object::rpdo2_mapping_2, 0x1601, 2, 4, ro, 0, any, any,
     0x2002'0210},
    {"MT 47: 2002 03 10", "1601h/3", mt, object::rpdo2_mapping_3, 0x1601, 3, 4, ro, 0, any, any,
     0x2002'0310},
    {"MT 48: 1", "1602h/0", mt, object::rpdo3_mapping_count, 0x1602, 0, 1, ro, 0, any, any, 1},
    {"MT 48: 2001 04 20 (the rings)", "1602h/1", mt, object::rpdo3_mapping_1, 0x1602, 1, 4, ro, 0,
     any, any, 0x2001'0420},
    {"MT 49: 2", "1603h/0", mt, object::rpdo4_mapping_count, 0x1603, 0, 1, ro, 0, any, any, 2},
    {"MT 49: 2003 02 08", "1603h/1", mt, object::rpdo4_mapping_1, 0x1603, 1, 4, ro, 0, any, any,
     0x2003'0208},
    {"MT 49: 2003 03 08", "1603h/2", mt, object::rpdo4_mapping_2, 0x1603, 2, 4, ro, 0, any, any,
     0x2003'0308},
    {"MT 50 a: 5", "1800h/0", mt, object::tpdo1_count, 0x1800, 0, 1, ro, 0, any, any, 5},
    {"MT 50 a: 0000 0195h", "1800h/1", mt, object::tpdo1_cob_id, 0x1800, 1, 4, ro, 0, any, any,
     0x195},
    {"MT 50 a: 01h..F0h, FEh (default)", "1800h/2", mt, object::tpdo1_transmission_type, 0x1800, 2,
     1, rw, 1, 0xF0, 0xFE, 0xFE},
    // 1801h/1802h: only reads are printed; the type's range is 1800h's (CiA 301's TPDO types).
    {"MT 51: 5", "1801h/0", mt, object::tpdo2_count, 0x1801, 0, 1, ro, 0, any, any, 5},
    {"MT 51: 0000 0295h", "1801h/1", mt, object::tpdo2_cob_id, 0x1801, 1, 4, ro, 0, any, any,
     0x295},
    {"MT 51: FEh", "1801h/2", mt, object::tpdo2_transmission_type, 0x1801, 2, 1, ro, 1, 0xF0, 0xFE,
     0xFE},
    {"MT 51: 0000h disabled", "1801h/5", mt, object::tpdo2_event_timer, 0x1801, 5, 2, ro, 0, 0xFEFF,
     any, 0},
    {"MT 52: 5", "1802h/0", mt, object::tpdo3_count, 0x1802, 0, 1, ro, 0, any, any, 5},
    {"MT 52: 0000 0395h", "1802h/1", mt, object::tpdo3_cob_id, 0x1802, 1, 4, ro, 0, any, any,
     0x395},
    {"MT 52: FEh", "1802h/2", mt, object::tpdo3_transmission_type, 0x1802, 2, 1, ro, 1, 0xF0, 0xFE,
     0xFE},
    {"MT 52: 0000h disabled", "1802h/5", mt, object::tpdo3_event_timer, 0x1802, 5, 2, ro, 0, 0xFEFF,
     any, 0},
    {"MT 53: 2", "1803h/0", mt, object::tpdo4_count, 0x1803, 0, 1, ro, 0, any, any, 2},
    {"MT 53: 0000 0495h", "1803h/1", mt, object::tpdo4_cob_id, 0x1803, 1, 4, ro, 0, any, any,
     0x495},
    {"MT 53, 3, E-SI-15: XX, 2006h's 08h", "1803h/2", mt, object::tpdo4_transmission_type, 0x1803,
     2, 1, ro, 0, any, any, 0x08},
    {"MT 54: 1", "1A00h/0", mt, object::tpdo1_mapping_count, 0x1A00, 0, 1, ro, 0, any, any, 1},
    {"MT 54, E-SI-19: 2000 01 10", "1A00h/1", mt, object::tpdo1_mapping_1, 0x1A00, 1, 4, ro, 0, any,
     any, 0x2000'0110},
    {"MT 55: 3", "1A01h/0", mt, object::tpdo2_mapping_count, 0x1A01, 0, 1, ro, 0, any, any, 3},
    {"MT 55, E-SI-24: 2000 02 08", "1A01h/1", mt, object::tpdo2_mapping_1, 0x1A01, 1, 4, ro, 0, any,
     any, 0x2000'0208},
    {"MT 55: 2000 03 10", "1A01h/2", mt, object::tpdo2_mapping_2, 0x1A01, 2, 4, ro, 0, any, any,
     0x2000'0310},
    {"MT 55, E-SI-24: 2000 06 08", "1A01h/3", mt, object::tpdo2_mapping_3, 0x1A01, 3, 4, ro, 0, any,
     any, 0x2000'0608},
    {"MT 56: 3", "1A02h/0", mt, object::tpdo3_mapping_count, 0x1A02, 0, 1, ro, 0, any, any, 3},
    {"MT 56, E-SI-24: 2000 04 08", "1A02h/1", mt, object::tpdo3_mapping_1, 0x1A02, 1, 4, ro, 0, any,
     any, 0x2000'0408},
    {"MT 56: 2000 05 10", "1A02h/2", mt, object::tpdo3_mapping_2, 0x1A02, 2, 4, ro, 0, any, any,
     0x2000'0510},
    {"MT 56, E-SI-24: 2000 07 08", "1A02h/3", mt, object::tpdo3_mapping_3, 0x1A02, 3, 4, ro, 0, any,
     any, 0x2000'0708},
    // docs/si-family.md: the per-colour dictionary (planes of the model's stride: size 0)
    {"si-family 2001h", "2001h/1", per, object::led_on_red, 0x2001, 1, 0, rw, 0, any, any, 0},
    {"si-family 2002h", "2002h/3", per, object::led_blink_blue, 0x2002, 3, 0, rw, 0, any, any, 0},
    // 2000h/1: 2 bytes, or 1 on 8 keys or fewer (size 0: value_kinds::keys; issue 22, inferred)
    {"si-family 2000h", "2000h/1", per, object::keys, 0x2000, 1, 0, ro, 0, any, any, 0},
    {"si-family 20FFh (write only)", "20FFh/1", per, object::protocol_j1939, 0x20FF, 1, 2, wo, 0, 1,
     any, 0},
    {"si-family 1800h/5: as PK1000 46 b", "1800h/5", per, object::tpdo1_event_timer, 0x1800, 5, 2,
     rw, 10, 0xFEFF, any, 0},
    {"si-family 1017h: 000Ah..FEFFh", "1017h/0", per, object::heartbeat_time, 0x1017, 0, 2, rw, 10,
     0xFEFF, any, 0},
    // The read-only rows of the per-colour dictionary (docs/si-family.md, "The per-colour
    // dictionary's read-only rows"): the source of each value in its section. "inferred" where no
    // page of these sizes prints it; the value is then the PKP2600SI and PKP3500-MT manuals' one.
    {"si-family: SI generic pages (1000h)", "1000h/0", per, object::device_type, 0x1000, 0, 4, ro,
     0, any, any, 0x000B'0191},
    {"si-family: inferred (1016h/0)", "1016h/0", per, object::consumer_heartbeat_count, 0x1016, 0,
     1, ro, 0, any, any, 1},
    {"si-family: inferred (1011h/0)", "1011h/0", per, object::restore_count, 0x1011, 0, 1, ro, 0,
     any, any, 1},
    {"si-family: inferred (1018h/0)", "1018h/0", per, object::identity_count, 0x1018, 0, 1, ro, 0,
     any, any, 4},
    {"si-family: inferred (1018h/1)", "1018h/1", per, object::vendor_id, 0x1018, 1, 4, ro, 0, any,
     any, 0x3E2},
    {"si-family: inferred (1400h/0)", "1400h/0", per, object::rpdo1_count, 0x1400, 0, 1, ro, 0, any,
     any, 2},
    {"si-family: inferred (1400h/1)", "1400h/1", per, object::rpdo1_cob_id, 0x1400, 1, 4, ro, 0,
     any, any, 0x215},
    {"si-family: PKP3500SI manual (1400h/2)", "1400h/2", per, object::rpdo1_transmission_type,
     0x1400, 2, 1, rw, 0, 0xF0, 0xFE, 0xFE},
    {"si-family: inferred (1401h/1)", "1401h/1", per, object::rpdo2_cob_id, 0x1401, 1, 4, ro, 0,
     any, any, 0x315},
    {"si-family: PKP2500SI manual (1402h: 415h)", "1402h/1", per, object::rpdo3_cob_id, 0x1402, 1,
     4, ro, 0, any, any, 0x415},
    {"si-family: SI generic pages (1403h: 515h)", "1403h/1", per, object::rpdo4_cob_id, 0x1403, 1,
     4, ro, 0, any, any, 0x515},
    {"si-family: inferred (1600h/0)", "1600h/0", per, object::rpdo1_mapping_count, 0x1600, 0, 1, ro,
     0, any, any, 3},
    // 1600h/1601h subs 1..3: 16 bits each at S = 16 (PKP2500SI manual, 1601h), 8 at S = 8; one
    // row for every stride, so no value.
    {"si-family: per stride, no value", "1600h/1", per, object::rpdo1_mapping_1, 0x1600, 1, 4, ro,
     0, any, any, 0},
    {"si-family: PKP2500SI manual (1601h/1..3)", "1601h/0", per, object::rpdo2_mapping_count,
     0x1601, 0, 1, ro, 0, any, any, 3},
    {"si-family: per stride, no value", "1601h/3", per, object::rpdo2_mapping_3, 0x1601, 3, 4, ro,
     0, any, any, 0},
    {"si-family: inferred (1602h/1)", "1602h/1", per, object::rpdo3_mapping_1, 0x1602, 1, 4, ro, 0,
     any, any, 0x2003'0108},
    {"si-family: inferred (1603h/0)", "1603h/0", per, object::rpdo4_mapping_count, 0x1603, 0, 1, ro,
     0, any, any, 2},
    {"si-family: inferred (1603h/2, the colour)", "1603h/2", per, object::rpdo4_mapping_2, 0x1603,
     2, 4, ro, 0, any, any, 0x2003'0308},
    {"si-family: SI generic pages (1800h/0)", "1800h/0", per, object::tpdo1_count, 0x1800, 0, 1, ro,
     0, any, any, 5},
    {"si-family: SI generic pages (1800h/1: 195h)", "1800h/1", per, object::tpdo1_cob_id, 0x1800, 1,
     4, ro, 0, any, any, 0x195},
    {"si-family: SI generic pages (1800h/2: FEh)", "1800h/2", per, object::tpdo1_transmission_type,
     0x1800, 2, 1, rw, 1, 0xF0, 0xFE, 0xFE},
    {"si-family: inferred (1A00h/0)", "1A00h/0", per, object::tpdo1_mapping_count, 0x1A00, 0, 1, ro,
     0, any, any, 1},
    {"si-family: PKP2500SI manual (1A00h/1)", "1A00h/1", per, object::tpdo1_mapping_1, 0x1A00, 1, 4,
     ro, 0, any, any, 0x2000'0110},
};

constexpr bool row_is(const object_row& r, const dict_row& e) {
    return r.id == e.id && r.address == canopen::sdo_address{e.index, e.sub} && r.size == e.size &&
           r.access == e.acc && r.min == e.min && r.max == e.max && r.also == e.also &&
           r.initial == e.initial;
}

// Found by its address and by its object, with every field as the manual gives it.
constexpr bool found_both_ways(const dict_row& e) {
    const auto by_address = find_row(e.dict, canopen::sdo_address{e.index, e.sub});
    const auto by_object = find_row(e.dict, e.id);
    return by_address && by_object && row_is(*by_address, e) && row_is(*by_object, e);
}
static_assert(
    powerkey_tests::all_rows_pass<first_failing(dict_rows, found_both_ways), std::size(dict_rows)>);

// What each dictionary lacks: an address, and an object another dictionary has.
struct absent_row {
    std::string_view section;
    std::string_view frame;
    dictionary dict;
    std::uint16_t index;
    std::uint8_t sub;
    object id;
};
constexpr absent_row absent_rows[] = {
    {"PK1000: no 6000h, no command module", "6000h/0", pk, 0x6000, 0, object::command_module},
    {"PK1000: 2003h has subs 1..6", "2003h/7", pk, 0x2003, 7, object::led_on_blue},
    {"PKP: no 2000h, no J1939", "2000h/1", li, 0x2000, 1, object::protocol_j1939},
    {"PKP: 6500h has sub 1 only", "6500h/2", li, 0x6500, 2, object::led_on_red},
    {"2600SI: no 2001h/4, LEDs in pieces", "2001h/4", packed, 0x2001, 4, object::led_on_red},
    {"2600SI: no encoders", "2000h/2", packed, 0x2000, 2, object::encoder1_tick_counter},
    {"MT: no 2001h/5, no pieces", "2001h/5", mt, 0x2001, 5, object::led_on_r1_12_g1_4},
    {"MT: no 6000h", "6000h/0", mt, 0x6000, 0, object::command_module},
    {"si-family: no 2001h/4 (rings)", "2001h/4", per, 0x2001, 4, object::led_on_encoder},
    {"si-family: no 2006h", "2006h/0", per, 0x2006, 0, object::analog_input_period},
    {"2600SI: no 1801h (TPDO1 only)", "1801h/0", packed, 0x1801, 0, object::tpdo2_count},
    {"2600SI: 1018h has subs 1 and 4 (35)", "1018h/2", packed, 0x1018, 2, object::product_code},
    {"MT: 1803h has no sub 5 (53)", "1803h/5", mt, 0x1803, 5, object::firmware_checksum},
    {"MT: 1018h has no sub 3 (41)", "1018h/3", mt, 0x1018, 3, object::revision_number},
    {"si-family: no 1A01h (no encoders)", "1A01h/1", per, 0x1A01, 1, object::tpdo2_mapping_1},
};
constexpr bool absent(const absent_row& r) {
    return !find_row(r.dict, canopen::sdo_address{r.index, r.sub}) && !find_row(r.dict, r.id) &&
           !find_row(r.dict, static_cast<object>(object_count)) &&
           !find_row(r.dict, static_cast<object>(0xFF));
}
static_assert(
    powerkey_tests::all_rows_pass<first_failing(absent_rows, absent), std::size(absent_rows)>);

// The access rule: a read-only row is not writable, a write-only row not readable.
struct access_row {
    std::string_view section;
    std::string_view frame;
    dictionary dict;
    object id;
    bool readable, writable;
};
constexpr access_row access_rows[] = {
    {"PK1000 16: keys", "", pk, object::keys, true, false},
    {"PK1000 19", "", pk, object::led_brightness, true, true},
    {"PKP 13: command module", "", li, object::command_module, false, true},
    {"2600SI 26", "", packed, object::demo_mode, false, true},
    {"MT 24", "", mt, object::analog_input_0, true, false},
    {"si-family 20FFh", "", per, object::protocol_j1939, false, true},
};
constexpr bool access_holds(const access_row& r) {
    const auto row = find_row(r.dict, r.id);
    return row && row->readable() == r.readable && row->writable() == r.writable;
}
static_assert(powerkey_tests::all_rows_pass<first_failing(access_rows, access_holds),
                                            std::size(access_rows)>);

// Ranges: both ends, one past each, and the extra value (FEh event-driven, 00h TOP off).
struct range_row {
    std::string_view section;
    std::string_view frame;
    dictionary dict;
    object id;
    std::uint32_t value;
    bool in;
};
constexpr range_row range_rows[] = {
    {"PK1000 46: 00h is not a TPDO type", "", pk, object::tpdo1_transmission_type, 0x00, false},
    {"PK1000 46: 01h every SYNC", "", pk, object::tpdo1_transmission_type, 0x01, true},
    {"PK1000 46: F0h every 240th SYNC", "", pk, object::tpdo1_transmission_type, 0xF0, true},
    {"PK1000 46: F1h", "", pk, object::tpdo1_transmission_type, 0xF1, false},
    {"PK1000 46: FDh", "", pk, object::tpdo1_transmission_type, 0xFD, false},
    {"PK1000 46: FEh event-driven", "", pk, object::tpdo1_transmission_type, 0xFE, true},
    {"PK1000 46: FFh", "", pk, object::tpdo1_transmission_type, 0xFF, false},
    {"PK1000 23: node 00h", "", pk, object::node_id, 0x00, false},
    {"PK1000 23: node 7Fh", "", pk, object::node_id, 0x7F, true},
    {"PK1000 23: node 80h", "", pk, object::node_id, 0x80, false},
    {"PKP 30: 3Fh", "", li, object::led_brightness, 0x3F, true},
    {"PKP 30: 40h", "", li, object::led_brightness, 0x40, false},
    {"PKP 17: 9 ms", "", li, object::heartbeat_time, 9, false},
    {"PKP 17: FFFFh", "", li, object::heartbeat_time, 0xFFFF, true},
    {"2600SI: 1017h FEFFh", "", packed, object::heartbeat_time, 0xFEFF, true},
    {"2600SI: 1017h FF00h", "", packed, object::heartbeat_time, 0xFF00, false},
    {"MT 19 f: 00h disabled", "", mt, object::encoder1_top_position, 0x00, true},
    {"MT 19 f: 01h", "", mt, object::encoder1_top_position, 0x01, false},
    {"MT 19 f: 02h", "", mt, object::encoder1_top_position, 0x02, true},
    {"MT 19 f: 10h", "", mt, object::encoder1_top_position, 0x10, true},
    {"MT 19 f: 11h", "", mt, object::encoder1_top_position, 0x11, false},
    {"MT 25: 07h", "", mt, object::analog_input_period, 0x07, false},
    {"MT 25: C8h", "", mt, object::analog_input_period, 0xC8, true},
    {"MT 25: C9h", "", mt, object::analog_input_period, 0xC9, false},
    {"MT 50: 31h", "", mt, object::tpdo1_event_timer, 0x31, false},
    {"MT 50: 32h", "", mt, object::tpdo1_event_timer, 0x32, true},
    {"si-family 2003h/3: 0Ah", "", per, object::backlight_colour, 0x0A, false},
    {"si-family 2003h/3: 09h", "", per, object::backlight_colour, 0x09, true},
};
constexpr bool range_holds(const range_row& r) {
    const auto row = find_row(r.dict, r.id);
    return row && row->in_range(r.value) == r.in;
}
static_assert(
    powerkey_tests::all_rows_pass<first_failing(range_rows, range_holds), std::size(range_rows)>);

// The range of every writable row of a kind with a fixed range, in every dictionary: levels
// 00h..3Fh, colours 01h..09h (keep, 00h, only in the PDO), node ids 01h..7Fh (15h at delivery),
// flags 0..1; the default in range. A number is 1, 2 or 4 bytes (the expedited sizes).
constexpr bool ranges_hold(dictionary d) {
    for (const auto& r : rows_of(d)) {
        const auto k = info(r.id).kind;
        if (k == value_kind::number && r.size != 1 && r.size != 2 && r.size != 4) return false;
        if (!r.writable()) continue;
        if (k == value_kind::brightness &&
            !(r.min == 0 && r.max == 0x3F && !r.in_range(0x40) && r.in_range(r.initial)))
            return false;
        if (k == value_kind::colour && !(r.min == 1 && r.max == 9 && !r.in_range(0) &&
                                         !r.in_range(10) && r.in_range(r.initial)))
            return false;
        if (k == value_kind::node && !(r.min == 1 && r.max == 0x7F && !r.in_range(0) &&
                                       !r.in_range(0x80) && r.initial == 0x15))
            return false;
        if (k == value_kind::flag && !(r.min == 0 && r.max == 1 && !r.in_range(2))) return false;
    }
    return true;
}
static_assert(ranges_hold(pk) && ranges_hold(li) && ranges_hold(packed) && ranges_hold(mt) &&
              ranges_hold(per));

// Every row of every dictionary is of an object with a name and a kind (none only for 1001h,
// which the keypads abort: PK1000 31); every object is in some dictionary; every model's
// dictionary is a named one with rows.
constexpr bool every_row_named_and_typed(dictionary d) {
    const auto rows = rows_of(d);
    if (rows.empty() || !is_named(d)) return false;
    for (const auto& r : rows) {
        if (to_string(r.id).empty() || to_string(info(r.id).kind).empty()) return false;
        if (info(r.id).kind == value_kind::none && r.id != object::error_register) return false;
    }
    return true;
}
constexpr bool every_object_somewhere() {
    for (const object o : enum_values<object>()) {
        bool somewhere = false;
        for (const dictionary d : all_dictionaries) somewhere = somewhere || find_row(d, o);
        if (!somewhere) return false;
    }
    for (const model m : enum_values<model>())
        if (!every_row_named_and_typed(info(m)->dictionary)) return false;
    return std::size(all_dictionaries) == dictionary_count;
}
static_assert(every_object_somewhere());

// A value the optimiser cannot see through, so that the builders below run at run time.
template <class T>
T opaque(T v) {
    volatile T keep = v;
    return keep;
}

bool same_row(const object_row& a, const object_row& b) {
    return a.id == b.id && a.address == b.address && a.size == b.size && a.access == b.access &&
           a.min == b.min && a.max == b.max && a.also == b.also && a.initial == b.initial;
}

template <std::size_t N, class Own, class Shared>
void check_join(const std::array<object_row, N>& built, const Own& own, const Shared& shared) {
    REQUIRE(detail::joined_size(own, shared) == N);
    const auto again = detail::join_rows<N>(own, shared);
    for (std::size_t i = 0; i < N; ++i) {
        CAPTURE(i);
        CHECK(same_row(again[i], built[i]));
    }
    // Own rows first, in their order; then every shared row that no own row replaces.
    for (std::size_t i = 0; i < std::size(own); ++i) CHECK(same_row(built[i], own[i]));
    std::size_t replaced = 0;
    for (const auto& c : shared) replaced += detail::replaced(own, c) ? 1u : 0u;
    CHECK(std::size(own) + std::size(shared) - replaced == N);
}
}  // namespace

TEST_CASE("dictionary rows pinned from the manuals, found by address and by object") {
    powerkey_tests::check_rows(dict_rows, found_both_ways);
}

TEST_CASE("what each dictionary lacks is not found, by address or by object") {
    powerkey_tests::check_rows(absent_rows, absent);
}

TEST_CASE("access and ranges of the rows, and the range rules of every dictionary") {
    powerkey_tests::check_rows(access_rows, access_holds);
    powerkey_tests::check_rows(range_rows, range_holds);
    for (const auto d : all_dictionaries) {
        CAPTURE(std::string(to_string(d)));
        CHECK(ranges_hold(d));
    }
}

TEST_CASE("every row is of a named object with a kind; every object and model has a dictionary") {
    for (const auto d : all_dictionaries) {
        CAPTURE(std::string(to_string(d)));
        CHECK(every_row_named_and_typed(d));
    }
    CHECK(every_object_somewhere());
}

TEST_CASE("the PK1000 and SI dictionaries are their own rows, then the shared ones not replaced") {
    check_join(detail::pk1000_rows, detail::pk1000_own_rows, detail::pk_shared_rows);
    check_join(detail::si_common_rows, detail::si_common_own_rows, detail::pk_shared_rows);
    check_join(detail::si_packed_rows, detail::si_packed_own_rows, detail::si_common_rows);
    check_join(detail::si_mt_rows, detail::si_mt_own_rows, detail::si_common_rows);
    check_join(detail::si_per_colour_rows, detail::si_per_colour_own_rows, detail::si_common_rows);
    // The PKP-3500-MT replaces shared rows with its own (docs/models.md): the TPDO1 event timer.
    CHECK(detail::replaced(detail::si_mt_own_rows,
                           *find_row(dictionary::si_mt, object::tpdo1_event_timer)));
    CHECK(!detail::replaced(detail::si_mt_own_rows, *find_row(dictionary::si_mt, object::keys)));
}

TEST_CASE("every dictionary is well formed: one row per object and per address, min <= max") {
    for (const auto d : enum_values<dictionary>()) {
        CAPTURE(to_string(d));
        CHECK(detail::rows_well_formed(rows_of(opaque(d))));
    }
    object_row twice[] = {rows_of(dictionary::pk1000)[0], rows_of(dictionary::pk1000)[0]};
    CHECK(!detail::rows_well_formed(twice));
    object_row upside_down[] = {rows_of(dictionary::pk1000)[0]};
    upside_down[0].min = 5;
    upside_down[0].max = 4;
    CHECK(!detail::rows_well_formed(upside_down));
}

// --- every range at both ends and one step outside, through the codec ------------------------
// Walked from the rows themselves, for every model and every row of its dictionary whose kind is
// one number checked against the row (number, flag, brightness, colour, baud, show, node, period;
// value_kinds.hpp) and for the period of 1016h: min - 1, min, max, max + 1 and `also` with its
// neighbours, each written (600h) and read back (580h). The row's own answer (in_range, and 0 for
// a period: off) decides: accepted as that object and value, or refused with value_out_of_range.
// An access the row lacks is unknown_command; any other size is size_mismatch; a bit past the
// size is reserved_not_zero. A new row is walked without a new line here.
namespace {
constexpr canopen::node_id walk_node = canopen::default_node_id;

constexpr bool one_number(value_kind k) {
    return k == value_kind::number || k == value_kind::flag || k == value_kind::brightness ||
           k == value_kind::colour || k == value_kind::baud || k == value_kind::show ||
           k == value_kind::node || k == value_kind::period;
}
constexpr std::uint32_t largest_of(std::uint8_t size) {
    return size >= 4 ? 0xFFFF'FFFFu : (std::uint32_t{1} << (8 * size)) - 1;
}
// The values to try: each end of the range, one step outside each, `also` and its neighbours,
// and 0; those the row's size can carry.
std::vector<std::uint32_t> boundary_values(const object_row& r) {
    std::vector<std::uint32_t> v = {0, r.min, r.max};
    if (r.min > 0) v.push_back(r.min - 1);
    if (r.max < 0xFFFF'FFFFu) v.push_back(r.max + 1);
    if (r.min < r.max) v.push_back(r.min + 1);
    if (r.also != any) {
        v.push_back(r.also);
        v.push_back(r.also - 1);
        if (r.also < 0xFFFF'FFFFu) v.push_back(r.also + 1);
    }
    std::vector<std::uint32_t> fit;
    for (const auto x : v)
        if (x <= largest_of(r.size)) fit.push_back(x);
    return fit;
}

// What decode must answer for `data` in a write (or a read reply) of row r: the object and raw
// value, or the error.
struct answer_is {
    bool accepted;
    errc error;
};
template <class M>
bool decodes_as(const result<message>& got, const object_row& r, std::uint32_t data,
                const answer_is& want) {
    if (!want.accepted) return !got && got.error() == want.error;
    if (!got) return false;
    const auto* m = std::get_if<M>(&*got);
    return m != nullptr && m->object == r.id && m->value.raw == data;
}
void walk_value(model m, const object_row& r, std::uint32_t data, answer_is want) {
    CAPTURE(data);
    for (const bool write : {true, false}) {
        CAPTURE(write);
        const bool allowed = write ? r.writable() : r.readable();
        const auto got =
            decode(powerkey_tests::expedited_frame(walk_node, r.address, r.size, data, write),
                   walk_node, m);
        const answer_is w = allowed ? want : answer_is{false, errc::unknown_command};
        if (write)
            CHECK(decodes_as<sdo_write>(got, r, data, w));
        else
            CHECK(decodes_as<sdo_read_reply>(got, r, data, w));
    }
}
}  // namespace

TEST_CASE("every row's range at both ends and one step outside, in every model, both ways") {
    std::size_t rows = 0, values = 0;
    for (const model m : enum_values<model>()) {
        const auto d = info(m)->dictionary;
        for (const object_row& r : rows_of(d)) {
            const value_kind k = info(r.id).kind;
            CAPTURE(std::string(to_string(m)));
            CAPTURE(std::string(to_string(r.id)));
            if (r.size == 0) continue;  // strings and the per-colour planes: no range
            if (one_number(k)) {
                ++rows;
                for (const auto v : boundary_values(r)) {
                    ++values;
                    const bool in = r.in_range(v) || (k == value_kind::period && v == 0);
                    walk_value(m, r, v, {in, errc::value_out_of_range});
                }
            } else if (k == value_kind::consumer_heartbeat) {
                // 1016h sub 1: the period (bits 0..15) off or within the row's range, the producer
                // (bits 16..23) a node id (PK1000 28).
                ++rows;
                for (const std::uint32_t producer : {0x00u, 0x01u, 0x7Fu, 0x80u}) {
                    for (const std::uint32_t t : {0u, r.min - 1, r.min, r.min + 1, 0xFFFFu}) {
                        const bool in = producer >= 1 && producer <= 0x7F &&
                                        (t == 0 || (t >= r.min && t <= r.max));
                        walk_value(m, r, producer << 16 | t, {in, errc::value_out_of_range});
                    }
                }
            } else {
                continue;
            }
            // The object's size only, and nothing past it.
            const std::uint32_t valid = r.in_range(r.initial) ? r.initial : r.min;
            for (const std::uint8_t other : {std::uint8_t{1}, std::uint8_t{2}, std::uint8_t{4}}) {
                if (other == r.size) continue;
                CAPTURE(int{other});
                if (r.writable())
                    CHECK(decode(powerkey_tests::expedited_frame(walk_node, r.address, other,
                                                                 valid & largest_of(other), true),
                                 walk_node, m) == errc::size_mismatch);
                if (r.readable())
                    CHECK(decode(powerkey_tests::expedited_frame(walk_node, r.address, other,
                                                                 valid & largest_of(other), false),
                                 walk_node, m) == errc::size_mismatch);
            }
            for (unsigned bit = 8u * r.size; bit < 32; ++bit) {
                CAPTURE(bit);
                walk_value(m, r, valid | (1u << bit), {false, errc::reserved_not_zero});
            }
        }
    }
    // The walk reached rows of every kind above in every model (a table that lost its ranges
    // would walk nothing).
    CHECK(rows >= 100);
    CHECK(values >= 400);
}
