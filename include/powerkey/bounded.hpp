// powerkey: bounded<Tag, Rep, Min, Max>, an integer that is always inside [Min, Max].
// Literals are checked at compile time (a consteval constructor), run-time values through
// make(), which returns errc::value_out_of_range instead of clamping. The Tag keeps two
// bounded types with the same range (a node id and an NMT target, say) from mixing.
#ifndef POWERKEY_BOUNDED_HPP
#define POWERKEY_BOUNDED_HPP

#include <powerkey/result.hpp>

#include <concepts>
#include <cstdint>
#include <utility>

namespace powerkey {

namespace detail {
// Not constexpr: calling it from a consteval constructor makes a bad literal fail to compile.
inline void literal_out_of_range() noexcept {}
}  // namespace detail

// clang 14 does not reject a consteval constructor whose evaluation fails when it converts the
// initialiser of a namespace-scope variable or a default member initialiser (`node_id g = 0x80;`
// compiles to 128). clang's diagnose_if attribute checks the argument at overload resolution,
// in every context; g++ needs no help (its consteval check holds everywhere).
#if defined(__clang__)
#define POWERKEY_LITERAL_IN_RANGE(ok) \
    __attribute__((diagnose_if(!(ok), "literal out of range for this bounded type", "error")))
#else
#define POWERKEY_LITERAL_IN_RANGE(ok)
#endif

template <class Tag, std::unsigned_integral Rep, Rep Min, Rep Max>
class bounded {
    static_assert(Min <= Max);

    template <std::integral I>
    static constexpr bool in_range(I v) noexcept {
        return std::cmp_greater_equal(v, Min) && std::cmp_less_equal(v, Max);
    }
    // The attribute's condition is formed before the constraint is checked (for a bounded
    // argument too, when clang looks for a copy): true for anything but an integer.
    template <class T>
    static constexpr bool literal_in_range(const T& v) noexcept {
        if constexpr (std::integral<T>)
            return in_range(v);
        else
            return true;
    }

public:
    using rep = Rep;
    static constexpr Rep min = Min;
    static constexpr Rep max = Max;

    // From a literal or constant: out of range does not compile, whatever the context
    // (constexpr or not, local, namespace scope, member initialiser, aggregate element).
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wgcc-compat"  // diagnose_if is a clang attribute
#endif
    template <std::integral I>
    consteval bounded(I v) noexcept POWERKEY_LITERAL_IN_RANGE(literal_in_range(v))
        : v_(static_cast<Rep>(v)) {
        if (!in_range(v)) detail::literal_out_of_range();
    }
#if defined(__clang__)
#pragma clang diagnostic pop
#endif

    // From a run-time value: out of range is errc::value_out_of_range.
    template <std::integral I>
    [[nodiscard]] static constexpr result<bounded> make(I v) noexcept {
        if (!in_range(v)) return errc::value_out_of_range;
        return bounded(v, 0);
    }

    [[nodiscard]] constexpr Rep value() const noexcept { return v_; }

    friend constexpr bool operator==(bounded, bounded) noexcept = default;

    // result<bounded> needs a default; it is Min, always valid.
    constexpr bounded() noexcept = default;

private:
    template <std::integral I>
    constexpr bounded(I v, int) noexcept : v_(static_cast<Rep>(v)) {}

    Rep v_ = Min;
};

}  // namespace powerkey

#endif  // POWERKEY_BOUNDED_HPP
