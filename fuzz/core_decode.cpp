// Every core decoder (NMT, SYNC, heartbeat, SDO request and response, the J1939 switch) on an
// arbitrary frame and node. Properties, for each decoder:
//  - no crash, no undefined behaviour, no read of a data byte past the dlc (ASan poisons them);
//  - a refusal carries a listed errc;
//  - what decodes re-encodes to the same frame and decodes again to the same value (a fixed point,
//    properties.hpp's decode_fixed_point);
//  - at most one decoder accepts a given frame, and the COB-ID classification agrees with it.
#include "properties.hpp"

using namespace powerkey;
using namespace powerkey_fuzz;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    input in(data, size);
    const canopen::node_id node = take_node(in);
    const can::frame f = take_frame(in);
    const auto info = canopen::classify(f);

    int accepted = 0;
    if (decode_fixed_point(
            f, [](const can::frame& x) { return canopen::decode_nmt(x); },
            [](const auto& m) { return canopen::encode(m); })) {
        ++accepted;
        POWERKEY_FUZZ_CHECK_FRAME(info.fn == canopen::function::nmt, f);
    }
    if (decode_fixed_point(
            f, [](const can::frame& x) { return canopen::decode_sync(x); },
            [](const auto& m) { return canopen::encode(m); })) {
        ++accepted;
        POWERKEY_FUZZ_CHECK_FRAME(info.fn == canopen::function::sync, f);
    }
    if (decode_fixed_point(
            f, [node](const can::frame& x) { return canopen::decode_heartbeat(x, node); },
            [node](const auto& m) { return canopen::encode(node, m); })) {
        ++accepted;
        POWERKEY_FUZZ_CHECK_FRAME(info.fn == canopen::function::heartbeat, f);
        POWERKEY_FUZZ_CHECK_FRAME(info.node == node.value(), f);
    }
    if (decode_fixed_point(
            f, [node](const can::frame& x) { return canopen::decode_sdo_request(x, node); },
            [node](const auto& m) { return canopen::encode_request(node, m); })) {
        ++accepted;
        POWERKEY_FUZZ_CHECK_FRAME(info.fn == canopen::function::sdo_rx, f);
        POWERKEY_FUZZ_CHECK_FRAME(info.node == node.value(), f);
    }
    if (decode_fixed_point(
            f, [node](const can::frame& x) { return canopen::decode_sdo_response(x, node); },
            [node](const auto& m) { return canopen::encode_response(node, m); })) {
        ++accepted;
        POWERKEY_FUZZ_CHECK_FRAME(info.fn == canopen::function::sdo_tx, f);
        POWERKEY_FUZZ_CHECK_FRAME(info.node == node.value(), f);
    }
    if (decode_fixed_point(
            f, [](const can::frame& x) { return j1939::decode_switch_to_canopen(x); },
            [](const auto& m) { return j1939::encode(m); })) {
        ++accepted;
        POWERKEY_FUZZ_CHECK_FRAME(f.is_extended(), f);
    }
    POWERKEY_FUZZ_CHECK_FRAME(accepted <= 1, f);

    // Identifiers: classification is consistent with cob_id, every 29-bit identifier is classified
    // j1939 and is a J1939 identifier that rebuilds to itself; concerns() agrees with the node.
    POWERKEY_FUZZ_CHECK_FRAME(
        canopen::concerns(info, node) ==
            (info.fn == canopen::function::nmt || info.fn == canopen::function::sync ||
             info.fn == canopen::function::j1939 ||
             (info.fn != canopen::function::other && info.node == node.value())),
        f);
    if (const auto sid = f.std_id()) {
        POWERKEY_FUZZ_CHECK_FRAME(info.fn != canopen::function::j1939, f);
        if (info.fn != canopen::function::nmt && info.fn != canopen::function::sync &&
            info.fn != canopen::function::other) {
            const auto n = canopen::node_id::make(info.node);
            POWERKEY_FUZZ_CHECK_FRAME(n.has_value() && canopen::cob_id(info.fn, *n) == *sid, f);
        }
        POWERKEY_FUZZ_CHECK_FRAME(!j1939::parse_id(f).has_value(), f);
    } else {
        POWERKEY_FUZZ_CHECK_FRAME(info.fn == canopen::function::j1939 && info.node == 0, f);
        const auto id = j1939::parse_id(f);
        POWERKEY_FUZZ_CHECK_FRAME(id.has_value(), f);
        const auto rebuilt = j1939::make_id(*id);
        POWERKEY_FUZZ_CHECK_FRAME(rebuilt.has_value() && *rebuilt == *f.ext_id(), f);
    }
    return 0;
}
