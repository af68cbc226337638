// powerkey tool: why encode() refused a message whose fields each held a value of their type (a
// key above a PKP-2200's four, an encoder message for a keypad without encoders): found by
// putting the model to the test, field by field, so that the tool and the Python module name the
// same field and the same range. Header-only, no dependency but the library.
#ifndef POWERKEY_TOOL_REFUSAL_HPP
#define POWERKEY_TOOL_REFUSAL_HPP

#include <powerkey/canopen/node_id.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/keypad/models.hpp>

#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

namespace tool {

struct refusal {
    enum class what : unsigned char {
        not_for_model,  // the model has no such message at all: even its defaults are refused
        field,          // `field` holds a value the model does not take; it takes 1..`most`
        other,          // no single field explains it: encode's error says why
    };
    what kind = what::other;
    std::string_view field;  // what::field: the field's name (static storage)
    unsigned most = 0;       // what::field: the largest n in 1..64 the field takes alone, or 0
};

namespace detail {

// Sets field `index` of s to its value in d.
template <class S>
void reset_field(S& s, S d, std::size_t index) {
    std::size_t i = 0;
    S::fields(s, [&](std::string_view, auto& v) {
        if (i++ != index) return;
        std::size_t j = 0;
        S::fields(d, [&](std::string_view, auto& w) {
            if constexpr (std::is_same_v<decltype(v), decltype(w)>)
                if (j == index) v = w;
            ++j;
        });
    });
}

// Sets field `index` of s to the number n (a set to {n}); false when the field is no number.
template <class S>
bool set_field_number(S& s, std::size_t index, unsigned n) {
    std::size_t i = 0;
    bool done = false;
    S::fields(s, [&](std::string_view, auto& v) {
        if (i++ != index) return;
        using T = std::remove_cvref_t<decltype(v)>;
        if constexpr (powerkey::is_index_set<T>::value) {
            if (n <= T::max) v = T{n}, done = true;
        } else if constexpr (powerkey::is_bounded<T>::value) {
            if (const auto r = T::make(n)) v = *r, done = true;
        } else if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
            v = static_cast<T>(n), done = true;
        }
    });
    return done;
}

}  // namespace detail

// Whether model m has messages of kind S at all: its defaults encode, or do with one field set
// to a number a user would give: 1..64 (a key, a value), or the index of a common object (1000h
// device type, which CiA 301 makes mandatory; 1008h device name, which every keypad has).
template <class S>
bool speaks(const S& defaults, powerkey::model m, powerkey::canopen::node_id node) {
    const auto encodes = [&](const S& s) {
        return powerkey::encode(node, m, powerkey::message{s}).has_value();
    };
    if (encodes(defaults)) return true;
    std::size_t count = 0;
    S probe = defaults;
    S::fields(probe, [&count](std::string_view, auto&) { ++count; });
    for (std::size_t i = 0; i < count; ++i)
        for (unsigned n = 1; n <= 64 + 2; ++n) {
            S one = defaults;
            const unsigned value = n <= 64 ? n : n == 65 ? 0x1000 : 0x1008;
            if (detail::set_field_number(one, i, value) && encodes(one)) return true;
        }
    return false;
}

// Why encode(node, m, built) failed. `defaults` is the message as built before any field was
// given (its kind's defaults). A field is to blame when the message encodes with that field
// alone changed (back to its default, or to a number 1..64); a kind is not the model's when no
// such change of its defaults encodes either.
template <class S>
refusal explain_refusal(const S& built, const S& defaults, powerkey::model m,
                        powerkey::canopen::node_id node) {
    const auto encodes = [&](const S& s) {
        return powerkey::encode(node, m, powerkey::message{s}).has_value();
    };
    std::size_t count = 0;
    S names = built;
    S::fields(names, [&count](std::string_view, auto&) { ++count; });
    // The largest n in 1..64 field i of `from` takes (0: none).
    const auto most_of = [&](const S& from, std::size_t i) {
        unsigned most = 0;
        for (unsigned n = 1; n <= 64; ++n) {
            S one = from;
            if (detail::set_field_number(one, i, n) && encodes(one)) most = n;
        }
        return most;
    };
    for (std::size_t i = 0; i < count; ++i) {
        S back = built;
        detail::reset_field(back, defaults, i);
        const unsigned most = most_of(built, i);
        if (!encodes(back) && most == 0) continue;
        std::string_view name;
        std::size_t k = 0;
        S::fields(names, [&](std::string_view n, auto&) {
            if (k++ == i) name = n;
        });
        return {refusal::what::field, name, most};
    }
    if (!speaks(defaults, m, node)) return {refusal::what::not_for_model, {}, 0};
    return {};
}

// The same for a message of any kind; init(S&) gives a struct of the kind its defaults.
template <class Init>
refusal explain_refusal(const powerkey::message& built, powerkey::model m,
                        powerkey::canopen::node_id node, Init&& init) {
    return powerkey::visit_message(built, [&](const auto& s) -> refusal {
        using S = std::remove_cvref_t<decltype(s)>;
        S d{};
        init(d);
        return explain_refusal(s, d, m, node);
    });
}

}  // namespace tool

#endif
