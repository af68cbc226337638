// powerkey: the candump / cansend text form of a frame (615#4000200100000000, 18EF2100#041B80,
// 080#: an id of exactly 3 or 8 hex digits, 0..8 data bytes, no R, no ##), both ways, at compile
// time too. Formatting writes upper case, as candump does.
#ifndef POWERKEY_CAN_CANDUMP_HPP
#define POWERKEY_CAN_CANDUMP_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/detail/hex.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace powerkey::can {

namespace detail {
// Not constexpr: reaching it in a consteval parse is a compile error naming the problem.
inline void candump_literal_is_malformed() noexcept {}
}  // namespace detail

// Parse "ID#DATA". Errors: syntax_error (anything malformed: a missing '#', an id of other than
// 3 or 8 digits, a non-hex digit, an odd number of data digits), value_out_of_range (a 3-digit id
// above 7FFh or an 8-digit id above 1FFFFFFFh), wrong_length (more than 8 data bytes).
[[nodiscard]] constexpr result<frame> parse_candump(std::string_view text) noexcept {
    const auto hash = text.find('#');
    if (hash == std::string_view::npos) return errc::syntax_error;
    const auto id_text = text.substr(0, hash);
    const auto data_text = text.substr(hash + 1);
    if (id_text.size() != 3 && id_text.size() != 8) return errc::syntax_error;
    std::uint32_t id = 0;
    for (char c : id_text) {
        const int v = powerkey::detail::hex_value(c);
        if (v < 0) return errc::syntax_error;
        id = (id << 4) | static_cast<std::uint32_t>(v);
    }
    if (data_text.size() % 2 != 0) return errc::syntax_error;
    if (data_text.size() > 16) return errc::wrong_length;
    payload p{};
    const std::size_t n = data_text.size() / 2;
    for (std::size_t i = 0; i < n; ++i) {
        const int hi = powerkey::detail::hex_value(data_text[2 * i]);
        const int lo = powerkey::detail::hex_value(data_text[2 * i + 1]);
        if (hi < 0 || lo < 0) return errc::syntax_error;
        p[i] = static_cast<std::uint8_t>((hi << 4) | lo);
    }
    const auto length = dlc::make(n).value();
    if (id_text.size() == 3) {
        const auto sid = standard_id::make(id);
        if (!sid) return errc::value_out_of_range;
        return frame(*sid, length, p);
    }
    const auto eid = extended_id::make(id);
    if (!eid) return errc::value_out_of_range;
    return frame(*eid, length, p);
}

// A frame written as a literal in the candump form; malformed text does not compile.
[[nodiscard]] consteval frame candump(std::string_view text) noexcept {
    const auto r = parse_candump(text);
    if (!r) detail::candump_literal_is_malformed();
    return r.value();
}

// The text of one frame: at most 8 + 1 + 16 characters, no terminator needed.
class candump_text {
public:
    static constexpr std::size_t capacity = 25;
    [[nodiscard]] constexpr std::string_view view() const noexcept { return {buf_.data(), size_}; }
    constexpr operator std::string_view() const noexcept { return view(); }
    friend constexpr bool operator==(const candump_text& a, std::string_view b) noexcept {
        return a.view() == b;
    }

private:
    friend constexpr candump_text format_candump(const frame& f) noexcept;
    std::array<char, capacity> buf_{};
    std::size_t size_ = 0;
};

[[nodiscard]] constexpr candump_text format_candump(const frame& f) noexcept {
    candump_text t;
    const int digits = f.is_extended() ? 8 : 3;
    for (int i = digits - 1; i >= 0; --i)
        t.buf_[t.size_++] = powerkey::detail::hex_digit(f.raw_id() >> (4 * i));
    t.buf_[t.size_++] = '#';
    for (std::uint8_t b : f.data()) {
        t.buf_[t.size_++] = powerkey::detail::hex_digit(b >> 4);
        t.buf_[t.size_++] = powerkey::detail::hex_digit(b);
    }
    return t;
}

}  // namespace powerkey::can

#endif  // POWERKEY_CAN_CANDUMP_HPP
