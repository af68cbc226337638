// powerkey.hpp, the library as a whole: every decoder it offers (the CiA 301 and J1939 ones, and
// decode(frame, node, model) for every model), over a sweep of frames around every row of the
// frame tables (tests/invariants.hpp), refuses only with listed codes, keeps decode -> encode ->
// decode a fixed point (every decoded message encodes to a frame that decodes to it), agrees with
// the one SDO parser on every SDO frame (tests/sdo_agreement.hpp), and (under AddressSanitizer)
// reads no data byte past the dlc.
#include <doctest/doctest.h>

#include "../fuzz/fuzz.hpp"
#include "invariants.hpp"

#include <cstddef>
#include <cstdint>

namespace {
using namespace powerkey;

// A named constant rather than a consteval call inside the loops: clang 14 crashes generating
// code for an immediate invocation there.
constexpr can::standard_id sdo_rx_15 = 0x615;

#ifdef POWERKEY_FUZZ_ASAN
constexpr bool asan = true;
using past_dlc_guard = powerkey_fuzz::poison_past_dlc;
#else
constexpr bool asan = false;
using past_dlc_guard = invariants::no_guard;
#endif

TEST_CASE("the bytes past the dlc are unreadable while a decoder runs (ASan builds)") {
    if (!asan) {
        MESSAGE("not an AddressSanitizer build: the past-dlc check runs in build/clang-asan");
        return;
    }
    // The guard is effective for every dlc: exactly the bytes at and past the dlc are poisoned,
    // and all of them are readable again afterwards.
    for (std::uint8_t n = 0; n <= 8; ++n) {
        const can::payload p{1, 2, 3, 4, 5, 6, 7, 8};
        powerkey_fuzz::aligned_frame held{can::frame(sdo_rx_15, can::dlc::make(n).value(), p)};
        {
            const powerkey_fuzz::poison_past_dlc guard(held.f);
            CHECK(guard.effective());
        }
        CHECK(held.f == can::frame(sdo_rx_15, can::dlc::make(n).value(), p));
    }
}

TEST_CASE("every decoder keeps its invariants on a sweep around every manual row") {
    std::size_t frames = 0, failures = 0, decoded = 0;
    invariants::sweep([&](const can::frame& f, canopen::node_id node) {
        ++frames;
        const powerkey_fuzz::aligned_frame held{f};
        const auto v = invariants::check_all<past_dlc_guard>(held.f, node);
        decoded += v.accepted;
        if (v.any() && failures++ < 20) {
            INFO("frame " << can::format_candump(f).view() << " node " << int{node.value()});
            INFO(v.decoder << ": " << v.what);
            CHECK(!v.any());
        }
    });
    MESSAGE(frames << " frames, " << decoded << " decodes accepted, " << failures << " violations");
    CHECK(frames > 100000);
    CHECK(decoded > frames / 4);  // not a sweep of refusals only
    CHECK(failures == 0);
}

}  // namespace
