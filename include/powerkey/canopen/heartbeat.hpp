// powerkey: boot-up and heartbeat (CiA 301 7.2.8.3.2), COB-ID 700h + node, one data byte: the
// producer's NMT state. PK1000 manual sections 8, 9 and 29; PKP manual sections 8, 9 and 17.
#ifndef POWERKEY_CANOPEN_HEARTBEAT_HPP
#define POWERKEY_CANOPEN_HEARTBEAT_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/detail/message.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/frame_form.hpp>

#include <cstdint>
#include <string_view>

namespace powerkey::canopen {

// clang-format off
#define POWERKEY_CANOPEN_NMT_STATE_LIST(X) \
    X(boot_up, 0x00)  /* the boot-up message: the node has just entered pre-operational */ \
    X(stopped, 0x04) \
    X(operational, 0x05) \
    X(pre_operational, 0x7F)
// clang-format on
enum class nmt_state : std::uint8_t { POWERKEY_CANOPEN_NMT_STATE_LIST(POWERKEY_DETAIL_ENUMERATOR) };

}  // namespace powerkey::canopen

POWERKEY_DETAIL_ENUM_NAMES(powerkey::canopen::nmt_state, POWERKEY_CANOPEN_NMT_STATE_LIST);

namespace powerkey::canopen {

struct heartbeat_message {
    POWERKEY_DETAIL_MESSAGE(heartbeat_message);
    POWERKEY_DETAIL_FIELDS(f("state", self.state));
    nmt_state state = nmt_state::boot_up;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

[[nodiscard]] constexpr can::frame encode(node_id node, const heartbeat_message& m) noexcept {
    return can::frame(cob_id(function::heartbeat, node),
                      std::array<std::uint8_t, 1>{static_cast<std::uint8_t>(m.state)});
}

// Whether b is a state a heartbeat carries: 00h, 04h, 05h or 7Fh.
[[nodiscard]] constexpr bool is_heartbeat_state(std::uint8_t b) noexcept {
    return b == 0x00 || b == 0x04 || b == 0x05 || b == 0x7F;
}

// Errors: docs/canopen.md, "Boot-up and heartbeat" (the keypads use no node-guarding toggle bit).
[[nodiscard]] constexpr result<heartbeat_message> decode_heartbeat(const can::frame& f,
                                                                   node_id node) noexcept {
    if (const auto e = detail::check_frame(f, cob_id(function::heartbeat, node), 1); e != errc{})
        return e;
    if (!is_heartbeat_state(f[0])) return errc::value_out_of_range;
    return heartbeat_message{static_cast<nmt_state>(f[0])};
}

}  // namespace powerkey::canopen

#endif  // POWERKEY_CANOPEN_HEARTBEAT_HPP
