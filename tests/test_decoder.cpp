// The any-frame decoder on the core rows: classification, decoding both ways, foreign frames.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/decoder.hpp>
#include <powerkey/fields.hpp>

#include "decoder_rows.hpp"

namespace {
using namespace powerkey;
using namespace decoder_rows;
constexpr canopen::node_id keypad = canopen::default_node_id;

constexpr bool encodes_every_row() {
    for (const auto& r : core_rows)
        if (core::encode(keypad, r.expected) != can::parse_candump(r.frame).value()) return false;
    return true;
}
static_assert(encodes_every_row());

constexpr bool decodes_every_row() {
    for (const auto& r : core_rows) {
        const auto m = core::decode(can::parse_candump(r.frame).value(), keypad);
        if (!m || *m != r.expected) return false;
    }
    return true;
}
static_assert(decodes_every_row());

static_assert(classify(can::candump("615#00")) == frame_class{bus_function::sdo_rx, 0x15});
static_assert(classify(can::candump("18EF2100#00")) == frame_class{bus_function::j1939, 0});
static_assert(classify(can::candump("00000615#00")) == frame_class{bus_function::j1939, 0});
static_assert(parse_model("pkp2400") == model::pkp2400);
static_assert(parse_model("pkp2500") == errc::value_out_of_range);
static_assert(kind_of(core::message{canopen::sync_message{}}) == "sync");
}  // namespace

TEST_CASE("core rows decode to their meaning and encode back to the same bytes") {
    CHECK(encodes_every_row());
    CHECK(decodes_every_row());
    for (const auto& r : core_rows) {
        CAPTURE(r.section);
        CAPTURE(r.frame);
        const auto f = can::parse_candump(r.frame);
        REQUIRE(f.has_value());
        const auto c = core::decode(*f, keypad);
        REQUIRE(c.has_value());
        CHECK(*c == r.expected);
        CHECK(core::encode(keypad, *c) == *f);
    }
}

TEST_CASE("the NMT, SYNC, heartbeat and J1939 rows mean the same to every model that has them") {
    for (const auto& r : core_rows) {
        const auto kind = kind_of(r.expected);
        if (kind.substr(0, 4) == "sdo_") continue;  // the profiles type their SDOs per object
        for (model m : all_models) {
            if (kind == "j1939_switch_to_canopen" && m != model::pk1000) continue;
            CAPTURE(r.frame);
            CAPTURE(to_string(m));
            const auto f = can::parse_candump(r.frame).value();
            const auto d = decode(f, keypad, m);
            REQUIRE(d.has_value());
            CHECK(kind_of(*d) == kind);
            const auto back = encode(keypad, m, *d);
            REQUIRE(back.has_value());
            CHECK(*back == f);
        }
    }
}

TEST_CASE("frames of another node or function are classified and refused") {
    for (const auto& r : foreign_rows) {
        CAPTURE(r.frame);
        const auto f = can::parse_candump(r.frame).value();
        CHECK(classify(f) == r.cls);
        CHECK_FALSE(concerns(classify(f), keypad));
        for (model m : all_models) CHECK(decode(f, keypad, m) == r.error);
    }
}

TEST_CASE("malformed frames of the keypad give the core decoder's error") {
    for (const auto& r : bad_rows) {
        CAPTURE(r.frame);
        CHECK(core::decode(can::parse_candump(r.frame).value(), keypad) == r.error);
    }
}

TEST_CASE("an abort keeps its direction") {
    const auto from_client = can::candump("615#8008100000000405");
    const auto from_keypad = can::candump("595#8008100000000405");
    const auto a = core::decode(from_client, keypad);
    const auto b = core::decode(from_keypad, keypad);
    REQUIRE(a.has_value());
    REQUIRE(b.has_value());
    CHECK(kind_of(*a) == "sdo_abort_request");
    CHECK(kind_of(*b) == "sdo_abort_response");
    CHECK(core::encode(keypad, *a) == from_client);
    CHECK(core::encode(keypad, *b) == from_keypad);
}

TEST_CASE("model names") {
    for (model m : all_models) CHECK(parse_model(to_string(m)) == m);
    CHECK(parse_model("PK1000") == errc::value_out_of_range);
    CHECK(parse_model("") == errc::value_out_of_range);
}
