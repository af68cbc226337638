// The keypad encoder powerkey::encode(node, model, message) fed every kind of the flat message
// with arbitrary raw field values (fuzz.hpp): any enum value (static_cast<baud_rate>(0xFA)), any
// object, any object_value {raw, map, size}, any command code and members, any LED and key bits,
// for every model (and a value that is no model). Property (issue 10): the message is refused
// with a listed errc, or it encodes to a frame that decodes back to exactly the same message; and
// encode of the message as its own type, and encode<M> with the model a template argument (one
// model of each dictionary), give the same answer.
#include "properties.hpp"

#include <powerkey/keypad/codec.hpp>

#include <cstddef>
#include <type_traits>
#include <utility>

namespace {
// Whether model i is the first of the table with its dictionary: encode<M> is checked for one
// model of each dictionary (each model's instantiation costs the target's build time).
constexpr bool first_of_its_dictionary(std::size_t i) {
    for (std::size_t j = 0; j < i; ++j)
        if (powerkey::detail::model_table[j].dictionary ==
            powerkey::detail::model_table[i].dictionary)
            return false;
    return true;
}
// f(std::integral_constant<model, M>{}) when m is such a model.
template <class F, std::size_t... I>
void with_model(powerkey::model m, F f, std::index_sequence<I...>) {
    (
        [&] {
            if constexpr (first_of_its_dictionary(I))
                if (static_cast<powerkey::model>(I) == m)
                    f(std::integral_constant<powerkey::model, static_cast<powerkey::model>(I)>{});
        }(),
        ...);
}
}  // namespace

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
            // The model a template argument (its own dictionary's tables), for one model of each
            // dictionary: the same answer.
            with_model(
                m,
                [&](auto known) {
                    constexpr model M = decltype(known)::value;
                    POWERKEY_FUZZ_CHECK(encode<M>(node, msg) == r);
                },
                std::make_index_sequence<model_count>{});
            return r;
        },
        [&](const can::frame& f) { return decode(f, node, m); });
    if (!info(m)) POWERKEY_FUZZ_CHECK(!encoded);
    return 0;
}
