// The keypad encoder powerkey::encode(node, model, message) fed every kind of the flat message
// with arbitrary raw field values (fuzz.hpp): any enum value (static_cast<baud_rate>(0xFA)), any
// object, any object_value {raw, map, size}, any command code and members, any LED and key bits,
// for every model (and a value that is no model). Property (issue 10): the message is refused
// with a listed errc, or it encodes to a frame that decodes back to exactly the same message; and
// encode of the message as its own type gives the same answer.
#include "properties.hpp"

#include <powerkey/keypad/codec.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace powerkey;
    using namespace powerkey_fuzz;
    input in(data, size);
    const auto m = static_cast<model>(in.u8() % (model_count + 1));
    const canopen::node_id node = take_node(in);
    const bool encoded = encode_accepted<message>(
        in,
        [&](const message& msg) {
            const auto r = encode(node, m, msg);
            // The same message as its own type (the PDOs and SDOs that check themselves, issue
            // 24): the same answer.
            std::visit(
                [&](const auto& v) {
                    if constexpr (detail::canopen_alternative<std::decay_t<decltype(v)>>)
                        POWERKEY_FUZZ_CHECK(encode(node, m, v) == r);
                },
                msg);
            return r;
        },
        [&](const can::frame& f) { return decode(f, node, m); });
    if (!info(m)) POWERKEY_FUZZ_CHECK(!encoded);
    return 0;
}
