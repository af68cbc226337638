// powerkey tool: writing text fast and safely. Every string that comes from the bus or from the
// user's input (uploaded device names, a log line quoted in an error) goes through escape():
// control characters, DEL, quotes, backslashes and bytes above 7Fh are written as \xNN (so no
// escape sequence reaches the terminal), and long strings are cut with "...".
#ifndef POWERKEY_TOOL_TEXT_HPP
#define POWERKEY_TOOL_TEXT_HPP

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace tool {

inline constexpr char upper_hex[] = "0123456789ABCDEF";

// One byte as \xHH, the escape of every writer of untrusted text (this one, the JUnit XML of
// `check`).
inline void append_hex_escape(std::string& out, unsigned char u) {
    const char e[4] = {'\\', 'x', upper_hex[u >> 4], upper_hex[u & 15]};
    out.append(e, 4);
}

// At most `max` characters of s (then "..."), escaped.
inline void append_escaped(std::string& out, std::string_view s, std::size_t max = 64) {
    const bool cut = s.size() > max;
    if (cut) s = s.substr(0, max);
    for (char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u >= 0x7F || c == '"' || c == '\\') {
            append_hex_escape(out, u);
        } else {
            out += c;
        }
    }
    if (cut) out += "...";
}

inline std::string escape(std::string_view s, std::size_t max = 64) {
    std::string out;
    append_escaped(out, s, max);
    return out;
}

// True when s can be written as it is (the common case, checked before escaping).
inline bool plain(std::string_view s) {
    for (char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u >= 0x7F || c == '"' || c == '\\') return false;
    }
    return true;
}

// One append per number: appending digit by digit costs more than the rest of a line.
inline void append_hex(std::string& out, std::uint64_t v, int digits) {
    char b[17];
    const int n = digits > 16 ? 16 : digits;
    for (int i = 0; i < n; ++i) b[i] = upper_hex[(v >> (4 * (n - 1 - i))) & 15];
    out.append(b, static_cast<std::size_t>(n));
}

// A node id, COB-ID, address ...: fixed digits and an h, as the manuals write them ("3Ah").
inline void append_hex_h(std::string& out, std::uint64_t v, int digits) {
    char b[18];
    const int n = digits > 16 ? 16 : digits;
    for (int i = 0; i < n; ++i) b[i] = upper_hex[(v >> (4 * (n - 1 - i))) & 15];
    b[n] = 'h';
    out.append(b, static_cast<std::size_t>(n) + 1);
}

// Bytes as hex digits, "0102AB", in one append.
inline void append_hex_bytes(std::string& out, const std::uint8_t* data, std::size_t n) {
    char b[128];
    if (n > 64) n = 64;
    for (std::size_t i = 0; i < n; ++i) {
        b[2 * i] = upper_hex[data[i] >> 4];
        b[2 * i + 1] = upper_hex[data[i] & 15];
    }
    out.append(b, 2 * n);
}

inline void append_decimal(std::string& out, std::uint64_t v) {
    char b[24];
    const auto r = std::to_chars(b, b + sizeof b, v);
    out.append(b, static_cast<std::size_t>(r.ptr - b));
}

// Hex digits needed for the largest value of a field.
inline constexpr int hex_digits(std::uint64_t max) {
    int d = 1;
    while (max > 15) {
        max >>= 4;
        ++d;
    }
    return d;
}

// What a line of output costs is the number of appends to the output string, not the
// formatting. A line in a stack buffer, appended to the string when full and when flushed:
// one append a line.
class line_out {
public:
    explicit line_out(std::string& s) : s_(s) {}
    line_out(const line_out&) = delete;
    line_out& operator=(const line_out&) = delete;
    ~line_out() { flush(); }
    void put(char c) {
        if (n_ == capacity) flush();
        b_[n_++] = c;
    }
    void put(std::string_view v) {
        if (v.size() > capacity - n_) {
            flush();
            if (v.size() > capacity) return s_.append(v), void();
        }
        std::memcpy(b_ + n_, v.data(), v.size());
        n_ += v.size();
    }
    template <class F>
    void put_with(std::size_t max, F&& f) {
        if (max > capacity - n_) flush();
        n_ += f(b_ + n_);
    }
    void flush() {
        s_.append(b_, n_);
        n_ = 0;
    }

private:
    static constexpr std::size_t capacity = 1024;
    std::string& s_;
    char b_[capacity];
    std::size_t n_ = 0;
};

}  // namespace tool

#endif
