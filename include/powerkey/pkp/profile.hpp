// powerkey PKP: the whole profile behind two calls.
//   pkp::decode(frame, node, model)   any frame of a PKP keypad -> a typed message, or an errc
//   pkp::encode(node, model, message) the inverse: encode(decode(f)) == f for every accepted f
// Frames: NMT 000h, SYNC 080h, key state 180h, LED on 200h, LED blink 300h, SDO 600h/580h, boot-up
// and heartbeat 700h (+ node for all but NMT and SYNC). The PKP manual has no J1939 mode.
#ifndef POWERKEY_PKP_PROFILE_HPP
#define POWERKEY_PKP_PROFILE_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/canopen/sync.hpp>
#include <powerkey/pkp/command.hpp>
#include <powerkey/pkp/model.hpp>
#include <powerkey/pkp/objects.hpp>
#include <powerkey/pkp/pdo.hpp>
#include <powerkey/result.hpp>

#include <type_traits>
#include <variant>

namespace powerkey::pkp {

using message = std::variant<
    // CiA 301 core
    canopen::nmt_message, canopen::sync_message, canopen::heartbeat_message,
    canopen::sdo_segment_request, canopen::sdo_segment_response,
    canopen::sdo_upload_initiate_response, canopen::sdo_abort, sdo_abort_request,
    // PDOs
    key_state, led_on, led_blink,
    // SDO reads and writes of the object table
    read_request, read_response, write_request, write_response, keys_response, write_led_on,
    write_led_blink, led_on_response, led_blink_response,
    // the command module, 6500h sub 1
    set_led_state, set_led_brightness, set_backlight_brightness, set_backlight_colour,
    set_active_on_startup, set_baud_rate, set_periodic_transmission, set_boot_up_service,
    set_node_id, set_demo_mode, set_default_backlight_level, set_default_led_level,
    set_default_backlight_colour, set_startup_show>;

// --- decoding ---------------------------------------------------------------------------------

namespace detail {

template <class V>
constexpr message widen(const V& v) noexcept {
    return std::visit([](const auto& x) -> message { return x; }, v);
}

constexpr result<message> decode_request(const can::frame& f, canopen::node_id node,
                                         model m) noexcept {
    const auto r = canopen::decode_sdo_request(f, node);
    if (!r) return r.error();
    if (std::holds_alternative<canopen::sdo_segment_request>(*r))
        return message{std::get<canopen::sdo_segment_request>(*r)};
    if (std::holds_alternative<canopen::sdo_abort>(*r)) {
        const auto& a = std::get<canopen::sdo_abort>(*r);
        return message{sdo_abort_request{a}};
    }
    if (std::holds_alternative<canopen::sdo_upload_request>(*r)) {
        const auto o = find_object(std::get<canopen::sdo_upload_request>(*r).address);
        if (!o) return errc::unknown_object;
        if (!info(*o)->readable) return errc::unknown_command;
        return message{read_request{*o}};
    }
    const auto& d = std::get<canopen::sdo_download_request>(*r);
    const auto o = find_object(d.address);
    if (!o) return errc::unknown_object;
    if (!info(*o)->writable) return errc::unknown_command;
    const auto i = *info(*o);
    switch (i.type) {
        case value_type::commands: {
            const auto c = decode_command(d, m);
            if (!c) return c.error();
            return widen(*c);
        }
        case value_type::led_map: {
            if (d.value.size.value() != 4) return errc::size_mismatch;
            const auto l = led_value_of(m, d.value.bytes);
            if (!l) return l.error();
            if (*o == object::led_on) return message{write_led_on{*l}};
            return message{write_led_blink{*l}};
        }
        default: {
            const auto v = number_of(i, d.value);
            if (!v) return v.error();
            return message{write_request{*o, *v}};
        }
    }
}

constexpr result<message> decode_response(const can::frame& f, canopen::node_id node,
                                          model m) noexcept {
    const auto r = canopen::decode_sdo_response(f, node);
    if (!r) return r.error();
    if (std::holds_alternative<canopen::sdo_segment_response>(*r))
        return message{std::get<canopen::sdo_segment_response>(*r)};
    if (std::holds_alternative<canopen::sdo_abort>(*r))
        return message{std::get<canopen::sdo_abort>(*r)};
    if (std::holds_alternative<canopen::sdo_download_response>(*r)) {
        const auto o = find_object(std::get<canopen::sdo_download_response>(*r).address);
        if (!o) return errc::unknown_object;
        if (!info(*o)->writable) return errc::unknown_command;
        return message{write_response{*o}};
    }
    if (std::holds_alternative<canopen::sdo_upload_initiate_response>(*r)) {
        const auto& s = std::get<canopen::sdo_upload_initiate_response>(*r);
        const auto o = find_object(s.address);
        if (!o || info(*o)->type != value_type::string) return errc::unknown_object;
        return message{s};
    }
    const auto& u = std::get<canopen::sdo_upload_response>(*r);
    const auto o = find_object(u.address);
    if (!o || info(*o)->type == value_type::string) return errc::unknown_object;
    if (!info(*o)->readable) return errc::unknown_command;
    const auto i = *info(*o);
    if (i.type == value_type::keys || i.type == value_type::led_map) {
        if (u.value.size.value() != 4) return errc::size_mismatch;
        if (i.type == value_type::keys) {
            const auto k = keys_value_of(m, u.value.bytes);
            if (!k) return k.error();
            return message{keys_response{*k}};
        }
        const auto l = led_value_of(m, u.value.bytes);
        if (!l) return l.error();
        if (*o == object::led_on) return message{led_on_response{*l}};
        return message{led_blink_response{*l}};
    }
    const auto v = number_of(i, u.value);
    if (!v) return v.error();
    return message{read_response{*o, *v}};
}

}  // namespace detail

// Any frame of a PKP keypad of model m at `node`. Errors:
//   wrong_id_format  a 29-bit identifier
//   wrong_id         an identifier of another node, or of a function the keypad does not use
//   wrong_length, reserved_not_zero, value_out_of_range
//                    from the message's decoder (NMT, heartbeat, PDOs, SDO, command module)
//   unknown_command  an NMT or SDO specifier the keypad does not use, a 6500h command byte it
//                    does not define, an access the entry does not have (a write to a read-only
//                    entry or its acknowledgement, a read of 6500h)
//   unknown_object   an SDO for an index/sub-index the profile does not define; an expedited
//                    reply for a string entry or a segmented one for a number entry
//   size_mismatch    an expedited SDO whose size is not the entry's
[[nodiscard]] constexpr result<message> decode(const can::frame& f, canopen::node_id node,
                                               model m) noexcept {
    if (f.is_extended()) return errc::wrong_id_format;
    if (key_count(m) == 0) return errc::value_out_of_range;
    const auto c = canopen::classify(f);
    if (c.fn == canopen::function::nmt) {
        const auto r = canopen::decode_nmt(f);
        if (!r) return r.error();
        return message{*r};
    }
    if (c.fn == canopen::function::sync) {
        const auto r = canopen::decode_sync(f);
        if (!r) return r.error();
        return message{*r};
    }
    if (c.node != node.value()) return errc::wrong_id;
    switch (c.fn) {
        case canopen::function::tpdo1: {
            const auto r = decode_key_state(f, node, m);
            if (!r) return r.error();
            return message{*r};
        }
        case canopen::function::rpdo1: {
            const auto r = decode_led_on(f, node, m);
            if (!r) return r.error();
            return message{*r};
        }
        case canopen::function::rpdo2: {
            const auto r = decode_led_blink(f, node, m);
            if (!r) return r.error();
            return message{*r};
        }
        case canopen::function::heartbeat: {
            const auto r = canopen::decode_heartbeat(f, node);
            if (!r) return r.error();
            return message{*r};
        }
        case canopen::function::sdo_rx: return detail::decode_request(f, node, m);
        case canopen::function::sdo_tx: return detail::decode_response(f, node, m);
        default: return errc::wrong_id;
    }
}

// --- encoding ---------------------------------------------------------------------------------

namespace detail {

using canopen::node_id;

constexpr result<can::frame> encode_one(node_id, model, const canopen::nmt_message& v) noexcept {
    return canopen::encode(v);
}
constexpr result<can::frame> encode_one(node_id, model, const canopen::sync_message& v) noexcept {
    return canopen::encode(v);
}
template <class V>
requires std::is_same_v<V, canopen::heartbeat_message> ||
    std::is_same_v<V, canopen::sdo_segment_request> ||
    std::is_same_v<V, canopen::sdo_segment_response>
constexpr result<can::frame> encode_one(node_id n, model, const V& v) noexcept {
    return canopen::encode(n, v);
}
constexpr result<can::frame> encode_one(node_id n, model,
                                        const canopen::sdo_upload_initiate_response& v) noexcept {
    const auto o = find_object(v.address);
    if (!o || info(*o)->type != value_type::string) return errc::unknown_object;
    return canopen::encode(n, v);
}
constexpr result<can::frame> encode_one(node_id n, model, const canopen::sdo_abort& v) noexcept {
    return canopen::encode(n, v, canopen::sdo_direction::response);
}
constexpr result<can::frame> encode_one(node_id n, model, const sdo_abort_request& v) noexcept {
    return canopen::encode(n, v);
}
template <class V>
requires std::is_same_v<V, key_state> || std::is_same_v<V, led_on> || std::is_same_v<V, led_blink>
constexpr result<can::frame> encode_one(node_id n, model m, const V& v) noexcept {
    return encode(n, m, v);
}
constexpr result<can::frame> encode_one(node_id n, model, const read_request& v) noexcept {
    const auto i = info(v.entry);
    if (!i) return errc::unknown_object;
    if (!i->readable) return errc::unknown_command;
    return canopen::encode(n, canopen::sdo_upload_request{i->address});
}
constexpr result<can::frame> encode_one(node_id n, model, const read_response& v) noexcept {
    const auto i = info(v.entry);
    if (!i || i->type != value_type::number) return errc::unknown_object;
    if (!in_range(*i, v.value)) return errc::value_out_of_range;
    return canopen::encode(
        n, canopen::sdo_upload_response{i->address, number_bytes(i->size, v.value)});
}
constexpr result<can::frame> encode_one(node_id n, model, const write_request& v) noexcept {
    const auto i = info(v.entry);
    if (!i || i->type != value_type::number) return errc::unknown_object;
    if (!i->writable) return errc::unknown_command;
    if (!in_range(*i, v.value)) return errc::value_out_of_range;
    return canopen::encode(
        n, canopen::sdo_download_request{i->address, number_bytes(i->size, v.value)});
}
constexpr result<can::frame> encode_one(node_id n, model, const write_response& v) noexcept {
    const auto i = info(v.entry);
    if (!i) return errc::unknown_object;
    if (!i->writable) return errc::unknown_command;
    return canopen::encode(n, canopen::sdo_download_response{i->address});
}
constexpr result<can::frame> encode_one(node_id n, model m, const keys_response& v) noexcept {
    if (!keys_fit(m, v.keys)) return errc::value_out_of_range;
    return canopen::encode(n, canopen::sdo_upload_response{info(object::keys)->address,
                                                           {4, keys_value_bytes(v.keys)}});
}

constexpr result<can::frame> encode_led_value(node_id n, model m, object o, const leds& l,
                                              bool request) noexcept {
    if (!l.fits(m, sdo_led_planes(m))) return errc::value_out_of_range;
    const canopen::expedited_data d{4, led_value_bytes(m, l)};
    const auto a = info(o)->address;
    if (request) return canopen::encode(n, canopen::sdo_download_request{a, d});
    return canopen::encode(n, canopen::sdo_upload_response{a, d});
}
constexpr result<can::frame> encode_one(node_id n, model m, const write_led_on& v) noexcept {
    return encode_led_value(n, m, object::led_on, v.value, true);
}
constexpr result<can::frame> encode_one(node_id n, model m, const write_led_blink& v) noexcept {
    return encode_led_value(n, m, object::led_blink, v.value, true);
}
constexpr result<can::frame> encode_one(node_id n, model m, const led_on_response& v) noexcept {
    return encode_led_value(n, m, object::led_on, v.value, false);
}
constexpr result<can::frame> encode_one(node_id n, model m, const led_blink_response& v) noexcept {
    return encode_led_value(n, m, object::led_blink, v.value, false);
}

// The command module.
template <class V>
requires requires { V::code; }
constexpr result<can::frame> encode_one(node_id n, model m, const V& v) noexcept {
    const auto r = command_request(m, command{v});
    if (!r) return r.error();
    return canopen::encode(n, *r);
}

}  // namespace detail

// The frame of a message for a keypad of model m at `node`. Errors: value_out_of_range (a key,
// LED or value the model or entry does not have, e.g. blue LEDs in 6001h on a PKP-2600),
// unknown_command (an access the entry does not have: a write of a read-only entry, a read of
// 6500h), unknown_object (a message of the wrong shape for its entry, e.g. a number reply for a
// string entry).
[[nodiscard]] constexpr result<can::frame> encode(canopen::node_id node, model m,
                                                  const message& msg) noexcept {
    if (key_count(m) == 0) return errc::value_out_of_range;
    return std::visit([&](const auto& v) { return detail::encode_one(node, m, v); }, msg);
}

}  // namespace powerkey::pkp

#endif  // POWERKEY_PKP_PROFILE_HPP
