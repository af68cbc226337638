// powerkey: the object dictionaries as data. One `object` enum names every entry of every keypad
// by its meaning (the same name wherever it appears: `led_brightness` is 2003h sub 1 on the
// PK1000 and 6201h sub 1 on the PKP); each object has one value kind, which decides its type and
// field names; and each dictionary is a table of rows: address, size, access, range, and the
// default value the manual gives. A keypad of a known dictionary is a row in models.hpp.
//
//   dictionary   keypads                            manual
//   pk1000       PK1000 (2000h.., J1939 switch)     PK1000_CANopen_UM_rev1.13, sections 16-49
//   pkp_li       PKP-2200/2400/2600 (6000h.., 6500h) PKP-2200-2400-LI_CANopen_UM_rev1.1, 13-32
#ifndef POWERKEY_KEYPAD_OBJECTS_HPP
#define POWERKEY_KEYPAD_OBJECTS_HPP

#include <powerkey/canopen/sdo.hpp>
#include <powerkey/detail/inline.hpp>
#include <powerkey/detail/lookup.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/keypad/values.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace powerkey {

// Every object of every dictionary, by meaning. The comments give the address per dictionary.
enum class object : std::uint8_t {
    // keys and LEDs
    keys,             // pk1000 2000h/1 (16), pkp_li 6000h (14)
    led_on,           // pkp_li 6001h (15): the whole map, the model's planes that fit 32 bits
    led_blink,        // pkp_li 6002h (16)
    led_on_red,       // pk1000 2001h/1 (17): one plane
    led_on_green,     // pk1000 2001h/2
    led_blink_red,    // pk1000 2002h/1 (18)
    led_blink_green,  // pk1000 2002h/2
    // brightness and backlight
    led_brightness,            // pk1000 2003h/1 (19 a), pkp_li 6201h/1 (30)
    backlight_level,           // pk1000 2003h/2 (19 b), pkp_li 6201h/2 (30)
    backlight_colour,          // pk1000 2003h/3 (19 c)
    default_backlight_colour,  // pk1000 2003h/4 (19 d)
    default_led_brightness,    // pk1000 2003h/5 (19 e)
    default_backlight_level,   // pk1000 2003h/6 (19 f)
    brightness_count,          // pkp_li 6201h/0
    // settings
    baud_rate,          // pk1000 2010h (20)
    boot_up,            // pk1000 2011h (21): send the boot-up message at power on
    active_on_startup,  // pk1000 2012h (22): operational at power on without NMT start
    node_id,            // pk1000 2013h (23)
    startup_show,       // pk1000 2014h (24)
    led_power,          // pk1000 2015h (25): LED supply; off = low power
    demo_mode,          // pk1000 2100h (26)
    protocol_j1939,     // pk1000 20FFh/1 (27, 49): 1 switches the keypad to J1939
    protocol_rs485,     // pk1000 20FFh/2 (27)
    command_module,     // pkp_li 6500h/1 (13): write only, commands.hpp
    // heartbeat
    consumer_heartbeat_count,  // pk1000 1016h/0 (28)
    consumer_heartbeat,        // pk1000 1016h/1
    heartbeat_time,            // pk1000 1017h (29), pkp_li 1017h (17): producer period
    // identification
    device_type,           // 1000h (pk1000 30, pkp_li 18)
    error_register,        // pk1000 1001h (31): not implemented, the keypad aborts a read
    device_name,           // 1008h string
    hardware_version,      // 1009h string
    software_version,      // 100Ah string
    model_name,            // 100Bh string
    serial_number_string,  // pk1000 2200h (48), pkp_li 6300h (31): string
    device_model,          // pkp_li 6100h/2 (29): string
    firmware_spec_count,   // pkp_li 6100h/0
    identity_count,        // 1018h/0
    vendor_id,             // 1018h/1
    product_code,          // pkp_li 1018h/2
    revision_number,       // pkp_li 1018h/3: byte 4 app, 5 com lib, 6 hw lib revision
    serial_number,         // pk1000 1018h/4, pkp_li 6100h/1
    firmware_checksum,     // pkp_li 1018h/4
    bootloader_present,    // pkp_li 6301h (32)
    key_led_count_count,   // pkp_li 6302h/0
    total_keys,            // pkp_li 6302h/1
    external_keys,         // pkp_li 6302h/2
    total_leds,            // pkp_li 6302h/3
    external_leds,         // pkp_li 6302h/4
    restore_count,         // pk1000 1011h/0 (36)
    restore_defaults,      // pk1000 1011h/1: write "load"; a read gives the restore flags
    // PDO communication and mapping parameters
    rpdo1_count,
    rpdo1_cob_id,
    rpdo1_transmission_type,
    rpdo1_inhibit_time,
    rpdo2_count,
    rpdo2_cob_id,
    rpdo2_transmission_type,
    rpdo2_inhibit_time,
    rpdo3_count,
    rpdo3_cob_id,
    rpdo3_transmission_type,
    rpdo4_count,
    rpdo4_cob_id,
    rpdo4_transmission_type,
    rpdo1_mapping_count,
    rpdo1_mapping_1,
    rpdo1_mapping_2,
    rpdo2_mapping_count,
    rpdo2_mapping_1,
    rpdo2_mapping_2,
    rpdo3_mapping_count,
    rpdo3_mapping_1,
    rpdo4_mapping_count,
    rpdo4_mapping_1,
    rpdo4_mapping_2,
    tpdo1_count,
    tpdo1_cob_id,
    tpdo1_transmission_type,
    tpdo1_inhibit_time,
    tpdo1_event_timer,
    tpdo1_mapping_count,
    tpdo1_mapping_1,
    // The SI family (docs/si-family.md): "2600SI n" is the PKP2600SI manual's section n, "MT n"
    // the PKP3500-MT manual's.
    led_on_blue,                 // 2001h/3 (MT 20 a): one plane
    led_blink_blue,              // 2002h/3 (MT 21 a)
    led_on_r1_12_g1_4,           // 2001h/1 (2600SI 17): bits 0..15 of the LED-on string
    led_on_g5_12,                // 2001h/2: bits 16..23
    led_on_b1_12,                // 2001h/3: bits 24..35
    led_blink_r1_12_g1_4,        // 2002h/1 (2600SI 18)
    led_blink_g5_12,             // 2002h/2
    led_blink_b1_12,             // 2002h/3
    led_on_encoder,              // 2001h/4 (MT 20 c): the encoder rings, LEDs 1..32
    led_blink_encoder,           // 2002h/4 (MT 21 c)
    encoder1_direction_counter,  // 2000h/2 (MT 19 b): bit 7 counterclockwise, bits 0..6 ticks
    encoder1_tick_counter,       // 2000h/3 (MT 19 c): read the count, write the start-up count
    encoder2_direction_counter,  // 2000h/4 (MT 19 d)
    encoder2_tick_counter,       // 2000h/5 (MT 19 e)
    encoder1_top_position,       // 2000h/6 (MT 19 f): 00h none, 02h..10h ticks
    encoder2_top_position,       // 2000h/7 (MT 19 g)
    digital_input_count,         // 2004h/0 (MT 23)
    digital_inputs,              // 2004h/1: bit 0 IN0 .. bit 3 IN3
    analog_input_count,          // 2005h/0 (MT 24)
    analog_input_0,              // 2005h/1: 00h..FFh = 0..5 V
    analog_input_1,              // 2005h/2
    analog_input_2,              // 2005h/3
    analog_input_3,              // 2005h/4
    analog_input_period,         // 2006h (MT 25): 08h..C8h x 10 ms
    rpdo1_mapping_3,
    rpdo2_mapping_3,
    tpdo2_count,  // 1801h (MT 51): encoder 1
    tpdo2_cob_id,
    tpdo2_transmission_type,
    tpdo2_event_timer,
    tpdo3_count,  // 1802h (MT 52): encoder 2
    tpdo3_cob_id,
    tpdo3_transmission_type,
    tpdo3_event_timer,
    tpdo4_count,  // 1803h (MT 53): analog inputs
    tpdo4_cob_id,
    tpdo4_transmission_type,
    tpdo2_mapping_count,  // 1A01h (MT 55)
    tpdo2_mapping_1,
    tpdo2_mapping_2,
    tpdo2_mapping_3,
    tpdo3_mapping_count,  // 1A02h (MT 56)
    tpdo3_mapping_1,
    tpdo3_mapping_2,
    tpdo3_mapping_3,
};

// What an object's value is: its C++ type and the field names it shows (messages.hpp).
enum class value_kind : std::uint8_t {
    // number..node first: the codec checks these seven with one range test (kind <= node).
    number,              // "value": an unsigned number (counts, identity words, times, types)
    flag,                // "enabled": 00h off, 01h on
    brightness,          // "level": 00h..3Fh
    colour,              // "colour": backlight_colour
    baud,                // "baud_rate": baud_rate
    show,                // "startup_show": startup_show
    node,                // "node_id": 01h..7Fh
    period,              // "period_ms": 0 = off, else the row's range
    keys,                // "keys": key bits 0..N-1
    led_plane,           // "red" / "green" / "blue": one plane of an LED map
    led_map,             // "red", "green", "blue": the planes of the model's rule that fit
    consumer_heartbeat,  // "period_ms", "producer": 1016h sub 1
    cob_id,              // "invalid", "no_rtr", "can_id": a PDO COB-ID (CiA 301 7.5.2.35)
    pdo_mapping,         // "index", "subindex", "bits": a PDO mapping entry
    device_type,         // "profile", "digital_input" ..: 1000h (CiA 401 I/O functionality)
    string,              // "size", "bytes": up to 4 bytes expedited, more by segments
    restore,             // "value": writes carry "load", reads the restore flags
    led_part,            // "red", "green", "blue": bits [offset, offset + width) of the LED string
    ring,                // "leds": the encoder ring LEDs 1..32
    direction_counter,   // "counterclockwise", "ticks": an encoder's ticks since its last TPDO
    none,                // no value: the keypad aborts a read (1001h)
    commands,            // the command module: commands.hpp
};

enum class access : std::uint8_t { read_only, write_only, read_write };

// The "load" signature of a restore (1011h sub 1, PK1000 section 36), little endian.
inline constexpr std::uint32_t load_signature = 0x6461'6F6C;

// The value kind of every object, and for an LED plane object the plane it holds.
struct object_kind {
    object id;
    value_kind kind;
    plane holds = plane::red;  // led_plane only
    std::uint8_t offset = 0;   // led_part: the first bit of the LED string it carries
    std::uint8_t width = 0;    // led_part: how many bits
};

namespace detail {
using vk = value_kind;
using obj = object;
inline constexpr object_kind object_kinds[] = {
    {obj::keys, vk::keys},
    {obj::led_on, vk::led_map},
    {obj::led_blink, vk::led_map},
    {obj::led_on_red, vk::led_plane, plane::red},
    {obj::led_on_green, vk::led_plane, plane::green},
    {obj::led_blink_red, vk::led_plane, plane::red},
    {obj::led_blink_green, vk::led_plane, plane::green},
    {obj::led_brightness, vk::brightness},
    {obj::backlight_level, vk::brightness},
    {obj::backlight_colour, vk::colour},
    {obj::default_backlight_colour, vk::colour},
    {obj::default_led_brightness, vk::brightness},
    {obj::default_backlight_level, vk::brightness},
    {obj::brightness_count, vk::number},
    {obj::baud_rate, vk::baud},
    {obj::boot_up, vk::flag},
    {obj::active_on_startup, vk::flag},
    {obj::node_id, vk::node},
    {obj::startup_show, vk::show},
    {obj::led_power, vk::flag},
    {obj::demo_mode, vk::flag},
    {obj::protocol_j1939, vk::flag},
    {obj::protocol_rs485, vk::flag},
    {obj::command_module, vk::commands},
    {obj::consumer_heartbeat_count, vk::number},
    {obj::consumer_heartbeat, vk::consumer_heartbeat},
    {obj::heartbeat_time, vk::period},
    {obj::device_type, vk::device_type},
    {obj::error_register, vk::none},
    {obj::device_name, vk::string},
    {obj::hardware_version, vk::string},
    {obj::software_version, vk::string},
    {obj::model_name, vk::string},
    {obj::serial_number_string, vk::string},
    {obj::device_model, vk::string},
    {obj::firmware_spec_count, vk::number},
    {obj::identity_count, vk::number},
    {obj::vendor_id, vk::number},
    {obj::product_code, vk::number},
    {obj::revision_number, vk::number},
    {obj::serial_number, vk::number},
    {obj::firmware_checksum, vk::number},
    {obj::bootloader_present, vk::number},
    {obj::key_led_count_count, vk::number},
    {obj::total_keys, vk::number},
    {obj::external_keys, vk::number},
    {obj::total_leds, vk::number},
    {obj::external_leds, vk::number},
    {obj::restore_count, vk::number},
    {obj::restore_defaults, vk::restore},
    {obj::rpdo1_count, vk::number},
    {obj::rpdo1_cob_id, vk::cob_id},
    {obj::rpdo1_transmission_type, vk::number},
    {obj::rpdo1_inhibit_time, vk::number},
    {obj::rpdo2_count, vk::number},
    {obj::rpdo2_cob_id, vk::cob_id},
    {obj::rpdo2_transmission_type, vk::number},
    {obj::rpdo2_inhibit_time, vk::number},
    {obj::rpdo3_count, vk::number},
    {obj::rpdo3_cob_id, vk::cob_id},
    {obj::rpdo3_transmission_type, vk::number},
    {obj::rpdo4_count, vk::number},
    {obj::rpdo4_cob_id, vk::cob_id},
    {obj::rpdo4_transmission_type, vk::number},
    {obj::rpdo1_mapping_count, vk::number},
    {obj::rpdo1_mapping_1, vk::pdo_mapping},
    {obj::rpdo1_mapping_2, vk::pdo_mapping},
    {obj::rpdo2_mapping_count, vk::number},
    {obj::rpdo2_mapping_1, vk::pdo_mapping},
    {obj::rpdo2_mapping_2, vk::pdo_mapping},
    {obj::rpdo3_mapping_count, vk::number},
    {obj::rpdo3_mapping_1, vk::pdo_mapping},
    {obj::rpdo4_mapping_count, vk::number},
    {obj::rpdo4_mapping_1, vk::pdo_mapping},
    {obj::rpdo4_mapping_2, vk::pdo_mapping},
    {obj::tpdo1_count, vk::number},
    {obj::tpdo1_cob_id, vk::cob_id},
    {obj::tpdo1_transmission_type, vk::number},
    {obj::tpdo1_inhibit_time, vk::number},
    {obj::tpdo1_event_timer, vk::period},
    {obj::tpdo1_mapping_count, vk::number},
    {obj::tpdo1_mapping_1, vk::pdo_mapping},
    {obj::led_on_blue, vk::led_plane, plane::blue},
    {obj::led_blink_blue, vk::led_plane, plane::blue},
    {obj::led_on_r1_12_g1_4, vk::led_part, plane::red, 0, 16},
    {obj::led_on_g5_12, vk::led_part, plane::red, 16, 8},
    {obj::led_on_b1_12, vk::led_part, plane::red, 24, 12},
    {obj::led_blink_r1_12_g1_4, vk::led_part, plane::red, 0, 16},
    {obj::led_blink_g5_12, vk::led_part, plane::red, 16, 8},
    {obj::led_blink_b1_12, vk::led_part, plane::red, 24, 12},
    {obj::led_on_encoder, vk::ring},
    {obj::led_blink_encoder, vk::ring},
    {obj::encoder1_direction_counter, vk::direction_counter},
    {obj::encoder1_tick_counter, vk::number},
    {obj::encoder2_direction_counter, vk::direction_counter},
    {obj::encoder2_tick_counter, vk::number},
    {obj::encoder1_top_position, vk::number},
    {obj::encoder2_top_position, vk::number},
    {obj::digital_input_count, vk::number},
    {obj::digital_inputs, vk::number},
    {obj::analog_input_count, vk::number},
    {obj::analog_input_0, vk::number},
    {obj::analog_input_1, vk::number},
    {obj::analog_input_2, vk::number},
    {obj::analog_input_3, vk::number},
    {obj::analog_input_period, vk::number},
    {obj::rpdo1_mapping_3, vk::pdo_mapping},
    {obj::rpdo2_mapping_3, vk::pdo_mapping},
    {obj::tpdo2_count, vk::number},
    {obj::tpdo2_cob_id, vk::cob_id},
    {obj::tpdo2_transmission_type, vk::number},
    {obj::tpdo2_event_timer, vk::period},
    {obj::tpdo3_count, vk::number},
    {obj::tpdo3_cob_id, vk::cob_id},
    {obj::tpdo3_transmission_type, vk::number},
    {obj::tpdo3_event_timer, vk::period},
    {obj::tpdo4_count, vk::number},
    {obj::tpdo4_cob_id, vk::cob_id},
    {obj::tpdo4_transmission_type, vk::number},
    {obj::tpdo2_mapping_count, vk::number},
    {obj::tpdo2_mapping_1, vk::pdo_mapping},
    {obj::tpdo2_mapping_2, vk::pdo_mapping},
    {obj::tpdo2_mapping_3, vk::pdo_mapping},
    {obj::tpdo3_mapping_count, vk::number},
    {obj::tpdo3_mapping_1, vk::pdo_mapping},
    {obj::tpdo3_mapping_2, vk::pdo_mapping},
    {obj::tpdo3_mapping_3, vk::pdo_mapping},
};
constexpr bool kinds_in_enum_order() noexcept {
    for (std::size_t i = 0; i < std::size(object_kinds); ++i)
        if (static_cast<std::size_t>(object_kinds[i].id) != i) return false;
    return true;
}
static_assert(kinds_in_enum_order());
static_assert(std::size(object_kinds) == static_cast<std::size_t>(object::tpdo3_mapping_3) + 1);
}  // namespace detail

inline constexpr std::size_t object_count = std::size(detail::object_kinds);

// The kind of an object's value; `none` for a value outside the enum.
[[nodiscard]] constexpr object_kind kind_of(object id) noexcept {
    const auto i = static_cast<std::size_t>(id);
    return i < object_count ? detail::object_kinds[i] : object_kind{id, value_kind::none};
}

// One entry of a dictionary.
struct object_row {
    object id;
    canopen::sdo_address address;
    // Expedited bytes: 1, 2 or 4; 0 for a string (1..4 expedited, or segmented) and for an LED
    // plane of the per-colour SI scheme (the model's stride / 8: 2 bytes with 16, 1 with 8).
    std::uint8_t size;
    powerkey::access access;
    std::uint32_t min = 0;  // valid values: min..max, or `also` (FEh event-driven, 0 = off ...)
    std::uint32_t max = 0xFFFF'FFFF;
    std::uint32_t also = 0xFFFF'FFFF;
    std::uint32_t initial = 0;  // the value the manual gives at delivery (for a number kind)

    [[nodiscard]] constexpr bool readable() const noexcept {
        return access != powerkey::access::write_only;
    }
    [[nodiscard]] constexpr bool writable() const noexcept {
        return access != powerkey::access::read_only;
    }
    // The row's range, for the kinds whose value is one number.
    [[nodiscard]] constexpr bool in_range(std::uint32_t v) const noexcept {
        return (v >= min && v <= max) || v == also;
    }
};

enum class dictionary : std::uint8_t {
    pk1000,         // PK1000
    pkp_li,         // PKP-2200/2400/2600 LI: 6000h.., command module 6500h
    si_packed,      // PKP-2600-SI: the PK1000's objects, 2001h/2002h cut from the RPDO string
    si_mt,          // PKP-3500-MT: per-colour planes, encoders, inputs
    si_per_colour,  // PKP-3500-SI, 2500-SI, 1500-LI, 2200/2300/2400-SI (partly inferred)
};

namespace detail {
constexpr auto ro = access::read_only;
constexpr auto rw = access::read_write;
constexpr auto wo = access::write_only;
constexpr std::uint32_t any = 0xFFFF'FFFF;
constexpr std::uint32_t none_else = 0xFFFF'FFFF;

// A dictionary written as its own rows and rows it shares with others: its own rows, then the
// shared rows that no own row replaces (an own row replaces the shared row of the same object).
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
// Writes the manuals show without a read (2100h, 20FFh, 1011h sub 1) are write-only here; the
// COB-IDs read back without the CiA 301 bits 30/31; 1017h takes 000Ah..FEFFh (both manuals).
// Each fact once: the rows the three SI dictionaries share (those of pk_shared_rows and these),
// then each one's own rows; an own row replaces the shared row of the same object.
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
inline constexpr object_row si_per_colour_own_rows[] = {
    {obj::led_on_red, {0x2001, 1}, 0, rw},      {obj::led_on_green, {0x2001, 2}, 0, rw},
    {obj::led_on_blue, {0x2001, 3}, 0, rw},     {obj::led_blink_red, {0x2002, 1}, 0, rw},
    {obj::led_blink_green, {0x2002, 2}, 0, rw}, {obj::led_blink_blue, {0x2002, 3}, 0, rw},
    {obj::rpdo1_mapping_1, {0x1600, 1}, 4, ro}, {obj::rpdo1_mapping_2, {0x1600, 2}, 4, ro},
    {obj::rpdo1_mapping_3, {0x1600, 3}, 4, ro}, {obj::rpdo2_mapping_1, {0x1601, 1}, 4, ro},
    {obj::rpdo2_mapping_2, {0x1601, 2}, 4, ro}, {obj::rpdo2_mapping_3, {0x1601, 3}, 4, ro},
};

inline constexpr auto si_packed_rows =
    join_rows<joined_size(si_packed_own_rows, si_common_rows)>(si_packed_own_rows, si_common_rows);
inline constexpr auto si_mt_rows =
    join_rows<joined_size(si_mt_own_rows, si_common_rows)>(si_mt_own_rows, si_common_rows);
inline constexpr auto si_per_colour_rows =
    join_rows<joined_size(si_per_colour_own_rows, si_common_rows)>(si_per_colour_own_rows,
                                                                   si_common_rows);
}  // namespace detail

// The rows of a dictionary: manual order for the PKP; for the PK1000 and the SI dictionaries each
// one's own rows, then the rows it shares (join_rows).
[[nodiscard]] constexpr std::span<const object_row> rows_of(dictionary d) noexcept {
    switch (d) {
        case dictionary::pkp_li: return detail::pkp_li_rows;
        case dictionary::si_packed: return detail::si_packed_rows;
        case dictionary::si_mt: return detail::si_mt_rows;
        case dictionary::si_per_colour: return detail::si_per_colour_rows;
        case dictionary::pk1000: break;
    }
    return detail::pk1000_rows;
}

namespace detail {
inline constexpr dictionary dictionaries[] = {dictionary::pk1000, dictionary::pkp_li,
                                              dictionary::si_packed, dictionary::si_mt,
                                              dictionary::si_per_colour};
inline constexpr std::size_t dictionary_count = std::size(dictionaries);

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
static_assert(rows_well_formed(pk1000_rows));
static_assert(rows_well_formed(pkp_li_rows));
static_assert(rows_well_formed(si_packed_rows));
static_assert(rows_well_formed(si_mt_rows));
static_assert(rows_well_formed(si_per_colour_rows));

// --- the codec's rows ---------------------------------------------------------------------------
// What the decoder needs of a row, in 8 bytes instead of object_row's 24, generated at compile
// time from the rows above: one table of the distinct codec rows of all dictionaries (the SI
// dictionaries share most of theirs, and most ranges repeat), one table of the distinct ranges,
// and per dictionary a hash table of row numbers. The full rows stay for rows_of and find_row
// (the virtual keypad, the tool): a firmware that only decodes links none of them.

// An SDO address as the frame carries it in bytes 1..3: index | sub-index << 16.
constexpr std::uint32_t wire_key(canopen::sdo_address a) noexcept {
    return a.index | (std::uint32_t{a.subindex} << 16);
}

// The values a number kind accepts: min..min + span, or `also` (a row's min, max - min, also).
struct value_range {
    std::uint32_t min = 0;
    std::uint32_t span = 0xFFFF'FFFF;
    std::uint32_t also = 0xFFFF'FFFF;
    [[nodiscard]] constexpr bool contains(std::uint32_t v) const noexcept {
        return v - min <= span || v == also;
    }
    friend constexpr bool operator==(const value_range&, const value_range&) noexcept = default;
};

struct codec_row {
    std::uint32_t key;  // the wire_key of the address
    object id;
    value_kind kind;
    // Bits 0..2 the size (object_row::size), bit 3 readable, bit 4 writable, bits 5..7 a
    // led_part's width in bits / 4.
    std::uint8_t flags;
    std::uint8_t a;  // the range (value_ranges); led_plane: the plane; led_part: its first bit

    [[nodiscard]] constexpr canopen::sdo_address address() const noexcept {
        return {static_cast<std::uint16_t>(key), static_cast<std::uint8_t>(key >> 16)};
    }
    [[nodiscard]] constexpr std::uint8_t size() const noexcept { return flags & 7; }
    [[nodiscard]] constexpr bool readable() const noexcept { return (flags & 8) != 0; }
    [[nodiscard]] constexpr bool writable() const noexcept { return (flags & 16) != 0; }
    [[nodiscard]] constexpr unsigned part_width() const noexcept { return (flags >> 5) * 4u; }
    [[nodiscard]] constexpr std::uint64_t packed() const noexcept {
        return key | std::uint64_t{static_cast<std::uint8_t>(id)} << 24 |
               std::uint64_t{static_cast<std::uint8_t>(kind)} << 32 | std::uint64_t{flags} << 40 |
               std::uint64_t{a} << 48;
    }
};

constexpr value_range range_of(const object_row& r) noexcept {
    return {r.min, r.max - r.min, r.also};
}

// Calls f(row) for every row of every dictionary.
template <class F>
constexpr void for_each_row(F f) noexcept {
    for (const dictionary d : dictionaries)
        for (const auto& r : rows_of(d)) f(r);
}

constexpr auto collect_ranges() noexcept {
    distinct_set<value_range, 64> s;
    for_each_row([&s](const object_row& r) { s.add(range_of(r)); });
    return s;
}
inline constexpr auto all_ranges = collect_ranges();
inline constexpr auto value_ranges = [] {
    std::array<value_range, all_ranges.size> t{};
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = all_ranges.items[i];
    return t;
}();

constexpr codec_row codec_row_of(const object_row& r) noexcept {
    const object_kind k = object_kinds[static_cast<std::size_t>(r.id)];
    codec_row c{
        wire_key(r.address), r.id, k.kind,
        static_cast<std::uint8_t>(r.size | (r.readable() ? 8 : 0) | (r.writable() ? 16 : 0)), 0};
    if (k.kind == value_kind::led_plane) {
        c.a = static_cast<std::uint8_t>(k.holds);
    } else if (k.kind == value_kind::led_part) {
        c.a = k.offset;
        c.flags = static_cast<std::uint8_t>(c.flags | (k.width / 4) << 5);
    } else {
        for (std::size_t i = 0; i < value_ranges.size(); ++i)
            if (value_ranges[i] == range_of(r)) c.a = static_cast<std::uint8_t>(i);
    }
    return c;
}
// A led_part's width fits the row: a multiple of 4 bits, at most 28.
constexpr bool part_widths_fit() noexcept {
    for (const auto& k : object_kinds)
        if (k.kind == value_kind::led_part && (k.width % 4 != 0 || k.width / 4 > 7)) return false;
    return true;
}
static_assert(part_widths_fit());

// The distinct codec rows, packed (a 64-bit compare each: clang counts constexpr steps); at most
// 254, so that a row number (1..) and the sentinel fit a byte.
using codec_row_set = distinct_set<std::uint64_t, 254>;
constexpr codec_row_set collect_codec_rows() noexcept {
    codec_row_set s;
    for_each_row([&s](const object_row& r) { s.add(codec_row_of(r).packed()); });
    return s;
}
inline constexpr codec_row_set all_codec_rows = collect_codec_rows();
// The codec rows, numbered from 1: row 0 is a sentinel whose key no address has (a wire key is 24
// bits), so that an empty hash slot (0) fails the lookup's key test like a wrong row, with no test
// of its own.
inline constexpr codec_row no_codec_row{0xFFFF'FFFF, object{}, value_kind::none, 0, 0};
inline constexpr auto codec_rows = [] {
    std::array<codec_row, all_codec_rows.size + 1> t{};
    t[0] = no_codec_row;
    for (std::size_t i = 0; i < all_codec_rows.size; ++i) {
        const auto v = all_codec_rows.items[i];
        t[i + 1] = {static_cast<std::uint32_t>(v) & 0xFF'FFFF, static_cast<object>(v >> 24),
                    static_cast<value_kind>(v >> 32), static_cast<std::uint8_t>(v >> 40),
                    static_cast<std::uint8_t>(v >> 48)};
    }
    return t;
}();
// The codec row number (1..) of a full row.
constexpr std::uint8_t codec_row_number(const object_row& r) noexcept {
    return static_cast<std::uint8_t>(all_codec_rows.find(codec_row_of(r).packed()) + 1);
}

// Per dictionary, a hash table of codec row numbers (0: empty) by address: open addressing
// over 256 slots, with one multiplier for all five dictionaries, the first candidate with which
// every address is found within two probes. All five tables in one array, dictionary d's at
// d * 256: a fixed size costs some slots (a dictionary has 44..101 rows) and saves the lookup
// reading a size and a place per dictionary.
inline constexpr unsigned slot_bits = 8;
inline constexpr std::size_t slots_per_dictionary = std::size_t{1} << slot_bits;
static_assert(static_cast<std::size_t>(dictionary::si_per_colour) + 1 == dictionary_count);

// The most probes any address of rows needs.
constexpr std::size_t max_probes(std::span<const object_row> rows,
                                 std::uint32_t multiplier) noexcept {
    std::array<bool, slots_per_dictionary> used{};
    std::size_t most = 0;
    for (const auto& r : rows) {
        std::size_t s = home_slot(wire_key(r.address), multiplier, 32 - slot_bits);
        std::size_t probes = 1;
        for (; used[s]; ++probes) s = (s + 1) % slots_per_dictionary;
        used[s] = true;
        most = probes > most ? probes : most;
    }
    return most;
}
constexpr std::uint32_t find_multiplier() noexcept {
    for (std::size_t t = 0; t < 4096; ++t) {
        bool fits = true;
        for (const dictionary d : dictionaries)
            fits = fits && max_probes(rows_of(d), hash_candidate(t)) <= 2;
        if (fits) return hash_candidate(t);
    }
    return 0;
}
inline constexpr std::uint32_t hash_multiplier = find_multiplier();
static_assert(hash_multiplier != 0, "no multiplier finds every address in two probes");

inline constexpr auto address_slots = [] {
    std::array<std::uint8_t, dictionary_count * slots_per_dictionary> t{};
    for (std::size_t d = 0; d < dictionary_count; ++d) {
        for (const auto& r : rows_of(dictionaries[d])) {
            std::size_t s = home_slot(wire_key(r.address), hash_multiplier, 32 - slot_bits);
            while (t[d * slots_per_dictionary + s] != 0) s = (s + 1) % slots_per_dictionary;
            t[d * slots_per_dictionary + s] = codec_row_number(r);
        }
    }
    return t;
}();

// Row s, whose key a 24-bit key matched: not the sentinel. Telling the compiler so (g++ and clang)
// drops the callers' `== 0` tests from the path of a known address (-3 instructions per SDO frame,
// docs/performance.md).
constexpr std::uint8_t matched_row(std::uint8_t s) noexcept {
    POWERKEY_DETAIL_ASSUME_NOT(s == 0);
    return s;
}

// The codec row number at wire address `key` (its low 24 bits, as wire_key makes it) in
// dictionary d, 0 when it has none.
// Two probes, unrolled: every address is found within two (find_multiplier). An empty slot is
// row 0, the sentinel no key matches; a key whose home slot is empty is nowhere (it would have
// been put there: no row is ever removed).
constexpr std::uint8_t find_codec_row(dictionary d, std::uint32_t key) noexcept {
    key &= 0xFF'FFFF;
    const std::size_t table = static_cast<std::size_t>(d) * slots_per_dictionary;
    const std::uint32_t home = home_slot(key, hash_multiplier, 32 - slot_bits);
    const std::uint8_t s = address_slots[table + home];
    if (codec_rows[s].key == key) return matched_row(s);
    const std::uint8_t t = address_slots[table + ((home + 1) % slots_per_dictionary)];
    if (codec_rows[t].key == key) return matched_row(t);
    return 0;
}

// Per dictionary and object: the codec row number (the encoder's lookup), and the full row
// index + 1 (find_row); 0 when the dictionary lacks the object.
template <bool Full>
constexpr auto by_object() noexcept {
    std::array<std::array<std::uint8_t, object_count>, dictionary_count> t{};
    for (std::size_t d = 0; d < dictionary_count; ++d) {
        const auto rows = rows_of(dictionaries[d]);
        for (std::size_t i = 0; i < rows.size(); ++i)
            t[d][static_cast<std::size_t>(rows[i].id)] =
                Full ? static_cast<std::uint8_t>(i + 1) : codec_row_number(rows[i]);
    }
    return t;
}
inline constexpr auto codec_rows_by_object = by_object<false>();
inline constexpr auto full_rows_by_object = by_object<true>();

// The codec row number of object o in dictionary d, 0 when it has none.
constexpr std::uint8_t find_codec_row(dictionary d, object o) noexcept {
    const auto i = static_cast<std::size_t>(o);
    if (i >= object_count) return 0;
    return codec_rows_by_object[static_cast<std::size_t>(d)][i];
}
}  // namespace detail

// The row of an object in a dictionary; nullopt when the dictionary does not have it.
// (A copy, not a pointer: a null test on the address of a static object is not a constant
// expression under UBSan.)
[[nodiscard]] constexpr std::optional<object_row> find_row(dictionary d, object o) noexcept {
    const auto i = static_cast<std::size_t>(o);
    if (i >= object_count) return std::nullopt;
    const std::uint8_t r = detail::full_rows_by_object[static_cast<std::size_t>(d)][i];
    if (r == 0) return std::nullopt;
    return rows_of(d)[r - 1u];
}

// The row at an address; nullopt when the dictionary has none there (errc::unknown_object).
[[nodiscard]] constexpr std::optional<object_row> find_row(dictionary d,
                                                           canopen::sdo_address a) noexcept {
    const std::uint8_t r = detail::find_codec_row(d, detail::wire_key(a));
    if (r == 0) return std::nullopt;
    return find_row(d, detail::codec_rows[r].id);
}

// --- names ----------------------------------------------------------------------------------

template <>
struct enum_names<object> {
    using o = object;
    static constexpr enum_name_entry<o> entries[] = {
        {o::keys, "keys"},
        {o::led_on, "led_on"},
        {o::led_blink, "led_blink"},
        {o::led_on_red, "led_on_red"},
        {o::led_on_green, "led_on_green"},
        {o::led_blink_red, "led_blink_red"},
        {o::led_blink_green, "led_blink_green"},
        {o::led_brightness, "led_brightness"},
        {o::backlight_level, "backlight_level"},
        {o::backlight_colour, "backlight_colour"},
        {o::default_backlight_colour, "default_backlight_colour"},
        {o::default_led_brightness, "default_led_brightness"},
        {o::default_backlight_level, "default_backlight_level"},
        {o::brightness_count, "brightness_count"},
        {o::baud_rate, "baud_rate"},
        {o::boot_up, "boot_up"},
        {o::active_on_startup, "active_on_startup"},
        {o::node_id, "node_id"},
        {o::startup_show, "startup_show"},
        {o::led_power, "led_power"},
        {o::demo_mode, "demo_mode"},
        {o::protocol_j1939, "protocol_j1939"},
        {o::protocol_rs485, "protocol_rs485"},
        {o::command_module, "command_module"},
        {o::consumer_heartbeat_count, "consumer_heartbeat_count"},
        {o::consumer_heartbeat, "consumer_heartbeat"},
        {o::heartbeat_time, "heartbeat_time"},
        {o::device_type, "device_type"},
        {o::error_register, "error_register"},
        {o::device_name, "device_name"},
        {o::hardware_version, "hardware_version"},
        {o::software_version, "software_version"},
        {o::model_name, "model_name"},
        {o::serial_number_string, "serial_number_string"},
        {o::device_model, "device_model"},
        {o::firmware_spec_count, "firmware_spec_count"},
        {o::identity_count, "identity_count"},
        {o::vendor_id, "vendor_id"},
        {o::product_code, "product_code"},
        {o::revision_number, "revision_number"},
        {o::serial_number, "serial_number"},
        {o::firmware_checksum, "firmware_checksum"},
        {o::bootloader_present, "bootloader_present"},
        {o::key_led_count_count, "key_led_count_count"},
        {o::total_keys, "total_keys"},
        {o::external_keys, "external_keys"},
        {o::total_leds, "total_leds"},
        {o::external_leds, "external_leds"},
        {o::restore_count, "restore_count"},
        {o::restore_defaults, "restore_defaults"},
        {o::rpdo1_count, "rpdo1_count"},
        {o::rpdo1_cob_id, "rpdo1_cob_id"},
        {o::rpdo1_transmission_type, "rpdo1_transmission_type"},
        {o::rpdo1_inhibit_time, "rpdo1_inhibit_time"},
        {o::rpdo2_count, "rpdo2_count"},
        {o::rpdo2_cob_id, "rpdo2_cob_id"},
        {o::rpdo2_transmission_type, "rpdo2_transmission_type"},
        {o::rpdo2_inhibit_time, "rpdo2_inhibit_time"},
        {o::rpdo3_count, "rpdo3_count"},
        {o::rpdo3_cob_id, "rpdo3_cob_id"},
        {o::rpdo3_transmission_type, "rpdo3_transmission_type"},
        {o::rpdo4_count, "rpdo4_count"},
        {o::rpdo4_cob_id, "rpdo4_cob_id"},
        {o::rpdo4_transmission_type, "rpdo4_transmission_type"},
        {o::rpdo1_mapping_count, "rpdo1_mapping_count"},
        {o::rpdo1_mapping_1, "rpdo1_mapping_1"},
        {o::rpdo1_mapping_2, "rpdo1_mapping_2"},
        {o::rpdo2_mapping_count, "rpdo2_mapping_count"},
        {o::rpdo2_mapping_1, "rpdo2_mapping_1"},
        {o::rpdo2_mapping_2, "rpdo2_mapping_2"},
        {o::rpdo3_mapping_count, "rpdo3_mapping_count"},
        {o::rpdo3_mapping_1, "rpdo3_mapping_1"},
        {o::rpdo4_mapping_count, "rpdo4_mapping_count"},
        {o::rpdo4_mapping_1, "rpdo4_mapping_1"},
        {o::rpdo4_mapping_2, "rpdo4_mapping_2"},
        {o::tpdo1_count, "tpdo1_count"},
        {o::tpdo1_cob_id, "tpdo1_cob_id"},
        {o::tpdo1_transmission_type, "tpdo1_transmission_type"},
        {o::tpdo1_inhibit_time, "tpdo1_inhibit_time"},
        {o::tpdo1_event_timer, "tpdo1_event_timer"},
        {o::tpdo1_mapping_count, "tpdo1_mapping_count"},
        {o::tpdo1_mapping_1, "tpdo1_mapping_1"},
        {o::led_on_blue, "led_on_blue"},
        {o::led_blink_blue, "led_blink_blue"},
        {o::led_on_r1_12_g1_4, "led_on_r1_12_g1_4"},
        {o::led_on_g5_12, "led_on_g5_12"},
        {o::led_on_b1_12, "led_on_b1_12"},
        {o::led_blink_r1_12_g1_4, "led_blink_r1_12_g1_4"},
        {o::led_blink_g5_12, "led_blink_g5_12"},
        {o::led_blink_b1_12, "led_blink_b1_12"},
        {o::led_on_encoder, "led_on_encoder"},
        {o::led_blink_encoder, "led_blink_encoder"},
        {o::encoder1_direction_counter, "encoder1_direction_counter"},
        {o::encoder1_tick_counter, "encoder1_tick_counter"},
        {o::encoder2_direction_counter, "encoder2_direction_counter"},
        {o::encoder2_tick_counter, "encoder2_tick_counter"},
        {o::encoder1_top_position, "encoder1_top_position"},
        {o::encoder2_top_position, "encoder2_top_position"},
        {o::digital_input_count, "digital_input_count"},
        {o::digital_inputs, "digital_inputs"},
        {o::analog_input_count, "analog_input_count"},
        {o::analog_input_0, "analog_input_0"},
        {o::analog_input_1, "analog_input_1"},
        {o::analog_input_2, "analog_input_2"},
        {o::analog_input_3, "analog_input_3"},
        {o::analog_input_period, "analog_input_period"},
        {o::rpdo1_mapping_3, "rpdo1_mapping_3"},
        {o::rpdo2_mapping_3, "rpdo2_mapping_3"},
        {o::tpdo2_count, "tpdo2_count"},
        {o::tpdo2_cob_id, "tpdo2_cob_id"},
        {o::tpdo2_transmission_type, "tpdo2_transmission_type"},
        {o::tpdo2_event_timer, "tpdo2_event_timer"},
        {o::tpdo3_count, "tpdo3_count"},
        {o::tpdo3_cob_id, "tpdo3_cob_id"},
        {o::tpdo3_transmission_type, "tpdo3_transmission_type"},
        {o::tpdo3_event_timer, "tpdo3_event_timer"},
        {o::tpdo4_count, "tpdo4_count"},
        {o::tpdo4_cob_id, "tpdo4_cob_id"},
        {o::tpdo4_transmission_type, "tpdo4_transmission_type"},
        {o::tpdo2_mapping_count, "tpdo2_mapping_count"},
        {o::tpdo2_mapping_1, "tpdo2_mapping_1"},
        {o::tpdo2_mapping_2, "tpdo2_mapping_2"},
        {o::tpdo2_mapping_3, "tpdo2_mapping_3"},
        {o::tpdo3_mapping_count, "tpdo3_mapping_count"},
        {o::tpdo3_mapping_1, "tpdo3_mapping_1"},
        {o::tpdo3_mapping_2, "tpdo3_mapping_2"},
        {o::tpdo3_mapping_3, "tpdo3_mapping_3"},
    };
};

template <>
struct enum_names<access> {
    static constexpr enum_name_entry<access> entries[] = {{access::read_only, "read_only"},
                                                          {access::write_only, "write_only"},
                                                          {access::read_write, "read_write"}};
};

template <>
struct enum_names<dictionary> {
    static constexpr enum_name_entry<dictionary> entries[] = {
        {dictionary::pk1000, "pk1000"},
        {dictionary::pkp_li, "pkp_li"},
        {dictionary::si_packed, "si_packed"},
        {dictionary::si_mt, "si_mt"},
        {dictionary::si_per_colour, "si_per_colour"}};
};

template <>
struct enum_names<value_kind> {
    using k = value_kind;
    static constexpr enum_name_entry<k> entries[] = {
        {k::number, "number"},
        {k::flag, "flag"},
        {k::brightness, "brightness"},
        {k::colour, "colour"},
        {k::baud, "baud"},
        {k::show, "show"},
        {k::node, "node"},
        {k::period, "period"},
        {k::keys, "keys"},
        {k::led_plane, "led_plane"},
        {k::led_map, "led_map"},
        {k::consumer_heartbeat, "consumer_heartbeat"},
        {k::cob_id, "cob_id"},
        {k::pdo_mapping, "pdo_mapping"},
        {k::device_type, "device_type"},
        {k::string, "string"},
        {k::restore, "restore"},
        {k::none, "none"},
        {k::led_part, "led_part"},
        {k::ring, "ring"},
        {k::direction_counter, "direction_counter"},
        {k::commands, "commands"},
    };
};

}  // namespace powerkey

#endif  // POWERKEY_KEYPAD_OBJECTS_HPP
