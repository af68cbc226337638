// The invariant sweep of tests/invariants.hpp with operator new trapping: every decoder of
// the library, on every frame of the sweep (refusals included, which the manual rows alone do not
// reach), allocates nothing, refuses only with listed codes and keeps the fixed point.
#include "../invariants.hpp"
#include "check.hpp"

namespace {

bool invariants_hold() {
    bool ok = true;
    std::size_t frames = 0, decoded = 0;
    invariants::sweep([&](const powerkey::can::frame& f, powerkey::canopen::node_id node) {
        ++frames;
        const auto v = invariants::check_all<invariants::no_guard>(f, node);
        decoded += v.accepted;
        ok = !v.any() && ok;
    });
    return ok && frames > 10000 && decoded > frames / 4;
}
const freestanding::registration reg("invariants", invariants_hold);

}  // namespace
