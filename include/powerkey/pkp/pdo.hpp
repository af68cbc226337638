// powerkey PKP: the three PDOs (PKP manual sections 10-12, reference/pkp-2600.md).
//   key state  TPDO1 180h + node, 5 bytes: bytes 0..1 keys K1..K12 (bit k-1), bytes 2..3 00h,
//              byte 4 tick timer (+1 every 100 ms, wraps)
//   LED on     RPDO1 200h + node, 8 bytes: the LED bit map (model.hpp), unused bits and bytes 00h
//   LED blink  RPDO2 300h + node, 8 bytes: the same map; on + blink = alternate blink
#ifndef POWERKEY_PKP_PDO_HPP
#define POWERKEY_PKP_PDO_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/detail/checks.hpp>
#include <powerkey/pkp/model.hpp>
#include <powerkey/result.hpp>

#include <cstdint>
#include <string_view>

namespace powerkey::pkp {

// Section 10: which keys are pressed, and the tick timer (units of 100 ms, 00h..FFh, wraps).
struct key_state {
    static constexpr std::string_view kind = "pkp_key_state";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("keys", self.keys);
        f("tick", self.tick);
    }
    key_set keys;
    std::uint8_t tick = 0;
    friend constexpr bool operator==(const key_state&, const key_state&) noexcept = default;
};

// Section 11: which LEDs are on (red, green, blue sets of keys).
struct led_on_tag {
    static constexpr std::string_view kind = "pkp_led_on";
};
using led_on = leds_message<led_on_tag>;

// Section 12: which LEDs blink; an LED also on in led_on blinks in alternate mode.
struct led_blink_tag {
    static constexpr std::string_view kind = "pkp_led_blink";
};
using led_blink = leds_message<led_blink_tag>;

namespace detail {
constexpr can::frame led_pdo(canopen::function fn, canopen::node_id node, model m,
                             const leds& l) noexcept {
    can::payload p{};
    pack_leds(m, l, 3, p, 0, 8);
    return can::frame(canopen::cob_id(fn, node), 8, p);
}
constexpr result<leds> decode_led_pdo(canopen::function fn, const can::frame& f,
                                      canopen::node_id node, model m) noexcept {
    if (const auto e = powerkey::detail::check_frame(f, canopen::cob_id(fn, node), 8); e != errc{})
        return e;
    return unpack_leds(m, f.bytes(), 3, 0, 8);
}
}  // namespace detail

// Errors: value_out_of_range (a key above the model's key count).
[[nodiscard]] constexpr result<can::frame> encode(canopen::node_id node, model m,
                                                  const key_state& s) noexcept {
    if (!detail::keys_fit(m, s.keys) || key_count(m) == 0) return errc::value_out_of_range;
    can::payload p{};
    detail::pack_keys(s.keys, p, 0);
    p[4] = s.tick;
    return can::frame(canopen::cob_id(canopen::function::tpdo1, node), 5, p);
}
[[nodiscard]] constexpr result<can::frame> encode(canopen::node_id node, model m,
                                                  const led_on& s) noexcept {
    if (!s.value.fits(m)) return errc::value_out_of_range;
    return detail::led_pdo(canopen::function::rpdo1, node, m, s.value);
}
[[nodiscard]] constexpr result<can::frame> encode(canopen::node_id node, model m,
                                                  const led_blink& s) noexcept {
    if (!s.value.fits(m)) return errc::value_out_of_range;
    return detail::led_pdo(canopen::function::rpdo2, node, m, s.value);
}

// Compile-time model: the map cannot name a key the model lacks, so these cannot fail.
template <model M>
[[nodiscard]] constexpr can::frame encode_led_on(canopen::node_id node,
                                                 const led_map<M>& map) noexcept {
    return detail::led_pdo(canopen::function::rpdo1, node, M, map.value());
}
template <model M>
[[nodiscard]] constexpr can::frame encode_led_blink(canopen::node_id node,
                                                    const led_map<M>& map) noexcept {
    return detail::led_pdo(canopen::function::rpdo2, node, M, map.value());
}

// Errors: wrong_id_format, wrong_id (not 180h + node), wrong_length (not 5 bytes),
// reserved_not_zero (a key bit above the model's keys, or bytes 2..3 not 00h).
[[nodiscard]] constexpr result<key_state> decode_key_state(const can::frame& f,
                                                           canopen::node_id node,
                                                           model m) noexcept {
    if (const auto e =
            powerkey::detail::check_frame(f, canopen::cob_id(canopen::function::tpdo1, node), 5);
        e != errc{})
        return e;
    const auto keys = detail::unpack_keys(m, f.bytes(), 0, 4);
    if (!keys) return keys.error();
    return key_state{*keys, f[4]};
}

// Errors: wrong_id_format, wrong_id (not 200h + node), wrong_length (not 8 bytes),
// reserved_not_zero (a bit that names no LED of the model).
[[nodiscard]] constexpr result<led_on> decode_led_on(const can::frame& f, canopen::node_id node,
                                                     model m) noexcept {
    const auto l = detail::decode_led_pdo(canopen::function::rpdo1, f, node, m);
    if (!l) return l.error();
    return led_on{*l};
}

// Errors: as decode_led_on, for 300h + node.
[[nodiscard]] constexpr result<led_blink> decode_led_blink(const can::frame& f,
                                                           canopen::node_id node,
                                                           model m) noexcept {
    const auto l = detail::decode_led_pdo(canopen::function::rpdo2, f, node, m);
    if (!l) return l.error();
    return led_blink{*l};
}

}  // namespace powerkey::pkp

#endif  // POWERKEY_PKP_PDO_HPP
