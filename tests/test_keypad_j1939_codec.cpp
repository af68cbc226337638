// keypad/j1939_codec.hpp: the J1939 codec against the two complete J1939 manuals and the other
// models' frames (tests/j1939_rows.hpp): every row both ways, with any keypad and narrowed to one;
// the decoder's and the encoder's refusals; the errata; TABLE 3; the encoder over raw field values.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/j1939_codec.hpp>
#include <powerkey/names.hpp>

#include "j1939_rows.hpp"
#include "support.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace {
using namespace j1939_rows;
using namespace powerkey_tests;
namespace can = powerkey::can;

static_assert(powerkey_tests::all_rows_pass<first_failing(pkp1600si_rows, round_trips),
                                            std::size(pkp1600si_rows)>);
static_assert(powerkey_tests::all_rows_pass<first_failing(pkp2600si_rows, round_trips),
                                            std::size(pkp2600si_rows)>);
static_assert(
    powerkey_tests::all_rows_pass<first_failing(other_rows, round_trips), std::size(other_rows)>);
static_assert(
    powerkey_tests::all_rows_pass<first_failing(error_rows, refused), std::size(error_rows)>);
static_assert(powerkey_tests::all_rows_pass<first_failing(encode_error_rows, encode_refused),
                                            std::size(encode_error_rows)>);

// The errata of the J1939 manuals (docs/errata.md, ## J1939) and the behaviour chosen.
struct erratum_row {
    std::string_view section;
    model_set models;
    std::string_view frame;
    j1939_rows::message expected;  // what the frame decodes to
};
constexpr erratum_row errata[] = {
    // E-J1939-1: 37h's row is labelled "Set startup LED show"; 34h is that command.
    {"E-J1939-1", complete, "18EF2100#041B3702FFFFFFFF", management_cmd(true)},
    {"E-J1939-1", complete, "18EF2100#041B3400FFFFFFFF", show_cmd(startup_show::disabled)},
    // E-J1939-1: PKP2600SI 26, 7Dh "sets the default value of the backlight": its colour.
    {"E-J1939-1", complete, "18EF2100#041B7D02FFFFFFFF", colour_cmd(backlight_colour::green)},
    // E-J1939-2: four characters and 00h as the table says, five as the examples print.
    {"E-J1939-2", complete, "18EFFF21#041B2A56322E3130", revision("V2.10")},
    {"E-J1939-2", complete, "18EFFF21#041B2A56322E3100", revision("V2.1")},
    // E-J1939-3: the codes as sent, Fh where the examples fill LEDs they do not mean.
    {"E-J1939-3", m1600si, "18A62100#005FFFFFFFFFFFFF", leds(2, "00F5FF")},
    {"E-J1939-3", m1600si, "18A72100#1101FFFFFFFFFFFF", leds(1, "1110FF")},
};
constexpr bool erratum_holds(const erratum_row& r) {
    const auto f = frame_of(r.frame);
    return for_models(r.models, [&](model m) {
        const auto d = decode(f, m);
        return d && *d == r.expected && encode(m, r.expected) == powerkey::result<can::frame>{f};
    });
}
static_assert(
    powerkey_tests::all_rows_pass<first_failing(errata, erratum_holds), std::size(errata)>);
// E-J1939-2: the revision's characters are those before the first 00h.
static_assert(std::get<software_revision>(*decode(frame_of("18EFFF21#041B2A56322E3130"),
                                                  model::pkp1600si))
                  .length() == 5);
static_assert(std::get<software_revision>(*decode(frame_of("18EFFF21#041B2A56312E3300"),
                                                  model::pkp2600si))
                  .length() == 4);
// E-J1939-3: with the example before it ("LED #1,2,3 red ON"), TABLE 3 lights LEDs 1 and 2 red,
// blinks LED 3 red and lights LED 4 cyan; the Fh fill leaves LEDs 5 and 6 undefined (Fh/Fh).
constexpr bool ycyan() {
    const auto one =
        std::get<multiple_leds>(*decode(frame_of("18A72100#1101FFFFFFFFFFFF"), model::pkp1600si));
    const auto two =
        std::get<multiple_leds>(*decode(frame_of("18A62100#005FFFFFFFFFFFFF"), model::pkp1600si));
    return combine(one, two, 1) == led_look{led_mode::on, lc::red, lc::off, true} &&
           combine(one, two, 3) == led_look{led_mode::blink, lc::red, lc::off, true} &&
           combine(one, two, 4) == led_look{led_mode::on, lc::cyan, lc::off, true} &&
           combine(one, two, 5).defined == false && combine(one, two, 6).defined == false;
}
static_assert(ycyan());
// The multiple-LED frame's data word (section 7b): LED k's code in bits 4(k-1)..4k-1, LEDs 1..16,
// each alone; a code set again replaces the old one; numbers outside 1..16 change nothing; the
// LEDs of a set get a code and the others that had it lose it.
constexpr bool nibbles_led_by_led() {
    for (unsigned k = 1; k <= 16; ++k) {
        multiple_leds m;
        m.set(k, 0xA);
        if (m.word() != std::uint64_t{0xA} << (4 * (k - 1)) || m.code_of(k) != 0xA) return false;
        m.set(k, 0x5);
        if (m.word() != std::uint64_t{0x5} << (4 * (k - 1)) ||
            m.leds_of(0x5) != powerkey::led_set{k})
            return false;
    }
    multiple_leds m;
    m.set(0, 1).set(17, 1);
    if (m.word() != 0) return false;
    m.set_leds(2, powerkey::led_set{1, 16});
    m.set_leds(3, powerkey::led_set{2});
    m.set_leds(2, powerkey::led_set{3});
    return m.word() == 0x0000'0000'0000'0230u && m.leds_of(2) == powerkey::led_set{3} &&
           m.leds_of(3) == powerkey::led_set{2};
}
static_assert(nibbles_led_by_led());
// E-J1939-4: the CANopen -> J1939 switch of section 27 is printed with five bytes (E-PK-10,
// E-SI-7): strictly refused; read tolerantly it is the 8-byte write, trimmed (a keypad switches
// on it: docs/errata.md).
static_assert(powerkey::decode(frame_of("615#2BFF200101"), 0x15, model::pkp2600si,
                               powerkey::reading::strict) == errc::wrong_length);
static_assert(powerkey::form_of(*powerkey::decode(frame_of("615#2BFF200101"), 0x15,
                                                  model::pkp2600si)) ==
              powerkey::frame_form::trimmed);
static_assert(
    powerkey::decode(frame_of("615#2BFF200101000000"), 0x15, model::pkp2600si).has_value());

// TABLE 3 (section 7b), row by row, and codes_for as its inverse.
struct table3_row {
    std::uint8_t c1, c2;
    led_look look;
};
constexpr table3_row table3[] = {
    {0x0, 0x0, {led_mode::off, lc::off, lc::off, true}},
    {0x1, 0x0, {led_mode::on, lc::red, lc::off, true}},
    {0x0, 0x9, {led_mode::on, lc::yellow_green, lc::off, true}},
    {0x2, 0x2, {led_mode::alternate_blink, lc::green, lc::green, true}},
    {0x4, 0x5, {led_mode::alternate_blink, lc::yellow, lc::cyan, true}},
    {0x3, 0xF, {led_mode::blink, lc::blue, lc::off, true}},
    {0xF, 0x7, {led_mode::blink, lc::white, lc::off, true}},
    {0xF, 0x0, {led_mode::off, lc::off, lc::off, false}},
    {0x0, 0xF, {led_mode::off, lc::off, lc::off, false}},
    {0xF, 0xF, {led_mode::off, lc::off, lc::off, false}},
    {0xA, 0x0, {led_mode::off, lc::off, lc::off, false}},
    {0x1, 0xE, {led_mode::off, lc::off, lc::off, false}},
};
constexpr bool table3_holds() {
    for (const auto& r : table3) {
        if (!(combine(r.c1, r.c2) == r.look)) return false;
        if (!r.look.defined) continue;
        const auto back = codes_for(r.look.mode, r.look.colour, r.look.secondary);
        if (!back || !(combine(back->colour_1, back->colour_2) == r.look)) return false;
    }
    return !codes_for(led_mode::on, lc::off, lc::off) &&
           !codes_for(led_mode::alternate_blink, lc::red, lc::not_used) &&
           codes_for(led_mode::off, lc::red, lc::red) == code_pair{};
}
static_assert(table3_holds());

// Every pair of codes 0h..Fh, and every look of every mode, colour and secondary colour 0..15:
// a defined look comes back from its codes; codes_for gives codes exactly for a colour (and, to
// alternate, a secondary colour) in 1h..9h, and those codes show the look asked for.
constexpr bool every_code_pair_and_look() {
    for (unsigned c1 = 0; c1 < 16; ++c1) {
        for (unsigned c2 = 0; c2 < 16; ++c2) {
            const led_look look =
                combine(static_cast<std::uint8_t>(c1), static_cast<std::uint8_t>(c2));
            if (!look.defined) continue;
            const auto back = codes_for(look.mode, look.colour, look.secondary);
            if (!back || !(combine(back->colour_1, back->colour_2) == look)) return false;
        }
    }
    for (const led_mode mode : {led_mode::on, led_mode::blink, led_mode::alternate_blink}) {
        for (unsigned c = 0; c < 16; ++c) {
            for (unsigned s2 = 0; s2 < 16; ++s2) {
                const auto colour = static_cast<lc>(c), secondary = static_cast<lc>(s2);
                const auto codes = codes_for(mode, colour, secondary);
                const bool valid =
                    c >= 1 && c <= 9 && (mode != led_mode::alternate_blink || (s2 >= 1 && s2 <= 9));
                if (codes.has_value() != valid) return false;
                if (!codes) continue;
                const led_look look = combine(codes->colour_1, codes->colour_2);
                if (!look.defined || look.mode != mode || look.colour != colour) return false;
                if (mode == led_mode::alternate_blink && look.secondary != secondary) return false;
            }
        }
    }
    return true;
}
static_assert(every_code_pair_and_look());

// encode never builds a frame decode refuses, nor one that decodes to another message: run for
// every model over raw field values (fuzz/j1939.cpp does the same with arbitrary bytes).
constexpr bool encodes_back(model m, const j1939_rows::message& msg, keypad_address k = {}) {
    const auto f = encode(m, msg, k);
    if (!f) return f.error() != errc{};
    const auto d = decode(*f, m, k);
    return d && *d == msg;
}

// encode checks the message's own fields (detail::own_check): the same answer as building the
// frame field by field and reading it back with the whole decoder (the frame, or decode's error,
// or value_out_of_range when it reads as another message).
template <class T>
constexpr powerkey::result<can::frame> encode_by_decode(model m, const T& msg, keypad_address k) {
    if (!powerkey::j1939::detail::is_j1939_model(m)) return errc::value_out_of_range;
    const can::frame f =
        powerkey::j1939::detail::build(powerkey::j1939::detail::j1939_row_of(m), msg);
    const auto d = decode(f, m, k);
    if (!d) return d.error();
    const T* same = std::get_if<T>(&*d);
    if (same == nullptr || !(*same == msg)) return errc::value_out_of_range;
    return f;
}
template <class T>
bool encodes_as_by_decode(model m, const T& msg) {
    for (const keypad_address k :
         {keypad_address{}, keypad_address{0x21}, keypad_address{0x00}, keypad_address{0xFF}}) {
        if (!(encode(m, msg, k) == encode_by_decode(m, msg, k))) return false;
        if (!(encode(m, j1939_rows::message(msg), k) == encode_by_decode(m, msg, k))) return false;
    }
    return true;
}

// decode_key_or_led answers as decode for the frames of command 01h; another 29-bit frame is
// wrong_id (after decode's own refusals of its identifier and length), an 11-bit one
// wrong_id_format.
constexpr bool key_or_led_agrees(const can::frame& f, model m, keypad_address k) {
    const auto narrow = decode_key_or_led(f, m, k);
    const auto whole = decode(f, m, k);
    if (!f.is_extended()) return narrow == errc::wrong_id_format;
    if (((f.raw_id() >> 16) & 0x3FF) != 0xEF) return narrow == errc::wrong_id;
    if (f.size() != 8 || f[0] != 0x04 || f[1] != 0x1B || f[2] != 0x01) {
        if (!whole && (whole.error() == errc::wrong_id || whole.error() == errc::wrong_length))
            return narrow == whole.error();
        return narrow == errc::wrong_id;
    }
    if (!whole) return narrow == whole.error();
    return std::visit(
        [&narrow](const auto& v) {
            using T = std::remove_cvref_t<decltype(v)>;
            if constexpr (std::is_same_v<T, key_contact> || std::is_same_v<T, set_led> ||
                          std::is_same_v<T, set_led_code>) {
                const T* same = narrow ? std::get_if<T>(&*narrow) : nullptr;
                return same != nullptr && *same == v;
            } else {
                return false;
            }
        },
        *whole);
}
template <class Row>
constexpr bool key_or_led_row(const Row& r) {
    const auto f = powerkey::can::parse_candump(r.frame);
    if (!f) return false;
    return for_models(r.models, [&](model m) {
        return key_or_led_agrees(*f, m, {}) && key_or_led_agrees(*f, m, keypad_address{0x21});
    });
}
static_assert(
    powerkey_tests::all_rows_pass<first_failing(pkp2600si_rows, key_or_led_row<j1939_rows::row>),
                                  std::size(pkp2600si_rows)>);
}  // namespace

// Every member a command's row names (fields()), but its code and route, set from v: a bool to
// v's low bit, a byte to v, an enum to its low nibble, a checked level to its low 6 bits.
static void set_row_members(command& c, unsigned v) {
    command::fields(c, [&](std::string_view name, auto& field) {
        using T = std::remove_cvref_t<decltype(field)>;
        if (name == "command" || name == "priority" || name == "destination" || name == "source")
            return;
        if constexpr (std::is_same_v<T, bool>)
            field = (v & 1) != 0;
        else if constexpr (std::is_same_v<T, std::uint8_t>)
            field = static_cast<std::uint8_t>(v);
        else if constexpr (std::is_enum_v<T>)
            field = static_cast<T>(v & 0xF);
        else
            field = T::make(v & 0x3F).value();
    });
}

TEST_CASE("j1939: decode_key_or_led answers as decode on every row, wrong_id off command 01h") {
    check_rows(pkp1600si_rows, key_or_led_row<j1939_rows::row>);
    check_rows(pkp2600si_rows, key_or_led_row<j1939_rows::row>);
    check_rows(other_rows, key_or_led_row<j1939_rows::row>);
    check_rows(error_rows, key_or_led_row<j1939_rows::error_row>);
}

TEST_CASE("j1939: encode of a command 01h message answers as reading its frame back with decode") {
    for (std::size_t i = 0; i < model_row_count; ++i) {
        const auto m = static_cast<model>(i);
        CAPTURE(i);
        for (unsigned key = 0; key <= 18; ++key) {
            const auto k8 = static_cast<std::uint8_t>(key);
            for (unsigned c = 0; c <= 0x10; ++c) {
                const auto colour = static_cast<lc>(c == 0x10 ? 0xFF : c);
                for (const std::uint8_t to :
                     {std::uint8_t{0x21}, std::uint8_t{0xFF}, std::uint8_t{0x00}}) {
                    for (unsigned mode = 0; mode <= 4; ++mode) {
                        const auto md = static_cast<led_mode>(mode);
                        for (const lc second : {lc::off, lc::red, lc::yellow_green, lc::not_used,
                                                static_cast<lc>(0x0A)})
                            CHECK(encodes_as_by_decode(m, set_led{.source = 0x00,
                                                                  .destination = to,
                                                                  .priority = 6,
                                                                  .key = k8,
                                                                  .colour = colour,
                                                                  .mode = md,
                                                                  .secondary = second}));
                        CHECK(encodes_as_by_decode(
                            m, key_contact{.source = 0x21,
                                           .destination = to,
                                           .priority = 6,
                                           .key = k8,
                                           .pressed = mode == 1,
                                           .identifier = static_cast<std::uint8_t>(c * 16)}));
                    }
                    CHECK(encodes_as_by_decode(m,
                                               set_led_code{.source = 0x00,
                                                            .destination = to,
                                                            .priority = 6,
                                                            .key = k8,
                                                            .code = static_cast<std::uint8_t>(c)}));
                }
            }
        }
    }
}

TEST_CASE("j1939: encode of every other message answers as reading its frame back with decode") {
    const std::uint8_t addresses[] = {0x21, 0xFF, 0x00, 0x05};
    for (std::size_t i = 0; i < model_row_count; ++i) {
        const auto m = static_cast<model>(i);
        CAPTURE(i);
        for (const std::uint8_t to : addresses) {
            for (const std::uint8_t from : addresses) {
                CAPTURE(unsigned{to});
                CAPTURE(unsigned{from});
                for (unsigned bit = 0; bit <= 17; ++bit) {
                    const key_set keys = key_set::from_mask((std::uint64_t{1} << bit) >> 1);
                    CHECK(encodes_as_by_decode(m, heartbeat{.source = from,
                                                            .destination = to,
                                                            .priority = 5,
                                                            .counter = 7,
                                                            .keys = keys,
                                                            .identifier = 0x21}));
                }
                CHECK(encodes_as_by_decode(m, heartbeat{.source = from,
                                                        .destination = to,
                                                        .priority = 6,
                                                        .counter = 0,
                                                        .keys = key_set::from_mask(0x1'0001),
                                                        .identifier = 0xFF}));
                for (const std::string_view text :
                     {"V2.10", "V2.1", "", "\x1F", "\x7F", "ab\0c", "\xFF\xFF\xFF\xFF\xFF",
                      "\xFF\xFF\xFF\xFF\xFE", "V2.1\xFF"}) {
                    software_revision v{
                        .source = from, .destination = to, .priority = 6, .bytes = {}};
                    for (std::size_t b = 0; b < text.size() && b < 5; ++b)
                        v.bytes[b] = static_cast<std::uint8_t>(text[b]);
                    CHECK(encodes_as_by_decode(m, v));
                }
                for (unsigned key = 0; key <= 17; key += 1) {
                    const auto k8 = static_cast<std::uint8_t>(key);
                    for (unsigned mode : {0u, 1u, 3u, 4u, 0xFFu}) {
                        const auto md = static_cast<led_mode>(mode);
                        for (const lc c : {lc::off, lc::red, lc::yellow_green,
                                           static_cast<lc>(0x0A), lc::not_used}) {
                            CHECK(encodes_as_by_decode(m, led_ack{.source = from,
                                                                  .destination = to,
                                                                  .priority = 6,
                                                                  .mode = md,
                                                                  .key = k8,
                                                                  .colour = c,
                                                                  .secondary = c}));
                            CHECK(encodes_as_by_decode(m, led_ack{.source = from,
                                                                  .destination = to,
                                                                  .priority = 6,
                                                                  .mode = md,
                                                                  .key = k8,
                                                                  .colour = lc::blue,
                                                                  .secondary = lc::not_used}));
                        }
                    }
                    for (const unsigned code : {0x00u, 0x05u, 0xFFu})
                        CHECK(encodes_as_by_decode(
                            m, led_ack_code{.source = from,
                                            .destination = to,
                                            .priority = 6,
                                            .key = k8,
                                            .code = static_cast<std::uint8_t>(code)}));
                }
                address_claimed claim{.source = from, .destination = to, .priority = 6, .name = {}};
                claim.name.function = 0x81;
                claim.name.arbitrary_address_capable = true;
                CHECK(encodes_as_by_decode(m, claim));
                switch_to_canopen back{6, to, from};
                CHECK(encodes_as_by_decode(m, back));
                back.form = powerkey::frame_form::trimmed;
                CHECK(encodes_as_by_decode(m, back));
                for (std::uint64_t n = 0; n < 0x1'0000'0000; n += 0x1234'5679) {
                    multiple_leds l{.source = from,
                                    .destination = to,
                                    .priority = 6,
                                    .frame = 1,
                                    .nibbles = multiple_leds::halves(n * 0x1'0001)};
                    CHECK(encodes_as_by_decode(m, l));
                    l.frame = 2;
                    l.nibbles[1] = 0;
                    CHECK(encodes_as_by_decode(m, l));
                }
                // Each LED's code alone at every value, the others 0h: codes Ah..Eh and a code
                // past the model's LEDs refused, as the decoder refuses their frame.
                for (unsigned k = 0; k < 16; ++k)
                    for (std::uint64_t code = 0; code < 16; ++code) {
                        CAPTURE(k);
                        CAPTURE(code);
                        const multiple_leds l{.source = from,
                                              .destination = to,
                                              .priority = 6,
                                              .frame = 1,
                                              .nibbles = multiple_leds::halves(code << (4 * k))};
                        CHECK(encodes_as_by_decode(m, l));
                    }
            }
        }
        // The commands over four routes (to the keypad, to every address, from the keypad to
        // another, from it to itself): every code byte, every fifth parameter value, and a member
        // the command's row may not carry set.
        const std::uint8_t routes[][2] = {{0x21, 0x00}, {0xFF, 0x00}, {0x05, 0x21}, {0x21, 0x21}};
        for (const auto& route : routes) {
            for (unsigned code = 0; code < 0x100; ++code) {
                CAPTURE(unsigned{route[0]});
                CAPTURE(unsigned{route[1]});
                CAPTURE(code);
                bool same = true;
                for (unsigned v = 0; v < 0x100; v += 5) {
                    command c = cmd(static_cast<cc>(code));
                    c.destination = route[0];
                    c.source = route[1];
                    set_row_members(c, v);
                    same = same && encodes_as_by_decode(m, c);
                    c.identifier = static_cast<std::uint8_t>(v ^ 0x40);  // maybe not its own
                    same = same && encodes_as_by_decode(m, c);
                }
                CHECK(same);
            }
        }
    }
}

TEST_CASE("j1939: every example of the PKP1600SI J1939 manual both ways") {
    check_rows(pkp1600si_rows, round_trips);
}

TEST_CASE("j1939: every example of the PKP2600SI J1939 manual both ways") {
    check_rows(pkp2600si_rows, round_trips);
}

TEST_CASE("j1939: the other models' frames (reference, inferred where marked)") {
    check_rows(other_rows, round_trips);
}

// The keypad a message is of: what the keypad sends names it as its source, what it is sent as its
// destination; every manual row's is the keypad's address when the frame was sent.
constexpr bool names_its_keypad(std::span<const j1939_rows::row> rows) {
    for (const auto& r : rows)
        if (std::visit([](const auto& v) { return keypad_address_of(v); }, r.expected) != r.keypad)
            return false;
    return true;
}
static_assert(names_its_keypad(pkp1600si_rows) && names_its_keypad(pkp2600si_rows) &&
              names_its_keypad(other_rows));
static_assert(sent_by_keypad<key_contact> && sent_by_keypad<address_claimed> &&
              !sent_by_keypad<set_led> && !sent_by_keypad<switch_to_canopen>);

TEST_CASE("j1939: the decoder's refusals") { check_rows(error_rows, refused); }

TEST_CASE("j1939: the encoder's refusals") { check_rows(encode_error_rows, encode_refused); }

TEST_CASE("j1939: errata decisions (docs/errata.md, ## J1939) and TABLE 3") {
    check_rows(errata, erratum_holds);
    CHECK(ycyan());
    CHECK(table3_holds());
    CHECK(powerkey::decode(frame_of("615#2BFF200101"), 0x15, model::pkp2600si,
                           powerkey::reading::strict) == errc::wrong_length);
}

TEST_CASE("j1939: direction of 01h and 2Ah, and narrowing to one keypad") {
    // Narrowed to 21h, a key contact state sent to 05h (6Eh) round-trips whatever its bytes.
    const key_contact to_05{.source = 0x21,
                            .destination = 0x05,
                            .priority = 6,
                            .key = 1,
                            .pressed = true,
                            .identifier = 0x02};
    const auto f = encode(model::pkp2600si, to_05, std::uint8_t{0x21});
    REQUIRE(f.has_value());
    CHECK(*f == frame_of("18EF0521#041B01010102FFFF"));
    // Not narrowed, the same bytes read as an LED command from 21h to 05h.
    const auto as_led = decode(*f, model::pkp2600si);
    REQUIRE(as_led.has_value());
    CHECK(std::holds_alternative<set_led>(*as_led));
    // A key state with the default identifier is one whatever its destination.
    const auto with_21 = decode(frame_of("18EF0521#041B01010121FFFF"), model::pkp2600si);
    REQUIRE(with_21.has_value());
    CHECK(*with_21 == j1939_rows::message{key_contact{.source = 0x21,
                                                      .destination = 0x05,
                                                      .priority = 6,
                                                      .key = 1,
                                                      .pressed = true,
                                                      .identifier = 0x21}});
    // The revision request and its answer, told apart by bytes 3..7.
    CHECK(std::holds_alternative<command>(
        *decode(frame_of("18EF2100#041B2AFFFFFFFFFF"), model::pkp1600si)));
    CHECK(std::holds_alternative<software_revision>(
        *decode(frame_of("18EFFF21#041B2A56322E3130"), model::pkp1600si)));
    // After 70h 02h the keypad's frames come from 02h: narrowed to 02h they decode, to 21h not.
    const auto moved = frame_of("18EFFF02#041B01010121FFFF");
    CHECK(decode(moved, model::pkp2600si, std::uint8_t{0x02}).has_value());
    CHECK(decode(moved, model::pkp2600si, std::uint8_t{0x21}) == errc::wrong_id);
    // Any priority decodes and is kept.
    const auto p3 = decode(frame_of("0CEF2100#041B0220FFFFFFFF"), model::pkp1600si);
    REQUIRE(p3.has_value());
    constexpr priority three = 3;
    CHECK(std::get<command>(*p3).priority == three);
    CHECK(encode(model::pkp1600si, *p3) ==
          powerkey::result<can::frame>{frame_of("0CEF2100#041B0220FFFFFFFF")});
}

TEST_CASE("j1939: encode refuses or round-trips, over raw field values") {
    for (std::size_t i = 0; i < model_row_count; ++i) {
        const auto m = static_cast<model>(i);
        CAPTURE(i);
        for (unsigned key = 0; key <= 18; ++key) {
            for (unsigned c = 0; c <= 0x10; ++c) {
                const auto k8 = static_cast<std::uint8_t>(key);
                const auto colour = static_cast<lc>(c == 0x10 ? 0xFF : c);
                for (unsigned mode = 0; mode <= 4; ++mode) {
                    const auto md = static_cast<led_mode>(mode);
                    CHECK(encodes_back(m, set_led{.source = 0x00,
                                                  .destination = 0x21,
                                                  .priority = 6,
                                                  .key = k8,
                                                  .colour = colour,
                                                  .mode = md,
                                                  .secondary = colour}));
                    CHECK(encodes_back(m, led_ack{.source = 0x21,
                                                  .destination = 0xFF,
                                                  .priority = 6,
                                                  .mode = md,
                                                  .key = k8,
                                                  .colour = colour,
                                                  .secondary = colour}));
                    CHECK(encodes_back(
                        m, key_contact{.source = 0x21,
                                       .destination = 0xFF,
                                       .priority = 6,
                                       .key = k8,
                                       .pressed = mode == 1,
                                       .identifier = static_cast<std::uint8_t>(c * 16)}));
                }
                CHECK(encodes_back(m, set_led_code{.source = 0x00,
                                                   .destination = 0x21,
                                                   .priority = 6,
                                                   .key = k8,
                                                   .code = static_cast<std::uint8_t>(c)}));
                CHECK(encodes_back(m, led_ack_code{.source = 0x21,
                                                   .destination = 0xFF,
                                                   .priority = 6,
                                                   .key = k8,
                                                   .code = static_cast<std::uint8_t>(c)}));
            }
        }
        for (unsigned code = 0; code < 0x100; ++code) {
            for (unsigned v = 0; v < 0x100; v += 3) {
                command c = cmd(static_cast<cc>(code));
                c.address = static_cast<std::uint8_t>(v);
                c.identifier = static_cast<std::uint8_t>(0xFF - v);
                c.period_10ms = static_cast<std::uint8_t>(v);
                c.enabled = (v & 1) != 0;
                c.level = powerkey::level::make(v & 0x3F).value();
                c.colour = static_cast<backlight_colour>(v & 0xF);
                c.baud = static_cast<baud_rate>(v & 7);
                c.show = static_cast<startup_show>(v & 3);
                c.multiple_leds = (v & 2) != 0;
                CHECK(encodes_back(m, c));
                // Only the members the command's row names.
                command only = cmd(static_cast<cc>(code));
                set_row_members(only, v);
                CHECK(encodes_back(m, only));
            }
        }
        for (std::uint64_t n = 0; n < 0x1'0000'0000; n += 0x1234'5679) {
            multiple_leds l{.source = 0x00,
                            .destination = 0x21,
                            .priority = 6,
                            .frame = 1,
                            .nibbles = multiple_leds::halves(n * 0x1'0001)};
            CHECK(encodes_back(m, l));
            l.frame = 2;
            CHECK(encodes_back(m, l, std::uint8_t{0x21}));
        }
    }
}

TEST_CASE("j1939: a message describes itself through its fields") {
    std::array<char, 200> buf{};
    const auto d = decode(frame_of("18EFFF21#041B01030121FFFF"), model::pkp1600si);
    REQUIRE(d.has_value());
    const auto text = powerkey::describe(*d, 0x15, buf);
    REQUIRE(text.has_value());
    CHECK(*text ==
          "node 15h  J1939 key contact  priority: 6  destination: FFh  source: 21h  key: 3  "
          "pressed: yes  identifier: 21h");
    const auto leds_text = powerkey::describe(
        *decode(frame_of("18A62100#005FFFFFFFFFFFFF"), model::pkp1600si), 0x15, buf);
    REQUIRE(leds_text.has_value());
    CHECK(*leds_text ==
          "node 15h  J1939 multiple leds  priority: 6  destination: 21h  source: 00h  frame: 02h  "
          "red: -  green: -  blue: -  yellow: -  cyan: 4  violet: -  white: -  amber: -  "
          "yellow_green: -  blink: 3 5 6");
}

// --- every parameter byte of every J1939 command, every reserved byte's bits -----------------
// Walked from the command table for every J1939 model: each configuration command (EF00h, 04h 1Bh
// code p1 p2, then FFh) with each parameter at every byte, accepted exactly when the manuals'
// range of the parameter's kind holds (below; PKP2600SI J1939 and PKP1600SI J1939 manuals,
// sections 8-27), else value_out_of_range; each bit of each byte after the parameters cleared
// alone: reserved_not_ff. A command the model's manuals lack is unknown_command, one no source
// shows on it undocumented, whatever its bytes.
namespace {
namespace pj = powerkey::j1939;
using jp = pj::command_param;
using powerkey::errc;
// The manuals' range of a parameter's byte; `p1` the command's first byte (the heartbeat's
// FFh is taken only when it is switched off).
constexpr bool j1939_param_accepts(jp p, unsigned b, unsigned p1) {
    switch (p) {
        case jp::none: return b == 0xFF;
        case jp::level: return b <= 0x3F;
        case jp::flag: return b <= 1;
        case jp::show: return b <= 2;
        case jp::management: return b == 0 || b == 2;
        case jp::destination: return b != 0xFE;
        case jp::baud: return b == 2 || b == 3;
        case jp::source: return (b >= 1 && b <= 0xFD) || b == 0xFF;
        case jp::identifier: return b != 0xFE;
        case jp::period: return b >= 0x05 && b <= 0xFE;
        case jp::heartbeat_time: return (b >= 0x05 && b <= 0xFE) || (b == 0xFF && p1 == 0);
        case jp::colour: return b >= 1 && b <= 9;
    }
    return false;
}
constexpr unsigned j1939_lowest(jp p) {
    for (unsigned b = 0; b < 0x100; ++b)
        if (j1939_param_accepts(p, b, 0)) return b;
    return 0xFF;
}
can::frame config_frame(unsigned code, unsigned p1, unsigned p2, unsigned cleared_bit = 64) {
    std::uint64_t w = 0xFFFF'FFFF'FFFF'FFFFu;
    w = (w & ~std::uint64_t{0xFF'FFFF'FFFF}) | 0x04 | 0x1B << 8 | std::uint64_t{code} << 16 |
        std::uint64_t{p1} << 24 | std::uint64_t{p2} << 32;
    if (cleared_bit < 64) w &= ~(std::uint64_t{1} << cleared_bit);
    can::payload p{};
    for (std::size_t i = 0; i < 8; ++i) p[i] = static_cast<std::uint8_t>(w >> (8 * i));
    return can::frame(can::extended_id::make(0x18EF'2100).value(), can::dlc::make(8).value(), p);
}
}  // namespace

TEST_CASE("TABLE 3: every pair of codes and every look of every colour") {
    CHECK(every_code_pair_and_look());
}

TEST_CASE("every parameter byte of every J1939 command and every reserved bit, in every model") {
    std::size_t walked = 0;
    for (std::size_t i = 0; i < pj::model_row_count; ++i) {
        const auto m = static_cast<powerkey::model>(i);
        const auto r = *pj::row(m);
        CAPTURE(i);
        for (unsigned code = 0; code < 0x100; ++code) {
            const auto* row = pj::find_command(static_cast<std::uint8_t>(code));
            if (row == nullptr || code == 0x2A) continue;  // 2Ah: the revision request and answer
            CAPTURE(code);
            const auto cov = r.frames.of(row->what);
            const unsigned v1 = j1939_lowest(row->p1), v2 = j1939_lowest(row->p2);
            if (cov == pj::coverage::absent || cov == pj::coverage::unknown) {
                CHECK(pj::decode(config_frame(code, v1, v2), m) ==
                      (cov == pj::coverage::absent ? errc::unknown_command : errc::undocumented));
                continue;
            }
            ++walked;
            if (row->p1 != jp::none) {
                for (unsigned b = 0; b < 0x100; ++b) {
                    CAPTURE(b);
                    // the second parameter at a byte valid whatever the first is
                    const unsigned other = row->p2 == jp::heartbeat_time ? 0x05 : v2;
                    const auto got = pj::decode(config_frame(code, b, other), m);
                    if (j1939_param_accepts(row->p1, b, 0))
                        CHECK(got.has_value());
                    else
                        CHECK(got == errc::value_out_of_range);
                }
            }
            if (row->p2 != jp::none) {
                for (unsigned b = 0; b < 0x100; ++b) {
                    CAPTURE(b);
                    const auto got = pj::decode(config_frame(code, v1, b), m);
                    if (j1939_param_accepts(row->p2, b, v1))
                        CHECK(got.has_value());
                    else
                        CHECK(got == errc::value_out_of_range);
                }
            }
            const unsigned used = row->p1 == jp::none   ? 3
                                  : row->p2 == jp::none ? 4
                                                        : 5;  // bytes up to the params
            for (unsigned bit = 8 * used; bit < 64; ++bit) {
                CAPTURE(bit);
                CHECK(pj::decode(config_frame(code, v1, v2, bit), m) == errc::reserved_not_ff);
            }
        }
    }
    CHECK(walked >= 20);
}

// The LED command (7a) and the LED acknowledgement (19) of the SI form, every byte of each field:
// colour 00h..09h, state 00h..03h, secondary colour 00h..09h or FFh, an LED the model has; any
// other byte value_out_of_range. The command's byte 6 FFh reads as a key contact state where the
// other bytes allow it (the command is told by byte 6), so the command's secondary is walked to
// FEh.
TEST_CASE("every byte of the SI-form LED command and acknowledgement, in every J1939 model") {
    namespace pj = powerkey::j1939;
    using powerkey::errc;
    const auto frame = [](std::uint32_t id, std::uint64_t w) {
        can::payload p{};
        for (std::size_t i = 0; i < 8; ++i) p[i] = static_cast<std::uint8_t>(w >> (8 * i));
        return can::frame(can::extended_id::make(id).value(), can::dlc::make(8).value(), p);
    };
    const auto bytes = [](std::initializer_list<unsigned> b) {
        std::uint64_t w = 0;
        unsigned i = 0;
        for (const unsigned x : b) w |= std::uint64_t{x} << (8 * i++);
        return w;
    };
    std::size_t walked = 0;
    for (std::size_t i = 0; i < pj::model_row_count; ++i) {
        const auto m = static_cast<powerkey::model>(i);
        const auto r = *pj::row(m);
        if (r.form != pj::led_form::si) continue;
        CAPTURE(i);
        const bool command = r.frames.has(pj::feature::led_command);
        const bool ack = r.frames.has(pj::feature::led_ack);
        unsigned led = 0;
        for (unsigned k = 1; k <= 16 && led == 0; ++k)
            if (((r.leds >> (k - 1)) & 1u) != 0) led = k;
        if (led == 0) continue;
        ++walked;
        for (unsigned b = 0; b < 0x100; ++b) {
            CAPTURE(b);
            // to the keypad: 04h 1Bh 01h, LED, colour, state, secondary, FFh
            if (command) {
                const auto at = [&](unsigned c, unsigned s, unsigned s2) {
                    return pj::decode(
                        frame(0x18EF'2100, bytes({0x04, 0x1B, 0x01, led, c, s, s2, 0xFF})), m);
                };
                const auto colour = at(b, 1, 0);
                CHECK((colour.has_value() ? errc{} : colour.error()) ==
                      (b <= 9 ? errc{} : errc::value_out_of_range));
                const auto state = at(1, b, 0);
                CHECK((state.has_value() ? errc{} : state.error()) ==
                      (b <= 3 ? errc{} : errc::value_out_of_range));
                if (b != 0xFF) {
                    const auto secondary = at(1, 3, b);
                    CHECK((secondary.has_value() ? errc{} : secondary.error()) ==
                          (b <= 9 ? errc{} : errc::value_out_of_range));
                }
            }
            // from the keypad: 00h, state, LED, colour, secondary, FFh FFh FFh
            if (ack) {
                const auto at = [&](unsigned s, unsigned c, unsigned s2) {
                    return pj::decode(
                        frame(0x18EF'FF21, bytes({0x00, s, led, c, s2, 0xFF, 0xFF, 0xFF})), m);
                };
                const auto state = at(b, 1, 0);
                CHECK((state.has_value() ? errc{} : state.error()) ==
                      (b <= 3 ? errc{} : errc::value_out_of_range));
                const auto colour = at(1, b, 0);
                CHECK((colour.has_value() ? errc{} : colour.error()) ==
                      (b <= 9 ? errc{} : errc::value_out_of_range));
                const auto secondary = at(3, 1, b);
                CHECK((secondary.has_value() ? errc{} : secondary.error()) ==
                      (b <= 9 || b == 0xFF ? errc{} : errc::value_out_of_range));
            }
        }
    }
    CHECK(walked >= 2);
}

// The software revision's answer (11): each of its five bytes at every value: printable ASCII
// 20h..7Eh, or 00h to end the text (after which only 00h); anything else value_out_of_range.
TEST_CASE("every byte of each character of the software revision's answer") {
    namespace pj = powerkey::j1939;
    using powerkey::errc;
    for (unsigned at = 0; at < 5; ++at) {
        for (unsigned b = 0; b < 0x100; ++b) {
            if (b == 0xFF) continue;  // five FFh bytes are the request
            CAPTURE(at);
            CAPTURE(b);
            can::payload p{0x04, 0x1B, 0x2A, 'V', '2', '.', '1', '0'};
            p[3 + at] = static_cast<std::uint8_t>(b);
            const auto got = pj::decode(can::frame(can::extended_id::make(0x18EF'FF21).value(),
                                                   can::dlc::make(8).value(), p),
                                        powerkey::model::pkp1600si);
            // 00h ends the text: the bytes after it must be 00h too (only the last may be 00h here)
            const bool ok = (b >= 0x20 && b <= 0x7E) || (b == 0 && at == 4);
            CHECK((got.has_value() ? errc{} : got.error()) ==
                  (ok ? errc{} : errc::value_out_of_range));
            if (got) CHECK(std::get<pj::software_revision>(*got).length() == (b == 0 ? 4u : 5u));
        }
    }
}

// The switch back to CANopen (27): 04h 1Bh 80h 00h, then FFh; byte 3 at every other value is
// value_out_of_range, each bit of bytes 4..7 cleared alone reserved_not_ff.
TEST_CASE("every byte 3 and every reserved bit of the switch back to CANopen") {
    namespace pj = powerkey::j1939;
    using powerkey::errc;
    const auto at = [](std::uint64_t w) {
        can::payload p{};
        for (std::size_t i = 0; i < 8; ++i) p[i] = static_cast<std::uint8_t>(w >> (8 * i));
        return pj::decode(
            can::frame(can::extended_id::make(0x18EF'2100).value(), can::dlc::make(8).value(), p),
            powerkey::model::pkp2600si);
    };
    const std::uint64_t manual = 0xFFFF'FFFF'0080'1B04u;
    REQUIRE(at(manual).has_value());
    for (unsigned b = 1; b < 0x100; ++b) {
        CAPTURE(b);
        CHECK(at(manual | std::uint64_t{b} << 24) == errc::value_out_of_range);
    }
    for (unsigned bit = 32; bit < 64; ++bit) {
        CAPTURE(bit);
        CHECK(at(manual & ~(std::uint64_t{1} << bit)) == errc::reserved_not_ff);
    }
}

// The decoder answers the frequent frames in place and sends the others through every check in
// decode's order (j1939::detail::decode_frame): the two must agree on every frame. Each kind of
// frame of the rows (manual examples, other models, refusals) and of the bench's J1939 mixed log,
// to the global address and to the keypad's, with every value of each data byte in turn, in every
// model; each answer is also checked against the checks alone.
TEST_CASE("j1939: the fast path answers as the checks in order, every byte of every frame kind") {
    namespace pj = powerkey::j1939;
    std::vector<can::frame> kinds;
    const auto add = [&kinds](std::string_view text) {
        const can::frame f = frame_of(text);
        for (const can::frame& k : kinds)
            if (k.raw_id() == f.raw_id() && k.size() == f.size() &&
                (k.data_le() & 0xFF'FFFF) == (f.data_le() & 0xFF'FFFF))
                return;
        kinds.push_back(f);
    };
    for (const auto& r : pkp1600si_rows) add(r.frame);
    for (const auto& r : pkp2600si_rows) add(r.frame);
    for (const auto& r : other_rows) add(r.frame);
    for (const auto& r : error_rows) add(r.frame);
    for (const auto text :
         {"18EF2100#041B0101010100FF", "18EFFF21#0001010100FFFFFF", "18A72100#110100000000FFFF",
          "18A62100#000000000096FFFF", "0CF00400#FF7D7DE015FFF0FF", "18EAFF00#00EE00"})
        add(text);
    REQUIRE(kinds.size() >= 40);
    std::size_t decoded = 0, compared = 0;
    for (std::size_t i = 0; i <= pj::model_row_count; ++i) {
        const auto m = static_cast<powerkey::model>(i);
        for (const can::frame& kind : kinds) {
            for (const std::uint32_t destination : {0xFFu, 0x21u}) {
                // An 11-bit frame keeps its identifier (wrong_id_format either way).
                const std::uint32_t id = kind.is_extended()
                                             ? (kind.raw_id() & ~0xFF00u) | (destination << 8)
                                             : kind.raw_id();
                for (std::size_t at = 0; at < kind.size(); ++at) {
                    for (unsigned v = 0; v < 0x100; ++v) {
                        can::payload p = kind.bytes();
                        p[at] = static_cast<std::uint8_t>(v);
                        const auto length = can::dlc::make(kind.size()).value();
                        const can::frame f =
                            kind.is_extended()
                                ? can::frame(can::extended_id::make(id).value(), length, p)
                                : can::frame(can::standard_id::make(id).value(), length, p);
                        const auto fast = pj::decode(f, m);
                        const auto checked =
                            pj::detail::decode_checked_only<pj::message>(f, m, std::nullopt);
                        ++compared;
                        if (fast) ++decoded;
                        if (fast == checked) continue;
                        CAPTURE(i);
                        const std::string text(can::format_candump(f).view());
                        CAPTURE(text);
                        CHECK(fast == checked);
                    }
                }
            }
        }
    }
    CHECK(decoded > compared / 40);  // the walk reaches decodable frames, not only refusals
}
