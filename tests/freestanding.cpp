// Built with -fno-exceptions -fno-rtti, and with an operator new that traps: every decoder and
// encoder of the library runs here on the manual frames without exceptions, RTTI or the heap.
#include <powerkey/powerkey.hpp>

#include <cstdlib>
#include <new>

void* operator new(std::size_t) { std::abort(); }
void* operator new[](std::size_t) { std::abort(); }
void operator delete(void*) noexcept { std::abort(); }
void operator delete[](void*) noexcept { std::abort(); }
void operator delete(void*, std::size_t) noexcept { std::abort(); }
void operator delete[](void*, std::size_t) noexcept { std::abort(); }

namespace {
using namespace powerkey;

int failures = 0;
void expect(bool ok) { failures += ok ? 0 : 1; }

void core() {
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
}
}  // namespace

int main() {
    core();
    return failures == 0 ? 0 : 1;
}
