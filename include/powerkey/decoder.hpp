// powerkey: the any-frame decoder. Given a keypad model and its node id, one constexpr call turns
// any CAN frame into a typed message, or into a precise error; a frame that belongs to no keypad
// (another node, another function) is classified and refused with errc::wrong_id, never
// mis-decoded.
//
//   classify(f)                    which function (nmt .. heartbeat, j1939, other) and node
//   core::decode(f, node)          the CiA 301 / J1939 messages every keypad speaks
//   decode(f, node, model)         everything the model's profile defines
//   encode(node, model, message)   the inverse: encode(decode(f)) == f
#ifndef POWERKEY_DECODER_HPP
#define POWERKEY_DECODER_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/canopen/sync.hpp>
#include <powerkey/j1939/id.hpp>
#include <powerkey/j1939/protocol_switch.hpp>
#include <powerkey/pk1000/profile.hpp>
#include <powerkey/pkp/profile.hpp>
#include <powerkey/result.hpp>

#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>
#include <variant>

namespace powerkey {

// --- models ---------------------------------------------------------------------------------

enum class model : std::uint8_t { pk1000, pkp2200, pkp2400, pkp2600 };

// The names the command-line tool takes and prints.
[[nodiscard]] constexpr std::string_view to_string(model m) noexcept {
    switch (m) {
        case model::pk1000: return "pk1000";
        case model::pkp2200: return "pkp2200";
        case model::pkp2400: return "pkp2400";
        case model::pkp2600: return "pkp2600";
    }
    return "unknown";
}

inline constexpr model all_models[] = {model::pk1000, model::pkp2200, model::pkp2400,
                                       model::pkp2600};

// A model from its name; errc::value_out_of_range for any other text.
[[nodiscard]] constexpr result<model> parse_model(std::string_view name) noexcept {
    for (model m : all_models)
        if (to_string(m) == name) return m;
    return errc::value_out_of_range;
}

// --- classification -------------------------------------------------------------------------

// What a frame is on the bus, before decoding: the CiA 301 function of an 11-bit identifier,
// or j1939 for every 29-bit identifier.
enum class bus_function : std::uint8_t {
    nmt,
    sync,
    tpdo1,
    rpdo1,
    rpdo2,
    rpdo3,
    rpdo4,
    sdo_tx,
    sdo_rx,
    heartbeat,
    j1939,
    other,
};

[[nodiscard]] constexpr std::string_view to_string(bus_function f) noexcept {
    switch (f) {
        case bus_function::nmt: return "nmt";
        case bus_function::sync: return "sync";
        case bus_function::tpdo1: return "tpdo1";
        case bus_function::rpdo1: return "rpdo1";
        case bus_function::rpdo2: return "rpdo2";
        case bus_function::rpdo3: return "rpdo3";
        case bus_function::rpdo4: return "rpdo4";
        case bus_function::sdo_tx: return "sdo_tx";
        case bus_function::sdo_rx: return "sdo_rx";
        case bus_function::heartbeat: return "heartbeat";
        case bus_function::j1939: return "j1939";
        case bus_function::other: return "other";
    }
    return "other";
}

struct frame_class {
    bus_function function = bus_function::other;
    // The node of a per-node COB-ID (tpdo1 .. heartbeat), 1..127; 0 for nmt, sync, j1939, other.
    std::uint8_t node = 0;
    friend constexpr bool operator==(const frame_class&, const frame_class&) noexcept = default;
};

[[nodiscard]] constexpr frame_class classify(const can::frame& f) noexcept {
    if (f.is_extended()) return {bus_function::j1939, 0};
    const auto c = canopen::classify(f);
    switch (c.fn) {
        case canopen::function::nmt: return {bus_function::nmt, 0};
        case canopen::function::sync: return {bus_function::sync, 0};
        case canopen::function::tpdo1: return {bus_function::tpdo1, c.node};
        case canopen::function::rpdo1: return {bus_function::rpdo1, c.node};
        case canopen::function::rpdo2: return {bus_function::rpdo2, c.node};
        case canopen::function::rpdo3: return {bus_function::rpdo3, c.node};
        case canopen::function::rpdo4: return {bus_function::rpdo4, c.node};
        case canopen::function::sdo_tx: return {bus_function::sdo_tx, c.node};
        case canopen::function::sdo_rx: return {bus_function::sdo_rx, c.node};
        case canopen::function::heartbeat: return {bus_function::heartbeat, c.node};
        case canopen::function::other: break;
    }
    return {bus_function::other, 0};
}

// True when the frame is addressed to or sent by the keypad `node`: NMT and SYNC (every node
// hears them), a J1939 frame (the keypad's protocol switch), or a per-node COB-ID of `node`.
[[nodiscard]] constexpr bool concerns(const frame_class& c, canopen::node_id node) noexcept {
    switch (c.function) {
        case bus_function::nmt:
        case bus_function::sync:
        case bus_function::j1939: return true;
        case bus_function::other: return false;
        default: return c.node == node.value();
    }
}

// --- the core messages every keypad speaks ------------------------------------------------------

namespace core {

// An SDO abort sent by the client (600h + node): the core type keeps its direction.
using canopen::sdo_abort_request;

// An SDO abort sent by the keypad (580h + node).
struct sdo_abort_response {
    static constexpr std::string_view kind = "sdo_abort_response";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        canopen::sdo_abort::fields(self.abort, f);
    }
    canopen::sdo_abort abort;
    friend constexpr bool operator==(const sdo_abort_response&,
                                     const sdo_abort_response&) noexcept = default;
};

using message =
    std::variant<canopen::nmt_message, canopen::sync_message, canopen::heartbeat_message,
                 j1939::switch_to_canopen, canopen::sdo_download_request,
                 canopen::sdo_upload_request, canopen::sdo_segment_request, sdo_abort_request,
                 canopen::sdo_download_response, canopen::sdo_upload_response,
                 canopen::sdo_upload_initiate_response, canopen::sdo_segment_response,
                 sdo_abort_response>;

// The core view of a frame of keypad `node`. Errors: wrong_id (another node's COB-ID, or a
// function no keypad uses), unknown_object (a PDO: its meaning is the profile's), and whatever
// the core decoder of the frame's function returns.
[[nodiscard]] constexpr result<message> decode(const can::frame& f,
                                               canopen::node_id node) noexcept {
    const auto c = classify(f);
    if (!concerns(c, node)) return errc::wrong_id;
    auto lift = [](const auto& r) -> result<message> {
        if (!r) return r.error();
        return message{*r};
    };
    switch (c.function) {
        case bus_function::nmt: return lift(canopen::decode_nmt(f));
        case bus_function::sync: return lift(canopen::decode_sync(f));
        case bus_function::heartbeat: return lift(canopen::decode_heartbeat(f, node));
        case bus_function::j1939: return lift(j1939::decode_switch_to_canopen(f));
        case bus_function::sdo_rx: {
            const auto r = canopen::decode_sdo_request(f, node);
            if (!r) return r.error();
            return std::visit(
                [](const auto& v) -> result<message> {
                    if constexpr (std::is_same_v<std::decay_t<decltype(v)>, canopen::sdo_abort>)
                        return message{sdo_abort_request{v}};
                    else
                        return message{v};
                },
                *r);
        }
        case bus_function::sdo_tx: {
            const auto r = canopen::decode_sdo_response(f, node);
            if (!r) return r.error();
            return std::visit(
                [](const auto& v) -> result<message> {
                    if constexpr (std::is_same_v<std::decay_t<decltype(v)>, canopen::sdo_abort>)
                        return message{sdo_abort_response{v}};
                    else
                        return message{v};
                },
                *r);
        }
        default: return errc::unknown_object;
    }
}

[[nodiscard]] constexpr can::frame encode(canopen::node_id node, const message& m) noexcept {
    return std::visit(
        [node](const auto& v) -> can::frame {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, canopen::nmt_message> ||
                          std::is_same_v<T, canopen::sync_message> ||
                          std::is_same_v<T, j1939::switch_to_canopen>)
                return encode(v);  // canopen::encode or j1939::encode, found by ADL
            else if constexpr (std::is_same_v<T, sdo_abort_request>)
                return canopen::encode(node, v.abort, canopen::sdo_direction::request);
            else if constexpr (std::is_same_v<T, sdo_abort_response>)
                return canopen::encode(node, v.abort, canopen::sdo_direction::response);
            else
                return canopen::encode(node, v);
        },
        m);
}

}  // namespace core

// --- every frame of a model ---------------------------------------------------------------------

// The PKP profile's model for a PKP keypad; nullopt for the PK1000.
[[nodiscard]] constexpr std::optional<pkp::model> pkp_model(model m) noexcept {
    switch (m) {
        case model::pkp2200: return pkp::model::pkp2200;
        case model::pkp2400: return pkp::model::pkp2400;
        case model::pkp2600: return pkp::model::pkp2600;
        default: return std::nullopt;
    }
}

// A message of any model: the PK1000 profile's or the PKP profile's.
using message = std::variant<pk1000::message, pkp::message>;

// Any frame of keypad `node` of model `m`. Errors: wrong_id (a frame of another node, or of a
// function no keypad uses), wrong_id_format (a 29-bit frame for a keypad without J1939), and
// every error of the profile's decoder (unknown_object, value_out_of_range, wrong_length ...).
[[nodiscard]] constexpr result<message> decode(const can::frame& f, canopen::node_id node,
                                               model m) noexcept {
    if (const auto pm = pkp_model(m)) {
        const auto r = pkp::decode(f, node, *pm);
        if (!r) return r.error();
        return message{*r};
    }
    const auto r = pk1000::decode(f, node);
    if (!r) return r.error();
    return message{*r};
}

// The inverse of decode: encode(node, m, *decode(f, node, m)) == f. Errors: unknown_command
// (a message of another model's profile), and the profile encoder's errors (a key or LED the
// model lacks: value_out_of_range).
[[nodiscard]] constexpr result<can::frame> encode(canopen::node_id node, model m,
                                                  const message& msg) noexcept {
    if (const auto* c = std::get_if<pk1000::message>(&msg)) {
        if (pkp_model(m)) return errc::unknown_command;
        return pk1000::encode(node, *c);
    }
    const auto pm = pkp_model(m);
    if (!pm) return errc::unknown_command;
    return pkp::encode(node, *pm, std::get<pkp::message>(msg));
}

}  // namespace powerkey

#endif  // POWERKEY_DECODER_HPP
