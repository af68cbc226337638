// powerkey: the 64-bit J1939 NAME a device claims its address with (PGN EE00h, J1939-81 4.1.1),
// sent little endian in the 8 data bytes of the address claim. Bits, least significant first:
//   0..20 identity number | 21..31 manufacturer code | 32..34 ECU instance |
//   35..39 function instance | 40..47 function | 48 reserved (0) | 49..55 vehicle system |
//   56..59 vehicle system instance | 60..62 industry group | 63 arbitrary address capable
// The keypads' manuals print one NAME only (PKP1600SI and PKP2600SI J1939 manuals, section 20):
// 3F 42 6F 1A 00 82 3C C0, identity 999999, manufacturer 211, function 130, vehicle system 30,
// industry group 4, arbitrary address capable; the field split is J1939-81's (docs/j1939.md).
#ifndef POWERKEY_J1939_NAME_HPP
#define POWERKEY_J1939_NAME_HPP

#include <powerkey/bounded.hpp>
#include <powerkey/detail/message.hpp>
#include <powerkey/result.hpp>

#include <cstdint>

namespace powerkey::j1939 {

struct identity_number_tag;
struct manufacturer_code_tag;
struct ecu_instance_tag;
struct function_instance_tag;
struct vehicle_system_tag;
struct vehicle_system_instance_tag;
struct industry_group_tag;

struct name {
    POWERKEY_DETAIL_FIELDS(f("identity_number", self.identity_number),
                           f("manufacturer_code", self.manufacturer_code),
                           f("ecu_instance", self.ecu_instance),
                           f("function_instance", self.function_instance),
                           f("function", self.function), f("vehicle_system", self.vehicle_system),
                           f("vehicle_system_instance", self.vehicle_system_instance),
                           f("industry_group", self.industry_group),
                           f("arbitrary_address_capable", self.arbitrary_address_capable));
    bounded<identity_number_tag, std::uint32_t, 0, 0x1F'FFFF> identity_number = 0;
    bounded<manufacturer_code_tag, std::uint16_t, 0, 0x7FF> manufacturer_code = 0;
    bounded<ecu_instance_tag, std::uint8_t, 0, 7> ecu_instance = 0;
    bounded<function_instance_tag, std::uint8_t, 0, 0x1F> function_instance = 0;
    std::uint8_t function = 0;
    bounded<vehicle_system_tag, std::uint8_t, 0, 0x7F> vehicle_system = 0;
    bounded<vehicle_system_instance_tag, std::uint8_t, 0, 0xF> vehicle_system_instance = 0;
    bounded<industry_group_tag, std::uint8_t, 0, 7> industry_group = 0;
    bool arbitrary_address_capable = false;
    friend constexpr bool operator==(const name&, const name&) noexcept = default;
};

// The 64-bit value of n (bit 48, reserved, 0).
[[nodiscard]] constexpr std::uint64_t pack_name(const name& n) noexcept {
    return std::uint64_t{n.identity_number.value()} |
           (std::uint64_t{n.manufacturer_code.value()} << 21) |
           (std::uint64_t{n.ecu_instance.value()} << 32) |
           (std::uint64_t{n.function_instance.value()} << 35) | (std::uint64_t{n.function} << 40) |
           (std::uint64_t{n.vehicle_system.value()} << 49) |
           (std::uint64_t{n.vehicle_system_instance.value()} << 56) |
           (std::uint64_t{n.industry_group.value()} << 60) |
           (std::uint64_t{n.arbitrary_address_capable ? 1u : 0u} << 63);
}

// The fields of a 64-bit NAME; errc::reserved_not_zero when bit 48 is set.
[[nodiscard]] constexpr result<name> unpack_name(std::uint64_t v) noexcept {
    if (((v >> 48) & 1u) != 0) return errc::reserved_not_zero;
    const auto bits = [v](unsigned at, unsigned n) {
        return static_cast<std::uint32_t>((v >> at) & ((std::uint64_t{1} << n) - 1));
    };
    name n;
    // Each field is cut to its width, so every make() succeeds.
    n.identity_number = decltype(n.identity_number)::make(bits(0, 21)).value();
    n.manufacturer_code = decltype(n.manufacturer_code)::make(bits(21, 11)).value();
    n.ecu_instance = decltype(n.ecu_instance)::make(bits(32, 3)).value();
    n.function_instance = decltype(n.function_instance)::make(bits(35, 5)).value();
    n.function = static_cast<std::uint8_t>(bits(40, 8));
    n.vehicle_system = decltype(n.vehicle_system)::make(bits(49, 7)).value();
    n.vehicle_system_instance = decltype(n.vehicle_system_instance)::make(bits(56, 4)).value();
    n.industry_group = decltype(n.industry_group)::make(bits(60, 3)).value();
    n.arbitrary_address_capable = bits(63, 1) != 0;
    return n;
}

}  // namespace powerkey::j1939

#endif  // POWERKEY_J1939_NAME_HPP
