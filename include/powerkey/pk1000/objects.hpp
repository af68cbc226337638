// powerkey PK1000: the object dictionary of the manual (sections 16 to 49) and a typed value for
// every entry that carries one. Every entry is read with an SDO upload (40h) and, where the
// manual documents a write, written with an expedited download of the entry's size:
//   615#2F 03 20 01 | 09 00 00 00    write 2003h sub 1, one byte (2Fh), value 09h
//   595#60 03 20 01 | 00 00 00 00    the keypad's acknowledgement
//   615#40 03 20 01 | 00 00 00 00    read 2003h sub 1
//   595#4F 03 20 01 | 09 00 00 00    the keypad's reply, one byte
// Each value type V below knows its address (from its fields), its expedited size, and how to
// check and read its bytes. Bytes past the size must be zero, so a decoded value re-encodes to
// the same frame; the string objects (1008h, 1009h, 100Ah, 100Bh, 2200h) are raw bytes.
#ifndef POWERKEY_PK1000_OBJECTS_HPP
#define POWERKEY_PK1000_OBJECTS_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/detail/bytes.hpp>
#include <powerkey/detail/lookup.hpp>
#include <powerkey/pk1000/pdo.hpp>
#include <powerkey/pk1000/values.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace powerkey::pk1000 {

using canopen::expedited_data;
using canopen::sdo_address;

// Every (index, sub-index) the manual defines, in manual order.
enum class entry : std::uint8_t {
    keys,                          // 2000h/01 section 16, read only
    led_on_red,                    // 2001h/01 section 17
    led_on_green,                  // 2001h/02
    led_blink_red,                 // 2002h/01 section 18
    led_blink_green,               // 2002h/02
    led_brightness,                // 2003h/01 section 19 a
    backlight_brightness,          // 2003h/02 section 19 b
    backlight_colour,              // 2003h/03 section 19 c
    default_backlight_colour,      // 2003h/04 section 19 d
    default_led_brightness,        // 2003h/05 section 19 e
    default_backlight_brightness,  // 2003h/06 section 19 f
    baud_rate,                     // 2010h/00 section 20
    boot_up,                       // 2011h/00 section 21
    active_on_startup,             // 2012h/00 section 22
    node_id,                       // 2013h/00 section 23
    startup_show,                  // 2014h/00 section 24
    led_power,                     // 2015h/00 section 25
    demo_mode,                     // 2100h/00 section 26
    bus_j1939,                     // 20FFh/01 sections 27, 49
    bus_rs485,                     // 20FFh/02 section 27
    consumer_heartbeat_count,      // 1016h/00 section 28, read only
    consumer_heartbeat,            // 1016h/01
    producer_heartbeat,            // 1017h/00 section 29
    device_type,                   // 1000h/00 section 30, read only
    error_register,                // 1001h/00 section 31, not implemented: the keypad aborts
    device_name,                   // 1008h/00 section 32, read only
    hardware_version,              // 1009h/00 section 33, read only
    firmware_version,              // 100Ah/00 section 34, read only
    model_id,                      // 100Bh/00 section 35, read only
    restore_count,                 // 1011h/00 section 36, read only
    restore_all,                   // 1011h/01, write "load"
    identity_count,                // 1018h/00 section 37, read only
    vendor_id,                     // 1018h/01, read only
    serial_number,                 // 1018h/04, read only
    rpdo1_count,                   // 1400h/00 section 38, read only
    rpdo1_cob_id,                  // 1400h/01, read only
    rpdo1_transmission,            // 1400h/02
    rpdo2_count,                   // 1401h/00 section 39, read only
    rpdo2_cob_id,                  // 1401h/01, read only
    rpdo2_transmission,            // 1401h/02
    rpdo3_count,                   // 1402h/00 section 40, read only
    rpdo3_cob_id,                  // 1402h/01, read only
    rpdo3_transmission,            // 1402h/02, read only
    rpdo4_count,                   // 1403h/00 section 41, read only
    rpdo4_cob_id,                  // 1403h/01, read only
    rpdo4_transmission,            // 1403h/02, read only
    rpdo1_mapping_count,           // 1600h/00 section 42, read only
    rpdo1_mapping_1,               // 1600h/01, read only
    rpdo1_mapping_2,               // 1600h/02, read only
    rpdo2_mapping_count,           // 1601h/00 section 43, read only
    rpdo2_mapping_1,               // 1601h/01, read only
    rpdo2_mapping_2,               // 1601h/02, read only
    rpdo3_mapping_count,           // 1602h/00 section 44, read only
    rpdo3_mapping_1,               // 1602h/01, read only
    rpdo4_mapping_count,           // 1603h/00 section 45, read only
    rpdo4_mapping_1,               // 1603h/01, read only
    rpdo4_mapping_2,               // 1603h/02, read only
    tpdo1_count,                   // 1800h/00 section 46, read only
    tpdo1_cob_id,                  // 1800h/01, read only
    tpdo1_transmission,            // 1800h/02
    tpdo1_event_timer,             // 1800h/05
    tpdo1_mapping_count,           // 1A00h/00 section 47, read only
    tpdo1_mapping_1,               // 1A00h/01, read only
    serial_string,                 // 2200h/00 section 48, read only
};

struct entry_info {
    std::string_view name;
    sdo_address address;
    bool writable;
};

inline constexpr entry_info entries[] = {
    {"keys", {0x2000, 1}, false},
    {"led_on_red", {0x2001, 1}, true},
    {"led_on_green", {0x2001, 2}, true},
    {"led_blink_red", {0x2002, 1}, true},
    {"led_blink_green", {0x2002, 2}, true},
    {"led_brightness", {0x2003, 1}, true},
    {"backlight_brightness", {0x2003, 2}, true},
    {"backlight_colour", {0x2003, 3}, true},
    {"default_backlight_colour", {0x2003, 4}, true},
    {"default_led_brightness", {0x2003, 5}, true},
    {"default_backlight_brightness", {0x2003, 6}, true},
    {"baud_rate", {0x2010, 0}, true},
    {"boot_up", {0x2011, 0}, true},
    {"active_on_startup", {0x2012, 0}, true},
    {"node_id", {0x2013, 0}, true},
    {"startup_show", {0x2014, 0}, true},
    {"led_power", {0x2015, 0}, true},
    {"demo_mode", {0x2100, 0}, true},
    {"bus_j1939", {0x20FF, 1}, true},
    {"bus_rs485", {0x20FF, 2}, true},
    {"consumer_heartbeat_count", {0x1016, 0}, false},
    {"consumer_heartbeat", {0x1016, 1}, true},
    {"producer_heartbeat", {0x1017, 0}, true},
    {"device_type", {0x1000, 0}, false},
    {"error_register", {0x1001, 0}, false},
    {"device_name", {0x1008, 0}, false},
    {"hardware_version", {0x1009, 0}, false},
    {"firmware_version", {0x100A, 0}, false},
    {"model_id", {0x100B, 0}, false},
    {"restore_count", {0x1011, 0}, false},
    {"restore_all", {0x1011, 1}, true},
    {"identity_count", {0x1018, 0}, false},
    {"vendor_id", {0x1018, 1}, false},
    {"serial_number", {0x1018, 4}, false},
    {"rpdo1_count", {0x1400, 0}, false},
    {"rpdo1_cob_id", {0x1400, 1}, false},
    {"rpdo1_transmission", {0x1400, 2}, true},
    {"rpdo2_count", {0x1401, 0}, false},
    {"rpdo2_cob_id", {0x1401, 1}, false},
    {"rpdo2_transmission", {0x1401, 2}, true},
    {"rpdo3_count", {0x1402, 0}, false},
    {"rpdo3_cob_id", {0x1402, 1}, false},
    {"rpdo3_transmission", {0x1402, 2}, false},
    {"rpdo4_count", {0x1403, 0}, false},
    {"rpdo4_cob_id", {0x1403, 1}, false},
    {"rpdo4_transmission", {0x1403, 2}, false},
    {"rpdo1_mapping_count", {0x1600, 0}, false},
    {"rpdo1_mapping_1", {0x1600, 1}, false},
    {"rpdo1_mapping_2", {0x1600, 2}, false},
    {"rpdo2_mapping_count", {0x1601, 0}, false},
    {"rpdo2_mapping_1", {0x1601, 1}, false},
    {"rpdo2_mapping_2", {0x1601, 2}, false},
    {"rpdo3_mapping_count", {0x1602, 0}, false},
    {"rpdo3_mapping_1", {0x1602, 1}, false},
    {"rpdo4_mapping_count", {0x1603, 0}, false},
    {"rpdo4_mapping_1", {0x1603, 1}, false},
    {"rpdo4_mapping_2", {0x1603, 2}, false},
    {"tpdo1_count", {0x1800, 0}, false},
    {"tpdo1_cob_id", {0x1800, 1}, false},
    {"tpdo1_transmission", {0x1800, 2}, true},
    {"tpdo1_event_timer", {0x1800, 5}, true},
    {"tpdo1_mapping_count", {0x1A00, 0}, false},
    {"tpdo1_mapping_1", {0x1A00, 1}, false},
    {"serial_string", {0x2200, 0}, false},
};

inline constexpr std::size_t entry_count = sizeof(entries) / sizeof(entries[0]);
static_assert(static_cast<std::size_t>(entry::serial_string) + 1 == entry_count);

[[nodiscard]] constexpr const entry_info& info(entry e) noexcept {
    return entries[static_cast<std::size_t>(e)];
}
[[nodiscard]] constexpr std::string_view to_string(entry e) noexcept {
    if (static_cast<std::size_t>(e) >= entry_count) return "";
    return info(e).name;
}
[[nodiscard]] constexpr sdo_address address_of(entry e) noexcept { return info(e).address; }

namespace detail {
// The entries' addresses in a compile-time hash table (issue 7: one or two probes per lookup).
inline constexpr auto entry_table = [] {
    std::array<std::uint32_t, entry_count> keys{};
    for (std::size_t i = 0; i < entry_count; ++i)
        keys[i] =
            powerkey::detail::address_key(entries[i].address.index, entries[i].address.subindex);
    return powerkey::detail::address_table<entry_count, 8>(keys);
}();
static_assert(entry_table.max_probes() <= 2);
}  // namespace detail

// The entry at an address; errc::unknown_object for one the manual does not define.
[[nodiscard]] constexpr result<entry> find_entry(sdo_address a) noexcept {
    const auto row = detail::entry_table.find(powerkey::detail::address_key(a.index, a.subindex));
    if (!row) return errc::unknown_object;
    return static_cast<entry>(*row);
}

namespace detail {
// errc{} when d holds exactly `size` bytes and the bytes past them are zero.
constexpr errc expect_size(const expedited_data& d, std::uint8_t size) noexcept {
    if (d.size.value() != size) return errc::size_mismatch;
    for (std::size_t i = size; i < 4; ++i)
        if (d.bytes[i] != 0) return errc::reserved_not_zero;
    return errc{};
}
constexpr expedited_data data_u8(std::uint8_t v) noexcept { return expedited_data::u8(v); }

// A small enum whose values index a table of addresses: covers / decode / address.
template <class E, std::size_t N>
constexpr bool table_covers(const std::array<sdo_address, N>& t, sdo_address a) noexcept {
    for (const auto& x : t)
        if (x == a) return true;
    return false;
}
template <class E, std::size_t N>
constexpr E table_find(const std::array<sdo_address, N>& t, sdo_address a) noexcept {
    for (std::size_t i = 0; i < N; ++i)
        if (t[i] == a) return static_cast<E>(i);
    return static_cast<E>(0);
}
}  // namespace detail

// --- 2000h: key states (section 16), read only ------------------------------------------------

struct keys_value {
    static constexpr std::string_view value_kind = "pk1000_keys";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("pressed", self.pressed);
    }
    key_set pressed;

    static constexpr sdo_address at{0x2000, 1};
    [[nodiscard]] constexpr sdo_address address() const noexcept { return at; }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept { return a == at; }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return expedited_data::u16(static_cast<std::uint16_t>(pressed.mask()));
    }
    [[nodiscard]] static constexpr result<keys_value> parse(sdo_address,
                                                            const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 2); e != errc{}) return e;
        if ((d.bytes[1] & 0xFC) != 0) return errc::reserved_not_zero;
        return keys_value{key_set::from_mask(d.value())};
    }
    friend constexpr bool operator==(const keys_value&, const keys_value&) noexcept = default;
};

// --- 2001h, 2002h: LED on and LED blink registers (sections 17, 18) ---------------------------

namespace detail {
template <std::uint16_t Index>
struct led_register {
    led_colour colour = led_colour::red;  // the sub-index: 01h red, 02h green
    led_set leds;

    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("colour", self.colour);
        f("leds", self.leds);
    }
    [[nodiscard]] constexpr sdo_address address() const noexcept {
        return {Index, static_cast<std::uint8_t>(colour)};
    }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept {
        return a.index == Index && (a.subindex == 1 || a.subindex == 2);
    }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return expedited_data::u32(static_cast<std::uint32_t>(leds.mask()));
    }
    template <class Derived>
    static constexpr result<Derived> parse_as(sdo_address a, const expedited_data& d) noexcept {
        if (const auto e = expect_size(d, 4); e != errc{}) return e;
        if ((d.value() >> led_count) != 0) return errc::reserved_not_zero;
        Derived v;
        v.colour = static_cast<led_colour>(a.subindex);
        v.leds = led_set::from_mask(d.value());
        return v;
    }
    friend constexpr bool operator==(const led_register&, const led_register&) noexcept = default;
};
}  // namespace detail

struct led_on_value : detail::led_register<0x2001> {
    static constexpr std::string_view set_kind = "pk1000_set_led_on";
    static constexpr std::string_view value_kind = "pk1000_led_on_register";
    [[nodiscard]] static constexpr result<led_on_value> parse(sdo_address a,
                                                              const expedited_data& d) noexcept {
        return parse_as<led_on_value>(a, d);
    }
};

struct led_blink_value : detail::led_register<0x2002> {
    static constexpr std::string_view set_kind = "pk1000_set_led_blink";
    static constexpr std::string_view value_kind = "pk1000_led_blink_register";
    [[nodiscard]] static constexpr result<led_blink_value> parse(sdo_address a,
                                                                 const expedited_data& d) noexcept {
        return parse_as<led_blink_value>(a, d);
    }
};

// --- 2003h: brightness levels and colours (section 19) ----------------------------------------

// The sub-index of 2003h that holds a level.
enum class level_setting : std::uint8_t {
    led = 0x01,                // a) LED indicators, until power off
    backlight = 0x02,          // b) backlight, until power off
    default_led = 0x05,        // e) LED indicators at power on
    default_backlight = 0x06,  // f) backlight at power on
};

[[nodiscard]] constexpr std::string_view to_string(level_setting s) noexcept {
    switch (s) {
        case level_setting::led: return "led";
        case level_setting::backlight: return "backlight";
        case level_setting::default_led: return "default_led";
        case level_setting::default_backlight: return "default_backlight";
    }
    return "";
}

struct brightness_value {
    static constexpr std::string_view set_kind = "pk1000_set_brightness";
    static constexpr std::string_view value_kind = "pk1000_brightness";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("setting", self.setting);
        f("level", self.level);
    }
    level_setting setting = level_setting::led;
    brightness level = 0x3F;

    [[nodiscard]] constexpr sdo_address address() const noexcept {
        return {0x2003, static_cast<std::uint8_t>(setting)};
    }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept {
        return a.index == 0x2003 &&
               (a.subindex == 1 || a.subindex == 2 || a.subindex == 5 || a.subindex == 6);
    }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return detail::data_u8(level.value());
    }
    [[nodiscard]] static constexpr result<brightness_value> parse(
        sdo_address a, const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 1); e != errc{}) return e;
        const auto level = brightness::make(d.bytes[0]);
        if (!level) return level.error();
        return brightness_value{static_cast<level_setting>(a.subindex), *level};
    }
    friend constexpr bool operator==(const brightness_value&,
                                     const brightness_value&) noexcept = default;
};

// The sub-index of 2003h that holds a colour.
enum class colour_setting : std::uint8_t {
    current = 0x03,   // c) until power off
    power_on = 0x04,  // d) at power on
};

[[nodiscard]] constexpr std::string_view to_string(colour_setting s) noexcept {
    switch (s) {
        case colour_setting::current: return "current";
        case colour_setting::power_on: return "power_on";
    }
    return "";
}

struct colour_value {
    static constexpr std::string_view set_kind = "pk1000_set_backlight_colour";
    static constexpr std::string_view value_kind = "pk1000_backlight_colour";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("setting", self.setting);
        f("colour", self.colour);
    }
    colour_setting setting = colour_setting::current;
    backlight_colour colour = backlight_colour::amber_orange;

    [[nodiscard]] constexpr sdo_address address() const noexcept {
        return {0x2003, static_cast<std::uint8_t>(setting)};
    }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept {
        return a.index == 0x2003 && (a.subindex == 3 || a.subindex == 4);
    }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return detail::data_u8(static_cast<std::uint8_t>(colour));
    }
    [[nodiscard]] static constexpr result<colour_value> parse(sdo_address a,
                                                              const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 1); e != errc{}) return e;
        if (!is_backlight_colour(d.bytes[0])) return errc::value_out_of_range;
        return colour_value{static_cast<colour_setting>(a.subindex),
                            static_cast<backlight_colour>(d.bytes[0])};
    }
    friend constexpr bool operator==(const colour_value&, const colour_value&) noexcept = default;
};

// --- 2010h: baud rate (section 20) --------------------------------------------------------------

struct baud_rate_value {
    static constexpr std::string_view set_kind = "pk1000_set_baud_rate";
    static constexpr std::string_view value_kind = "pk1000_baud_rate";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("rate", self.rate);
    }
    baud_rate rate = baud_rate::kbit_125;

    static constexpr sdo_address at{0x2010, 0};
    [[nodiscard]] constexpr sdo_address address() const noexcept { return at; }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept { return a == at; }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return detail::data_u8(static_cast<std::uint8_t>(rate));
    }
    [[nodiscard]] static constexpr result<baud_rate_value> parse(sdo_address,
                                                                 const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 1); e != errc{}) return e;
        if (d.bytes[0] > 0x07) return errc::value_out_of_range;
        return baud_rate_value{static_cast<baud_rate>(d.bytes[0])};
    }
    friend constexpr bool operator==(const baud_rate_value&,
                                     const baud_rate_value&) noexcept = default;
};

// --- 2011h, 2012h, 2015h, 2100h, 20FFh: on/off settings (sections 21, 22, 25, 26, 27, 49) -----

enum class flag : std::uint8_t {
    boot_up,            // 2011h: send the boot-up message at power on
    active_on_startup,  // 2012h: operational at power on, without NMT start
    led_power,          // 2015h: LED supply; off = low power, LEDs not accessible
    demo_mode,          // 2100h: demo mode after the next power cycle
    j1939,              // 20FFh/01: 1 switches the keypad to J1939 (section 49)
    rs485,              // 20FFh/02: RS485 bus
};

[[nodiscard]] constexpr std::string_view to_string(flag s) noexcept {
    switch (s) {
        case flag::boot_up: return "boot_up";
        case flag::active_on_startup: return "active_on_startup";
        case flag::led_power: return "led_power";
        case flag::demo_mode: return "demo_mode";
        case flag::j1939: return "j1939";
        case flag::rs485: return "rs485";
    }
    return "";
}

struct flag_value {
    static constexpr std::string_view set_kind = "pk1000_set_flag";
    static constexpr std::string_view value_kind = "pk1000_flag";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("setting", self.setting);
        f("enabled", self.enabled);
    }
    flag setting = flag::boot_up;
    bool enabled = false;

    static constexpr std::array<sdo_address, 6> table{
        {{0x2011, 0}, {0x2012, 0}, {0x2015, 0}, {0x2100, 0}, {0x20FF, 1}, {0x20FF, 2}}};
    // 20FFh is written with 2Bh, two bytes (sections 27, 49); the others with 2Fh.
    static constexpr std::uint8_t size_of(flag s) noexcept {
        return s == flag::j1939 || s == flag::rs485 ? 2 : 1;
    }
    [[nodiscard]] constexpr sdo_address address() const noexcept {
        return table[static_cast<std::size_t>(setting)];
    }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept {
        return detail::table_covers<flag>(table, a);
    }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        expedited_data d = detail::data_u8(enabled ? 1 : 0);
        if (size_of(setting) == 2) d.size = 2;
        return d;
    }
    [[nodiscard]] static constexpr result<flag_value> parse(sdo_address a,
                                                            const expedited_data& d) noexcept {
        const auto s = detail::table_find<flag>(table, a);
        if (const auto e = detail::expect_size(d, size_of(s)); e != errc{}) return e;
        if (d.value() > 1) return errc::value_out_of_range;
        return flag_value{s, d.value() == 1};
    }
    friend constexpr bool operator==(const flag_value&, const flag_value&) noexcept = default;
};

// --- 2013h: node id (section 23). The acknowledgement comes from the new node id. ------------

struct node_id_value {
    static constexpr std::string_view set_kind = "pk1000_set_node_id";
    static constexpr std::string_view value_kind = "pk1000_node_id";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("new_node_id", self.new_node_id);
    }
    canopen::node_id new_node_id = canopen::default_node_id;

    static constexpr sdo_address at{0x2013, 0};
    [[nodiscard]] constexpr sdo_address address() const noexcept { return at; }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept { return a == at; }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return detail::data_u8(new_node_id.value());
    }
    [[nodiscard]] static constexpr result<node_id_value> parse(sdo_address,
                                                               const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 1); e != errc{}) return e;
        const auto n = canopen::node_id::make(d.bytes[0]);
        if (!n) return n.error();
        return node_id_value{*n};
    }
    friend constexpr bool operator==(const node_id_value&, const node_id_value&) noexcept = default;
};

// --- 2014h: startup LED show (section 24) -------------------------------------------------------

struct startup_show_value {
    static constexpr std::string_view set_kind = "pk1000_set_startup_show";
    static constexpr std::string_view value_kind = "pk1000_startup_show";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("show", self.show);
    }
    startup_show show = startup_show::complete;

    static constexpr sdo_address at{0x2014, 0};
    [[nodiscard]] constexpr sdo_address address() const noexcept { return at; }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept { return a == at; }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return detail::data_u8(static_cast<std::uint8_t>(show));
    }
    [[nodiscard]] static constexpr result<startup_show_value> parse(
        sdo_address, const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 1); e != errc{}) return e;
        if (d.bytes[0] > 0x02) return errc::value_out_of_range;
        return startup_show_value{static_cast<startup_show>(d.bytes[0])};
    }
    friend constexpr bool operator==(const startup_show_value&,
                                     const startup_show_value&) noexcept = default;
};

// --- 1016h, 1017h: heartbeat consumer and producer (sections 28, 29) --------------------------
// A period of 0000h disables the function; otherwise it is 000Ah..FFFFh ms. `enabled` says which,
// and `period_ms` is meaningful (and encoded) only when enabled; decoding 0000h gives its minimum.

struct consumer_heartbeat_value {
    static constexpr std::string_view set_kind = "pk1000_set_consumer_heartbeat";
    static constexpr std::string_view value_kind = "pk1000_consumer_heartbeat";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("enabled", self.enabled);
        f("period_ms", self.period_ms);
        f("producer", self.producer);
    }
    bool enabled = false;
    heartbeat_ms period_ms{};
    canopen::node_id producer = 1;  // the node whose heartbeat is watched, 01h..7Fh

    // Off is 0000h on the wire, so an off value must carry the default period to round-trip.
    [[nodiscard]] constexpr bool canonical() const noexcept {
        return enabled || period_ms == heartbeat_ms{};
    }

    static constexpr sdo_address at{0x1016, 1};
    [[nodiscard]] constexpr sdo_address address() const noexcept { return at; }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept { return a == at; }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        expedited_data d{4, {}};
        powerkey::detail::store_le_u16(d.bytes, 0, enabled ? period_ms.value() : 0);
        d.bytes[2] = producer.value();
        return d;
    }
    [[nodiscard]] static constexpr result<consumer_heartbeat_value> parse(
        sdo_address, const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 4); e != errc{}) return e;
        if (d.bytes[3] != 0) return errc::reserved_not_zero;
        const auto node = canopen::node_id::make(d.bytes[2]);
        if (!node) return node.error();
        const std::uint16_t t = powerkey::detail::load_le_u16(d.bytes, 0);
        if (t == 0) return consumer_heartbeat_value{false, {}, *node};
        const auto period = heartbeat_ms::make(t);
        if (!period) return period.error();
        return consumer_heartbeat_value{true, *period, *node};
    }
    friend constexpr bool operator==(const consumer_heartbeat_value&,
                                     const consumer_heartbeat_value&) noexcept = default;
};

struct producer_heartbeat_value {
    static constexpr std::string_view set_kind = "pk1000_set_producer_heartbeat";
    static constexpr std::string_view value_kind = "pk1000_producer_heartbeat";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("enabled", self.enabled);
        f("period_ms", self.period_ms);
    }
    bool enabled = false;
    heartbeat_ms period_ms{};

    [[nodiscard]] constexpr bool canonical() const noexcept {
        return enabled || period_ms == heartbeat_ms{};
    }

    static constexpr sdo_address at{0x1017, 0};
    [[nodiscard]] constexpr sdo_address address() const noexcept { return at; }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept { return a == at; }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return expedited_data::u16(enabled ? period_ms.value() : std::uint16_t{0});
    }
    [[nodiscard]] static constexpr result<producer_heartbeat_value> parse(
        sdo_address, const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 2); e != errc{}) return e;
        if (d.value() == 0) return producer_heartbeat_value{};
        const auto period = heartbeat_ms::make(d.value());
        if (!period) return period.error();
        return producer_heartbeat_value{true, *period};
    }
    friend constexpr bool operator==(const producer_heartbeat_value&,
                                     const producer_heartbeat_value&) noexcept = default;
};

// --- 1000h: device type (section 30), read only -----------------------------------------------
// Bytes 4..5: device profile number (0191h = 401, CiA 401 generic I/O); bytes 6..7: CiA 401 I/O
// functionality, bit 0 digital input, 1 digital output, 2 analogue input, 3 analogue output.

struct device_type_value {
    static constexpr std::string_view value_kind = "pk1000_device_type";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("profile", self.profile);
        f("digital_input", self.digital_input);
        f("digital_output", self.digital_output);
        f("analogue_input", self.analogue_input);
        f("analogue_output", self.analogue_output);
    }
    std::uint16_t profile = 401;
    bool digital_input = true;
    bool digital_output = true;
    bool analogue_input = false;
    bool analogue_output = false;

    static constexpr sdo_address at{0x1000, 0};
    [[nodiscard]] constexpr sdo_address address() const noexcept { return at; }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept { return a == at; }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        const std::uint32_t io = (digital_input ? 1u : 0u) | (digital_output ? 2u : 0u) |
                                 (analogue_input ? 4u : 0u) | (analogue_output ? 8u : 0u);
        return expedited_data::u32(profile | (io << 16));
    }
    [[nodiscard]] static constexpr result<device_type_value> parse(
        sdo_address, const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 4); e != errc{}) return e;
        const std::uint32_t v = d.value();
        if ((v >> 20) != 0) return errc::reserved_not_zero;
        return device_type_value{static_cast<std::uint16_t>(v), ((v >> 16) & 1) != 0,
                                 ((v >> 17) & 1) != 0, ((v >> 18) & 1) != 0, ((v >> 19) & 1) != 0};
    }
    friend constexpr bool operator==(const device_type_value&,
                                     const device_type_value&) noexcept = default;
};

// --- 1008h, 1009h, 100Ah, 100Bh, 2200h: strings (sections 32-35, 48), read only --------------
// Short strings come expedited (1..4 bytes, this value); longer ones in segments, which the
// profile decodes as the core segmented-upload frames (see canopen/sdo_upload.hpp).

enum class string_object : std::uint8_t {
    device_name,       // 1008h "BlinkMarine"
    hardware_version,  // 1009h "V_03"
    firmware_version,  // 100Ah "V2.8"
    model_id,          // 100Bh "PK1000"
    serial_number,     // 2200h
};

[[nodiscard]] constexpr std::string_view to_string(string_object s) noexcept {
    switch (s) {
        case string_object::device_name: return "device_name";
        case string_object::hardware_version: return "hardware_version";
        case string_object::firmware_version: return "firmware_version";
        case string_object::model_id: return "model_id";
        case string_object::serial_number: return "serial_number";
    }
    return "";
}

struct string_value {
    static constexpr std::string_view value_kind = "pk1000_string";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("object", self.object);
        f("size", self.size);
        f("bytes", self.bytes);
    }
    string_object object = string_object::device_name;
    canopen::expedited_size size = 4;
    std::array<std::uint8_t, 4> bytes{};  // bytes past `size` are zero

    [[nodiscard]] constexpr bool canonical() const noexcept {
        for (std::size_t i = size.value(); i < 4; ++i)
            if (bytes[i] != 0) return false;
        return true;
    }

    static constexpr std::array<sdo_address, 5> table{
        {{0x1008, 0}, {0x1009, 0}, {0x100A, 0}, {0x100B, 0}, {0x2200, 0}}};
    [[nodiscard]] constexpr sdo_address address() const noexcept {
        return table[static_cast<std::size_t>(object)];
    }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept {
        return detail::table_covers<string_object>(table, a);
    }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        expedited_data d{size, {}};
        for (std::size_t i = 0; i < size.value(); ++i) d.bytes[i] = bytes[i];
        return d;
    }
    [[nodiscard]] static constexpr result<string_value> parse(sdo_address a,
                                                              const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, d.size.value()); e != errc{}) return e;
        return string_value{detail::table_find<string_object>(table, a), d.size, d.bytes};
    }
    friend constexpr bool operator==(const string_value&, const string_value&) noexcept = default;
};

// --- 1011h/01: restore default parameters (section 36) ----------------------------------------
// The write carries the signature "load" (6Ch 6Fh 61h 64h), nothing else; the defaults come back
// after the next reset. A read of 1011h/01 returns CiA 301 flags (bit 0: restores on command).

inline constexpr std::uint32_t load_signature = 0x6461'6F6C;  // "load", little endian

struct restore_defaults {
    static constexpr std::string_view set_kind = "pk1000_restore_defaults";
    template <class Self, class F>
    static constexpr void fields(Self&, F&&) {}

    static constexpr sdo_address at{0x1011, 1};
    [[nodiscard]] constexpr sdo_address address() const noexcept { return at; }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept { return a == at; }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return expedited_data::u32(load_signature);
    }
    [[nodiscard]] static constexpr result<restore_defaults> parse(
        sdo_address, const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 4); e != errc{}) return e;
        if (d.value() != load_signature) return errc::value_out_of_range;
        return restore_defaults{};
    }
    friend constexpr bool operator==(const restore_defaults&,
                                     const restore_defaults&) noexcept = default;
};

struct restore_capability {
    static constexpr std::string_view value_kind = "pk1000_restore_capability";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("flags", self.flags);
    }
    std::uint32_t flags = 0;

    static constexpr sdo_address at{0x1011, 1};
    [[nodiscard]] constexpr sdo_address address() const noexcept { return at; }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept { return a == at; }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return expedited_data::u32(flags);
    }
    [[nodiscard]] static constexpr result<restore_capability> parse(
        sdo_address, const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 4); e != errc{}) return e;
        return restore_capability{d.value()};
    }
    friend constexpr bool operator==(const restore_capability&,
                                     const restore_capability&) noexcept = default;
};

// --- sub-index 00h of the records: highest sub-index / number of entries, read only ----------

enum class record : std::uint8_t {
    consumer_heartbeat,  // 1016h
    restore,             // 1011h
    identity,            // 1018h
    rpdo1,               // 1400h
    rpdo2,               // 1401h
    rpdo3,               // 1402h
    rpdo4,               // 1403h
    rpdo1_mapping,       // 1600h
    rpdo2_mapping,       // 1601h
    rpdo3_mapping,       // 1602h
    rpdo4_mapping,       // 1603h
    tpdo1,               // 1800h
    tpdo1_mapping,       // 1A00h
};

[[nodiscard]] constexpr std::string_view to_string(record r) noexcept {
    switch (r) {
        case record::consumer_heartbeat: return "consumer_heartbeat";
        case record::restore: return "restore";
        case record::identity: return "identity";
        case record::rpdo1: return "rpdo1";
        case record::rpdo2: return "rpdo2";
        case record::rpdo3: return "rpdo3";
        case record::rpdo4: return "rpdo4";
        case record::rpdo1_mapping: return "rpdo1_mapping";
        case record::rpdo2_mapping: return "rpdo2_mapping";
        case record::rpdo3_mapping: return "rpdo3_mapping";
        case record::rpdo4_mapping: return "rpdo4_mapping";
        case record::tpdo1: return "tpdo1";
        case record::tpdo1_mapping: return "tpdo1_mapping";
    }
    return "";
}

struct subindex_count_value {
    static constexpr std::string_view value_kind = "pk1000_subindex_count";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("record", self.of);
        f("count", self.count);
    }
    record of = record::consumer_heartbeat;
    std::uint8_t count = 0;

    static constexpr std::array<sdo_address, 13> table{{{0x1016, 0},
                                                        {0x1011, 0},
                                                        {0x1018, 0},
                                                        {0x1400, 0},
                                                        {0x1401, 0},
                                                        {0x1402, 0},
                                                        {0x1403, 0},
                                                        {0x1600, 0},
                                                        {0x1601, 0},
                                                        {0x1602, 0},
                                                        {0x1603, 0},
                                                        {0x1800, 0},
                                                        {0x1A00, 0}}};
    [[nodiscard]] constexpr sdo_address address() const noexcept {
        return table[static_cast<std::size_t>(of)];
    }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept {
        return detail::table_covers<record>(table, a);
    }
    [[nodiscard]] constexpr expedited_data data() const noexcept { return detail::data_u8(count); }
    [[nodiscard]] static constexpr result<subindex_count_value> parse(
        sdo_address a, const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 1); e != errc{}) return e;
        return subindex_count_value{detail::table_find<record>(table, a), d.bytes[0]};
    }
    friend constexpr bool operator==(const subindex_count_value&,
                                     const subindex_count_value&) noexcept = default;
};

// --- 1018h: identity (section 37), read only ----------------------------------------------------

enum class identity_item : std::uint8_t { vendor_id = 0x01, serial_number = 0x04 };

[[nodiscard]] constexpr std::string_view to_string(identity_item i) noexcept {
    switch (i) {
        case identity_item::vendor_id: return "vendor_id";
        case identity_item::serial_number: return "serial_number";
    }
    return "";
}

// Blink Marine's CiA vendor id (section 37).
inline constexpr std::uint32_t blink_marine_vendor_id = 0x0000'03E2;

struct identity_value {
    static constexpr std::string_view value_kind = "pk1000_identity";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("item", self.item);
        f("value", self.value);
    }
    identity_item item = identity_item::vendor_id;
    std::uint32_t value = 0;

    [[nodiscard]] constexpr sdo_address address() const noexcept {
        return {0x1018, static_cast<std::uint8_t>(item)};
    }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept {
        return a.index == 0x1018 && (a.subindex == 1 || a.subindex == 4);
    }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return expedited_data::u32(value);
    }
    [[nodiscard]] static constexpr result<identity_value> parse(sdo_address a,
                                                                const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 4); e != errc{}) return e;
        return identity_value{static_cast<identity_item>(a.subindex), d.value()};
    }
    friend constexpr bool operator==(const identity_value&,
                                     const identity_value&) noexcept = default;
};

// --- 1400h..1403h, 1800h sub 1: PDO COB-IDs (sections 38-41, 46), read only -------------------
// CiA 301: bit 31 set = PDO not valid, bit 30 set = no RTR, bits 10..0 the 11-bit CAN id; bits
// 29..11 are zero for an 11-bit id. The keypad answers 4000 0200h + node and the like.

enum class pdo : std::uint8_t { rpdo1, rpdo2, rpdo3, rpdo4, tpdo1 };

[[nodiscard]] constexpr std::string_view to_string(pdo p) noexcept {
    switch (p) {
        case pdo::rpdo1: return "rpdo1";
        case pdo::rpdo2: return "rpdo2";
        case pdo::rpdo3: return "rpdo3";
        case pdo::rpdo4: return "rpdo4";
        case pdo::tpdo1: return "tpdo1";
    }
    return "";
}

struct pdo_cob_id_value {
    static constexpr std::string_view value_kind = "pk1000_pdo_cob_id";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("pdo", self.of);
        f("invalid", self.invalid);
        f("no_rtr", self.no_rtr);
        f("can_id", self.can_id);
    }
    pdo of = pdo::rpdo1;
    bool invalid = false;
    bool no_rtr = true;
    can::standard_id can_id = 0x215;

    static constexpr std::array<sdo_address, 5> table{
        {{0x1400, 1}, {0x1401, 1}, {0x1402, 1}, {0x1403, 1}, {0x1800, 1}}};
    [[nodiscard]] constexpr sdo_address address() const noexcept {
        return table[static_cast<std::size_t>(of)];
    }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept {
        return detail::table_covers<pdo>(table, a);
    }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return expedited_data::u32((invalid ? 0x8000'0000u : 0u) | (no_rtr ? 0x4000'0000u : 0u) |
                                   can_id.value());
    }
    [[nodiscard]] static constexpr result<pdo_cob_id_value> parse(
        sdo_address a, const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 4); e != errc{}) return e;
        const std::uint32_t v = d.value();
        if ((v & 0x3FFF'F800u) != 0) return errc::reserved_not_zero;
        return pdo_cob_id_value{detail::table_find<pdo>(table, a), (v >> 31) != 0,
                                ((v >> 30) & 1) != 0, can::standard_id::make(v & 0x7FF).value()};
    }
    friend constexpr bool operator==(const pdo_cob_id_value&,
                                     const pdo_cob_id_value&) noexcept = default;
};

// --- 1400h..1403h sub 2: RPDO transmission type (sections 38-41) ------------------------------
// 00h..F0h synchronous (applied at the next SYNC), FEh event-driven. Only 1400h and 1401h are
// writable; 1402h and 1403h are always FEh.

enum class rpdo : std::uint8_t { rpdo1, rpdo2, rpdo3, rpdo4 };

[[nodiscard]] constexpr std::string_view to_string(rpdo p) noexcept {
    if (static_cast<unsigned>(p) > static_cast<unsigned>(rpdo::rpdo4)) return "";
    return to_string(static_cast<pdo>(p));
}

struct rpdo_transmission_value {
    static constexpr std::string_view set_kind = "pk1000_set_rpdo_transmission";
    static constexpr std::string_view value_kind = "pk1000_rpdo_transmission";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("pdo", self.of);
        f("event_driven", self.event_driven);
        f("sync_type", self.sync_type);
    }
    rpdo of = rpdo::rpdo1;
    bool event_driven = true;
    rpdo_sync_type sync_type{};  // meaningful (and encoded) only when not event-driven

    [[nodiscard]] constexpr bool canonical() const noexcept {
        return !event_driven || sync_type == rpdo_sync_type{};
    }

    [[nodiscard]] constexpr sdo_address address() const noexcept {
        return {static_cast<std::uint16_t>(0x1400 + static_cast<unsigned>(of)), 2};
    }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept {
        return a.index >= 0x1400 && a.index <= 0x1403 && a.subindex == 2;
    }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return detail::data_u8(event_driven ? event_driven_type : sync_type.value());
    }
    [[nodiscard]] static constexpr result<rpdo_transmission_value> parse(
        sdo_address a, const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 1); e != errc{}) return e;
        const auto of = static_cast<rpdo>(a.index - 0x1400);
        if (d.bytes[0] == event_driven_type) return rpdo_transmission_value{of, true, {}};
        const auto t = rpdo_sync_type::make(d.bytes[0]);
        if (!t) return t.error();
        return rpdo_transmission_value{of, false, *t};
    }
    friend constexpr bool operator==(const rpdo_transmission_value&,
                                     const rpdo_transmission_value&) noexcept = default;
};

// --- 1800h sub 2 and sub 5: TPDO transmission type and event timer (section 46) -------------

struct tpdo_transmission_value {
    static constexpr std::string_view set_kind = "pk1000_set_tpdo_transmission";
    static constexpr std::string_view value_kind = "pk1000_tpdo_transmission";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("event_driven", self.event_driven);
        f("sync_type", self.sync_type);
    }
    bool event_driven = true;
    tpdo_sync_type sync_type{};  // every n-th SYNC; meaningful only when not event-driven

    [[nodiscard]] constexpr bool canonical() const noexcept {
        return !event_driven || sync_type == tpdo_sync_type{};
    }

    static constexpr sdo_address at{0x1800, 2};
    [[nodiscard]] constexpr sdo_address address() const noexcept { return at; }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept { return a == at; }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return detail::data_u8(event_driven ? event_driven_type : sync_type.value());
    }
    [[nodiscard]] static constexpr result<tpdo_transmission_value> parse(
        sdo_address, const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 1); e != errc{}) return e;
        if (d.bytes[0] == event_driven_type) return tpdo_transmission_value{};
        const auto t = tpdo_sync_type::make(d.bytes[0]);
        if (!t) return t.error();
        return tpdo_transmission_value{false, *t};
    }
    friend constexpr bool operator==(const tpdo_transmission_value&,
                                     const tpdo_transmission_value&) noexcept = default;
};

// Periodic key-state transmission: 0000h off, else 000Ah..FEFFh ms.
struct event_timer_value {
    static constexpr std::string_view set_kind = "pk1000_set_event_timer";
    static constexpr std::string_view value_kind = "pk1000_event_timer";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("enabled", self.enabled);
        f("period_ms", self.period_ms);
    }
    bool enabled = false;
    event_timer_ms period_ms{};

    [[nodiscard]] constexpr bool canonical() const noexcept {
        return enabled || period_ms == event_timer_ms{};
    }

    static constexpr sdo_address at{0x1800, 5};
    [[nodiscard]] constexpr sdo_address address() const noexcept { return at; }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept { return a == at; }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return expedited_data::u16(enabled ? period_ms.value() : std::uint16_t{0});
    }
    [[nodiscard]] static constexpr result<event_timer_value> parse(
        sdo_address, const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 2); e != errc{}) return e;
        if (d.value() == 0) return event_timer_value{};
        const auto period = event_timer_ms::make(d.value());
        if (!period) return period.error();
        return event_timer_value{true, *period};
    }
    friend constexpr bool operator==(const event_timer_value&,
                                     const event_timer_value&) noexcept = default;
};

// --- 1600h..1603h, 1A00h: PDO mapping entries (sections 42-45, 47), read only -----------------
// CiA 301: index in bits 31..16, sub-index in 15..8, length in bits in 7..0; e.g. 2001 01 20h.

enum class mapping_entry : std::uint8_t {
    rpdo1_1,  // 1600h/01
    rpdo1_2,  // 1600h/02
    rpdo2_1,  // 1601h/01
    rpdo2_2,  // 1601h/02
    rpdo3_1,  // 1602h/01
    rpdo4_1,  // 1603h/01
    rpdo4_2,  // 1603h/02
    tpdo1_1,  // 1A00h/01
};

[[nodiscard]] constexpr std::string_view to_string(mapping_entry m) noexcept {
    switch (m) {
        case mapping_entry::rpdo1_1: return "rpdo1_1";
        case mapping_entry::rpdo1_2: return "rpdo1_2";
        case mapping_entry::rpdo2_1: return "rpdo2_1";
        case mapping_entry::rpdo2_2: return "rpdo2_2";
        case mapping_entry::rpdo3_1: return "rpdo3_1";
        case mapping_entry::rpdo4_1: return "rpdo4_1";
        case mapping_entry::rpdo4_2: return "rpdo4_2";
        case mapping_entry::tpdo1_1: return "tpdo1_1";
    }
    return "";
}

struct pdo_mapping_value {
    static constexpr std::string_view value_kind = "pk1000_pdo_mapping";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("entry", self.at_entry);
        f("index", self.index);
        f("subindex", self.subindex);
        f("bits", self.bits);
    }
    mapping_entry at_entry = mapping_entry::rpdo1_1;
    std::uint16_t index = 0;    // the mapped object
    std::uint8_t subindex = 0;  // its sub-index
    std::uint8_t bits = 0;      // its length in bits

    static constexpr std::array<sdo_address, 8> table{{{0x1600, 1},
                                                       {0x1600, 2},
                                                       {0x1601, 1},
                                                       {0x1601, 2},
                                                       {0x1602, 1},
                                                       {0x1603, 1},
                                                       {0x1603, 2},
                                                       {0x1A00, 1}}};
    [[nodiscard]] constexpr sdo_address address() const noexcept {
        return table[static_cast<std::size_t>(at_entry)];
    }
    [[nodiscard]] static constexpr bool covers(sdo_address a) noexcept {
        return detail::table_covers<mapping_entry>(table, a);
    }
    [[nodiscard]] constexpr expedited_data data() const noexcept {
        return expedited_data::u32((std::uint32_t{index} << 16) | (std::uint32_t{subindex} << 8) |
                                   bits);
    }
    [[nodiscard]] static constexpr result<pdo_mapping_value> parse(
        sdo_address a, const expedited_data& d) noexcept {
        if (const auto e = detail::expect_size(d, 4); e != errc{}) return e;
        const std::uint32_t v = d.value();
        return pdo_mapping_value{detail::table_find<mapping_entry>(table, a),
                                 static_cast<std::uint16_t>(v >> 16),
                                 static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v)};
    }
    friend constexpr bool operator==(const pdo_mapping_value&,
                                     const pdo_mapping_value&) noexcept = default;
};

}  // namespace powerkey::pk1000

#endif  // POWERKEY_PK1000_OBJECTS_HPP
