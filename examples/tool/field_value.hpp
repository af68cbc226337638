// powerkey tool: field values both ways, generated from the kind/fields convention.
//   bool                  JSON true/false; on the command line true/false, yes/no, on/off, 1/0
//   integers, bounded     JSON numbers; on the command line 58, 0x3A or 3Ah
//   enums                 their stable name, or the number when the value has no unique name
//   std::array<uint8_t>   a hex string, "0102AB" (JSON and command line)
//   index_set<N>          JSON array [1,7]; on the command line 1,7 or - for none
#ifndef POWERKEY_TOOL_FIELD_VALUE_HPP
#define POWERKEY_TOOL_FIELD_VALUE_HPP

#include "json.hpp"

#include <powerkey/detail/hex.hpp>
#include <powerkey/fields.hpp>

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_map>

namespace tool {

// --- enums by name ------------------------------------------------------------------------------

// Name -> value of an enum, built once by trying values through its to_string. Types of one or
// two bytes are tried in full; wider ones (the 32-bit SDO abort codes) over every value whose
// low 8 bits and high 16 bits may be non-zero (CiA 301 codes are of the form 0xMMMM'00LL and
// 0xMMMM'LLLL with small LL). When two values share a name the higher one keeps it (NMT 02h stop,
// not the legacy 00h) and the lower one is written as a number.
template <class E>
const std::unordered_map<std::string_view, std::underlying_type_t<E>>& enum_names() {
    using U = std::underlying_type_t<E>;
    static const auto table = [] {
        std::unordered_map<std::string_view, U> t;
        auto add = [&t](U v) {
            const auto n = powerkey::enum_name(static_cast<E>(v));
            if (!n.empty()) t.emplace(n, v);  // scanning downwards: the first (highest) stays
        };
        if constexpr (sizeof(U) <= 2) {
            for (std::uint32_t v = std::numeric_limits<U>::max() + 1u; v-- > 0;)
                add(static_cast<U>(v));
        } else {
            for (std::uint32_t hi = 0x1000; hi-- > 0;)
                for (std::uint32_t lo = 0x100; lo-- > 0;) add(static_cast<U>((hi << 16) | lo));
        }
        return t;
    }();
    return table;
}

// --- numbers ------------------------------------------------------------------------------------

inline bool parse_number(std::string_view s, std::uint64_t& out) {
    int base = 10;
    if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        base = 16;
        s.remove_prefix(2);
    } else if (s.size() > 1 && (s.back() == 'h' || s.back() == 'H')) {
        base = 16;
        s.remove_suffix(1);
    }
    if (s.empty() || s.size() > 16) return false;
    std::uint64_t v = 0;
    for (char c : s) {
        const int d = powerkey::detail::hex_value(c);
        if (d < 0 || d >= base) return false;
        v = v * static_cast<std::uint64_t>(base) + static_cast<std::uint64_t>(d);
    }
    out = v;
    return true;
}

// --- writing ------------------------------------------------------------------------------------

template <class T>
void write_json_value(json::object_writer& w, const T& v) {
    if constexpr (std::is_same_v<T, bool>) {
        w.boolean(v);
    } else if constexpr (std::is_enum_v<T>) {
        const auto n = powerkey::enum_name(v);
        const auto& names = enum_names<T>();
        const auto it = n.empty() ? names.end() : names.find(n);
        if (it != names.end() && it->second == static_cast<std::underlying_type_t<T>>(v))
            w.string(n);
        else
            w.number(static_cast<std::uint64_t>(v));
    } else if constexpr (powerkey::is_index_set<T>::value) {
        w.raw("[");
        bool first = true;
        for (unsigned i = 1; i <= T::max; ++i) {
            if (!v.contains(i)) continue;
            if (!first) w.raw(",");
            first = false;
            w.number(i);
        }
        w.raw("]");
    } else if constexpr (powerkey::is_byte_array<T>::value) {
        std::string hex;
        for (auto b : v) {
            hex += powerkey::detail::hex_digit(b >> 4u);
            hex += powerkey::detail::hex_digit(b);
        }
        w.string(hex);
    } else if constexpr (powerkey::is_bounded<T>::value) {
        w.number(v.value());
    } else {
        static_assert(std::is_integral_v<T>, "a field type outside the kind/fields convention");
        w.number(static_cast<std::uint64_t>(v));
    }
}

// --- reading ------------------------------------------------------------------------------------

template <class T>
std::string set_from_number(T& v, std::uint64_t n);

// Sets v from text (the command line, or a JSON string). Returns "" or what is wrong.
template <class T>
std::string set_from_text(T& v, std::string_view s) {
    if constexpr (std::is_same_v<T, bool>) {
        if (s == "true" || s == "yes" || s == "on" || s == "1") return v = true, "";
        if (s == "false" || s == "no" || s == "off" || s == "0") return v = false, "";
        return "expected true or false";
    } else if constexpr (std::is_enum_v<T>) {
        using U = std::underlying_type_t<T>;
        const auto& names = enum_names<T>();
        if (const auto it = names.find(s); it != names.end())
            return v = static_cast<T>(it->second), "";
        std::uint64_t n = 0;
        if (!parse_number(s, n)) return "unknown name";
        if (n > std::numeric_limits<U>::max()) return "value out of range";
        v = static_cast<T>(static_cast<U>(n));
        return "";
    } else if constexpr (powerkey::is_index_set<T>::value) {
        T set{};
        if (s == "-" || s.empty()) return v = set, "";
        while (!s.empty()) {
            const auto comma = s.find(',');
            std::uint64_t n = 0;
            if (!parse_number(s.substr(0, comma), n)) return "expected numbers like 1,7";
            if (n < 1 || n > T::max) return "number outside 1.." + std::to_string(T::max);
            set.insert(static_cast<unsigned>(n));
            if (comma == std::string_view::npos) break;
            s.remove_prefix(comma + 1);
        }
        v = set;
        return "";
    } else if constexpr (powerkey::is_byte_array<T>::value) {
        if (s.size() % 2 != 0 || s.size() > 2 * v.size()) return "expected hex bytes";
        T bytes{};
        for (std::size_t i = 0; i < s.size() / 2; ++i) {
            const int hi = powerkey::detail::hex_value(s[2 * i]);
            const int lo = powerkey::detail::hex_value(s[2 * i + 1]);
            if (hi < 0 || lo < 0) return "expected hex bytes";
            bytes[i] = static_cast<std::uint8_t>((hi << 4) | lo);
        }
        v = bytes;
        return "";
    } else {
        std::uint64_t n = 0;
        if (!parse_number(s, n)) return "expected a number";
        return set_from_number(v, n);
    }
}

template <class T>
std::string set_from_number(T& v, std::uint64_t n) {
    if constexpr (powerkey::is_bounded<T>::value) {
        const auto r = T::make(n);
        if (!r) return "value out of range";
        v = *r;
        return "";
    } else if constexpr (std::is_same_v<T, bool>) {
        if (n > 1) return "expected true or false";
        v = n == 1;
        return "";
    } else if constexpr (std::is_enum_v<T>) {
        using U = std::underlying_type_t<T>;
        if (n > std::numeric_limits<U>::max()) return "value out of range";
        v = static_cast<T>(static_cast<U>(n));
        return "";
    } else if constexpr (std::is_integral_v<T>) {
        if (n > std::numeric_limits<T>::max()) return "value out of range";
        v = static_cast<T>(n);
        return "";
    } else {
        return "expected " + std::string(powerkey::is_index_set<T>::value ? "a list" : "hex text");
    }
}

template <class T>
std::string set_from_json(T& v, const json::value& j) {
    switch (j.t) {
        case json::value::type::string: return set_from_text(v, j.s);
        case json::value::type::number: return set_from_number(v, j.n);
        case json::value::type::boolean:
            if constexpr (std::is_same_v<T, bool>) return v = j.b, "";
            return "unexpected boolean";
        case json::value::type::array:
            if constexpr (powerkey::is_index_set<T>::value) {
                T set{};
                for (const auto& item : j.items) {
                    if (item.t != json::value::type::number || item.n < 1 || item.n > T::max)
                        return "expected numbers 1.." + std::to_string(T::max);
                    set.insert(static_cast<unsigned>(item.n));
                }
                v = set;
                return "";
            }
            return "unexpected array";
        default: return "unexpected value";
    }
}

}  // namespace tool

#endif
