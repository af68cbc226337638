// powerkey tool: why encode() refused a message whose fields each held a value of their type (a
// key above a PKP-2200's four, an encoder message for a keypad without encoders): found by
// putting the model to the test, field by field, so that the tool and the Python module name the
// same field and the same range (a number's range, a set's largest number, an enumeration's
// names). Header-only, no dependency but the library and the tool's text of values.
#ifndef POWERKEY_TOOL_REFUSAL_HPP
#define POWERKEY_TOOL_REFUSAL_HPP

#include "field_text.hpp"

#include <powerkey/canopen/node_id.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/j1939_codec.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/keypad/models.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace tool {

struct refusal {
    enum class what : unsigned char {
        not_for_model,  // the model has no such message at all: even its defaults are refused
        field,          // `field` holds a value the model does not take (what it takes below)
        other,          // no single field explains it: encode's error says why
    };
    what kind = what::other;
    std::string_view field;  // what::field: the field's name (static storage)
    // What::field: what the field takes, the other fields as given. One of:
    unsigned most = 0;    // a set of numbers (keys, LEDs): 1..most
    bool number = false;  // a number: low..high (the values it takes are a range)
    std::uint64_t low = 0, high = 0;
    std::uint64_t value = 0;                   // a number: the value given
    std::array<std::string_view, 32> names{};  // an enumeration: the names it takes, in order
    std::size_t name_count = 0;
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

// Sets field `index` of s to the number n (a set to {n}); false when the field is no number or
// cannot hold n.
template <class S>
bool set_field_number(S& s, std::size_t index, std::uint64_t n) {
    std::size_t i = 0;
    bool done = false;
    S::fields(s, [&](std::string_view, auto& v) {
        if (i++ != index) return;
        using T = std::remove_cvref_t<decltype(v)>;
        if constexpr (powerkey::is_index_set<T>::value) {
            if (n >= 1 && n <= T::max) v = T{static_cast<unsigned>(n)}, done = true;
        } else if constexpr (powerkey::is_bounded<T>::value) {
            if (const auto r = T::make(n)) v = *r, done = true;
        } else if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
            if (n <= std::numeric_limits<T>::max()) v = static_cast<T>(n), done = true;
        }
    });
    return done;
}

// The largest and smallest number field `index` of `from` takes, knowing that `known` is taken:
// found by halving, for the values a field takes are a range.
template <class S, class Encodes>
void number_range(const S& from, std::size_t index, std::uint64_t known, std::uint64_t most,
                  std::uint64_t least, const Encodes& encodes, refusal& r) {
    const auto takes = [&](std::uint64_t n) {
        S one = from;
        return set_field_number(one, index, n) && encodes(one);
    };
    std::uint64_t yes = known, no = most;  // the largest: in [yes, no]
    if (takes(most)) {
        yes = most;
    } else {
        while (no - yes > 1) {
            const std::uint64_t mid = yes + (no - yes) / 2;
            (takes(mid) ? yes : no) = mid;
        }
    }
    r.high = yes;
    yes = known;  // the smallest: in [no, yes]
    no = least;
    if (takes(least)) {
        yes = least;
    } else {
        while (yes - no > 1) {
            const std::uint64_t mid = no + (yes - no) / 2;
            (takes(mid) ? yes : no) = mid;
        }
    }
    r.low = yes;
    r.number = true;
}

}  // namespace detail

// Whether model m has messages of kind S at all: its defaults encode, or do with one field set
// to a number a user would give: 1..64 (a key, a value), or the index of a common object (1000h
// device type, which CiA 301 makes mandatory; 1008h device name, which every keypad has).
template <class S>
bool speaks(const S& defaults, powerkey::model m, powerkey::canopen::node_id node,
            powerkey::j1939::keypad_address address = std::nullopt) {
    const auto encodes = [&](const S& s) {
        return powerkey::encode(node, m, powerkey::message{s}, address).has_value();
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
// such change of its defaults encodes either. `address`: the J1939 keypad encode was narrowed to
// (the tool's --address), so that the search asks the encode that refused.
template <class S>
refusal explain_refusal(const S& built, const S& defaults, powerkey::model m,
                        powerkey::canopen::node_id node,
                        powerkey::j1939::keypad_address address = std::nullopt) {
    const auto encodes = [&](const S& s) {
        return powerkey::encode(node, m, powerkey::message{s}, address).has_value();
    };
    std::size_t count = 0;
    S names = built;
    S::fields(names, [&count](std::string_view, auto&) { ++count; });
    // What field i takes, given that its default is taken (back_encodes) or the number `some`.
    const auto blame = [&](std::size_t i, bool back_encodes, std::uint64_t some) {
        refusal r{refusal::what::field, {}, 0};
        std::size_t k = 0;
        S work = built;
        S::fields(work, [&](std::string_view name, auto& v) {
            if (k++ != i) return;
            r.field = name;
            using T = std::remove_cvref_t<decltype(v)>;
            if constexpr (powerkey::is_index_set<T>::value) {
                for (unsigned n = 1; n <= T::max && n <= 64; ++n) {
                    S one = built;
                    if (detail::set_field_number(one, i, n) && encodes(one)) r.most = n;
                }
            } else if constexpr (powerkey::is_bounded<T>::value ||
                                 (std::is_integral_v<T> && !std::is_same_v<T, bool>)) {
                const auto number = [](const T& x) -> std::uint64_t {
                    if constexpr (powerkey::is_bounded<T>::value)
                        return x.value();
                    else
                        return static_cast<std::uint64_t>(x);
                };
                std::uint64_t least = 0;
                if constexpr (powerkey::is_bounded<T>::value) least = T::min;
                std::uint64_t known = some;
                if (back_encodes) {
                    S d = defaults;
                    std::size_t j = 0;
                    S::fields(d, [&](std::string_view, auto& w) {
                        if constexpr (std::is_same_v<std::remove_cvref_t<decltype(w)>, T>)
                            if (j == i) known = number(w);
                        ++j;
                    });
                }
                r.value = number(v);
                detail::number_range(built, i, known, max_of<T>(), least, encodes, r);
            } else if constexpr (std::is_enum_v<T>) {
                for (const T e : powerkey::enum_values<T>()) {
                    const T was = v;
                    v = e;
                    if (encodes(work) && r.name_count < r.names.size())
                        r.names[r.name_count++] = powerkey::to_string(e);
                    v = was;
                }
            }
        });
        return r;
    };
    // A field is to blame when the message encodes with it alone changed: back to its default,
    // or to a number 1..64.
    for (std::size_t i = 0; i < count; ++i) {
        S back = built;
        detail::reset_field(back, defaults, i);
        std::uint64_t some = 0;
        for (unsigned n = 1; n <= 64 && some == 0; ++n) {
            S one = built;
            if (detail::set_field_number(one, i, n) && encodes(one)) some = n;
        }
        const bool back_encodes = encodes(back);
        if (back_encodes || some != 0) return blame(i, back_encodes, some);
    }
    // Else an enumeration another of whose names encodes (after the numbers: changing an object
    // changes what the fields after it mean).
    for (std::size_t i = 0; i < count; ++i) {
        bool named = false;
        std::size_t k = 0;
        S probe = built;
        S::fields(probe, [&](std::string_view, auto& v) {
            using T = std::remove_cvref_t<decltype(v)>;
            if (k++ != i) return;
            if constexpr (std::is_enum_v<T>) {
                for (const T e : powerkey::enum_values<T>()) {
                    const T was = v;
                    v = e;
                    named = named || encodes(probe);
                    v = was;
                }
            }
        });
        if (named) return blame(i, false, 0);
    }
    if (!speaks(defaults, m, node, address)) return {refusal::what::not_for_model, {}, 0};
    return {};
}

// What the field of a refusal takes, after the value given (`given`, as the caller shows it):
// "'5' is more than a pkp2200 takes (1..4)", "'65536' is more than a pk1000 takes (0..65535)",
// "'3' is not what a pk1000 takes (start, stop, ...)". Numbers as the text prints the field (hex
// with h, counts and times in decimal: field_text.hpp).
inline std::string refusal_text(const refusal& r, std::string_view given,
                                std::string_view model_name) {
    std::string range;
    if (r.most > 0) {
        range = "1.." + std::to_string(r.most);
    } else if (r.number) {
        const int digits = hex_digits(r.high);
        auto put = [&](std::uint64_t v) {
            if (hex_field(r.field))
                append_hex_h(range, v, digits);
            else
                append_decimal(range, v);
        };
        put(r.low);
        range += "..";
        put(r.high);
    } else {
        for (std::size_t i = 0; i < r.name_count; ++i)
            range.append(i ? ", " : "").append(r.names[i]);
    }
    const std::string m(model_name);
    std::string text(given);
    if (r.number && r.value > r.high)
        text += " is more than a " + m + " takes";
    else if (r.number && r.value < r.low)
        text += " is less than a " + m + " takes";
    else if (r.most > 0)
        text += " is more than a " + m + " takes";
    else
        text += " is not what a " + m + " takes";
    if (!range.empty()) text += " (" + range + ")";
    return text;
}

// An addressed J1939 key contact state whose bytes read as an LED command too (identifier
// 00h..03h: docs/j1939.md, "Which way a frame goes") encodes only narrowed to its sender: without
// `address`, the text after "KIND: " that says so (give the source as the address: `--address
// 21h`, or in Python `address=0x21`), else "".
inline std::string narrowing_needed(const powerkey::message& msg, powerkey::model m,
                                    powerkey::canopen::node_id node,
                                    powerkey::j1939::keypad_address address, bool python = false) {
    const auto* k = std::get_if<powerkey::j1939::key_contact>(&msg);
    if (address || !k || !powerkey::encode(node, m, msg, k->source)) return {};
    std::string s = "addressed to ";
    append_hex_h(s, k->destination, 2);
    s += " with identifier ";
    append_hex_h(s, k->identifier, 2);
    s += ", its bytes read as an LED command too: give ";
    if (python) {
        s += "address=0x";
        append_hex(s, k->source, 2);
    } else {
        s += "--address ";
        append_hex_h(s, k->source, 2);
    }
    return s + " (the keypad's address) to encode it";
}

// The same for a message of any kind; init(S&) gives a struct of the kind its defaults.
template <class Init>
refusal explain_refusal(const powerkey::message& built, powerkey::model m,
                        powerkey::canopen::node_id node, Init&& init,
                        powerkey::j1939::keypad_address address = std::nullopt) {
    return powerkey::visit_message(built, [&](const auto& s) -> refusal {
        using S = std::remove_cvref_t<decltype(s)>;
        S d{};
        init(d);
        return explain_refusal(s, d, m, node, address);
    });
}

}  // namespace tool

#endif
