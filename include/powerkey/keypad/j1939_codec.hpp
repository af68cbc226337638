// powerkey: every J1939 frame of the keypads behind two calls, driven by the J1939 model table:
//
//   j1939::decode(frame, model, keypad)    -> result<j1939::message>
//   j1939::encode(model, message, keypad)  -> result<can::frame>    encode(decode(f)) == f
//
// Addresses come from the identifier: the keypad's frames decode whatever its source address,
// commands whatever their destination and sender. `keypad` (optional) narrows to the keypad at
// one address: its own frames must come from it, commands must go to it. A frame on a PGN the
// keypads do not use (anything but EF00h, A700h, A600h, EE00h) is not a keypad frame
// (errc::wrong_id). The same PGN and command byte carry both directions (01h is a key contact
// state from the keypad and an LED command to it; 2Ah a request and its answer): the direction
// comes from the data and the identifier, as docs/j1939.md says. encode checks the message's
// fields as decode would check its frame, then builds the frame: it never returns a frame decode
// refuses or reads as another meaning (tests and fuzz/j1939_encode.cpp prove it).
#ifndef POWERKEY_KEYPAD_J1939_CODEC_HPP
#define POWERKEY_KEYPAD_J1939_CODEC_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/detail/bytes.hpp>
#include <powerkey/detail/inline.hpp>
#include <powerkey/j1939/id.hpp>
#include <powerkey/j1939/name.hpp>
#include <powerkey/j1939/protocol_switch.hpp>
#include <powerkey/keypad/j1939_messages.hpp>
#include <powerkey/keypad/j1939_models.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/keypad/values.hpp>
#include <powerkey/result.hpp>

#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <variant>

namespace powerkey::j1939 {

// The PGNs of the keypads besides proprietary A (EF00h, protocol_switch.hpp): the two frames of
// the multiple-LED command (section 7b) and the address claim (section 20). All PDU1.
inline constexpr pgn multiple_leds_1_pgn = 0xA700;  // "AUXILIARY I/O #2", "color 1"
inline constexpr pgn multiple_leds_2_pgn = 0xA600;  // "AUXILIARY I/O #3", "color 2"
inline constexpr pgn address_claim_pgn = 0xEE00;

// A PGN the keypads use: any other is not a keypad frame (decode's errc::wrong_id).
[[nodiscard]] constexpr bool is_keypad_pgn(pgn p) noexcept {
    return p == proprietary_a_pgn || p == multiple_leds_1_pgn || p == multiple_leds_2_pgn ||
           p == address_claim_pgn;
}
// Bytes 0..1 of every proprietary-A keypad frame but the LED acknowledgement (section 4).
inline constexpr std::uint8_t header_0 = 0x04;
inline constexpr std::uint8_t header_1 = 0x1B;

// The keypad whose frames decode: nullopt for any (the default), or its source address.
using keypad_address = std::optional<std::uint8_t>;

// --- the multiple-LED codes and TABLE 3 (section 7b) ---------------------------------------------

// What one LED shows, as a single-LED command says it. `defined` is false for the code pairs
// TABLE 3 does not give (Fh with 0h or Fh, and codes Ah..Eh).
struct led_look {
    led_mode mode = led_mode::off;
    led_colour colour = led_colour::off;
    led_colour secondary = led_colour::off;
    bool defined = true;
    friend constexpr bool operator==(const led_look&, const led_look&) noexcept = default;
};

// TABLE 3: the LED of code c1 in the "color 1" frame and c2 in the "color 2" frame. Same colour
// in both alternates that colour with itself ("LED ALT BLINKS with the chosen color").
[[nodiscard]] constexpr led_look combine(std::uint8_t c1, std::uint8_t c2) noexcept {
    const auto colour = [](std::uint8_t c) { return c >= 1 && c <= 9; };
    const auto as = [](std::uint8_t c) { return static_cast<led_colour>(c); };
    if (c1 == 0 && c2 == 0) return {};
    if (colour(c1) && c2 == 0) return {led_mode::on, as(c1), led_colour::off, true};
    if (c1 == 0 && colour(c2)) return {led_mode::on, as(c2), led_colour::off, true};
    if (colour(c1) && colour(c2)) return {led_mode::alternate_blink, as(c1), as(c2), true};
    if (colour(c1) && c2 == 0xF) return {led_mode::blink, as(c1), led_colour::off, true};
    if (c1 == 0xF && colour(c2)) return {led_mode::blink, as(c2), led_colour::off, true};
    return {led_mode::off, led_colour::off, led_colour::off, false};
}

// The LED of k as the two frames say it.
[[nodiscard]] constexpr led_look combine(const multiple_leds& colour_1,
                                         const multiple_leds& colour_2, unsigned k) noexcept {
    return combine(colour_1.code_of(k), colour_2.code_of(k));
}

// The two codes that make an LED show `look` (the inverse of combine): off 0h/0h, on c/0h, blink
// c/Fh, alternate blink c/s. nullopt for a look TABLE 3 cannot give (a colour outside 1h..9h,
// where it shows one).
struct code_pair {
    std::uint8_t colour_1 = 0;
    std::uint8_t colour_2 = 0;
    friend constexpr bool operator==(const code_pair&, const code_pair&) noexcept = default;
};
[[nodiscard]] constexpr std::optional<code_pair> codes_for(led_mode mode, led_colour colour,
                                                           led_colour secondary) noexcept {
    const auto c = static_cast<std::uint8_t>(colour);
    const auto s = static_cast<std::uint8_t>(secondary);
    if (mode == led_mode::off) return code_pair{};
    if (c < 1 || c > 9) return std::nullopt;
    switch (mode) {
        case led_mode::on: return code_pair{c, 0};
        case led_mode::blink: return code_pair{c, 0xF};
        case led_mode::alternate_blink:
            if (s < 1 || s > 9) return std::nullopt;
            return code_pair{c, s};
        default: return std::nullopt;
    }
}

namespace detail {

// The decoders below build the message variant M: j1939::message for j1939::decode, or
// powerkey::message for the any-frame decoder (keypad/codec.hpp), which then needs no copy from
// one variant to the other; or the one message a reader of one kind returns (decode_key_contact).
template <class M, class T>
constexpr result<M> answer(const T& v) noexcept {
    if constexpr (std::is_same_v<M, T>)
        return v;
    else
        return result<M>(std::in_place, std::in_place_type<T>, v);
}

// Bytes [from, 8) of the data word w are FFh.
constexpr bool ff_from(std::uint64_t w, unsigned from) noexcept {
    return (w >> (8 * from)) == (~std::uint64_t{0} >> (8 * from));
}

constexpr std::uint8_t byte_of(std::uint64_t w, unsigned i) noexcept {
    return static_cast<std::uint8_t>(w >> (8 * i));
}

// The identifier's source, destination and priority as bytes 0, 1 and 2 of a word: the first
// three members of the messages the fast path answers (key_contact, heartbeat, led_ack, set_led),
// whose data fields follow in the frame's order, so that their answer is this word and the data
// bytes in place (in_place_of).
constexpr std::uint64_t route_word(std::uint32_t id) noexcept {
    return (id & 0xFFFF) | ((id >> 10) & 0x7'0000);
}
// The same of a 29-bit identifier of PGN EF00h to FFh, whose other bits are known: shifted by 10,
// the 29-bit flag, PDU format and destination are 20'3BFFh under the priority (one add fewer).
constexpr std::uint64_t route_word_to_global(std::uint32_t id) noexcept {
    return (id & 0xFFFF) + (id >> 10) - 0x20'3BFF;
}
// The message T whose members are the bytes of v in order (T is 8 bytes, its last ones padding):
// one store of a word where member-wise construction took a store or two per member. v holds a
// value of each member (a priority 0..7, a bool 00h/01h).
template <class T>
constexpr T in_place_of(std::uint64_t v) noexcept {
    static_assert(sizeof(T) == 8 && std::is_trivially_copyable_v<T>);
    if constexpr (std::endian::native == std::endian::little) {
        return std::bit_cast<T>(v);
    } else {
        std::array<std::uint8_t, 8> bytes{};
        for (unsigned i = 0; i < 8; ++i) bytes[i] = byte_of(v, i);
        return std::bit_cast<T>(bytes);
    }
}

// Bits 25..16 of a 29-bit identifier (EDP, DP, PDU format: a PDU1 PGN's high bits) of a keypad
// PGN: EF00h, A700h, A600h, EE00h.
constexpr bool is_keypad_pf(std::uint32_t pf) noexcept {
    return pf == 0xEF || pf == 0xA7 || pf == 0xA6 || pf == 0xEE;
}

// The identifier of a frame the keypad sends: from the narrowed keypad, if any.
constexpr errc from_keypad(std::uint8_t source, keypad_address keypad) noexcept {
    return keypad && source != *keypad ? errc::wrong_id : errc{};
}
// The identifier of a command: to the narrowed keypad, if any; and not to the global address,
// which no source shows a keypad taking commands on.
constexpr errc to_keypad(std::uint8_t destination, keypad_address keypad) noexcept {
    if (keypad && destination != *keypad) return errc::wrong_id;
    if (destination == global_address) return errc::undocumented;
    return errc{};
}

// The model's word on a frame: absent is unknown_command, unknown is undocumented.
constexpr errc covered(const model_row& r, feature f) noexcept {
    switch (r.frames.of(f)) {
        case coverage::absent: return errc::unknown_command;
        case coverage::unknown: return errc::undocumented;
        default: return errc{};
    }
}

// An LED number the model's LED commands address.
constexpr bool has_led(const model_row& r, std::uint8_t k) noexcept {
    return k >= 1 && k <= 16 && ((r.leds >> (k - 1)) & 1u) != 0;
}
constexpr bool is_colour(std::uint8_t c) noexcept { return c <= 0x09; }
constexpr bool is_secondary(std::uint8_t c) noexcept { return c <= 0x09 || c == 0xFF; }

// The identifier fields every message starts with.
struct route {
    j1939::priority priority;
    std::uint8_t destination;
    std::uint8_t source;
};

// The checks of a frame the keypad sends (`sent`) or is sent (`received`) before its data's:
// the identifier, then the model's word on the frame.
constexpr errc sent(const model_row& r, feature f, const route& at,
                    keypad_address keypad) noexcept {
    const errc e = from_keypad(at.source, keypad);
    return e != errc{} ? e : covered(r, f);
}
constexpr errc received(const model_row& r, feature f, const route& at,
                        keypad_address keypad) noexcept {
    const errc e = to_keypad(at.destination, keypad);
    return e != errc{} ? e : covered(r, f);
}

// --- proprietary A (EF00h): the frames of the keypad ---------------------------------------------

// Errors after the route: reserved_not_ff, value_out_of_range.
template <class M>
constexpr result<M> key_contact_of(const route& at, std::uint64_t w) noexcept {
    if (!ff_from(w, 6)) return errc::reserved_not_ff;
    const std::uint8_t key = byte_of(w, 3), state = byte_of(w, 4), id = byte_of(w, 5);
    if (key < 1 || key > 16 || state > 1 || id == 0xFF) return errc::value_out_of_range;
    return answer<M>(key_contact{.source = at.source,
                                 .destination = at.destination,
                                 .priority = at.priority,
                                 .key = key,
                                 .pressed = state == 1,
                                 .identifier = id});
}

template <class M>
constexpr result<M> heartbeat_of(const model_row& r, const route& at, std::uint64_t w) noexcept {
    if (byte_of(w, 6) != 0xFF) return errc::reserved_not_ff;
    const auto keys = static_cast<std::uint32_t>((w >> 32) & 0xFFFF);
    if ((keys >> r.keys) != 0) return errc::reserved_not_zero;
    return answer<M>(heartbeat{.source = at.source,
                               .destination = at.destination,
                               .priority = at.priority,
                               .counter = byte_of(w, 3),
                               .keys = key_set::from_mask(keys),
                               .identifier = byte_of(w, 7)});
}

template <class M>
constexpr result<M> revision_of(const route& at, std::uint64_t w) noexcept {
    software_revision v{
        .source = at.source, .destination = at.destination, .priority = at.priority, .bytes = {}};
    bool ended = false;
    for (unsigned i = 0; i < 5; ++i) {
        const std::uint8_t b = byte_of(w, 3 + i);
        if (b == 0)
            ended = true;
        else if (ended || b < 0x20 || b > 0x7E)
            return errc::value_out_of_range;
        v.bytes[i] = b;
    }
    return answer<M>(v);
}

template <class M>
constexpr result<M> led_ack_of(const model_row& r, const route& at, std::uint64_t w) noexcept {
    const std::uint8_t b1 = byte_of(w, 1), key = byte_of(w, 2), b3 = byte_of(w, 3),
                       b4 = byte_of(w, 4);
    if (r.form == led_form::code) {
        if (b1 != 0xFF || !ff_from(w, 4)) return errc::reserved_not_ff;
        if (!has_led(r, key)) return errc::value_out_of_range;
        return answer<M>(led_ack_code{.source = at.source,
                                      .destination = at.destination,
                                      .priority = at.priority,
                                      .key = key,
                                      .code = b3});
    }
    if (!ff_from(w, 5)) return errc::reserved_not_ff;
    if (b1 > 3 || !has_led(r, key) || !is_colour(b3) || !is_secondary(b4))
        return errc::value_out_of_range;
    return answer<M>(led_ack{.source = at.source,
                             .destination = at.destination,
                             .priority = at.priority,
                             .mode = static_cast<led_mode>(b1),
                             .key = key,
                             .colour = static_cast<led_colour>(b3),
                             .secondary = static_cast<led_colour>(b4)});
}

// --- proprietary A (EF00h): the frames to the keypad ---------------------------------------------

template <class M>
constexpr result<M> set_led_of(const model_row& r, const route& at, std::uint64_t w) noexcept {
    const std::uint8_t key = byte_of(w, 3), b4 = byte_of(w, 4), b5 = byte_of(w, 5),
                       b6 = byte_of(w, 6);
    if (r.form == led_form::code) {
        if (!ff_from(w, 5)) return errc::reserved_not_ff;
        if (!has_led(r, key)) return errc::value_out_of_range;
        return answer<M>(set_led_code{.source = at.source,
                                      .destination = at.destination,
                                      .priority = at.priority,
                                      .key = key,
                                      .code = b4});
    }
    if (byte_of(w, 7) != 0xFF) return errc::reserved_not_ff;
    if (!has_led(r, key) || !is_colour(b4) || b5 > 3 || !is_secondary(b6))
        return errc::value_out_of_range;
    return answer<M>(set_led{.source = at.source,
                             .destination = at.destination,
                             .priority = at.priority,
                             .key = key,
                             .colour = static_cast<led_colour>(b4),
                             .mode = static_cast<led_mode>(b5),
                             .secondary = static_cast<led_colour>(b6)});
}

// Errors: value_out_of_range for a byte outside the parameter's range.
constexpr errc read_param(command_param p, std::uint8_t b, command& c) noexcept {
    switch (p) {
        case command_param::none: return errc{};
        case command_param::level:
            if (b > level::max) return errc::value_out_of_range;
            c.level = level::make(b).value();
            return errc{};
        case command_param::flag:
            if (b > 1) return errc::value_out_of_range;
            c.enabled = b == 1;
            return errc{};
        case command_param::show:
            if (b > 2) return errc::value_out_of_range;
            c.show = static_cast<startup_show>(b);
            return errc{};
        case command_param::management:
            if (b != 0 && b != 2) return errc::value_out_of_range;
            c.multiple_leds = b == 2;
            return errc{};
        case command_param::destination:
            if (b == 0xFE) return errc::value_out_of_range;
            c.address = b;
            return errc{};
        case command_param::baud:
            if (b != 2 && b != 3) return errc::value_out_of_range;
            c.baud = static_cast<baud_rate>(b);  // the PK1000 codes: 02h 500k, 03h 250k
            return errc{};
        case command_param::source:
            if (b == 0 || b == 0xFE) return errc::value_out_of_range;
            c.address = b;
            return errc{};
        case command_param::identifier:
            if (b == 0xFE) return errc::value_out_of_range;
            c.identifier = b;
            return errc{};
        case command_param::heartbeat_time:
            if (b == 0xFF && !c.enabled) {
                c.period_10ms = b;
                return errc{};
            }
            [[fallthrough]];
        case command_param::period:
            if (b < 0x05 || b > 0xFE) return errc::value_out_of_range;
            c.period_10ms = b;
            return errc{};
        case command_param::colour:
            if (b < 1 || b > 9) return errc::value_out_of_range;
            c.colour = static_cast<backlight_colour>(b);
            return errc{};
    }
    return errc::value_out_of_range;
}

constexpr std::uint8_t write_param(command_param p, const command& c) noexcept {
    switch (p) {
        case command_param::level: return c.level.value();
        case command_param::flag: return c.enabled ? 1 : 0;
        case command_param::show: return static_cast<std::uint8_t>(c.show);
        case command_param::management: return c.multiple_leds ? 2 : 0;
        case command_param::destination:
        case command_param::source: return c.address;
        case command_param::identifier: return c.identifier;
        case command_param::baud: return static_cast<std::uint8_t>(c.baud);
        case command_param::period:
        case command_param::heartbeat_time: return c.period_10ms;
        case command_param::colour: return static_cast<std::uint8_t>(c.colour);
        case command_param::none: break;
    }
    return 0xFF;
}

// Errors: reserved_not_ff (a byte after the parameters), value_out_of_range.
template <class M>
constexpr result<M> command_of(const command_row& row, const route& at, std::uint64_t w) noexcept {
    const unsigned used = row.p1 == command_param::none ? 3 : row.p2 == command_param::none ? 4 : 5;
    if (!ff_from(w, used)) return errc::reserved_not_ff;
    command c{};
    c.priority = at.priority;
    c.destination = at.destination;
    c.source = at.source;
    c.code = row.code;
    if (const errc e = read_param(row.p1, byte_of(w, 3), c); e != errc{}) return e;
    if (const errc e = read_param(row.p2, byte_of(w, 4), c); e != errc{}) return e;
    return answer<M>(c);
}

template <class M>
constexpr result<M> switch_of(const route& at, std::uint64_t w) noexcept {
    if (!ff_from(w, 4)) return errc::reserved_not_ff;
    if (byte_of(w, 3) != 0x00) return errc::value_out_of_range;
    return answer<M>(switch_to_canopen{at.priority, at.destination, at.source});
}

// Command 01h: the keypad's key contact state or an LED command to it. Narrowed, the keypad's
// own frame is its key state. Otherwise a frame to the global address is a key state (commands
// go to the keypad's address); an addressed frame is an LED command when its bytes can only be
// one (LI form: byte 5 FFh, which no keypad identifier is; SI form: byte 6 not FFh), or when
// they can be either (SI: byte 4 00h/01h, byte 5 00h..03h, byte 6 FFh).
constexpr bool is_led_command(const model_row& r, const route& at, std::uint64_t w,
                              keypad_address keypad) noexcept {
    if (keypad) return at.source != *keypad;
    if (at.destination == global_address) return false;
    if (r.form == led_form::code) return byte_of(w, 5) == 0xFF;
    if (byte_of(w, 6) != 0xFF) return true;
    return byte_of(w, 4) <= 1 && byte_of(w, 5) <= 3;
}
// Command 01h after its header, either way.
template <class M>
POWERKEY_DETAIL_HOT constexpr result<M> command_01_of(const model_row& r, const route& at,
                                                      std::uint64_t w,
                                                      keypad_address keypad) noexcept {
    if (is_led_command(r, at, w, keypad)) {
        if (const errc e = received(r, feature::led_command, at, keypad); e != errc{}) return e;
        return set_led_of<M>(r, at, w);
    }
    if (const errc e = sent(r, feature::key_contact, at, keypad); e != errc{}) return e;
    return key_contact_of<M>(at, w);
}

template <class M>
constexpr result<M> decode_proprietary_a(const model_row& r, const route& at, std::uint64_t w,
                                         keypad_address keypad) noexcept {
    const std::uint8_t b0 = byte_of(w, 0);
    if (b0 == 0x00) {  // the LED acknowledgement has no header
        if (const errc e = sent(r, feature::led_ack, at, keypad); e != errc{}) return e;
        return led_ack_of<M>(r, at, w);
    }
    if (b0 != header_0 || byte_of(w, 1) != header_1) return errc::unknown_command;
    const std::uint8_t code = byte_of(w, 2);
    switch (code) {
        case 0x01: return command_01_of<M>(r, at, w, keypad);
        case 0xF9:
            if (const errc e = sent(r, feature::heartbeat, at, keypad); e != errc{}) return e;
            return heartbeat_of<M>(r, at, w);
        case 0x80:
            if (const errc e = received(r, feature::switch_to_canopen, at, keypad); e != errc{})
                return e;
            return switch_of<M>(at, w);
        case 0x2A:
            if (!ff_from(w, 3)) {  // the answer; the request's bytes 3..7 are FFh
                if (const errc e = sent(r, feature::software_revision, at, keypad); e != errc{})
                    return e;
                return revision_of<M>(at, w);
            }
            break;
        default: break;
    }
    const command_row* row = find_command(code);
    if (row == nullptr) return errc::unknown_command;
    if (const errc e = received(r, row->what, at, keypad); e != errc{}) return e;
    return command_of<M>(*row, at, w);
}

// --- the multiple-LED frames (A700h, A600h) and the address claim (EE00h) -----------------------

// Every byte of v at most the byte of `max` at its place, each byte of max at most 7Fh, in one
// add: a byte up to 7Fh gets its high bit from the add exactly when it is above its bound, and
// carries into no other; a byte above 7Fh has its high bit set in v already, so that the test
// fails whatever its carry does to the byte above it.
constexpr bool bytes_at_most(std::uint64_t v, std::uint64_t max) noexcept {
    constexpr std::uint64_t low7 = 0x7F7F'7F7F'7F7F'7F7F;
    return (((v + (low7 - max)) | v) & ~low7) == 0;
}

// A nibble of w that is Ah..Eh, a code the multiple-LED frames do not use: bit 3 set and its low
// three bits 2..6. Every nibble at once, in two adds that carry out of no nibble: low + 6 has
// bit 3 set from 2 up, low + 1 only at 7 (Fh, blink).
constexpr bool has_unused_code(std::uint64_t w) noexcept {
    const std::uint64_t low = w & 0x7777'7777'7777'7777;
    return (w & (low + 0x6666'6666'6666'6666) & ~(low + 0x1111'1111'1111'1111) &
            0x8888'8888'8888'8888) != 0;
}

template <class M>
constexpr result<M> multiple_leds_of(const model_row& r, const route& at, colour_frame frame,
                                     std::uint64_t w, keypad_address keypad) noexcept {
    if (const errc e = received(r, feature::multiple_leds, at, keypad); e != errc{}) return e;
    const unsigned bits = 4u * r.plane_leds;
    const std::uint64_t used = powerkey::detail::low_bits(bits);
    if ((w | used) != ~std::uint64_t{0}) return errc::reserved_not_ff;
    if (has_unused_code(w)) return errc::value_out_of_range;  // the nibbles past `used` are Fh
    return answer<M>(multiple_leds{.source = at.source,
                                   .destination = at.destination,
                                   .priority = at.priority,
                                   .frame = frame,
                                   .nibbles = multiple_leds::halves(w & used)});
}

template <class M>
constexpr result<M> address_claimed_of(const model_row& r, const route& at, std::uint64_t w,
                                       keypad_address keypad) noexcept {
    if (const errc e = sent(r, feature::address_claim, at, keypad); e != errc{}) return e;
    const auto n = unpack_name(w);
    if (!n) return n.error();
    return answer<M>(address_claimed{
        .source = at.source, .destination = at.destination, .priority = at.priority, .name = *n});
}

// --- encoding
// -------------------------------------------------------------------------------------

constexpr can::frame frame_of(pgn p, j1939::priority priority, std::uint8_t destination,
                              std::uint8_t source, std::uint64_t data) noexcept {
    // Every PGN here is PDU1 with a zero low byte and a priority is 0..7: make_id cannot fail (said
    // to the compiler, so that no error path is built).
    POWERKEY_DETAIL_ASSUME_NOT(priority.value() > 7);
    const auto id = make_id({priority, p, destination, source}).value();
    can::payload bytes{};
    powerkey::detail::store_le<8>(bytes, 0, data);
    return can::frame(id, can::dlc::make(8).value(), bytes);
}
constexpr can::frame frame_of(pgn p, j1939::priority priority, std::uint8_t destination,
                              std::uint8_t source, const can::payload& bytes) noexcept {
    POWERKEY_DETAIL_ASSUME_NOT(priority.value() > 7);
    const auto id = make_id({priority, p, destination, source}).value();
    return can::frame(id, can::dlc::make(8).value(), bytes);
}

constexpr std::uint64_t header(std::uint8_t code) noexcept {
    return header_0 | (std::uint64_t{header_1} << 8) | (std::uint64_t{code} << 16);
}
// Bytes [from, 8) FFh.
constexpr std::uint64_t ff_past(unsigned from) noexcept {
    return ~powerkey::detail::low_bits(8 * from);
}
constexpr std::uint64_t at_byte(std::uint8_t v, unsigned i) noexcept {
    return std::uint64_t{v} << (8 * i);
}
template <class E>
constexpr std::uint8_t raw(E e) noexcept {
    return static_cast<std::uint8_t>(e);
}

template <class T>
inline constexpr bool is_command_01 =
    std::is_same_v<T, key_contact> || std::is_same_v<T, set_led> || std::is_same_v<T, set_led_code>;
// The data word of a command 01h message (build's and the direction test's).
constexpr std::uint64_t data_01(const key_contact& v) noexcept {
    return header(0x01) | at_byte(v.key, 3) | at_byte(v.pressed ? 1 : 0, 4) |
           at_byte(v.identifier, 5) | ff_past(6);
}
constexpr std::uint64_t data_01(const set_led& v) noexcept {
    return header(0x01) | at_byte(v.key, 3) | at_byte(raw(v.colour), 4) | at_byte(raw(v.mode), 5) |
           at_byte(raw(v.secondary), 6) | ff_past(7);
}
constexpr std::uint64_t data_01(const set_led_code& v) noexcept {
    return header(0x01) | at_byte(v.key, 3) | at_byte(v.code, 4) | ff_past(5);
}

// The frame of one message, field by field (encode checks the message first: own_check).
template <class T>
constexpr can::frame build([[maybe_unused]] const model_row& r, const T& v) noexcept {
    const auto ef = [&v](const auto& data) {
        return frame_of(proprietary_a_pgn, v.priority, v.destination, v.source, data);
    };
    if constexpr (std::is_same_v<T, set_led>) {
        return ef(can::payload{header_0, header_1, 0x01, v.key, raw(v.colour), raw(v.mode),
                               raw(v.secondary), 0xFF});
    } else if constexpr (is_command_01<T>) {
        return ef(data_01(v));
    } else if constexpr (std::is_same_v<T, heartbeat>) {
        const auto keys = static_cast<std::uint16_t>(v.keys.mask());
        return ef(header(0xF9) | at_byte(v.counter, 3) | (std::uint64_t{keys} << 32) |
                  at_byte(0xFF, 6) | at_byte(v.identifier, 7));
    } else if constexpr (std::is_same_v<T, software_revision>) {
        std::uint64_t d = header(0x2A);
        for (unsigned i = 0; i < 5; ++i) d |= at_byte(v.bytes[i], 3 + i);
        return ef(d);
    } else if constexpr (std::is_same_v<T, led_ack>) {
        return ef(at_byte(raw(v.mode), 1) | at_byte(v.key, 2) | at_byte(raw(v.colour), 3) |
                  at_byte(raw(v.secondary), 4) | ff_past(5));
    } else if constexpr (std::is_same_v<T, led_ack_code>) {
        return ef(at_byte(0xFF, 1) | at_byte(v.key, 2) | at_byte(v.code, 3) | ff_past(4));
    } else if constexpr (std::is_same_v<T, address_claimed>) {
        return frame_of(address_claim_pgn, v.priority, v.destination, v.source, pack_name(v.name));
    } else if constexpr (std::is_same_v<T, multiple_leds>) {
        const std::uint64_t used = powerkey::detail::low_bits(4u * r.plane_leds);
        return frame_of(v.frame.value() == 1 ? multiple_leds_1_pgn : multiple_leds_2_pgn,
                        v.priority, v.destination, v.source, (v.word() & used) | ~used);
    } else if constexpr (std::is_same_v<T, command>) {
        const command_row* row = find_command(raw(v.code));
        if (row == nullptr) return ef(header(raw(v.code)) | ff_past(3));
        return ef(header(raw(v.code)) | at_byte(write_param(row->p1, v), 3) |
                  at_byte(write_param(row->p2, v), 4) | ff_past(5));
    } else {
        static_assert(std::is_same_v<T, switch_to_canopen>);
        return encode(v);
    }
}

// --- the checks of encode, made on the message (issue 24) ----------------------------------------
// Each is what decode finds in the frame build makes of the message, in decode's order, so that
// encode needs no decoder: decode's error for that frame, or value_out_of_range when the frame
// reads back as another message (another kind, or a member the frame cannot carry). The small
// tests decode makes (the route, the model's word, the direction of 01h, a command's parameter
// bytes) are the decoder's own functions. tests/test_keypad_j1939_codec.cpp compares every check
// with building the frame and reading it back, over every model and many values of every field.

// decode's first test of a frame's identifier when narrowed: from the keypad or to it.
constexpr errc narrowed(const route& at, keypad_address keypad) noexcept {
    return keypad && at.source != *keypad && at.destination != *keypad ? errc::wrong_id : errc{};
}
template <class T>
constexpr route message_route(const T& v) noexcept {
    return {v.priority, v.destination, v.source};
}

// A command 01h frame w up to its fields: the route, the direction decode reads it in (`led`),
// the model's word on that direction and the reserved bytes of that layout (command_01_of,
// key_contact_of, set_led_of).
constexpr errc check_01(const model_row& r, const route& at, std::uint64_t w, keypad_address keypad,
                        bool& led) noexcept {
    if (const errc e = narrowed(at, keypad); e != errc{}) return e;
    led = is_led_command(r, at, w, keypad);
    if (led) {
        if (const errc e = received(r, feature::led_command, at, keypad); e != errc{}) return e;
        const bool reserved_ff = r.form == led_form::code ? ff_from(w, 5) : byte_of(w, 7) == 0xFF;
        return reserved_ff ? errc{} : errc::reserved_not_ff;
    }
    if (const errc e = sent(r, feature::key_contact, at, keypad); e != errc{}) return e;
    return ff_from(w, 6) ? errc{} : errc::reserved_not_ff;
}
// The fields of each layout of 01h, as decode checks them.
constexpr bool key_contact_fits(const key_contact& v) noexcept {
    return v.key >= 1 && v.key <= 16 && v.identifier != 0xFF;
}
constexpr bool set_led_fits(const model_row& r, const set_led& v) noexcept {
    return has_led(r, v.key) && is_colour(raw(v.colour)) && raw(v.mode) <= 3 &&
           is_secondary(raw(v.secondary));
}

constexpr errc own_check(const model_row& r, const key_contact& v, keypad_address keypad) noexcept {
    bool led = false;
    if (const errc e = check_01(r, message_route(v), data_01(v), keypad, led); e != errc{})
        return e;
    return !led && key_contact_fits(v) ? errc{} : errc::value_out_of_range;
}
constexpr errc own_check(const model_row& r, const set_led& v, keypad_address keypad) noexcept {
    bool led = false;
    if (const errc e = check_01(r, message_route(v), data_01(v), keypad, led); e != errc{})
        return e;
    return led && r.form == led_form::si && set_led_fits(r, v) ? errc{} : errc::value_out_of_range;
}
constexpr errc own_check(const model_row& r, const set_led_code& v,
                         keypad_address keypad) noexcept {
    bool led = false;
    if (const errc e = check_01(r, message_route(v), data_01(v), keypad, led); e != errc{})
        return e;
    return led && r.form == led_form::code && has_led(r, v.key) ? errc{} : errc::value_out_of_range;
}

// The heartbeat: key bits above the model's keys are reserved (0); a key above 16 has no bit.
constexpr errc heartbeat_keys(const model_row& r, std::uint64_t keys) noexcept {
    if (((keys & 0xFFFF) >> r.keys) != 0) return errc::reserved_not_zero;
    return keys > 0xFFFF ? errc::value_out_of_range : errc{};
}
constexpr errc own_check(const model_row& r, const heartbeat& v, keypad_address keypad) noexcept {
    const route at = message_route(v);
    if (const errc e = narrowed(at, keypad); e != errc{}) return e;
    if (const errc e = sent(r, feature::heartbeat, at, keypad); e != errc{}) return e;
    return heartbeat_keys(r, v.keys.mask());
}

// The answer to 2Ah; all five bytes FFh is the request's frame.
constexpr errc own_check(const model_row& r, const software_revision& v,
                         keypad_address keypad) noexcept {
    const route at = message_route(v);
    if (const errc e = narrowed(at, keypad); e != errc{}) return e;
    bool request = true;
    for (const std::uint8_t b : v.bytes) request = request && b == 0xFF;
    if (request) {
        const errc e = received(r, feature::software_revision, at, keypad);
        return e != errc{} ? e : errc::value_out_of_range;
    }
    if (const errc e = sent(r, feature::software_revision, at, keypad); e != errc{}) return e;
    bool ended = false;
    for (const std::uint8_t b : v.bytes) {
        if (b == 0)
            ended = true;
        else if (ended || !(b >= 0x20 && b <= 0x7E))  // ASCII, and nothing after a 00h
            return errc::value_out_of_range;
    }
    return errc{};
}

// The LED acknowledgement: the model's form decides how its bytes read.
constexpr errc own_check(const model_row& r, const led_ack& v, keypad_address keypad) noexcept {
    const route at = message_route(v);
    if (const errc e = narrowed(at, keypad); e != errc{}) return e;
    if (const errc e = sent(r, feature::led_ack, at, keypad); e != errc{}) return e;
    if (r.form == led_form::code)
        return raw(v.mode) != 0xFF || raw(v.secondary) != 0xFF ? errc::reserved_not_ff
                                                               : errc::value_out_of_range;
    const bool fits = raw(v.mode) <= 3 && has_led(r, v.key) && is_colour(raw(v.colour)) &&
                      is_secondary(raw(v.secondary));
    return fits ? errc{} : errc::value_out_of_range;
}
constexpr errc own_check(const model_row& r, const led_ack_code& v,
                         keypad_address keypad) noexcept {
    const route at = message_route(v);
    if (const errc e = narrowed(at, keypad); e != errc{}) return e;
    if (const errc e = sent(r, feature::led_ack, at, keypad); e != errc{}) return e;
    return r.form == led_form::code && has_led(r, v.key) ? errc{} : errc::value_out_of_range;
}

// The NAME: every value of its fields has its bits (bit 48 stays 0).
constexpr errc own_check(const model_row& r, const address_claimed& v,
                         keypad_address keypad) noexcept {
    const route at = message_route(v);
    if (const errc e = narrowed(at, keypad); e != errc{}) return e;
    return sent(r, feature::address_claim, at, keypad);
}

// A multiple-LED frame: codes Ah..Eh are not used; LEDs past the model's have no nibble.
constexpr errc own_check(const model_row& r, const multiple_leds& v,
                         keypad_address keypad) noexcept {
    const route at = message_route(v);
    if (const errc e = narrowed(at, keypad); e != errc{}) return e;
    if (const errc e = received(r, feature::multiple_leds, at, keypad); e != errc{}) return e;
    const std::uint64_t w = v.word();
    for (unsigned k = 0; k < r.plane_leds; ++k) {
        const auto c = static_cast<unsigned>((w >> (4 * k)) & 0xF);
        if (c > 9 && c < 0xF) return errc::value_out_of_range;  // Ah..Eh
    }
    return (w & ~powerkey::detail::low_bits(4u * r.plane_leds)) != 0 ? errc::value_out_of_range
                                                                     : errc{};
}

// A configuration command: its code byte as decode dispatches it (01h, F9h and 80h are other
// frames: build's bytes after them are FFh), then its parameters through decode's own reader and
// the members its row does not name at their defaults.
constexpr errc own_check(const model_row& r, const command& v, keypad_address keypad) noexcept {
    const route at = message_route(v);
    if (const errc e = narrowed(at, keypad); e != errc{}) return e;
    const std::uint8_t code = raw(v.code);
    const auto other = [](errc e) { return e != errc{} ? e : errc::value_out_of_range; };
    if (code == 0x01) {
        bool led = false;
        return other(check_01(r, at, header(0x01) | ff_past(3), keypad, led));
    }
    if (code == 0xF9) {
        if (const errc e = sent(r, feature::heartbeat, at, keypad); e != errc{}) return e;
        return other(heartbeat_keys(r, 0xFFFF));
    }
    if (code == 0x80) return other(received(r, feature::switch_to_canopen, at, keypad));
    const command_row* row = find_command(code);
    if (row == nullptr) return errc::unknown_command;
    if (const errc e = received(r, row->what, at, keypad); e != errc{}) return e;
    command c{};
    c.priority = v.priority;
    c.destination = v.destination;
    c.source = v.source;
    c.code = row->code;
    if (const errc e = read_param(row->p1, write_param(row->p1, v), c); e != errc{}) return e;
    if (const errc e = read_param(row->p2, write_param(row->p2, v), c); e != errc{}) return e;
    return c == v ? errc{} : errc::value_out_of_range;
}

constexpr errc own_check(const model_row& r, const switch_to_canopen& v,
                         keypad_address keypad) noexcept {
    const route at = message_route(v);
    if (const errc e = narrowed(at, keypad); e != errc{}) return e;
    if (const errc e = received(r, feature::switch_to_canopen, at, keypad); e != errc{}) return e;
    return v.form == frame_form::manual ? errc{} : errc::value_out_of_range;
}

}  // namespace detail

// Any frame of a keypad of model m, in J1939. Checks in this order, and errors:
//   value_out_of_range  m is not a model
//   wrong_id_format     an 11-bit frame
//   wrong_id            a PGN other than EF00h, A700h, A600h, EE00h (not a keypad frame); with
//                       `keypad`, a frame neither from nor to it, a keypad frame not from it or a
//                       command not to it
//   wrong_length        not 8 data bytes
//   unknown_command     EF00h data without the 04 1B header (and not the acknowledgement's 00h),
//                       a command byte no manual has; a frame the model's manual does not have
//   undocumented        a frame whose layout on this model no source shows; a command to the
//                       global address FFh
//   reserved_not_ff     a "not used" byte that is not FFh
//   reserved_not_zero   a heartbeat key bit above the model's keys; the NAME's reserved bit
//   value_out_of_range  a field outside its range (key 00h or above 10h, an LED the model lacks,
//                       a colour above 09h, a state above 03h, a level above 3Fh, a baud code
//                       other than 02h/03h, a reserved address FEh, a period below 05h, a
//                       multiple-LED code Ah..Eh, revision bytes that are not ASCII, ...)
namespace detail {
// decode, building the variant M (j1939::message, or powerkey::message for keypad/codec.hpp).
// The identifier's fields.
constexpr route route_of(std::uint32_t id) noexcept {
    return {priority::make((id >> 26) & 7u).value(), static_cast<std::uint8_t>(id >> 8),
            static_cast<std::uint8_t>(id)};
}

// A 29-bit frame on a keypad PGN (pf: is_keypad_pf) of a keypad of row r, every check in the
// order decode documents. Out of line: the frequent frames that pass every check are answered
// before it (decode_frame).
template <class M>
constexpr result<M> check_and_decode(const can::frame& f, std::uint32_t pf, const model_row& r,
                                     keypad_address keypad) noexcept {
    const route at = route_of(f.raw_id());
    if (keypad && at.source != *keypad && at.destination != *keypad) return errc::wrong_id;
    if (f.size() != 8) return errc::wrong_length;
    const std::uint64_t w = f.data_le();
    switch (pf) {
        case 0xEF: return decode_proprietary_a<M>(r, at, w, keypad);
        case 0xA7: return multiple_leds_of<M>(r, at, 1, w, keypad);
        case 0xA6: return multiple_leds_of<M>(r, at, 2, w, keypad);
        default: return address_claimed_of<M>(r, at, w, keypad);
    }
}
template <class M>
POWERKEY_DETAIL_COLD constexpr result<M> decode_checked(const can::frame& f, std::uint32_t pf,
                                                        const model_row& r,
                                                        keypad_address keypad) noexcept {
    return check_and_decode<M>(f, pf, r, keypad);
}
template <class M>
POWERKEY_DETAIL_COLD constexpr result<M> decode_checked(const can::frame& f, std::uint32_t pf,
                                                        const model_row& r) noexcept {
    return check_and_decode<M>(f, pf, r, std::nullopt);
}

// The LED commands' and acknowledgement's bound of LED - 1 in the fast path's bytes_at_most, and
// the test of the LED's bit below it: with the row a constant (decode<M>: Row a reference) whose
// LEDs are 1..n, n - 1 and no bit to test; otherwise 0Fh and the LED's bit in the row.
template <class Row>
constexpr std::uint64_t led_bound(const model_row& r) noexcept {
    if constexpr (std::is_reference_v<Row>)
        if (r.leds != 0 && std::has_single_bit(r.leds + 1u))
            return static_cast<std::uint64_t>(std::popcount(r.leds) - 1);
    return 0x0F;
}
template <class Row>
constexpr bool has_led_below_bound(const model_row& r, std::uint8_t k) noexcept {
    if (led_bound<Row>(r) != 0x0F) return true;
    return ((r.leds >> (k - 1)) & 1u) != 0;
}

// The model row as decode_frame takes it: a copy, whose fields g++ reads where they are kept
// (through a reference it recomputed the row's address from a spilled model at each use); under
// -Os a reference, the smaller call.
using row_argument = std::conditional_t<POWERKEY_DETAIL_SIZE, const model_row&, const model_row>;

// A frame of a keypad of row r (decode after the model's test). The frames of a keypad on its bus
// (key contact state, heartbeat, SI LED command and acknowledgement, the multiple-LED frames, the
// level commands 02h and 03h), from or to any address, are answered in place when every check
// decode_checked makes passes: one test of the identifier (29-bit, the PGN) and the length, one
// of the header and command byte, the model's word on the frame, the fields' ranges in as few
// tests as they fold into. Anything else, a frame refused included, goes through the checks in
// decode's order (decode_checked, out of line), so the fast path only ever answers what
// decode_checked answers. Under -Os one decoder, decode_checked.
template <class M, class Row = row_argument>
POWERKEY_DETAIL_HOT constexpr result<M> decode_frame(const can::frame& f,
                                                     std::type_identity_t<Row> r,
                                                     keypad_address keypad) noexcept {
    const std::uint32_t id = f.id_word();
    const std::uint32_t pf = (id >> 16) & 0x83FF;  // the 29-bit flag, EDP, DP and PDU format
    if (!POWERKEY_DETAIL_SIZE && !keypad && f.size() == 8) {
        const std::uint64_t w = f.data_le();
        // To the global address FFh (PDU specific), tested where it decides, by an add that
        // carries out of FFh only: g++ then stores the destination from the identifier with the
        // other bytes of the answer rather than as a constant FFh on its own.
        const auto to_global = [id] { return ((id + 0x100) & 0xFF00) == 0; };
        // The 29-bit flag, EDP, DP and PDU format where the identifier has them (no shift).
        const std::uint32_t at_pf = id & 0x83FF'0000;
        if ((id & 0x83FF'FF00) == 0x80EF'FF00) {
            // Proprietary A to the global address FFh: the keypad's own frames (a command to
            // the global address is refused: to_keypad). The PGN and the direction of 01h in one
            // compare. Header and command byte; the tests in the order of their frames' share.
            const auto head = static_cast<std::uint32_t>(w) & 0xFF'FFFF;
            if (head == 0x01'1B04) {
                // The key contact state (is_led_command). Less 01h at byte 3 and FF FF at bytes
                // 6 and 7, and turned by three bytes: key - 1 at most 0Fh (a key 00h borrows and
                // fails there) and the state 00h/01h by their masks in the high bytes, bytes 7,
                // 6 and 5 FF FF 00h..FEh (the identifier not FFh) as the low three at most FEh
                // (any other value, or a borrow, makes them more).
                if ((std::rotl(w - 0xFFFF'0000'0100'0000, 24) & 0xFEF0'0000'00FF'FFFF) <= 0xFE &&
                    r.frames.has(feature::key_contact)) {
                    // The route, then key, state and identifier where the frame has them
                    // (bytes 3..5); bytes 6 and 7, the struct's padding, 00h.
                    const std::uint64_t v = route_word_to_global(id) | (w & 0xFFFF'FF00'0000);
                    return answer<M>(in_place_of<key_contact>(v));
                }
            } else if (head == 0xF9'1B04) {
                // The heartbeat: byte 6 FFh and no key bit above the model's keys, in one masked
                // compare (decode<M>: 46 against 50 instructions a heartbeat; j1939::decode,
                // whose mask is made on each frame, 54 against 53).
                const auto keys = static_cast<std::uint32_t>((w >> 32) & 0xFFFF);
                const std::uint64_t above = (0xFFFF'0000'0000 << r.keys) & 0xFFFF'0000'0000;
                if ((w & (above | 0xFF'0000'0000'0000)) == 0xFF'0000'0000'0000 &&
                    r.frames.has(feature::heartbeat)) {
                    // The route and counter as one word, keys and identifier apart (the
                    // identifier moved from byte 7 to 6 for one word cost 5 more: the struct's
                    // last byte is padding, so g++ stored 4, 2 and 1 bytes all the same).
                    const std::uint64_t v = route_word(id) | (w & 0xFF00'0000);
                    return answer<M>(heartbeat{.source = byte_of(v, 0),
                                               .destination = byte_of(v, 1),
                                               .priority = priority::make(byte_of(v, 2)).value(),
                                               .counter = byte_of(v, 3),
                                               .keys = key_set::from_mask(keys),
                                               .identifier = byte_of(w, 7)});
                }
            } else if ((head & 0xFF) == 0) {
                // The SI acknowledgement: 00h | state | LED | colour | secondary | FF FF FF. As
                // the LED command's: bytes 5..7 FFh (plus 1 at byte 5, 00h), the state, LED - 1
                // and colours at most 03h, 0Fh, 09h, 09h (a secondary FFh goes to
                // decode_checked); an LED the model has.
                if (bytes_at_most(w + 0xFF'FFFF'0000, 0x09'0900'0300 | (led_bound<Row>(r) << 16)) &&
                    r.form == led_form::si && r.frames.has(feature::led_ack) &&
                    has_led_below_bound<Row>(r, byte_of(w, 2))) {
                    // State, LED, colour and secondary colour from bytes 1..4 to bytes 3..6.
                    return answer<M>(in_place_of<led_ack>(route_word_to_global(id) |
                                                          ((w << 16) & 0x00FF'FFFF'FF00'0000)));
                }
            }
        } else if ((id & 0x83B6'0000) != 0x80A6'0000) {
            // A PDU format other than A6h, A7h, EEh, EFh (and AEh, AFh, E6h, E7h, which differ
            // from them in bits 3 and 6 alone, and go on to the tests below): a 29-bit frame on
            // another PGN is not a keypad frame. One test where three were.
            if (id >= 0x8000'0000 && is_row(r)) return errc::wrong_id;
        } else if (at_pf == 0x80EF'0000) {
            // Proprietary A to one address: the commands (the keypad's own frames to an address
            // go to decode_checked).
            const auto head = static_cast<std::uint32_t>(w) & 0xFF'FFFF;
            if (head == 0x01'1B04) {
                if (bytes_at_most(w + 0x00FF'FFFF'FF00'0000,
                                  0x0009'0309'0001'1B04 | (led_bound<Row>(r) << 24)) &&
                    r.form == led_form::si && r.frames.has(feature::led_command) &&
                    has_led_below_bound<Row>(r, byte_of(w, 3))) {
                    // Addressed with byte 6 not FFh, the LED command (is_led_command): in one
                    // add and one bytes_at_most, byte 7 FFh (plus 1 it is 00h, its carry out of
                    // the word) and the LED - 1, colour, state and secondary colour at most 0Fh,
                    // 09h, 03h, 09h (an LED 00h borrows and fails there; the header's bytes are
                    // their own bounds); an LED the model has.
                    return answer<M>(
                        in_place_of<set_led>(route_word(id) | (w & 0x00FF'FFFF'FF00'0000)));
                }
            } else if ((head | 0x01'0000) == 0x03'1B04) {
                // LED brightness (02h) and backlight level (03h): 04 1B cmd | level | FF FF FF FF.
                const bool led = head == 0x02'1B04;
                if (ff_from(w, 4) && byte_of(w, 3) <= level::max &&
                    r.frames.has(led ? feature::led_brightness : feature::backlight_level)) {
                    const route at = route_of(id);
                    command c{};
                    c.priority = at.priority;
                    c.destination = at.destination;
                    c.source = at.source;
                    c.code =
                        led ? command_code::set_led_brightness : command_code::set_backlight_level;
                    c.level = level::make(byte_of(w, 3)).value();
                    return answer<M>(c);
                }
            }
        } else if ((at_pf & ~0x1'0000u) == 0x80A6'0000) {  // a multiple-LED frame, A700h or A600h
            // A model with the frame has 1..16 LEDs in it (rows_consistent, j1939_models.hpp), so
            // that the mask of their nibbles is one shift.
            if (r.frames.has(feature::multiple_leds) && !to_global()) {
                const std::uint64_t used = ~std::uint64_t{0} >> (64 - 4u * r.plane_leds);
                // The codes of the frame's LEDs alone (the nibbles past them are Fh, tested
                // first): 74 -> 72 instructions a multiple-LED frame through j1939::decode.
                if ((w | used) == ~std::uint64_t{0} && !has_unused_code(w & used)) {
                    // The route and the frame (1 for A700h, whose PDU format's bit 0 is set;
                    // 2 for A600h) as one word.
                    const auto v = static_cast<std::uint32_t>(route_word(id)) + 0x0200'0000 -
                                   ((id << 8) & 0x0100'0000);
                    return answer<M>(
                        multiple_leds{.source = byte_of(v, 0),
                                      .destination = byte_of(v, 1),
                                      .priority = priority::make(byte_of(v, 2)).value(),
                                      .frame = colour_frame::make(byte_of(v, 3)).value(),
                                      .nibbles = multiple_leds::halves(w & used)});
                }
            }
        }
    }
    // Not a model (decode_as's row_or_none; under -Os decode_as tests the model itself).
    if (!POWERKEY_DETAIL_SIZE && !is_row(r)) return errc::value_out_of_range;
    if (!f.is_extended()) return errc::wrong_id_format;
    // Most 29-bit frames on a bus are not a keypad's: refused here, without a call.
    if (!is_keypad_pf(pf & 0x3FF)) return errc::wrong_id;
    // Any keypad: a call without the (empty) address, which would take a register for nothing
    // (under -Os one function, the one with the address).
    if (!POWERKEY_DETAIL_SIZE && !keypad) return decode_checked<M>(f, pf & 0x3FF, r);
    return decode_checked<M>(f, pf & 0x3FF, r, keypad);
}
// decode without the fast path: every frame through the checks in order. The tests and the fuzz
// target hold decode to it.
template <class M>
constexpr result<M> decode_checked_only(const can::frame& f, model m,
                                        keypad_address keypad) noexcept {
    if (!is_j1939_model(m)) return errc::value_out_of_range;
    if (!f.is_extended()) return errc::wrong_id_format;
    const std::uint32_t pf = (f.raw_id() >> 16) & 0x3FF;
    if (!is_keypad_pf(pf)) return errc::wrong_id;
    return check_and_decode<M>(f, pf, j1939_row_of(m), keypad);
}
template <class M>
POWERKEY_DETAIL_HOT constexpr result<M> decode_as(const can::frame& f, model m,
                                                  keypad_address keypad) noexcept {
    if constexpr (POWERKEY_DETAIL_SIZE) {
        if (!is_j1939_model(m)) return errc::value_out_of_range;
        return decode_frame<M>(f, j1939_row_of(m), keypad);
    } else {
        return decode_frame<M>(f, row_or_none(m), keypad);
    }
}
}  // namespace detail

[[nodiscard]] POWERKEY_DETAIL_HOT constexpr result<message> decode(
    const can::frame& f, model m, keypad_address keypad = std::nullopt) noexcept {
    return detail::decode_as<message>(f, m, keypad);
}

// The frames of command 01h alone: the keypad's key contact state and the LED command to it (the
// SI form set_led, the LI form set_led_code), for a program that speaks nothing else (the J1939
// firmware of docs/performance.md): decode's answer when f is one of them, decode's error when f
// is a command 01h frame it refuses, wrong_id for any other frame (another PGN, another command
// byte, no `04 1B` header). Only this part of the J1939 decoder is in the program.
using key_or_led = std::variant<key_contact, set_led, set_led_code>;
[[nodiscard]] constexpr result<key_or_led> decode_key_or_led(
    const can::frame& f, model m, keypad_address keypad = std::nullopt) noexcept {
    if (!detail::is_j1939_model(m)) return errc::value_out_of_range;
    if (!f.is_extended()) return errc::wrong_id_format;
    if (((f.raw_id() >> 16) & 0x3FF) != 0xEF) return errc::wrong_id;
    const detail::route at = detail::route_of(f.raw_id());
    if (keypad && at.source != *keypad && at.destination != *keypad) return errc::wrong_id;
    if (f.size() != 8) return errc::wrong_length;
    const std::uint64_t w = f.data_le();
    if ((w & 0xFF'FFFF) != detail::header(0x01)) return errc::wrong_id;
    return detail::command_01_of<key_or_led>(detail::j1939_row_of(m), at, w, keypad);
}

// The frame of msg for a keypad of model m, such that decode(frame, m, keypad) == msg. A message
// decode could never return is refused with the error decode gives its frame, or with
// value_out_of_range when the frame decodes to another meaning (a member the command does not
// use set, an LED past the model's multiple-LED frame, an addressed key state whose bytes read
// as an LED command: narrow to the keypad to send it). The message checks its own fields
// (detail::own_check): no decoder is in a program that only encodes.
// One alternative of j1939::message: encode(m, set_led{...}) needs no visit of the variant.
template <class T>
concept message_alternative = []<class... A>(std::type_identity<std::variant<A...>>) {
    return (std::is_same_v<T, A> || ...);
}(std::type_identity<message>{});

namespace detail {
template <class T>
POWERKEY_DETAIL_INLINE constexpr result<can::frame> encode_on(const model_row& r, const T& msg,
                                                              keypad_address keypad) noexcept {
    if (const errc e = own_check(r, msg, keypad); e != errc{}) return e;
    return build(r, msg);
}
}  // namespace detail

template <message_alternative T>
[[nodiscard]] constexpr result<can::frame> encode(model m, const T& msg,
                                                  keypad_address keypad = std::nullopt) noexcept {
    if (!detail::is_j1939_model(m)) return errc::value_out_of_range;
    return detail::encode_on(detail::j1939_row_of(m), msg, keypad);
}

[[nodiscard]] constexpr result<can::frame> encode(model m, const message& msg,
                                                  keypad_address keypad = std::nullopt) noexcept {
    return std::visit([m, keypad](const auto& v) { return encode(m, v, keypad); }, msg);
}

// --- a keypad known when the program is built ----------------------------------------------------
// decode, decode_key_or_led, decode_key_contact and encode with the model a template argument:
// decode<model::pkp2600si>(f, keypad). The same engine as the calls above, with the same results
// for every frame and message (tests/test_keypad_j1939_typed.cpp runs every manual row through
// both, for every model). A reader inlines the engine whole (POWERKEY_DETAIL_FLATTEN) and is
// itself inlined into its caller as j1939::decode is (POWERKEY_DETAIL_HOT; called, its answer
// went back through memory: 72.2 against 54.3 instructions a frame on the J1939 mixed log), and
// encode<M> of one message type is inlined into its caller with the message's own check, so that
// the model's row is a constant: no model table, and not the paths this model never takes
// (another LED form, frames its manual does not have). Where the caller's keypad address and
// fields are constants, they fold too. Under -Os each is one function, called.

template <model M>
[[nodiscard]] POWERKEY_DETAIL_FLATTEN POWERKEY_DETAIL_HOT constexpr result<message> decode(
    const can::frame& f, keypad_address keypad = std::nullopt) noexcept {
    static_assert(detail::is_j1939_model(M), "M is a row of the J1939 model table");
    // The row by reference: a constant, whose fields the fast path reads where they are and whose
    // address the out-of-line reader takes (a copy was made on every frame: 50.4 against 48.6
    // instructions a frame on the J1939 mixed log).
    return detail::decode_frame<message, const model_row&>(f, detail::j1939_row_of(M), keypad);
}

template <model M>
[[nodiscard]] POWERKEY_DETAIL_FLATTEN POWERKEY_DETAIL_HOT constexpr result<key_or_led>
decode_key_or_led(const can::frame& f, keypad_address keypad = std::nullopt) noexcept {
    static_assert(detail::is_j1939_model(M), "M is a row of the J1939 model table");
    return decode_key_or_led(f, M, keypad);
}

template <model M, message_alternative T>
[[nodiscard]] POWERKEY_DETAIL_INLINE constexpr result<can::frame> encode(
    const T& msg, keypad_address keypad = std::nullopt) noexcept {
    static_assert(detail::is_j1939_model(M), "M is a row of the J1939 model table");
    return detail::encode_on(detail::j1939_row_of(M), msg, keypad);
}

template <model M>
[[nodiscard]] POWERKEY_DETAIL_FLATTEN constexpr result<can::frame> encode(
    const message& msg, keypad_address keypad = std::nullopt) noexcept {
    static_assert(detail::is_j1939_model(M), "M is a row of the J1939 model table");
    return encode(M, msg, keypad);
}

namespace detail {
// decode_key_contact up to the key contact state's own fields: one errc, so that the caller builds
// one error result (each error path of a result<key_contact> writes a default message).
constexpr errc key_contact_front(const can::frame& f, const model_row& r,
                                 keypad_address keypad) noexcept {
    if (!f.is_extended()) return errc::wrong_id_format;
    if (((f.raw_id() >> 16) & 0x3FF) != 0xEF) return errc::wrong_id;
    const route at = route_of(f.raw_id());
    if (keypad && at.source != *keypad && at.destination != *keypad) return errc::wrong_id;
    if (f.size() != 8) return errc::wrong_length;
    const std::uint64_t w = f.data_le();
    if ((w & 0xFF'FFFF) != header(0x01)) return errc::wrong_id;
    if (is_led_command(r, at, w, keypad)) return errc::wrong_id;  // an LED command to the keypad
    return sent(r, feature::key_contact, at, keypad);
}
}  // namespace detail

// The key contact state alone, for a controller that reads nothing else from its keypad (the J1939
// firmware of docs/performance.md): decode's answer when f is a key contact state (command 01h
// read in the keypad's direction, as decode reads it), decode's error when f is one it refuses,
// wrong_id for any other frame (an LED command to the keypad included). Only the model's key
// contact path is in the program.
template <model M>
[[nodiscard]] POWERKEY_DETAIL_FLATTEN POWERKEY_DETAIL_HOT constexpr result<key_contact>
decode_key_contact(const can::frame& f, keypad_address keypad = std::nullopt) noexcept {
    static_assert(detail::is_j1939_model(M), "M is a row of the J1939 model table");
    const errc e = detail::key_contact_front(f, detail::j1939_row_of(M), keypad);
    if (e != errc{}) return e;
    return detail::key_contact_of<key_contact>(detail::route_of(f.raw_id()), f.data_le());
}
}  // namespace powerkey::j1939

#endif  // POWERKEY_KEYPAD_J1939_CODEC_HPP
