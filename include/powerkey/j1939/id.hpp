// powerkey: the SAE J1939 29-bit identifier (J1939-21 5.2):
//   bits 28..26 priority | 25 EDP | 24 DP | 23..16 PDU format (PF) | 15..8 PDU specific (PS) | 7..0
//   SA
// PF < F0h is PDU1: PS is the destination address and the PGN's low byte is 00h.
// PF >= F0h is PDU2: PS is a group extension, part of the PGN, and there is no destination.
#ifndef POWERKEY_J1939_ID_HPP
#define POWERKEY_J1939_ID_HPP

#include <powerkey/bounded.hpp>
#include <powerkey/can/frame.hpp>

#include <cstdint>
#include <optional>

namespace powerkey::j1939 {

struct priority_tag;
struct pgn_tag;
// 0 (highest) .. 7 (lowest).
using priority = bounded<priority_tag, std::uint8_t, 0, 7>;
// Parameter group number, 18 bits: EDP, DP, PF, PS.
using pgn = bounded<pgn_tag, std::uint32_t, 0, 0x3FFFF>;

// Address FFh is the global (broadcast) address; FEh the null address, the sender of an address
// claim that says it cannot claim one (J1939-81), and no other frame's.
inline constexpr std::uint8_t global_address = 0xFF;
inline constexpr std::uint8_t null_address = 0xFE;

struct identifier {
    j1939::priority priority = 6;
    j1939::pgn pgn = 0;
    std::uint8_t destination = global_address;  // PDU1 only; global_address for PDU2
    std::uint8_t source = 0;

    [[nodiscard]] constexpr bool is_pdu1() const noexcept {
        return ((pgn.value() >> 8) & 0xFF) < 0xF0;
    }
    friend constexpr bool operator==(const identifier&, const identifier&) noexcept = default;
};

// Errors: value_out_of_range for a PDU1 PGN whose low byte is not 00h (that byte is the
// destination, which has its own field), or a PDU2 identifier whose destination is not FFh.
[[nodiscard]] constexpr result<can::extended_id> make_id(const identifier& id) noexcept {
    const std::uint32_t p = id.pgn.value();
    std::uint32_t ps = p & 0xFF;
    if (id.is_pdu1()) {
        if (ps != 0) return errc::value_out_of_range;
        ps = id.destination;
    } else if (id.destination != global_address) {
        return errc::value_out_of_range;
    }
    return can::extended_id::make((std::uint32_t{id.priority.value()} << 26) |
                                  ((p & 0x3FF00) << 8) | (ps << 8) | id.source);
}

// Every 29-bit identifier is a valid J1939 identifier, so this cannot fail.
[[nodiscard]] constexpr identifier parse_id(can::extended_id id) noexcept {
    const std::uint32_t v = id.value();
    identifier r;
    r.priority = priority::make((v >> 26) & 7).value();
    r.source = static_cast<std::uint8_t>(v);
    const std::uint32_t pf = (v >> 16) & 0xFF;
    const std::uint32_t ps = (v >> 8) & 0xFF;
    const std::uint32_t dp_edp = (v >> 24) & 3;
    if (pf < 0xF0) {
        r.pgn = pgn::make((dp_edp << 16) | (pf << 8)).value();
        r.destination = static_cast<std::uint8_t>(ps);
    } else {
        r.pgn = pgn::make((dp_edp << 16) | (pf << 8) | ps).value();
        r.destination = global_address;
    }
    return r;
}

// The J1939 view of a frame; nullopt for an 11-bit frame.
[[nodiscard]] constexpr std::optional<identifier> parse_id(const can::frame& f) noexcept {
    if (const auto id = f.ext_id()) return parse_id(*id);
    return std::nullopt;
}

}  // namespace powerkey::j1939

#endif  // POWERKEY_J1939_ID_HPP
