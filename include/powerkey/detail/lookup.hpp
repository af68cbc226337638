// powerkey detail: what the compile-time tables are built with. The hash of the object
// dictionaries' address tables (keypad/objects.hpp), so that finding an object is a multiply, a
// shift and at most two probes instead of a search (issue 7: the binary search was ~60
// instructions of every SDO decode); and distinct_set, which keeps each value once (the codec's
// ranges and rows, the command module's parameter pairs).
#ifndef POWERKEY_DETAIL_LOOKUP_HPP
#define POWERKEY_DETAIL_LOOKUP_HPP

#include <array>
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

// Row + 1 of each code below N in `table` (a row's code read by `code_of`), 0 for none: finding a
// row by its code (a command byte) is one load instead of a search.
template <std::size_t N, class Table, class CodeOf>
constexpr std::array<std::uint8_t, N> index_by_code(const Table& table, CodeOf code_of) noexcept {
    std::array<std::uint8_t, N> t{};
    for (std::size_t i = 0; i < std::size(table); ++i)
        t[static_cast<std::size_t>(code_of(table[i]))] = static_cast<std::uint8_t>(i + 1);
    return t;
}

// The distinct values added, in the order first seen; find() and add() give a value's index.
// More than Cap values is not a constant expression (a table builder fails to compile).
template <class T, std::size_t Cap>
struct distinct_set {
    std::array<T, Cap> items{};
    std::size_t size = 0;
    constexpr std::size_t find(const T& v) const noexcept {
        for (std::size_t i = 0; i < size; ++i)
            if (items[i] == v) return i;
        return size;
    }
    constexpr std::size_t add(const T& v) noexcept {
        const std::size_t i = find(v);
        if (i == size) items[size++] = v;
        return i;
    }
};

}  // namespace powerkey::detail

#endif  // POWERKEY_DETAIL_LOOKUP_HPP
