// The core encoders fed arbitrary in-range values: every message a caller can build encodes to a
// frame that its decoder accepts and decodes back to the same message. The fields are filled
// through each message's `fields` list, so a field added later is fuzzed too. The CiA 301
// encoders are total (they return a frame), so enum fields take their named values only; the SDO
// abort code takes any 32-bit value, as the decoder keeps any. The keypad encoder, which refuses,
// gets raw values of every field (encode.cpp).
#include "fuzz.hpp"

#include <variant>

namespace {
using namespace powerkey;
using namespace powerkey_fuzz;
using namespace powerkey::canopen;

// The SDO abort appears twice: as a request (600h + node) and as a response (580h + node).
using core_message =
    std::variant<nmt_message, sync_message, heartbeat_message, sdo_download_request,
                 sdo_upload_request, sdo_segment_request, sdo_abort, sdo_download_response,
                 sdo_upload_response, sdo_upload_initiate_response, sdo_segment_response, sdo_abort,
                 j1939::switch_to_canopen>;
constexpr std::size_t first_request = 3;
constexpr std::size_t first_response = 7;
constexpr std::size_t last_response = 11;

template <class T>
void fill_in_range(input& in, T& v) {
    if constexpr (named_enum<T> && !std::is_same_v<T, sdo_abort_code>) {
        constexpr auto values = enum_values<T>();
        v = values[in.u8() % values.size()];
    } else {
        fill_value(in, v);
    }
}

template <class M>
void fill_message(input& in, M& m) {
    M::fields(m, [&in](std::string_view, auto& field) { fill_in_range(in, field); });
}

template <class Decoded, class Message>
void check_decodes_to(const can::frame& f, const Decoded& decoded, const Message& expected) {
    POWERKEY_FUZZ_CHECK_FRAME(decoded.has_value(), f);
    POWERKEY_FUZZ_CHECK_FRAME(*decoded == expected, f);
}

template <std::size_t I>
void check_alternative(input& in, node_id node) {
    std::variant_alternative_t<I, core_message> m{};
    fill_message(in, m);
    aligned_frame held{};
    if constexpr (I == 0 || I == 1) {
        held.f = encode(m);
    } else if constexpr (I == 2) {
        held.f = encode(node, m);
    } else if constexpr (I < first_response) {
        held.f = encode_request(node, sdo_request{std::in_place_index<I - first_request>, m});
    } else if constexpr (I <= last_response) {
        held.f = encode_response(node, sdo_response{std::in_place_index<I - first_response>, m});
    } else {
        held.f = j1939::encode(m);
    }
    const can::frame& f = held.f;
    const poison_past_dlc guard(held.f);
    if constexpr (I == 0) {
        check_decodes_to(f, decode_nmt(f), m);
    } else if constexpr (I == 1) {
        check_decodes_to(f, decode_sync(f), m);
    } else if constexpr (I == 2) {
        check_decodes_to(f, decode_heartbeat(f, node), m);
    } else if constexpr (I < first_response) {
        check_decodes_to(f, decode_sdo_request(f, node),
                         sdo_request{std::in_place_index<I - first_request>, m});
    } else if constexpr (I <= last_response) {
        check_decodes_to(f, decode_sdo_response(f, node),
                         sdo_response{std::in_place_index<I - first_response>, m});
    } else if (m.destination == j1939::global_address) {
        // Built as asked, but no source shows a keypad acting on the switch sent to every address:
        // the decoder refuses it (docs/j1939.md).
        POWERKEY_FUZZ_CHECK_FRAME(j1939::decode_switch_to_canopen(f) == errc::undocumented, f);
    } else {
        check_decodes_to(f, j1939::decode_switch_to_canopen(f), m);
    }
}

template <std::size_t... I>
void dispatch(std::size_t which, input& in, node_id node, std::index_sequence<I...>) {
    ((which == I ? check_alternative<I>(in, node) : void()), ...);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    input in(data, size);
    constexpr std::size_t n = std::variant_size_v<core_message>;
    const std::size_t which = in.u8() % n;
    const node_id node = take_node(in);
    dispatch(which, in, node, std::make_index_sequence<n>{});
    return 0;
}
