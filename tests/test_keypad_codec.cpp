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

#include "codec_rows.hpp"
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
// model and both readings (issue 24: the same rows serve both APIs).
template <std::size_t... I>
constexpr bool compile_time_model_agrees(const can::frame& f, canopen::node_id n,
                                         std::index_sequence<I...>) {
    return ((decode<static_cast<model>(I)>(f, n) == decode(f, n, static_cast<model>(I)) &&
             decode<static_cast<model>(I)>(f, n, reading::strict) ==
                 decode(f, n, static_cast<model>(I), reading::strict)) &&
            ...);
}
template <class Row>
constexpr bool both_model_apis_agree(const Row& r) {
    return compile_time_model_agrees(frame_of(r.frame), node_of(r.node),
                                     std::make_index_sequence<model_count>{});
}
static_assert(first_failing(core_rows, both_model_apis_agree<row>) == std::size(core_rows));
static_assert(first_failing(core_error_rows, both_model_apis_agree<error_row>) ==
              std::size(core_error_rows));

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

TEST_CASE("decode<M> with the model known at compile time answers as decode(f, node, M)") {
    // Every manual row and every refusal row, through every model, read tolerantly and strictly.
    check_rows(core_rows, both_model_apis_agree<row>);
    check_rows(core_error_rows, both_model_apis_agree<error_row>);
    check_rows(pk1000_rows::rows, both_model_apis_agree<row>);
    check_rows(pk1000_rows::error_rows, both_model_apis_agree<error_row>);
    check_rows(pkp_rows::rows, both_model_apis_agree<row>);
    check_rows(pkp_rows::error_rows, both_model_apis_agree<error_row>);
    check_rows(si_rows::rows, both_model_apis_agree<row>);
    check_rows(si_rows::error_rows, both_model_apis_agree<error_row>);
    check_rows(si_rows::errata_rows, both_model_apis_agree<error_row>);
    check_rows(si_reference_rows::rows, both_model_apis_agree<row>);
}
