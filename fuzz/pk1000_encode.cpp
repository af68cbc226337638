// The PK1000 profile encoder (pk1000::encode) fed every message kind with arbitrary in-range
// fields: every message encodes, and decodes back to the same message.
#include "profile.hpp"

#include <powerkey/pk1000/profile.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace powerkey;
    using namespace powerkey_fuzz;
    input in(data, size);
    const canopen::node_id node = take_node(in);
    encode_accepted<pk1000::message>(
        in, [&](const pk1000::message& msg) { return pk1000::encode(node, msg); },
        [&](const can::frame& f) { return pk1000::decode(f, node); });
    return 0;
}
