// powerkey: generic access to messages through the kind/fields convention (every message struct
// has `static constexpr std::string_view kind` and `fields(self, f)`, which calls f(name, member)
// for each field): docs/decoder.md, "The message type".
#ifndef POWERKEY_FIELDS_HPP
#define POWERKEY_FIELDS_HPP

#include <powerkey/bounded.hpp>
#include <powerkey/index_set.hpp>
#include <powerkey/names.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace powerkey {

// A struct that follows the convention.
template <class T>
concept message_struct = requires {
    { T::kind } -> std::convertible_to<std::string_view>;
};

namespace detail {
template <class T>
struct is_variant : std::false_type {};
template <class... Ts>
struct is_variant<std::variant<Ts...>> : std::true_type {};
}  // namespace detail

// Calls f(struct) with the message struct that m holds, through any depth of nested variants.
template <class M, class F>
constexpr decltype(auto) visit_message(const M& msg, F&& f) {
    if constexpr (detail::is_variant<M>::value)
        return std::visit(
            [&f](const auto& inner) -> decltype(auto) { return visit_message(inner, f); }, msg);
    else
        return f(msg);
}

// The kind of the struct that m holds.
template <class M>
[[nodiscard]] constexpr std::string_view kind_of(const M& msg) noexcept {
    return visit_message(msg, [](const auto& s) { return std::string_view{s.kind}; });
}

// A message's kind is its struct's name (a J1939 one's with `j1939_` before it); text written
// before that (JSON, Python) is read through current_kind: docs/decoder.md, "The message type".
inline constexpr std::string_view former_kinds[][2] = {
    {"nmt", "nmt_message"},
    {"sync", "sync_message"},
    {"heartbeat", "heartbeat_message"},
    {"sdo_download", "sdo_download_request"},
    {"sdo_upload", "sdo_upload_request"},
};
[[nodiscard]] constexpr std::string_view current_kind(std::string_view kind) noexcept {
    for (const auto& f : former_kinds)
        if (f[0] == kind) return f[1];
    return kind;
}

// Calls f(name, value) for every field of the struct that m holds.
template <class M, class F>
constexpr void for_each_field(const M& msg, F&& f) {
    visit_message(msg, [&f](const auto& s) { std::decay_t<decltype(s)>::fields(s, f); });
}

// Calls f(std::type_identity<S>{}) for every struct S a message type can hold (depth first, in
// the variants' order); f returns true to stop. Returns true when f stopped.
template <class M, class F>
constexpr bool for_each_alternative(F&& f) {
    if constexpr (detail::is_variant<M>::value) {
        return [&f]<class... Ts>(std::type_identity<std::variant<Ts...>>) {
            return (for_each_alternative<Ts>(f) || ...);
        }(std::type_identity<M>{});
    } else {
        return f(std::type_identity<M>{});
    }
}

// Puts the struct s into a message of type M (through nested variants), when M can hold it.
template <class M, class S>
[[nodiscard]] constexpr bool assign_message(M& m, const S& s) {
    if constexpr (std::is_same_v<M, S>) {
        m = s;
        return true;
    } else if constexpr (detail::is_variant<M>::value) {
        return [&]<class... Ts>(std::type_identity<std::variant<Ts...>>) {
            return ([&] {
                if constexpr (std::is_same_v<Ts, S>) {
                    m = s;
                    return true;
                } else if constexpr (detail::is_variant<Ts>::value) {
                    Ts inner{};
                    if (!assign_message(inner, s)) return false;
                    m = std::move(inner);
                    return true;
                } else {
                    return false;
                }
            }() || ...);
        }(std::type_identity<M>{});
    } else {
        return false;
    }
}

// --- field types ----------------------------------------------------------------------------

template <class T>
struct is_bounded : std::false_type {};
template <class Tag, class Rep, Rep Min, Rep Max>
struct is_bounded<bounded<Tag, Rep, Min, Max>> : std::true_type {};

template <class T>
struct is_index_set : std::false_type {};
template <std::size_t N>
struct is_index_set<index_set<N>> : std::true_type {};

template <class T>
struct is_byte_array : std::false_type {};
template <std::size_t N>
struct is_byte_array<std::array<std::uint8_t, N>> : std::true_type {};

}  // namespace powerkey

#endif  // POWERKEY_FIELDS_HPP
