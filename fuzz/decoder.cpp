// The any-frame decoder (powerkey::decode) for every model on arbitrary frames: no crash, no read
// past the dlc, listed errors, decode -> encode -> decode a fixed point; and its encoder fed
// every message kind with arbitrary in-range fields: what encodes decodes back to the same value.
#include "profile.hpp"

#include <powerkey/decoder.hpp>

namespace {
using namespace powerkey;
using namespace powerkey_fuzz;

constexpr model models[] = {model::pk1000, model::pkp2200, model::pkp2400, model::pkp2600};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    input in(data, size);
    const std::uint8_t mode = in.u8();
    const model m = models[(mode >> 1) % std::size(models)];
    const canopen::node_id node = take_node(in);
    if ((mode & 1) == 0) {
        const can::frame f = take_frame(in);
        decode_fixed_point(
            f, [&](const can::frame& x) { return decode(x, node, m); },
            [&](const message& msg) { return encode(node, m, msg); });
    } else {
        encode_accepted<message>(
            in, [&](const message& msg) { return encode(node, m, msg); },
            [&](const can::frame& f) { return decode(f, node, m); });
    }
    return 0;
}
