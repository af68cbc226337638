// The session follower fed an arbitrary sequence of frames (any model, any start node).
// Properties: no crash and no read past any frame's dlc; each event's decoding is exactly the
// any-frame decoder's for the node the event names, its J1939 frames narrowed to the keypad
// address the session had narrowed to before the frame (a 70h narrows it); the followed node id,
// protocol and J1939 address change only with an event that says so; the upload text never
// exceeds its capacity.
#include "fuzz.hpp"

#include <powerkey/keypad/codec.hpp>
#include <powerkey/session.hpp>

namespace {
using namespace powerkey;
using namespace powerkey_fuzz;

// Most frames are SDO traffic of the followed node, where the state lives; one in four is an
// arbitrary frame.
can::frame take_bus_frame(input& in, canopen::node_id node) {
    const std::uint8_t kind = in.u8();
    if ((kind & 3) == 0) return take_frame(in);
    can::payload p{};
    for (auto& b : p) b = in.u8();
    const auto fn = (kind & 3) == 1 ? canopen::function::sdo_rx : canopen::function::sdo_tx;
    return can::frame(canopen::cob_id(fn, node), 8, p);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    input in(data, size);
    const auto m = static_cast<model>(in.u8() % model_count);
    session<16> s(m, take_node(in));
    for (int i = 0; i < 64 && !in.empty(); ++i) {
        aligned_frame held{take_bus_frame(in, s.node())};
        const auto node_before = s.node();
        const auto protocol_before = s.protocol();
        const auto narrowing_before = s.j1939_narrowing();
        const auto address_before = s.j1939_address();
        const auto e = [&] {
            const poison_past_dlc guard(held.f);
            return s.step(held.f);
        }();
        const can::frame& f = held.f;
        POWERKEY_FUZZ_CHECK_FRAME(e.decoded == decode(f, e.node, m, narrowing_before), f);
        if (!e.decoded) POWERKEY_FUZZ_CHECK_FRAME(is_listed(e.decoded.error()), f);
        if (e.upload_error != errc{}) POWERKEY_FUZZ_CHECK_FRAME(is_listed(e.upload_error), f);
        if (e.new_node)
            POWERKEY_FUZZ_CHECK_FRAME(s.node() == *e.new_node, f);
        else
            POWERKEY_FUZZ_CHECK_FRAME(s.node() == node_before, f);
        if (e.new_protocol)
            POWERKEY_FUZZ_CHECK_FRAME(s.protocol() == *e.new_protocol, f);
        else
            POWERKEY_FUZZ_CHECK_FRAME(s.protocol() == protocol_before, f);
        if (e.new_address)
            POWERKEY_FUZZ_CHECK_FRAME(s.j1939_address() == *e.new_address, f);
        else
            POWERKEY_FUZZ_CHECK_FRAME(s.j1939_address() == address_before, f);
        POWERKEY_FUZZ_CHECK_FRAME(s.text().size() <= 16 && s.upload().bytes().size() <= 16, f);
        POWERKEY_FUZZ_CHECK_FRAME(s.model() == m, f);
    }
    return 0;
}
