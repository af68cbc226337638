// powerkey: the J1939 frame that switches a keypad back to CANopen (PK1000 manual section 49):
//   18EF2100#041B8000FFFFFFFF
//   priority 6, PGN EF00h (proprietary A, PDU1), destination 21h (the keypad's default J1939
//   address), source 00h; data 04 1B 80 00 FF FF FF FF, a fixed signature.
// The opposite switch, CANopen to J1939, is an SDO write of object protocol_j1939 (20FFh sub 1).
#ifndef POWERKEY_J1939_PROTOCOL_SWITCH_HPP
#define POWERKEY_J1939_PROTOCOL_SWITCH_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/detail/message.hpp>
#include <powerkey/frame_form.hpp>
#include <powerkey/j1939/id.hpp>

#include <array>
#include <cstdint>
#include <string_view>

namespace powerkey::j1939 {

inline constexpr std::uint8_t keypad_default_address = 0x21;
inline constexpr pgn proprietary_a_pgn = 0xEF00;
inline constexpr std::array<std::uint8_t, 8> switch_to_canopen_data = {0x04, 0x1B, 0x80, 0x00,
                                                                       0xFF, 0xFF, 0xFF, 0xFF};

struct switch_to_canopen {
    POWERKEY_DETAIL_J1939_MESSAGE(switch_to_canopen);
    POWERKEY_DETAIL_FIELDS(f("priority", self.priority), f("destination", self.destination),
                           f("source", self.source));
    j1939::priority priority = 6;
    std::uint8_t destination = keypad_default_address;
    std::uint8_t source = 0x00;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

[[nodiscard]] constexpr can::frame encode(const switch_to_canopen& m) noexcept {
    // A PDU1 PGN with a zero low byte always makes a valid identifier.
    const auto id = make_id({m.priority, proprietary_a_pgn, m.destination, m.source});
    return can::frame(id.value(), switch_to_canopen_data);
}

// Errors: wrong_id_format (an 11-bit frame), wrong_id (a PGN other than EF00h), wrong_length (not
// 8 bytes), unknown_command (other data: another proprietary message on the same PGN),
// undocumented (sent to the global address FFh: no source shows a keypad acting on a command
// there; the keypad codec, keypad/j1939_codec.hpp, refuses it the same way).
[[nodiscard]] constexpr result<switch_to_canopen> decode_switch_to_canopen(
    const can::frame& f) noexcept {
    const auto id = parse_id(f);
    if (!id) return errc::wrong_id_format;
    if (id->pgn != proprietary_a_pgn) return errc::wrong_id;
    if (f.size() != 8) return errc::wrong_length;
    for (std::size_t i = 0; i < 8; ++i)
        if (f[i] != switch_to_canopen_data[i]) return errc::unknown_command;
    if (id->destination == global_address) return errc::undocumented;
    return switch_to_canopen{id->priority, id->destination, id->source};
}

}  // namespace powerkey::j1939

#endif  // POWERKEY_J1939_PROTOCOL_SWITCH_HPP
