// powerkey tool: field values both ways, for every field type of the kind/fields convention.
// What the text output prints, encode accepts back:
//   bool                  yes/no (also true/false, on/off, 1/0); JSON true/false
//   integers, bounded     decimal, or hex with h for node ids, COB-IDs, addresses and identity
//                         and mapping words (3Ah); encode also takes 58 and 0x3A
//   enums                 their stable name, or the number (hex with h) when it has no unique name
//   std::array<uint8_t>   hex bytes "72 69 6E" (with or without spaces); JSON "72696E"
//   index_set<N>          "1 7", "1-28" or "-" for none (also 1,7); JSON [1,7]
// Reading JSON goes through nlohmann::json; writing JSON through json_writer.hpp.
#ifndef POWERKEY_TOOL_FIELD_VALUE_HPP
#define POWERKEY_TOOL_FIELD_VALUE_HPP

#include "json_writer.hpp"
#include "text.hpp"

#include <nlohmann/json.hpp>
#include <powerkey/fields.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace tool {

// --- enums by name ------------------------------------------------------------------------------

// Name -> value of an enum, built once by trying values through enum_name. Types of one or two
// bytes are tried in full; wider ones (the 32-bit SDO abort codes) over every value whose low 8
// bits and high 16 bits may be non-zero (CiA 301 codes are of the form 0xMMMM'00LL and
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

// The names of an enum in value order, for error messages ("start, stop, ..."), at most 12.
template <class E>
std::string enum_name_list() {
    std::vector<std::pair<std::uint64_t, std::string_view>> v;
    for (const auto& [name, value] : enum_names<E>())
        v.emplace_back(static_cast<std::uint64_t>(value), name);
    std::sort(v.begin(), v.end());
    std::string s;
    for (std::size_t i = 0; i < v.size() && i < 12; ++i)
        s.append(i ? ", " : "").append(v[i].second);
    if (v.size() > 12) s += ", ... (" + std::to_string(v.size()) + " names)";
    return s;
}

// True when v has a name that means v (not NMT's legacy stop 00h, whose name 02h has taken).
// Asked once per enumerator a line prints: one-byte and two-byte enums answer from a table made
// once, wider ones (SDO abort codes) from a cache of the codes seen.
template <class E>
bool has_unique_name(E v) {
    using U = std::underlying_type_t<E>;
    auto compute = [](E x) {
        const auto n = powerkey::enum_name(x);
        if (n.empty()) return false;
        const auto& names = enum_names<E>();
        const auto it = names.find(n);
        return it != names.end() && it->second == static_cast<U>(x);
    };
    if constexpr (sizeof(U) <= 2) {
        static const auto table = [&compute] {
            std::vector<bool> t(std::size_t{std::numeric_limits<U>::max()} + 1);
            for (std::size_t x = 0; x < t.size(); ++x) t[x] = compute(static_cast<E>(x));
            return t;
        }();
        return table[static_cast<std::size_t>(v)];
    } else {
        // A log holds a handful of distinct codes: a short list beats hashing.
        static std::vector<std::pair<U, bool>> seen;
        for (const auto& [code, unique] : seen)
            if (code == static_cast<U>(v)) return unique;
        const bool unique = compute(v);
        if (seen.size() < 256) seen.emplace_back(static_cast<U>(v), unique);
        return unique;
    }
}

// --- numbers ------------------------------------------------------------------------------------

inline int hex_digit_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

// 58, 0x3A or 3Ah.
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
        const int d = hex_digit_value(c);
        if (d < 0 || d >= base) return false;
        if (base == 10 && v > (std::numeric_limits<std::uint64_t>::max() - 9) / 10) return false;
        v = v * static_cast<std::uint64_t>(base) + static_cast<std::uint64_t>(d);
    }
    out = v;
    return true;
}

// Fields whose numbers the manuals write in hex: node ids, COB-IDs, J1939 addresses and PGNs.
// `context` is the name of the object an SDO value belongs to (identity and mapping words).
inline bool hex_field(std::string_view name, std::string_view context) {
    constexpr std::string_view names[] = {"target",  "new_node_id", "new_node",    "node",
                                          "node_id", "source",      "destination", "can_id",
                                          "cob_id",  "pgn",         "index"};
    for (auto n : names)
        if (n == name) return true;
    if (name.find("mapping") != std::string_view::npos ||
        name.find("address") != std::string_view::npos)
        return true;
    if (name == "value") {
        constexpr std::string_view words[] = {"vendor",   "product", "revision", "serial",
                                              "identity", "mapping", "cob",      "node"};
        for (auto w : words)
            if (context.find(w) != std::string_view::npos) return true;
    }
    return false;
}

// --- text ---------------------------------------------------------------------------------------

template <class T>
constexpr std::uint64_t max_of() {
    if constexpr (powerkey::is_bounded<T>::value)
        return T::max;
    else
        return std::numeric_limits<T>::max();
}

// Appends the text form of a field value.
template <class T>
void write_text_value(std::string& out, std::string_view name, std::string_view context,
                      const T& v) {
    if constexpr (std::is_same_v<T, bool>) {
        out += v ? "yes" : "no";
    } else if constexpr (std::is_enum_v<T>) {
        if (has_unique_name(v))
            out += powerkey::enum_name(v);
        else
            append_hex_h(out, static_cast<std::uint64_t>(v), 2 * static_cast<int>(sizeof(T)));
    } else if constexpr (powerkey::is_index_set<T>::value) {
        if (v.empty()) out += '-';
        bool first = true;
        for (unsigned i = 1; i <= T::max; ++i) {
            if (!v.contains(i)) continue;
            unsigned last = i;  // three or more in a row print as a range, "1-28"
            while (last < T::max && v.contains(last + 1)) ++last;
            if (!first) out += ' ';
            first = false;
            append_decimal(out, i);
            if (last >= i + 2) {
                out += '-';
                append_decimal(out, last);
                i = last;
            }
        }
    } else if constexpr (powerkey::is_byte_array<T>::value) {
        for (std::size_t i = 0; i < v.size(); ++i) {
            if (i != 0) out += ' ';
            append_hex(out, v[i], 2);
        }
    } else {
        std::uint64_t n = 0;
        if constexpr (powerkey::is_bounded<T>::value)
            n = v.value();
        else
            n = static_cast<std::uint64_t>(v);
        if (hex_field(name, context))
            append_hex_h(out, n, hex_digits(max_of<T>()));
        else
            append_decimal(out, n);
    }
}

// --- JSON writing -------------------------------------------------------------------------------

template <class T>
void write_json_value(json::object_writer& w, const T& v) {
    if constexpr (std::is_same_v<T, bool>) {
        w.boolean(v);
    } else if constexpr (std::is_enum_v<T>) {
        if (has_unique_name(v))
            w.string(powerkey::enum_name(v));
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
        for (auto b : v) append_hex(hex, b, 2);
        w.string(hex);
    } else if constexpr (powerkey::is_bounded<T>::value) {
        w.number(v.value());
    } else {
        static_assert(std::is_integral_v<T>, "a field type outside the kind/fields convention");
        w.number(static_cast<std::uint64_t>(v));
    }
}

// --- reading ------------------------------------------------------------------------------------

// The range of a number field, for error messages: "0..63", "1..7Fh".
template <class T>
std::string range_of(std::string_view name) {
    std::uint64_t lo = 0;
    if constexpr (powerkey::is_bounded<T>::value) lo = T::min;
    std::string s;
    auto put = [&](std::uint64_t v) {
        if (hex_field(name, ""))
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
        const auto& names = enum_names<T>();
        if (const auto it = names.find(s); it != names.end())
            return v = static_cast<T>(it->second), "";
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
            const int hi = i + 1 < s.size() ? hex_digit_value(s[i]) : -1;
            const int lo = i + 1 < s.size() ? hex_digit_value(s[i + 1]) : -1;
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

template <class T>
std::string set_from_json(T& v, const nlohmann::json& j, std::string_view name = "") {
    if (j.is_string()) return set_from_text(v, j.get_ref<const std::string&>(), name);
    if (j.is_number_unsigned()) return set_from_number(v, j.get<std::uint64_t>(), name);
    if (j.is_number_integer()) return "a negative number";
    if (j.is_boolean()) {
        if constexpr (std::is_same_v<T, bool>) return v = j.get<bool>(), "";
        return "unexpected true/false";
    }
    if (j.is_array()) {
        if constexpr (powerkey::is_index_set<T>::value) {
            T set{};
            for (const auto& item : j) {
                if (!item.is_number_unsigned() || item.get<std::uint64_t>() < 1 ||
                    item.get<std::uint64_t>() > T::max)
                    return "expected numbers 1.." + std::to_string(T::max);
                set.insert(static_cast<unsigned>(item.get<std::uint64_t>()));
            }
            v = set;
            return "";
        }
        return "unexpected array";
    }
    return "unexpected value";
}

}  // namespace tool

#endif
