// powerkey: names of enumerators, from one table per enum (enum_names<E>: {value, name} pairs,
// the first of a value its name, later ones aliases from_string also accepts): to_string,
// from_string, enum_values. docs/decoder.md, "Names".
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
// Whether the value of entry i is already an earlier entry's (an alias).
template <named_enum E>
constexpr bool is_alias(std::size_t i) noexcept {
    const auto& t = enum_names<E>::entries;
    for (std::size_t j = 0; j < i; ++j)
        if (t[j].value == t[i].value) return true;
    return false;
}
template <named_enum E>
constexpr std::size_t distinct_values() noexcept {
    std::size_t count = 0;
    for (std::size_t i = 0; i < std::size(enum_names<E>::entries); ++i)
        if (!is_alias<E>(i)) ++count;
    return count;
}
}  // namespace detail

// Every named value once, in table order.
template <named_enum E>
[[nodiscard]] constexpr auto enum_values() noexcept {
    std::array<E, detail::distinct_values<E>()> out{};
    std::size_t k = 0;
    for (std::size_t i = 0; i < std::size(enum_names<E>::entries); ++i)
        if (!detail::is_alias<E>(i)) out[k++] = enum_names<E>::entries[i].value;
    return out;
}

// True when e has a name.
template <named_enum E>
[[nodiscard]] constexpr bool is_named(E e) noexcept {
    return !to_string(e).empty();
}

}  // namespace powerkey

#endif  // POWERKEY_NAMES_HPP
