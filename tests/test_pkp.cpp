// The PKP-2200/2400/2600 profile: every example frame of the PKP manual and the PKP-2600 rows of
// the reference, both ways, for each model a row applies to (tests/pkp_rows.hpp).
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/pkp/profile.hpp>

#include <cstddef>
#include <string_view>
#include <utility>

#include "pkp_rows.hpp"

namespace {
using namespace powerkey;
using namespace pkp_rows;
using pkp::model;

constexpr canopen::node_id node_of(const row& r) noexcept {
    return canopen::node_id::make(r.node).value();
}

// Row i encodes to its frame and its frame decodes to it, for every model it applies to.
constexpr bool row_ok(const row& r) noexcept {
    const auto f = can::parse_candump(r.frame);
    if (!f) return false;
    bool any = false;
    for (model m : pkp::all_models) {
        if (!applies(r.models, m)) continue;
        any = true;
        const auto e = pkp::encode(node_of(r), m, r.expected);
        if (!e || *e != *f) return false;
        const auto d = pkp::decode(*f, node_of(r), m);
        if (!d || *d != r.expected) return false;
    }
    return any;
}

constexpr bool rows_ok(std::size_t from, std::size_t to) noexcept {
    for (std::size_t i = from; i < to && i < std::size(rows); ++i)
        if (!row_ok(rows[i])) return false;
    return true;
}

// The table is proved at compile time in slices (each within the compilers' step limits).
static_assert(rows_ok(0, 30));
static_assert(rows_ok(30, 60));
static_assert(rows_ok(60, 90));
static_assert(rows_ok(90, 120));
static_assert(rows_ok(120, 150));
static_assert(rows_ok(150, 180));
static_assert(rows_ok(180, 210));
static_assert(rows_ok(210, 240));
static_assert(rows_ok(240, 270));
static_assert(rows_ok(270, 300));
static_assert(rows_ok(300, 330));
static_assert(rows_ok(330, 360));
static_assert(std::size(rows) <= 360, "add a slice above");

constexpr bool error_row_ok(const error_row& r) noexcept {
    const auto f = can::parse_candump(r.frame);
    if (!f) return false;
    bool any = false;
    for (model m : pkp::all_models) {
        if (!applies(r.models, m)) continue;
        any = true;
        if (pkp::decode(*f, canopen::default_node_id, m) != r.error) return false;
    }
    return any;
}
constexpr bool error_rows_ok() noexcept {
    for (const auto& r : error_rows)
        if (!error_row_ok(r)) return false;
    return true;
}
static_assert(error_rows_ok());

constexpr bool encode_error_rows_ok() noexcept {
    for (const auto& r : encode_error_rows)
        if (pkp::encode(canopen::default_node_id, r.model, r.message) != r.error) return false;
    return true;
}
static_assert(encode_error_rows_ok());

// --- the compile-time model --------------------------------------------------------------------

using pkp::colour;
// PKP 11: one colour for each button from 1 to 7, built as a typed PKP-2400 constant.
constexpr auto one_colour_each = pkp::led_map<model::pkp2400>{
    {1, colour::red},     {2, colour::green}, {3, colour::blue},  {4, colour::amber},
    {5, colour::magenta}, {6, colour::cyan},  {7, colour::white},
};
static_assert(pkp::encode_led_on(canopen::default_node_id, one_colour_each) ==
              can::candump("215#596A740000000000"));
static_assert(one_colour_each.colour_of(5) == colour::magenta);
static_assert(one_colour_each.colour_of(8) == colour::off);
// PKP 12, PKP-2200: all magenta LEDs blink.
static_assert(pkp::encode_led_blink(canopen::default_node_id,
                                    pkp::led_map<model::pkp2200>{{1, colour::magenta},
                                                                 {2, colour::magenta},
                                                                 {3, colour::magenta},
                                                                 {4, colour::magenta}}) ==
              can::candump("315#0F0F000000000000"));
// ref: PKP-2600 white key 12 sets R12, G12, B12 (bits 11, 23, 35).
static_assert(pkp::encode_led_on(canopen::default_node_id,
                                 pkp::led_map<model::pkp2600>{{12, colour::white}}) ==
              can::candump("215#0008800008000000"));

static_assert(pkp::key_count(model::pkp2200) == 4 && pkp::key_count(model::pkp2400) == 8 &&
              pkp::key_count(model::pkp2600) == 12);
static_assert(pkp::key_number<model::pkp2200>::max == 4);
static_assert(pkp::key_number<model::pkp2600>::max == 12);

// --- the one bit-map rule, checked against the reference's table of bytes used ------------------

// Bytes an RGB LED-on PDO uses for a model when every LED is on.
constexpr std::size_t bytes_used(model m) noexcept {
    pkp::leds l;
    for (unsigned k = 1; k <= pkp::key_count(m); ++k) l.set(k, colour::white);
    const auto f = pkp::encode(canopen::default_node_id, m, pkp::message{pkp::led_on{l}});
    std::size_t used = 0;
    for (std::size_t i = 0; i < 8; ++i)
        if ((*f)[i] != 0) used = i + 1;
    return used;
}
static_assert(bytes_used(model::pkp2200) == 2);
static_assert(bytes_used(model::pkp2400) == 3);
static_assert(bytes_used(model::pkp2600) == 5);

// One LED on sets exactly bit c*N + (k-1) of the PDO, for every model, plane and key.
constexpr bool single_bits_follow_the_rule() noexcept {
    for (model m : pkp::all_models)
        for (unsigned c = 0; c < 3; ++c)
            for (unsigned k = 1; k <= pkp::key_count(m); ++k) {
                pkp::leds l;
                l.of(static_cast<pkp::plane>(c)).insert(k);
                const auto f =
                    pkp::encode(canopen::default_node_id, m, pkp::message{pkp::led_on{l}});
                if (!f) return false;
                const std::size_t want = c * pkp::key_count(m) + (k - 1);
                for (std::size_t i = 0; i < 64; ++i) {
                    const bool set = (((*f)[i / 8] >> (i % 8)) & 1) != 0;
                    if (set != (i == want)) return false;
                }
                if (pkp::decode(*f, canopen::default_node_id, m) != pkp::message{pkp::led_on{l}})
                    return false;
            }
    return true;
}
static_assert(single_bits_follow_the_rule());

// --- colours and modes ---------------------------------------------------------------------------

constexpr bool colours_round_trip() noexcept {
    for (unsigned c = 0; c < 8; ++c) {
        pkp::leds l;
        l.set(3, static_cast<colour>(c));
        if (l.colour_of(3) != static_cast<colour>(c)) return false;
        if (pkp::to_string(static_cast<colour>(c)) == "unknown") return false;
    }
    return true;
}
static_assert(colours_round_trip());

// PKP 12: LED #4 on green, blink red and green: green blinks in alternate mode, red blinks.
constexpr pkp::leds on4 = pkp::leds{}.set(4, colour::green);
constexpr pkp::leds blink4 = pkp::leds{}.set(4, colour::amber);
static_assert(pkp::mode_of(on4, blink4, pkp::plane::green, 4) == pkp::led_mode::alternate_blink);
static_assert(pkp::mode_of(on4, blink4, pkp::plane::red, 4) == pkp::led_mode::blink);
static_assert(pkp::mode_of(on4, blink4, pkp::plane::blue, 4) == pkp::led_mode::off);
static_assert(pkp::mode_of(on4, pkp::leds{}, pkp::plane::green, 4) == pkp::led_mode::on);

// --- the object table
// ------------------------------------------------------------------------------

constexpr bool table_is_consistent() noexcept {
    for (std::size_t i = 0; i < pkp::object_count; ++i) {
        const auto o = static_cast<pkp::object>(i);
        const auto in = pkp::info(o);
        if (!in || pkp::find_object(in->address) != o) return false;  // unique addresses
        if (pkp::to_string(o) == "unknown" || pkp::to_string(o).empty()) return false;
        for (std::size_t j = 0; j < i; ++j)
            if (pkp::to_string(static_cast<pkp::object>(j)) == pkp::to_string(o)) return false;
        if (in->type == pkp::value_type::number && in->size != 1 && in->size != 2 && in->size != 4)
            return false;
    }
    return !pkp::info(static_cast<pkp::object>(pkp::object_count)).has_value() &&
           pkp::to_string(static_cast<pkp::object>(0xFF)) == "unknown";
}
static_assert(table_is_consistent());

// PKP 23: 43 18 10 03 10 16 12 00 is app revision 10h, com lib 16h, hw lib 12h.
static_assert(pkp::revision_of(
                  std::get<pkp::read_response>(pkp::decode(can::candump("595#4318100310161200"),
                                                           canopen::default_node_id, model::pkp2400)
                                                   .value())
                      .value) == pkp::revision{0x10, 0x16, 0x12});

// Every kind is unique and every profile-specific kind is prefixed "pkp_".
template <std::size_t... I>
constexpr bool kinds_ok(std::index_sequence<I...>) noexcept {
    constexpr std::string_view kinds[] = {std::variant_alternative_t<I, pkp::message>::kind...};
    for (std::size_t i = 0; i < sizeof...(I); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (kinds[i] == kinds[j]) return false;
    std::size_t prefixed = 0;
    for (auto k : kinds)
        if (k.starts_with("pkp_")) ++prefixed;
    return prefixed == sizeof...(I) - 8;  // the 8 core messages are not prefixed
}
static_assert(kinds_ok(std::make_index_sequence<std::variant_size_v<pkp::message>>{}));

}  // namespace

TEST_CASE("PKP: every manual and reference row, both ways, per model") {
    CHECK(rows_ok(0, std::size(rows)));
    for (const auto& r : rows) {
        CAPTURE(r.section);
        CAPTURE(r.frame);
        const auto f = can::parse_candump(r.frame);
        REQUIRE(f.has_value());
        for (model m : pkp::all_models) {
            if (!applies(r.models, m)) continue;
            CAPTURE(pkp::to_string(m));
            const auto d = pkp::decode(*f, node_of(r), m);
            REQUIRE(d.has_value());
            CHECK(d.value() == r.expected);
            const auto e = pkp::encode(node_of(r), m, *d);
            REQUIRE(e.has_value());
            CHECK(can::format_candump(*e).view() == can::format_candump(*f).view());
        }
    }
}

TEST_CASE("PKP: frames each model refuses, with the precise error") {
    CHECK(error_rows_ok());
    for (const auto& r : error_rows) {
        CAPTURE(r.section);
        CAPTURE(r.frame);
        const auto f = can::parse_candump(r.frame);
        REQUIRE(f.has_value());
        for (model m : pkp::all_models) {
            if (!applies(r.models, m)) continue;
            CAPTURE(pkp::to_string(m));
            const auto d = pkp::decode(*f, canopen::default_node_id, m);
            REQUIRE_FALSE(d.has_value());
            CHECK(to_string(d.error()) == to_string(r.error));
        }
    }
}

TEST_CASE("PKP: messages a model cannot carry do not encode") {
    CHECK(encode_error_rows_ok());
    for (const auto& r : encode_error_rows) {
        CAPTURE(r.what);
        const auto e = pkp::encode(canopen::default_node_id, r.model, r.message);
        REQUIRE_FALSE(e.has_value());
        CHECK(to_string(e.error()) == to_string(r.error));
    }
}

TEST_CASE("PKP: the bit-map rule, colours and the object table") {
    CHECK(bytes_used(model::pkp2200) == 2);
    CHECK(bytes_used(model::pkp2400) == 3);
    CHECK(bytes_used(model::pkp2600) == 5);
    CHECK(single_bits_follow_the_rule());
    CHECK(colours_round_trip());
    CHECK(table_is_consistent());
    CHECK(pkp::encode_led_on(canopen::default_node_id, one_colour_each) ==
          can::candump("215#596A740000000000"));
}

TEST_CASE("PKP errata: the manual's frames pin the chosen behaviour") {
    constexpr auto node = canopen::default_node_id;
    // E-PKP-1: the 13a reply printed with data 09 07 is refused; the request it describes
    // (LED 9 blue) decodes on a PKP-2600.
    CHECK(pkp::decode(can::candump("595#6000650100090700"), node, model::pkp2600) ==
          errc::reserved_not_zero);
    CHECK(pkp::decode(can::candump("615#2300650101090700"), node, model::pkp2600).value() ==
          pkp::message{pkp::set_led_state{9, pkp::led_state::blue_on}});
    // E-PKP-2: the 12h reply printed on 195h is no key-state PDO (8 bytes, not 5); on 595h it is
    // the command module's write response.
    CHECK(pkp::decode(can::candump("195#6000650100000000"), node, model::pkp2400) ==
          errc::wrong_length);
    CHECK(pkp::decode(can::candump("595#6000650100000000"), node, model::pkp2400).value() ==
          pkp::message{pkp::write_response{pkp::object::command_module}});
    // E-PKP-3: node id 00h is no node id.
    CHECK(pkp::decode(can::candump("615#2300650170000000"), node, model::pkp2400) ==
          errc::value_out_of_range);
    // E-PKP-4 (E-CORE-4): 41h for the 6300h read is refused; 40h reads it.
    CHECK(pkp::decode(can::candump("615#4100630000000000"), node, model::pkp2400) ==
          errc::reserved_not_zero);
    // E-PKP-5: 1400h/1 answers the COB-ID in 2 bytes (4Bh), base 200h without the node id; a
    // CiA 301 4-byte answer is a size the profile does not use.
    CHECK(pkp::decode(can::candump("595#4B00140100020000"), node, model::pkp2400).value() ==
          pkp::message{pkp::read_response{pkp::object::rpdo1_cob_id, 0x200}});
    CHECK(pkp::decode(can::candump("595#4300140115020000"), node, model::pkp2400) ==
          errc::size_mismatch);
    // E-PKP-6: sub-index 0 values are kept as printed (6302h has 4 entries but answers 2).
    CHECK(pkp::decode(can::candump("595#4F02630002000000"), node, model::pkp2200).value() ==
          pkp::message{pkp::read_response{pkp::object::key_led_count_count, 2}});
    // E-PKP-7: heartbeat 0 is off; 1..9 ms are below the minimum, both ways.
    CHECK(pkp::decode(can::candump("615#2B17100000000000"), node, model::pkp2400).value() ==
          pkp::message{pkp::write_request{pkp::object::heartbeat_time, 0}});
    CHECK(pkp::decode(can::candump("615#2B17100009000000"), node, model::pkp2400) ==
          errc::value_out_of_range);
    CHECK(pkp::encode(node, model::pkp2400, pkp::write_request{pkp::object::heartbeat_time, 9}) ==
          errc::value_out_of_range);
    // E-PKP-8: PKP-2600 keys 9..12 in key-state byte 1; 6001h carries red and green only, so
    // data byte 7 (blue 1..8 by the rule) is refused and blue does not encode.
    CHECK(pkp::decode(can::candump("195#000F000000"), node, model::pkp2600).value() ==
          pkp::message{pkp::key_state{pkp_rows::span(9, 12), 0}});
    CHECK(pkp::decode(can::candump("615#23016000000000FF"), node, model::pkp2600) ==
          errc::reserved_not_zero);
    CHECK(pkp::encode(node, model::pkp2600,
                      pkp::write_led_on{pkp_rows::rgb({}, {}, pkp_rows::keys({1}))}) ==
          errc::value_out_of_range);
    // E-PKP-9 (E-CORE-3): the 6100h sub 2 reply 40h decodes as printed, size not indicated, and
    // re-encodes unchanged.
    const auto f = can::candump("595#4000610208000000");
    const auto d = pkp::decode(f, node, model::pkp2400);
    REQUIRE(d.has_value());
    CHECK(d.value() == pkp::message{canopen::sdo_upload_initiate_response{{0x6100, 2}, false, 8}});
    CHECK(pkp::encode(node, model::pkp2400, *d).value() == f);
}

TEST_CASE("PKP: node id change moves the session to the new COB-IDs") {
    // PKP 13h: the request and reply on 615h/595h, then the boot-up on 718h.
    const auto req = pkp::decode(can::candump("615#2300650170180000"), 0x15, model::pkp2400);
    REQUIRE(req.has_value());
    const auto* s = std::get_if<pkp::set_node_id>(&*req);
    REQUIRE(s != nullptr);
    CHECK(s->new_node.value() == 0x18);
    CHECK(pkp::decode(can::candump("718#00"), 0x15, model::pkp2400) == errc::wrong_id);
    CHECK(pkp::decode(can::candump("718#00"), s->new_node, model::pkp2400).has_value());
}
