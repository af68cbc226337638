// powerkey PK1000: every frame of the PK1000 CANopen manual (rev 1.13, sections 4 to 49) as one
// typed message, both ways:
//   pk1000::decode(frame, node) -> result<pk1000::message>
//   pk1000::encode(node, message) -> result<can::frame>, and encode(node, decode(f, node)) == f
// `node` is the keypad's current node id: it picks the COB-IDs of the PDOs, SDOs and heartbeat.
// After a write of 2013h (set_request<node_id_value>) the keypad answers from the new node id,
// so a follower decodes the acknowledgement with new_node_id(message).
#ifndef POWERKEY_PK1000_PROFILE_HPP
#define POWERKEY_PK1000_PROFILE_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/canopen/sync.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/j1939/protocol_switch.hpp>
#include <powerkey/pk1000/objects.hpp>
#include <powerkey/pk1000/pdo.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace powerkey::pk1000 {

// Host -> keypad, 600h + node: write the value V (an expedited download, 23h/2Bh/2Fh).
template <class V>
struct set_request {
    static constexpr std::string_view kind = V::set_kind;
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        V::fields(self.value, f);
    }
    V value;
    friend constexpr bool operator==(const set_request&, const set_request&) noexcept = default;
};

// Keypad -> host, 580h + node: the value V read (an expedited upload response, 43h/4Bh/4Fh).
template <class V>
struct value_reply {
    static constexpr std::string_view kind = V::value_kind;
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        V::fields(self.value, f);
    }
    V value;
    friend constexpr bool operator==(const value_reply&, const value_reply&) noexcept = default;
};

// Host -> keypad: read an entry (40h).
struct read_request {
    static constexpr std::string_view kind = "pk1000_read";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("object", self.object);
    }
    entry object = entry::keys;
    friend constexpr bool operator==(const read_request&, const read_request&) noexcept = default;
};

// Keypad -> host: a write was done (60h), the manual's "Command accepted" / "ACK".
struct set_ack {
    static constexpr std::string_view kind = "pk1000_set_ack";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("object", self.object);
    }
    entry object = entry::led_on_red;
    friend constexpr bool operator==(const set_ack&, const set_ack&) noexcept = default;
};

// Host -> keypad abort (80h on 600h + node); canopen::sdo_abort in the message is the keypad's.
using canopen::sdo_abort_request;

template <class... Ts>
struct type_list {};

// The values the manual writes, and the values the keypad replies with.
using set_values = type_list<led_on_value, led_blink_value, brightness_value, colour_value,
                             baud_rate_value, flag_value, node_id_value, startup_show_value,
                             consumer_heartbeat_value, producer_heartbeat_value, restore_defaults,
                             rpdo_transmission_value, tpdo_transmission_value, event_timer_value>;
using reply_values =
    type_list<keys_value, led_on_value, led_blink_value, brightness_value, colour_value,
              baud_rate_value, flag_value, node_id_value, startup_show_value,
              consumer_heartbeat_value, producer_heartbeat_value, device_type_value, string_value,
              restore_capability, subindex_count_value, identity_value, pdo_cob_id_value,
              rpdo_transmission_value, tpdo_transmission_value, event_timer_value,
              pdo_mapping_value>;

namespace detail {
template <class Head, class Sets, class Replies, class Tail>
struct make_message;
template <class... H, class... S, class... R, class... T>
struct make_message<type_list<H...>, type_list<S...>, type_list<R...>, type_list<T...>> {
    using type = std::variant<H..., set_request<S>..., value_reply<R>..., T...>;
};
}  // namespace detail

// Every frame the PK1000 speaks or hears.
using message = typename detail::make_message<
    type_list<canopen::nmt_message, canopen::sync_message, canopen::heartbeat_message,
              j1939::switch_to_canopen, key_state, led_on, led_blink, led_brightness, backlight,
              read_request, set_ack>,
    set_values, reply_values,
    type_list<canopen::sdo_segment_request, canopen::sdo_segment_response,
              canopen::sdo_upload_initiate_response, canopen::sdo_abort, sdo_abort_request>>::type;

// --- encoding -----------------------------------------------------------------------------------

namespace detail {
template <class T>
struct is_set_request : std::false_type {};
template <class V>
struct is_set_request<set_request<V>> : std::true_type {};
template <class T>
struct is_value_reply : std::false_type {};
template <class V>
struct is_value_reply<value_reply<V>> : std::true_type {};

template <class T>
constexpr can::frame encode_one(canopen::node_id node, const T& m) noexcept {
    using namespace canopen;
    if constexpr (is_set_request<T>::value) {
        return canopen::encode(node, sdo_download_request{m.value.address(), m.value.data()});
    } else if constexpr (is_value_reply<T>::value) {
        return canopen::encode(node, sdo_upload_response{m.value.address(), m.value.data()});
    } else if constexpr (std::is_same_v<T, read_request>) {
        return canopen::encode(node, sdo_upload_request{address_of(m.object)});
    } else if constexpr (std::is_same_v<T, set_ack>) {
        return canopen::encode(node, sdo_download_response{address_of(m.object)});
    } else if constexpr (std::is_same_v<T, sdo_abort>) {
        return canopen::encode(node, m, sdo_direction::response);
    } else if constexpr (std::is_same_v<T, sdo_abort_request>) {
        return canopen::encode(node, m.abort, sdo_direction::request);
    } else if constexpr (std::is_same_v<T, nmt_message> || std::is_same_v<T, sync_message> ||
                         std::is_same_v<T, j1939::switch_to_canopen>) {
        return encode(m);
    } else {
        return encode(node, m);  // heartbeat, PDOs, segments, initiate response
    }
}
}  // namespace detail

// --- decoding -----------------------------------------------------------------------------------

namespace detail {
template <class T>
constexpr result<message> lift(const result<T>& r) noexcept {
    if (!r) return r.error();
    return message{*r};
}

// For each entry, the position in the list of the first value type that covers its address
// (0xFF: none). Computed once at compile time, so that decoding an SDO looks the entry up once
// and dispatches on a small integer instead of asking every value type in turn (issue 7).
template <class... Vs>
constexpr std::array<std::uint8_t, entry_count> value_type_index(type_list<Vs...>) noexcept {
    std::array<std::uint8_t, entry_count> t{};
    for (std::size_t e = 0; e < entry_count; ++e) {
        const auto a = entries[e].address;
        std::uint8_t k = 0, found = 0xFF;
        ((found == 0xFF && Vs::covers(a) ? (found = k, ++k) : ++k), ...);
        t[e] = found;
    }
    return t;
}
template <class List>
inline constexpr auto value_type_table = value_type_index(List{});

template <template <class> class Wrap, class V>
constexpr result<message> parse_one(canopen::sdo_address a,
                                    const canopen::expedited_data& d) noexcept {
    const auto v = V::parse(a, d);
    if (!v) return v.error();
    return message{Wrap<V>{*v}};
}

// The value type the entry's table row names parses the data; unknown_object if none does.
template <template <class> class Wrap, class... Vs, std::size_t... I>
constexpr result<message> parse_value(type_list<Vs...> list, std::index_sequence<I...>, entry e,
                                      canopen::sdo_address a,
                                      const canopen::expedited_data& d) noexcept {
    const std::uint8_t k = value_type_table<decltype(list)>[static_cast<std::size_t>(e)];
    result<message> out = errc::unknown_object;
    (void)((k == I ? (out = parse_one<Wrap, Vs>(a, d), true) : false) || ...);
    return out;
}
template <template <class> class Wrap, class... Vs>
constexpr result<message> parse_value(type_list<Vs...> list, entry e, canopen::sdo_address a,
                                      const canopen::expedited_data& d) noexcept {
    return parse_value<Wrap>(list, std::index_sequence_for<Vs...>{}, e, a, d);
}

constexpr bool is_string_entry(entry e) noexcept {
    return e == entry::device_name || e == entry::hardware_version ||
           e == entry::firmware_version || e == entry::model_id || e == entry::serial_string;
}

constexpr result<message> decode_request(const can::frame& f, canopen::node_id node) noexcept {
    const auto r = canopen::decode_sdo_request(f, node);
    if (!r) return r.error();
    if (const auto* w = std::get_if<canopen::sdo_download_request>(&*r)) {
        const auto e = find_entry(w->address);
        if (!e) return e.error();
        if (!info(*e).writable) return errc::unknown_command;
        return parse_value<set_request>(set_values{}, *e, w->address, w->value);
    }
    if (const auto* u = std::get_if<canopen::sdo_upload_request>(&*r)) {
        const auto e = find_entry(u->address);
        if (!e) return e.error();
        return message{read_request{*e}};
    }
    if (const auto* s = std::get_if<canopen::sdo_segment_request>(&*r)) return message{*s};
    return message{sdo_abort_request{std::get<canopen::sdo_abort>(*r)}};
}

constexpr result<message> decode_response(const can::frame& f, canopen::node_id node) noexcept {
    const auto r = canopen::decode_sdo_response(f, node);
    if (!r) return r.error();
    if (const auto* a = std::get_if<canopen::sdo_download_response>(&*r)) {
        const auto e = find_entry(a->address);
        if (!e) return e.error();
        if (!info(*e).writable) return errc::unknown_command;
        return message{set_ack{*e}};
    }
    if (const auto* u = std::get_if<canopen::sdo_upload_response>(&*r)) {
        const auto e = find_entry(u->address);
        if (!e) return e.error();
        return parse_value<value_reply>(reply_values{}, *e, u->address, u->value);
    }
    if (const auto* i = std::get_if<canopen::sdo_upload_initiate_response>(&*r)) {
        const auto e = find_entry(i->address);
        if (!e || !is_string_entry(*e)) return errc::unknown_object;
        return message{*i};
    }
    if (const auto* s = std::get_if<canopen::sdo_segment_response>(&*r)) return message{*s};
    return message{std::get<canopen::sdo_abort>(*r)};
}
}  // namespace detail

// --- encoding: what the decoder would refuse is refused here too --------------------------------

namespace detail {
template <class V, class... Vs>
constexpr std::uint8_t type_index(type_list<Vs...>) noexcept {
    std::uint8_t i = 0, found = 0xFF;
    ((std::is_same_v<V, Vs> && found == 0xFF ? (found = i, ++i) : ++i), ...);
    return found;
}

// errc{} when every enumeration field holds a named value (any 32-bit abort code is valid).
template <class T>
constexpr errc check_enum_fields(const T& m) noexcept {
    errc e{};
    T::fields(m, [&e](std::string_view, const auto& v) {
        using F = std::remove_cvref_t<decltype(v)>;
        if constexpr (std::is_enum_v<F> && !std::is_same_v<F, canopen::sdo_abort_code>)
            if (enum_name(v).empty()) e = errc::value_out_of_range;
    });
    return e;
}

// errc{} when the message encodes to a frame that decode() accepts and reads back unchanged;
// otherwise the error decode() would return for that frame, or value_out_of_range for a value
// the wire cannot carry (an "off" heartbeat with a period, bytes past a string's size).
template <class T>
constexpr errc check_encodable(const T& m) noexcept {
    if (const auto e = check_enum_fields(m); e != errc{}) return e;
    if constexpr (is_set_request<T>::value || is_value_reply<T>::value) {
        using V = std::remove_cvref_t<decltype(m.value)>;
        if constexpr (requires { m.value.canonical(); })
            if (!m.value.canonical()) return errc::value_out_of_range;
        const auto e = find_entry(m.value.address());
        if (!e) return e.error();
        if constexpr (is_set_request<T>::value) {
            if (!info(*e).writable) return errc::unknown_command;
            if (value_type_table<set_values>[static_cast<std::size_t>(*e)] !=
                type_index<V>(set_values{}))
                return errc::unknown_object;
        } else {
            if (value_type_table<reply_values>[static_cast<std::size_t>(*e)] !=
                type_index<V>(reply_values{}))
                return errc::unknown_object;
        }
    } else if constexpr (std::is_same_v<T, set_ack>) {
        if (!info(m.object).writable) return errc::unknown_command;
    } else if constexpr (std::is_same_v<T, canopen::sdo_upload_initiate_response>) {
        const auto e = find_entry(m.address);
        if (!e || !is_string_entry(*e)) return errc::unknown_object;
    }
    return errc{};
}
}  // namespace detail

// The frame of a message for the keypad `node`, such that decode(encode(m)) == m. Every message
// decode() returns encodes; a message built by hand that decode() could never return is refused:
//   value_out_of_range  an enumeration field with no named value; an "off" heartbeat or event
//                       timer with a period, an event-driven PDO with a sync type, a string value
//                       with bytes past its size (the wire cannot carry them)
//   unknown_object      a value for an address the manual does not define for it; a segmented
//                       upload response for an entry that is not a string
//   unknown_command     a write to, or a write acknowledgement of, a read-only entry
[[nodiscard]] constexpr result<can::frame> encode(canopen::node_id node,
                                                  const message& m) noexcept {
    return std::visit(
        [node](const auto& v) -> result<can::frame> {
            if (const auto e = detail::check_encodable(v); e != errc{}) return e;
            return detail::encode_one(node, v);
        },
        m);
}

// Any frame of a PK1000 whose node id is `node`. Errors:
//   wrong_id            another node's COB-ID, a COB-ID the keypad does not use, a 29-bit frame
//                       on a PGN other than EF00h
//   wrong_length        a frame of the wrong dlc (e.g. an SDO of fewer than 8 bytes)
//   unknown_command     an NMT command or SDO specifier the keypads do not use; a write to, or a
//                       write acknowledgement of, an entry the manual documents as read only;
//                       other J1939 proprietary-A data
//   unknown_object      an SDO for an index / sub-index the manual does not define; an upload
//                       response for 1001h (not implemented: the keypad aborts)
//   size_mismatch       an expedited SDO whose size is not the entry's (2Bh for a 1-byte entry)
//   reserved_not_zero   a reserved bit or byte set (LED bits above #28, bytes past the size, ...)
//   value_out_of_range  a value outside the manual's range (brightness > 3Fh, colour, node id,
//                       heartbeat 1..9 ms, event timer above FEFFh, baud code above 07h, ...)
[[nodiscard]] constexpr result<message> decode(const can::frame& f,
                                               canopen::node_id node) noexcept {
    if (f.is_extended()) return detail::lift(j1939::decode_switch_to_canopen(f));
    const auto id = canopen::classify(f);
    switch (id.fn) {
        case canopen::function::nmt: return detail::lift(canopen::decode_nmt(f));
        case canopen::function::sync: return detail::lift(canopen::decode_sync(f));
        case canopen::function::other: return errc::wrong_id;
        default: break;
    }
    if (id.node != node.value()) return errc::wrong_id;
    switch (id.fn) {
        case canopen::function::tpdo1: return detail::lift(decode_key_state(f, node));
        case canopen::function::rpdo1: return detail::lift(decode_led_on(f, node));
        case canopen::function::rpdo2: return detail::lift(decode_led_blink(f, node));
        case canopen::function::rpdo3: return detail::lift(decode_led_brightness(f, node));
        case canopen::function::rpdo4: return detail::lift(decode_backlight(f, node));
        case canopen::function::sdo_rx: return detail::decode_request(f, node);
        case canopen::function::sdo_tx: return detail::decode_response(f, node);
        case canopen::function::heartbeat: return detail::lift(canopen::decode_heartbeat(f, node));
        default: return errc::wrong_id;
    }
}

// The node id a message moves the keypad to (a write of 2013h), if it does.
[[nodiscard]] constexpr std::optional<canopen::node_id> new_node_id(const message& m) noexcept {
    if (!std::holds_alternative<set_request<node_id_value>>(m)) return std::nullopt;
    return std::get<set_request<node_id_value>>(m).value.new_node_id;
}

}  // namespace powerkey::pk1000

#endif  // POWERKEY_PK1000_PROFILE_HPP
