// keypad/codec.hpp with the model a template argument (decode_key_state<M>, encode<M>): every
// manual row, refusal and encoder refusal of tests/*_rows.hpp through both the compile-time and
// the run-time calls, for every model (not only the row's), read tolerantly and strictly; the
// same answers, the same errors and, for the row's models, the row's bytes. Compile-time rows with
// the PK1000 and PKP manuals' bytes.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/keypad/codec.hpp>

#include "codec_rows.hpp"
#include "key_state_agreement.hpp"
#include "pk1000_rows.hpp"
#include "pkp_rows.hpp"
#include "si_reference_rows.hpp"
#include "si_rows.hpp"
#include "support.hpp"

#include <cstddef>
#include <iterator>
#include <string_view>
#include <utility>
#include <variant>

namespace {
using namespace powerkey;
using namespace powerkey_tests;
using codec_rows::node_of;

// encode<M> against encode(node, M, ...): the same frame or error, for the message and for the
// alternative it holds.
template <model M>
constexpr bool encode_agrees(canopen::node_id node, const message& msg) {
    if (!(encode<M>(node, msg) == encode(node, M, msg))) return false;
    return std::visit([&](const auto& v) { return encode<M>(node, v) == encode(node, M, v); }, msg);
}

// Frame f, message msg (for the encoders) through model M's calls; for a model of `own`, encode<M>
// of the alternative msg holds gives `want` (the row's bytes, or its error).
template <model M>
constexpr bool same_for(const can::frame& f, canopen::node_id node, const message& msg,
                        const model_set& own, const result<can::frame>& want) {
    if (!key_state_agreement::agrees<M>(f, node, reading::tolerant)) return false;
    if (!key_state_agreement::agrees<M>(f, node, reading::strict)) return false;
    if (!encode_agrees<M>(node, msg)) return false;
    if (!own.contains(M)) return true;
    return std::visit([&](const auto& v) { return encode<M>(node, v) == want; }, msg);
}
template <std::size_t... I>
constexpr bool same_for_every_model(const can::frame& f, canopen::node_id node, const message& msg,
                                    const model_set& own, const result<can::frame>& want,
                                    std::index_sequence<I...>) {
    return (same_for<static_cast<model>(I)>(f, node, msg, own, want) && ...);
}
constexpr bool typed_agrees(const can::frame& f, canopen::node_id node, const message& msg,
                            const model_set& own, const result<can::frame>& want) {
    return same_for_every_model(f, node, msg, own, want, std::make_index_sequence<model_count>{});
}

// A manual row: its frame through the readers, its meaning through the encoders (the row's
// bytes for its models).
constexpr bool typed_row(const codec_rows::row& r) {
    const auto f = can::parse_candump(r.frame);
    return f && typed_agrees(*f, node_of(r.node), r.expected, r.models, *f);
}
// A refusal: the frame through the readers, and what the first model's decode reads in it (or
// nothing) through the encoders.
constexpr bool typed_error_row(const codec_rows::error_row& r) {
    const auto f = can::parse_candump(r.frame);
    if (!f) return false;
    const auto d = decode(*f, node_of(r.node), model::pk1000);
    return typed_agrees(*f, node_of(r.node), d ? *d : message{}, {}, can::frame{});
}
// An encoder refusal: refused by encode<M> with the row's error for its models; its raw frame
// (a key state of no key where there is none) through the readers.
constexpr bool typed_encode_error_row(const codec_rows::encode_error_row& r) {
    const auto f = can::parse_candump(r.frame.empty() ? "195#000000002A" : r.frame);
    return f && typed_agrees(*f, node_of(r.node), r.msg, r.models, r.error);
}

// Key states not in the manual's form, of another node and in 29 bits: padded with 00h bytes
// (read as padded tolerantly, wrong_length strictly), cut short, padded with a byte set. `error`:
// what decode_key_state<model::pk1000> answers tolerantly (errc{}: a key state); every model
// answers as its decode (typed_error_row).
constexpr codec_rows::error_row form_rows[] = {
    {"key state padded to 6", {}, 0x15, "195#090000002A00", errc{}},
    {"key state padded to 8", {}, 0x15, "195#090000002A000000", errc{}},
    {"key state padded, key 11", {}, 0x15, "195#000400002A00", errc::reserved_not_zero},
    {"key state padded, byte 5 set", {}, 0x15, "195#090000002A01", errc::wrong_length},
    {"key state padded, byte 6 set", {}, 0x15, "195#090000002A0001", errc::wrong_length},
    {"key state of 4 bytes", {}, 0x15, "195#09000000", errc::wrong_length},
    {"key state of 0 bytes", {}, 0x15, "195#", errc::wrong_length},
    {"key state of node 16h", {}, 0x15, "196#090000002A", errc::wrong_id},
    {"key state of node 15h, 29 bits", {}, 0x15, "00000195#090000002A", errc::wrong_id},
    {"LED map on, node 7Fh", {}, 0x7F, "27F#0100000000000000", errc::wrong_id},
};
constexpr bool pk1000_form_row(const codec_rows::error_row& r) {
    const auto f = can::parse_candump(r.frame);
    return f && decode_key_state<model::pk1000>(*f, node_of(r.node)).error() == r.error &&
           typed_error_row(r);
}

// Hard-coded rows with the manuals' bytes, proved at compile time: what decode_key_state<M> reads
// and encode<M> builds.
struct key_row {
    std::string_view section;
    std::string_view frame;
    key_set keys;
    std::uint8_t tick;
};
template <model M>
constexpr bool reads(const key_row& r) {
    const auto k = decode_key_state<M>(frame_of(r.frame), 0x15);
    return k && *k == key_state{r.keys, r.tick} &&
           encode<M>(0x15, key_state{r.keys, r.tick}) == frame_of(r.frame);
}
constexpr key_row pk1000_keys[] = {
    {"PK1000 11", "195#000000002A", {}, 0x2A},
    {"PK1000 11", "195#090000002A", {1, 4}, 0x2A},
    {"PK1000 11", "195#000200002A", {10}, 0x2A},
};
constexpr key_row pkp2400_keys[] = {
    {"PKP 10 PKP-2400 key 2 (XX=80)", "195#0200000080", {2}, 0x80},
    {"PKP 10 PKP-2400 keys 7, 2 (XX=FE)", "195#42000000FE", {2, 7}, 0xFE},
};
static_assert(
    all_rows_pass<first_failing(pk1000_keys, reads<model::pk1000>), std::size(pk1000_keys)>);
static_assert(
    all_rows_pass<first_failing(pkp2400_keys, reads<model::pkp2400>), std::size(pkp2400_keys)>);

// Refusals: a key the model lacks, a reserved byte, another length read strictly, not this PDO.
static_assert(decode_key_state<model::pk1000>(frame_of("195#000400002A"), 0x15) ==
              errc::reserved_not_zero);  // PK1000 key 11
static_assert(decode_key_state<model::pk1000>(frame_of("195#000001002A"), 0x15) ==
              errc::reserved_not_zero);
static_assert(decode_key_state<model::pkp2400>(frame_of("195#0001000010"), 0x15) ==
              errc::reserved_not_zero);  // PKP-2400 key 9
static_assert(decode_key_state<model::pk1000>(frame_of("195#000000002A00"), 0x15,
                                              reading::strict) == errc::wrong_length);
static_assert(decode_key_state<model::pk1000>(frame_of("195#00000000"), 0x15) ==
              errc::wrong_length);
static_assert(decode_key_state<model::pk1000>(frame_of("215#0100000000000000"), 0x15) ==
              errc::wrong_id);
static_assert(decode_key_state<model::pk1000>(frame_of("196#090000002A"), 0x15) == errc::wrong_id);
// Padded with 00h, read tolerantly: the manual's key state, `form` padded.
static_assert(decode_key_state<model::pk1000>(frame_of("195#090000002A0000"), 0x15) ==
              key_state{{1, 4}, 0x2A, frame_form::padded});

// LED maps: PK1000 sections 12 and 13, PKP section 11 (PKP-2400) and 12 (PKP-2200).
static_assert(encode<model::pk1000>(0x15, led_on{{{17}, {28}, {}}}) ==
              frame_of("215#0000010000000008"));
static_assert(encode<model::pk1000>(0x15, led_blink{{{2, 15, 24, 28}, {6, 13, 19, 25}, {}}}) ==
              frame_of("315#0240800820100401"));
static_assert(encode<model::pkp2400>(0x15, led_on{{{2, 7}, {}, {}}}) ==
              frame_of("215#4200000000000000"));
static_assert(encode<model::pkp2400>(0x15, led_on{{{}, {}, {2, 3}}}) ==
              frame_of("215#0000060000000000"));
static_assert(encode<model::pkp2200>(0x15, led_blink{{{}, {}, {1}}}) ==
              frame_of("315#0001000000000000"));
// What the LED PDO cannot carry: PK1000 red LED 29, a blue LED on the two-colour PK1000, PKP-2400
// key 9; a key 11 on the PK1000's key state.
static_assert(encode<model::pk1000>(0x15, led_on{{{29}, {}, {}}}) == errc::value_out_of_range);
static_assert(encode<model::pk1000>(0x15, led_blink{{{}, {}, {1}}}) == errc::value_out_of_range);
static_assert(encode<model::pkp2400>(0x15, led_on{{{9}, {}, {}}}) == errc::value_out_of_range);
static_assert(encode<model::pk1000>(0x15, key_state{{11}, 0x2A}) == errc::reserved_not_zero);

// The PDO rows of the PK1000 and PKP manuals (identifiers 180h..57Fh) at compile time too, and the
// key states not in the manual's form.
constexpr bool typed_pdo_row(const codec_rows::row& r) {
    const auto f = can::parse_candump(r.frame);
    if (f && (f->is_extended() || f->raw_id() < 0x180 || f->raw_id() >= 0x580)) return true;
    return typed_row(r);
}
static_assert(
    all_rows_pass<first_failing(pk1000_rows::rows, typed_pdo_row), std::size(pk1000_rows::rows)>);
static_assert(
    all_rows_pass<first_failing(pkp_rows::rows, typed_pdo_row), std::size(pkp_rows::rows)>);
static_assert(all_rows_pass<first_failing(form_rows, pk1000_form_row), std::size(form_rows)>);
}  // namespace

TEST_CASE("codec: decode_key_state<M> and encode<M> answer as the run-time calls, every row") {
    check_rows(codec_rows::core_rows, typed_row);
    check_rows(pk1000_rows::rows, typed_row);
    check_rows(pkp_rows::rows, typed_row);
    check_rows(si_rows::rows, typed_row);
    check_rows(si_reference_rows::rows, typed_row);
    check_rows(codec_rows::core_error_rows, typed_error_row);
    check_rows(pk1000_rows::error_rows, typed_error_row);
    check_rows(pkp_rows::error_rows, typed_error_row);
    check_rows(si_rows::error_rows, typed_error_row);
    check_rows(si_rows::errata_rows, typed_error_row);
    check_rows(si_reference_rows::error_rows, typed_error_row);
    check_rows(form_rows, pk1000_form_row);
    check_rows(pk1000_rows::encode_error_rows, typed_encode_error_row);
    check_rows(pkp_rows::encode_error_rows, typed_encode_error_row);
}

TEST_CASE("codec: decode_key_state<M> and encode<M> on the manuals' bytes") {
    for (const key_row& r : pk1000_keys) CHECK(reads<model::pk1000>(r));
    for (const key_row& r : pkp2400_keys) CHECK(reads<model::pkp2400>(r));
    CHECK(decode_key_state<model::pk1000>(frame_of("195#000400002A"), 0x15) ==
          errc::reserved_not_zero);
    CHECK(decode_key_state<model::pk1000>(frame_of("195#090000002A0000"), 0x15) ==
          key_state{{1, 4}, 0x2A, frame_form::padded});
    CHECK(encode<model::pk1000>(0x15, led_on{{{17}, {28}, {}}}) ==
          frame_of("215#0000010000000008"));
    CHECK(encode<model::pk1000>(0x15, led_on{{{29}, {}, {}}}) == errc::value_out_of_range);
}
