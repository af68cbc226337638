// Freestanding check of the PK1000 rows: every manual row decodes to its meaning and re-encodes
// byte for byte, every refused frame is refused, and every message encode must refuse is refused,
// at run time with no exceptions, no RTTI and no heap.
#include <powerkey/powerkey.hpp>

#include "../pk1000_rows.hpp"
#include "check.hpp"

#include <array>

namespace {
using namespace powerkey;

bool pk1000_rows_both_ways() {
    bool ok = true;
    std::array<char, 160> buf{};
    for (const auto& r : pk1000_rows::rows) {
        ok = ok && codec_rows::round_trips(r);
        ok = ok && describe(r.expected, codec_rows::node_of(r.node), buf).has_value();
    }
    for (const auto& r : pk1000_rows::error_rows) ok = ok && codec_rows::refused(r);
    for (const auto& r : pk1000_rows::encode_error_rows) ok = ok && codec_rows::encode_refused(r);
    return ok;
}
const freestanding::registration reg("pk1000", pk1000_rows_both_ways);
}  // namespace
