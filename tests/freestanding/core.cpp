// Freestanding checks of the core: CiA 301, J1939, candump text, the segmented reader.
#include <powerkey/powerkey.hpp>

#include "check.hpp"

namespace {
using namespace powerkey;

bool core() {
    bool ok = true;
    auto expect = [&ok](bool b) { ok = ok && b; };
    constexpr canopen::node_id node = 0x15;
    expect(canopen::decode_nmt(can::candump("000#0115")).has_value());
    expect(canopen::decode_sync(can::candump("080#")).has_value());
    expect(canopen::decode_heartbeat(can::candump("715#7F"), node).has_value());
    expect(canopen::decode_sdo_request(can::candump("615#4008100000000000"), node).has_value());
    expect(canopen::decode_sdo_response(can::candump("595#4B17100064000000"), node).has_value());
    expect(j1939::decode_switch_to_canopen(can::candump("18EF2100#041B8000FFFFFFFF")).has_value());
    expect(can::parse_candump("615#4008").has_value());

    canopen::segmented_upload<16> r(node);
    expect(r.start({0x1008, 0}) == can::candump("615#4008100000000000"));
    expect(r.step(can::candump("595#41081000"
                               "0B000000"))
               .has_value());
    expect(r.step(can::candump("595#00426C696E6B4D61")).has_value());
    expect(r.step(can::candump("595#1772696E65000000")).has_value());
    expect(r.text() == "BlinkMarine");
    return ok;
}
const freestanding::registration reg("core", core);
}  // namespace
