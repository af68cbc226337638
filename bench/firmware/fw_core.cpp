// Footprint firmware (core): the CiA 301 part every keypad host needs and nothing else. Starts
// the keypad, watches its heartbeat, writes one object by expedited SDO when it boots, and resets
// it when it aborts an SDO. A reference point for firmwares (a) and (b).
// Each library call sits in its own function of namespace `calls`, so that scripts/footprint.sh
// can report the stack each one needs.
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/sdo.hpp>

#include "mailbox.hpp"

namespace co = powerkey::canopen;
namespace pc = powerkey::can;

namespace calls {
[[gnu::noinline]] pc::frame encode_nmt(co::nmt_command c, co::node_id n) {
    return co::encode(co::nmt_message{c, co::nmt_target::make(n.value()).value()});
}
[[gnu::noinline]] bool is_boot_up(const pc::frame& f, co::node_id n) {
    const auto hb = co::decode_heartbeat(f, n);
    return hb && hb->state == co::nmt_state::boot_up;
}
[[gnu::noinline]] pc::frame encode_sdo_write(co::node_id n, std::uint16_t ms) {
    return co::encode(n, co::sdo_download_request{{0x1017, 0}, co::expedited_data::u16(ms)});
}
[[gnu::noinline]] bool is_sdo_abort(const pc::frame& f, co::node_id n) {
    const auto r = co::decode_sdo_response(f, n);
    return r && std::holds_alternative<co::sdo_abort>(*r);
}
}  // namespace calls

[[noreturn]] void firmware_main() {
    constexpr co::node_id node = co::default_node_id;
    firmware::transmit(calls::encode_nmt(co::nmt_command::start, node));
    for (;;) {
        const auto f = firmware::receive();
        if (!f) continue;
        if (calls::is_boot_up(*f, node)) firmware::transmit(calls::encode_sdo_write(node, 500));
        if (calls::is_sdo_abort(*f, node))
            firmware::transmit(calls::encode_nmt(co::nmt_command::reset_node, node));
    }
}
