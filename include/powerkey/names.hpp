// powerkey: names of enumerators, from one table per enum. Each named enum E specialises
// enum_names<E> with a list of {value, name} pairs (the first pair of a value is its name; any
// later pair with the same value is an alias that from_string also accepts, such as the PK1000
// manual's "white_light_blue" for the backlight colour the PKP manual calls "white"):
//
//   to_string(backlight_colour::white)            "white"
//   from_string<backlight_colour>("white_light_blue")   backlight_colour::white
//   enum_values<backlight_colour>()               every value, in table order, once
//
// A value with no name prints as "" (the one spelling for "no such name"), and from_string
// returns nullopt for text that names nothing. The tables are only odr-used by
// code that asks for a name, so firmware that never prints keeps none of them (--gc-sections).
#ifndef POWERKEY_NAMES_HPP
#define POWERKEY_NAMES_HPP

#include <powerkey/enum_names.hpp>
#include <powerkey/result.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <type_traits>

namespace powerkey {

template <class E>
concept named_enum = std::is_enum_v<E> && requires {
    enum_names<E>::entries;
};

// The name of e, or "" when the table has none.
template <named_enum E>
[[nodiscard]] constexpr std::string_view to_string(E e) noexcept {
    for (const auto& n : enum_names<E>::entries)
        if (n.value == e) return n.name;
    return {};
}

// The value a name or alias stands for; nullopt for any other text. (An optional rather than a
// result: errc itself is a named enum, and result<errc> would be ambiguous.)
template <named_enum E>
[[nodiscard]] constexpr std::optional<E> from_string(std::string_view name) noexcept {
    for (const auto& n : enum_names<E>::entries)
        if (n.name == name) return n.value;
    return std::nullopt;
}

namespace detail {
template <named_enum E>
constexpr std::size_t distinct_values() noexcept {
    std::size_t count = 0;
    const auto& t = enum_names<E>::entries;
    for (std::size_t i = 0; i < std::size(t); ++i) {
        bool seen = false;
        for (std::size_t j = 0; j < i; ++j) seen = seen || t[j].value == t[i].value;
        count += seen ? 0 : 1;
    }
    return count;
}
}  // namespace detail

// Every named value once, in table order.
template <named_enum E>
[[nodiscard]] constexpr auto enum_values() noexcept {
    std::array<E, detail::distinct_values<E>()> out{};
    std::size_t k = 0;
    const auto& t = enum_names<E>::entries;
    for (std::size_t i = 0; i < std::size(t); ++i) {
        bool seen = false;
        for (std::size_t j = 0; j < i; ++j) seen = seen || t[j].value == t[i].value;
        if (!seen) out[k++] = t[i].value;
    }
    return out;
}

// True when e has a name.
template <named_enum E>
[[nodiscard]] constexpr bool is_named(E e) noexcept {
    return !to_string(e).empty();
}

}  // namespace powerkey

#endif  // POWERKEY_NAMES_HPP
