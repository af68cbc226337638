// powerkey: a session follows one keypad through a bus log, frame by frame, without allocation:
// SDO pairs, string uploads, node-id changes, the protocol switch and the J1939 address
// (docs/decoder.md, "The session follower").
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
#include <powerkey/keypad/lookup.hpp>
#include <powerkey/keypad/models.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <variant>

namespace powerkey {

// clang-format off
#define POWERKEY_BUS_PROTOCOL_LIST(X) \
    X(canopen) \
    X(j1939)
// clang-format on
enum class bus_protocol : std::uint8_t { POWERKEY_BUS_PROTOCOL_LIST(POWERKEY_DETAIL_ENUMERATOR) };

// Where an SDO frame stands in its exchange.
// clang-format off
#define POWERKEY_SDO_PAIRING_LIST(X) \
    X(none)  /* not an SDO frame of the keypad, or not decodable as one */ \
    X(request)  /* a request (download, upload, segment); the session now waits for its reply */ \
    X(reply)  /* the reply to the pending request: `request` says which object */ \
    X(unanswered)  /* a reply when no request was pending, or for another object */
// clang-format on
enum class sdo_pairing : std::uint8_t { POWERKEY_SDO_PAIRING_LIST(POWERKEY_DETAIL_ENUMERATOR) };

}  // namespace powerkey

POWERKEY_DETAIL_ENUM_NAMES(powerkey::bus_protocol, POWERKEY_BUS_PROTOCOL_LIST);
POWERKEY_DETAIL_ENUM_NAMES(powerkey::sdo_pairing, POWERKEY_SDO_PAIRING_LIST);

namespace powerkey {

// An SDO frame of the keypad as the session read it: which frame of the protocol (the SDO engine's
// sdo_op) and the object it names (none for a segment or segment request).
struct sdo_frame {
    canopen::sdo_op op;
    canopen::sdo_address address{};
    friend constexpr bool operator==(const sdo_frame&, const sdo_frame&) noexcept = default;
};

// What one frame meant, and what it changed.
struct session_event {
    canopen::cob_info cls;
    canopen::node_id node = canopen::default_node_id;  // the node the frame was decoded for
    result<message> decoded = errc::unexpected_frame;
    sdo_pairing sdo = sdo_pairing::none;
    std::optional<powerkey::sdo_frame> sdo_frame;  // an SDO frame of the keypad: what it is
    canopen::sdo_address request{};  // the object of the request answered (sdo == reply)
    bool upload_done = false;        // a string upload (segmented or not) ended here: see text()
    errc upload_error{};             // a segmented upload failed with this frame (toggle, abort..)
    std::optional<canopen::node_id> new_node;  // the keypad moved to this node id
    std::optional<bus_protocol> new_protocol;  // the keypad switched protocol
    std::optional<std::uint8_t> new_address;   // the keypad's J1939 address is now this
};

template <std::size_t TextCapacity = 64>
class session {
public:
    // `how`: frames not in the manual's form decoded (the default) or refused (reading::strict).
    constexpr session(powerkey::model m, canopen::node_id node,
                      reading how = reading::tolerant) noexcept
        : model_(m), info_(&detail::row_or_none(m)), node_(node), upload_(node), how_(how) {}

    // The J1939 frames of the keypad at `address` only (decode's J1939 narrowing: nullopt, the
    // default, for any address until a 70h moves the keypad).
    constexpr void narrow_j1939(j1939::keypad_address address) noexcept {
        narrowing_ = address;
        if (address) address_ = *address;
    }
    // The address decode narrows the J1939 frames to: nullopt while any address decodes.
    [[nodiscard]] constexpr j1939::keypad_address j1939_narrowing() const noexcept {
        return narrowing_;
    }
    // The keypad's J1939 address as the session follows it: the narrowing's, else 21h (the
    // default, section 5), moved by 70h and learned from an address claim.
    [[nodiscard]] constexpr std::uint8_t j1939_address() const noexcept { return address_; }

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
        e.decoded = decode(f, e.node, model_, narrowing_, how_);
        const bool ours = e.cls.node == e.node.value();
        if (e.cls.fn == canopen::function::sdo_rx && ours) {
            e.sdo_frame = sdo_frame_of(f, e);
            if (e.sdo_frame) on_request(*e.sdo_frame, e);
        } else if (e.cls.fn == canopen::function::sdo_tx && ours) {
            e.sdo_frame = sdo_frame_of(f, e);
            if (e.sdo_frame) on_reply(*e.sdo_frame, f, e);
        } else if (e.cls.fn == canopen::function::j1939 && e.decoded) {
            on_j1939(*e.decoded, e);
        }
        return e;
    }

private:
    enum class pending_kind : std::uint8_t { none, download, upload, segmented };

    constexpr canopen::sdo_address address_of(object o) const noexcept {
        return detail::codec_rows[detail::find_codec_row(info_->dictionary, o)].address();
    }

    // The SDO frame: from what decode returned, or as the SDO engine reads it when decode refused
    // it (an object the dictionary lacks, a value out of range: the keypad's abort still answers
    // it).
    constexpr std::optional<powerkey::sdo_frame> sdo_frame_of(
        const can::frame& f, const session_event& e) const noexcept {
        using op = canopen::sdo_op;
        if (e.decoded) {
            return std::visit(
                [this](const auto& v) -> std::optional<powerkey::sdo_frame> {
                    using T = std::remove_cvref_t<decltype(v)>;
                    if constexpr (std::is_same_v<T, sdo_read>)
                        return powerkey::sdo_frame{op::upload, address_of(v.object)};
                    else if constexpr (std::is_same_v<T, sdo_write>)
                        return powerkey::sdo_frame{op::expedited_download, address_of(v.object)};
                    else if constexpr (std::is_same_v<T, command>)
                        return powerkey::sdo_frame{op::expedited_download,
                                                   address_of(object::command_module)};
                    else if constexpr (std::is_same_v<T, canopen::sdo_segment_request>)
                        return powerkey::sdo_frame{op::segment_request};
                    else if constexpr (std::is_same_v<T, canopen::sdo_abort_request>)
                        return powerkey::sdo_frame{op::abort_request, v.abort.address};
                    else if constexpr (std::is_same_v<T, sdo_write_reply>)
                        return powerkey::sdo_frame{op::download_response, address_of(v.object)};
                    else if constexpr (std::is_same_v<T, sdo_read_reply>)
                        return powerkey::sdo_frame{op::expedited_upload, address_of(v.object)};
                    else if constexpr (std::is_same_v<T, canopen::sdo_upload_initiate_response>)
                        return powerkey::sdo_frame{op::upload_initiate, v.address};
                    else if constexpr (std::is_same_v<T, canopen::sdo_segment_response>)
                        return powerkey::sdo_frame{op::segment};
                    else if constexpr (std::is_same_v<T, canopen::sdo_abort_response>)
                        return powerkey::sdo_frame{op::abort_response, v.abort.address};
                    else
                        return std::nullopt;
                },
                *e.decoded);
        }
        // A frame of another length (trimmed, or refused as too short) is read zero-filled: its
        // request still waits for a reply whatever its form (issue 22).
        if (f.size() < 4) return std::nullopt;
        const auto w = canopen::sdo_word::of(detail::with_length(f, 8));
        const auto o = e.cls.fn == canopen::function::sdo_rx ? canopen::sdo_request_op(w)
                                                             : canopen::sdo_response_op(w);
        if (!o) return std::nullopt;
        if (*o == op::segment || *o == op::segment_request)
            return powerkey::sdo_frame{*o};  // a segment names no object
        return powerkey::sdo_frame{*o, w.address()};
    }

    constexpr void on_request(const powerkey::sdo_frame& s, session_event& e) noexcept {
        e.sdo = sdo_pairing::request;
        switch (s.op) {
            case canopen::sdo_op::expedited_download:
                pending_ = pending_kind::download;
                pending_address_ = s.address;
                change_ = std::nullopt;
                if (e.decoded) on_write(*e.decoded, e);
                break;
            case canopen::sdo_op::upload:
                pending_ = pending_kind::upload;
                pending_address_ = s.address;
                upload_ = canopen::segmented_upload<TextCapacity>(e.node);
                (void)upload_.start(s.address);
                break;
            case canopen::sdo_op::abort_request:
                pending_ = pending_kind::none;
                pending_address_ = s.address;
                break;
            default: break;  // a segment request keeps the segmented upload pending
        }
    }

    // The writes that move the keypad to another node id or protocol.
    constexpr void on_write(const message& msg, session_event& e) noexcept {
        if (const auto n = node_id_change(msg); n && *n != node_) {
            if (info_->replies_from_new_id) {  // PK1000 section 23: the reply comes from the new id
                previous_node_ = node_;
                node_ = *n;
                e.new_node = node_;
            } else {  // PKP section 13 h: the reply from the old id, the boot-up from the new one
                change_ = *n;
            }
        }
        if (const auto* w = std::get_if<sdo_write>(&msg);
            w && w->object == object::protocol_j1939 && w->value.raw == 1) {
            protocol_ = bus_protocol::j1939;  // PK1000 section 49
            e.new_protocol = protocol_;
        }
    }

    // The J1939 frames that move the keypad: 70h and 80h sent to its address, an address claim.
    constexpr void on_j1939(const message& msg, session_event& e) noexcept {
        if (const auto* c = std::get_if<j1939::command>(&msg)) {
            // Section 16: "the new source address takes effect immediately"; FFh is no change.
            if (c->code == j1939::command_code::set_source_address && c->destination == address_ &&
                c->address != j1939::global_address) {
                narrowing_ = c->address;  // the old address is no longer the keypad's
                if (c->address != address_) e.new_address = c->address;
                address_ = c->address;
            }
        } else if (const auto* s = std::get_if<j1939::switch_to_canopen>(&msg)) {
            if (s->destination == address_) {  // section 27; its CANopen node is unchanged
                protocol_ = bus_protocol::canopen;
                e.new_protocol = protocol_;
            }
        } else if (const auto* a = std::get_if<j1939::address_claimed>(&msg)) {
            // Narrowed, only the keypad's own claim decodes; otherwise a claim says where the
            // keypad is (the NAME is the same placeholder on every keypad: docs/j1939.md), but
            // for one from the null address FEh: a device that could claim none.
            if (a->source != address_ && a->source != j1939::null_address) {
                address_ = a->source;
                e.new_address = address_;
            }
        }
    }

    constexpr void on_reply(const powerkey::sdo_frame& s, const can::frame& f,
                            session_event& e) noexcept {
        e.sdo = sdo_pairing::unanswered;
        const pending_kind was = pending_;
        const canopen::sdo_address asked = pending_address_;
        auto answers = [&](canopen::sdo_address a) {
            return was != pending_kind::none && a == asked;
        };
        switch (s.op) {
            case canopen::sdo_op::download_response:
                if (was == pending_kind::download && answers(s.address)) pair(e);
                if (change_ && e.sdo == sdo_pairing::reply) {
                    node_ = *change_;
                    e.new_node = node_;
                }
                change_ = std::nullopt;
                break;
            case canopen::sdo_op::abort_response:
                if (answers(s.address)) pair(e);
                if (was == pending_kind::upload || was == pending_kind::segmented)
                    step_upload(f, e);
                if (previous_node_ && e.node == *previous_node_) {  // the change was refused
                    node_ = *previous_node_;
                    e.new_node = node_;
                }
                change_ = std::nullopt;
                break;
            case canopen::sdo_op::segment:
                if (was == pending_kind::segmented) {
                    pair(e);
                    step_upload(f, e);
                }
                break;
            case canopen::sdo_op::expedited_upload:
                if (was == pending_kind::upload && answers(s.address)) {
                    pair(e);
                    // A string of up to four bytes comes in one reply: it ends the upload too.
                    const auto* v = e.decoded ? std::get_if<sdo_read_reply>(&*e.decoded) : nullptr;
                    if (v && info(v->object).kind == value_kind::string) step_upload(f, e);
                }
                break;
            case canopen::sdo_op::upload_initiate:
                if (was == pending_kind::upload && answers(s.address)) {
                    pair(e);
                    step_upload(f, e);
                }
                break;
            default: break;
        }
        if (e.cls.node == node_.value() || (previous_node_ && e.node == *previous_node_))
            previous_node_ = std::nullopt;  // the first reply settles a node change
    }

    constexpr void pair(session_event& e) noexcept {
        e.sdo = sdo_pairing::reply;
        e.request = pending_address_;
        pending_ = pending_kind::none;
    }

    // The upload reader takes the reply as decode returned it; a reply decode refused is read by
    // the CiA 301 decoder (the same SDO engine).
    constexpr void step_upload(const can::frame& f, session_event& e) noexcept {
        if (upload_.state() != canopen::upload_state::running) return;
        const auto s = e.decoded ? upload_.step(as_response(*e.decoded)) : upload_.step(f);
        if (!s) {
            e.upload_error = s.error();
        } else if (upload_.state() == canopen::upload_state::done) {
            e.upload_done = true;
        } else {
            pending_ = pending_kind::segmented;
            pending_address_ = upload_.address();
        }
    }

    // The CiA 301 view of a decoded reply that belongs to an upload (step_upload's callers made
    // sure it is one): a string read whole, a segmented upload's start, a segment, an abort.
    constexpr canopen::sdo_response as_response(const message& msg) const noexcept {
        if (const auto* v = std::get_if<sdo_read_reply>(&msg)) {
            canopen::expedited_data d{
                canopen::expedited_size::make(v->value.size).value_or(canopen::expedited_size{4}),
                {}};
            detail::store_le<4>(d.bytes, 0, v->value.raw);
            return canopen::sdo_upload_response{address_of(v->object), d};
        }
        if (const auto* i = std::get_if<canopen::sdo_upload_initiate_response>(&msg)) return *i;
        if (const auto* s = std::get_if<canopen::sdo_segment_response>(&msg)) return *s;
        if (const auto* a = std::get_if<canopen::sdo_abort_response>(&msg)) return a->abort;
        return canopen::sdo_download_response{};  // not an upload's: the reader refuses it
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
    reading how_ = reading::tolerant;
    j1939::keypad_address narrowing_;  // decode's J1939 narrowing (narrow_j1939, then 70h)
    std::uint8_t address_ = j1939::keypad_default_address;  // the keypad's J1939 address
};

}  // namespace powerkey

#endif  // POWERKEY_SESSION_HPP
