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
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

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

// encode never builds a frame decode refuses, nor one that decodes to another message: run for
// every model over raw field values (fuzz/j1939.cpp does the same with arbitrary bytes).
constexpr bool encodes_back(model m, const j1939_rows::message& msg, keypad_address k = {}) {
    const auto f = encode(m, msg, k);
    if (!f) return f.error() != errc{};
    const auto d = decode(*f, m, k);
    return d && *d == msg;
}
}  // namespace

TEST_CASE("j1939: every example of the PKP1600SI J1939 manual both ways") {
    check_rows(pkp1600si_rows, round_trips);
}

TEST_CASE("j1939: every example of the PKP2600SI J1939 manual both ways") {
    check_rows(pkp2600si_rows, round_trips);
}

TEST_CASE("j1939: the other models' frames (reference, inferred where marked)") {
    check_rows(other_rows, round_trips);
}

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
    const key_contact to_05{6, 0x05, 0x21, 1, true, 0x02};
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
    CHECK(*with_21 == j1939_rows::message{key_contact{6, 0x05, 0x21, 1, true, 0x21}});
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
                    CHECK(encodes_back(m, set_led{6, 0x21, 0x00, k8, colour, md, colour}));
                    CHECK(encodes_back(m, led_ack{6, 0xFF, 0x21, k8, md, colour, colour}));
                    CHECK(encodes_back(m, key_contact{6, 0xFF, 0x21, k8, mode == 1,
                                                      static_cast<std::uint8_t>(c * 16)}));
                }
                CHECK(
                    encodes_back(m, set_led_code{6, 0x21, 0x00, k8, static_cast<std::uint8_t>(c)}));
                CHECK(
                    encodes_back(m, led_ack_code{6, 0xFF, 0x21, k8, static_cast<std::uint8_t>(c)}));
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
                command::fields(only, [&](std::string_view name, auto& field) {
                    using T = std::remove_cvref_t<decltype(field)>;
                    if (name == "command" || name == "priority" || name == "destination" ||
                        name == "source")
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
                CHECK(encodes_back(m, only));
            }
        }
        for (std::uint64_t n = 0; n < 0x1'0000'0000; n += 0x1234'5679) {
            multiple_leds l{6, 0x21, 0x00, 1, multiple_leds::halves(n * 0x1'0001)};
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
