// powerkey tool: field values as text, both ways, for every field type of the kind/fields
// convention. What the text output prints (describe() of the library), encode takes back:
//   bool                  yes/no (also true/false, on/off, 1/0)
//   integers, bounded     hex with h (3Ah) but counts and times (tick, period_ms, size, ...) in
//                         decimal, as describe() prints them; encode also takes 58 and 0x3A
//   enums                 their name from the enum's table (names.hpp; aliases are taken too), or
//                         the number (hex with h) for a value without a name
//   std::array<uint8_t>   hex bytes "72 69 6E" (with or without spaces)
//   index_set<N>          "1 7", "1-28" or "-" for none (also 1,7)
// Errors name the allowed values or range. Host-only (std::string), no other dependency: the
// Python module reads text values through the same functions. JSON: field_value.hpp.
#ifndef POWERKEY_TOOL_FIELD_TEXT_HPP
#define POWERKEY_TOOL_FIELD_TEXT_HPP

#include "numbers.hpp"
#include "text.hpp"

#include <powerkey/describe.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/names.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

namespace tool {

// --- enums by name ------------------------------------------------------------------------------

// The names of an enum in value order, for error messages ("start, stop, ..."), at most 12:
// straight from its table (names.hpp), first names only.
template <class E>
std::string enum_name_list() {
    std::string s;
    std::size_t i = 0;
    const auto values = powerkey::enum_values<E>();
    for (const E v : values) {
        if (i == 12) break;
        s.append(i++ ? ", " : "").append(powerkey::to_string(v));
    }
    if (values.size() > 12) s += ", ... (" + std::to_string(values.size()) + " names)";
    return s;
}

// --- message kinds ------------------------------------------------------------------------------

// A message kind as people write it: led-on or led_on; the kinds of the old per-family profiles
// (pk1000_led_on, pkp_led_on) are the same message, and the spellings before kinds were their
// structs' names (nmt for nmt_message: powerkey::current_kind) still read.
inline std::string kind_name(std::string_view text) {
    std::string name(text);
    for (char& c : name)
        if (c == '-') c = '_';
    for (std::string_view prefix : {"pk1000_", "pkp_"})
        if (name.starts_with(prefix)) name.erase(0, prefix.size());
    return std::string(powerkey::current_kind(name));
}

// --- numbers ------------------------------------------------------------------------------------

// Fields whose numbers print in hex (with h): all but counts and times, the rule of describe()
// (powerkey::is_decimal_field), so that errors quote ranges the way decode's text prints values.
inline bool hex_field(std::string_view name) { return !powerkey::is_decimal_field(name); }

// --- text ---------------------------------------------------------------------------------------

template <class T>
constexpr std::uint64_t max_of() {
    if constexpr (powerkey::is_bounded<T>::value)
        return T::max;
    else
        return std::numeric_limits<T>::max();
}

// Appends the text form of a field value: describe()'s own (describe_value), so list, errors and
// decode's text agree.
template <class T>
void write_text_value(std::string& out, std::string_view name, const T& v) {
    std::array<char, powerkey::description_capacity> buf{};
    powerkey::text_writer w(buf);
    powerkey::describe_value(w, name, v);
    out += w.view();
}

// --- reading ------------------------------------------------------------------------------------

// The range of a number field, for error messages: "0..63", "1..7Fh".
template <class T>
std::string range_of(std::string_view name) {
    std::uint64_t lo = 0;
    if constexpr (powerkey::is_bounded<T>::value) lo = T::min;
    std::string s;
    auto put = [&](std::uint64_t v) {
        if (hex_field(name))
            append_hex_h(s, v, hex_digits(max_of<T>()));
        else
            append_decimal(s, v);
    };
    put(lo);
    s += "..";
    put(max_of<T>());
    return s;
}

template <class T>
std::string set_from_number(T& v, std::uint64_t n, std::string_view name);

// Sets v from text (the command line, or a JSON string). Returns "" or what is wrong, naming the
// allowed values or range; the caller puts the field's name in front.
template <class T>
std::string set_from_text(T& v, std::string_view s, std::string_view name = "") {
    const std::string shown = "'" + escape(s, 32) + "'";
    if constexpr (std::is_same_v<T, bool>) {
        if (s == "yes" || s == "true" || s == "on" || s == "1") return v = true, "";
        if (s == "no" || s == "false" || s == "off" || s == "0") return v = false, "";
        return shown + " is not yes or no (also true/false, on/off, 1/0)";
    } else if constexpr (std::is_enum_v<T>) {
        using U = std::underlying_type_t<T>;
        if (const auto named = powerkey::from_string<T>(s)) return v = *named, "";
        std::uint64_t n = 0;
        if (!parse_number(s, n)) return "unknown name " + shown + " (" + enum_name_list<T>() + ")";
        if (n > std::numeric_limits<U>::max())
            return shown + " is outside 0.." + std::to_string(std::numeric_limits<U>::max());
        v = static_cast<T>(static_cast<U>(n));
        return "";
    } else if constexpr (powerkey::is_index_set<T>::value) {
        T set{};
        if (s == "-" || s.empty()) return v = set, "";
        const std::string range = "1.." + std::to_string(T::max);
        while (!s.empty()) {
            const auto sep = s.find_first_of(", ");
            const auto item = s.substr(0, sep);
            s.remove_prefix(sep == std::string_view::npos ? s.size() : sep + 1);
            if (item.empty()) continue;
            const auto dash = item.find('-');
            std::uint64_t a = 0, b = 0;
            if (!parse_number(item.substr(0, dash), a) ||
                (dash != std::string_view::npos && !parse_number(item.substr(dash + 1), b)))
                return shown + " is not a list of numbers like 1,7 or 1-28 or -";
            if (dash == std::string_view::npos) b = a;
            if (a < 1 || b > T::max || a > b)
                return "'" + escape(item, 32) + "' is outside " + range;
            for (auto i = a; i <= b; ++i) set.insert(static_cast<unsigned>(i));
        }
        v = set;
        return "";
    } else if constexpr (powerkey::is_byte_array<T>::value) {
        T bytes{};
        std::size_t n = 0;
        const std::string expected =
            " is not hex bytes (at most " + std::to_string(v.size()) + ", like 72 69 6E or 72696E)";
        for (std::size_t i = 0; i < s.size();) {
            if (s[i] == ' ') {
                ++i;
                continue;
            }
            const int hi = i + 1 < s.size() ? hex_digit(s[i]) : -1;
            const int lo = i + 1 < s.size() ? hex_digit(s[i + 1]) : -1;
            if (hi < 0 || lo < 0 || n == v.size()) return shown + expected;
            bytes[n++] = static_cast<std::uint8_t>((hi << 4) | lo);
            i += 2;
        }
        v = bytes;
        return "";
    } else {
        std::uint64_t n = 0;
        if (!parse_number(s, n))
            return shown + " is not a number (58, 0x3A or 3Ah; " + range_of<T>(name) + ")";
        return set_from_number(v, n, name);
    }
}

template <class T>
std::string set_from_number(T& v, std::uint64_t n, std::string_view name) {
    if constexpr (powerkey::is_bounded<T>::value) {
        const auto r = T::make(n);
        if (!r) return std::to_string(n) + " is outside " + range_of<T>(name);
        v = *r;
        return "";
    } else if constexpr (std::is_same_v<T, bool>) {
        if (n > 1) return std::to_string(n) + " is not yes or no";
        v = n == 1;
        return "";
    } else if constexpr (std::is_enum_v<T>) {
        using U = std::underlying_type_t<T>;
        if (n > std::numeric_limits<U>::max())
            return std::to_string(n) + " is outside 0.." +
                   std::to_string(std::numeric_limits<U>::max());
        v = static_cast<T>(static_cast<U>(n));
        return "";
    } else if constexpr (std::is_integral_v<T>) {
        if (n > std::numeric_limits<T>::max())
            return std::to_string(n) + " is outside " + range_of<T>(name);
        v = static_cast<T>(n);
        return "";
    } else if constexpr (powerkey::is_index_set<T>::value) {
        return "expected a list like [1,7]";
    } else {
        return "expected hex bytes like \"72696E\"";
    }
}

}  // namespace tool

#endif
