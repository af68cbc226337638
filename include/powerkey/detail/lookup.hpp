// powerkey detail: the hash of the object dictionaries' address tables (keypad/objects.hpp builds
// them at compile time), so that finding an object is a multiply, a shift and at most two probes
// instead of a search (issue 7: the binary search was ~60 instructions of every SDO decode).
#ifndef POWERKEY_DETAIL_LOOKUP_HPP
#define POWERKEY_DETAIL_LOOKUP_HPP

#include <cstddef>
#include <cstdint>

namespace powerkey::detail {

// Multiplicative hashing: the top `32 - shift` bits of key * multiplier.
constexpr std::uint32_t home_slot(std::uint32_t key, std::uint32_t multiplier,
                                  unsigned shift) noexcept {
    return (key * multiplier) >> shift;
}

// The multipliers a table builder tries, in order: odd numbers from a linear congruential
// sequence that starts at 2^32 / phi (Fibonacci hashing).
constexpr std::uint32_t hash_candidate(std::size_t t) noexcept {
    std::uint32_t x = 0x9E37'79B1u;
    for (std::size_t i = 0; i < t; ++i) x = x * 1'664'525u + 1'013'904'223u;
    return x | 1u;
}

}  // namespace powerkey::detail

#endif  // POWERKEY_DETAIL_LOOKUP_HPP
