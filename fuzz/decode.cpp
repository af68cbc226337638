// The keypad decoder powerkey::decode(frame, node, model) on arbitrary frames, for every model of
// the model table (and, one input in five, a value that is no model). Properties: no crash, no
// read past the dlc, every refusal a listed errc, decode -> encode -> decode a fixed point; and
// the accessors never answer for a frame that decodes to nothing; every SDO entry point agrees
// with the SDO engine (tests/sdo_agreement.hpp); decode_key_state<M> answers as decode
// (tests/key_state_agreement.hpp).
#include "key_state_agreement.hpp"
#include "properties.hpp"
#include "sdo_agreement.hpp"

#include <powerkey/keypad/accessors.hpp>
#include <powerkey/keypad/codec.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace powerkey;
    using namespace powerkey_fuzz;
    input in(data, size);
    // model_count + 1 choices: the last is a value outside the enum (decode refuses it).
    const auto m = static_cast<model>(in.u8() % (model_count + 1));
    const canopen::node_id node = take_node(in);
    const can::frame f = take_frame(in);
    // Read strictly, decode -> encode -> decode is a fixed point.
    const bool decoded = decode_fixed_point(
        f, [&](const can::frame& x) { return decode(x, node, m, reading::strict); },
        [&](const message& msg) { return encode(node, m, msg); });
    if (!info(m)) POWERKEY_FUZZ_CHECK_FRAME(!decoded, f);
    // Read tolerantly (the default): the manual's form reads the same; a frame not in it (trimmed,
    // padded) reads as the meaning of the manual's frame that encode builds (docs/decoder.md).
    if (const auto t = decode(f, node, m)) {
        if (form_of(*t) == frame_form::manual) {
            POWERKEY_FUZZ_CHECK_FRAME(decoded && *t == *decode(f, node, m, reading::strict), f);
        } else {
            const auto e = encode(node, m, *t);
            POWERKEY_FUZZ_CHECK_FRAME(!decoded && e && e->size() != f.size(), f);
            const auto back = decode(*e, node, m, reading::strict);
            POWERKEY_FUZZ_CHECK_FRAME(back && *back == detail::with_form(*t, frame_form::manual),
                                      f);
        }
    }
    // The key state alone, the model a template argument: decode's answer, past the dlc unread.
    {
        aligned_frame held{f};
        const poison_past_dlc guard(held.f);
        POWERKEY_FUZZ_CHECK_FRAME(key_state_agreement::agrees(m, held.f, node), f);
    }
    // One SDO parser: the engine, the CiA 301 decoders, every model's decode and the session agree.
    POWERKEY_FUZZ_CHECK_FRAME(sdo_agreement::disagreement(f, node).empty(), f);
    if (decoded) {
        // The accessors read the decoded message without touching anything else.
        const auto msg = *decode(f, node, m, reading::strict);
        (void)pressed_keys(msg);
        (void)led_on_map(msg, m);
        (void)led_blink_map(msg, m);
        (void)led_brightness_level(msg);
        (void)backlight_change(msg);
        (void)node_id_change(msg);
        (void)reported_nmt_state(msg);
    }
    return 0;
}
