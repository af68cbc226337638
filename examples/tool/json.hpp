// powerkey tool: the little JSON the tool needs. Writing: one object per line, keys in a fixed
// order. Reading: the objects `decode --json` writes (strings, integers, booleans, null, arrays
// of integers, one nested object), with a clear error for anything else.
#ifndef POWERKEY_TOOL_JSON_HPP
#define POWERKEY_TOOL_JSON_HPP

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tool::json {

// --- writing ------------------------------------------------------------------------------------

class object_writer {
public:
    explicit object_writer(std::string& out) : out_(out) { out_ += '{'; }
    void key(std::string_view k) {
        if (!first_) out_ += ',';
        first_ = false;
        string(k);
        out_ += ':';
    }
    void string(std::string_view s) {
        out_ += '"';
        for (char c : s) {
            const auto u = static_cast<unsigned char>(c);
            if (c == '"' || c == '\\') {
                out_ += '\\';
                out_ += c;
            } else if (u < 0x20) {
                static constexpr char hex[] = "0123456789abcdef";
                out_ += "\\u00";
                out_ += hex[u >> 4];
                out_ += hex[u & 15];
            } else {
                out_ += c;
            }
        }
        out_ += '"';
    }
    void number(std::uint64_t v) { out_ += std::to_string(v); }
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

// --- reading ------------------------------------------------------------------------------------

struct value {
    enum class type { null, boolean, number, string, array, object } t = type::null;
    bool b = false;
    std::uint64_t n = 0;            // numbers: non-negative integers only
    std::string s;                  // strings
    std::vector<value> items;       // arrays
    std::vector<std::string> keys;  // objects: the keys in order, and ...
    std::vector<value> members;     // ... their values (a vector may hold an incomplete type)

    [[nodiscard]] const value* find(std::string_view k) const {
        for (std::size_t i = 0; i < keys.size(); ++i)
            if (keys[i] == k) return &members[i];
        return nullptr;
    }
};

class parser {
public:
    explicit parser(std::string_view text) : s_(text) {}

    // The value of the whole text; `error` says what is wrong when it returns false.
    bool parse(value& out, std::string& error) {
        if (!parse_value(out, 0)) {
            error = error_ + " at column " + std::to_string(pos_ + 1);
            return false;
        }
        skip_space();
        if (pos_ != s_.size()) {
            error = "unexpected text after the object at column " + std::to_string(pos_ + 1);
            return false;
        }
        return true;
    }

private:
    void skip_space() {
        while (pos_ < s_.size() &&
               (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\r' || s_[pos_] == '\n'))
            ++pos_;
    }
    bool fail(const char* what) {
        error_ = what;
        return false;
    }
    bool literal(std::string_view word) {
        if (s_.substr(pos_, word.size()) != word) return false;
        pos_ += word.size();
        return true;
    }
    bool parse_string(std::string& out) {
        if (pos_ >= s_.size() || s_[pos_] != '"') return fail("expected a string");
        ++pos_;
        while (pos_ < s_.size() && s_[pos_] != '"') {
            char c = s_[pos_++];
            if (c == '\\') {
                if (pos_ >= s_.size()) return fail("unterminated string");
                const char e = s_[pos_++];
                switch (e) {
                    case '"':
                    case '\\':
                    case '/': c = e; break;
                    case 'n': c = '\n'; break;
                    case 't': c = '\t'; break;
                    case 'r': c = '\r'; break;
                    case 'b': c = '\b'; break;
                    case 'f': c = '\f'; break;
                    case 'u': {
                        if (pos_ + 4 > s_.size()) return fail("bad \\u escape");
                        unsigned v = 0;
                        for (int i = 0; i < 4; ++i) {
                            const char h = s_[pos_++];
                            v <<= 4;
                            if (h >= '0' && h <= '9')
                                v |= static_cast<unsigned>(h - '0');
                            else if (h >= 'a' && h <= 'f')
                                v |= static_cast<unsigned>(h - 'a' + 10);
                            else if (h >= 'A' && h <= 'F')
                                v |= static_cast<unsigned>(h - 'A' + 10);
                            else
                                return fail("bad \\u escape");
                        }
                        if (v > 0x7F) return fail("only ASCII \\u escapes are supported");
                        c = static_cast<char>(v);
                        break;
                    }
                    default: return fail("bad escape");
                }
            }
            out += c;
        }
        if (pos_ >= s_.size()) return fail("unterminated string");
        ++pos_;
        return true;
    }
    bool parse_value(value& v, int depth) {
        if (depth > 4) return fail("nested too deeply");
        skip_space();
        if (pos_ >= s_.size()) return fail("unexpected end of line");
        const char c = s_[pos_];
        if (c == '{') {
            v.t = value::type::object;
            ++pos_;
            skip_space();
            if (pos_ < s_.size() && s_[pos_] == '}') return ++pos_, true;
            for (;;) {
                skip_space();
                std::string k;
                if (!parse_string(k)) return false;
                skip_space();
                if (pos_ >= s_.size() || s_[pos_] != ':') return fail("expected ':'");
                ++pos_;
                value member;
                if (!parse_value(member, depth + 1)) return false;
                v.keys.push_back(std::move(k));
                v.members.push_back(std::move(member));
                skip_space();
                if (pos_ < s_.size() && s_[pos_] == ',') {
                    ++pos_;
                    continue;
                }
                if (pos_ < s_.size() && s_[pos_] == '}') return ++pos_, true;
                return fail("expected ',' or '}'");
            }
        }
        if (c == '[') {
            v.t = value::type::array;
            ++pos_;
            skip_space();
            if (pos_ < s_.size() && s_[pos_] == ']') return ++pos_, true;
            for (;;) {
                value item;
                if (!parse_value(item, depth + 1)) return false;
                v.items.push_back(std::move(item));
                skip_space();
                if (pos_ < s_.size() && s_[pos_] == ',') {
                    ++pos_;
                    continue;
                }
                if (pos_ < s_.size() && s_[pos_] == ']') return ++pos_, true;
                return fail("expected ',' or ']'");
            }
        }
        if (c == '"') {
            v.t = value::type::string;
            return parse_string(v.s);
        }
        if (literal("true")) return v.t = value::type::boolean, v.b = true, true;
        if (literal("false")) return v.t = value::type::boolean, v.b = false, true;
        if (literal("null")) return v.t = value::type::null, true;
        if (c >= '0' && c <= '9') {
            v.t = value::type::number;
            std::uint64_t n = 0;
            while (pos_ < s_.size() && s_[pos_] >= '0' && s_[pos_] <= '9') {
                if (n > (UINT64_MAX - 9) / 10) return fail("number too large");
                n = n * 10 + static_cast<std::uint64_t>(s_[pos_++] - '0');
            }
            if (pos_ < s_.size() && (s_[pos_] == '.' || s_[pos_] == 'e' || s_[pos_] == 'E'))
                return fail("only integers are supported");
            v.n = n;
            return true;
        }
        if (c == '-') return fail("negative numbers are not supported");
        return fail("unexpected character");
    }

    std::string_view s_;
    std::size_t pos_ = 0;
    std::string error_;
};

}  // namespace tool::json

#endif
