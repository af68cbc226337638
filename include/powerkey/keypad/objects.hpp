// powerkey: the vocabulary of the object dictionaries, every object of every keypad one row of
// POWERKEY_OBJECTS named by its meaning (docs/models.md, "The object vocabulary").
#ifndef POWERKEY_KEYPAD_OBJECTS_HPP
#define POWERKEY_KEYPAD_OBJECTS_HPP

#include <powerkey/canopen/sdo.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/keypad/values.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace powerkey {

// What an object's value is: its fields, checks and packing, each kind's in value_kinds.hpp. The
// list of kinds, in the order of the enum.
// clang-format off
#define POWERKEY_VALUE_KINDS(X)                                                                   \
    X(number) X(flag) X(brightness) X(colour) X(baud) X(show) X(node) X(period) X(keys)          \
    X(led_plane) X(led_map) X(consumer_heartbeat) X(cob_id) X(pdo_mapping) X(device_type)       \
    X(string) X(restore) X(led_part) X(ring) X(direction_counter) X(none) X(commands)
// clang-format on

enum class value_kind : std::uint8_t { POWERKEY_VALUE_KINDS(POWERKEY_DETAIL_ENUMERATOR) };

}  // namespace powerkey

POWERKEY_DETAIL_ENUM_NAMES(powerkey::value_kind, POWERKEY_VALUE_KINDS);

namespace powerkey {

// Every object of every dictionary: X(name, value kind) and, for an LED plane, the plane it holds
// (led_plane), or for a piece of the LED string the plane its first bit is in, the bit and the
// width (led_part). Appending keeps the numbers of the objects before it.
// clang-format off
#define POWERKEY_OBJECTS(X) \
    /* keys and LEDs */ \
    X(keys, keys) \
    X(led_on, led_map)  /* the whole map, the model's planes that fit 32 bits */ \
    X(led_blink, led_map) \
    X(led_on_red, led_plane, red)  /* one plane */ \
    X(led_on_green, led_plane, green) \
    X(led_blink_red, led_plane, red) \
    X(led_blink_green, led_plane, green) \
    /* brightness and backlight */ \
    X(led_brightness, brightness) \
    X(backlight_level, brightness) \
    X(backlight_colour, colour) \
    X(default_backlight_colour, colour) \
    X(default_led_brightness, brightness) \
    X(default_backlight_level, brightness) \
    X(brightness_count, number) \
    /* settings */ \
    X(baud_rate, baud) \
    X(boot_up, flag)  /* send the boot-up message at power on */ \
    X(active_on_startup, flag)  /* operational at power on without NMT start */ \
    X(node_id, node) \
    X(startup_show, show) \
    X(led_power, flag)  /* LED supply; off = low power */ \
    X(demo_mode, flag) \
    X(protocol_j1939, flag)  /* 1 switches the keypad to J1939 */ \
    X(protocol_rs485, flag) \
    X(command_module, commands)  /* write only, commands.hpp */ \
    /* heartbeat */ \
    X(consumer_heartbeat_count, number) \
    X(consumer_heartbeat, consumer_heartbeat) \
    X(heartbeat_time, period)  /* producer period */ \
    /* identification */ \
    X(device_type, device_type) \
    X(error_register, none)  /* not implemented, the keypad aborts a read */ \
    X(device_name, string) \
    X(hardware_version, string) \
    X(software_version, string) \
    X(model_name, string) \
    X(serial_number_string, string)  /* string */ \
    X(device_model, string)  /* string */ \
    X(firmware_spec_count, number) \
    X(identity_count, number) \
    X(vendor_id, number) \
    X(product_code, number) \
    X(revision_number, number)  /* byte 4 app, 5 com lib, 6 hw lib revision */ \
    X(serial_number, number) \
    X(firmware_checksum, number) \
    X(bootloader_present, number) \
    X(key_led_count_count, number) \
    X(total_keys, number) \
    X(external_keys, number) \
    X(total_leds, number) \
    X(external_leds, number) \
    X(restore_count, number) \
    X(restore_defaults, restore)  /* write "load"; a read gives the restore flags */ \
    /* PDO communication and mapping parameters */ \
    X(rpdo1_count, number) \
    X(rpdo1_cob_id, cob_id) \
    X(rpdo1_transmission_type, number) \
    X(rpdo1_inhibit_time, number) \
    X(rpdo2_count, number) \
    X(rpdo2_cob_id, cob_id) \
    X(rpdo2_transmission_type, number) \
    X(rpdo2_inhibit_time, number) \
    X(rpdo3_count, number) \
    X(rpdo3_cob_id, cob_id) \
    X(rpdo3_transmission_type, number) \
    X(rpdo4_count, number) \
    X(rpdo4_cob_id, cob_id) \
    X(rpdo4_transmission_type, number) \
    X(rpdo1_mapping_count, number) \
    X(rpdo1_mapping_1, pdo_mapping) \
    X(rpdo1_mapping_2, pdo_mapping) \
    X(rpdo2_mapping_count, number) \
    X(rpdo2_mapping_1, pdo_mapping) \
    X(rpdo2_mapping_2, pdo_mapping) \
    X(rpdo3_mapping_count, number) \
    X(rpdo3_mapping_1, pdo_mapping) \
    X(rpdo4_mapping_count, number) \
    X(rpdo4_mapping_1, pdo_mapping) \
    X(rpdo4_mapping_2, pdo_mapping) \
    X(tpdo1_count, number) \
    X(tpdo1_cob_id, cob_id) \
    X(tpdo1_transmission_type, number) \
    X(tpdo1_inhibit_time, number) \
    X(tpdo1_event_timer, period) \
    X(tpdo1_mapping_count, number) \
    X(tpdo1_mapping_1, pdo_mapping) \
    /* The SI family (docs/si-family.md): "2600SI n" is the PKP2600SI manual's section n, "MT n" */ \
    /* the PKP3500-MT manual's. */ \
    X(led_on_blue, led_plane, blue)  /* one plane */ \
    X(led_blink_blue, led_plane, blue) \
    X(led_on_r1_12_g1_4, led_part, red, 0, 16)  /* bits 0..15 of the LED-on string */ \
    X(led_on_g5_12, led_part, red, 16, 8)  /* bits 16..23 */ \
    X(led_on_b1_12, led_part, red, 24, 12)  /* bits 24..35 */ \
    X(led_blink_r1_12_g1_4, led_part, red, 0, 16) \
    X(led_blink_g5_12, led_part, red, 16, 8) \
    X(led_blink_b1_12, led_part, red, 24, 12) \
    X(led_on_encoder, ring)  /* the encoder rings, LEDs 1..32 */ \
    X(led_blink_encoder, ring) \
    X(encoder1_direction_counter, direction_counter)  /* bit 7 counterclockwise, bits 0..6 ticks */ \
    X(encoder1_tick_counter, number)  /* read the count, write the start-up count */ \
    X(encoder2_direction_counter, direction_counter) \
    X(encoder2_tick_counter, number) \
    X(encoder1_top_position, number)  /* 00h none, 02h..10h ticks */ \
    X(encoder2_top_position, number) \
    X(digital_input_count, number) \
    X(digital_inputs, number)  /* bit 0 IN0 .. bit 3 IN3 */ \
    X(analog_input_count, number) \
    X(analog_input_0, number)  /* 00h..FFh = 0..5 V */ \
    X(analog_input_1, number) \
    X(analog_input_2, number) \
    X(analog_input_3, number) \
    X(analog_input_period, number)  /* 08h..C8h x 10 ms */ \
    X(rpdo1_mapping_3, pdo_mapping) \
    X(rpdo2_mapping_3, pdo_mapping) \
    X(tpdo2_count, number)  /* encoder 1 */ \
    X(tpdo2_cob_id, cob_id) \
    X(tpdo2_transmission_type, number) \
    X(tpdo2_event_timer, period) \
    X(tpdo3_count, number)  /* encoder 2 */ \
    X(tpdo3_cob_id, cob_id) \
    X(tpdo3_transmission_type, number) \
    X(tpdo3_event_timer, period) \
    X(tpdo4_count, number)  /* analog inputs */ \
    X(tpdo4_cob_id, cob_id) \
    X(tpdo4_transmission_type, number) \
    X(tpdo2_mapping_count, number) \
    X(tpdo2_mapping_1, pdo_mapping) \
    X(tpdo2_mapping_2, pdo_mapping) \
    X(tpdo2_mapping_3, pdo_mapping) \
    X(tpdo3_mapping_count, number) \
    X(tpdo3_mapping_1, pdo_mapping) \
    X(tpdo3_mapping_2, pdo_mapping) \
    X(tpdo3_mapping_3, pdo_mapping)

// clang-format on

enum class object : std::uint8_t {
#define POWERKEY_DETAIL_OBJECT_ENUM(name, ...) name,
    POWERKEY_OBJECTS(POWERKEY_DETAIL_OBJECT_ENUM)
#undef POWERKEY_DETAIL_OBJECT_ENUM
};

// What an object is: its name, its value kind, and for an LED plane the plane it holds.
struct object_info {
    object id;
    std::string_view name;
    value_kind kind;
    plane holds = plane::red;  // led_plane; led_part: the plane of its first bit
    std::uint8_t offset = 0;   // led_part: the first bit of the LED string it carries
    std::uint8_t width = 0;    // led_part: how many bits
};

namespace detail {
// The extras of a row, if any, start with the plane: X(led_on_red, led_plane, red).
#define POWERKEY_DETAIL_OBJECT_INFO(name, kind, ...) \
    object_info{object::name, #name, value_kind::kind __VA_OPT__(, plane::) __VA_ARGS__},
inline constexpr object_info object_infos[] = {POWERKEY_OBJECTS(POWERKEY_DETAIL_OBJECT_INFO)};
#undef POWERKEY_DETAIL_OBJECT_INFO
}  // namespace detail

inline constexpr std::size_t object_count = std::size(detail::object_infos);

// What an object is; kind `none` and no name for a value outside the enum.
[[nodiscard]] constexpr object_info info(object id) noexcept {
    const auto i = static_cast<std::size_t>(id);
    return i < object_count ? detail::object_infos[i] : object_info{id, {}, value_kind::none};
}

template <>
struct enum_names<object> {
    static constexpr auto entries = [] {
        std::array<enum_name_entry<object>, object_count> t{};
        for (std::size_t i = 0; i < t.size(); ++i)
            t[i] = {detail::object_infos[i].id, detail::object_infos[i].name};
        return t;
    }();
};

// clang-format off
#define POWERKEY_ACCESS_LIST(X) \
    X(read_only) \
    X(write_only) \
    X(read_write)
// clang-format on
enum class access : std::uint8_t { POWERKEY_ACCESS_LIST(POWERKEY_DETAIL_ENUMERATOR) };

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

// The dictionary families (dictionaries.hpp has their rows): X(name).
#define POWERKEY_DICTIONARIES(X) X(pk1000) X(pkp_li) X(si_packed) X(si_mt) X(si_per_colour)

enum class dictionary : std::uint8_t { POWERKEY_DICTIONARIES(POWERKEY_DETAIL_ENUMERATOR) };

}  // namespace powerkey

POWERKEY_DETAIL_ENUM_NAMES(powerkey::dictionary, POWERKEY_DICTIONARIES);
POWERKEY_DETAIL_ENUM_NAMES(powerkey::access, POWERKEY_ACCESS_LIST);

namespace powerkey {
inline constexpr std::size_t dictionary_count = std::size(enum_names<dictionary>::entries);
}  // namespace powerkey

#endif  // POWERKEY_KEYPAD_OBJECTS_HPP
