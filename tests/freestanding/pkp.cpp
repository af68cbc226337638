// Freestanding check of the PKP profile: every manual row decodes and re-encodes, and every
// refused frame is refused, with no exceptions, no RTTI and no heap.
#include <powerkey/powerkey.hpp>

#include "../pkp_rows.hpp"
#include "check.hpp"

namespace {
using namespace powerkey;

bool pkp_rows_both_ways() {
    for (const auto& r : pkp_rows::rows) {
        const auto f = can::parse_candump(r.frame);
        if (!f) return false;
        const auto node = canopen::node_id::make(r.node).value();
        for (pkp::model m : pkp::all_models) {
            if (!pkp_rows::applies(r.models, m)) continue;
            const auto d = pkp::decode(*f, node, m);
            if (!d || *d != r.expected) return false;
            const auto e = pkp::encode(node, m, *d);
            if (!e || *e != *f) return false;
        }
    }
    for (const auto& r : pkp_rows::error_rows) {
        const auto f = can::parse_candump(r.frame);
        if (!f) return false;
        for (pkp::model m : pkp::all_models)
            if (pkp_rows::applies(r.models, m) &&
                pkp::decode(*f, canopen::default_node_id, m) != r.error)
                return false;
    }
    return true;
}
const freestanding::registration reg("pkp", pkp_rows_both_ways);
}  // namespace
