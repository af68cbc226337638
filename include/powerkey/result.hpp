// powerkey: result<T>, a value or an errc. Member names follow std::expected so that code can
// move to it later; unlike std::expected it needs no exceptions: value() on an error is a
// precondition violation (checked by assertions in constant evaluation, undefined at run time).
#ifndef POWERKEY_RESULT_HPP
#define POWERKEY_RESULT_HPP

#include <powerkey/error.hpp>

#include <type_traits>
#include <utility>

namespace powerkey {

namespace detail {
// Not constexpr on purpose: reaching it during constant evaluation is a compile error.
inline void value_of_an_error_result() noexcept {}
}  // namespace detail

template <class T>
class [[nodiscard]] result {
    static_assert(std::is_default_constructible_v<T>, "result<T> stores a T at all times");
    static_assert(!std::is_same_v<std::remove_cv_t<T>, errc>, "result<errc> would be ambiguous");

public:
    using value_type = T;
    using error_type = errc;

    constexpr result(const T& v) noexcept(std::is_nothrow_copy_constructible_v<T>) : value_(v) {}
    constexpr result(T&& v) noexcept(std::is_nothrow_move_constructible_v<T>)
        : value_(std::move(v)) {}
    constexpr result(errc e) noexcept : error_(e) {}
    // The value built in place from args (for result<variant>: std::in_place_type<A>, args of A),
    // so that a decoder writes its answer straight into the caller's result instead of building
    // a T and moving it in (CHANGELOG.md "How we got here").
    template <class... A>
    requires std::is_constructible_v<T, A...>
    constexpr explicit result(std::in_place_t,
                              A&&... args) noexcept(std::is_nothrow_constructible_v<T, A...>)
        : value_(std::forward<A>(args)...) {}

    [[nodiscard]] constexpr bool has_value() const noexcept { return error_ == errc{}; }
    constexpr explicit operator bool() const noexcept { return has_value(); }

    [[nodiscard]] constexpr const T& value() const& noexcept { return check(), value_; }
    [[nodiscard]] constexpr T& value() & noexcept { return check(), value_; }
    [[nodiscard]] constexpr T&& value() && noexcept { return check(), std::move(value_); }
    constexpr const T& operator*() const& noexcept { return check(), value_; }
    constexpr T& operator*() & noexcept { return check(), value_; }
    constexpr const T* operator->() const noexcept { return check(), &value_; }
    constexpr T* operator->() noexcept { return check(), &value_; }

    // The error code; meaningful only when !has_value().
    [[nodiscard]] constexpr errc error() const noexcept { return error_; }

    template <class U>
    [[nodiscard]] constexpr T value_or(U&& fallback) const& {
        return has_value() ? value_ : static_cast<T>(std::forward<U>(fallback));
    }

    friend constexpr bool operator==(const result& a, const result& b) noexcept {
        if (a.has_value() != b.has_value()) return false;
        return a.has_value() ? a.value_ == b.value_ : a.error_ == b.error_;
    }
    friend constexpr bool operator==(const result& a, errc e) noexcept {
        return !a.has_value() && a.error_ == e;
    }

private:
    constexpr void check() const noexcept {
        if (std::is_constant_evaluated() && !has_value()) detail::value_of_an_error_result();
    }

    T value_{};
    errc error_{};  // errc{} (zero) is no error: every named code is non-zero
};

}  // namespace powerkey

#endif  // POWERKEY_RESULT_HPP
