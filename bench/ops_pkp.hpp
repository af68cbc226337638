// PKP-2400 operations at node 15h through the one codec (powerkey::decode / encode with
// model::pkp2400), and the any-frame decoder on a mixed log. Inputs are frames printed in the PKP
// manual (sections 10-13, 14-17); each is proved at compile time to decode, so that no benchmark
// silently measures an error path.
#ifndef POWERKEY_BENCH_OPS_PKP_HPP
#define POWERKEY_BENCH_OPS_PKP_HPP

#include <powerkey/keypad/codec.hpp>

#include <array>
#include <cstddef>
#include <initializer_list>

#include "ops.hpp"

namespace bench {

inline constexpr powerkey::model pkp_model = powerkey::model::pkp2400;

// Section 10 (PKP-2400 table; the tick byte, XX in the manual, is filled in).
inline constexpr std::array pkp_key_frames = {
    candump("195#0000000011"),
    candump("195#0100000012"),
    candump("195#0200000013"),
    candump("195#4200000014"),
};
// Sections 11 and 12 (PKP-2400 tables).
inline constexpr std::array pkp_led_on_frames = {
    candump("215#0000000000000000"), candump("215#0100000000000000"),
    candump("215#4200000000000000"), candump("215#0011000000000000"),
    candump("215#596A740000000000"),
};
inline constexpr std::array pkp_led_blink_frames = {
    candump("315#0100000000000000"),
    candump("315#4200000000000000"),
    candump("315#0000060000000000"),
    candump("315#0007070000000000"),
};
// Expedited SDO requests: the command module (13), LED map write (15), heartbeat time (17).
inline constexpr std::array pkp_sdo_request_frames = {
    candump("615#2300650101080100"), candump("615#2300650102100000"),
    candump("615#23006501032F0000"), candump("615#2300650112013200"),
    candump("615#2301600000010000"), candump("615#4000600000000000"),
    candump("615#2B17100032000000"), candump("615#4017100000000000"),
};
// Expedited SDO responses.
inline constexpr std::array pkp_sdo_response_frames = {
    candump("595#6000650100000000"),
    candump("595#6001600000000000"),
    candump("595#4301600001000000"),
    candump("595#4301600000FF0000"),
};

inline constexpr std::array pkp_key_messages = {
    powerkey::message{powerkey::key_state{{}, 0x11}},
    powerkey::message{powerkey::key_state{{1}, 0x12}},
    powerkey::message{powerkey::key_state{{2}, 0x13}},
    powerkey::message{powerkey::key_state{{2, 7}, 0x14}}};
inline constexpr std::array pkp_led_messages = {
    powerkey::message{powerkey::led_on{powerkey::leds{{1}, {}, {}}}},
    powerkey::message{powerkey::led_on{powerkey::leds{{2, 7}, {}, {}}}},
    powerkey::message{powerkey::led_on{powerkey::leds{{}, {1, 5}, {}}}},
    powerkey::message{powerkey::led_on{powerkey::leds{{1, 4, 5, 7}, {2, 4, 6, 7}, {3, 5, 6, 7}}}}};
// The same maps as a firmware builds them from run-time key numbers: (key, colour) pairs.
struct led_request {
    unsigned key;
    powerkey::colour c;
    unsigned key2;
    powerkey::colour c2;
};
inline constexpr std::array pkp_led_requests = {
    led_request{1, powerkey::colour::red, 0, powerkey::colour::off},
    led_request{2, powerkey::colour::red, 7, powerkey::colour::red},
    led_request{1, powerkey::colour::green, 5, powerkey::colour::green},
    led_request{1, powerkey::colour::amber, 8, powerkey::colour::white}};
inline constexpr std::array pkp_sdo_messages = {
    powerkey::message{powerkey::command{.code = powerkey::command_code::set_led_state,
                                        .key = 8,
                                        .state = powerkey::led_state::red_on}},
    powerkey::message{
        powerkey::command{.code = powerkey::command_code::set_led_brightness, .level = 0x10}},
    powerkey::message{
        powerkey::sdo_write{powerkey::object::heartbeat_time, powerkey::number_value(50)}},
    powerkey::message{powerkey::sdo_read{powerkey::object::heartbeat_time}},
};

// A realistic minute on a bus, compressed to 64 frames: mostly key-state and LED PDOs, the
// keypad's heartbeat, SYNC, a few configuration SDOs with their replies, and traffic of other
// devices (another node's PDO and heartbeat, a J1939 frame), which the decoder must refuse.
inline constexpr std::array mixed_log = {
    candump("000#0115"),
    candump("715#05"),
    candump("215#0100000000000000"),
    candump("195#0100000012"),
    candump("196#0100000000"),
    candump("315#0000060000000000"),
    candump("195#0000000013"),
    candump("080#"),
    candump("215#4200000000000000"),
    candump("195#4200000014"),
    candump("716#05"),
    candump("215#0011000000000000"),
    candump("615#2300650102100000"),
    candump("595#6000650100000000"),
    candump("195#0200000015"),
    candump("18FEF100#FFFFFFFFFFFFFFFF"),
    candump("715#05"),
    candump("215#596A740000000000"),
    candump("195#0000000016"),
    candump("315#0100000000000000"),
    candump("080#"),
    candump("195#0100000017"),
    candump("216#0100000000000000"),
    candump("215#0000000000000000"),
    candump("195#0000000018"),
    candump("715#05"),
    candump("615#4017100000000000"),
    candump("595#4B17100032000000"),
    candump("195#4200000019"),
    candump("215#4200000000000000"),
    candump("195#000000001A"),
    candump("080#"),
    candump("315#0007070000000000"),
    candump("195#020000001B"),
    candump("715#05"),
    candump("215#0100000000000000"),
    candump("195#000000001C"),
    candump("196#0000000000"),
    candump("615#2300650101080100"),
    candump("595#6000650100000000"),
    candump("195#010000001D"),
    candump("215#0011000000000000"),
    candump("080#"),
    candump("195#000000001E"),
    candump("715#05"),
    candump("315#4200000000000000"),
    candump("195#420000001F"),
    candump("215#596A740000000000"),
    candump("716#05"),
    candump("195#0000000020"),
    candump("215#0000000000000000"),
    candump("615#2301600000010000"),
    candump("595#6001600000000000"),
    candump("195#0100000021"),
    candump("080#"),
    candump("715#05"),
    candump("195#0000000022"),
    candump("215#4200000000000000"),
    candump("315#0100000000000000"),
    candump("195#0200000023"),
    candump("18FEF100#FFFFFFFFFFFFFFFF"),
    candump("195#0000000024"),
    candump("715#05"),
    candump("215#0100000000000000"),
};

namespace detail {
constexpr auto pkp_decode = [](const pc::frame& f) { return powerkey::decode(f, node, pkp_model); };
}  // namespace detail

static_assert(detail::all_decode(pkp_key_frames, detail::pkp_decode));
static_assert(detail::all_decode(pkp_led_on_frames, detail::pkp_decode));
static_assert(detail::all_decode(pkp_led_blink_frames, detail::pkp_decode));
static_assert(detail::all_decode(pkp_sdo_request_frames, detail::pkp_decode));
static_assert(detail::all_decode(pkp_sdo_response_frames, detail::pkp_decode));

// How many frames of the mixed log belong to the keypad (the rest are refused with wrong_id or
// wrong_id_format): kept in the table's notes.
inline constexpr std::size_t mixed_log_keypad_frames = keypad_frames(mixed_log, pkp_model);
static_assert(mixed_log_keypad_frames == mixed_log.size() - 7);

// The decoded log, for the encoder: encode(decode(f)) == f for each of these.
inline constexpr auto mixed_log_messages =
    keypad_messages<mixed_log_keypad_frames>(mixed_log, pkp_model);

inline void pkp_key_state_decode(std::size_t calls) {
    decode_all(pkp_key_frames, pkp_model, calls);
}
inline void pkp_key_state_encode(std::size_t calls) {
    encode_all(pkp_key_messages, pkp_model, calls);
}
inline void pkp_led_on_decode(std::size_t calls) {
    decode_all(pkp_led_on_frames, pkp_model, calls);
}
inline void pkp_led_blink_decode(std::size_t calls) {
    decode_all(pkp_led_blink_frames, pkp_model, calls);
}
inline void pkp_led_on_encode(std::size_t calls) { encode_all(pkp_led_messages, pkp_model, calls); }
// The firmware's way: the map from run-time key numbers (leds::set), then encode.
inline void pkp_led_on_encode_typed(std::size_t calls) {
    const auto n = opaque(node);
    const auto m = opaque(pkp_model);
    cycle(pkp_led_requests, calls, [n, m](const led_request& r) {
        powerkey::leds l;
        l.set(r.key, r.c).set(r.key2, r.c2);
        return powerkey::encode(n, m, powerkey::led_on{l});
    });
}
// The same messages as their own types: encode of one PDO type checks its own fields (no
// decoder; issue 24's target is 30 instructions).
template <class T, std::size_t N>
constexpr auto alternatives_of(const std::array<powerkey::message, N>& messages) {
    std::array<T, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = std::get<T>(messages[i]);
    return out;
}
inline constexpr auto pkp_key_states = alternatives_of<powerkey::key_state>(pkp_key_messages);
inline constexpr auto pkp_led_ons = alternatives_of<powerkey::led_on>(pkp_led_messages);
inline void pkp_key_state_encode_own(std::size_t calls) {
    encode_all(pkp_key_states, pkp_model, calls);
}
inline void pkp_led_on_encode_own(std::size_t calls) { encode_all(pkp_led_ons, pkp_model, calls); }
// The model a template argument (issue 24, firmware (a_codec)'s calls): the key states through
// decode_key_state<M>, the LED maps through encode<M>.
inline void one_pkp_key_state_decode(std::size_t calls) {
    const auto n = opaque(node);
    cycle(pkp_key_frames, calls, [n](const pc::frame& f) BENCH_INLINE {
        return powerkey::decode_key_state<pkp_model>(f, n);
    });
}
inline void one_pkp_led_on_encode(std::size_t calls) { encode_all<pkp_model>(pkp_led_ons, calls); }
// SDO writes and a command of the PKP manual (section 13 a; 1017h, 6201h), encoded with the model
// a template argument (each checks itself: no decoder).
inline constexpr std::array<powerkey::sdo_write, 2> pkp_sdo_writes{{
    {powerkey::object::heartbeat_time, powerkey::number_value(50)},
    {powerkey::object::led_brightness, powerkey::level_value(powerkey::level{0x30})},
}};
inline constexpr std::array<powerkey::command, 1> pkp_commands{{
    {.code = powerkey::command_code::set_led_state, .key = 8, .state = powerkey::led_state::red_on},
}};
inline void one_pkp_sdo_write_encode(std::size_t calls) {
    encode_all<pkp_model>(pkp_sdo_writes, calls);
}
inline void one_pkp_command_encode(std::size_t calls) {
    encode_all<pkp_model>(pkp_commands, calls);
}
// The same write with its object a constant where it is written, as a firmware writes it
// (encode<M>(node, sdo_write{object::heartbeat_time, v})): its row, kind and range fold at
// compile time; the values (PKP 1017h: 50 ms, and 1000 ms) are not known.
inline constexpr std::array<powerkey::object_value, 2> pkp_heartbeat_times{{
    powerkey::number_value(50),
    powerkey::number_value(1000),
}};
inline void one_pkp_sdo_write_known_object_encode(std::size_t calls) {
    const auto n = opaque(node);
    cycle(pkp_heartbeat_times, calls, [n](const powerkey::object_value& v) BENCH_INLINE {
        return powerkey::encode<pkp_model>(
            n, powerkey::sdo_write{powerkey::object::heartbeat_time, v});
    });
}
inline void pkp_sdo_request_decode(std::size_t calls) {
    decode_all(pkp_sdo_request_frames, pkp_model, calls);
}
inline void pkp_sdo_response_decode(std::size_t calls) {
    decode_all(pkp_sdo_response_frames, pkp_model, calls);
}
inline void pkp_sdo_encode(std::size_t calls) { encode_all(pkp_sdo_messages, pkp_model, calls); }
inline void any_decode_mixed_log(std::size_t calls) { decode_all(mixed_log, pkp_model, calls); }
inline void any_encode_mixed_log(std::size_t calls) {
    encode_all(mixed_log_messages, pkp_model, calls);
}

inline constexpr op pkp_ops[] = {
    {"pkp2400/key_state/decode", pkp_key_state_decode},
    {"pkp2400/key_state/encode", pkp_key_state_encode},
    {"pkp2400/led_on/decode", pkp_led_on_decode},
    {"pkp2400/led_blink/decode", pkp_led_blink_decode},
    {"pkp2400/led_on/encode", pkp_led_on_encode},
    {"pkp2400/led_on/encode_typed", pkp_led_on_encode_typed},
    {"pkp2400/key_state/encode_own", pkp_key_state_encode_own},
    {"pkp2400/led_on/encode_own", pkp_led_on_encode_own},
    {"pkp2400/one/key_state/decode_key_state", one_pkp_key_state_decode},
    {"pkp2400/one/led_on/encode", one_pkp_led_on_encode},
    {"pkp2400/one/sdo_write/encode", one_pkp_sdo_write_encode},
    {"pkp2400/one/command/encode", one_pkp_command_encode},
    {"pkp2400/one/sdo_write/encode_known_object", one_pkp_sdo_write_known_object_encode},
    {"pkp2400/sdo/decode_request", pkp_sdo_request_decode},
    {"pkp2400/sdo/decode_response", pkp_sdo_response_decode},
    {"pkp2400/sdo/encode", pkp_sdo_encode},
    {"any/pkp2400/decode_mixed_log", any_decode_mixed_log},
    {"any/pkp2400/encode_mixed_log", any_encode_mixed_log, "frame (keypad frames only)"},
};

}  // namespace bench

#endif  // POWERKEY_BENCH_OPS_PKP_HPP
