// The PKP profile decoder (pkp::decode) on arbitrary frames, for each model: no crash, no read
// past the dlc, listed errors, and decode -> encode -> decode is a fixed point.
#include "profile.hpp"

#include <powerkey/pkp/profile.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace powerkey;
    using namespace powerkey_fuzz;
    input in(data, size);
    const auto m = static_cast<pkp::model>(in.u8() % 3);
    const canopen::node_id node = take_node(in);
    const can::frame f = take_frame(in);
    decode_fixed_point(
        f, [&](const can::frame& x) { return pkp::decode(x, node, m); },
        [&](const pkp::message& msg) { return pkp::encode(node, m, msg); });
    return 0;
}
