// Every manual row of both manuals through every model, including the models it is not written
// for: whatever a model makes of the frame, it either refuses it or reads a meaning that encodes
// back to the same bytes, and the description of that meaning fits 160 characters.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/keypad/codec.hpp>

#include <array>
#include <cstddef>
#include <iterator>

#include "codec_rows.hpp"
#include "pk1000_rows.hpp"
#include "pkp_rows.hpp"
#include "support.hpp"

namespace {
using namespace powerkey;
using namespace codec_rows;
using powerkey_tests::check_rows;
using powerkey_tests::first_failing;
using powerkey_tests::frame_of;

// Every model: refused, or decoded to a meaning that encodes to the same frame.
constexpr bool every_model_round_trips(const row& r) {
    const auto f = frame_of(r.frame);
    for (std::size_t i = 0; i < model_count; ++i) {
        const auto m = static_cast<model>(i);
        const auto d = decode(f, node_of(r.node), m);
        if (!d) {
            if (applies(r.models, m)) return false;
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

// The description of every meaning a model reads fits 160 characters.
bool describes(const row& r) {
    const auto f = frame_of(r.frame);
    for (std::size_t i = 0; i < model_count; ++i) {
        const auto m = static_cast<model>(i);
        const auto d = decode(f, node_of(r.node), m);
        if (!d) continue;
        std::array<char, 160> buf{};
        if (!describe(*d, node_of(r.node), buf)) return false;
    }
    return true;
}
}  // namespace

TEST_CASE("every manual row through every model: refused, or read back to the same bytes") {
    check_rows(core_rows, every_model_round_trips);
    check_rows(pk1000_rows::rows, every_model_round_trips);
    check_rows(pkp_rows::rows, every_model_round_trips);
}

TEST_CASE("every meaning a model reads from a manual row has a description of 160 characters") {
    check_rows(core_rows, describes);
    check_rows(pk1000_rows::rows, describes);
    check_rows(pkp_rows::rows, describes);
}
