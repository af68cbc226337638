// powerkey tool: one line of a bus log, in any of the three forms people paste:
//   (1700000000.000000) can0 195#0900000012     candump -l files and candump -L output
//   195#0900000012                              cansend arguments
//   (1700000000.000000)  can0  195   [5]  09 00 00 00 12
//                                               candump's own screen output, timestamp optional
// Blank lines and lines starting with '#' or "//" are not frames.
#ifndef POWERKEY_TOOL_LOG_LINE_HPP
#define POWERKEY_TOOL_LOG_LINE_HPP

#include <powerkey/can/candump.hpp>
#include <powerkey/detail/hex.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace tool {

struct log_line {
    std::string_view time;       // without the parentheses; empty when the line had none
    std::string_view interface;  // empty when the line had none
    powerkey::can::frame frame;
};

enum class line_kind { frame, skip, bad };

struct parsed_line {
    line_kind kind = line_kind::skip;
    log_line line;
    std::string_view problem;  // for bad lines: what is wrong, one short phrase
};

namespace detail {
inline std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() &&
           (s.back() == ' ' || s.back() == '\t' || s.back() == '\r' || s.back() == '\n'))
        s.remove_suffix(1);
    return s;
}
inline std::string_view next_token(std::string_view& s) {
    s = trim(s);
    std::size_t n = 0;
    while (n < s.size() && s[n] != ' ' && s[n] != '\t') ++n;
    const auto t = s.substr(0, n);
    s.remove_prefix(n);
    return t;
}
inline bool all_hex(std::string_view s) {
    for (char c : s)
        if (powerkey::detail::hex_value(c) < 0) return false;
    return !s.empty();
}
inline std::string_view candump_problem(powerkey::errc e) {
    switch (e) {
        case powerkey::errc::value_out_of_range: return "identifier out of range";
        case powerkey::errc::wrong_length: return "more than 8 data bytes";
        default: return "malformed frame (expected ID#DATA)";
    }
}
}  // namespace detail

inline parsed_line parse_log_line(std::string_view text) {
    parsed_line out;
    std::string_view s = detail::trim(text);
    if (s.empty() || s.front() == '#' || s.substr(0, 2) == "//") return out;
    out.kind = line_kind::bad;
    if (s.front() == '(') {
        const auto close = s.find(')');
        if (close == std::string_view::npos) {
            out.problem = "unclosed timestamp";
            return out;
        }
        out.line.time = s.substr(1, close - 1);
        s.remove_prefix(close + 1);
    }
    std::string_view rest = s;
    std::string_view first = detail::next_token(rest);
    std::string_view frame_text;
    if (first.find('#') != std::string_view::npos) {
        frame_text = first;  // cansend form, maybe after a timestamp
    } else {
        out.line.interface = first;
        std::string_view second = detail::next_token(rest);
        if (second.find('#') != std::string_view::npos) {
            frame_text = second;  // candump -L form
        } else {
            // candump screen form: ID [n] bytes...
            std::string_view len = detail::next_token(rest);
            if (!detail::all_hex(second) || len.size() < 3 || len.front() != '[' ||
                len.back() != ']') {
                out.problem = "not a frame (expected ID#DATA or a candump line)";
                return out;
            }
            std::array<char, 8 + 1 + 16> buf{};
            std::size_t n = 0;
            if (second.size() != 3 && second.size() != 8) {
                out.problem = "identifier of other than 3 or 8 digits";
                return out;
            }
            for (char c : second) buf[n++] = c;
            buf[n++] = '#';
            std::size_t bytes = 0;
            for (auto b = detail::next_token(rest); !b.empty(); b = detail::next_token(rest)) {
                if (b.size() != 2 || !detail::all_hex(b)) {
                    out.problem = "data bytes must be two hex digits each";
                    return out;
                }
                if (++bytes > 8) {
                    out.problem = "more than 8 data bytes";
                    return out;
                }
                buf[n++] = b[0];
                buf[n++] = b[1];
            }
            const auto count = len.substr(1, len.size() - 2);
            if (count.size() != 1 || count[0] - '0' != static_cast<int>(bytes)) {
                out.problem = "the [length] does not match the data bytes";
                return out;
            }
            const auto f = powerkey::can::parse_candump({buf.data(), n});
            if (!f) {
                out.problem = detail::candump_problem(f.error());
                return out;
            }
            out.kind = line_kind::frame;
            out.line.frame = *f;
            return out;
        }
    }
    if (!detail::trim(rest).empty()) {
        out.problem = "unexpected text after the frame";
        return out;
    }
    if (frame_text.find("##") != std::string_view::npos) {
        out.problem = "CAN FD frames are not supported";
        return out;
    }
    if (frame_text.find('R') != std::string_view::npos &&
        frame_text.find('#') + 1 < frame_text.size() &&
        frame_text[frame_text.find('#') + 1] == 'R') {
        out.problem = "remote frames are not supported";
        return out;
    }
    const auto f = powerkey::can::parse_candump(frame_text);
    if (!f) {
        out.problem = detail::candump_problem(f.error());
        return out;
    }
    out.kind = line_kind::frame;
    out.line.frame = *f;
    return out;
}

}  // namespace tool

#endif
