// powerkey: every frame of every keypad behind two calls, driven by the model table:
//   decode(frame, node, model)     -> result<message>      any CAN frame to its meaning, or an errc
//   encode(node, model, message)   -> result<can::frame>   the inverse: encode(decode(f)) == f
// What each accepts and refuses: docs/decoder.md; why the code is shaped as it is:
// docs/performance.md, "The codec's shape".
#ifndef POWERKEY_KEYPAD_CODEC_HPP
#define POWERKEY_KEYPAD_CODEC_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/canopen/sync.hpp>
#include <powerkey/detail/bytes.hpp>
#include <powerkey/detail/inline.hpp>
#include <powerkey/detail/lookup.hpp>
#include <powerkey/j1939/protocol_switch.hpp>
#include <powerkey/keypad/commands.hpp>
#include <powerkey/keypad/j1939_codec.hpp>
#include <powerkey/keypad/lookup.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/keypad/value_kinds.hpp>
#include <powerkey/result.hpp>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <variant>

namespace powerkey {

namespace detail {

// An alternative of message, built in the caller's result (no message built and moved).
template <class T>
constexpr result<message> answer(const T& v) noexcept {
    return result<message>(std::in_place, std::in_place_type<T>, v);
}

// A frame of a length its identifier does not have: wrong_length read strictly, else read again
// (reread; docs/decoder.md, "Tolerant and strict reading"). Defined before any use: clang
// evaluates a constant expression only through functions defined where it is used.
template <bool j1939, class Layout>
constexpr result<message> reread(const can::frame& f, const Layout& keypad) noexcept;
template <reading how, class Frame, class Layout>
constexpr result<message> misfit(const Frame& f, const Layout& keypad) noexcept {
    if constexpr (how == reading::strict)
        return errc::wrong_length;
    else
        return reread<true>(f, keypad);
}

// A CiA 301 or J1939 decoder's answer (NMT, SYNC, the switch back), wrong_length as misfit's.
template <reading how, class T, class Layout>
constexpr result<message> lift(const result<T>& r, const can::frame& f,
                               const Layout& keypad) noexcept {
    if (!r) return r.error() == errc::wrong_length ? misfit<how>(f, keypad) : r.error();
    return answer(*r);
}

// --- SDO values ---------------------------------------------------------------------------------
// What each kind checks and reads is its own (value_kinds.hpp); here is only the dispatch.

// The expedited size of row r's value: its own, or its kind's (K::size) when the row leaves it 0.
constexpr std::uint8_t row_size(const model_layout& keypad, const codec_row& r,
                                std::uint8_t carried) noexcept {
    if (r.size() != 0) return r.size();
    if (r.kind == value_kind::led_plane) return value_kinds::led_plane::size(keypad, r, carried);
    if (r.kind == value_kind::keys) return value_kinds::keys::size(keypad, r, carried);
    return value_kinds::string::size(keypad, r, carried);
}
// The same as the decoder tests it: the SI keys of two sizes check theirs in their kind.
POWERKEY_DETAIL_INLINE constexpr std::uint8_t decoded_size(const model_layout& keypad,
                                                           const codec_row& r,
                                                           std::uint8_t carried) noexcept {
    if (r.size() != 0) return r.size();
    if (r.kind == value_kind::led_plane) return value_kinds::led_plane::size(keypad, r, carried);
    return carried;
}
// Every row of size 0 is a string, a per-colour plane or the SI keys of two sizes.
constexpr bool sized_rows_known() noexcept {
    for (const codec_row& r : codec_rows)
        if (r.size() == 0 && r.key != no_codec_row.key && r.kind != value_kind::led_plane &&
            r.kind != value_kind::keys && r.kind != value_kind::string)
            return false;
    return true;
}
static_assert(sized_rows_known());

// The largest value of each expedited size (a table: no 64-bit shift by a variable).
inline constexpr std::uint32_t largest_of_size[8] = {
    0, 0xFF, 0xFFFF, 0xFF'FFFF, 0xFFFF'FFFF, 0xFFFF'FFFF, 0xFFFF'FFFF, 0xFFFF'FFFF};

// The sdo_write (`write`) or sdo_read_reply of row r with value v.
POWERKEY_DETAIL_HOT constexpr result<message> value_answer(const codec_row& r,
                                                           const object_value& v,
                                                           bool write) noexcept {
    if (write) return answer(sdo_write{r.id, v});
    return answer(sdo_read_reply{r.id, v});
}

// Kind K's value of row r, checked, as its message.
template <class K>
POWERKEY_DETAIL_INLINE constexpr result<message> kind_message(const model_layout& keypad,
                                                              const codec_row& r, std::uint8_t size,
                                                              std::uint32_t data,
                                                              bool write) noexcept {
    if (const errc e = K::check(keypad, r, size, data, write); e != errc{}) return e;
    return value_answer(r, K::value(keypad, r, size, data), write);
}

// The kinds that decoders meet rarely (K::common false), out of line.
POWERKEY_DETAIL_COLD constexpr result<message> rare_value(const model_layout& keypad,
                                                          const codec_row& r, std::uint8_t size,
                                                          std::uint32_t data, bool write) noexcept {
    switch (r.kind) {
#define POWERKEY_DETAIL_RARE_CASE(name)                                           \
    case value_kind::name:                                                        \
        if constexpr (!value_kinds::name::common)                                 \
            return kind_message<value_kinds::name>(keypad, r, size, data, write); \
        break;
        POWERKEY_VALUE_KINDS(POWERKEY_DETAIL_RARE_CASE)
#undef POWERKEY_DETAIL_RARE_CASE
    }
    return errc::unknown_object;
}

// The sdo_write (`write`) or sdo_read_reply of row r's value in the `size` (1..4) little-endian
// bytes of `data`. Errors: size_mismatch, reserved_not_zero (bytes past the size), then K::check's.
POWERKEY_DETAIL_HOT constexpr result<message> value_message(const model_layout& keypad,
                                                            const codec_row& r, std::uint8_t size,
                                                            std::uint32_t data,
                                                            bool write) noexcept {
    if (size != decoded_size(keypad, r, size)) return errc::size_mismatch;
    if (data > largest_of_size[size & 7u]) return errc::reserved_not_zero;  // bytes past the size
    switch (r.kind) {
#define POWERKEY_DETAIL_COMMON_CASE(name)                                         \
    case value_kind::name:                                                        \
        if constexpr (value_kinds::name::common)                                  \
            return kind_message<value_kinds::name>(keypad, r, size, data, write); \
        break;
        POWERKEY_VALUE_KINDS(POWERKEY_DETAIL_COMMON_CASE)
#undef POWERKEY_DETAIL_COMMON_CASE
    }
    return rare_value(keypad, r, size, data, write);
}

// The expedited bytes of a value of row r (what value_message reads back; the codec checks it).
constexpr canopen::expedited_data write_value(const model_layout& keypad, const codec_row& r,
                                              const object_value& v) noexcept {
    const std::uint8_t carried = v.size >= 1 && v.size <= 4 ? v.size : std::uint8_t{4};
    return visit_kind(r.kind, [&](auto k) {
        using K = decltype(k);
        const std::uint8_t size = r.size() != 0 ? r.size() : K::size(keypad, r, carried);
        canopen::expedited_data d{
            canopen::expedited_size::make(size).value_or(canopen::expedited_size{4}), {}};
        store_le<4>(d.bytes, 0, K::pack(keypad, r, v));
        return d;
    });
}

// --- the command module -------------------------------------------------------------------------

// Errors: value_out_of_range for a parameter outside its range.
constexpr errc read_param(const model_layout& keypad, command_param p, std::uint8_t b,
                          command& c) noexcept {
    switch (p) {
        case command_param::none: return errc{};
        case command_param::key:
            if (b < 1 || b > keypad.keys) return errc::value_out_of_range;
            c.key = b;
            return errc{};
        case command_param::state:
            if (b > 0x0E || b == 0x0B || b == 0x0D) return errc::value_out_of_range;
            c.state = static_cast<led_state>(b);
            return errc{};
        case command_param::brightness:
            if (b > 0x3F) return errc::value_out_of_range;
            c.level = level::make(b).value();
            return errc{};
        case command_param::colour:
            if (b < 1 || b > 9) return errc::value_out_of_range;
            c.colour = static_cast<backlight_colour>(b);
            return errc{};
        case command_param::flag:
            if (b > 1) return errc::value_out_of_range;
            c.enabled = b == 1;
            return errc{};
        case command_param::baud:
            if (b >= std::size(command_bauds)) return errc::value_out_of_range;
            c.baud = command_bauds[b];
            return errc{};
        case command_param::period_10ms: c.period_10ms = b; return errc{};
        case command_param::node: {
            const auto n = canopen::node_id::make(b);
            if (!n) return n.error();
            c.node_id = *n;
            return errc{};
        }
        case command_param::show:
            if (b < 1 || b > std::size(command_shows)) return errc::value_out_of_range;
            c.show = command_shows[b - 1u];
            return errc{};
    }
    return errc::value_out_of_range;
}

constexpr std::uint8_t write_param(command_param p, const command& c) noexcept {
    switch (p) {
        case command_param::key: return c.key;
        case command_param::state: return static_cast<std::uint8_t>(c.state);
        case command_param::brightness: return c.level.value();
        case command_param::colour: return static_cast<std::uint8_t>(c.colour);
        case command_param::flag: return c.enabled ? 1 : 0;
        case command_param::baud:
            for (std::uint8_t i = 0; i < std::size(command_bauds); ++i)
                if (command_bauds[i] == c.baud) return i;
            return 0xFF;
        case command_param::period_10ms: return c.period_10ms;
        case command_param::node: return c.node_id.value();
        case command_param::show:
            for (std::uint8_t i = 0; i < std::size(command_shows); ++i)
                if (command_shows[i] == c.show) return static_cast<std::uint8_t>(i + 1);
            return 0xFF;
        case command_param::none: break;
    }
    return 0;
}

// The parameter pairs (p1, p2) of command_table, each once: one decoder body per pair.
struct command_shape {
    command_param p1;
    command_param p2;
    friend constexpr bool operator==(const command_shape&, const command_shape&) = default;
};
inline constexpr auto all_command_shapes = [] {
    distinct_set<command_shape, std::size(command_table)> s;
    for (const command_row& r : command_table) s.add({r.p1, r.p2});
    return s;
}();
inline constexpr auto command_shapes = [] {
    std::array<command_shape, all_command_shapes.size> t{};
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = all_command_shapes.items[i];
    return t;
}();
// The pair + 1 of each command byte, 0 for none (as command_index, one load less and no bound).
inline constexpr auto command_shape_index = [] {
    std::array<std::uint8_t, 0x100> t{};
    for (const command_row& r : command_table)
        t[static_cast<std::size_t>(r.code)] =
            static_cast<std::uint8_t>(all_command_shapes.find({r.p1, r.p2}) + 1);
    return t;
}();
// The pair + 1 of each row of command_table.
inline constexpr auto command_row_shapes = [] {
    std::array<std::uint8_t, std::size(command_table)> t{};
    for (std::size_t i = 0; i < t.size(); ++i)
        t[i] = static_cast<std::uint8_t>(
            all_command_shapes.find({command_table[i].p1, command_table[i].p2}) + 1);
    return t;
}();
// command_shape_index[byte] by a scan of the rows (a test holds the two equal for every byte).
constexpr std::uint8_t scan_command_shape(std::uint8_t byte) noexcept {
    for (std::size_t i = 0; i < std::size(command_table); ++i)
        if (static_cast<std::uint8_t>(command_table[i].code) == byte) return command_row_shapes[i];
    return 0;
}
// The pair + 1 of command byte `byte`: the table, or under -Os (POWERKEY_DETAIL_SIZE) the scan.
constexpr std::uint8_t command_shape_of(std::uint8_t byte) noexcept {
    if constexpr (POWERKEY_DETAIL_SIZE)
        return scan_command_shape(byte);
    else
        return command_shape_index[byte];
}

// The command `code` of parameter pair S in data bytes 4..7 (code, p1, p2, 00h). Errors:
// reserved_not_zero (byte 7, or byte 6 of a one-parameter command), then read_param's.
template <std::size_t S>
constexpr result<message> command_of(const model_layout& keypad, command_code code,
                                     std::uint32_t data) noexcept {
    constexpr command_shape shape = command_shapes[S];
    const auto b1 = static_cast<std::uint8_t>(data >> 8);
    const auto b2 = static_cast<std::uint8_t>(data >> 16);
    if ((data >> 24) != 0 || (shape.p2 == command_param::none && b2 != 0))
        return errc::reserved_not_zero;
    command c{};
    c.code = code;
    if (const errc e = read_param(keypad, shape.p1, b1, c); e != errc{}) return e;
    if (const errc e = read_param(keypad, shape.p2, b2, c); e != errc{}) return e;
    return answer(c);
}

// The command in a download to 6500h sub 1. Errors: size_mismatch (not 4 bytes), unknown_command
// (byte 4 names no command), then command_of's.
POWERKEY_DETAIL_INLINE constexpr result<message> read_command(const model_layout& keypad,
                                                              std::uint8_t size,
                                                              std::uint32_t data) noexcept {
    static_assert(command_shapes.size() == 8, "one case below per pair in command_shapes");
    if (size != 4) return errc::size_mismatch;
    const auto byte = static_cast<std::uint8_t>(data);
    const auto code = static_cast<command_code>(byte);  // a command's byte is its code
    switch (command_shape_of(byte)) {
        case 1: return command_of<0>(keypad, code, data);
        case 2: return command_of<1>(keypad, code, data);
        case 3: return command_of<2>(keypad, code, data);
        case 4: return command_of<3>(keypad, code, data);
        case 5: return command_of<4>(keypad, code, data);
        case 6: return command_of<5>(keypad, code, data);
        case 7: return command_of<6>(keypad, code, data);
        case 8: return command_of<7>(keypad, code, data);
        default: return errc::unknown_command;
    }
}

constexpr canopen::expedited_data write_command(const command& c) noexcept {
    const auto row = find_command(static_cast<std::uint8_t>(c.code));
    if (!row) return {4, {static_cast<std::uint8_t>(c.code), 0, 0, 0}};
    return {
        4,
        {static_cast<std::uint8_t>(c.code), write_param(row->p1, c), write_param(row->p2, c), 0}};
}

// --- SDO frames ---------------------------------------------------------------------------------
// The CiA 301 engine (canopen/sdo.hpp) says which frame it is; its address is looked up here.

// The command module is writable wherever it is: decode_request tests its kind before the access.
constexpr bool commands_writable() noexcept {
    for (const codec_row& r : codec_rows)
        if (r.kind == value_kind::commands && !r.writable()) return false;
    return true;
}
static_assert(commands_writable());

// A segment request or an abort from the client, or a refusal.
POWERKEY_DETAIL_COLD constexpr result<message> other_request(canopen::sdo_word w) noexcept {
    const auto op = canopen::other_request_op(w);
    if (!op) return op.error();
    if (*op == canopen::sdo_op::segment_request) return message{w.segment_request()};
    return message{canopen::sdo_abort_request{w.abort()}};
}

// Errors: wrong_length, the engine's, unknown_object (no such address), unknown_command (an
// access the row lacks), then value_message's or read_command's.
template <reading how, class Layout>
constexpr result<message> decode_request(const Layout& keypad, const can::frame& f) noexcept {
    if (f.size() != 8) return misfit<how>(f, keypad);
    const auto w = canopen::sdo_word::of(f);
    return canopen::visit_sdo_request<result<message>>(
        w,
        [&keypad, w]() POWERKEY_DETAIL_INLINE_LAMBDA -> result<message> {  // an expedited write
            const std::uint8_t i = find_codec_row(keypad, w.key());
            if (i == 0) return errc::unknown_object;
            const codec_row& r = codec_row_at(keypad, i);
            if (r.kind == value_kind::commands)  // writable (commands_writable): tested first
                return read_command(keypad, w.size(), w.data());
            if (!r.writable()) return errc::unknown_command;
            return value_message(keypad, r, w.size(), w.data(), true);
        },
        [&keypad, w]() POWERKEY_DETAIL_INLINE_LAMBDA -> result<message> {  // a read
            const std::uint8_t i = find_codec_row(keypad, w.key());
            if (i == 0) return errc::unknown_object;
            const codec_row& r = codec_row_at(keypad, i);
            if (!r.readable()) return errc::unknown_command;
            return answer(sdo_read{r.id});
        },
        [w]() POWERKEY_DETAIL_INLINE_LAMBDA { return other_request(w); });
}

// A segment, a segmented upload's start (string objects only) or an abort, or a refusal.
template <class Layout>
POWERKEY_DETAIL_COLD constexpr result<message> other_reply(const Layout& keypad,
                                                           canopen::sdo_word w) noexcept {
    const auto op = canopen::other_response_op(w);
    if (!op) return op.error();
    if (*op == canopen::sdo_op::segment) return message{w.segment()};
    if (*op == canopen::sdo_op::upload_initiate) {
        const std::uint8_t i = find_codec_row(keypad, w.key());
        if (i == 0) return errc::unknown_object;
        if (codec_row_at(keypad, i).kind != value_kind::string) return errc::unknown_object;
        return message{w.upload_initiate()};
    }
    return message{canopen::sdo_abort_response{w.abort()}};
}

// Errors: as decode_request's (unknown_object also for a segmented upload of a non-string).
template <reading how, class Layout>
constexpr result<message> decode_reply(const Layout& keypad, const can::frame& f) noexcept {
    if (f.size() != 8) return misfit<how>(f, keypad);
    const auto w = canopen::sdo_word::of(f);
    return canopen::visit_sdo_response<result<message>>(
        w,
        [&keypad, w]() POWERKEY_DETAIL_INLINE_LAMBDA -> result<message> {  // a write acknowledged
            const std::uint8_t i = find_codec_row(keypad, w.key());
            if (i == 0) return errc::unknown_object;
            const codec_row& r = codec_row_at(keypad, i);
            if (!r.writable()) return errc::unknown_command;
            return answer(sdo_write_reply{r.id});
        },
        [&keypad, w]() POWERKEY_DETAIL_INLINE_LAMBDA -> result<message> {  // the value read
            const std::uint8_t i = find_codec_row(keypad, w.key());
            if (i == 0) return errc::unknown_object;
            const codec_row& r = codec_row_at(keypad, i);
            if (!r.readable()) return errc::unknown_command;
            return value_message(keypad, r, w.size(), w.data(), false);
        },
        [&keypad, w]() POWERKEY_DETAIL_INLINE_LAMBDA { return other_reply(keypad, w); });
}

// --- PDO frames ---------------------------------------------------------------------------------

// The key state of a TPDO1 of checked length, for decode (R = message) and decode_key_state<M>
// (R = key_state). Errors: reserved_not_zero (a key the model lacks, bytes 2..3 not 00h).
template <class R>
POWERKEY_DETAIL_INLINE constexpr result<R> key_state_of(const model_layout& keypad,
                                                        const can::frame& f) noexcept {
    const auto w = static_cast<std::uint32_t>(load_le<4>(f.bytes(), 0));
    if ((w & keypad.not_keys) != 0) return errc::reserved_not_zero;
    if constexpr (std::is_same_v<R, message>)
        return answer(key_state{key_set::from_mask(w), f[4]});
    else
        return key_state{key_set::from_mask(w), f[4]};
}

// The PDO of function code `code` (this node's): its length and data checked. No byte past the
// dlc is read (the fuzz targets poison them).
template <reading how>
POWERKEY_DETAIL_INLINE constexpr result<message> decode_pdo(const model_layout& keypad,
                                                            std::uint32_t code,
                                                            const can::frame& f) noexcept {
    switch (code) {
        case 0x3: {  // TPDO1: keys in bytes 0..1, 00h 00h, the tick
            if (f.size() != 5) return misfit<how>(f, keypad);
            return key_state_of<message>(keypad, f);
        }
        case 0x4:    // RPDO1 LEDs on
        case 0x6: {  // RPDO2 LEDs blinking
            if (f.size() != 8) return misfit<how>(f, keypad);
            const std::uint64_t v = f.data_le();
            // unpack_leds(keypad, v, keypad.planes); blue shifted twice (never by 64 at once).
            if ((v & ~keypad.led_bits) != 0) return errc::reserved_not_zero;
            const std::uint64_t up = v >> keypad.stride;
            const leds l{led_set::from_mask(v & keypad.led_mask),
                         led_set::from_mask(up & keypad.led_mask),
                         led_set::from_mask((up >> keypad.stride) & keypad.led_mask)};
            if (code == 0x4) return answer(led_on{l});
            return answer(led_blink{l});
        }
        case 0x5:    // TPDO2 encoder 1
        case 0x7: {  // TPDO3 encoder 2
            if (!keypad.encoders) return errc::wrong_id;
            if (f.size() != 8) return misfit<how>(f, keypad);
            const std::uint64_t v = f.data_le();
            if ((v >> 32) != 0) return errc::reserved_not_zero;
            const auto top = static_cast<std::uint8_t>(v >> 24);
            if (top == 1 || top > 0x10) return errc::value_out_of_range;
            return answer(encoder_state{code == 0x5 ? std::uint8_t{1} : std::uint8_t{2},
                                        (v & 0x80) != 0, static_cast<std::uint8_t>(v & 0x7F),
                                        static_cast<std::uint16_t>(v >> 8), top});
        }
        case 0x9: {  // TPDO4 analog inputs
            if (!keypad.encoders) return errc::wrong_id;
            if (f.size() != 8) return misfit<how>(f, keypad);
            const std::uint64_t v = f.data_le();
            // In 32-bit halves: no 64-bit shift by a variable.
            const std::uint32_t half[2] = {static_cast<std::uint32_t>(v),
                                           static_cast<std::uint32_t>(v >> 32)};
            analog_inputs a;
            for (std::size_t i = 0; i < 4; ++i) {
                const auto in = static_cast<std::uint16_t>(half[i / 2] >> (16 * (i % 2)));
                if (in > 500) return errc::value_out_of_range;
                a.mv[i] = static_cast<std::uint16_t>(in * 10);
            }
            return answer(a);
        }
        case 0x8: {  // RPDO3: the encoder rings, or the LED brightness
            if (keypad.encoder_leds_pdo) {
                if (f.size() != 8) return misfit<how>(f, keypad);
                const std::uint64_t v = f.data_le();
                if ((v >> 32) != 0) return errc::reserved_not_zero;
                return answer(encoder_leds{led_set::from_mask(v)});
            }
            if (!keypad.brightness_pdo) return errc::wrong_id;
            if (f.size() != 8) return misfit<how>(f, keypad);
            const std::uint64_t v = f.data_le();
            if ((v >> 8) != 0) return errc::reserved_not_zero;
            if (v > level::max) return errc::value_out_of_range;
            return answer(led_brightness{*level::make(v)});
        }
        case 0xA: {  // RPDO4: backlight level and colour
            if (!keypad.backlight_pdo) return errc::wrong_id;
            if (f.size() != 8) return misfit<how>(f, keypad);
            const std::uint64_t v = f.data_le();
            if ((v >> 16) != 0 || (!keypad.backlight_colour && (v >> 8) != 0))
                return errc::reserved_not_zero;
            const auto colour = static_cast<std::uint8_t>(v >> 8);
            if ((v & 0xFF) > level::max || colour > 0x09) return errc::value_out_of_range;
            return answer(backlight{*level::make(v & 0xFF), static_cast<backlight_colour>(colour)});
        }
        default: return errc::wrong_id;
    }
}

// A 29-bit frame of the keypad at `address` (nullopt: any), read by the J1939 codec.
constexpr result<message> decode_j1939(model m, const can::frame& f,
                                       j1939::keypad_address address) noexcept {
    return j1939::detail::decode_as<message>(f, m, address);
}
// The same at any address, from the front's default case (docs/performance.md, J1939).
POWERKEY_DETAIL_COLD constexpr result<message> decode_extended(const model_layout& keypad,
                                                               const can::frame& f) noexcept {
    return j1939::detail::decode_frame<message>(f, j1939::detail::j1939_row_of(keypad.id),
                                                std::nullopt);
}

// A J1939 alternative of message (encode hands it to the J1939 codec).
template <class T>
inline constexpr bool is_j1939_alternative = j1939::message_alternative<T>;

// The J1939 alternatives: the switch back and every one from key_contact on (one index compare).
inline constexpr std::size_t switch_index =
    message(std::in_place_type<j1939::switch_to_canopen>).index();
inline constexpr std::size_t first_j1939_index =
    message(std::in_place_type<j1939::key_contact>).index();
constexpr bool j1939_alternatives_in_place() noexcept {
    return []<std::size_t... I>(std::index_sequence<I...>) {
        return ((is_j1939_alternative<std::variant_alternative_t<I, message>> ==
                 (I == switch_index || I >= first_j1939_index)) &&
                ...);
    }
    (std::make_index_sequence<std::variant_size_v<message>>{});
}
static_assert(j1939_alternatives_in_place());

// A J1939 message's frame as j1939::encode builds it (narrowed to `address` when given).
POWERKEY_DETAIL_COLD constexpr result<can::frame> encode_j1939(
    model m, const message& msg, j1939::keypad_address address) noexcept {
    return std::visit(
        [m, address](const auto& v) -> result<can::frame> {
            using T = std::remove_cvref_t<decltype(v)>;
            if constexpr (is_j1939_alternative<T>) {
                T manual = v;  // whatever `form` says, the manual's form is built
                if constexpr (requires { manual.form; }) manual.form = frame_form::manual;
                return j1939::encode(m, manual, address);
            } else {
                return errc::wrong_id_format;  // not reached: encode chose this path by the index
            }
        },
        msg);
}

// --- frames not in the manual's form -----------------------------------------------------------
// (docs/decoder.md, "Tolerant and strict reading")

// The bytes from the first up to the last one whose bits `mask` names.
constexpr std::uint8_t bytes_of(std::uint64_t mask) noexcept {
    return static_cast<std::uint8_t>((std::bit_width(mask) + 7) / 8);
}

// How many leading bytes of msg's frame may carry anything on this keypad (docs/decoder.md,
// "trimmed"); `printed` is msg's frame in the manual's form.
template <class Layout>
constexpr std::uint8_t used_length(const Layout& keypad, const message& msg,
                                   const can::frame& printed) noexcept {
    return std::visit(
        [&keypad, &printed](const auto& v) -> std::uint8_t {
            using T = std::remove_cvref_t<decltype(v)>;
            if constexpr (std::is_same_v<T, canopen::sync_message>) {
                return 0;
            } else if constexpr (std::is_same_v<T, canopen::heartbeat_message> ||
                                 std::is_same_v<T, led_brightness>) {
                return 1;
            } else if constexpr (std::is_same_v<T, canopen::nmt_message>) {
                return 2;
            } else if constexpr (std::is_same_v<T, key_state>) {
                return 5;  // the tick in byte 4
            } else if constexpr (std::is_same_v<T, led_on> || std::is_same_v<T, led_blink>) {
                return bytes_of(keypad.led_bits);
            } else if constexpr (std::is_same_v<T, backlight>) {
                return keypad.backlight_colour ? 2 : 1;
            } else if constexpr (std::is_same_v<T, encoder_state> ||
                                 std::is_same_v<T, encoder_leds> || std::is_same_v<T, sdo_read> ||
                                 std::is_same_v<T, sdo_write_reply>) {
                return 4;  // an SDO's specifier and address
            } else if constexpr (std::is_same_v<T, sdo_write> ||
                                 std::is_same_v<T, sdo_read_reply>) {
                const auto key = canopen::sdo_word::of(printed).key();
                const codec_row& r = codec_row_at(keypad, find_codec_row(keypad, key));
                const std::uint8_t size = row_size(keypad, r, v.value.size);
                const std::uint32_t bits = visit_row_kind(
                    keypad, r.kind, [&](auto k) { return decltype(k)::used_bits(keypad, r); });
                return static_cast<std::uint8_t>(4 + bytes_of(bits & largest_of_size[size & 7u]));
            } else if constexpr (std::is_same_v<T, command>) {
                const std::uint8_t pair = command_shape_of(static_cast<std::uint8_t>(v.code));
                if (pair == 0) return 8;
                const command_shape& shape = command_shapes[pair - 1u];
                return static_cast<std::uint8_t>(5 + (shape.p1 != command_param::none ? 1 : 0) +
                                                 (shape.p2 != command_param::none ? 1 : 0));
            } else {
                return 8;  // analog inputs, segments, aborts, the J1939 switch: every byte
            }
        },
        msg);
}

// f with `length` bytes: its first ones, then 00h.
constexpr can::frame with_length(const can::frame& f, std::uint8_t length) noexcept {
    can::payload p{};
    for (std::size_t i = 0; i < length && i < f.size(); ++i) p[i] = f[i];
    const auto dlc = can::dlc::make(length).value();
    if (f.is_extended()) return can::frame(*f.ext_id(), dlc, p);
    return can::frame(*f.std_id(), dlc, p);
}

// --- encoding -----------------------------------------------------------------------------------

// The frame of function fn for `node` whose dlc bytes are `bits`, little endian.
POWERKEY_DETAIL_INLINE constexpr can::frame word_frame(canopen::function fn, canopen::node_id node,
                                                       std::uint8_t dlc,
                                                       std::uint64_t bits) noexcept {
    can::payload p{};
    store_le<8>(p, 0, bits);
    return can::frame(canopen::cob_id(fn, node), can::dlc::make(dlc).value(), p);
}

// The frame of one alternative v (not checked: encode reads it back, or checks v first).
template <class T, class Layout>
constexpr result<can::frame> build_of(const Layout& keypad, canopen::node_id node,
                                      const T& v) noexcept {
    using canopen::function;
    if constexpr (std::is_same_v<T, canopen::nmt_message> ||
                  std::is_same_v<T, canopen::sync_message> ||
                  std::is_same_v<T, j1939::switch_to_canopen>) {
        return encode(v);  // canopen::encode or j1939::encode, found by ADL
    } else if constexpr (is_j1939_alternative<T>) {
        return errc::wrong_id_format;  // encode gives these to encode_j1939
    } else if constexpr (std::is_same_v<T, key_state>) {
        return word_frame(function::tpdo1, node, 5,
                          (v.keys.mask() & 0xFFFF) | (std::uint64_t{v.tick} << 32));
    } else if constexpr (std::is_same_v<T, led_on> || std::is_same_v<T, led_blink>) {
        return word_frame(std::is_same_v<T, led_on> ? function::rpdo1 : function::rpdo2, node, 8,
                          pack_leds(keypad, v.map, keypad.planes));
    } else if constexpr (std::is_same_v<T, led_brightness>) {
        return word_frame(function::rpdo3, node, 8, v.level.value());
    } else if constexpr (std::is_same_v<T, encoder_leds>) {
        return word_frame(function::rpdo3, node, 8, v.leds.mask());
    } else if constexpr (std::is_same_v<T, encoder_state>) {
        return word_frame(v.encoder == 2 ? function::tpdo3 : function::tpdo2, node, 8,
                          (v.counterclockwise ? 0x80u : 0u) | (v.ticks & 0x7Fu) |
                              (std::uint64_t{v.counter} << 8) | (std::uint64_t{v.top} << 24));
    } else if constexpr (std::is_same_v<T, analog_inputs>) {
        std::uint64_t bits = 0;
        for (std::size_t i = 0; i < 4; ++i)
            bits |= std::uint64_t{static_cast<std::uint16_t>(v.mv[i] / 10)} << (16 * i);
        return word_frame(function::tpdo4, node, 8, bits);
    } else if constexpr (std::is_same_v<T, backlight>) {
        return word_frame(
            function::rpdo4, node, 8,
            v.level.value() | (std::uint64_t{static_cast<std::uint8_t>(v.colour)} << 8));
    } else if constexpr (std::is_same_v<T, sdo_read> || std::is_same_v<T, sdo_write> ||
                         std::is_same_v<T, sdo_read_reply> || std::is_same_v<T, sdo_write_reply>) {
        const std::uint8_t i = find_codec_row(keypad, v.object);
        if (i == 0) return errc::unknown_object;
        const codec_row& row = codec_row_at(keypad, i);
        if constexpr (std::is_same_v<T, sdo_read>) {
            return canopen::encode(node, canopen::sdo_upload_request{row.address()});
        } else if constexpr (std::is_same_v<T, sdo_write_reply>) {
            return canopen::encode(node, canopen::sdo_download_response{row.address()});
        } else if constexpr (std::is_same_v<T, sdo_write>) {
            if (row.kind == value_kind::commands)
                return errc::unknown_object;  // a command is a `command`
            return canopen::encode(node, canopen::sdo_download_request{
                                             row.address(), write_value(keypad, row, v.value)});
        } else {
            return canopen::encode(node, canopen::sdo_upload_response{
                                             row.address(), write_value(keypad, row, v.value)});
        }
    } else if constexpr (std::is_same_v<T, command>) {
        const std::uint8_t i = find_codec_row(keypad, object::command_module);
        if (i == 0) return errc::unknown_object;
        return canopen::encode(node, canopen::sdo_download_request{
                                         codec_row_at(keypad, i).address(), write_command(v)});
    } else {
        return canopen::encode(node, v);  // heartbeat, segments, initiate, aborts
    }
}
template <class Layout>
constexpr result<can::frame> build(const Layout& keypad, canopen::node_id node,
                                   const message& msg) noexcept {
    return std::visit([&keypad, node](const auto& v) { return build_of(keypad, node, v); }, msg);
}

// decode's checks of a PDO's frame, made on the message (docs/decoder.md, "encode"): decode's
// error, or value_out_of_range for what the frame cannot carry (a key above 16, an LED past the
// model's planes or LEDs).
constexpr errc own_check(const model_layout& keypad, const key_state& v) noexcept {
    const std::uint64_t k = v.keys.mask();
    if ((k & 0xFFFF & keypad.not_keys) != 0) return errc::reserved_not_zero;
    return k > 0xFFFF ? errc::value_out_of_range : errc{};
}
// RPDO3 brightness: the encoder rings on a model whose RPDO3 is them; wrong_id without the PDO.
constexpr errc own_check(const model_layout& keypad, const led_brightness&) noexcept {
    if (keypad.encoder_leds_pdo) return errc::value_out_of_range;
    return keypad.brightness_pdo ? errc{} : errc::wrong_id;
}
// RPDO4 backlight: a colour byte on a level-only keypad is reserved, a colour past 09h none.
constexpr errc own_check(const model_layout& keypad, const backlight& v) noexcept {
    if (!keypad.backlight_pdo) return errc::wrong_id;
    const auto colour = static_cast<std::uint8_t>(v.colour);
    if (!keypad.backlight_colour && colour != 0) return errc::reserved_not_zero;
    return colour > 0x09 ? errc::value_out_of_range : errc{};
}
template <class T>
requires(std::is_same_v<T, led_on> || std::is_same_v<T, led_blink>) constexpr errc
    own_check(const model_layout& keypad, const T& v) noexcept {
    const std::uint64_t one = keypad.led_mask;
    const std::uint64_t outside = (v.map.red.mask() & ~one) |
                                  (v.map.green.mask() & ~(keypad.planes > 1 ? one : 0)) |
                                  (v.map.blue.mask() & ~(keypad.planes > 2 ? one : 0));
    return outside != 0 ? errc::value_out_of_range : errc{};
}

// The frame of a PDO that checks itself, checked.
template <class T, class Layout>
requires requires(const model_layout& k, const T& v) { own_check(k, v); }
constexpr result<can::frame> own_frame(const Layout& keypad, canopen::node_id node,
                                       const T& v) noexcept {
    if (const errc e = own_check(keypad, v); e != errc{}) return e;
    constexpr bool led_map = std::is_same_v<T, led_on> || std::is_same_v<T, led_blink>;
    if constexpr (led_map && is_fixed_layout<Layout>) {
        // The check leaves each plane within the model's LEDs: pack_leds' masks fold.
        const std::uint64_t outside = ~std::uint64_t{keypad.led_mask};
        POWERKEY_DETAIL_ASSUME_NOT((v.map.red.mask() & outside) != 0);
        POWERKEY_DETAIL_ASSUME_NOT((v.map.green.mask() & outside) != 0);
        POWERKEY_DETAIL_ASSUME_NOT((v.map.blue.mask() & outside) != 0);
    }
    return build_of(keypad, node, v);
}

// The SDO alternatives check themselves too (docs/decoder.md, "encode").
template <class T>
concept own_sdo = std::is_same_v<T, sdo_read> || std::is_same_v<T, sdo_write> ||
    std::is_same_v<T, sdo_read_reply> || std::is_same_v<T, sdo_write_reply> ||
    std::is_same_v<T, command>;

// An expedited SDO frame: the specifier, row's address and 4 data bytes.
POWERKEY_DETAIL_INLINE constexpr can::frame sdo_frame(canopen::function fn, canopen::node_id node,
                                                      std::uint8_t specifier, const codec_row& row,
                                                      std::uint64_t data) noexcept {
    return word_frame(fn, node, 8, specifier | std::uint64_t{row.key} << 8 | data << 32);
}

// A kind whose value is its raw number (kind_defaults' value() and pack()).
template <class K>
inline constexpr bool raw_kind =
    &K::value == &kind_defaults::value&&& K::pack == &kind_defaults::pack;
// Every row of such a kind has one size, 1..4 bytes (checked_sdo takes it as the size sent).
constexpr bool raw_rows_sized() noexcept {
    for (const codec_row& r : codec_rows)
        if (r.key != no_codec_row.key && !visit_kind(r.kind, [&r](auto k) {
                return !raw_kind<decltype(k)> || (r.size() >= 1 && r.size() <= 4);
            }))
            return false;
    return true;
}
static_assert(raw_rows_sized());

// An SDO read (40h), write (23h..2Fh), write reply (60h) or read reply (43h..4Fh).
enum class sdo_verb : std::uint8_t { read, write, write_reply, read_reply };
// The specifier of an expedited read reply (43h) or write (23h) of `size` bytes (CiA 301).
inline constexpr std::uint8_t value_specifier[2][5] = {{0x43, 0x4F, 0x4B, 0x47, 0x43},
                                                       {0x23, 0x2F, 0x2B, 0x27, 0x23}};
// The frame of a write or read reply of row `row` of kind K with value v, checked.
template <class K, class Layout>
POWERKEY_DETAIL_INLINE constexpr result<can::frame> value_frame(const Layout& keypad,
                                                                canopen::node_id node,
                                                                const codec_row& row, sdo_verb verb,
                                                                const object_value& v) noexcept {
    using canopen::function;
    const bool write = verb == sdo_verb::write;
    if constexpr (std::is_same_v<K, value_kinds::commands>)
        if (write) return errc::unknown_object;  // a `command`
    if constexpr (raw_kind<K>) {
        // The bytes read back as v exactly when v has no map and no size (raw_rows_sized).
        const std::uint8_t raw_size = row.size();
        if (v.raw > largest_of_size[raw_size]) return errc::reserved_not_zero;
        if (const errc e = K::check(keypad, row, raw_size, v.raw, write); e != errc{}) return e;
        if ((v.map.red.mask() | v.map.green.mask() | v.map.blue.mask() | v.size) != 0)
            return errc::value_out_of_range;
        return sdo_frame(write ? function::sdo_rx : function::sdo_tx, node,
                         value_specifier[write ? 1 : 0][raw_size], row, v.raw);
    }
    const std::uint8_t carried = v.size >= 1 && v.size <= 4 ? v.size : std::uint8_t{4};
    const auto sent =
        canopen::expedited_size::make(row.size() != 0 ? row.size() : K::size(keypad, row, carried))
            .value_or(canopen::expedited_size{4});
    const std::uint8_t size = sent.value();
    const std::uint32_t data = K::pack(keypad, row, v);
    if (size != decoded_size(keypad, row, size)) return errc::size_mismatch;
    if (data > largest_of_size[size]) return errc::reserved_not_zero;
    if (const errc e = K::check(keypad, row, size, data, write); e != errc{}) return e;
    if (!(K::value(keypad, row, size, data) == v)) return errc::value_out_of_range;
    return sdo_frame(write ? function::sdo_rx : function::sdo_tx, node,
                     value_specifier[write ? 1 : 0][size], row, data);
}
// value_frame of the kind visit_row_kind finds.
template <class Layout>
struct value_frame_of {
    const Layout& keypad;
    canopen::node_id node;
    const codec_row& row;
    sdo_verb verb;
    const object_value& v;
    template <class K>
    POWERKEY_DETAIL_HOT constexpr result<can::frame> operator()(K) const noexcept {
        return value_frame<K>(keypad, node, row, verb, v);
    }
};
// The frame of an SDO read, write or reply of object `id`, checked; inlined into encode's entry
// points, and one out-of-line copy, checked_sdo.
template <class Layout>
POWERKEY_DETAIL_INLINE constexpr result<can::frame> checked_sdo_inline(
    const Layout& given, canopen::node_id node, object id, sdo_verb verb,
    const object_value& v) noexcept {
    using canopen::function;
    const auto& keypad = known(given);
    const std::uint8_t i = find_codec_row(keypad, id);
    if (i == 0) return errc::unknown_object;
    const codec_row& row = codec_row_at(keypad, i);
    const bool write = verb == sdo_verb::write || verb == sdo_verb::write_reply;
    // (a write of the command module: unknown_object in value_frame, commands_writable)
    if (write ? !row.writable() : !row.readable()) return errc::unknown_command;
    if (verb == sdo_verb::read) return sdo_frame(function::sdo_rx, node, 0x40, row, 0);
    if (verb == sdo_verb::write_reply) return sdo_frame(function::sdo_tx, node, 0x60, row, 0);
    return visit_row_kind(keypad, row.kind, value_frame_of<Layout>{keypad, node, row, verb, v});
}

template <class Layout>
constexpr result<can::frame> checked_sdo(const Layout& keypad, canopen::node_id node, object id,
                                         sdo_verb verb, const object_value& v) noexcept {
    return checked_sdo_inline(keypad, node, id, verb, v);
}

// An SDO read, write or reply as its own type: its verb, and its value when it carries one.
template <class T>
inline constexpr sdo_verb verb_of = std::is_same_v<T, sdo_read>          ? sdo_verb::read
                                    : std::is_same_v<T, sdo_write>       ? sdo_verb::write
                                    : std::is_same_v<T, sdo_write_reply> ? sdo_verb::write_reply
                                                                         : sdo_verb::read_reply;
template <class T, class Layout>
requires(own_sdo<T> && !std::is_same_v<T, command>) constexpr result<can::frame> own_frame(
    const Layout& keypad, canopen::node_id node, const T& v) noexcept {
    if constexpr (requires { v.value; })
        return checked_sdo(keypad, node, v.object, verb_of<T>, v.value);
    else
        return checked_sdo(keypad, node, v.object, verb_of<T>, {});
}
// A command checks itself as read_command reads it (docs/performance.md, "The codec's shape").
// command_word_bits(p): the byte of command_word that carries p (test_keypad_commands.cpp).
constexpr std::uint64_t command_word(const command& c) noexcept {
    const std::uint32_t low = std::uint32_t{c.key} |
                              std::uint32_t{static_cast<std::uint8_t>(c.state)} << 8 |
                              std::uint32_t{c.level.value()} << 16 |
                              std::uint32_t{static_cast<std::uint8_t>(c.colour)} << 24;
    const std::uint32_t high = std::uint32_t{static_cast<std::uint8_t>(c.baud)} |
                               std::uint32_t{c.period_10ms} << 8 |
                               std::uint32_t{c.node_id.value()} << 16 |
                               std::uint32_t{static_cast<std::uint8_t>(c.show)} << 24;
    return low | std::uint64_t{high} << 32;
}
constexpr std::uint64_t command_word_bits(command_param p) noexcept {
    switch (p) {
        case command_param::key: return 0xFFull;
        case command_param::state: return 0xFFull << 8;
        case command_param::brightness: return 0xFFull << 16;
        case command_param::colour: return 0xFFull << 24;
        case command_param::baud: return 0xFFull << 32;
        case command_param::period_10ms: return 0xFFull << 40;
        case command_param::node: return 0xFFull << 48;
        case command_param::show: return 0xFFull << 56;
        case command_param::flag:
        case command_param::none: break;
    }
    return 0;
}
// The frame of command v of parameter pair S (its row found: `row`).
template <std::size_t S, class Layout>
POWERKEY_DETAIL_INLINE constexpr result<can::frame> command_frame(const Layout& keypad,
                                                                  canopen::node_id node,
                                                                  const codec_row& row,
                                                                  const command& v) noexcept {
    constexpr command_shape shape = command_shapes[S];
    const std::uint8_t b1 = write_param(shape.p1, v);
    const std::uint8_t b2 = write_param(shape.p2, v);
    command back{};  // read_param's checks (what it stores is not used)
    if (const errc e = read_param(keypad, shape.p1, b1, back); e != errc{}) return e;
    if (const errc e = read_param(keypad, shape.p2, b2, back); e != errc{}) return e;
    constexpr std::uint64_t others = ~(command_word_bits(shape.p1) | command_word_bits(shape.p2));
    constexpr bool flag = shape.p1 == command_param::flag || shape.p2 == command_param::flag;
    if (((command_word(v) ^ command_word(command{})) & others) != 0 ||
        (!flag && v.enabled != command{}.enabled))
        return errc::value_out_of_range;
    return sdo_frame(
        canopen::function::sdo_rx, node, 0x23, row,
        static_cast<std::uint8_t>(v.code) | std::uint32_t{b1} << 8 | std::uint32_t{b2} << 16);
}
template <class Layout>
POWERKEY_DETAIL_INLINE constexpr result<can::frame> command_frame_inline(
    const Layout& given, canopen::node_id node, const command& v) noexcept {
    static_assert(command_shapes.size() == 8, "one case below per pair in command_shapes");
    const auto& keypad = known(given);
    const std::uint8_t i = find_codec_row(keypad, object::command_module);
    if (i == 0) return errc::unknown_object;
    const codec_row& row = codec_row_at(keypad, i);
    switch (command_shape_of(static_cast<std::uint8_t>(v.code))) {
        case 1: return command_frame<0>(keypad, node, row, v);
        case 2: return command_frame<1>(keypad, node, row, v);
        case 3: return command_frame<2>(keypad, node, row, v);
        case 4: return command_frame<3>(keypad, node, row, v);
        case 5: return command_frame<4>(keypad, node, row, v);
        case 6: return command_frame<5>(keypad, node, row, v);
        case 7: return command_frame<6>(keypad, node, row, v);
        case 8: return command_frame<7>(keypad, node, row, v);
        default: return errc::unknown_command;
    }
}
template <class Layout>
constexpr result<can::frame> own_frame(const Layout& keypad, canopen::node_id node,
                                       const command& v) noexcept {
    return command_frame_inline(keypad, node, v);
}
// own_frame of an SDO message, inlined into encode's entry points.
template <class T, class Layout>
requires own_sdo<T> POWERKEY_DETAIL_INLINE constexpr result<can::frame> own_frame_inline(
    const Layout& keypad, canopen::node_id node, const T& v) noexcept {
    if constexpr (std::is_same_v<T, command>)
        return command_frame_inline(keypad, node, v);
    else if constexpr (requires { v.value; })
        return checked_sdo_inline(keypad, node, v.object, verb_of<T>, v.value);
    else
        return checked_sdo_inline(keypad, node, v.object, verb_of<T>, {});
}

// The front (docs/performance.md, "The codec's shape"). With `j1939` false a 29-bit frame is
// wrong_id and no J1939 code is in the program (decode_canopen).
template <reading how, bool j1939 = true, class Layout = model_layout>
POWERKEY_DETAIL_HOT constexpr result<message> decode_at(const can::frame& f, canopen::node_id node,
                                                        const Layout& keypad) noexcept {
    // canopen::classify as a rotation: this node's function code, or past the 16 codes.
    const std::uint32_t id = f.id_word();
    const std::uint32_t code = std::rotr(id - node.value(), 7);
    switch (code) {
        case 0x0:  // the node id as a COB-ID
        case 0x1:  // EMCY
        case 0x2:  // TIME
        case 0xD:
        case 0xF: return errc::wrong_id;
        case 0x3: return decode_pdo<how>(keypad, 0x3, f);
        case 0x4:  // LEDs on and blinking: one body (smaller; the kind is one test at its end)
        case 0x6: return decode_pdo<how>(keypad, code, f);
        case 0x5: return decode_pdo<how>(keypad, 0x5, f);
        case 0x7: return decode_pdo<how>(keypad, 0x7, f);
        case 0x8: return decode_pdo<how>(keypad, 0x8, f);
        case 0x9: return decode_pdo<how>(keypad, 0x9, f);
        case 0xA: return decode_pdo<how>(keypad, 0xA, f);
        case 0xB: return decode_reply<how>(keypad, f);
        case 0xC: return decode_request<how>(keypad, f);
        case 0xE: {  // heartbeat (canopen::decode_heartbeat, the identifier known)
            if (f.size() != 1) return misfit<how>(f, keypad);
            if (!canopen::is_heartbeat_state(f[0])) return errc::value_out_of_range;
            return answer(canopen::heartbeat_message{canopen::nmt_state{f[0]}});
        }
        default:
            if (f.is_extended()) {
                if constexpr (!j1939) return errc::wrong_id;
                // Most 29-bit frames on a bus are no keypad's: refused here, without a call.
                if (!j1939::detail::is_keypad_pf((id >> 16) & 0x3FF)) return errc::wrong_id;
                return decode_extended(keypad, f);
            }
            // Another node's frame, or one for every node: 000h (NMT) and 080h (SYNC).
            if (id == canopen::nmt_cob_id.value())
                return lift<how>(canopen::decode_nmt(f), f, keypad);
            if (id == canopen::sync_cob_id.value())
                return lift<how>(canopen::decode_sync(f), f, keypad);
            return errc::wrong_id;
    }
}

// f read at its identifier's manual length by the strict front (docs/decoder.md, "Tolerant and
// strict reading"); the node is the frame's own (NMT and SYNC read the same for every node).
template <bool j1939, class Layout>
POWERKEY_DETAIL_COLD constexpr result<message> reread(const can::frame& f,
                                                      const Layout& keypad) noexcept {
    const std::uint32_t own = f.id_word() & 0x7F;
    const auto node = *canopen::node_id::make(own == 0 ? 1 : own);
    const std::uint8_t n = f.size();
    for (std::uint8_t k = 0; k <= 8; ++k) {
        if (k == n) continue;
        const can::frame printed = with_length(f, k);
        const auto r = decode_at<reading::strict, j1939>(printed, node, keypad);
        if (!r && r.error() == errc::wrong_length) continue;  // not this identifier's length
        for (std::uint8_t i = k; i < n; ++i)
            if (f[i] != 0) return errc::wrong_length;
        if (!r) return k < n ? r : result<message>(errc::wrong_length);
        if (k > n) {
            if (n < used_length(keypad, *r, printed)) return errc::wrong_length;
            return with_form(*r, frame_form::trimmed);
        }
        return with_form(*r, frame_form::padded);
    }
    return errc::wrong_length;
}
}  // namespace detail

namespace detail {
// A CANopen message's frame: a PDO that checks itself built checked, any other built and read
// back by the front (`j1939`: decode's, false: decode_canopen's; docs/decoder.md, "encode").
template <bool j1939, class Layout>
constexpr result<can::frame> encode_canopen(canopen::node_id node, const Layout& keypad,
                                            const message& msg) noexcept {
    if (std::holds_alternative<key_state>(msg))
        return own_frame(keypad, node, std::get<key_state>(msg));
    if (std::holds_alternative<led_on>(msg)) return own_frame(keypad, node, std::get<led_on>(msg));
    if (std::holds_alternative<led_blink>(msg))
        return own_frame(keypad, node, std::get<led_blink>(msg));
    if (std::holds_alternative<led_brightness>(msg))
        return own_frame(keypad, node, std::get<led_brightness>(msg));
    if (std::holds_alternative<backlight>(msg))
        return own_frame(keypad, node, std::get<backlight>(msg));
    const auto f = build(keypad, node, msg);
    if (!f) return f.error();
    const auto back = decode_at<reading::strict, j1939>(*f, node, keypad);
    if (!back) return back.error();
    if (!(*back == with_form(msg, frame_form::manual))) return errc::value_out_of_range;
    return *f;
}
template <bool j1939>
constexpr result<can::frame> encode_canopen(canopen::node_id node, model m,
                                            const message& msg) noexcept {
    return encode_canopen<j1939>(node, layout(m), msg);
}

// An alternative of message that is not J1939's.
template <class T>
concept canopen_alternative = !is_j1939_alternative<T> && requires(const T& v) {
    {message(std::in_place_type<T>, v)};
};

template <bool j1939, class Layout>
POWERKEY_DETAIL_INLINE constexpr result<message> decode_on(const can::frame& f,
                                                           canopen::node_id node,
                                                           const Layout& keypad,
                                                           reading how) noexcept {
    if (how == reading::strict || POWERKEY_DETAIL_SIZE) {
        // Under -Os the strict decoder serves both readings (docs/decoder.md).
        const auto r = decode_at<reading::strict, j1939>(f, node, keypad);
        if (how == reading::strict || r || r.error() != errc::wrong_length) return r;
        return reread<j1939>(f, keypad);
    }
    return decode_at<reading::tolerant, j1939>(f, node, keypad);
}
template <bool j1939>
POWERKEY_DETAIL_INLINE constexpr result<message> decode_on(const can::frame& f,
                                                           canopen::node_id node, model m,
                                                           reading how) noexcept {
    if (!is_model(m)) return errc::value_out_of_range;
    return decode_on<j1939>(f, node, layout(m), how);
}
}  // namespace detail

// Any frame of keypad `node` of model `m` (docs/decoder.md; its errors: docs/errors.md, "decode,
// model by model").
[[nodiscard]] POWERKEY_DETAIL_INLINE constexpr result<message> decode(
    const can::frame& f, canopen::node_id node, model m, reading how = reading::tolerant) noexcept {
    return detail::decode_on<true>(f, node, m, how);
}

// decode on a CANopen bus only: a 29-bit frame is wrong_id (docs/decoder.md, "A CANopen bus only").
[[nodiscard]] POWERKEY_DETAIL_INLINE constexpr result<message> decode_canopen(
    const can::frame& f, canopen::node_id node, model m, reading how = reading::tolerant) noexcept {
    return detail::decode_on<false>(f, node, m, how);
}

// decode with the model known when the program is built (docs/decoder.md).
template <model M>
[[nodiscard]] POWERKEY_DETAIL_INLINE constexpr result<message> decode(
    const can::frame& f, canopen::node_id node, reading how = reading::tolerant) noexcept {
    static_assert(detail::is_model(M), "M is a row of the model table");
    return detail::decode_on<true>(f, node, detail::fixed_layout_v<M>, how);
}
// decode_canopen for a keypad whose model is known when the program is built.
template <model M>
[[nodiscard]] POWERKEY_DETAIL_INLINE constexpr result<message> decode_canopen(
    const can::frame& f, canopen::node_id node, reading how = reading::tolerant) noexcept {
    static_assert(detail::is_model(M), "M is a row of the model table");
    return detail::decode_on<false>(f, node, detail::fixed_layout_v<M>, how);
}

// decode with the J1939 frames narrowed to the keypad at `address` (j1939::decode's `keypad`).
[[nodiscard]] constexpr result<message> decode(const can::frame& f, canopen::node_id node, model m,
                                               j1939::keypad_address address,
                                               reading how = reading::tolerant) noexcept {
    if (f.is_extended() && detail::is_model(m)) return detail::decode_j1939(m, f, address);
    return decode(f, node, m, how);
}

// The frame of msg for keypad `node` of model `m` in the manual's form, such that
// decode(frame, node, m) == msg, or the error decode gives its frame (docs/decoder.md, "encode").
[[nodiscard]] constexpr result<can::frame> encode(canopen::node_id node, model m,
                                                  const message& msg) noexcept {
    if (!detail::is_model(m)) return errc::value_out_of_range;
    if (msg.index() >= detail::first_j1939_index || msg.index() == detail::switch_index)
        [[unlikely]]
        return detail::encode_j1939(m, msg, std::nullopt);
    return detail::encode_canopen<true>(node, m, msg);
}

namespace detail {
// A PDO that checks itself (key_state, led_on, led_blink, led_brightness, backlight).
template <class T>
concept own_pdo = requires(const model_layout& keypad, const T& v) {
    own_check(keypad, v);
};

// encode of one CANopen alternative for the model whose layout is `keypad`.
template <class T, class Layout>
POWERKEY_DETAIL_INLINE constexpr result<can::frame> encode_alternative(const Layout& keypad,
                                                                       canopen::node_id node,
                                                                       const T& msg) noexcept {
    if constexpr (own_pdo<T>)
        return own_frame(keypad, node, msg);
    else if constexpr (own_sdo<T>)
        return own_frame_inline(keypad, node, msg);
    else
        return encode_canopen<false>(node, keypad, message(msg));
}
}  // namespace detail

// encode of one CANopen alternative: no J1939 code, no decoder for one that checks itself.
template <detail::canopen_alternative T>
[[nodiscard]] constexpr result<can::frame> encode(canopen::node_id node, model m,
                                                  const T& msg) noexcept {
    if (!detail::is_model(m)) return errc::value_out_of_range;
    return detail::encode_alternative(detail::layout(m), node, msg);
}

// The model of a behaviour class (behaviour::controller's Keypad): any_model, chosen at run time,
// or model_constant<M>, known when the program is built (M's rows alone).
struct any_model {};
template <model M>
struct model_constant {
    static_assert(detail::is_model(M), "M is a row of the model table");
    static constexpr model value = M;
};

// The same, a J1939 message narrowed to the keypad at `address`, as decode(f, node, m, address)
// reads it (a key contact state to an address would otherwise read as an LED command).
[[nodiscard]] constexpr result<can::frame> encode(canopen::node_id node, model m,
                                                  const message& msg,
                                                  j1939::keypad_address address) noexcept {
    if (detail::is_model(m) &&
        (msg.index() >= detail::first_j1939_index || msg.index() == detail::switch_index))
        return detail::encode_j1939(m, msg, address);
    return encode(node, m, msg);
}

// --- a keypad known when the program is built ----------------------------------------------------
// docs/decoder.md, "The model known at compile time".

namespace detail {
// Bytes `from` up to f's length are all 00h (bytes past the length are not read).
constexpr bool zeros_from(const can::frame& f, std::uint8_t from) noexcept {
    for (std::uint8_t i = from; i < f.size(); ++i)
        if (f[i] != 0) return false;
    return true;
}
}  // namespace detail

// The key state alone: decode's answer when f is the model's TPDO1, wrong_id for any other frame.
// (No shorter form exists: the tick is the last byte.)
template <model M>
[[nodiscard]] POWERKEY_DETAIL_FLATTEN constexpr result<key_state> decode_key_state(
    const can::frame& f, canopen::node_id node, reading how = reading::tolerant) noexcept {
    static_assert(detail::is_model(M), "M is a row of the model table");
    if (f.id_word() != canopen::cob_id(canopen::function::tpdo1, node).value())
        return errc::wrong_id;
    if (f.size() == 5) return detail::key_state_of<key_state>(detail::fixed_layout_v<M>, f);
    if (how == reading::strict || f.size() < 5 || !detail::zeros_from(f, 5))
        return errc::wrong_length;
    auto r = detail::key_state_of<key_state>(detail::fixed_layout_v<M>, f);
    if (r) r->form = frame_form::padded;
    return r;
}

// encode(node, M, msg) of one CANopen alternative with M's layout a constant: a PDO that checks
// itself or a command flattened (POWERKEY_DETAIL_FLATTEN), the rest inlined.
template <model M, detail::canopen_alternative T>
requires(detail::own_pdo<T> || std::is_same_v<T, command>) [[nodiscard]] POWERKEY_DETAIL_FLATTEN
    constexpr result<can::frame> encode(canopen::node_id node, const T& msg) noexcept {
    static_assert(detail::is_model(M), "M is a row of the model table");
    return detail::encode_alternative(detail::fixed_layout_v<M>, node, msg);
}
template <model M, detail::canopen_alternative T>
requires(!detail::own_pdo<T> && !std::is_same_v<T, command>) [[nodiscard]] POWERKEY_DETAIL_INLINE
    constexpr result<can::frame> encode(canopen::node_id node, const T& msg) noexcept {
    static_assert(detail::is_model(M), "M is a row of the model table");
    return detail::encode_alternative(detail::fixed_layout_v<M>, node, msg);
}

// encode(node, M, msg) of any message.
template <model M>
[[nodiscard]] constexpr result<can::frame> encode(canopen::node_id node,
                                                  const message& msg) noexcept {
    static_assert(detail::is_model(M), "M is a row of the model table");
    if (msg.index() >= detail::first_j1939_index || msg.index() == detail::switch_index)
        [[unlikely]]
        return detail::encode_j1939(M, msg, std::nullopt);
    return detail::encode_canopen<false>(node, detail::fixed_layout_v<M>, msg);
}

}  // namespace powerkey

#endif  // POWERKEY_KEYPAD_CODEC_HPP
