// canopen/sync.hpp: the SYNC frame of PK1000 section 10 both ways, and what the decoder refuses.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/canopen/sync.hpp>

#include "support.hpp"

namespace {
using namespace powerkey;
using namespace powerkey::canopen;

using namespace powerkey_tests;

constexpr bool sync_both_ways() {
    return encode(sync_message{}) == can::candump("080#") &&
           decode_sync(can::candump("080#")).has_value();
}
static_assert(sync_both_ways());  // PK1000 10

constexpr bad_row bad_sync[] = {
    {"extended id", "00000080#", errc::wrong_id_format},
    {"not 080h", "081#", errc::wrong_id},
    {"a counter byte", "080#01", errc::wrong_length},
};
constexpr auto sync_refuses = refused_by([](const can::frame& f) { return decode_sync(f); });
static_assert(first_failing(bad_sync, sync_refuses) == std::size(bad_sync));
}  // namespace

TEST_CASE("SYNC both ways, PK1000 10") { CHECK(sync_both_ways()); }

TEST_CASE("the SYNC decoder refuses malformed frames with the documented error") {
    check_rows(bad_sync, sync_refuses);
}
