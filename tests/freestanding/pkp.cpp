// Freestanding check of the PKP rows: every manual row decodes and re-encodes for every model it
// applies to, every refused frame is refused, and every message encode must refuse is refused,
// with no exceptions, no RTTI and no heap.
#include <powerkey/powerkey.hpp>

#include "../pkp_rows.hpp"
#include "check.hpp"

#include <array>

namespace {
using namespace powerkey;

bool pkp_rows_both_ways() {
    bool ok = true;
    std::array<char, 160> buf{};
    for (const auto& r : pkp_rows::rows) {
        ok = ok && codec_rows::round_trips(r);
        ok = ok && describe(r.expected, codec_rows::node_of(r.node), buf).has_value();
    }
    for (const auto& r : pkp_rows::error_rows) ok = ok && codec_rows::refused(r);
    for (const auto& r : pkp_rows::encode_error_rows) ok = ok && codec_rows::encode_refused(r);
    return ok;
}
const freestanding::registration reg("pkp", pkp_rows_both_ways);
}  // namespace
