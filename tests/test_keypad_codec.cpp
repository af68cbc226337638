// keypad/codec.hpp: decode(frame, node, model) and encode(node, model, message) on the core rows
// (the frames every keypad speaks whatever its dictionary) per model; frames of another node or
// function classified and refused; malformed frames; an abort's direction; and every manual row
// through every model, including the models it is not written for. The manuals' own rows are in
// test_keypad_codec_pk1000.cpp, _pkp.cpp and _si.cpp.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/names.hpp>

#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

#include "codec_rows.hpp"
#include "j1939_rows.hpp"
#include "pk1000_rows.hpp"
#include "pkp_rows.hpp"
#include "si_reference_rows.hpp"
#include "si_rows.hpp"
#include "support.hpp"

namespace {
using namespace powerkey;
using namespace codec_rows;
using namespace powerkey_tests;
constexpr canopen::node_id keypad = canopen::default_node_id;

static_assert(first_failing(core_rows, round_trips) == std::size(core_rows));
static_assert(first_failing(core_error_rows, refused) == std::size(core_error_rows));

// Classified as the row says, of no concern to keypad 15h, refused by every model.
constexpr bool foreign(const foreign_row& r) {
    const auto f = frame_of(r.frame);
    if (!(canopen::classify(f) == r.cls) || canopen::concerns(canopen::classify(f), keypad))
        return false;
    return for_models(all, [&](model m) { return decode(f, keypad, m) == r.error; });
}
static_assert(first_failing(foreign_rows, foreign) == std::size(foreign_rows));

// Every model, whether the row is written for it or not: refused, or decoded to a meaning that
// encodes to the same frame; never refused by a model the row is written for.
constexpr bool every_model_round_trips(const row& r) {
    const auto f = frame_of(r.frame);
    for (std::size_t i = 0; i < model_count; ++i) {
        const auto m = static_cast<model>(i);
        const auto d = decode(f, node_of(r.node), m);
        if (!d) {
            if (r.models.contains(m)) return false;
            continue;
        }
        const auto e = encode(node_of(r.node), m, *d);
        if (!e || !(*e == f)) return false;
    }
    return true;
}
static_assert(first_failing(core_rows, every_model_round_trips) == std::size(core_rows));
static_assert(first_failing(pk1000_rows::rows, every_model_round_trips) ==
              std::size(pk1000_rows::rows));
static_assert(first_failing(pkp_rows::rows, every_model_round_trips) == std::size(pkp_rows::rows));

// decode<M>(f, node), the model known at compile time, answers as decode(f, node, M) for every
// model and both readings (issue 24: the same rows serve both APIs); so do decode_canopen<M> and
// encode<M> of each message read (M's dictionary alone).
template <model M>
constexpr bool decode_agrees(const can::frame& f, canopen::node_id n) {
    return decode<M>(f, n) == decode(f, n, M) &&
           decode<M>(f, n, reading::strict) == decode(f, n, M, reading::strict);
}
template <model M>
constexpr bool canopen_calls_agree(const can::frame& f, canopen::node_id n) {
    if (!(decode_canopen<M>(f, n) == decode_canopen(f, n, M))) return false;
    const auto m = decode(f, n, M);
    return !m || encode<M>(n, *m) == encode(n, M, *m);
}
// Every model's calls on a row's frame: decode's (false), or decode_canopen's and encode's (true).
template <bool canopen_calls, class Row, std::size_t... I>
constexpr bool every_model(const Row& r, std::index_sequence<I...>) {
    const auto f = frame_of(r.frame);
    const auto n = node_of(r.node);
    if constexpr (canopen_calls)
        return (canopen_calls_agree<static_cast<model>(I)>(f, n) && ...);
    else
        return (decode_agrees<static_cast<model>(I)>(f, n) && ...);
}
template <class Row>
constexpr bool both_model_apis_agree(const Row& r) {
    return every_model<false>(r, std::make_index_sequence<model_count>{});
}
template <class Row>
constexpr bool compile_time_canopen_rows_agree(const Row& r) {
    return every_model<true>(r, std::make_index_sequence<model_count>{});
}
template <class Row>
constexpr bool compile_time_calls_agree(const Row& r) {
    return both_model_apis_agree(r) && compile_time_canopen_rows_agree(r);
}
static_assert(first_failing(core_rows, both_model_apis_agree<row>) == std::size(core_rows));
static_assert(first_failing(core_rows, compile_time_canopen_rows_agree<row>) ==
              std::size(core_rows));
static_assert(first_failing(core_error_rows, both_model_apis_agree<error_row>) ==
              std::size(core_error_rows));

// decode_canopen answers as decode for every 11-bit frame, and refuses every 29-bit frame with
// wrong_id; encode of one CANopen alternative (no J1939 code) builds what encode of the message
// builds, or refuses it the same way.
template <std::size_t... I>
constexpr bool canopen_only_agrees(const can::frame& f, canopen::node_id n,
                                   std::index_sequence<I...>) {
    const auto one = [&f, n](model m) {
        for (const reading how : {reading::tolerant, reading::strict}) {
            const auto r = decode_canopen(f, n, m, how);
            if (f.is_extended() ? r != result<message>(errc::wrong_id) : r != decode(f, n, m, how))
                return false;
            if (!r) continue;
            const bool same = std::visit(
                [&](const auto& v) {
                    if constexpr (detail::canopen_alternative<std::remove_cvref_t<decltype(v)>>)
                        return encode(n, m, v) == encode(n, m, *r);
                    else
                        return true;
                },
                *r);
            if (!same) return false;
        }
        return true;
    };
    return (one(static_cast<model>(I)) && ...);
}
template <class Row>
constexpr bool canopen_only_decoder_agrees(const Row& r) {
    return canopen_only_agrees(frame_of(r.frame), node_of(r.node),
                               std::make_index_sequence<model_count>{});
}
static_assert(first_failing(core_rows, canopen_only_decoder_agrees<row>) == std::size(core_rows));

// A value the optimiser cannot see through, so that the check below runs at run time.
template <class T>
T opaque(T v) {
    volatile T keep = v;
    return keep;
}
}  // namespace

TEST_CASE("core rows decode to their meaning and encode back to the same bytes, per model") {
    check_rows(core_rows, round_trips);
}

TEST_CASE("frames of another node or function are classified and refused") {
    check_rows(foreign_rows, foreign);
}

TEST_CASE("malformed frames of the keypad give the precise error, per model") {
    check_rows(core_error_rows, refused);
}

TEST_CASE("every manual row through every model: refused, or read back to the same bytes") {
    check_rows(core_rows, every_model_round_trips);
    check_rows(pk1000_rows::rows, every_model_round_trips);
    check_rows(pkp_rows::rows, every_model_round_trips);
}

TEST_CASE("an abort keeps its direction") {
    const auto from_client = frame_of("615#8008100000000405");
    const auto from_keypad = frame_of("595#8008100000000405");
    for (std::size_t i = 0; i < model_count; ++i) {
        const auto m = static_cast<model>(i);
        CAPTURE(to_string(m));
        const auto a = decode(from_client, keypad, m);
        const auto b = decode(from_keypad, keypad, m);
        REQUIRE(a.has_value());
        REQUIRE(b.has_value());
        CHECK(kind_of(*a) == "sdo_abort_request");
        CHECK(kind_of(*b) == "sdo_abort_response");
        CHECK(encode(keypad, m, *a) == from_client);
        CHECK(encode(keypad, m, *b) == from_keypad);
    }
}

// The codec takes the command module as writable without looking: every row of it is.
TEST_CASE("the codec's compile-time check of the command module, again at run time") {
    CHECK(opaque(&detail::commands_writable)());
}

TEST_CASE(
    "decode<M>, decode_canopen<M> and encode<M> with the model known at compile time answer as the "
    "run-time calls") {
    // Every manual row and every refusal row, through every model, read tolerantly and strictly.
    check_rows(core_rows, compile_time_calls_agree<row>);
    check_rows(core_error_rows, compile_time_calls_agree<error_row>);
    check_rows(pk1000_rows::rows, compile_time_calls_agree<row>);
    check_rows(pk1000_rows::error_rows, compile_time_calls_agree<error_row>);
    check_rows(pkp_rows::rows, compile_time_calls_agree<row>);
    check_rows(pkp_rows::error_rows, compile_time_calls_agree<error_row>);
    check_rows(si_rows::rows, compile_time_calls_agree<row>);
    check_rows(si_rows::error_rows, compile_time_calls_agree<error_row>);
    check_rows(si_rows::errata_rows, compile_time_calls_agree<error_row>);
    check_rows(si_reference_rows::rows, compile_time_calls_agree<row>);
}

TEST_CASE("decode_canopen answers as decode on 11-bit frames and refuses 29-bit ones") {
    // Every manual row and refusal row (the J1939 rows among them), every model, both readings;
    // each decoded CANopen message encoded as its own alternative and as a message.
    check_rows(core_rows, canopen_only_decoder_agrees<row>);
    check_rows(core_error_rows, canopen_only_decoder_agrees<error_row>);
    check_rows(pk1000_rows::rows, canopen_only_decoder_agrees<row>);
    check_rows(pkp_rows::rows, canopen_only_decoder_agrees<row>);
    check_rows(si_rows::rows, canopen_only_decoder_agrees<row>);
    check_rows(si_rows::error_rows, canopen_only_decoder_agrees<error_row>);
    // The J1939 manuals' frames: read by decode, wrong_id to decode_canopen.
    for (const auto& r : j1939_rows::pkp2600si_rows) {
        CAPTURE(r.frame);
        const auto f = frame_of(r.frame);
        CHECK(decode(f, keypad, model::pkp2600si).has_value());
        CHECK(decode_canopen(f, keypad, model::pkp2600si) == result<message>(errc::wrong_id));
    }
}

// What encode did before its messages checked themselves, kept as the oracle they are held to:
// build the frame, read it back strictly, and return it only when the meaning comes back.
result<can::frame> encode_by_reading_back(canopen::node_id node, model m, const message& msg) {
    const auto f = detail::build(detail::layout(m), node, msg);
    if (!f) return f.error();
    const auto back = decode(*f, node, m, reading::strict);
    if (!back) return back.error();
    if (!(*back == detail::with_form(msg, frame_form::manual))) return errc::value_out_of_range;
    return *f;
}

// encode of key_state, led_on, led_blink, led_brightness and backlight, as their own types and as
// messages, checks the fields itself (no decoder): the same answer as the frame read back, for
// every model over key maps and LED maps with each bit alone and in blocks, ticks, every level and
// every colour byte.
TEST_CASE("encode of a PDO that checks itself answers as the frame read back") {
    std::vector<std::uint32_t> masks{0, 0xFFFF'FFFF, 0x0000'FFFF, 0xFFFF'0000, 0x0FFF'FFFF};
    for (unsigned b = 0; b < 32; ++b) masks.push_back(std::uint32_t{1} << b);
    for (unsigned b = 1; b <= 32; ++b) masks.push_back(b == 32 ? 0xFFFF'FFFF : (1u << b) - 1);
    for (const model m : enum_values<model>()) {
        CAPTURE(std::string(to_string(m)));
        for (const std::uint32_t k : masks) {
            CAPTURE(k);
            const key_state ks{key_set::from_mask(k), static_cast<std::uint8_t>(k * 7)};
            const auto same = [&](const auto& v) {
                const auto want = encode_by_reading_back(keypad, m, message(v));
                CHECK(encode(keypad, m, v) == want);
                CHECK(encode(keypad, m, message(v)) == want);
            };
            same(ks);
            for (const std::uint32_t k2 : {0u, k, 0x1u, 0x8000'0000u}) {
                const leds l{led_set::from_mask(k), led_set::from_mask(k2),
                             led_set::from_mask(k ^ k2)};
                same(led_on{l});
                same(led_blink{l});
                same(led_on{leds{{}, {}, led_set::from_mask(k)}});
            }
        }
        for (unsigned v = 0; v <= 0xFF; ++v) {  // every level (brightness) and colour byte
            CAPTURE(v);
            const auto same = [&](const auto& msg) {
                const auto want = encode_by_reading_back(keypad, m, message(msg));
                CHECK(encode(keypad, m, msg) == want);
                CHECK(encode(keypad, m, message(msg)) == want);
            };
            const level l = level::make(v & 0x3F).value();
            if (v <= 0x3F) same(led_brightness{l});
            same(backlight{l, static_cast<backlight_colour>(v)});
        }
    }
}

// The same at compile time, with the PKP manual's bytes (PKP section 13 a: LED 8 red; 1017h).
static_assert(encode(keypad, model::pkp2400,
                     command{
                         .code = command_code::set_led_state, .key = 8, .state = led_state::red_on})
                  .value() == frame_of("615#2300650101080100"));
static_assert(encode(keypad, model::pkp2400, sdo_write{object::heartbeat_time, number_value(50)})
                  .value() == frame_of("615#2B17100032000000"));
static_assert(encode(keypad, model::pkp2400, message(led_on{leds{}.set(2, colour::red)})).value() ==
              encode(keypad, model::pkp2400, led_on{leds{}.set(2, colour::red)}).value());

// The SDO reads, writes, replies and commands as their own types check themselves the same way
// (the row, its access, the value read back from the bytes built): the same answer as the frame
// read back, for every
// model, every object (in the model's dictionary or not) over values with each bit alone and in
// blocks, LED maps, string piece sizes, and every command with parameters in and out of range.
// A message's form (how decode read it) does not matter: each form encodes to the manual's frame.
TEST_CASE("encode of an SDO message answers as the frame read back") {
    std::vector<std::uint32_t> raws{0,      0xFFFF'FFFF, 0x3F,           0x40,
                                    0x7F,   0x80,        0xFF,           0x100,
                                    0xFFFF, 0x1'0000,    load_signature, 0x6576'6173};
    for (unsigned b = 0; b < 32; ++b) raws.push_back(std::uint32_t{1} << b);
    for (const model m : enum_values<model>()) {
        CAPTURE(std::string(to_string(m)));
        const auto same = [&](const auto& v) {  // encode of v as its own type
            const auto want = encode_by_reading_back(keypad, m, message(v));
            CHECK(encode(keypad, m, v) == want);
            // own_frame, the out-of-line copy the controller calls (encode inlines its body)
            CHECK(detail::own_frame(detail::layout(m), keypad, v) == want);
        };
        for (const object o : enum_values<object>()) {
            CAPTURE(std::string(to_string(o)));
            for (const frame_form f : enum_values<frame_form>()) {
                same(sdo_read{o, f});
                same(sdo_write_reply{o, f});
                same(sdo_write{o, number_value(1), f});
                same(sdo_read_reply{o, number_value(1), f});
            }
            for (const std::uint32_t raw : raws) {
                CAPTURE(raw);
                for (const unsigned size : {0u, 1u, 2u, 4u, 5u}) {
                    for (const bool with_map : {false, true}) {
                        object_value v{raw, {}, static_cast<std::uint8_t>(size)};
                        if (with_map)
                            v.map = {led_set::from_mask(raw), led_set::from_mask(raw >> 1),
                                     led_set::from_mask(~raw)};
                        same(sdo_write{o, v});
                        same(sdo_read_reply{o, v});
                    }
                }
            }
        }
        for (const command_code c : enum_values<command_code>()) {
            CAPTURE(std::string(to_string(c)));
            for (unsigned b = 0; b < 0x100; b += 3) {
                command cmd{};
                cmd.code = c;
                const auto u = static_cast<std::uint8_t>(b);
                cmd.key = u;
                cmd.state = static_cast<led_state>(u & 0xF);
                cmd.level = level::make(u & 0x3F).value();
                cmd.colour = static_cast<backlight_colour>(u % 11);
                cmd.enabled = (b & 1) != 0;
                cmd.baud = static_cast<baud_rate>(u % 10);
                cmd.period_10ms = u;
                cmd.node_id = canopen::node_id::make(u % 0x80 == 0 ? 1 : u % 0x80).value();
                cmd.show = static_cast<startup_show>(u % 5);
                same(cmd);
                cmd.key = 1;  // the other members at their defaults but one
                same(cmd);
            }
            // Each member alone off its default (the members a code does not carry are tested in
            // one masked compare): refused unless the code carries it and the value is in range.
            for (int member = 0; member < 9; ++member) {
                command one{c};
                switch (member) {
                    case 0: one.key = 2; break;
                    case 1: one.state = led_state::green_on; break;
                    case 2: one.level = level::make(0x20).value(); break;
                    case 3: one.colour = backlight_colour::red; break;
                    case 4: one.enabled = true; break;
                    case 5: one.baud = baud_rate::kbit_500; break;
                    case 6: one.period_10ms = 7; break;
                    case 7: one.node_id = canopen::node_id::make(0x22).value(); break;
                    default: one.show = startup_show::disabled; break;
                }
                CAPTURE(member);
                same(one);
            }
            for (const frame_form f : enum_values<frame_form>()) {
                command defaults{c};  // most codes take the defaults
                defaults.form = f;
                same(defaults);
            }
        }
    }
}

// Every byte of the one-byte fields of the CiA 301 frames every model takes, through decode: the
// heartbeat's state (00h boot-up, 04h stopped, 05h operational, 7Fh pre-operational; PK1000 8-9,
// PKP 8-9), the NMT command (01h, 02h, 80h, 81h, 82h and the legacy 00h; PK1000 4-7) with this
// node and 00h (all) as the target. Anything else is refused with value_out_of_range (a state)
// or unknown_command (a command).
TEST_CASE("every heartbeat state byte and NMT command byte, in every model") {
    const canopen::node_id node = canopen::default_node_id;
    for (const model m : enum_values<model>()) {
        CAPTURE(std::string(to_string(m)));
        for (unsigned b = 0; b < 0x100; ++b) {
            CAPTURE(b);
            const can::payload hb{static_cast<std::uint8_t>(b)};
            const auto state = decode(
                can::frame(can::standard_id::make(0x715).value(), can::dlc::make(1).value(), hb),
                node, m);
            if (b == 0x00 || b == 0x04 || b == 0x05 || b == 0x7F)
                CHECK(state.has_value());
            else
                CHECK(state == errc::value_out_of_range);
            for (const unsigned target : {0x00u, 0x15u}) {
                const can::payload nmt{static_cast<std::uint8_t>(b),
                                       static_cast<std::uint8_t>(target)};
                const auto command = decode(can::frame(can::standard_id::make(0x000).value(),
                                                       can::dlc::make(2).value(), nmt),
                                            node, m);
                if (b <= 0x02 || (b >= 0x80 && b <= 0x82))
                    CHECK(command.has_value());
                else
                    CHECK(command == errc::unknown_command);
            }
        }
    }
}
