// powerkey tool: reading numbers, the one place for it. Every subcommand, option and log reader
// reads digits here: what people type (58, 0x3A, 3Ah), what logs hold (hex identifiers and
// bytes, decimal lengths) and times in seconds (--press 0.42:3, a log's 1700000000.000000).
#ifndef POWERKEY_TOOL_NUMBERS_HPP
#define POWERKEY_TOOL_NUMBERS_HPP

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

namespace tool {

namespace detail {
// The value of every byte as a hex digit, -1 for a byte that is none: one load per digit (a log
// of a million lines reads thirty million digits).
inline constexpr auto hex_values = [] {
    std::array<signed char, 256> t{};
    for (auto& v : t) v = -1;
    for (int c = '0'; c <= '9'; ++c)
        t[static_cast<std::size_t>(c)] = static_cast<signed char>(c - '0');
    for (int c = 'A'; c <= 'F'; ++c) {
        t[static_cast<std::size_t>(c)] = static_cast<signed char>(c - 'A' + 10);
        t[static_cast<std::size_t>(c - 'A' + 'a')] = static_cast<signed char>(c - 'A' + 10);
    }
    return t;
}();
}  // namespace detail

// 0..15 for a hex digit of either case, -1 for anything else.
constexpr int hex_digit(char c) noexcept {
    return detail::hex_values[static_cast<unsigned char>(c)];
}

// Digits of one base only, as logs write them (no prefix, no sign): at most 8 hex or 10 decimal
// digits whose value fits 32 bits.
constexpr bool parse_digits(std::string_view s, std::uint32_t& out, int base = 16) noexcept {
    if (s.empty() || s.size() > (base == 16 ? 8u : 10u)) return false;
    std::uint64_t v = 0;
    for (char c : s) {
        const int d = hex_digit(c);
        if (d < 0 || d >= base) return false;
        v = v * static_cast<unsigned>(base) + static_cast<unsigned>(d);
    }
    if (v > 0xFFFF'FFFFu) return false;
    out = static_cast<std::uint32_t>(v);
    return true;
}

// A number as people write it, and as the manuals and the text output do: 58, 0x3A or 3Ah.
constexpr bool parse_number(std::string_view s, std::uint64_t& out) noexcept {
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
        const int d = hex_digit(c);
        if (d < 0 || d >= base) return false;
        if (base == 10 && v > (std::numeric_limits<std::uint64_t>::max() - 9) / 10) return false;
        v = v * static_cast<std::uint64_t>(base) + static_cast<std::uint64_t>(d);
    }
    out = v;
    return true;
}

// Whether parse_seconds reads s (digits, at most one point, a digit at least, at most 12 digits
// of whole seconds), without computing the value: what a log reader checks on every line.
constexpr bool is_seconds(std::string_view s) noexcept {
    std::size_t whole = 0, fraction = 0;
    bool point = false;
    for (const char c : s) {
        if (c >= '0' && c <= '9')
            ++(point ? fraction : whole);
        else if (c == '.' && !point)
            point = true;
        else
            return false;
    }
    return whole + fraction > 0 && whole <= 12;
}

// Seconds as decimal digits with an optional fraction ("1700000000.000000", "0.42", "3"), in
// microseconds (digits past the sixth of the fraction are dropped). Nothing else: no sign, no
// exponent. nullopt past 2^62 microseconds (146,000 years).
constexpr std::optional<std::int64_t> parse_seconds(std::string_view s) noexcept {
    const auto dot = s.find('.');
    const auto whole = s.substr(0, dot);
    const auto fraction = dot == std::string_view::npos ? std::string_view{} : s.substr(dot + 1);
    if (whole.empty() && fraction.empty()) return std::nullopt;
    std::int64_t v = 0;
    for (char c : whole) {
        if (c < '0' || c > '9' || v > (std::int64_t{1} << 62) / 10'000'000) return std::nullopt;
        v = v * 10 + (c - '0');
    }
    v *= 1'000'000;
    std::int64_t scale = 100'000;
    for (char c : fraction) {
        if (c < '0' || c > '9') return std::nullopt;
        v += (c - '0') * scale;
        scale /= 10;
    }
    return v;
}

}  // namespace tool

#endif
