// The PK1000 manual's example frames (PK1000_CANopen_UM_rev1.13), one row each: the section, the
// frame as printed (candump form), the keypad's node id and the decoded meaning. Shared by the
// doctest suite, the freestanding check, and the tools that want sample logs and seed corpora.
// Rows marked E-PK-n are errata (docs/errata.md): `rows` holds the frames that decode, with the
// meaning the library gives them; `bad_rows` holds printed frames the library rejects, each with
// its corrected frame in `rows`. Where the manual prints a placeholder (the tick timer "XX" of
// the key-state PDO) the row uses 2Ah.
#ifndef POWERKEY_TESTS_PK1000_ROWS_HPP
#define POWERKEY_TESTS_PK1000_ROWS_HPP

#include <powerkey/pk1000/profile.hpp>

#include <string_view>

namespace pk1000_rows {

using namespace powerkey;
using namespace powerkey::pk1000;
// Other profiles and the any-keypad decoder also name a `message`; this one is the PK1000's.
using message = powerkey::pk1000::message;
using canopen::nmt_command;
using canopen::nmt_state;

struct row {
    std::string_view section;
    std::string_view frame;
    message expected;
    canopen::node_id node = canopen::default_node_id;
};

struct bad_row {
    std::string_view section;
    std::string_view frame;
    errc error;
    canopen::node_id node = canopen::default_node_id;
};

constexpr message rd(entry e) { return read_request{e}; }
constexpr message ack(entry e) { return set_ack{e}; }
template <class V>
constexpr message set(V v) {
    return set_request<V>{v};
}
template <class V>
constexpr message reply(V v) {
    return value_reply<V>{v};
}
constexpr message nmt(nmt_command c) { return canopen::nmt_message{c, 0x15}; }
constexpr message hb(nmt_state s) { return canopen::heartbeat_message{s}; }
constexpr message sync() { return canopen::sync_message{}; }
constexpr message keys(key_set k) { return key_state{k, 0x2A}; }
constexpr message on(led_set r, led_set g) { return led_on{r, g}; }
constexpr message blink(led_set r, led_set g) { return led_blink{r, g}; }
constexpr led_on_value on_reg(led_colour c, led_set s) { return {{c, s}}; }
constexpr led_blink_value blink_reg(led_colour c, led_set s) { return {{c, s}}; }
constexpr brightness_value level(level_setting s, std::uint8_t v) {
    return {s, brightness::make(v).value()};
}
constexpr message seg_req(bool toggle) { return canopen::sdo_segment_request{toggle}; }
constexpr message seg(bool toggle, std::uint8_t unused, bool last,
                      std::array<std::uint8_t, 7> bytes) {
    return canopen::sdo_segment_response{toggle, canopen::segment_unused::make(unused).value(),
                                         last, bytes};
}
constexpr message initiate(std::uint16_t index, std::uint32_t size) {
    return canopen::sdo_upload_initiate_response{{index, 0}, true, size};
}
constexpr message count(record r, std::uint8_t n) { return reply(subindex_count_value{r, n}); }
constexpr message cob(pdo p, std::uint16_t id) {
    return reply(pdo_cob_id_value{p, false, true, can::standard_id::make(id).value()});
}
constexpr message rpdo_type(rpdo p) { return reply(rpdo_transmission_value{p, true, {}}); }
constexpr message mapping(mapping_entry e, std::uint16_t index, std::uint8_t sub,
                          std::uint8_t bits) {
    return reply(pdo_mapping_value{e, index, sub, bits});
}

using L = led_colour;
using S = level_setting;

inline constexpr row rows[] = {
    // --- NMT, boot-up, SYNC -------------------------------------------------------------------
    {"4", "000#0115", nmt(nmt_command::start)},
    {"5", "000#8015", nmt(nmt_command::enter_pre_operational)},
    {"6", "000#8115", nmt(nmt_command::reset_node)},
    {"7", "000#0215", nmt(nmt_command::stop)},
    {"8", "715#00", hb(nmt_state::boot_up)},
    {"10", "080#", sync()},
    // --- 11 key state PDO (tick XX = 2Ah) ------------------------------------------------------
    {"11", "195#000000002A", keys({})},
    {"11", "195#010000002A", keys({1})},
    {"11", "195#080000002A", keys({4})},
    {"11", "195#090000002A", keys({1, 4})},
    {"11", "195#000100002A", keys({9})},
    {"11", "195#000200002A", keys({10})},
    // --- 12 LED on PDO
    // -----------------------------------------------------------------------------
    {"12", "215#0000000000000000", on({}, {})},
    {"12", "215#0100000000000000", on({1}, {})},
    {"12", "215#0500000000000000", on({1, 3}, {})},
    {"12", "215#0000000000200000", on({}, {14})},
    {"12", "215#0000010000000008", on({17}, {28})},
    {"12 E-PK-1 corrected", "215#0102040880402000", on({1, 10, 19, 28}, {8, 15, 22})},
    // --- 13 LED blink PDO
    // --------------------------------------------------------------------------
    {"13", "315#0000000000000000", blink({}, {})},
    {"13", "315#0200000000000000", blink({2}, {})},
    {"13", "315#0500000000000000", blink({1, 3}, {})},
    {"13", "315#0000000000200000", blink({}, {14})},
    {"13", "315#0000010000000008", blink({17}, {28})},
    {"13", "315#0240800820100401", blink({2, 15, 24, 28}, {6, 13, 19, 25})},
    {"13", "315#FFFFFF0FFFFFFF0F",
     blink({1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12, 13, 14,
            15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28},
           {1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12, 13, 14,
            15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28})},
    {"13", "215#FFFFFF0F00000000",
     on({1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12, 13, 14,
         15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28},
        {})},
    // --- 14, 15 brightness and backlight PDOs ----------------------------------------------------
    {"14", "415#0800000000000000", led_brightness{8}},
    {"14", "415#1000000000000000", led_brightness{0x10}},
    {"15", "515#0000000000000000", backlight{0, backlight_pdo_colour::keep}},
    {"15", "515#2003000000000000", backlight{0x20, backlight_pdo_colour::blue}},
    // --- 16 2000h key states
    // -----------------------------------------------------------------------
    {"16", "615#4000200100000000", rd(entry::keys)},
    {"16", "595#4B00200100000000", reply(keys_value{{}})},
    {"16", "595#4B00200101000000", reply(keys_value{{1}})},
    {"16", "595#4B00200102000000", reply(keys_value{{2}})},
    {"16", "595#4B00200104000000", reply(keys_value{{3}})},
    {"16", "595#4B00200103000000", reply(keys_value{{1, 2}})},
    {"16", "595#4B00200121000000", reply(keys_value{{1, 6}})},
    {"16", "595#4B00200188010000", reply(keys_value{{4, 8, 9}})},
    {"16", "595#4B002001FF030000", reply(keys_value{{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}})},
    // --- 17 2001h LED on register
    // ------------------------------------------------------------------
    {"17a", "615#2301200104000000", set(on_reg(L::red, {3}))},
    {"17a", "595#6001200100000000", ack(entry::led_on_red)},
    {"17a", "615#2301200200200000", set(on_reg(L::green, {14}))},
    {"17a", "595#6001200200000000", ack(entry::led_on_green)},
    {"17b", "615#4001200100000000", rd(entry::led_on_red)},
    {"17b", "595#4301200108000000", reply(on_reg(L::red, {4}))},
    {"17b", "615#4001200200000000", rd(entry::led_on_green)},
    {"17b", "595#4301200200020000", reply(on_reg(L::green, {10}))},
    // --- 18 2002h LED blink register
    // ---------------------------------------------------------------
    {"18a", "615#2302200104000000", set(blink_reg(L::red, {3}))},
    {"18a", "595#6002200100000000", ack(entry::led_blink_red)},
    {"18a", "615#2302200200008000", set(blink_reg(L::green, {24}))},
    {"18a", "595#6002200200000000", ack(entry::led_blink_green)},
    {"18b", "615#4002200100000000", rd(entry::led_blink_red)},
    {"18b", "595#4302200108000000", reply(blink_reg(L::red, {4}))},
    {"18b", "615#4002200200000000", rd(entry::led_blink_green)},
    {"18b", "595#4302200200010000", reply(blink_reg(L::green, {9}))},
    // --- 19 2003h brightness and colours
    // ----------------------------------------------------------
    {"19a", "615#2F03200109000000", set(level(S::led, 9))},
    {"19a", "595#6003200100000000", ack(entry::led_brightness)},
    {"19a", "615#4003200100000000", rd(entry::led_brightness)},
    {"19a", "595#4F03200109000000", reply(level(S::led, 9))},
    {"19b", "615#2F0320020D000000", set(level(S::backlight, 0x0D))},
    {"19b", "595#6003200200000000", ack(entry::backlight_brightness)},
    {"19b", "615#4003200200000000", rd(entry::backlight_brightness)},
    {"19b", "595#4F0320020D000000", reply(level(S::backlight, 0x0D))},
    {"19c", "615#2F03200305000000",
     set(colour_value{colour_setting::current, backlight_colour::cyan})},
    {"19c", "595#6003200300000000", ack(entry::backlight_colour)},
    {"19c", "615#4003200300000000", rd(entry::backlight_colour)},
    {"19c E-PK-2", "595#4F03200304000000",
     reply(colour_value{colour_setting::current, backlight_colour::yellow})},
    {"19d", "615#2F03200406000000",
     set(colour_value{colour_setting::power_on, backlight_colour::violet})},
    {"19d", "595#6003200400000000", ack(entry::default_backlight_colour)},
    {"19d", "615#4003200400000000", rd(entry::default_backlight_colour)},
    {"19d", "595#4F03200406000000",
     reply(colour_value{colour_setting::power_on, backlight_colour::violet})},
    {"19e", "615#2F03200513000000", set(level(S::default_led, 0x13))},
    {"19e", "595#6003200500000000", ack(entry::default_led_brightness)},
    {"19e", "615#4003200500000000", rd(entry::default_led_brightness)},
    {"19e", "595#4F03200513000000", reply(level(S::default_led, 0x13))},
    {"19f E-PK-3 corrected", "615#2F03200616000000", set(level(S::default_backlight, 0x16))},
    {"19f", "595#6003200600000000", ack(entry::default_backlight_brightness)},
    {"19f", "615#4003200600000000", rd(entry::default_backlight_brightness)},
    {"19f E-PK-3 corrected", "595#4F03200616000000", reply(level(S::default_backlight, 0x16))},
    // --- 20..27 settings
    // ---------------------------------------------------------------------------
    {"20", "615#2F10200004000000", set(baud_rate_value{baud_rate::kbit_125})},
    {"20", "595#6010200000000000", ack(entry::baud_rate)},
    {"20", "615#4010200000000000", rd(entry::baud_rate)},
    {"20", "595#4F10200004000000", reply(baud_rate_value{baud_rate::kbit_125})},
    {"21", "615#2F11200001000000", set(flag_value{flag::boot_up, true})},
    {"21", "595#6011200000000000", ack(entry::boot_up)},
    {"21", "615#4011200000000000", rd(entry::boot_up)},
    {"21", "595#4F11200001000000", reply(flag_value{flag::boot_up, true})},
    {"22", "615#2F12200001000000", set(flag_value{flag::active_on_startup, true})},
    {"22", "595#6012200000000000", ack(entry::active_on_startup)},
    {"22", "615#4012200000000000", rd(entry::active_on_startup)},
    {"22", "595#4F12200000000000", reply(flag_value{flag::active_on_startup, false})},
    {"23", "615#2F1320003A000000", set(node_id_value{0x3A})},
    {"23", "5BA#6013200000000000", ack(entry::node_id), 0x3A},
    {"23", "63A#4013200000000000", rd(entry::node_id), 0x3A},
    {"23", "5BA#4F1320003A000000", reply(node_id_value{0x3A}), 0x3A},
    {"24", "615#2F14200002000000", set(startup_show_value{startup_show::fast_flash})},
    {"24", "595#6014200000000000", ack(entry::startup_show)},
    {"24", "615#4014200000000000", rd(entry::startup_show)},
    {"24", "595#4F14200002000000", reply(startup_show_value{startup_show::fast_flash})},
    {"25", "615#2F15200000000000", set(flag_value{flag::led_power, false})},
    {"25", "595#6015200000000000", ack(entry::led_power)},
    {"26", "615#2F00210001000000", set(flag_value{flag::demo_mode, true})},
    {"26", "595#6000210000000000", ack(entry::demo_mode)},
    {"27", "615#2BFF200200000000", set(flag_value{flag::rs485, false})},
    {"27", "595#60FF200200000000", ack(entry::bus_rs485)},
    // --- 28, 29 heartbeat
    // ----------------------------------------------------------------------------
    {"28", "615#4016100000000000", rd(entry::consumer_heartbeat_count)},
    {"28", "595#4F16100001000000", count(record::consumer_heartbeat, 1)},
    {"28", "615#2316100164007E00", set(consumer_heartbeat_value{true, 100, 0x7E})},
    {"28", "595#6016100100000000", ack(entry::consumer_heartbeat)},
    {"28", "615#23161001F4010100", set(consumer_heartbeat_value{true, 500, 0x01})},
    {"28", "595#6016100100000000", ack(entry::consumer_heartbeat)},
    {"28", "615#4016100100000000", rd(entry::consumer_heartbeat)},
    {"28", "595#43161001F4010100", reply(consumer_heartbeat_value{true, 500, 0x01})},
    {"29", "615#4017100000000000", rd(entry::producer_heartbeat)},
    {"29", "595#4B17100064000000", reply(producer_heartbeat_value{true, 100})},
    {"29", "615#2B17100000000000", set(producer_heartbeat_value{false, {}})},
    {"29", "595#6017100000000000", ack(entry::producer_heartbeat)},
    {"29", "615#2B17100032000000", set(producer_heartbeat_value{true, 50})},
    {"29", "595#6017100000000000", ack(entry::producer_heartbeat)},
    {"29", "615#2B171000F4010000", set(producer_heartbeat_value{true, 500})},
    {"29", "595#6017100000000000", ack(entry::producer_heartbeat)},
    {"29", "715#00", hb(nmt_state::boot_up)},
    {"29", "715#7F", hb(nmt_state::pre_operational)},
    {"29", "000#0115", nmt(nmt_command::start)},
    {"29", "715#05", hb(nmt_state::operational)},
    // --- 30..37 identification and restore -----------------------------------------------------
    {"30", "615#4000100000000000", rd(entry::device_type)},
    {"30 E-PK-6 E-PK-7", "595#4300100091010B00",
     reply(device_type_value{0x0191, true, true, false, true})},
    // 31: not in the manual's examples; the read a host may send and the CiA 301 abort
    // ("object does not exist") it receives.
    {"31", "615#4001100000000000", rd(entry::error_register)},
    {"31", "595#8001100000000206",
     canopen::sdo_abort{{0x1001, 0}, canopen::sdo_abort_code::object_does_not_exist}},
    {"32", "615#4008100000000000", rd(entry::device_name)},
    {"32", "595#410810000B000000", initiate(0x1008, 11)},
    {"32", "615#6000000000000000", seg_req(false)},
    {"32", "595#00426C696E6B4D61", seg(false, 0, false, {'B', 'l', 'i', 'n', 'k', 'M', 'a'})},
    {"32", "615#7000000000000000", seg_req(true)},
    {"32", "595#1772696E65000000", seg(true, 3, true, {'r', 'i', 'n', 'e', 0, 0, 0})},
    {"33", "615#4009100000000000", rd(entry::hardware_version)},
    {"33", "595#43091000565F3033",
     reply(string_value{string_object::hardware_version, 4, {'V', '_', '0', '3'}})},
    {"34", "615#400A100000000000", rd(entry::firmware_version)},
    {"34", "595#430A100056322E38",
     reply(string_value{string_object::firmware_version, 4, {'V', '2', '.', '8'}})},
    {"35", "615#400B100000000000", rd(entry::model_id)},
    {"35", "595#410B100007000000", initiate(0x100B, 7)},
    {"35", "615#6000000000000000", seg_req(false)},
    {"35", "595#01504B3130303000", seg(false, 0, true, {'P', 'K', '1', '0', '0', '0', 0})},
    {"36", "615#4011100000000000", rd(entry::restore_count)},
    {"36", "595#4F11100001000000", count(record::restore, 1)},
    {"36", "615#231110016C6F6164", set(restore_defaults{})},
    {"36 E-PK-4", "595#4311100100000000", reply(restore_capability{0})},
    {"37", "615#4018100000000000", rd(entry::identity_count)},
    {"37", "595#4F18100004000000", count(record::identity, 4)},
    {"37", "615#4018100100000000", rd(entry::vendor_id)},
    {"37", "595#43181001E2030000", reply(identity_value{identity_item::vendor_id, 0x3E2})},
    // --- 38..41 RPDO communication parameters -------------------------------------------------
    {"38", "615#4000140000000000", rd(entry::rpdo1_count)},
    {"38", "595#4F00140002000000", count(record::rpdo1, 2)},
    {"38", "615#4000140100000000", rd(entry::rpdo1_cob_id)},
    {"38", "595#4300140115020040", cob(pdo::rpdo1, 0x215)},
    {"38", "615#4000140200000000", rd(entry::rpdo1_transmission)},
    {"38", "595#4F001402FE000000", rpdo_type(rpdo::rpdo1)},
    {"38", "615#2F00140201000000", set(rpdo_transmission_value{rpdo::rpdo1, false, 1})},
    {"38", "595#6000140200000000", ack(entry::rpdo1_transmission)},
    {"38", "080#", sync()},
    {"38", "215#0000000001000000", on({}, {1})},
    {"38", "080#", sync()},
    {"39", "615#4001140000000000", rd(entry::rpdo2_count)},
    {"39", "595#4F01140002000000", count(record::rpdo2, 2)},
    {"39", "615#4001140100000000", rd(entry::rpdo2_cob_id)},
    {"39", "595#4301140115030040", cob(pdo::rpdo2, 0x315)},
    {"39", "615#4001140200000000", rd(entry::rpdo2_transmission)},
    {"39", "595#4F011402FE000000", rpdo_type(rpdo::rpdo2)},
    {"39", "615#2F01140200000000", set(rpdo_transmission_value{rpdo::rpdo2, false, 0})},
    {"39", "595#6001140200000000", ack(entry::rpdo2_transmission)},
    {"39", "080#", sync()},
    {"39", "315#0100000000000000", blink({1}, {})},
    {"39", "080#", sync()},
    {"40", "615#4002140000000000", rd(entry::rpdo3_count)},
    {"40", "595#4F02140002000000", count(record::rpdo3, 2)},
    {"40", "615#4002140100000000", rd(entry::rpdo3_cob_id)},
    {"40", "595#4302140115040040", cob(pdo::rpdo3, 0x415)},
    {"40", "615#4002140200000000", rd(entry::rpdo3_transmission)},
    {"40", "595#4F021402FE000000", rpdo_type(rpdo::rpdo3)},
    {"41", "615#4003140000000000", rd(entry::rpdo4_count)},
    {"41", "595#4F03140002000000", count(record::rpdo4, 2)},
    {"41", "615#4003140100000000", rd(entry::rpdo4_cob_id)},
    {"41", "595#4303140115050040", cob(pdo::rpdo4, 0x515)},
    {"41", "615#4003140200000000", rd(entry::rpdo4_transmission)},
    {"41", "595#4F031402FE000000", rpdo_type(rpdo::rpdo4)},
    // --- 42..45 RPDO mapping
    // ------------------------------------------------------------------------
    {"42", "615#4000160000000000", rd(entry::rpdo1_mapping_count)},
    {"42", "595#4F00160002000000", count(record::rpdo1_mapping, 2)},
    {"42", "615#4000160100000000", rd(entry::rpdo1_mapping_1)},
    {"42", "595#4300160120010120", mapping(mapping_entry::rpdo1_1, 0x2001, 1, 0x20)},
    {"42", "615#4000160200000000", rd(entry::rpdo1_mapping_2)},
    {"42", "595#4300160220020120", mapping(mapping_entry::rpdo1_2, 0x2001, 2, 0x20)},
    {"43", "615#4001160000000000", rd(entry::rpdo2_mapping_count)},
    {"43", "595#4F01160002000000", count(record::rpdo2_mapping, 2)},
    {"43", "615#4001160100000000", rd(entry::rpdo2_mapping_1)},
    {"43", "595#4301160120010220", mapping(mapping_entry::rpdo2_1, 0x2002, 1, 0x20)},
    {"43", "615#4001160200000000", rd(entry::rpdo2_mapping_2)},
    {"43 E-PK-5", "595#4301160120020220", mapping(mapping_entry::rpdo2_1, 0x2002, 2, 0x20)},
    {"44", "615#4002160000000000", rd(entry::rpdo3_mapping_count)},
    {"44", "595#4F02160001000000", count(record::rpdo3_mapping, 1)},
    {"44", "615#4002160100000000", rd(entry::rpdo3_mapping_1)},
    {"44", "595#4302160108010320", mapping(mapping_entry::rpdo3_1, 0x2003, 1, 0x08)},
    {"45", "615#4003160000000000", rd(entry::rpdo4_mapping_count)},
    {"45", "595#4F03160002000000", count(record::rpdo4_mapping, 2)},
    {"45", "615#4003160100000000", rd(entry::rpdo4_mapping_1)},
    {"45", "595#4303160108020320", mapping(mapping_entry::rpdo4_1, 0x2003, 2, 0x08)},
    {"45", "615#4003160200000000", rd(entry::rpdo4_mapping_2)},
    {"45", "595#4303160208030320", mapping(mapping_entry::rpdo4_2, 0x2003, 3, 0x08)},
    // --- 46 TPDO communication parameters -------------------------------------------------------
    {"46a", "615#4000180000000000", rd(entry::tpdo1_count)},
    {"46a", "595#4F00180005000000", count(record::tpdo1, 5)},
    {"46a", "615#4000180100000000", rd(entry::tpdo1_cob_id)},
    {"46a", "595#4300180195010040", cob(pdo::tpdo1, 0x195)},
    {"46a", "615#4000180200000000", rd(entry::tpdo1_transmission)},
    {"46a", "595#4F001802FE000000", reply(tpdo_transmission_value{})},
    {"46a", "615#4000180500000000", rd(entry::tpdo1_event_timer)},
    {"46a", "595#4B00180500000000", reply(event_timer_value{})},
    {"46a", "615#2F00180201000000", set(tpdo_transmission_value{false, 1})},
    {"46a", "595#6000180200000000", ack(entry::tpdo1_transmission)},
    {"46a", "080#", sync()},
    {"46a", "195#000000002A", keys({})},
    {"46a", "080#", sync()},
    {"46a", "195#010000002A", keys({1})},
    {"46b", "615#2B00180500000000", set(event_timer_value{})},
    {"46b", "595#6000180500000000", ack(entry::tpdo1_event_timer)},
    {"46b", "615#2B00180532000000", set(event_timer_value{true, 50})},
    {"46b", "595#6000180500000000", ack(entry::tpdo1_event_timer)},
    {"46b", "615#2B001805F4010000", set(event_timer_value{true, 500})},
    {"46b", "595#6000180500000000", ack(entry::tpdo1_event_timer)},
    // --- 47 TPDO mapping, 48 serial number string ------------------------------------------------
    {"47", "615#40001A0000000000", rd(entry::tpdo1_mapping_count)},
    {"47", "595#4F001A0001000000", count(record::tpdo1_mapping, 1)},
    {"47", "615#40001A0100000000", rd(entry::tpdo1_mapping_1)},
    {"47", "595#43001A0110010020", mapping(mapping_entry::tpdo1_1, 0x2000, 1, 0x10)},
    {"48", "615#4000220000000000", rd(entry::serial_string)},
    {"48", "595#4100220008000000", initiate(0x2200, 8)},
    {"48", "615#6000000000000000", seg_req(false)},
    {"48 E-CORE-1", "595#0046464646464646",
     seg(false, 0, false, {'F', 'F', 'F', 'F', 'F', 'F', 'F'})},
    {"48", "615#7000000000000000", seg_req(true)},
    {"48", "595#1D46000000000000", seg(true, 6, true, {'F', 0, 0, 0, 0, 0, 0})},
    // --- 49 protocol switch
    // ----------------------------------------------------------------------------
    {"49 E-PK-10 corrected", "615#2BFF200101000000", set(flag_value{flag::j1939, true})},
    {"49", "18EF2100#041B8000FFFFFFFF", j1939::switch_to_canopen{}},
};

// Printed frames the library refuses, each an erratum with its corrected frame in `rows`.
inline constexpr bad_row bad_rows[] = {
    // LED #29 does not exist: byte 7 bit 4 is reserved.
    {"12 E-PK-1", "215#0102040880402010", errc::reserved_not_zero},
    // Level printed in byte 5 of a one-byte (2Fh / 4Fh) transfer.
    {"19f E-PK-3", "615#2F03200600160000", errc::reserved_not_zero},
    {"19f E-PK-3", "595#4F03200600160000", errc::reserved_not_zero},
    // An SDO of five bytes: CiA 301 SDOs are eight.
    {"49 E-PK-10", "615#2BFF200101", errc::wrong_length},
};

}  // namespace pk1000_rows

#endif  // POWERKEY_TESTS_PK1000_ROWS_HPP
