// powerkey detail: little-endian loads and stores on byte arrays, by shifts only, so that they
// work in constant evaluation and do not depend on the host's byte order. Never public API.
#ifndef POWERKEY_DETAIL_BYTES_HPP
#define POWERKEY_DETAIL_BYTES_HPP

#include <cstddef>
#include <cstdint>

namespace powerkey::detail {

template <class Bytes>
constexpr std::uint16_t load_le_u16(const Bytes& b, std::size_t at) noexcept {
    return static_cast<std::uint16_t>(b[at] | (b[at + 1] << 8));
}

template <class Bytes>
constexpr std::uint32_t load_le_u32(const Bytes& b, std::size_t at) noexcept {
    return static_cast<std::uint32_t>(b[at]) | (static_cast<std::uint32_t>(b[at + 1]) << 8) |
           (static_cast<std::uint32_t>(b[at + 2]) << 16) |
           (static_cast<std::uint32_t>(b[at + 3]) << 24);
}

template <class Bytes>
constexpr void store_le_u16(Bytes& b, std::size_t at, std::uint16_t v) noexcept {
    b[at] = static_cast<std::uint8_t>(v);
    b[at + 1] = static_cast<std::uint8_t>(v >> 8);
}

template <class Bytes>
constexpr void store_le_u32(Bytes& b, std::size_t at, std::uint32_t v) noexcept {
    b[at] = static_cast<std::uint8_t>(v);
    b[at + 1] = static_cast<std::uint8_t>(v >> 8);
    b[at + 2] = static_cast<std::uint8_t>(v >> 16);
    b[at + 3] = static_cast<std::uint8_t>(v >> 24);
}

// All eight bytes of a payload as one little-endian number. Written out rather than as a loop:
// g++ -O2 merges this form into a single 64-bit load (the loop cost ~55 instructions).
template <class Bytes>
constexpr std::uint64_t load_le_u64(const Bytes& b) noexcept {
    return std::uint64_t{load_le_u32(b, 0)} | (std::uint64_t{load_le_u32(b, 4)} << 32);
}

template <class Bytes>
constexpr void store_le_u64(Bytes& b, std::uint64_t v) noexcept {
    store_le_u32(b, 0, static_cast<std::uint32_t>(v));
    store_le_u32(b, 4, static_cast<std::uint32_t>(v >> 32));
}

// True when bytes [from, to) are all zero.
template <class Bytes>
constexpr bool all_zero(const Bytes& b, std::size_t from, std::size_t to) noexcept {
    for (std::size_t i = from; i < to; ++i)
        if (b[i] != 0) return false;
    return true;
}

}  // namespace powerkey::detail

#endif  // POWERKEY_DETAIL_BYTES_HPP
