// powerkey tool: the JSON lines of `decode --json`, written by hand. nlohmann/json reads the
// tool's JSON input; for writing, building a json object per frame costs about 3 times the whole
// decode (docs/performance.md has the figures), so one object per line is appended to a string
// directly, keys in a fixed order.
#ifndef POWERKEY_TOOL_JSON_WRITER_HPP
#define POWERKEY_TOOL_JSON_WRITER_HPP

#include "text.hpp"

#include <cstdint>
#include <string>
#include <string_view>

namespace tool::json {

class object_writer {
public:
    explicit object_writer(std::string& out) : out_(out) { out_ += '{'; }
    // Keys are the tool's own constants: no escaping needed.
    void key(std::string_view k) {
        // `,"key":` in one append: the writer's cost is in the number of appends.
        char b[72];
        std::size_t n = 0;
        if (!first_) b[n++] = ',';
        first_ = false;
        if (k.size() > 64) k = k.substr(0, 64);
        b[n++] = '"';
        for (char c : k) b[n++] = c;
        b[n++] = '"';
        b[n++] = ':';
        out_.append(b, n);
    }
    // Any bytes: control characters, quotes, backslashes and bytes above 7Fh escaped (\u00XX,
    // bytes above 7Fh read as Latin-1), so that every line is valid JSON whatever the bus sent.
    void string(std::string_view s) {
        if (s.size() <= 62 && plain(s)) {
            char b[64];
            b[0] = '"';
            for (std::size_t i = 0; i < s.size(); ++i) b[i + 1] = s[i];
            b[s.size() + 1] = '"';
            out_.append(b, s.size() + 2);
            return;
        }
        out_ += '"';
        if (plain(s)) {
            out_ += s;
        } else {
            for (char c : s) {
                const auto u = static_cast<unsigned char>(c);
                if (c == '"' || c == '\\') {
                    out_ += '\\';
                    out_ += c;
                } else if (u < 0x20 || u >= 0x7F) {
                    out_ += "\\u00";
                    out_ += upper_hex[u >> 4];
                    out_ += upper_hex[u & 15];
                } else {
                    out_ += c;
                }
            }
        }
        out_ += '"';
    }
    void number(std::uint64_t v) { append_decimal(out_, v); }
    void boolean(bool b) { out_ += b ? "true" : "false"; }
    void raw(std::string_view s) { out_ += s; }
    void close() { out_ += '}'; }

    void field(std::string_view k, std::string_view v) { key(k), string(v); }
    void field(std::string_view k, std::uint64_t v) { key(k), number(v); }
    void field_bool(std::string_view k, bool v) { key(k), boolean(v); }

private:
    std::string& out_;
    bool first_ = true;
};

}  // namespace tool::json

#endif
