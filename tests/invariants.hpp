// The invariants every decoder keeps on untrusted frames, checked over a systematic sweep of
// frames near the manuals' examples (shared by tests/test_powerkey.cpp, which runs it under
// ASan with the bytes past the dlc poisoned, and tests/freestanding/invariants.cpp, which runs it
// with operator new trapping):
//  - a refusal carries one of the listed codes (enum_values<errc>());
//  - what decodes re-encodes to the same frame, and that frame decodes again to the same message:
//    for every decoded message, encode gives back a frame that decodes to that message.
// The decoders: the CiA 301 and J1939 ones, and decode(frame, node, model) for every model of the
// table; and every SDO entry point agrees with the SDO engine (sdo_agreement.hpp). The sweep: every
// row of every frame table (tests/codec_rows.hpp, pk1000_rows.hpp, pkp_rows.hpp: manual rows,
// refused rows, foreign frames), each with every byte in turn set to each of a few dozen telling
// values (command specifiers, bounds, all ones), with every dlc from 0 to 8, on every COB-ID
// function of the keypad and of another node, and as a 29-bit frame.
#ifndef POWERKEY_TESTS_INVARIANTS_HPP
#define POWERKEY_TESTS_INVARIANTS_HPP

#include <powerkey/powerkey.hpp>

#include "codec_rows.hpp"
#include "pk1000_rows.hpp"
#include "pkp_rows.hpp"
#include "sdo_agreement.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

namespace invariants {

using namespace powerkey;

// Byte values that reach the decoders' branches: SDO command specifiers with their toggle, size
// and flag bits, NMT commands and states, command-module codes, range bounds, all ones.
inline constexpr std::uint8_t telling_bytes[] = {
    0x00, 0x01, 0x02, 0x03, 0x04, 0x05, 0x07, 0x08, 0x09, 0x0A, 0x0B, 0x0F, 0x10, 0x11,
    0x12, 0x13, 0x14, 0x15, 0x16, 0x18, 0x1C, 0x20, 0x21, 0x22, 0x23, 0x27, 0x2B, 0x2F,
    0x3F, 0x40, 0x41, 0x42, 0x43, 0x47, 0x4B, 0x4F, 0x50, 0x60, 0x61, 0x62, 0x63, 0x65,
    0x70, 0x7A, 0x7D, 0x7E, 0x7F, 0x80, 0x81, 0x82, 0xA0, 0xC0, 0xEF, 0xF0, 0xFE, 0xFF};

inline constexpr std::uint16_t function_bases[] = {0x000, 0x080, 0x180, 0x200, 0x300, 0x400, 0x500,
                                                   0x580, 0x600, 0x700, 0x280, 0x380, 0x480};

// The first decoder that broke an invariant, and how; empty when all held.
struct violation {
    std::string_view decoder;
    std::string_view what;
    unsigned accepted = 0;  // how many decoders accepted the frame (check_all), so that a sweep
                            // can show it is not all refusals
    [[nodiscard]] constexpr bool any() const noexcept { return !decoder.empty(); }
};

inline constexpr bool listed(errc e) noexcept {
    for (errc c : enum_values<errc>())
        if (c == e) return true;
    return false;
}

// Guard is constructed around each decode call only (not around the re-encoding or the
// comparisons, which read every byte of the frame on purpose).
template <class Guard, class Decode, class Encode>
constexpr violation check(std::string_view name, const can::frame& f, Decode decode,
                          Encode encode) noexcept {
    auto d = [&] {
        const Guard guard(f);
        return decode(f);
    }();
    if (!d) return listed(d.error()) ? violation{} : violation{name, "an unlisted errc", 0};
    const result<can::frame> e = encode(*d);
    if (!e) return {name, "encode refuses a decoded message", 0};
    if (!(*e == f)) return {name, "does not re-encode to the same frame", 0};
    const auto again = decode(*e);
    if (!again || !(*again == *d)) return {name, "does not decode again to the same message", 0};
    return {{}, {}, 1};
}

// Every decoder of the library on one frame, for a keypad at `node`.
template <class Guard>
constexpr violation check_all(const can::frame& f, canopen::node_id node) noexcept {
    using namespace powerkey::canopen;
    violation v;
    unsigned accepted = 0;
    auto run = [&](const violation& w) {
        accepted += w.accepted;
        if (!v.any() && w.any()) v = w;
    };
    auto frame_of = [](const auto& x) -> result<can::frame> { return x; };
    run(check<Guard>(
        "canopen::decode_nmt", f, [](const can::frame& x) { return decode_nmt(x); },
        [&](const auto& m) { return frame_of(encode(m)); }));
    run(check<Guard>(
        "canopen::decode_sync", f, [](const can::frame& x) { return decode_sync(x); },
        [&](const auto& m) { return frame_of(encode(m)); }));
    run(check<Guard>(
        "canopen::decode_heartbeat", f,
        [node](const can::frame& x) { return decode_heartbeat(x, node); },
        [&](const auto& m) { return frame_of(encode(node, m)); }));
    run(check<Guard>(
        "canopen::decode_sdo_request", f,
        [node](const can::frame& x) { return decode_sdo_request(x, node); },
        [&](const auto& m) { return frame_of(encode_request(node, m)); }));
    run(check<Guard>(
        "canopen::decode_sdo_response", f,
        [node](const can::frame& x) { return decode_sdo_response(x, node); },
        [&](const auto& m) { return frame_of(encode_response(node, m)); }));
    run(check<Guard>(
        "j1939::decode_switch_to_canopen", f,
        [](const can::frame& x) { return j1939::decode_switch_to_canopen(x); },
        [&](const auto& m) { return frame_of(j1939::encode(m)); }));
    for (const model m : enum_values<model>()) {
        // Read strictly, the keypad codec is a bijection on the frames it takes; read tolerantly
        // (the default), a frame not in the manual's form decodes to the meaning of the manual's
        // frame, which encode builds (docs/decoder.md, "Tolerant and strict reading").
        run(check<Guard>(
            "powerkey::decode", f,
            [node, m](const can::frame& x) {
                return powerkey::decode(x, node, m, reading::strict);
            },
            [&](const message& msg) { return powerkey::encode(node, m, msg); }));
        if (v.any()) continue;
        const auto t = [&] {
            const Guard guard(f);
            return powerkey::decode(f, node, m);
        }();
        const auto s = powerkey::decode(f, node, m, reading::strict);
        if (!t) {
            if (!listed(t.error())) v = {"powerkey::decode (tolerant)", "an unlisted errc", 0};
        } else if (form_of(*t) == frame_form::manual) {
            if (!s || !(*s == *t))
                v = {"powerkey::decode (tolerant)", "the manual's form read otherwise", 0};
        } else {
            const auto e = powerkey::encode(node, m, *t);
            const auto back = e ? powerkey::decode(*e, node, m, reading::strict) : s;
            if (s || !e || e->size() == f.size() || !back ||
                !(*back == powerkey::detail::with_form(*t, frame_form::manual)))
                v = {"powerkey::decode (tolerant)", "not the meaning of its manual's form", 0};
        }
    }
    if (!v.any())
        if (const auto d = sdo_agreement::disagreement(f, node); !d.empty())
            v = {"one SDO parser", d, 0};
    v.accepted = accepted;
    return v;
}

// Calls visit(frame, node) for every frame of the sweep around one base frame.
template <class Visit>
constexpr void sweep_around(const can::frame& base, canopen::node_id node, Visit&& visit) {
    const auto with = [&](std::uint8_t n, const can::payload& p) {
        const auto length = can::dlc::make(n).value();
        if (base.is_extended()) return can::frame(base.ext_id().value(), length, p);
        return can::frame(base.std_id().value(), length, p);
    };
    visit(base, node);
    // Every byte, each telling value.
    for (std::size_t i = 0; i < base.size(); ++i) {
        for (std::uint8_t b : telling_bytes) {
            auto p = base.bytes();
            p[i] = b;
            visit(with(base.size(), p), node);
        }
    }
    // Every dlc, the bytes kept, new ones 00h and FFh.
    for (std::uint8_t n = 0; n <= 8; ++n) {
        auto p = base.bytes();
        visit(with(n, p), node);
        for (std::size_t i = base.size(); i < 8; ++i) p[i] = 0xFF;
        visit(with(n, p), node);
    }
    // The same data on every function of this node and of the next, and as a 29-bit frame.
    if (!base.is_extended()) {
        const auto length = can::dlc::make(base.size()).value();
        const auto other = canopen::node_id::make(node.value() % 127 + 1).value();
        for (std::uint16_t fn : function_bases) {
            for (auto n : {node, other}) {
                const auto id = static_cast<std::uint16_t>(fn + (fn <= 0x080 ? 0 : n.value()));
                visit(can::frame(can::standard_id::make(id).value(), length, base.bytes()), node);
            }
        }
        visit(can::frame(can::extended_id::make(base.raw_id()).value(), length, base.bytes()),
              node);
    }
}

// The node a row's frame is sent to: its `node` (a number or a node_id), else the default.
template <class Row>
constexpr canopen::node_id node_of_row(const Row& r) noexcept {
    if constexpr (requires { r.node; }) {
        if constexpr (std::is_same_v<std::remove_cvref_t<decltype(r.node)>, canopen::node_id>)
            return r.node;
        else
            return canopen::node_id::make(r.node).value_or(canopen::default_node_id);
    } else {
        return canopen::default_node_id;
    }
}

// The sweep around every row of a table whose frame parses (an encode_error_row may have none).
template <class Row, std::size_t N, class Visit>
constexpr void sweep_table(const Row (&rows)[N], Visit& visit) {
    for (const auto& r : rows)
        if (const auto f = can::parse_candump(r.frame)) sweep_around(*f, node_of_row(r), visit);
}

// The sweep around every row of every frame table.
template <class Visit>
void sweep(Visit&& visit) {
    sweep_table(codec_rows::core_rows, visit);
    sweep_table(codec_rows::core_error_rows, visit);
    sweep_table(codec_rows::foreign_rows, visit);
    sweep_table(pk1000_rows::rows, visit);
    sweep_table(pk1000_rows::error_rows, visit);
    sweep_table(pk1000_rows::encode_error_rows, visit);
    sweep_table(pkp_rows::rows, visit);
    sweep_table(pkp_rows::error_rows, visit);
    sweep_table(pkp_rows::encode_error_rows, visit);
}

// A guard that does nothing, where the bytes past the dlc cannot be poisoned.
struct no_guard {
    constexpr explicit no_guard(const can::frame&) noexcept {}
};

}  // namespace invariants

#endif  // POWERKEY_TESTS_INVARIANTS_HPP
