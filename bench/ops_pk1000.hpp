// PK1000 operations at node 15h, all through the one codec (powerkey::decode / encode with
// model::pk1000). The inputs are the manual's own rows (tests/pk1000_rows.hpp, shared with the
// test suite), picked by family at compile time, so every row the manual prints for a family is
// measured; the messages the encoders measure are those rows decoded at compile time, and every
// input is proved to decode. Only a row's `frame`, `models` and `node` are read here.
#ifndef POWERKEY_BENCH_OPS_PK1000_HPP
#define POWERKEY_BENCH_OPS_PK1000_HPP

#include <powerkey/keypad/codec.hpp>

#include <array>
#include <cstddef>
#include <type_traits>

#include "ops.hpp"
#include "pk1000_rows.hpp"

namespace bench {

inline constexpr auto pk1000 = powerkey::model::pk1000;

namespace pk_detail {

// The keypad's node id of a row: 15h unless the row names another (a number or a node_id).
template <class Row>
constexpr unsigned node_of(const Row& r) {
    if constexpr (requires { r.node; }) {
        if constexpr (std::is_integral_v<std::remove_cvref_t<decltype(r.node)>>)
            return r.node;
        else
            return r.node.value();
    } else {
        return 0x15;
    }
}

template <class Row>
constexpr pc::frame frame_of(const Row& r) {
    return pc::parse_candump(r.frame).value();
}

// Rows of a PK1000 at node 15h whose frame has function `fn` and, for SDOs, an expedited specifier.
template <co::function Fn, class Row>
constexpr bool in_family(const Row& r) {
    if constexpr (requires { r.models; })
        if (!r.models.contains(pk1000)) return false;
    if (node_of(r) != node.value()) return false;
    const auto f = pc::parse_candump(r.frame);
    if (!f || co::classify(*f).fn != Fn) return false;
    if constexpr (Fn == co::function::sdo_rx) {
        const auto c = (*f)[0];
        return c == 0x23 || c == 0x27 || c == 0x2B || c == 0x2F || c == 0x40;
    } else if constexpr (Fn == co::function::sdo_tx) {
        const auto c = (*f)[0];
        return c == 0x43 || c == 0x47 || c == 0x4B || c == 0x4F || c == 0x60;
    }
    return true;
}
template <co::function Fn>
constexpr std::size_t family_size() {
    std::size_t n = 0;
    for (const auto& r : pk1000_rows::rows)
        if (in_family<Fn>(r)) ++n;
    return n;
}
template <co::function Fn>
constexpr auto family_frames() {
    std::array<pc::frame, family_size<Fn>()> a{};
    std::size_t i = 0;
    for (const auto& r : pk1000_rows::rows)
        if (in_family<Fn>(r)) a[i++] = frame_of(r);
    return a;
}
// The frames decoded: what the encoders are given.
template <std::size_t N>
constexpr auto messages_of(const std::array<pc::frame, N>& frames) {
    std::array<powerkey::message, N> a{};
    for (std::size_t i = 0; i < N; ++i) a[i] = powerkey::decode(frames[i], node, pk1000).value();
    return a;
}
}  // namespace pk_detail

inline constexpr auto pk_key_frames = pk_detail::family_frames<co::function::tpdo1>();
inline constexpr auto pk_key_messages = pk_detail::messages_of(pk_key_frames);
inline constexpr auto pk_led_on_frames = pk_detail::family_frames<co::function::rpdo1>();
inline constexpr auto pk_led_on_messages = pk_detail::messages_of(pk_led_on_frames);
inline constexpr auto pk_led_blink_frames = pk_detail::family_frames<co::function::rpdo2>();
inline constexpr auto pk_backlight_frames = pk_detail::family_frames<co::function::rpdo4>();
inline constexpr auto pk_backlight_messages = pk_detail::messages_of(pk_backlight_frames);
inline constexpr auto pk_sdo_request_frames = pk_detail::family_frames<co::function::sdo_rx>();
inline constexpr auto pk_sdo_request_messages = pk_detail::messages_of(pk_sdo_request_frames);
inline constexpr auto pk_sdo_response_frames = pk_detail::family_frames<co::function::sdo_tx>();
inline constexpr auto pk_sdo_response_messages = pk_detail::messages_of(pk_sdo_response_frames);

inline constexpr auto pk_all_rows = [] {
    std::array<pc::frame, std::size(pk1000_rows::rows)> a{};
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = pk_detail::frame_of(pk1000_rows::rows[i]);
    return a;
}();

// The PK1000 counterpart of the PKP mixed log: key-state and LED PDOs, brightness and backlight,
// heartbeat, SYNC, configuration SDOs with replies, and other devices' traffic.
inline constexpr std::array pk_mixed_log = {
    candump("000#0115"),
    candump("715#05"),
    candump("215#0100000000000000"),
    candump("195#010000002A"),
    candump("196#0100000000"),
    candump("315#0200000000000000"),
    candump("195#000000002B"),
    candump("080#"),
    candump("215#0500000000000000"),
    candump("195#090000002C"),
    candump("716#05"),
    candump("215#0000000000200000"),
    candump("615#4000200100000000"),
    candump("595#4B00200101000000"),
    candump("195#000100002D"),
    candump("18FEF100#FFFFFFFFFFFFFFFF"),
    candump("715#05"),
    candump("215#0000010000000008"),
    candump("195#000000002E"),
    candump("315#0500000000000000"),
    candump("080#"),
    candump("195#010000002F"),
    candump("216#0100000000000000"),
    candump("215#0000000000000000"),
    candump("195#0000000030"),
    candump("715#05"),
    candump("415#0800000000000000"),
    candump("515#2003000000000000"),
    candump("195#0800000031"),
    candump("215#0102040880402000"),
    candump("195#0000000032"),
    candump("080#"),
    candump("315#0000010000000008"),
    candump("195#0002000033"),
    candump("715#05"),
    candump("215#0100000000000000"),
    candump("195#0000000034"),
    candump("196#0000000000"),
    candump("415#1000000000000000"),
    candump("515#0000000000000000"),
    candump("195#0100000035"),
    candump("215#0500000000000000"),
    candump("080#"),
    candump("195#0000000036"),
    candump("715#05"),
    candump("315#0200000000000000"),
    candump("195#0900000037"),
    candump("215#0000000000200000"),
    candump("716#05"),
    candump("195#0000000038"),
    candump("215#0000000000000000"),
    candump("615#4000200100000000"),
    candump("595#4B00200100000000"),
    candump("195#0100000039"),
    candump("080#"),
    candump("715#05"),
    candump("195#000000003A"),
    candump("215#0500000000000000"),
    candump("315#0000000000000000"),
    candump("195#080000003B"),
    candump("18FEF100#FFFFFFFFFFFFFFFF"),
    candump("195#000000003C"),
    candump("715#05"),
    candump("215#0100000000000000"),
};

namespace pk_detail {
constexpr auto decode_pk = [](const pc::frame& f) { return powerkey::decode(f, node, pk1000); };
}  // namespace pk_detail
static_assert(detail::all_decode(pk_key_frames, pk_detail::decode_pk) && pk_key_frames.size() >= 6);
static_assert(detail::all_decode(pk_led_on_frames, pk_detail::decode_pk));
static_assert(detail::all_decode(pk_led_blink_frames, pk_detail::decode_pk));
static_assert(detail::all_decode(pk_backlight_frames, pk_detail::decode_pk));
static_assert(detail::all_decode(pk_sdo_request_frames, pk_detail::decode_pk));
static_assert(detail::all_decode(pk_sdo_response_frames, pk_detail::decode_pk));

// 57 of the 64 frames are the keypad's; the J1939 frames and those of node 16h are refused.
inline constexpr std::size_t pk_mixed_log_keypad_frames = keypad_frames(pk_mixed_log, pk1000);
static_assert(pk_mixed_log_keypad_frames == pk_mixed_log.size() - 7);

inline constexpr auto pk_mixed_log_messages =
    keypad_messages<pk_mixed_log_keypad_frames>(pk_mixed_log, pk1000);

inline void pk_key_state_decode(std::size_t calls) { decode_all(pk_key_frames, pk1000, calls); }
inline void pk_key_state_encode(std::size_t calls) { encode_all(pk_key_messages, pk1000, calls); }
inline void pk_led_on_decode(std::size_t calls) { decode_all(pk_led_on_frames, pk1000, calls); }
inline void pk_led_on_encode(std::size_t calls) { encode_all(pk_led_on_messages, pk1000, calls); }
inline void pk_led_blink_decode(std::size_t calls) {
    decode_all(pk_led_blink_frames, pk1000, calls);
}
inline void pk_backlight_decode(std::size_t calls) {
    decode_all(pk_backlight_frames, pk1000, calls);
}
inline void pk_backlight_encode(std::size_t calls) {
    encode_all(pk_backlight_messages, pk1000, calls);
}
inline void pk_sdo_request_decode(std::size_t calls) {
    decode_all(pk_sdo_request_frames, pk1000, calls);
}
inline void pk_sdo_response_decode(std::size_t calls) {
    decode_all(pk_sdo_response_frames, pk1000, calls);
}
inline void pk_sdo_request_encode(std::size_t calls) {
    encode_all(pk_sdo_request_messages, pk1000, calls);
}
inline void pk_sdo_response_encode(std::size_t calls) {
    encode_all(pk_sdo_response_messages, pk1000, calls);
}
inline void pk_decode_all_rows(std::size_t calls) { decode_all(pk_all_rows, pk1000, calls); }
inline void any_pk1000_decode_mixed_log(std::size_t calls) {
    decode_all(pk_mixed_log, pk1000, calls);
}
inline void one_pk1000_decode_mixed_log(std::size_t calls) {
    const auto n = opaque(node);
    cycle(pk_mixed_log, calls, [n](const pc::frame& f) BENCH_INLINE {
        return powerkey::decode<powerkey::model::pk1000>(f, n);
    });
}
inline void any_pk1000_encode_mixed_log(std::size_t calls) {
    encode_all(pk_mixed_log_messages, pk1000, calls);
}

inline constexpr op pk1000_ops[] = {
    {"pk1000/key_state/decode", pk_key_state_decode},
    {"pk1000/key_state/encode", pk_key_state_encode},
    {"pk1000/led_on/decode", pk_led_on_decode},
    {"pk1000/led_on/encode", pk_led_on_encode},
    {"pk1000/led_blink/decode", pk_led_blink_decode},
    {"pk1000/backlight/decode", pk_backlight_decode},
    {"pk1000/backlight/encode", pk_backlight_encode},
    {"pk1000/sdo/decode_request", pk_sdo_request_decode},
    {"pk1000/sdo/decode_response", pk_sdo_response_decode},
    {"pk1000/sdo/encode_request", pk_sdo_request_encode},
    {"pk1000/sdo/encode_response", pk_sdo_response_encode},
    {"pk1000/decode/all_manual_rows", pk_decode_all_rows},
    {"any/pk1000/decode_mixed_log", any_pk1000_decode_mixed_log},
    {"one/pk1000/decode_mixed_log", one_pk1000_decode_mixed_log},
    {"any/pk1000/encode_mixed_log", any_pk1000_encode_mixed_log, "frame (keypad frames only)"},
};

}  // namespace bench

#endif  // POWERKEY_BENCH_OPS_PK1000_HPP
