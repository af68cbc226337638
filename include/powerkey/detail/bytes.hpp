// powerkey detail: the one little-endian load and store (load_le, store_le) and low_bits, by
// shifts, in constant evaluation too and whatever the host's byte order. Written out per width:
// g++ -O2 merges them into one load or store (a byte loop cost ~55 instructions).
#ifndef POWERKEY_DETAIL_BYTES_HPP
#define POWERKEY_DETAIL_BYTES_HPP

#include <powerkey/detail/inline.hpp>

#include <cstddef>
#include <cstdint>
#include <utility>

namespace powerkey::detail {

// Bytes [at, at + width) only: a decoder never reads past the dlc (the invariant tests poison
// those bytes under ASan). A switch that falls through: g++ -O2 left a loop at ~55 instructions.
template <class Bytes>
constexpr std::uint64_t load_le(const Bytes& b, std::size_t at, std::size_t width) noexcept {
    std::uint64_t v = 0;
    const auto byte = [&b, at](std::size_t i) { return std::uint64_t{b[at + i]} << (8 * i); };
    switch (width) {
        case 8: v |= byte(7); [[fallthrough]];
        case 7: v |= byte(6); [[fallthrough]];
        case 6: v |= byte(5); [[fallthrough]];
        case 5: v |= byte(4); [[fallthrough]];
        case 4: v |= byte(3); [[fallthrough]];
        case 3: v |= byte(2); [[fallthrough]];
        case 2: v |= byte(1); [[fallthrough]];
        case 1: v |= byte(0); [[fallthrough]];
        default: break;
    }
    return v;
}

template <std::size_t N, class Bytes>
requires(N >= 1 && N <= 8) constexpr std::uint64_t
    load_le(const Bytes& b, std::size_t at) noexcept {
    return load_le(b, at, N);
}

template <std::size_t N, class Bytes>
requires(N >= 1 && N <= 8) constexpr void store_le(Bytes& b, std::size_t at,
                                                   std::uint64_t v) noexcept {
    // Straight-line stores (a fold, not a loop): g++ -O2 merges them into one store; it left the
    // loop byte by byte, ~60 instructions of every encoder and of can::frame's constructor.
    // On a 32-bit core in 32-bit halves, so that it shifts registers, not a 64-bit value.
    if constexpr (sizeof(std::size_t) >= 8) {
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((b[at + I] = static_cast<std::uint8_t>(v >> (8 * I))), ...);
        }
        (std::make_index_sequence<N>{});
    } else {
        const auto lo = static_cast<std::uint32_t>(v);
        const auto hi = static_cast<std::uint32_t>(v >> 32);
        // Inlined into its caller always: under -Os g++ kept it out of line when one program
        // builds frames in several places, and then not one store folded (+316 bytes in a
        // firmware that builds two LED maps).
        [&]<std::size_t... I>(std::index_sequence<I...>) POWERKEY_DETAIL_INLINE_LAMBDA {
            ((b[at + I] = static_cast<std::uint8_t>((I < 4 ? lo : hi) >> (8 * (I % 4)))), ...);
        }
        (std::make_index_sequence<N>{});
    }
}

template <class Bytes>
constexpr void store_le(Bytes& b, std::size_t at, std::size_t width, std::uint64_t v) noexcept {
    for (std::size_t i = 0; i < width; ++i) b[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}

// The mask of the n low bits (n >= 64: every bit; a shift by 64 would be undefined).
constexpr std::uint64_t low_bits(unsigned n) noexcept {
    return n >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
}

}  // namespace powerkey::detail

#endif  // POWERKEY_DETAIL_BYTES_HPP
