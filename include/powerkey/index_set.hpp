// powerkey: index_set<N>, a set of the numbers 1..N (keys, LEDs) stored as N bits. Numbering from
// 1 follows the manuals ("key #1", "red LED #17"); bit storage is the caller's business.
#ifndef POWERKEY_INDEX_SET_HPP
#define POWERKEY_INDEX_SET_HPP

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <type_traits>

namespace powerkey {

template <std::size_t N>
class index_set {
    static_assert(N > 0 && N <= 64);
    // The smallest unsigned type with N bits: messages that hold several sets stay small, and
    // decoders copy less (a PKP LED map is 6 bytes, not 24).
    using storage = std::conditional_t<
        (N <= 8), std::uint8_t,
        std::conditional_t<(N <= 16), std::uint16_t,
                           std::conditional_t<(N <= 32), std::uint32_t, std::uint64_t>>>;

public:
    static constexpr std::size_t max = N;

    constexpr index_set() noexcept = default;
    // Numbers outside 1..N are ignored; use contains() to check what was kept.
    constexpr index_set(std::initializer_list<unsigned> numbers) noexcept {
        for (unsigned n : numbers) insert(n);
    }

    [[nodiscard]] constexpr bool contains(unsigned n) const noexcept {
        return n >= 1 && n <= N && ((bits_ >> (n - 1)) & 1u) != 0;
    }
    // Adds n; returns false (and changes nothing) when n is outside 1..N.
    constexpr bool insert(unsigned n) noexcept {
        if (n < 1 || n > N) return false;
        bits_ = static_cast<storage>(bits_ | (std::uint64_t{1} << (n - 1)));
        return true;
    }
    constexpr void erase(unsigned n) noexcept {
        if (n >= 1 && n <= N) bits_ = static_cast<storage>(bits_ & ~(std::uint64_t{1} << (n - 1)));
    }
    [[nodiscard]] constexpr bool empty() const noexcept { return bits_ == 0; }
    [[nodiscard]] constexpr std::size_t count() const noexcept {
        std::size_t c = 0;
        for (std::uint64_t b = bits_; b != 0; b &= b - 1) ++c;
        return c;
    }
    // Bit n-1 set for each member n.
    [[nodiscard]] constexpr std::uint64_t mask() const noexcept { return bits_; }
    [[nodiscard]] static constexpr index_set from_mask(std::uint64_t m) noexcept {
        index_set s;
        s.bits_ = static_cast<storage>(N == 64 ? m : (m & ((std::uint64_t{1} << N) - 1)));
        return s;
    }

    // The members in increasing order: `for (unsigned k : pressed) ...`.
    class iterator {
    public:
        using value_type = unsigned;
        using difference_type = std::ptrdiff_t;
        constexpr iterator() noexcept = default;
        constexpr explicit iterator(std::uint64_t rest) noexcept : rest_(rest) {}
        constexpr unsigned operator*() const noexcept {
            return static_cast<unsigned>(std::countr_zero(rest_)) + 1u;
        }
        constexpr iterator& operator++() noexcept {
            rest_ &= rest_ - 1;
            return *this;
        }
        constexpr iterator operator++(int) noexcept {
            iterator old = *this;
            ++*this;
            return old;
        }
        friend constexpr bool operator==(iterator, iterator) noexcept = default;

    private:
        std::uint64_t rest_ = 0;
    };
    [[nodiscard]] constexpr iterator begin() const noexcept { return iterator(bits_); }
    [[nodiscard]] constexpr iterator end() const noexcept { return iterator(0); }

    friend constexpr bool operator==(const index_set&, const index_set&) noexcept = default;

private:
    storage bits_ = 0;
};

}  // namespace powerkey

#endif  // POWERKEY_INDEX_SET_HPP
