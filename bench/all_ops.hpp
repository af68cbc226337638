// Every measured operation: the core ones, then each profile's and the any-frame decoder's once
// their headers exist, so that the suite builds at every stage of the library.
#ifndef POWERKEY_BENCH_ALL_OPS_HPP
#define POWERKEY_BENCH_ALL_OPS_HPP

#include "ops.hpp"
#include "ops_j1939.hpp"
#include "ops_pk1000.hpp"
#include "ops_pkp.hpp"
#include "ops_si.hpp"

#include <array>
#include <cstddef>
#include <span>

namespace bench {

inline constexpr std::array<std::span<const op>, 5> op_groups = {
    std::span<const op>(core_ops), std::span<const op>(pk1000_ops), std::span<const op>(pkp_ops),
    std::span<const op>(si_ops),   std::span<const op>(j1939_ops),
};

// Calls f(op) for every operation, floor first.
template <class F>
void for_each_op(F&& f) {
    for (auto group : op_groups)
        for (const op& o : group) f(o);
}

}  // namespace bench

#endif  // POWERKEY_BENCH_ALL_OPS_HPP
