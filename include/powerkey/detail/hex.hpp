// powerkey detail: hex digits, both ways, constexpr.
#ifndef POWERKEY_DETAIL_HEX_HPP
#define POWERKEY_DETAIL_HEX_HPP

namespace powerkey::detail {

// 0..15, or -1 for a character that is not a hex digit.
constexpr int hex_value(char c) noexcept {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

// The upper-case digit of the low four bits of v.
constexpr char hex_digit(unsigned v) noexcept { return "0123456789ABCDEF"[v & 0xFu]; }

}  // namespace powerkey::detail

#endif  // POWERKEY_DETAIL_HEX_HPP
