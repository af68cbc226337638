// powerkey: NMT node control (CiA 301 7.2.8.3.1), COB-ID 000h, two data bytes:
//   byte 0  command specifier   byte 1  target node (00h = all nodes)
// PK1000 manual sections 4-7, PKP manual sections 4-7.
#ifndef POWERKEY_CANOPEN_NMT_HPP
#define POWERKEY_CANOPEN_NMT_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/detail/message.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/frame_form.hpp>

#include <cstdint>
#include <string_view>

namespace powerkey::canopen {

enum class nmt_command : std::uint8_t {
    legacy_stop = 0x00,  // "Stop CANopen node (old sw compatibility)", both manuals section 7
    start = 0x01,
    stop = 0x02,
    enter_pre_operational = 0x80,
    reset_node = 0x81,
    reset_communication = 0x82,
};

}  // namespace powerkey::canopen

template <>
struct powerkey::enum_names<powerkey::canopen::nmt_command> {
    using c = canopen::nmt_command;
    static constexpr enum_name_entry<c> entries[] = {
        {c::start, "start"},
        {c::stop, "stop"},
        {c::enter_pre_operational, "pre_operational"},
        {c::reset_node, "reset_node"},
        {c::reset_communication, "reset_communication"},
        {c::legacy_stop, "legacy_stop"},
    };
};

namespace powerkey::canopen {

struct nmt_message {
    POWERKEY_DETAIL_MESSAGE(nmt_message);
    POWERKEY_DETAIL_FIELDS(f("command", self.command), f("target", self.target));
    nmt_command command = nmt_command::start;
    nmt_target target = all_nodes;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

[[nodiscard]] constexpr can::frame encode(const nmt_message& m) noexcept {
    return can::frame(nmt_cob_id, std::array<std::uint8_t, 2>{static_cast<std::uint8_t>(m.command),
                                                              m.target.value()});
}

// Errors: docs/canopen.md, "NMT node control".
[[nodiscard]] constexpr result<nmt_message> decode_nmt(const can::frame& f) noexcept {
    if (const auto e = detail::check_frame(f, nmt_cob_id, 2); e != errc{}) return e;
    nmt_message m;
    switch (f[0]) {
        case 0x00:
        case 0x01:
        case 0x02:
        case 0x80:
        case 0x81:
        case 0x82: m.command = static_cast<nmt_command>(f[0]); break;
        default: return errc::unknown_command;
    }
    const auto target = nmt_target::make(f[1]);
    if (!target) return target.error();
    m.target = *target;
    return m;
}

}  // namespace powerkey::canopen

#endif  // POWERKEY_CANOPEN_NMT_HPP
