// powerkey: a session follows a bus log, frame by frame and in order, without allocation:
//   - it decodes each frame for the keypad's current node id (decode(f, node, model));
//   - it pairs each SDO request with its reply (same index and sub-index) and flags replies
//     that answer nothing;
//   - it runs segmented uploads (device name 1008h, serial numbers ...) through the core reader
//     canopen::segmented_upload, so the whole string is there when the last segment passes;
//   - it follows a node-id change to the new COB-IDs: a keypad that answers from the new id
//     (PK1000 object 2013h, section 23) or from the old id and then boots up with the new one
//     (PKP command 6500h/70h, section 13 h), as the model table says;
//   - it notices the switch to J1939 (a write of protocol_j1939 = 1, PK1000 section 49) and back
//     (the 18EF2100h frame), for the models that have it.
//
//   session<> s(model::pk1000, canopen::default_node_id);
//   for (const can::frame& f : log) {
//       const auto e = s.step(f);
//       if (e.upload_done) print(s.text());
//       if (e.new_node) print(*e.new_node);
//   }
#ifndef POWERKEY_SESSION_HPP
#define POWERKEY_SESSION_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/canopen/sdo_upload.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/keypad/accessors.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/models.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <variant>

namespace powerkey {

enum class bus_protocol : std::uint8_t { canopen, j1939 };

// Where an SDO frame stands in its exchange.
enum class sdo_pairing : std::uint8_t {
    none,        // not an SDO frame of the keypad, or not decodable as one
    request,     // a request (download, upload, segment); the session now waits for its reply
    reply,       // the reply to the pending request: `request` says which object
    unanswered,  // a reply when no request was pending, or for another object
};

template <>
struct enum_names<bus_protocol> {
    static constexpr enum_name_entry<bus_protocol> entries[] = {{bus_protocol::canopen, "canopen"},
                                                                {bus_protocol::j1939, "j1939"}};
};
template <>
struct enum_names<sdo_pairing> {
    using p = sdo_pairing;
    static constexpr enum_name_entry<p> entries[] = {{p::none, "none"},
                                                     {p::request, "request"},
                                                     {p::reply, "reply"},
                                                     {p::unanswered, "unanswered"}};
};

// What one frame meant, and what it changed.
struct session_event {
    canopen::cob_info cls;
    canopen::node_id node = canopen::default_node_id;  // the node the frame was decoded for
    result<message> decoded = errc::unexpected_frame;
    sdo_pairing sdo = sdo_pairing::none;
    canopen::sdo_address request{};  // the object of the request answered (sdo == reply)
    bool upload_done = false;        // a string upload (segmented or not) ended here: see text()
    errc upload_error{};             // a segmented upload failed with this frame (toggle, abort..)
    std::optional<canopen::node_id> new_node;  // the keypad moved to this node id
    std::optional<bus_protocol> new_protocol;  // the keypad switched protocol
};

template <std::size_t TextCapacity = 64>
class session {
public:
    constexpr session(powerkey::model m, canopen::node_id node) noexcept
        : model_(m), info_(&detail::row_or_none(m)), node_(node), upload_(node) {}

    [[nodiscard]] constexpr powerkey::model model() const noexcept { return model_; }
    [[nodiscard]] constexpr canopen::node_id node() const noexcept { return node_; }
    [[nodiscard]] constexpr bus_protocol protocol() const noexcept { return protocol_; }
    // The last segmented upload: its text (NULs left out), its bytes, what went against the
    // segment rules, and the object read.
    [[nodiscard]] constexpr std::string_view text() const noexcept { return upload_.text(); }
    [[nodiscard]] constexpr const canopen::segmented_upload<TextCapacity>& upload() const noexcept {
        return upload_;
    }

    [[nodiscard]] constexpr session_event step(const can::frame& f) noexcept {
        session_event e;
        e.cls = canopen::classify(f);
        // During a node change the keypad may still answer (an abort) from the old id.
        e.node = node_;
        if (previous_node_ && e.cls.node == previous_node_->value()) e.node = *previous_node_;
        e.decoded = decode(f, e.node, model_);
        if (e.cls.fn == canopen::function::sdo_rx && e.cls.node == e.node.value())
            on_request(f, e);
        else if (e.cls.fn == canopen::function::sdo_tx && e.cls.node == e.node.value())
            on_reply(f, e);
        else if (e.decoded && std::holds_alternative<j1939::switch_to_canopen>(*e.decoded)) {
            protocol_ = bus_protocol::canopen;
            e.new_protocol = protocol_;
        }
        return e;
    }

private:
    enum class pending_kind : std::uint8_t { none, download, upload, segmented };

    constexpr void on_request(const can::frame& f, session_event& e) noexcept {
        const auto r = canopen::decode_sdo_request(f, e.node);
        if (!r) return;
        e.sdo = sdo_pairing::request;
        if (const auto* d = std::get_if<canopen::sdo_download_request>(&*r)) {
            pending_ = pending_kind::download;
            pending_address_ = d->address;
            change_ = std::nullopt;
            if (e.decoded) on_write(*e.decoded, e);
        } else if (const auto* u = std::get_if<canopen::sdo_upload_request>(&*r)) {
            pending_ = pending_kind::upload;
            pending_address_ = u->address;
            upload_ = canopen::segmented_upload<TextCapacity>(e.node);
            (void)upload_.start(u->address);
        } else if (const auto* a = std::get_if<canopen::sdo_abort>(&*r)) {
            pending_ = pending_kind::none;
            pending_address_ = a->address;
        }
        // A segment request keeps the segmented upload pending.
    }

    // The writes that move the keypad to another node id or protocol.
    constexpr void on_write(const message& m, session_event& e) noexcept {
        if (const auto n = node_id_change(m); n && *n != node_) {
            if (info_->replies_from_new_id) {  // PK1000 section 23: the reply comes from the new id
                previous_node_ = node_;
                node_ = *n;
                e.new_node = node_;
            } else {  // PKP section 13 h: the reply from the old id, the boot-up from the new one
                change_ = *n;
            }
        }
        if (const auto* w = std::get_if<sdo_write>(&m);
            w && w->object == object::protocol_j1939 && w->value.raw == 1) {
            protocol_ = bus_protocol::j1939;  // PK1000 section 49
            e.new_protocol = protocol_;
        }
    }

    constexpr void on_reply(const can::frame& f, session_event& e) noexcept {
        const auto r = canopen::decode_sdo_response(f, e.node);
        if (!r) return;
        e.sdo = sdo_pairing::unanswered;
        const pending_kind was = pending_;
        const canopen::sdo_address asked = pending_address_;
        auto answers = [&](canopen::sdo_address a) {
            return was != pending_kind::none && a == asked;
        };
        if (const auto* d = std::get_if<canopen::sdo_download_response>(&*r)) {
            if (was == pending_kind::download && answers(d->address)) pair(e);
            if (change_ && e.sdo == sdo_pairing::reply) {
                node_ = *change_;
                e.new_node = node_;
            }
            change_ = std::nullopt;
        } else if (const auto* a = std::get_if<canopen::sdo_abort>(&*r)) {
            if (answers(a->address)) pair(e);
            if (was == pending_kind::upload || was == pending_kind::segmented) step_upload(f, e);
            if (previous_node_ && e.node == *previous_node_) {  // the node change was refused
                node_ = *previous_node_;
                e.new_node = node_;
            }
            change_ = std::nullopt;
        } else if (std::holds_alternative<canopen::sdo_segment_response>(*r)) {
            if (was == pending_kind::segmented) {
                pair(e);
                step_upload(f, e);
            }
        } else if (const auto* u = std::get_if<canopen::sdo_upload_response>(&*r)) {
            if (was == pending_kind::upload && answers(u->address)) {
                pair(e);
                // A string of up to four bytes comes in one reply: it ends the upload too.
                const auto* v = e.decoded ? std::get_if<sdo_read_reply>(&*e.decoded) : nullptr;
                if (v && info(v->object).kind == value_kind::string) step_upload(f, e);
            }
        } else if (const auto* i = std::get_if<canopen::sdo_upload_initiate_response>(&*r)) {
            if (was == pending_kind::upload && answers(i->address)) {
                pair(e);
                step_upload(f, e);
            }
        }
        if (e.cls.node == node_.value() || (previous_node_ && e.node == *previous_node_))
            previous_node_ = std::nullopt;  // the first reply settles a node change
    }

    constexpr void pair(session_event& e) noexcept {
        e.sdo = sdo_pairing::reply;
        e.request = pending_address_;
        pending_ = pending_kind::none;
    }

    constexpr void step_upload(const can::frame& f, session_event& e) noexcept {
        if (upload_.state() != canopen::upload_state::running) return;
        const auto s = upload_.step(f);
        if (!s) {
            e.upload_error = s.error();
        } else if (upload_.state() == canopen::upload_state::done) {
            e.upload_done = true;
        } else {
            pending_ = pending_kind::segmented;
            pending_address_ = upload_.address();
        }
    }

    powerkey::model model_;
    const model_info* info_;  // the model's row (detail::row_or_none)
    canopen::node_id node_;
    bus_protocol protocol_ = bus_protocol::canopen;
    pending_kind pending_ = pending_kind::none;
    canopen::sdo_address pending_address_{};
    std::optional<canopen::node_id> previous_node_;  // the id before a change answered from the new
    std::optional<canopen::node_id> change_;         // the id after the reply (old-id models)
    canopen::segmented_upload<TextCapacity> upload_;
};

}  // namespace powerkey

#endif  // POWERKEY_SESSION_HPP
