// Every name the library prints is unique and reads back to its value: the enumerator names of
// every message field (what the tool prints and `encode --json` parses), the kinds of every
// message, the error names and the CiA 301 function names.
#include <doctest/doctest.h>

#include <powerkey/powerkey.hpp>

#include <array>
#include <cstdint>
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

template <class Message>
bool kinds_unique() {
    std::array<std::string_view, 256> kinds{};
    std::size_t n = 0;
    bool unique = true;
    for_each_alternative<Message>([&]<class S>(std::type_identity<S>) {
        for (std::size_t i = 0; i < n; ++i)
            if (kinds[i] == S::kind) unique = false;
        if (n < kinds.size()) kinds[n++] = S::kind;
        return false;
    });
    return unique && n > 0;
}
}  // namespace

TEST_CASE("enumerator names of every message field are unique") {
    const auto all = census<message>();
    CHECK_FALSE(all.duplicate);
    CHECK(all.types > 5);
    // 00h, the legacy stop, has a name of its own now: no alias is printed for two values.
    CHECK(check_enum_names<canopen::nmt_command>() == 6);
    // A few names pinned, as the tool prints them.
    CHECK(to_string(canopen::nmt_command::enter_pre_operational) == "pre_operational");
    CHECK(to_string(canopen::nmt_state::stopped) == "stopped");
    CHECK(to_string(static_cast<canopen::nmt_state>(0x01)).empty());
}

TEST_CASE("message kinds are unique in the one message type") {
    CHECK(kinds_unique<message>());
    std::size_t n = 0;
    for_each_alternative<message>([&n]<class S>(std::type_identity<S>) {
        ++n;
        return false;
    });
    CHECK(n == std::variant_size_v<message>);
}

TEST_CASE("error and function names") {
    constexpr auto errors = enum_values<errc>();
    std::array<std::string_view, errors.size()> seen{};
    for (std::size_t i = 0; i < errors.size(); ++i) {
        seen[i] = to_string(errors[i]);
        CHECK_FALSE(seen[i].empty());
        for (std::size_t j = 0; j < i; ++j) CHECK(seen[j] != seen[i]);
    }
    // "" is the one spelling for "no such name".
    CHECK(to_string(static_cast<errc>(0)).empty());
    constexpr canopen::function functions[] = {
        canopen::function::nmt,       canopen::function::sync,   canopen::function::tpdo1,
        canopen::function::rpdo1,     canopen::function::rpdo2,  canopen::function::rpdo3,
        canopen::function::rpdo4,     canopen::function::sdo_tx, canopen::function::sdo_rx,
        canopen::function::heartbeat, canopen::function::j1939,  canopen::function::other};
    const std::string_view expected[] = {"nmt",    "sync",      "tpdo1", "rpdo1",
                                         "rpdo2",  "rpdo3",     "rpdo4", "sdo_tx",
                                         "sdo_rx", "heartbeat", "j1939", "other"};
    for (std::size_t i = 0; i < std::size(functions); ++i)
        CHECK(to_string(functions[i]) == expected[i]);
}
