// The PKP profile encoder (pkp::encode) fed every message kind with arbitrary in-range fields,
// for each model: what encodes decodes back to the same message.
#include "profile.hpp"

#include <powerkey/pkp/profile.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace powerkey;
    using namespace powerkey_fuzz;
    input in(data, size);
    const auto m = static_cast<pkp::model>(in.u8() % 3);
    const canopen::node_id node = take_node(in);
    encode_accepted<pkp::message>(
        in, [&](const pkp::message& msg) { return pkp::encode(node, m, msg); },
        [&](const can::frame& f) { return pkp::decode(f, node, m); });
    return 0;
}
