// Every manual row of both profiles through the any-frame decoder: decode(frame, node, model)
// gives the row's meaning, encode gives the bytes back, and the description fits 160 characters.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/decoder.hpp>
#include <powerkey/describe.hpp>

#include "pk1000_rows.hpp"
#include "pkp_rows.hpp"

#include <array>

namespace {
using namespace powerkey;

constexpr bool pk1000_rows_round_trip() {
    for (const auto& r : pk1000_rows::rows) {
        const auto f = can::parse_candump(r.frame).value();
        const auto d = decode(f, r.node, model::pk1000);
        if (!d || *d != message{r.expected}) return false;
        const auto back = encode(r.node, model::pk1000, *d);
        if (!back || *back != f) return false;
    }
    return true;
}
static_assert(pk1000_rows_round_trip());

constexpr bool pkp_rows_round_trip(model m) {
    const auto pm = *pkp_model(m);
    for (const auto& r : pkp_rows::rows) {
        if (!pkp_rows::applies(r.models, pm)) continue;
        const auto node = canopen::node_id::make(r.node).value();
        const auto f = can::parse_candump(r.frame).value();
        const auto d = decode(f, node, m);
        if (!d || *d != message{r.expected}) return false;
        const auto back = encode(node, m, *d);
        if (!back || *back != f) return false;
    }
    return true;
}
static_assert(pkp_rows_round_trip(model::pkp2200));
static_assert(pkp_rows_round_trip(model::pkp2400));
static_assert(pkp_rows_round_trip(model::pkp2600));

// A message of one profile is not encoded for a model of the other.
constexpr message pk1000_sync{pk1000::message{canopen::sync_message{}}};
constexpr message pkp_sync{pkp::message{canopen::sync_message{}}};
static_assert(encode(canopen::default_node_id, model::pkp2400, pk1000_sync) ==
              errc::unknown_command);
static_assert(encode(canopen::default_node_id, model::pk1000, pkp_sync) == errc::unknown_command);
static_assert(encode(canopen::default_node_id, model::pk1000, pk1000_sync) ==
              result<can::frame>(can::candump("080#")));
}  // namespace

TEST_CASE("every PK1000 manual row through the any-frame decoder") {
    CHECK(pk1000_rows_round_trip());
    for (const auto& r : pk1000_rows::rows) {
        CAPTURE(r.section);
        CAPTURE(r.frame);
        const auto f = can::parse_candump(r.frame).value();
        const auto d = decode(f, r.node, model::pk1000);
        REQUIRE(d.has_value());
        CHECK(*d == message{r.expected});
        CHECK(encode(r.node, model::pk1000, *d) == result<can::frame>(f));
        std::array<char, 160> buf{};
        CHECK(describe(*d, r.node, buf).has_value());
        // The PKP models refuse or read differently, but never crash: any answer is fine here
        // except a PK1000-only message.
        for (model m : {model::pkp2200, model::pkp2400, model::pkp2600})
            if (const auto other = decode(f, r.node, m)) CHECK(other->index() == 1);
    }
    for (const auto& r : pk1000_rows::bad_rows) {
        CAPTURE(r.section);
        CAPTURE(r.frame);
        CHECK(decode(can::parse_candump(r.frame).value(), r.node, model::pk1000) == r.error);
    }
}

TEST_CASE("every PKP manual row through the any-frame decoder, for each model it applies to") {
    for (model m : {model::pkp2200, model::pkp2400, model::pkp2600}) {
        CHECK(pkp_rows_round_trip(m));
        const auto pm = *pkp_model(m);
        for (const auto& r : pkp_rows::rows) {
            if (!pkp_rows::applies(r.models, pm)) continue;
            CAPTURE(r.section);
            CAPTURE(r.frame);
            CAPTURE(to_string(m));
            const auto node = canopen::node_id::make(r.node).value();
            const auto f = can::parse_candump(r.frame).value();
            const auto d = decode(f, node, m);
            REQUIRE(d.has_value());
            CHECK(*d == message{r.expected});
            CHECK(encode(node, m, *d) == result<can::frame>(f));
            std::array<char, 160> buf{};
            CHECK(describe(*d, node, buf).has_value());
        }
        for (const auto& r : pkp_rows::error_rows) {
            if (!pkp_rows::applies(r.models, pm)) continue;
            CAPTURE(r.section);
            CAPTURE(r.frame);
            CHECK(decode(can::parse_candump(r.frame).value(), canopen::default_node_id, m) ==
                  r.error);
        }
    }
}
