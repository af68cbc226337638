// Freestanding check of the PK1000 profile: every manual row decodes and re-encodes at run time
// with no exceptions, no RTTI and no heap.
#include <powerkey/powerkey.hpp>

#include "../pk1000_rows.hpp"
#include "check.hpp"

namespace {
using namespace powerkey;

bool pk1000_profile() {
    bool ok = true;
    for (const auto& r : pk1000_rows::rows) {
        const auto f = can::parse_candump(r.frame);
        if (!f) return false;
        const auto m = pk1000::decode(*f, r.node);
        ok = ok && m.has_value() && *m == r.expected && pk1000::encode(r.node, *m) == *f;
    }
    for (const auto& r : pk1000_rows::bad_rows) {
        const auto f = can::parse_candump(r.frame);
        ok = ok && f.has_value() && pk1000::decode(*f, r.node) == r.error;
    }
    return ok;
}
const freestanding::registration reg("pk1000", pk1000_profile);
}  // namespace
