// powerkey detail: what every message struct takes from its name (its kind, the struct's name,
// `j1939_` before a J1939 one's; member-wise equality) and the shape of its fields(self, f).
#ifndef POWERKEY_DETAIL_MESSAGE_HPP
#define POWERKEY_DETAIL_MESSAGE_HPP

#include <string_view>

#define POWERKEY_DETAIL_MESSAGE_KIND(name, kind_name)    \
    static constexpr std::string_view kind = #kind_name; \
    friend constexpr bool operator==(const name&, const name&) noexcept = default
#define POWERKEY_DETAIL_MESSAGE(name) POWERKEY_DETAIL_MESSAGE_KIND(name, name)
#define POWERKEY_DETAIL_J1939_MESSAGE(name) POWERKEY_DETAIL_MESSAGE_KIND(name, j1939_##name)

// A message's `fields(self, f)` (fields.hpp), from its calls of f in order, comma-separated: each
// `f("name", self.member)`, or a shared function given self's part and f.
#define POWERKEY_DETAIL_FIELDS(...)                   \
    template <class Self, class F>                    \
    static constexpr void fields(Self& self, F&& f) { \
        (__VA_ARGS__);                                \
    }                                                 \
    static_assert(true, "a use ends with a semicolon")

#endif  // POWERKEY_DETAIL_MESSAGE_HPP
