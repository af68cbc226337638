// The PK1000 profile decoder (pk1000::decode) on arbitrary frames: no crash, no read past the dlc,
// listed errors, and decode -> encode -> decode is a fixed point.
#include "profile.hpp"

#include <powerkey/pk1000/profile.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace powerkey;
    using namespace powerkey_fuzz;
    input in(data, size);
    const canopen::node_id node = take_node(in);
    const can::frame f = take_frame(in);
    decode_fixed_point(
        f, [&](const can::frame& x) { return pk1000::decode(x, node); },
        [&](const pk1000::message& msg) { return pk1000::encode(node, msg); });
    return 0;
}
