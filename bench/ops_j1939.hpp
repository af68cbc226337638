// The keypads in J1939 (issue 21): a PKP-2600-SI on a vehicle's J1939 bus. The J1939 mixed log is
// a minute of such a bus compressed to 64 frames: the keypad's key contact states and heartbeats,
// a controller's LED commands (single and multiple), LED acknowledgements, a setting, and the
// traffic of other ECUs (engine, vehicle speed, temperatures, diagnostics, a request), which the
// decoder must refuse as not a keypad frame. Every keypad frame is printed in the PKP2600SI J1939
// manual (tests/j1939_rows.hpp) or follows its layouts with another key or colour; the count of
// keypad frames is proved at compile time.
#ifndef POWERKEY_BENCH_OPS_J1939_HPP
#define POWERKEY_BENCH_OPS_J1939_HPP

#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/j1939_codec.hpp>

#include <array>
#include <cstddef>
#include <type_traits>
#include <variant>

#include "ops.hpp"

namespace bench {

inline constexpr std::array j1939_mixed_log = {
    candump("18EFFF21#041B01010121FFFF"),  // key 1 pressed
    candump("0CF00400#FF7D7DE015FFF0FF"),  // EEC1 from the engine
    candump("18EF2100#041B0101010100FF"),  // LED 1 red, on
    candump("18EFFF21#0001010100FFFFFF"),  // its acknowledgement
    candump("18EFFF21#041B01010021FFFF"),  // key 1 released
    candump("18EFFF21#041BF9030000FF21"),  // heartbeat
    candump("18FEF100#FFFFFFFFFFFFFFFF"),  // CCVS
    candump("18EFFF21#041B01040121FFFF"), candump("18EF2100#041B0104020100FF"),
    candump("18EFFF21#0001040200FFFFFF"), candump("18EFFF21#041B01040021FFFF"),
    candump("0CF00300#D10000FFFFFFFFFF"),  // EEC2
    candump("18A72100#110100000000FFFF"),  // multiple LEDs, colour 1
    candump("18A62100#000000000096FFFF"),  // multiple LEDs, colour 2
    candump("18EFFF21#041B01080121FFFF"), candump("18EFFF21#041B01080021FFFF"),
    candump("18FEEE00#5A5AFFFF00FFFFFF"),  // ET1
    candump("18EFFF21#041BF9038000FF21"),  // heartbeat, key 8 held
    candump("18EFFF21#041B010C0121FFFF"), candump("18EF2100#041B010C030200FF"),
    candump("18EFFF21#00020C0300FFFFFF"), candump("18EFFF21#041B010C0021FFFF"),
    candump("0CF00400#FF7D7DE015FFF0FF"),
    candump("18EF2100#041B0220FFFFFFFF"),  // LED brightness
    candump("18EFFF21#041B01020121FFFF"), candump("18EFFF21#041B01020021FFFF"),
    candump("18FECA00#00FF00000000FFFF"),  // DM1
    candump("18EFFF21#041BF9030000FF21"), candump("18EFFF21#041B01050121FFFF"),
    candump("18EF2100#041B0105010100FF"), candump("18EFFF21#0001050100FFFFFF"),
    candump("18EFFF21#041B01050021FFFF"), candump("0CF00300#D10000FFFFFFFFFF"),
    candump("18A72100#000200000000FFFF"), candump("18A62100#000200000000FFFF"),
    candump("18EFFF21#041B01060121FFFF"), candump("18EFFF21#041B01060021FFFF"),
    candump("18EAFF00#00EE00"),  // a request for the address claimed
    candump("18EFFF21#041BF9030000FF21"), candump("18EFFF21#041B01090121FFFF"),
    candump("18EF2100#041B0109020100FF"), candump("18EFFF21#0001090200FFFFFF"),
    candump("18EFFF21#041B01090021FFFF"), candump("0CF00400#FF7D7DE015FFF0FF"),
    candump("18EF2100#041B0310FFFFFFFF"),  // backlight level
    candump("18EFFF21#041B01030121FFFF"), candump("18EFFF21#041B01030021FFFF"),
    candump("18FEF100#FFFFFFFFFFFFFFFF"), candump("18EFFF21#041BF9030000FF21"),
    candump("18EFFF21#041B010A0121FFFF"), candump("18EF2100#041B010A000000FF"),
    candump("18EFFF21#00000A0000FFFFFF"), candump("18EFFF21#041B010A0021FFFF"),
    candump("0CF00300#D10000FFFFFFFFFF"), candump("18A72100#000000040000FFFF"),
    candump("18A62100#000000050000FFFF"), candump("18EFFF21#041B010B0121FFFF"),
    candump("18EFFF21#041B010B0021FFFF"), candump("18FEEE00#5A5AFFFF00FFFFFF"),
    candump("18EFFF21#041BF9030000FF21"), candump("18EFFF21#041B01070121FFFF"),
    candump("18EFFF21#041B01070021FFFF"), candump("0CF00400#FF7D7DE015FFF0FF"),
    candump("18EFFF21#041BF9030000FF21"),
};

inline constexpr powerkey::model j1939_model = powerkey::model::pkp2600si;

// How many frames belong to the keypad (the others are other ECUs': wrong_id).
inline constexpr std::size_t j1939_mixed_log_keypad_frames =
    keypad_frames(j1939_mixed_log, j1939_model);
static_assert(j1939_mixed_log.size() == 64);
static_assert(j1939_mixed_log_keypad_frames == j1939_mixed_log.size() - 13);

// The decoded log, for the encoder.
inline constexpr auto j1939_mixed_log_messages =
    keypad_messages<j1939_mixed_log_keypad_frames>(j1939_mixed_log, j1939_model);

// The key contact states and LED commands of the log, alone.
inline constexpr std::array j1939_key_frames = {
    candump("18EFFF21#041B01010121FFFF"),
    candump("18EFFF21#041B01010021FFFF"),
    candump("18EFFF21#041B010C0121FFFF"),
    candump("18EFFF21#041B010C0021FFFF"),
};
inline constexpr std::array j1939_set_leds = {
    powerkey::j1939::set_led{
        .key = 1, .colour = powerkey::j1939::led_colour::red, .mode = powerkey::led_mode::on},
    powerkey::j1939::set_led{
        .key = 12, .colour = powerkey::j1939::led_colour::blue, .mode = powerkey::led_mode::blink},
};

inline void any_decode_j1939_mixed_log(std::size_t calls) {
    decode_all(j1939_mixed_log, j1939_model, calls);
}
inline void any_encode_j1939_mixed_log(std::size_t calls) {
    encode_all(j1939_mixed_log_messages, j1939_model, calls);
}
inline void j1939_decode_mixed_log(std::size_t calls) {
    const auto m = opaque(j1939_model);
    cycle(j1939_mixed_log, calls,
          [m](const pc::frame& f) BENCH_INLINE { return powerkey::j1939::decode(f, m); });
}
inline void j1939_key_contact_decode(std::size_t calls) {
    const auto m = opaque(j1939_model);
    cycle(j1939_key_frames, calls,
          [m](const pc::frame& f) BENCH_INLINE { return powerkey::j1939::decode(f, m); });
}
inline void j1939_set_led_encode(std::size_t calls) {
    const auto m = opaque(j1939_model);
    cycle(j1939_set_leds, calls, [m](const powerkey::j1939::set_led& v) BENCH_INLINE {
        return powerkey::j1939::encode(m, v);
    });
}

// The same with the model a template argument (issue 24): the whole reader, the key contact
// state alone (fw_j1939's reader, narrowed to the keypad), and the set_led encode, which checks
// its own fields.
inline void one_j1939_decode_mixed_log(std::size_t calls) {
    cycle(j1939_mixed_log, calls,
          [](const pc::frame& f) BENCH_INLINE { return powerkey::j1939::decode<j1939_model>(f); });
}
inline void one_j1939_key_contact_decode(std::size_t calls) {
    const auto keypad = opaque(powerkey::j1939::keypad_default_address);
    cycle(j1939_key_frames, calls, [keypad](const pc::frame& f) BENCH_INLINE {
        return powerkey::j1939::decode_key_contact<j1939_model>(f, keypad);
    });
}
inline void one_j1939_set_led_encode(std::size_t calls) {
    cycle(j1939_set_leds, calls, [](const powerkey::j1939::set_led& v) BENCH_INLINE {
        return powerkey::j1939::encode<j1939_model>(v);
    });
}

// The log's frames by what they decode to (T: a j1939::message alternative; void: the frames of
// other ECUs, refused), each kind measured alone: what each costs of the log's average
// (docs/performance.md, "The J1939 mixed log").
template <class T>
constexpr bool decodes_to(const pc::frame& f) {
    const auto r = powerkey::j1939::decode(f, j1939_model);
    if constexpr (std::is_void_v<T>)
        return !r;
    else
        return r && std::holds_alternative<T>(*r);
}
template <class T>
constexpr std::size_t frames_of_kind_count() {
    std::size_t n = 0;
    for (const auto& f : j1939_mixed_log) n += decodes_to<T>(f) ? 1u : 0u;
    return n;
}
template <class T>
inline constexpr auto j1939_log_kind = [] {
    std::array<pc::frame, frames_of_kind_count<T>()> out{};
    std::size_t i = 0;
    for (const auto& f : j1939_mixed_log)
        if (decodes_to<T>(f)) out[i++] = f;
    return out;
}();
static_assert(j1939_log_kind<void>.size() + j1939_log_kind<powerkey::j1939::key_contact>.size() +
                  j1939_log_kind<powerkey::j1939::heartbeat>.size() +
                  j1939_log_kind<powerkey::j1939::set_led>.size() +
                  j1939_log_kind<powerkey::j1939::led_ack>.size() +
                  j1939_log_kind<powerkey::j1939::multiple_leds>.size() +
                  j1939_log_kind<powerkey::j1939::command>.size() ==
              j1939_mixed_log.size());
template <class T>
void j1939_decode_log_kind(std::size_t calls) {
    const auto m = opaque(j1939_model);
    cycle(j1939_log_kind<T>, calls,
          [m](const pc::frame& f) BENCH_INLINE { return powerkey::j1939::decode(f, m); });
}
template <class T>
void one_j1939_decode_log_kind(std::size_t calls) {
    cycle(j1939_log_kind<T>, calls,
          [](const pc::frame& f) BENCH_INLINE { return powerkey::j1939::decode<j1939_model>(f); });
}

inline constexpr op j1939_ops[] = {
    {"pkp2600si/j1939/key_contact/decode", j1939_key_contact_decode},
    {"pkp2600si/j1939/set_led/encode", j1939_set_led_encode},
    {"pkp2600si/j1939/decode_mixed_log", j1939_decode_mixed_log},
    {"pkp2600si/j1939/one/key_contact/decode_key_contact", one_j1939_key_contact_decode},
    {"pkp2600si/j1939/one/set_led/encode", one_j1939_set_led_encode},
    {"pkp2600si/j1939/one/decode_mixed_log", one_j1939_decode_mixed_log},
    {"pkp2600si/j1939/log_kind/other_ecus/decode", j1939_decode_log_kind<void>},
    {"pkp2600si/j1939/log_kind/key_contact/decode",
     j1939_decode_log_kind<powerkey::j1939::key_contact>},
    {"pkp2600si/j1939/log_kind/heartbeat/decode",
     j1939_decode_log_kind<powerkey::j1939::heartbeat>},
    {"pkp2600si/j1939/log_kind/set_led/decode", j1939_decode_log_kind<powerkey::j1939::set_led>},
    {"pkp2600si/j1939/log_kind/led_ack/decode", j1939_decode_log_kind<powerkey::j1939::led_ack>},
    {"pkp2600si/j1939/log_kind/multiple_leds/decode",
     j1939_decode_log_kind<powerkey::j1939::multiple_leds>},
    {"pkp2600si/j1939/log_kind/command/decode", j1939_decode_log_kind<powerkey::j1939::command>},
    {"pkp2600si/j1939/one/log_kind/other_ecus/decode", one_j1939_decode_log_kind<void>},
    {"pkp2600si/j1939/one/log_kind/key_contact/decode",
     one_j1939_decode_log_kind<powerkey::j1939::key_contact>},
    {"pkp2600si/j1939/one/log_kind/heartbeat/decode",
     one_j1939_decode_log_kind<powerkey::j1939::heartbeat>},
    {"pkp2600si/j1939/one/log_kind/set_led/decode",
     one_j1939_decode_log_kind<powerkey::j1939::set_led>},
    {"pkp2600si/j1939/one/log_kind/led_ack/decode",
     one_j1939_decode_log_kind<powerkey::j1939::led_ack>},
    {"pkp2600si/j1939/one/log_kind/multiple_leds/decode",
     one_j1939_decode_log_kind<powerkey::j1939::multiple_leds>},
    {"pkp2600si/j1939/one/log_kind/command/decode",
     one_j1939_decode_log_kind<powerkey::j1939::command>},
    {"any/pkp2600si/decode_j1939_mixed_log", any_decode_j1939_mixed_log},
    {"any/pkp2600si/encode_j1939_mixed_log", any_encode_j1939_mixed_log,
     "frame (keypad frames only)"},
};

}  // namespace bench

#endif  // POWERKEY_BENCH_OPS_J1939_HPP
