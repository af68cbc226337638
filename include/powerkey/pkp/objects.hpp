// powerkey PKP: the object dictionary of the PKP manual (sections 13-32) as one table, and the SDO
// messages that read and write it. Each entry says its index and sub-index, what its value is,
// the expedited size the keypad uses (as printed in the manual; see E-PKP-5), whether it can be
// read and written, and its range.
#ifndef POWERKEY_PKP_OBJECTS_HPP
#define POWERKEY_PKP_OBJECTS_HPP

#include <powerkey/canopen/sdo.hpp>
#include <powerkey/detail/lookup.hpp>
#include <powerkey/pkp/model.hpp>
#include <powerkey/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace powerkey::pkp {

// Every entry of the profile. The underlying type is one byte so that tools can list the names.
enum class object : std::uint8_t {
    device_type,               // 1000h     (18)
    device_name,               // 1008h     (19) string
    hardware_version,          // 1009h     (20) string
    software_version,          // 100Ah     (21) string
    model_name,                // 100Bh     (22) string
    heartbeat_time,            // 1017h     (17) ms, 0 = off or 10..65535
    identity_count,            // 1018h/0   (23)
    vendor_id,                 // 1018h/1
    product_code,              // 1018h/2
    revision_number,           // 1018h/3   byte 4 app, 5 com lib, 6 hw lib revision
    firmware_checksum,         // 1018h/4
    rpdo1_count,               // 1400h/0   (24) LED-on PDO
    rpdo1_cob_id,              // 1400h/1
    rpdo1_inhibit_time,        // 1400h/3
    rpdo2_count,               // 1401h/0   (25) LED-blink PDO
    rpdo2_cob_id,              // 1401h/1
    rpdo2_inhibit_time,        // 1401h/3
    output_mapping_count,      // 1600h/0   (26)
    output_mapping_led_on,     // 1600h/1   6001 00 20h
    output_mapping_led_blink,  // 1600h/2   6002 00 20h
    tpdo1_count,               // 1800h/0   (27) key-state PDO
    tpdo1_cob_id,              // 1800h/1
    tpdo1_transmission_type,   // 1800h/2
    tpdo1_inhibit_time,        // 1800h/3
    tpdo1_event_timer,         // 1800h/5   ms, 0 = off
    input_mapping_count,       // 1A00h/0   (28)
    input_mapping_keys,        // 1A00h/1   6000 00 20h
    keys,                      // 6000h     (14) key states
    led_on,                    // 6001h     (15) LED-on map
    led_blink,                 // 6002h     (16) LED-blink map
    firmware_spec_count,       // 6100h/0   (29)
    serial_number,             // 6100h/1
    device_model,              // 6100h/2   string
    brightness_count,          // 6201h/0   (30)
    key_led_brightness,        // 6201h/1   00h..3Fh
    backlight_brightness,      // 6201h/2   00h..3Fh
    serial_number_string,      // 6300h     (31) string
    bootloader_present,        // 6301h     (32) 0 or 1
    key_led_count_count,       // 6302h/0
    total_keys,                // 6302h/1
    external_keys,             // 6302h/2
    total_leds,                // 6302h/3
    external_leds,             // 6302h/4
    command_module,            // 6500h/1   (13) write only, see command.hpp
};

// What an entry holds.
enum class value_type : std::uint8_t {
    number,    // an unsigned integer of `size` bytes
    keys,      // 6000h: key bits, model.hpp
    led_map,   // 6001h/6002h: the LED bit map, red and green only on the PKP-2600
    string,    // read by a segmented upload
    commands,  // 6500h/1: command.hpp
};

struct object_info {
    object id;
    std::string_view name;
    canopen::sdo_address address;
    value_type type;
    std::uint8_t size;  // expedited bytes (1, 2 or 4); 0 for strings
    bool readable;
    bool writable;
    std::uint32_t min = 0;
    std::uint32_t max = 0xFFFF'FFFF;
    bool zero_allowed = false;  // 0 is valid below min (heartbeat off)
};

namespace detail {
using vt = value_type;
inline constexpr object_info object_table[] = {
    {object::device_type, "device_type", {0x1000, 0}, vt::number, 4, true, false},
    {object::device_name, "device_name", {0x1008, 0}, vt::string, 0, true, false},
    {object::hardware_version, "hardware_version", {0x1009, 0}, vt::string, 0, true, false},
    {object::software_version, "software_version", {0x100A, 0}, vt::string, 0, true, false},
    {object::model_name, "model_name", {0x100B, 0}, vt::string, 0, true, false},
    {object::heartbeat_time,
     "heartbeat_time",
     {0x1017, 0},
     vt::number,
     2,
     true,
     true,
     10,
     0xFFFF,
     true},
    {object::identity_count, "identity_count", {0x1018, 0}, vt::number, 1, true, false, 0, 0xFF},
    {object::vendor_id, "vendor_id", {0x1018, 1}, vt::number, 4, true, false},
    {object::product_code, "product_code", {0x1018, 2}, vt::number, 4, true, false},
    {object::revision_number, "revision_number", {0x1018, 3}, vt::number, 4, true, false},
    {object::firmware_checksum, "firmware_checksum", {0x1018, 4}, vt::number, 4, true, false},
    {object::rpdo1_count, "rpdo1_count", {0x1400, 0}, vt::number, 1, true, false, 0, 0xFF},
    {object::rpdo1_cob_id, "rpdo1_cob_id", {0x1400, 1}, vt::number, 2, true, false, 0, 0xFFFF},
    {object::rpdo1_inhibit_time,
     "rpdo1_inhibit_time",
     {0x1400, 3},
     vt::number,
     2,
     true,
     false,
     0,
     0xFFFF},
    {object::rpdo2_count, "rpdo2_count", {0x1401, 0}, vt::number, 1, true, false, 0, 0xFF},
    {object::rpdo2_cob_id, "rpdo2_cob_id", {0x1401, 1}, vt::number, 2, true, false, 0, 0xFFFF},
    {object::rpdo2_inhibit_time,
     "rpdo2_inhibit_time",
     {0x1401, 3},
     vt::number,
     2,
     true,
     false,
     0,
     0xFFFF},
    {object::output_mapping_count,
     "output_mapping_count",
     {0x1600, 0},
     vt::number,
     1,
     true,
     false,
     0,
     0xFF},
    {object::output_mapping_led_on,
     "output_mapping_led_on",
     {0x1600, 1},
     vt::number,
     4,
     true,
     false},
    {object::output_mapping_led_blink,
     "output_mapping_led_blink",
     {0x1600, 2},
     vt::number,
     4,
     true,
     false},
    {object::tpdo1_count, "tpdo1_count", {0x1800, 0}, vt::number, 1, true, false, 0, 0xFF},
    {object::tpdo1_cob_id, "tpdo1_cob_id", {0x1800, 1}, vt::number, 2, true, false, 0, 0xFFFF},
    {object::tpdo1_transmission_type,
     "tpdo1_transmission_type",
     {0x1800, 2},
     vt::number,
     2,
     true,
     false,
     0,
     0xFFFF},
    {object::tpdo1_inhibit_time,
     "tpdo1_inhibit_time",
     {0x1800, 3},
     vt::number,
     2,
     true,
     false,
     0,
     0xFFFF},
    {object::tpdo1_event_timer,
     "tpdo1_event_timer",
     {0x1800, 5},
     vt::number,
     2,
     true,
     false,
     0,
     0xFFFF},
    {object::input_mapping_count,
     "input_mapping_count",
     {0x1A00, 0},
     vt::number,
     1,
     true,
     false,
     0,
     0xFF},
    {object::input_mapping_keys, "input_mapping_keys", {0x1A00, 1}, vt::number, 4, true, false},
    {object::keys, "keys", {0x6000, 0}, vt::keys, 4, true, false},
    {object::led_on, "led_on", {0x6001, 0}, vt::led_map, 4, true, true},
    {object::led_blink, "led_blink", {0x6002, 0}, vt::led_map, 4, true, true},
    {object::firmware_spec_count,
     "firmware_spec_count",
     {0x6100, 0},
     vt::number,
     1,
     true,
     false,
     0,
     0xFF},
    {object::serial_number, "serial_number", {0x6100, 1}, vt::number, 4, true, false},
    {object::device_model, "device_model", {0x6100, 2}, vt::string, 0, true, false},
    {object::brightness_count,
     "brightness_count",
     {0x6201, 0},
     vt::number,
     1,
     true,
     false,
     0,
     0xFF},
    {object::key_led_brightness,
     "key_led_brightness",
     {0x6201, 1},
     vt::number,
     1,
     true,
     true,
     0,
     0x3F},
    {object::backlight_brightness,
     "backlight_brightness",
     {0x6201, 2},
     vt::number,
     1,
     true,
     true,
     0,
     0x3F},
    {object::serial_number_string, "serial_number_string", {0x6300, 0}, vt::string, 0, true, false},
    {object::bootloader_present,
     "bootloader_present",
     {0x6301, 0},
     vt::number,
     1,
     true,
     false,
     0,
     1},
    {object::key_led_count_count,
     "key_led_count_count",
     {0x6302, 0},
     vt::number,
     1,
     true,
     false,
     0,
     0xFF},
    {object::total_keys, "total_keys", {0x6302, 1}, vt::number, 1, true, false, 0, 0xFF},
    {object::external_keys, "external_keys", {0x6302, 2}, vt::number, 1, true, false, 0, 0xFF},
    {object::total_leds, "total_leds", {0x6302, 3}, vt::number, 1, true, false, 0, 0xFF},
    {object::external_leds, "external_leds", {0x6302, 4}, vt::number, 1, true, false, 0, 0xFF},
    {object::command_module, "command_module", {0x6500, 1}, vt::commands, 4, false, true},
};

constexpr bool table_in_enum_order() noexcept {
    for (std::size_t i = 0; i < std::size(object_table); ++i)
        if (static_cast<std::size_t>(object_table[i].id) != i) return false;
    return true;
}
static_assert(table_in_enum_order());
}  // namespace detail

inline constexpr std::size_t object_count = std::size(detail::object_table);

// The table row of an object; nullopt for a value outside the enum. (A copy, not a pointer: a
// null test on the address of a static object is not a constant expression under UBSan.)
[[nodiscard]] constexpr std::optional<object_info> info(object o) noexcept {
    const auto i = static_cast<std::size_t>(o);
    if (i >= object_count) return std::nullopt;
    return detail::object_table[i];
}

[[nodiscard]] constexpr std::string_view to_string(object o) noexcept {
    const auto i = info(o);
    return i ? i->name : "unknown";
}

namespace detail {
// The table's addresses in a compile-time hash table (issue 7: one or two probes per lookup).
inline constexpr auto object_lookup = [] {
    constexpr std::size_t n = std::size(object_table);
    std::array<std::uint32_t, n> keys{};
    for (std::size_t i = 0; i < n; ++i)
        keys[i] = powerkey::detail::address_key(object_table[i].address.index,
                                                object_table[i].address.subindex);
    return powerkey::detail::address_table<n, 8>(keys);
}();
static_assert(object_lookup.max_probes() <= 2);
}  // namespace detail

// The object at an index and sub-index, if the profile defines one.
[[nodiscard]] constexpr std::optional<object> find_object(canopen::sdo_address a) noexcept {
    const auto row = detail::object_lookup.find(powerkey::detail::address_key(a.index, a.subindex));
    if (!row) return std::nullopt;
    return detail::object_table[*row].id;
}

// True when v is a valid value of a number entry.
[[nodiscard]] constexpr bool in_range(const object_info& i, std::uint32_t v) noexcept {
    if (i.size < 4 && (v >> (8 * i.size)) != 0) return false;
    return (v >= i.min && v <= i.max) || (i.zero_allowed && v == 0);
}

// 1018h sub 3 (section 23): the revision number's bytes, data byte 4 first.
struct revision {
    std::uint8_t app = 0;      // application revision
    std::uint8_t com_lib = 0;  // communication library revision
    std::uint8_t hw_lib = 0;   // hardware library revision
    friend constexpr bool operator==(const revision&, const revision&) noexcept = default;
};
[[nodiscard]] constexpr revision revision_of(std::uint32_t value) noexcept {
    return {static_cast<std::uint8_t>(value), static_cast<std::uint8_t>(value >> 8),
            static_cast<std::uint8_t>(value >> 16)};
}

// --- SDO messages ---------------------------------------------------------------------------

// Read an entry: upload request 40h to 600h + node.
struct read_request {
    static constexpr std::string_view kind = "pkp_read";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("object", self.entry);
    }
    object entry = object::device_type;
    friend constexpr bool operator==(const read_request&, const read_request&) noexcept = default;
};

// The value of a number entry: expedited upload response (4Fh/4Bh/43h by the entry's size).
struct read_response {
    static constexpr std::string_view kind = "pkp_read_response";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("object", self.entry);
        f("value", self.value);
    }
    object entry = object::device_type;
    std::uint32_t value = 0;
    friend constexpr bool operator==(const read_response&, const read_response&) noexcept = default;
};

// Write a number entry (1017h, 6201h subs 1 and 2): expedited download (2Fh/2Bh by size).
struct write_request {
    static constexpr std::string_view kind = "pkp_write";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("object", self.entry);
        f("value", self.value);
    }
    object entry = object::heartbeat_time;
    std::uint32_t value = 0;
    friend constexpr bool operator==(const write_request&, const write_request&) noexcept = default;
};

// The keypad confirms a write (60h) of any writable entry, the command module included.
struct write_response {
    static constexpr std::string_view kind = "pkp_write_response";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("object", self.entry);
    }
    object entry = object::command_module;
    friend constexpr bool operator==(const write_response&,
                                     const write_response&) noexcept = default;
};

// 6000h read reply (43h): the pressed keys in bytes 4..5.
struct keys_response {
    static constexpr std::string_view kind = "pkp_keys_response";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("keys", self.keys);
    }
    key_set keys;
    friend constexpr bool operator==(const keys_response&, const keys_response&) noexcept = default;
};

// 6001h (LED on) and 6002h (LED blink), written (23h) or read (43h): 4 bytes of the bit map.
// A PKP-2600 needs 36 bits for RGB, which do not fit: there these objects carry red and green
// only (reference/pkp-2600.md); blue is reached through the RPDOs or command 01h.
struct write_led_on_tag {
    static constexpr std::string_view kind = "pkp_write_led_on";
};
using write_led_on = leds_message<write_led_on_tag>;
struct write_led_blink_tag {
    static constexpr std::string_view kind = "pkp_write_led_blink";
};
using write_led_blink = leds_message<write_led_blink_tag>;
struct led_on_response_tag {
    static constexpr std::string_view kind = "pkp_led_on_response";
};
using led_on_response = leds_message<led_on_response_tag>;
struct led_blink_response_tag {
    static constexpr std::string_view kind = "pkp_led_blink_response";
};
using led_blink_response = leds_message<led_blink_response_tag>;

// An abort sent by the client (600h + node); one from the keypad is canopen::sdo_abort.
using canopen::sdo_abort_request;

// --- value helpers ----------------------------------------------------------------------------

// Colour planes 6001h/6002h carry for a model: 2 on the PKP-2600, else 3.
[[nodiscard]] constexpr unsigned sdo_led_planes(model m) noexcept {
    return m == model::pkp2600 ? 2 : 3;
}

namespace detail {
constexpr std::array<std::uint8_t, 4> four(const can::payload& p) noexcept {
    return {p[4], p[5], p[6], p[7]};
}
// The 4 data bytes of a 6001h/6002h value; the caller has checked fits().
constexpr std::array<std::uint8_t, 4> led_value_bytes(model m, const leds& l) noexcept {
    can::payload p{};
    pack_leds(m, l, sdo_led_planes(m), p, 4, 4);
    return four(p);
}
constexpr result<leds> led_value_of(model m, const std::array<std::uint8_t, 4>& b) noexcept {
    const can::payload p{0, 0, 0, 0, b[0], b[1], b[2], b[3]};
    return unpack_leds(m, p, sdo_led_planes(m), 4, 4);
}
constexpr std::array<std::uint8_t, 4> keys_value_bytes(const key_set& k) noexcept {
    can::payload p{};
    pack_keys(k, p, 4);
    return four(p);
}
constexpr result<key_set> keys_value_of(model m, const std::array<std::uint8_t, 4>& b) noexcept {
    const can::payload p{0, 0, 0, 0, b[0], b[1], b[2], b[3]};
    return unpack_keys(m, p, 4, 4);
}
// A number as `size` little-endian bytes, the rest 00h.
constexpr canopen::expedited_data number_bytes(std::uint8_t size, std::uint32_t v) noexcept {
    canopen::expedited_data d{canopen::expedited_size::make(size).value(), {}};
    powerkey::detail::store_le_u32(d.bytes, 0, v);
    return d;
}
// The number in an expedited value of the entry's size: size_mismatch for another size,
// reserved_not_zero for bytes past the size not 00h, value_out_of_range outside the range.
constexpr result<std::uint32_t> number_of(const object_info& i,
                                          const canopen::expedited_data& d) noexcept {
    if (d.size.value() != i.size) return errc::size_mismatch;
    if (!powerkey::detail::all_zero(d.bytes, i.size, 4)) return errc::reserved_not_zero;
    const auto v = d.value();
    if (!in_range(i, v)) return errc::value_out_of_range;
    return v;
}
}  // namespace detail

}  // namespace powerkey::pkp

#endif  // POWERKEY_PKP_OBJECTS_HPP
