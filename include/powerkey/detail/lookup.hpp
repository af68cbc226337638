// powerkey detail: a constant hash table from SDO addresses to table rows, built at compile time,
// so that finding an object is a multiply, a shift and one or two probes instead of a search
// (issue 7: the binary search was ~60 instructions of every SDO decode).
#ifndef POWERKEY_DETAIL_LOOKUP_HPP
#define POWERKEY_DETAIL_LOOKUP_HPP

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace powerkey::detail {

// index << 8 | sub-index: every SDO address as one number.
constexpr std::uint32_t address_key(std::uint16_t index, std::uint8_t subindex) noexcept {
    return (std::uint32_t{index} << 8) | subindex;
}

// Open addressing over 2^Bits slots, each 0 (empty) or row + 1; N rows, N < 255.
template <std::size_t N, unsigned Bits>
class address_table {
    static_assert(N < 255 && (std::size_t{1} << Bits) >= 2 * N);
    static constexpr std::size_t slots = std::size_t{1} << Bits;

public:
    // Keys must be distinct.
    constexpr explicit address_table(const std::array<std::uint32_t, N>& keys) noexcept
        : keys_(keys) {
        for (std::size_t row = 0; row < N; ++row) {
            std::size_t s = home(keys[row]);
            std::size_t probes = 1;
            while (slot_[s] != 0) {
                s = (s + 1) & (slots - 1);
                ++probes;
            }
            slot_[s] = static_cast<std::uint8_t>(row + 1);
            if (probes > max_probes_) max_probes_ = probes;
        }
    }

    // The row whose key is k, if any.
    [[nodiscard]] constexpr std::optional<std::size_t> find(std::uint32_t k) const noexcept {
        std::size_t s = home(k);
        for (std::size_t p = 0; p < max_probes_; ++p, s = (s + 1) & (slots - 1)) {
            const std::uint8_t v = slot_[s];
            if (v == 0) return std::nullopt;
            if (keys_[v - 1u] == k) return std::size_t{v - 1u};
        }
        return std::nullopt;
    }

    // The longest probe sequence any key needs; tests bound it.
    [[nodiscard]] constexpr std::size_t max_probes() const noexcept { return max_probes_; }

private:
    static constexpr std::size_t home(std::uint32_t k) noexcept {
        return static_cast<std::size_t>((k * 0x9E37'79B1u) >> (32 - Bits));
    }

    std::array<std::uint32_t, N> keys_{};
    std::array<std::uint8_t, slots> slot_{};
    std::size_t max_probes_ = 0;
};

}  // namespace powerkey::detail

#endif  // POWERKEY_DETAIL_LOOKUP_HPP
