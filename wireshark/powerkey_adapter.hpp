// powerkey Wireshark plugin: the one place that calls the library. The rest of the plugin
// (registration, preferences, tree building in plugin.cpp) sees only the plain types below, so
// that a change of the library's API is ported here and nowhere else.
//
// The library calls made here, for whoever ports the adapter to a new API:
//   models      powerkey::model, all_models, to_string(model), parse_model("pk1000"),
//               canopen::node_id::make, canopen::default_node_id
//   catalog     for_each_alternative<powerkey::message> and each alternative's S::fields(s, f)
//               (the kind/fields convention); field types through enum_name, is_index_set
//               (index_set<N>::contains), is_byte_array, is_bounded (bounded::value), integers
//   session     session<text_capacity>(model, node), step(frame) -> session_event: cls
//               (function, node), node, sdo (sdo_pairing::none, to_string), request (index,
//               subindex), upload_done + session::text(), upload_error (errc{}, to_string),
//               new_node, new_protocol (to_string(bus_protocol)); classify, concerns,
//               bus_function::j1939/nmt, canopen::decode_nmt (target), j1939::parse_id (pgn)
//   one frame   can::standard_id::make, can::extended_id::make, can::frame::make(id, bytes),
//               decode(frame, node, model) -> result<message>, to_string(errc), kind_of,
//               for_each_field, describe(msg, node, buf), to_string(bus_function),
//               canopen::decode_sdo_request/decode_sdo_response (alternatives' address.index
//               and address.subindex)
#ifndef POWERKEY_WIRESHARK_ADAPTER_HPP
#define POWERKEY_WIRESHARK_ADAPTER_HPP

#include <powerkey/powerkey.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
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

struct model_choice {
    std::string_view name;  // pk1000, pkp2200 ...: the tool's --model names
    int value;              // the preference's value
};

inline std::vector<model_choice> model_choices() {
    std::vector<model_choice> out;
    for (powerkey::model m : powerkey::all_models)
        out.push_back({powerkey::to_string(m), static_cast<int>(m)});
    return out;
}

inline int default_model() { return static_cast<int>(powerkey::parse_model("pk1000").value()); }

inline std::optional<powerkey::model> model_of(int value) {
    for (powerkey::model m : powerkey::all_models)
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
    bool hex = false;  // shown in hex (an object index)
    // Enumerator names for a number field that always holds one enum type (one or two bytes).
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

template <class E>
std::vector<std::pair<std::uint32_t, std::string>> value_names_of() {
    using U = std::underlying_type_t<E>;
    std::vector<std::pair<std::uint32_t, std::string>> out;
    if constexpr (sizeof(U) <= 2 && std::is_unsigned_v<U>) {
        for (std::uint32_t v = 0; v <= std::numeric_limits<U>::max(); ++v) {
            const auto n = powerkey::enum_name(static_cast<E>(static_cast<U>(v)));
            if (!n.empty()) out.emplace_back(v, std::string(n));
        }
    }
    return out;  // wider enums (SDO abort codes) are shown by name, not listed
}

template <class T>
void note_field(seen_field& s, std::string_view name) {
    if constexpr (std::is_same_v<T, bool>) {
        s.any_bool = true;
    } else if constexpr (std::is_enum_v<T>) {
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
        if (name == "index") s.hex = true;
    } else {
        static_assert(std::is_integral_v<T>, "a field type the plugin does not know");
    }
}

}  // namespace detail

// Every field name of every message of every model, in the order first seen.
inline std::vector<field_spec> message_fields() {
    std::vector<detail::seen_field> seen;
    powerkey::for_each_alternative<powerkey::message>([&seen]<class S>(std::type_identity<S>) {
        S s{};
        S::fields(s, [&seen](std::string_view name, const auto& value) {
            auto it = std::find_if(seen.begin(), seen.end(),
                                   [name](const auto& f) { return f.name == name; });
            if (it == seen.end()) {
                seen.push_back({});
                it = seen.end() - 1;
                it->name = std::string(name);
            }
            detail::note_field<std::decay_t<decltype(value)>>(*it, name);
        });
        return false;
    });
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
    bool upload_done = false;       // a segmented upload ended: text
    std::string_view upload_error;  // a segmented upload failed: the error code
    std::uint8_t new_node = 0;      // the keypad moved to this node id, 0 when it did not
    std::string_view new_protocol;  // "j1939" or "canopen" on a protocol switch
    std::uint16_t text_size = 0;
    std::array<char, text_capacity> text{};
    [[nodiscard]] std::string_view upload_text() const { return {text.data(), text_size}; }
};
static_assert(std::is_trivially_copyable_v<frame_record>);

namespace detail {

inline std::optional<powerkey::can::frame> to_frame(const frame_in& in) {
    using namespace powerkey;
    if (in.extended) {
        const auto id = can::extended_id::make(in.id);
        if (!id) return std::nullopt;
        const auto f = can::frame::make(*id, in.data);
        if (!f) return std::nullopt;
        return *f;
    }
    const auto id = can::standard_id::make(in.id);
    if (!id) return std::nullopt;
    const auto f = can::frame::make(*id, in.data);
    if (!f) return std::nullopt;
    return *f;
}

// The PGN of the keypad's J1939 switch frame (PK1000 section 49): proprietary A, EF00h.
inline constexpr std::uint32_t proprietary_a_pgn = 0xEF00;

inline bool is_keypads(const powerkey::can::frame& f, const powerkey::session_event& e) {
    using namespace powerkey;
    switch (e.cls.function) {
        case bus_function::j1939: {
            const auto id = j1939::parse_id(f);
            return id && id->pgn.value() == proprietary_a_pgn;
        }
        case bus_function::nmt: {
            // NMT to all nodes or to the keypad; a command for another node stays generic.
            const auto m = canopen::decode_nmt(f);
            return !m || m->target.value() == 0 || m->target.value() == e.node.value();
        }
        default: return concerns(e.cls, e.node);
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
        r.claimed = detail::is_keypads(*f, e);
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

inline std::string hex(std::uint64_t v, int digits) {
    static constexpr char d[] = "0123456789ABCDEF";
    std::string s;
    for (int i = digits - 1; i >= 0; --i) s += d[(v >> (4 * i)) & 0xF];
    return s;
}

template <std::size_t N>
std::string set_text(const powerkey::index_set<N>& v) {
    // As describe() writes sets: numbers, three or more in a row as a range, "-" for none.
    std::string s;
    for (unsigned i = 1; i <= N; ++i) {
        if (!v.contains(i)) continue;
        unsigned last = i;
        while (last < N && v.contains(last + 1)) ++last;
        if (!s.empty()) s += ' ';
        s += std::to_string(i);
        if (last >= i + 2) {
            s += '-' + std::to_string(last);
            i = last;
        }
    }
    return s.empty() ? "-" : s;
}

template <class T>
void fill(field_out& out, const field_spec& spec, std::string_view name, const T& v) {
    if constexpr (std::is_same_v<T, bool>) {
        out.flag = v;
        out.number = v ? 1u : 0u;
        out.text = v ? "yes" : "no";
        out.shown = out.text;
    } else if constexpr (std::is_enum_v<T>) {
        using U = std::underlying_type_t<T>;
        out.number = static_cast<std::uint64_t>(static_cast<U>(v));
        const auto n = powerkey::enum_name(v);
        out.text = n.empty() ? hex(out.number, 2 * int{sizeof(U)}) + "h" : std::string(n);
        out.shown = out.text;
        if (spec.type == field_type::number && !n.empty())
            out.shown += " (" + hex(out.number, 2 * int{sizeof(U)}) + "h)";
    } else if constexpr (powerkey::is_index_set<T>::value) {
        out.text = set_text(v);
        out.shown = out.text;
    } else if constexpr (powerkey::is_byte_array<T>::value) {
        out.bytes.assign(v.begin(), v.end());
        for (auto b : v) out.text += (out.text.empty() ? "" : " ") + hex(b, 2);
        out.shown = out.text;
    } else {
        if constexpr (powerkey::is_bounded<T>::value)
            out.number = static_cast<std::uint64_t>(v.value());
        else
            out.number = static_cast<std::uint64_t>(v);
        out.text = name == "index" ? hex(out.number, 4) + "h" : std::to_string(out.number);
        out.shown = out.text;
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
    const auto cls = classify(*f);
    out.function = std::string(to_string(cls.function));
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
            detail::fill(fo, *it, name, v);
            out.fields.push_back(std::move(fo));
        });
    }
    if (const auto n = canopen::node_id::make(cls.node)) {
        if (cls.function == bus_function::sdo_rx)
            detail::sdo_address_of(canopen::decode_sdo_request(*f, *n), out);
        else if (cls.function == bus_function::sdo_tx)
            detail::sdo_address_of(canopen::decode_sdo_response(*f, *n), out);
    }
    if (cls.function == bus_function::j1939)
        if (const auto id = j1939::parse_id(*f)) out.pgn = id->pgn.value();
    return out;
}

}  // namespace powerkey_ws

#endif  // POWERKEY_WIRESHARK_ADAPTER_HPP
