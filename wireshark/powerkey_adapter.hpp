// powerkey Wireshark plugin: the one place that calls the library. The rest of the plugin
// (registration, preferences, tree building in plugin.cpp) sees only the plain types below, so
// that a change of the library's API is ported here and nowhere else.
//
// The library calls made here, for whoever ports the adapter to a new API:
//   models      powerkey::model, enum_values<model>(), to_string(model), parse_model("pk1000"),
//               canopen::node_id::make, canopen::default_node_id
//   catalog     for_each_alternative<powerkey::message> and each alternative's S::fields(s, f)
//               (the kind/fields convention), called again for every value of each named-enum
//               field (the object of an SDO value, the code of a command: the fields that follow
//               depend on it); field types through named_enum, enum_names<E>::entries,
//               enum_values<E>(), is_index_set, is_byte_array, is_bounded, integers; how a value
//               reads through describe_value (and is_decimal_field for which numbers are
//               hex), text_writer
//   session     session<text_capacity>(model, node), step(frame) -> session_event: cls
//               (canopen::cob_info: fn, node), node, sdo (sdo_pairing::none, to_string), request
//               (index, subindex), upload_done + session::text(), upload_error (errc{},
//               to_string), new_node, new_protocol (to_string(bus_protocol)), new_address;
//               canopen::classify, canopen::concerns, canopen::function::j1939/nmt,
//               canopen::decode_nmt (target), j1939::parse_id (pgn), j1939::is_keypad_pgn
//   one frame   can::make_frame(id, bytes, id_format), decode(frame, node, model) ->
//               result<message>, to_string(errc), kind_of, for_each_field, describe(msg, node,
//               buf), to_string(canopen::function), canopen::decode_sdo_request /
//               decode_sdo_response (alternatives' address.index and address.subindex)
#ifndef POWERKEY_WIRESHARK_ADAPTER_HPP
#define POWERKEY_WIRESHARK_ADAPTER_HPP

#include <powerkey/powerkey.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace powerkey_ws {

// The longest string a segmented upload can deliver (device name, revisions, serial number...).
inline constexpr std::size_t text_capacity = 256;

// --- models -------------------------------------------------------------------------------------

// "pk1000, pkp2200, ...": every model of the table, for the preference's text and its errors.
inline std::string model_list() {
    std::string s;
    for (powerkey::model m : powerkey::enum_values<powerkey::model>())
        s.append(s.empty() ? "" : ", ").append(powerkey::to_string(m));
    return s;
}

// A model from a name as the tool's --model takes it: the library's parse_model.
inline std::optional<powerkey::model> model_from_name(std::string_view name) {
    if (const auto m = powerkey::parse_model(name)) return *m;
    return std::nullopt;
}

// Text from the user, shown in a message: printable ASCII as it is, the rest as \xNN, cut at 32.
inline std::string printable(std::string_view s) {
    constexpr char hex[] = "0123456789ABCDEF";
    std::string out;
    for (const char c : s.substr(0, 32)) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u < 0x7F && c != '\\') {
            out += c;
        } else {
            out += "\\x";
            out += hex[u >> 4];
            out += hex[u & 15];
        }
    }
    if (s.size() > 32) out += "...";
    return out;
}

inline int default_model() { return static_cast<int>(powerkey::parse_model("pk1000").value()); }

inline std::optional<powerkey::model> model_of(int value) {
    for (powerkey::model m : powerkey::enum_values<powerkey::model>())
        if (static_cast<int>(m) == value) return m;
    return std::nullopt;
}

inline bool valid_node(unsigned node) { return powerkey::canopen::node_id::make(node).has_value(); }

// --- the field catalog --------------------------------------------------------------------------

// How a message field is registered: one filter field per field name over every message.
enum class field_type : std::uint8_t {
    boolean,  // bool
    number,   // integers, bounded values, and enums when the name always holds the same enum
    text,     // key and LED sets ("1 7", "1-28", "-"), and enums when the name holds several
    bytes,    // raw bytes
};

struct field_spec {
    std::string name;
    field_type type = field_type::number;
    bool hex = false;  // a number the library writes in hex (describe: 15h, 2003h)
    // Enumerator names for a number field that always holds one enum type.
    std::vector<std::pair<std::uint32_t, std::string>> value_names;
};

namespace detail {

// What one field name has been seen holding, while the catalog is collected.
struct seen_field {
    std::string name;
    bool any_bool = false, any_number = false, any_set = false, any_bytes = false;
    bool any_enum = false;
    const void* enum_tag = nullptr;  // one address per enum type
    bool several_enums = false;
    bool hex = false;
    std::vector<std::pair<std::uint32_t, std::string>> value_names;
};

template <class E>
inline const void* enum_tag() {
    static const char tag = 0;
    return &tag;
}

// The names of an enum's values from its table: the first name of each value (later pairs of the
// same value are aliases that from_string accepts).
template <powerkey::named_enum E>
std::vector<std::pair<std::uint32_t, std::string>> value_names_of() {
    std::vector<std::pair<std::uint32_t, std::string>> out;
    for (const E e : powerkey::enum_values<E>())
        out.emplace_back(static_cast<std::uint32_t>(e), std::string(powerkey::to_string(e)));
    return out;
}

// Whether the library writes numbers of this field name in hex ("15h") or in decimal (counts
// and times): describe's own rule.
inline bool hex_number(std::string_view name) { return !powerkey::is_decimal_field(name); }

template <class T>
void note_field(seen_field& s, std::string_view name) {
    if constexpr (std::is_same_v<T, bool>) {
        s.any_bool = true;
    } else if constexpr (std::is_enum_v<T>) {
        static_assert(powerkey::named_enum<T>, "an enum field without a name table");
        if (s.any_enum && s.enum_tag != enum_tag<T>()) s.several_enums = true;
        if (!s.any_enum) s.value_names = value_names_of<T>();
        s.any_enum = true;
        s.enum_tag = enum_tag<T>();
    } else if constexpr (powerkey::is_index_set<T>::value) {
        s.any_set = true;
    } else if constexpr (powerkey::is_byte_array<T>::value) {
        s.any_bytes = true;
    } else if constexpr (powerkey::is_bounded<T>::value || std::is_integral_v<T>) {
        s.any_number = true;
        s.hex = hex_number(name);
    } else {
        static_assert(std::is_integral_v<T>, "a field type the plugin does not know");
    }
}

// Sets the field `name` of s, when it holds an E, through the fields convention.
template <class S, class E>
void set_field(S& s, std::string_view name, E value) {
    S::fields(s, [name, value](std::string_view n, auto& v) {
        if constexpr (std::is_same_v<std::decay_t<decltype(v)>, E>)
            if (n == name) v = value;
    });
}

}  // namespace detail

// Every field name of every message of every model, in the order first seen. Which fields an
// SDO value or a command carries depends on a named enum of the message (its object, its command
// code): each message is asked again with every value of each of its enum fields.
inline std::vector<field_spec> message_fields() {
    std::vector<detail::seen_field> seen;
    auto note = [&seen](std::string_view name, const auto& value) {
        auto it = std::find_if(seen.begin(), seen.end(),
                               [name](const auto& f) { return f.name == name; });
        if (it == seen.end()) {
            seen.push_back({});
            it = seen.end() - 1;
            it->name = std::string(name);
        }
        detail::note_field<std::decay_t<decltype(value)>>(*it, name);
    };
    powerkey::for_each_alternative<powerkey::message>([&note]<class S>(std::type_identity<S>) {
        const S s{};
        S::fields(s, note);
        // The enum fields of the default message, then the message with each of their values.
        std::vector<std::function<void()>> variations;
        S::fields(s, [&variations, &note](std::string_view name, const auto& value) {
            using T = std::decay_t<decltype(value)>;
            if constexpr (powerkey::named_enum<T>) {
                variations.emplace_back([name, &note] {
                    for (const T v : powerkey::enum_values<T>()) {
                        S t{};
                        detail::set_field(t, name, v);
                        S::fields(std::as_const(t), note);
                    }
                });
            }
        });
        for (const auto& vary : variations) vary();
        return false;
    });
    // powerkey.form: a frame not in the manual's form (docs/decoder.md), one field for every kind.
    note("form", powerkey::frame_form::manual);
    std::vector<field_spec> out;
    for (auto& s : seen) {
        field_spec f;
        f.name = s.name;
        f.hex = s.hex;
        const int kinds = int{s.any_bool} + int{s.any_number} + int{s.any_set} + int{s.any_bytes} +
                          int{s.any_enum};
        if (kinds > 1 || s.several_enums || s.any_set)
            f.type = field_type::text;
        else if (s.any_bool)
            f.type = field_type::boolean;
        else if (s.any_bytes)
            f.type = field_type::bytes;
        else
            f.type = field_type::number;
        if (f.type == field_type::number && s.any_enum) f.value_names = std::move(s.value_names);
        out.push_back(std::move(f));
    }
    return out;
}

// --- following the capture ---------------------------------------------------------------------

// A CAN frame as Wireshark hands it over.
struct frame_in {
    std::uint32_t id = 0;  // without flags
    bool extended = false;
    std::span<const std::uint8_t> data;
};

// What the first pass learned about one frame, kept with the packet (trivially copyable: it
// lives in Wireshark's file-scoped memory). Strings point at the library's static names.
struct frame_record {
    bool claimed = false;           // a frame of the keypad: the plugin dissects it
    int model = 0;                  // the model the session followed (the preference's value)
    std::uint8_t node = 0;          // the node id the frame was decoded for
    std::string_view sdo;           // "request", "reply", "unanswered", or empty
    std::uint16_t reply_index = 0;  // the request a reply answers (sdo == "reply")
    std::uint8_t reply_subindex = 0;
    bool upload_done = false;       // a string upload ended: text
    std::string_view upload_error;  // a segmented upload failed: the error code
    std::uint8_t new_node = 0;      // the keypad moved to this node id, 0 when it did not
    std::string_view new_protocol;  // "j1939" or "canopen" on a protocol switch
    bool address_moved = false;     // the keypad's J1939 address is now new_address
    std::uint8_t new_address = 0;
    std::uint16_t text_size = 0;
    std::array<char, text_capacity> text{};
    [[nodiscard]] std::string_view upload_text() const { return {text.data(), text_size}; }
};
static_assert(std::is_trivially_copyable_v<frame_record>);

namespace detail {

inline std::optional<powerkey::can::frame> to_frame(const frame_in& in) {
    using namespace powerkey;
    const auto f = can::make_frame(
        in.id, in.data, in.extended ? can::id_format::extended : can::id_format::standard);
    if (!f) return std::nullopt;
    return *f;
}

inline bool is_keypads(const powerkey::can::frame& f, const powerkey::session_event& e,
                       powerkey::model m) {
    using namespace powerkey;
    switch (e.cls.fn) {
        case canopen::function::j1939: {
            // A keypad's J1939 frame (keypad/j1939_codec.hpp), at any address: one that decodes,
            // or one on a keypad PGN that the model refuses for its content. Other PGNs, and
            // proprietary-A data without the keypads' 04 1B header (another vendor's), stay
            // with Wireshark's own J1939 dissector.
            (void)m;
            const auto id = j1939::parse_id(f);
            if (!id || !j1939::is_keypad_pgn(id->pgn)) return false;
            return e.decoded || (e.decoded.error() != errc::wrong_id &&
                                 e.decoded.error() != errc::unknown_command);
        }
        case canopen::function::nmt: {
            // NMT to all nodes or to the keypad; a command for another node stays generic.
            const auto msg = canopen::decode_nmt(f);
            return !msg || msg->target.value() == 0 || msg->target.value() == e.node.value();
        }
        default: return canopen::concerns(e.cls, e.node);
    }
}

}  // namespace detail

// Runs the library's session over the capture in order (Wireshark's first pass).
class follower {
public:
    follower(int model_value, unsigned node)
        : session_(
              model_of(model_value).value_or(powerkey::model::pk1000),
              powerkey::canopen::node_id::make(node).value_or(powerkey::canopen::default_node_id)) {
    }

    frame_record step(const frame_in& in) {
        frame_record r;
        const auto f = detail::to_frame(in);
        if (!f) return r;
        const auto e = session_.step(*f);
        r.claimed = detail::is_keypads(*f, e, session_.model());
        r.model = static_cast<int>(session_.model());
        r.node = e.node.value();
        if (e.sdo != powerkey::sdo_pairing::none) r.sdo = powerkey::to_string(e.sdo);
        r.reply_index = e.request.index;
        r.reply_subindex = e.request.subindex;
        if (e.upload_done) {
            r.upload_done = true;
            const auto t = session_.text();
            r.text_size = static_cast<std::uint16_t>(std::min(t.size(), r.text.size()));
            std::copy_n(t.begin(), r.text_size, r.text.begin());
        }
        if (e.upload_error != powerkey::errc{})
            r.upload_error = powerkey::to_string(e.upload_error);
        if (e.new_node) r.new_node = e.new_node->value();
        if (e.new_protocol) r.new_protocol = powerkey::to_string(*e.new_protocol);
        if (e.new_address) {
            r.address_moved = true;
            r.new_address = *e.new_address;
        }
        return r;
    }

private:
    powerkey::session<text_capacity> session_;
};

// --- one frame, ready to show ------------------------------------------------------------------

struct field_out {
    std::size_t spec = 0;             // index into message_fields()
    std::uint64_t number = 0;         // number fields
    bool flag = false;                // boolean fields
    std::string text;                 // text fields
    std::vector<std::uint8_t> bytes;  // bytes fields
    std::string shown;                // the value as the tool's text output writes it
};

struct frame_view {
    bool decoded = false;
    std::string kind;       // the stable kind name (decode --json "kind")
    std::string error;      // the error code of a refused frame
    std::string function;   // nmt, sync, tpdo1 ... (decode --json "function")
    std::uint8_t node = 0;  // decode --json "node"
    std::string summary;    // the tool's text: "node 15h  LED on  red: 1 7 ..."
    std::vector<field_out> fields;
    std::optional<std::uint16_t> sdo_index;  // an SDO frame that carries index and sub-index
    std::optional<std::uint8_t> sdo_subindex;
    std::optional<std::uint32_t> pgn;  // a J1939 frame
};

namespace detail {

// A value as describe() writes it after "name: ".
template <class T>
std::string described(std::string_view name, const T& v) {
    std::array<char, 128> buf{};
    powerkey::text_writer w(buf);
    powerkey::describe_value(w, name, v);
    return std::string(w.view());
}

template <class T>
void fill(field_out& out, std::string_view name, const T& v) {
    out.shown = described(name, v);
    out.text = out.shown;
    if constexpr (std::is_same_v<T, bool>) {
        out.flag = v;
        out.number = v ? 1u : 0u;
    } else if constexpr (std::is_enum_v<T>) {
        // Shown by name only: the number of an enumerator (an object, a command) is the library's
        // own, not a wire value; filters take the name (the field's value names) or the number.
        out.number = static_cast<std::uint64_t>(static_cast<std::underlying_type_t<T>>(v));
    } else if constexpr (powerkey::is_byte_array<T>::value) {
        out.bytes.assign(v.begin(), v.end());
    } else if constexpr (powerkey::is_bounded<T>::value) {
        out.number = static_cast<std::uint64_t>(v.value());
    } else if constexpr (std::is_integral_v<T>) {
        out.number = static_cast<std::uint64_t>(v);
    }
}

// The index and sub-index an SDO frame carries (not a segment).
template <class R>
void sdo_address_of(const R& r, frame_view& out) {
    if (!r) return;
    std::visit(
        [&out](const auto& v) {
            if constexpr (requires { v.address.index; }) {
                out.sdo_index = v.address.index;
                out.sdo_subindex = v.address.subindex;
            }
        },
        *r);
}

}  // namespace detail

// The frame as the first pass left it, decoded again (Wireshark re-dissects in any order).
inline frame_view view(const frame_in& in, const frame_record& r,
                       const std::vector<field_spec>& catalog) {
    using namespace powerkey;
    frame_view out;
    const auto f = detail::to_frame(in);
    const auto node = canopen::node_id::make(r.node);
    if (!f || !node) {
        out.error = to_string(errc::wrong_length);
        return out;
    }
    const auto cls = canopen::classify(*f);
    out.function = std::string(to_string(cls.fn));
    out.node = cls.node != 0 ? cls.node : r.node;
    const auto m = model_of(r.model).value_or(model::pk1000);
    const auto msg = decode(*f, *node, m);
    if (!msg) {
        out.error = std::string(to_string(msg.error()));
    } else {
        out.decoded = true;
        out.kind = std::string(kind_of(*msg));
        std::array<char, 512> buf{};
        const auto shown_node = canopen::node_id::make(out.node).value_or(*node);
        const auto d = describe(*msg, shown_node, buf);
        out.summary = d ? std::string(*d) : std::string(buf.data(), buf.size());
        for_each_field(*msg, [&](std::string_view name, const auto& v) {
            const auto it = std::find_if(catalog.begin(), catalog.end(),
                                         [name](const field_spec& s) { return s.name == name; });
            if (it == catalog.end()) return;
            field_out fo;
            fo.spec = static_cast<std::size_t>(it - catalog.begin());
            detail::fill(fo, name, v);
            out.fields.push_back(std::move(fo));
        });
        if (const auto form = form_of(*msg); form != frame_form::manual) {
            const auto it = std::find_if(catalog.begin(), catalog.end(),
                                         [](const field_spec& s) { return s.name == "form"; });
            if (it != catalog.end()) {
                field_out fo;
                fo.spec = static_cast<std::size_t>(it - catalog.begin());
                detail::fill(fo, "form", form);
                out.fields.push_back(std::move(fo));
            }
        }
    }
    if (const auto n = canopen::node_id::make(cls.node)) {
        if (cls.fn == canopen::function::sdo_rx)
            detail::sdo_address_of(canopen::decode_sdo_request(*f, *n), out);
        else if (cls.fn == canopen::function::sdo_tx)
            detail::sdo_address_of(canopen::decode_sdo_response(*f, *n), out);
    }
    if (cls.fn == canopen::function::j1939)
        if (const auto id = j1939::parse_id(*f)) out.pgn = id->pgn.value();
    return out;
}

}  // namespace powerkey_ws

#endif  // POWERKEY_WIRESHARK_ADAPTER_HPP
