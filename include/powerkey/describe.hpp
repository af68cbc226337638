// powerkey: a one-line description of any message (`node 15h  LED on  red: 1 7  green: -`),
// written into the caller's buffer, usable at compile time. The format: docs/decoder.md,
// "The description writer".
#ifndef POWERKEY_DESCRIBE_HPP
#define POWERKEY_DESCRIBE_HPP

#include <powerkey/canopen/node_id.hpp>
#include <powerkey/detail/hex.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/frame_form.hpp>
#include <powerkey/result.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>

namespace powerkey {

// Holds the description of every message of every model (tests/test_describe.cpp).
inline constexpr std::size_t description_capacity = 320;

// Appends text to a caller's buffer; remembers when something did not fit.
class text_writer {
public:
    constexpr explicit text_writer(std::span<char> out) noexcept : out_(out) {}

    constexpr void put(char c) noexcept {
        if (size_ < out_.size()) {
            out_[size_++] = c;
        } else {
            overflow_ = true;
        }
    }
    constexpr void put(std::string_view s) noexcept {
        for (char c : s) put(c);
    }
    constexpr void put_decimal(std::uint64_t v) noexcept {
        char digits[20]{};
        int n = 0;
        do {
            digits[n++] = static_cast<char>('0' + v % 10);
            v /= 10;
        } while (v != 0);
        while (n > 0) put(digits[--n]);
    }
    // `digits` upper-case hex digits, most significant first.
    constexpr void put_hex(std::uint64_t v, int digits) noexcept {
        for (int i = digits - 1; i >= 0; --i)
            put(detail::hex_digit(static_cast<unsigned>(v >> (4 * i))));
    }

    [[nodiscard]] constexpr bool overflow() const noexcept { return overflow_; }
    [[nodiscard]] constexpr std::string_view view() const noexcept { return {out_.data(), size_}; }

private:
    std::span<char> out_;
    std::size_t size_ = 0;
    bool overflow_ = false;
};

namespace detail {

// Words printed in capitals in a message title.
constexpr std::string_view upper_words[] = {"led", "sdo",  "nmt",  "pdo", "rgb",  "j1939",
                                            "id",  "rpdo", "tpdo", "cob", "rs485"};

constexpr void put_title(text_writer& w, std::string_view kind) noexcept {
    bool first = true;
    while (!kind.empty()) {
        const auto end = kind.find('_');
        const auto word = kind.substr(0, end);
        if (!first) w.put(' ');
        first = false;
        bool upper = false;
        for (auto u : upper_words) upper = upper || u == word;
        if (word == "canopen")
            w.put("CANopen");
        else
            for (char c : word)
                w.put(upper && c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c);
        if (end == std::string_view::npos) break;
        kind.remove_prefix(end + 1);
    }
}

// Field names whose numbers are counts or times, printed in decimal; all others print in hex.
constexpr std::string_view decimal_fields[] = {
    "tick",   "period_ms", "period_10ms", "size",  "bits",    "key", "subindex",
    "unused", "priority",  "encoder",     "ticks", "counter", "top"};

}  // namespace detail

// Whether describe() writes field `name`'s numbers in decimal (counts and times) or in hex with h.
[[nodiscard]] constexpr bool is_decimal_field(std::string_view name) noexcept {
    for (auto d : detail::decimal_fields)
        if (d == name) return true;
    return name.ends_with("_mv") || name.ends_with("_ms");
}

namespace detail {

constexpr void put_number(text_writer& w, std::string_view name, std::uint64_t v,
                          int width) noexcept {
    if (is_decimal_field(name)) return w.put_decimal(v);
    int digits = 2;
    while (digits < 2 * width && (v >> (4 * digits)) != 0) ++digits;
    if (name == "index") digits = 4;
    w.put_hex(v, digits);
    w.put('h');
}

template <class T>
constexpr void put_value(text_writer& w, std::string_view name, const T& v) noexcept {
    if constexpr (std::is_same_v<T, bool>) {
        w.put(v ? "yes" : "no");
    } else if constexpr (std::is_enum_v<T>) {
        const auto n = to_string(v);
        if (n.empty()) {
            w.put_hex(static_cast<std::uint64_t>(v), 2 * static_cast<int>(sizeof(T)));
            w.put('h');
        } else {
            w.put(n);
        }
    } else if constexpr (is_index_set<T>::value) {
        if (v.empty()) w.put('-');
        bool first = true;
        for (unsigned i = 1; i <= T::max; ++i) {
            if (!v.contains(i)) continue;
            unsigned last = i;  // three or more in a row print as a range, "1-28"
            while (last < T::max && v.contains(last + 1)) ++last;
            if (!first) w.put(' ');
            first = false;
            w.put_decimal(i);
            if (last >= i + 2) {
                w.put('-');
                w.put_decimal(last);
                i = last;
            }
        }
    } else if constexpr (is_byte_array<T>::value) {
        for (std::size_t i = 0; i < v.size(); ++i) {
            if (i != 0) w.put(' ');
            w.put_hex(v[i], 2);
        }
    } else if constexpr (is_bounded<T>::value) {
        put_number(w, name, v.value(), static_cast<int>(sizeof(typename T::rep)));
    } else if constexpr (std::is_integral_v<T>) {
        put_number(w, name, static_cast<std::uint64_t>(v), static_cast<int>(sizeof(T)));
    } else {
        static_assert(std::is_integral_v<T>, "a field type outside the kind/fields convention");
    }
}

}  // namespace detail

// Writes one field's value as describe() writes it after "name: " (a tool, a dissector or a
// binding that shows fields one by one shows them the same way). An overflow is w's to report.
template <class T>
constexpr void describe_value(text_writer& w, std::string_view name, const T& v) noexcept {
    detail::put_value(w, name, v);
}

// Writes the description of msg, sent to or by keypad `node`, into `out`: a view of `out`, or
// errc::buffer_too_small (`out` then holds the beginning).
template <class M>
[[nodiscard]] constexpr result<std::string_view> describe(const M& msg, canopen::node_id node,
                                                          std::span<char> out) noexcept {
    text_writer w(out);
    w.put("node ");
    w.put_hex(node.value(), 2);
    w.put("h  ");
    detail::put_title(w, kind_of(msg));
    for_each_field(msg, [&w](std::string_view name, const auto& value) {
        w.put("  ");
        w.put(name);
        w.put(": ");
        describe_value(w, name, value);
    });
    // A frame not in the manual's form says so (frame_form.hpp); the manual's form says nothing.
    visit_message(msg, [&w](const auto& s) {
        if constexpr (requires { s.form; }) {
            if (s.form != frame_form::manual) {
                w.put("  form: ");
                w.put(to_string(s.form));
            }
        }
    });
    if (w.overflow()) return errc::buffer_too_small;
    return w.view();
}

}  // namespace powerkey

#endif  // POWERKEY_DESCRIBE_HPP
