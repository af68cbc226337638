// powerkey tool: the JSON lines of `decode --json`, written by hand. nlohmann/json reads the
// tool's JSON input; for writing, building a json object per frame costs about 3 times the whole
// decode (docs/performance.md has the figures), so one object per line is appended to a string
// directly, keys in a fixed order.
//
// What a line costs is the number of appends to the output string, not the formatting: the
// writer puts its bytes into an `Out`. `string_out` appends each piece to a string (for code that
// mixes its own appends with the writer's); `line_out` (text.hpp) collects a whole line in a
// stack buffer and appends it to the string once (decode --json).
#ifndef POWERKEY_TOOL_JSON_WRITER_HPP
#define POWERKEY_TOOL_JSON_WRITER_HPP

#include "text.hpp"

#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace tool::json {

// Each piece appended to the string as it comes.
class string_out {
public:
    explicit string_out(std::string& s) : s_(s) {}
    void put(char c) { s_ += c; }
    void put(std::string_view v) { s_.append(v); }
    // f(p) writes at most `max` (<= 80) bytes at p and returns how many.
    template <class F>
    void put_with(std::size_t max, F&& f) {
        char b[80];
        (void)max;
        s_.append(b, f(b));
    }
    void flush() {}

private:
    std::string& s_;
};

using tool::line_out;

namespace detail {
// The bytes a JSON string cannot hold as they are (control characters, quote, backslash) and
// those written as \u00XX to keep the line ASCII (DEL, bytes above 7Fh).
inline constexpr auto needs_escape = [] {
    std::array<bool, 256> t{};
    for (std::size_t c = 0; c < 256; ++c) t[c] = c < 0x20 || c >= 0x7F || c == '"' || c == '\\';
    return t;
}();
}  // namespace detail

template <class Out>
class basic_object_writer {
public:
    explicit basic_object_writer(Out& out) : out_(out) { out_.put('{'); }
    // Keys are the tool's and the library's names: no escaping needed.
    void key(std::string_view k) {
        if (k.size() > 64) k = k.substr(0, 64);
        out_.put_with(k.size() + 4, [&](char* p) {
            std::size_t n = 0;
            if (!first_) p[n++] = ',';
            p[n++] = '"';
            std::memcpy(p + n, k.data(), k.size());
            n += k.size();
            p[n++] = '"';
            p[n++] = ':';
            return n;
        });
        first_ = false;
    }
    // Any bytes: control characters, quotes, backslashes and bytes above 7Fh escaped (\u00XX,
    // bytes above 7Fh read as Latin-1), so that every line is valid JSON whatever the bus sent.
    void string(std::string_view s) {
        if (s.size() <= 62) {  // the common case: copied and checked in one pass
            bool plain_text = true;
            out_.put_with(s.size() + 2, [&](char* p) -> std::size_t {
                p[0] = '"';
                for (std::size_t i = 0; i < s.size(); ++i) {
                    const char c = s[i];
                    if (detail::needs_escape[static_cast<unsigned char>(c)]) {
                        plain_text = false;
                        return 0;
                    }
                    p[i + 1] = c;
                }
                p[s.size() + 1] = '"';
                return s.size() + 2;
            });
            if (plain_text) return;
        }
        out_.put('"');
        if (plain(s)) {
            out_.put(s);
        } else {
            for (char c : s) {
                const auto u = static_cast<unsigned char>(c);
                if (c == '"' || c == '\\') {
                    out_.put('\\');
                    out_.put(c);
                } else if (u < 0x20 || u >= 0x7F) {
                    const char e[6] = {'\\', 'u', '0', '0', upper_hex[u >> 4], upper_hex[u & 15]};
                    out_.put(std::string_view(e, 6));
                } else {
                    out_.put(c);
                }
            }
        }
        out_.put('"');
    }
    void number(std::uint64_t v) {
        out_.put_with(20, [v](char* p) {
            return static_cast<std::size_t>(std::to_chars(p, p + 20, v).ptr - p);
        });
    }
    void boolean(bool b) { out_.put(b ? std::string_view("true") : std::string_view("false")); }
    void raw(std::string_view s) { out_.put(s); }
    void raw(char c) { out_.put(c); }
    void close() { out_.put('}'); }
    Out& out() { return out_; }

    void field(std::string_view k, std::string_view v) { key(k), string(v); }
    void field(std::string_view k, std::uint64_t v) { key(k), number(v); }
    void field_bool(std::string_view k, bool v) { key(k), boolean(v); }

private:
    Out& out_;
    bool first_ = true;
};

namespace detail {
struct string_out_member {  // constructed before the writer that uses it
    string_out own;
};
}  // namespace detail

// A writer straight into a string (its pieces appended as they come).
class object_writer : private detail::string_out_member, public basic_object_writer<string_out> {
public:
    explicit object_writer(std::string& s)
        : detail::string_out_member{string_out(s)}, basic_object_writer(own) {}
};

}  // namespace tool::json

#endif
