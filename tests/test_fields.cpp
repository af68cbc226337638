// fields.hpp: walking the one message type. Every struct a message can hold is visited once, has a
// kind of its own that kind_of returns for it, and its enumerator fields have names no other
// value of the same enum has (what the tool prints and `encode --json` parses).
#include <doctest/doctest.h>

#include <powerkey/fields.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/names.hpp>

#include <array>
#include <cstddef>
#include <string_view>
#include <type_traits>
#include <variant>

namespace {
using namespace powerkey;

// For an enum whose values fit one byte: every named value has a name no other value has.
// Returns the number of named values, or -1 on a duplicate.
template <class E>
int check_enum_names() {
    static_assert(sizeof(E) == 1);
    std::array<std::string_view, 256> names{};
    int named = 0;
    for (unsigned v = 0; v < 256; ++v) {
        names[v] = to_string(static_cast<E>(v));
        if (names[v].empty()) continue;
        ++named;
        for (unsigned w = 0; w < v; ++w)
            if (names[w] == names[v]) {
                MESSAGE("duplicate name " << names[v] << " for " << w << " and " << v);
                return -1;
            }
    }
    return named;
}

struct enum_census {
    int types = 0;
    int names = 0;
    bool duplicate = false;
};

template <class Message>
enum_census census() {
    enum_census c;
    for_each_alternative<Message>([&c]<class S>(std::type_identity<S>) {
        S s{};
        S::fields(s, [&c](std::string_view, const auto& v) {
            using F = std::remove_cvref_t<decltype(v)>;
            if constexpr (std::is_enum_v<F> && sizeof(F) == 1) {
                const int n = check_enum_names<F>();
                if (n < 0) c.duplicate = true;
                c.names += n > 0 ? n : 0;
                ++c.types;
            }
        });
        return false;
    });
    return c;
}

// Every kind once, and kind_of of a message holding S is S's kind.
template <class Message>
constexpr bool kinds_unique() {
    std::array<std::string_view, 256> kinds{};
    std::size_t n = 0;
    bool ok = true;
    for_each_alternative<Message>([&]<class S>(std::type_identity<S>) {
        for (std::size_t i = 0; i < n; ++i)
            if (kinds[i] == S::kind) ok = false;
        if (n < kinds.size()) kinds[n++] = S::kind;
        Message m{};
        ok = ok && assign_message(m, S{}) && kind_of(m) == S::kind;
        return false;
    });
    return ok && n > 0;
}
// At run time only: clang 14 cannot assign a std::variant of libstdc++ 12 to another alternative
// in a constant expression.
}  // namespace

TEST_CASE("enumerator names of every message field are unique") {
    const auto all = census<message>();
    CHECK_FALSE(all.duplicate);
    CHECK(all.types > 5);
}

TEST_CASE("message kinds are unique in the one message type, and kind_of names each") {
    CHECK(kinds_unique<message>());
    std::size_t n = 0;
    for_each_alternative<message>([&n]<class S>(std::type_identity<S>) {
        ++n;
        return false;
    });
    CHECK(n == std::variant_size_v<message>);
}
