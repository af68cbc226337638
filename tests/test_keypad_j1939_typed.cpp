// keypad/j1939_codec.hpp with the model a template argument (decode<M>, decode_key_or_led<M>,
// decode_key_contact<M>, encode<M>): every manual row and every refusal of tests/j1939_rows.hpp
// through both the compile-time and the run-time calls, for every model (not only the row's), with
// any keypad and narrowed; the same answer each time.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/keypad/j1939_codec.hpp>

#include "j1939_rows.hpp"
#include "support.hpp"

#include <cstddef>
#include <optional>
#include <utility>

namespace {
using namespace j1939_rows;
using namespace powerkey_tests;
namespace can = powerkey::can;

// decode_key_contact<M> against decode_key_or_led: the same key contact state, or the same
// error; wrong_id for a frame read as an LED command. Narrowed to k the direction is the source
// (from k: a key contact state), so the answer is exact; not narrowed, only where decode reads a
// key contact state, or refuses a frame decode_key_contact does not call an LED command.
template <model M>
constexpr bool key_contact_agrees(const can::frame& f, keypad_address k) {
    const auto kc = decode_key_contact<M>(f, k);
    const auto d = decode_key_or_led(f, M, k);
    const key_contact* v = d ? std::get_if<key_contact>(&*d) : nullptr;
    if (k) {
        const bool command_01 = f.is_extended() && ((f.raw_id() >> 16) & 0x3FF) == 0xEF &&
                                f.size() == 8 && f[0] == 0x04 && f[1] == 0x1B && f[2] == 0x01 &&
                                ((f.raw_id() & 0xFF) == *k || ((f.raw_id() >> 8) & 0xFF) == *k);
        if (command_01 && (f.raw_id() & 0xFF) != *k) return kc == errc::wrong_id;
    }
    if (v != nullptr) return kc && *kc == *v;
    if (kc) return false;
    if (!k && kc.error() == errc::wrong_id) return true;
    return !d && d.error() == kc.error();
}

// Frame f and message msg through the compile-time calls of model M and the run-time ones.
template <model M>
constexpr bool same_for(const can::frame& f, const message& msg, keypad_address k) {
    if (!key_contact_agrees<M>(f, k)) return false;
    if (!(decode<M>(f, k) == decode(f, M, k))) return false;
    if (!(decode_key_or_led<M>(f, k) == decode_key_or_led(f, M, k))) return false;
    if (!(encode<M>(msg, k) == encode(M, msg, k))) return false;
    return std::visit([&](const auto& v) { return encode<M>(v, k) == encode(M, v, k); }, msg);
}
template <std::size_t... I>
constexpr bool same_for_every_model(const can::frame& f, const message& msg, keypad_address k,
                                    std::index_sequence<I...>) {
    return (same_for<static_cast<model>(I)>(f, msg, k) && ...);
}
constexpr bool typed_agrees(const can::frame& f, const message& msg, keypad_address k) {
    return same_for_every_model(f, msg, k, std::make_index_sequence<model_row_count>{}) &&
           same_for_every_model(f, msg, std::nullopt, std::make_index_sequence<model_row_count>{});
}

constexpr bool typed_row(const j1939_rows::row& r) {
    const auto f = powerkey::can::parse_candump(r.frame);
    return f && typed_agrees(*f, r.expected, r.keypad);
}
// A refusal: the frame through the readers, and what it would decode to for the encoders.
constexpr bool typed_error_row(const error_row& r) {
    const auto f = powerkey::can::parse_candump(r.frame);
    if (!f) return false;
    const auto d = decode(*f, powerkey::model::pkp2600si);
    return typed_agrees(*f, d ? *d : message{}, r.keypad);
}
constexpr bool typed_encode_error_row(const encode_error_row& r) {
    const auto f =
        powerkey::can::parse_candump(r.frame.empty() ? "18EF2100#041B0220FFFFFFFF" : r.frame);
    return f && typed_agrees(*f, r.msg, r.keypad);
}

static_assert(all_rows_pass<first_failing(pkp2600si_rows, typed_row), std::size(pkp2600si_rows)>);
static_assert(all_rows_pass<first_failing(pkp1600si_rows, typed_row), std::size(pkp1600si_rows)>);
}  // namespace

TEST_CASE(
    "j1939: decode<M>, decode_key_or_led<M>, decode_key_contact<M> and encode<M> answer as the "
    "run-time calls") {
    check_rows(pkp1600si_rows, typed_row);
    check_rows(pkp2600si_rows, typed_row);
    check_rows(other_rows, typed_row);
    check_rows(error_rows, typed_error_row);
    check_rows(encode_error_rows, typed_encode_error_row);
}

TEST_CASE("j1939: encode<M> of a PKP-2600-SI LED command, narrowed and not") {
    using powerkey::led_mode;
    constexpr set_led green{.source = 0x00,
                            .destination = 0x21,
                            .priority = 6,
                            .key = 3,
                            .colour = led_colour::green,
                            .mode = led_mode::on,
                            .secondary = led_colour::off};
    static_assert(encode<model::pkp2600si>(green, std::uint8_t{0x21}).value() ==
                  frame_of("18EF2100#041B0103020100FF"));
    CHECK(encode<model::pkp2600si>(green) == encode(model::pkp2600si, green));
    // LED 13 is past the PKP-2600-SI's twelve; the PK1000's LED command is in no source.
    set_led thirteen = green;
    thirteen.key = 13;
    CHECK(encode<model::pkp2600si>(thirteen) == errc::value_out_of_range);
    CHECK(encode<model::pk1000>(green) == errc::undocumented);
}
