// powerkey._powerkey: the library for Python (docs/python.md). The package powerkey/ wraps it;
// this module only speaks in plain Python values (ints, strs, lists, bytes) and the few types of
// powerkey/_types.py, so that the vocabulary is the library's and the tool's JSON:
//   - a message's fields come from the kind/fields convention (fields.hpp), written with the
//     same rules as the tool's `decode --json` (tools/powerkey/field_value.hpp, write_json_value):
//     bool, enum name (a number when unnamed), [keys], "HEX" bytes, numbers;
//   - a message is built from a kind and fields as `powerkey encode` builds one, field by field
//     through the same visitor; a kind is written led_on or led-on, a value as a Python value or
//     as the tool's text ("3Ah", "1,7", "1-28", "yes"), read by the tool's own functions
//     (tools/powerkey/field_text.hpp, numbers.hpp);
//   - a refusal raises powerkey.DecodeError / EncodeError whose `code` is the errc's name, and
//     whose text is the tool's: the kind, the field and the range (led_on: red: [5] is more than
//     a pkp2200 takes (1..4); tools/powerkey/refusal.hpp finds the field);
//   - remote, CAN FD and error frames carry no keypad message, as for the tool.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "field_text.hpp"  // tools/powerkey: the tool's text values and numbers
#include "refusal.hpp"

#include <powerkey/behaviour/controller.hpp>
#include <powerkey/behaviour/virtual_keypad.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/keypad/accessors.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/names.hpp>
#include <powerkey/session.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace py = pybind11;
namespace pb = powerkey::behaviour;
using namespace powerkey;

namespace {

// --- the Python side's types (powerkey/_types.py), looked up once at import -------------------

struct python_types {
    py::object error, decode_error, encode_error, argument_error;
    py::object led_map_update, backlight_update, to_frame;
};
python_types& types() {
    // Leaked on purpose: Python objects must not be released after the interpreter is gone.
    static auto* t = new python_types;
    return *t;
}

[[noreturn]] void raise(const py::object& cls, const std::string& text, py::object code) {
    const py::object e = cls(text, code);
    PyErr_SetObject(cls.ptr(), e.ptr());
    throw py::error_already_set();
}
[[noreturn]] void raise_code(const py::object& cls, const std::string& what, errc e) {
    const std::string name(to_string(e));
    raise(cls, what.empty() ? name : what + ": " + name, py::str(name));
}
[[noreturn]] void argument_error(const std::string& text) {
    raise(types().argument_error, text, py::none());
}

std::string py_repr(py::handle o) { return py::repr(o).cast<std::string>(); }

// --- plain ints, whatever their size ---------------------------------------------------------
// Python ints have no size: they are compared as Python ints before any conversion, so that 2**64
// is a ValueError naming the range, not pybind11's "Unable to cast".

bool is_int(py::handle o) { return py::isinstance<py::int_>(o) && !py::isinstance<py::bool_>(o); }

void expect_int(py::handle o, const std::string& what, const char* expected = "an int") {
    if (!is_int(o)) throw py::type_error(what + ": expected " + expected + ", not " + py_repr(o));
}

bool int_within(py::handle o, std::uint64_t lo, std::uint64_t hi) {
    return !(o < py::int_(lo)) && !(o > py::int_(hi));
}

// An int lo..hi: TypeError for no int, ArgumentError (a ValueError) naming the range.
std::uint64_t int_arg(py::handle o, const std::string& what, std::uint64_t lo, std::uint64_t hi,
                      const std::string& why = "") {
    expect_int(o, what);
    if (!int_within(o, lo, hi))
        raise(types().argument_error,
              what + ": " + py_repr(o) + " is outside " + std::to_string(lo) + ".." +
                  std::to_string(hi) + why,
              py::str("value_out_of_range"));
    return o.cast<std::uint64_t>();
}

// A duration in ms: the library's clock compares times less than 2^31 ms apart.
pb::duration_ms duration_arg(py::handle o, const std::string& what) {
    return pb::duration_ms{static_cast<std::uint32_t>(int_arg(
        o, what, 0, 0x7FFF'FFFF, " ms (the clock compares times less than 2^31 ms apart)"))};
}

// A time in ms on the library's wrapping 32-bit counter: any int, taken modulo 2^32.
pb::millis millis_arg(py::handle o, const std::string& what = "t") {
    expect_int(o, what);
    const py::object low = py::reinterpret_borrow<py::object>(o) & py::int_(0xFFFF'FFFFu);
    return pb::millis{low.cast<std::uint32_t>()};
}

// True or False (or 0 or 1): the flags of a frame.
bool flag_arg(py::handle o, const std::string& what) {
    if (py::isinstance<py::bool_>(o)) return o.cast<bool>();
    if (is_int(o) && int_within(o, 0, 1)) return o.cast<std::uint64_t>() == 1;
    throw py::type_error(what + ": expected True or False, not " + py_repr(o));
}

// --- names ----------------------------------------------------------------------------------

template <named_enum E>
py::object enum_to_py(E e) {
    if (is_named(e)) return py::str(std::string(to_string(e)));
    return py::int_(static_cast<std::uint64_t>(e));
}

template <named_enum E>
std::string enum_names_text() {
    std::string names;
    for (const E v : enum_values<E>()) names.append(names.empty() ? "" : ", ").append(to_string(v));
    return names;
}

// A value of E from its name (aliases too) or its number; `named_only`: a number must be one of
// the named values (a colour, a mode), not any value of the enum's type (an abort code).
template <named_enum E>
E enum_from_py(py::handle o, const char* what, bool named_only = false) {
    if (py::isinstance<py::str>(o)) {
        const auto s = o.cast<std::string>();
        if (const auto v = from_string<E>(s)) return *v;
        argument_error(std::string(what) + ": unknown name '" + s + "' (" + enum_names_text<E>() +
                       ")");
    }
    if (is_int(o)) {
        using U = std::underlying_type_t<E>;
        if (!int_within(o, 0, std::numeric_limits<U>::max()))
            argument_error(std::string(what) + ": " + py_repr(o) + " is outside 0.." +
                           std::to_string(std::numeric_limits<U>::max()) +
                           (named_only ? " (" + enum_names_text<E>() + ")" : std::string()));
        const auto v = static_cast<E>(static_cast<U>(o.cast<std::uint64_t>()));
        if (named_only && !is_named(v))
            argument_error(std::string(what) + ": " + py_repr(o) + " names none of " +
                           enum_names_text<E>());
        return v;
    }
    // A bound enum (powerkey.Model): its int value.
    if (py::hasattr(o, "value") && is_int(o.attr("value")))
        return enum_from_py<E>(o.attr("value"), what, named_only);
    throw py::type_error(std::string(what) + ": expected a name or a number, not " + py_repr(o));
}

model model_from_py(py::handle o) {
    if (py::isinstance<model>(o)) return o.cast<model>();
    if (py::isinstance<py::str>(o)) {
        const auto s = o.cast<std::string>();
        if (const auto m = parse_model(s)) return *m;
        std::string names;
        for (const model m : enum_values<model>())
            names.append(names.empty() ? "" : ", ").append(to_string(m));
        raise(types().argument_error, "model: unknown model '" + s + "' (" + names + ")",
              py::str("value_out_of_range"));
    }
    throw py::type_error("model: expected a name like 'pkp2400' or powerkey.Model, not " +
                         py_repr(o));
}

// A keypad's J1939 address, 01h..FDh as 70h takes it (pb::j1939_source_address): a number, or
// the tool's text of --address as node takes --node's ("21h", "0x21", "33").
std::uint8_t address_arg(py::handle o, const char* what) {
    using range = pb::j1939_source_address;
    if (py::isinstance<py::str>(o)) {
        std::uint64_t v = 0;
        if (!tool::parse_number(o.cast<std::string>(), v) || !range::make(v))
            raise(types().argument_error,
                  std::string(what) + ": expected a J1939 keypad address 01h..FDh (0x21, 21h or " +
                      "33), got " + py_repr(o),
                  py::str("value_out_of_range"));
        return static_cast<std::uint8_t>(v);
    }
    return static_cast<std::uint8_t>(int_arg(o, what, range::min, range::max));
}

// A J1939 keypad address (01h..FDh, 70h's range: 00h is the controllers'), or None for any: the
// J1939 frames narrowed to that keypad.
j1939::keypad_address address_from_py(py::handle o) {
    if (o.is_none()) return std::nullopt;
    return address_arg(o, "address");
}

canopen::node_id node_from_py(py::handle o, const char* what = "node") {
    long long n = 0;
    if (py::isinstance<py::str>(o)) {  // as the tool's --node: "15h", "0x15", "21"
        std::uint64_t v = 0;
        if (!tool::parse_number(o.cast<std::string>(), v))
            argument_error(std::string(what) + ": expected a node id 1..127 (0x15, 15h or 21), " +
                           "got " + py_repr(o));
        n = v > 0xFFFF ? 0xFFFF : static_cast<long long>(v);
    } else if (!is_int(o)) {
        throw py::type_error(std::string(what) +
                             ": expected an int 1..127 or a str like '15h', "
                             "not " +
                             py_repr(o));
    } else {
        n = int_within(o, 0, 255) ? static_cast<long long>(o.cast<std::uint64_t>()) : 0;
    }
    const auto id = canopen::node_id::make(n < 0 || n > 255 ? 0u : static_cast<unsigned>(n));
    if (!id)
        raise(types().argument_error, std::string(what) + ": " + py_repr(o) + " is outside 1..127",
              py::str("value_out_of_range"));
    return *id;
}

// --- field values, both ways ----------------------------------------------------------------

const char upper_hex[] = "0123456789ABCDEF";

template <std::size_t N>
py::list index_list(const index_set<N>& s) {
    py::list l;
    for (unsigned i = 1; i <= N; ++i)
        if (s.contains(i)) l.append(i);
    return l;
}

// The value as the tool's JSON writes it (tools/powerkey/field_value.hpp, write_json_value).
template <class T>
py::object to_py(const T& v) {
    if constexpr (std::is_same_v<T, bool>) {
        return py::bool_(v);
    } else if constexpr (std::is_enum_v<T>) {
        return enum_to_py(v);
    } else if constexpr (is_index_set<T>::value) {
        return index_list(v);
    } else if constexpr (is_byte_array<T>::value) {
        std::string hex;
        for (const auto b : v) {
            hex += upper_hex[b >> 4];
            hex += upper_hex[b & 15];
        }
        return py::str(hex);
    } else if constexpr (is_bounded<T>::value) {
        return py::int_(static_cast<std::uint64_t>(v.value()));
    } else {
        static_assert(std::is_integral_v<T>, "a field type outside the kind/fields convention");
        return py::int_(static_cast<std::uint64_t>(v));
    }
}

[[noreturn]] void field_out_of_range(std::string_view field, const std::string& text) {
    raise(types().encode_error, std::string(field) + ": " + text, py::str("value_out_of_range"));
}

std::uint64_t unsigned_from_py(py::handle o, std::string_view field, std::uint64_t max) {
    expect_int(o, std::string(field));
    if (!int_within(o, 0, max))
        field_out_of_range(field, py_repr(o) + " is outside 0.." + std::to_string(max));
    return o.cast<std::uint64_t>();
}

// A field value from the tool's text ("3Ah", "1,7", "1-28", "yes", a name): the tool's own
// reader and its words; a value outside the range is an EncodeError, text that is no value an
// ArgumentError.
template <class T>
void from_text(T& v, const std::string& text, std::string_view field) {
    const auto e = tool::set_from_text(v, text, field);
    if (e.empty()) return;
    if (e.find(" is outside ") != std::string::npos) field_out_of_range(field, e);
    argument_error(std::string(field) + ": " + e);
}

// Sets v from a Python value: what to_py gives back, the tool's text for any field, and the
// obvious others (bytes for a byte array, any iterable of key numbers for a set, an enum's
// number).
template <class T>
void from_py(T& v, py::handle o, std::string_view field) {
    if (py::isinstance<py::str>(o)) return from_text(v, o.cast<std::string>(), field);
    if constexpr (std::is_same_v<T, bool>) {
        if (py::isinstance<py::bool_>(o)) {
            v = o.cast<bool>();
        } else {
            v = unsigned_from_py(o, field, 1) == 1;
        }
    } else if constexpr (std::is_enum_v<T>) {
        v = enum_from_py<T>(o, std::string(field).c_str());
    } else if constexpr (is_index_set<T>::value) {
        if (!py::isinstance<py::iterable>(o))
            throw py::type_error(std::string(field) +
                                 ": expected numbers like [1, 7] or '1,7', "
                                 "not " +
                                 py_repr(o));
        T s{};
        for (const auto item : o) {
            if (!is_int(item))
                throw py::type_error(std::string(field) + ": expected numbers like [1, 7], not " +
                                     py_repr(o));
            if (!int_within(item, 1, T::max))
                field_out_of_range(field,
                                   py_repr(item) + " is outside 1.." + std::to_string(T::max));
            s.insert(item.cast<unsigned>());
        }
        v = s;
    } else if constexpr (is_byte_array<T>::value) {
        if (!py::isinstance<py::bytes>(o) && !py::isinstance<py::bytearray>(o))
            throw py::type_error(std::string(field) + ": expected bytes or a hex string, not " +
                                 py_repr(o));
        const auto bytes =
            py::bytes(py::module_::import("builtins").attr("bytes")(o)).cast<std::string>();
        if (bytes.size() > v.size())
            field_out_of_range(field, "more than " + std::to_string(v.size()) + " bytes");
        T out{};
        for (std::size_t i = 0; i < bytes.size(); ++i) out[i] = static_cast<std::uint8_t>(bytes[i]);
        v = out;
    } else {
        // bounded and plain integers: the tool's range text ("99 is outside 00h..3Fh")
        if (!is_int(o))
            throw py::type_error(std::string(field) +
                                 ": expected an int or a str like '3Ah', "
                                 "not " +
                                 py_repr(o));
        if (!int_within(o, 0, std::numeric_limits<std::uint64_t>::max()))
            field_out_of_range(field, py_repr(o) + " is outside " + tool::range_of<T>(field));
        const auto e = tool::set_from_number(v, o.cast<std::uint64_t>(), field);
        if (!e.empty()) field_out_of_range(field, e);
    }
}

// --- messages -------------------------------------------------------------------------------

// A message with the model and node it was decoded for (or built for), which the LED-map
// accessors need.
struct py_message {
    message m;
    std::optional<model> md;
    std::optional<std::uint8_t> node;
};

py::dict fields_of(const message& m) {
    py::dict d;
    for_each_field(m, [&d](std::string_view name, const auto& v) {
        d[py::str(std::string(name))] = to_py(v);
    });
    return d;
}

std::string kind_names() {
    std::string s;
    for_each_alternative<message>([&]<class S>(std::type_identity<S>) {
        s.append(s.empty() ? "" : ", ").append(S::kind);
        return false;
    });
    return s;
}

// The message of `kind` with `fields` (the others keep their defaults; an NMT command's target
// defaults to `node`, as the tool's). Unknown kinds and field names raise ArgumentError.
// Sets the NMT target of s to `node`, the default of the tool's encode.
template <class S>
void target_default(S& s, std::optional<canopen::node_id> node) {
    if (!node) return;
    S::fields(s, [&](std::string_view name, auto& value) {
        if (name == "target") (void)tool::set_from_number(value, node->value(), name);
    });
}

// Runs f; an Error it raises gets `kind: ` in front of its text, as the tool's errors have.
template <class F>
void in_kind(std::string_view kind, F&& f) {
    try {
        f();
    } catch (py::error_already_set& e) {
        for (const py::object* cls :
             {&types().encode_error, &types().argument_error, &types().decode_error})
            if (e.matches(*cls)) {
                const std::string text = py::str(e.value()).cast<std::string>();
                const py::object code = e.value().attr("code");
                raise(*cls, std::string(kind) + ": " + text, code);
            }
        throw;
    }
}

message build_message(const std::string& kind_text, const py::dict& fields,
                      std::optional<canopen::node_id> node) {
    const std::string kind = tool::kind_name(kind_text);  // led-on, pkp_led_on: led_on
    message out;
    std::vector<std::string> used;
    const bool found = for_each_alternative<message>([&]<class S>(std::type_identity<S>) {
        if (S::kind != kind) return false;
        S s{};
        target_default(s, node);
        in_kind(kind, [&] {
            S::fields(s, [&](std::string_view name, auto& value) {
                const py::str key{std::string(name)};
                if (fields.contains(key)) {
                    from_py(value, fields[key], name);
                    used.emplace_back(name);
                }
            });
        });
        out = s;
        return true;
    });
    if (!found) argument_error("unknown kind '" + kind_text + "' (" + kind_names() + ")");
    for (const auto& [k, v] : fields) {
        const auto name = py::str(k).cast<std::string>();
        bool known = false;
        for (const auto& u : used) known = known || u == name;
        if (!known) {
            std::string names;
            for_each_field(out, [&names](std::string_view n, const auto&) {
                names.append(names.empty() ? "" : ", ").append(n);
            });
            argument_error(kind + ": unknown field '" + name + "' (" +
                           (names.empty() ? "none" : names) + ")");
        }
    }
    return out;
}

// encode() refused m: the tool's words for why (refusal.hpp), the errc as the code; `address` as
// encode was given it.
[[noreturn]] void refused(const message& m, model md, canopen::node_id node,
                          j1939::keypad_address address, errc e) {
    const std::string kind(kind_of(m));
    const std::string name(to_string(md));
    if (const auto narrow = tool::narrowing_needed(m, md, node, address, true); !narrow.empty())
        raise(types().encode_error, kind + ": " + narrow, py::str(std::string(to_string(e))));
    const auto why = tool::explain_refusal(
        m, md, node, [&](auto& s) { target_default(s, node); }, address);
    std::string text;
    if (why.kind == tool::refusal::what::not_for_model) {
        text = kind + " is not a message of a " + name;
    } else if (why.kind == tool::refusal::what::field) {
        py::object value = py::none();
        for_each_field(m, [&](std::string_view n, const auto& v) {
            if (n == why.field) value = to_py(v);
        });
        text = kind + ": " + std::string(why.field) + ": " +
               tool::refusal_text(why, py_repr(value), name);
    } else {
        raise_code(types().encode_error, "encode " + kind + " for " + name, e);
    }
    raise(types().encode_error, text, py::str(std::string(to_string(e))));
}

// --- frames ---------------------------------------------------------------------------------

// A frame's identifier: an int 0..1FFFFFFFh (a DecodeError past that: no frame has it).
std::uint64_t frame_id_arg(py::handle o, const std::string& what) {
    expect_int(o, what);
    if (!int_within(o, 0, 0x1FFF'FFFF))
        raise(types().decode_error,
              "frame: " + what + ": " + py_repr(o) + " is outside 0..0x1FFFFFFF (11 or 29 bits)",
              py::str("value_out_of_range"));
    return o.cast<std::uint64_t>();
}

// A frame from a can.Message (or anything with arbitration_id, data, is_extended_id), or from an
// (id, data[, extended]) tuple. Remote and error frames carry no keypad message.
can::frame frame_from_py(py::handle o) {
    std::uint64_t id = 0;
    py::object data;
    std::optional<bool> ext;
    if (py::hasattr(o, "arbitration_id")) {
        // As the tool: remote, CAN FD and error frames are log content it does not decode.
        for (const auto& [flag, what] :
             {std::pair{"is_remote_frame", "a remote frame"},
              std::pair{"is_error_frame", "an error frame"}, std::pair{"is_fd", "a CAN FD frame"}})
            if (py::hasattr(o, flag) && flag_arg(o.attr(flag), flag))
                raise(types().decode_error,
                      std::string(what) +
                          " carries no keypad message (powerkey decodes classic "
                          "CAN data frames)",
                      py::str("unexpected_frame"));
        id = frame_id_arg(o.attr("arbitration_id"), "arbitration_id");
        data = o.attr("data");
        if (py::hasattr(o, "is_extended_id"))
            ext = flag_arg(o.attr("is_extended_id"), "is_extended_id");
    } else if (py::isinstance<py::tuple>(o) && (py::len(o) == 2 || py::len(o) == 3)) {
        const auto t = py::reinterpret_borrow<py::tuple>(o);
        id = frame_id_arg(t[0], "id");
        data = t[1];
        if (py::len(t) == 3) ext = flag_arg(t[2], "extended");
    } else {
        throw py::type_error("expected a can.Message or (id, data), not " + py_repr(o));
    }
    // bytes(5) would be five zero bytes, bytes("ab") needs an encoding: neither is frame data.
    if (is_int(data) || py::isinstance<py::str>(data) || py::isinstance<py::bool_>(data))
        throw py::type_error("data: expected bytes (or a list of byte values), not " +
                             py_repr(data));
    const auto bytes = py::module_::import("builtins")
                           .attr("bytes")(data.is_none() ? py::bytes() : data)
                           .cast<std::string>();
    const bool extended = ext.value_or(id > 0x7FF);
    // A J1939 identifier given as a standard one (python-can's is_extended_id=False): name the
    // range, as frame_id_arg does (in hex: a J1939 identifier is read in hex).
    if (!extended && id > 0x7FF) {
        const bool message = py::hasattr(o, "arbitration_id");
        raise(types().decode_error,
              std::string(message ? "frame: arbitration_id: " : "frame: id: ") +
                  py::module_::import("builtins").attr("hex")(id).cast<std::string>() +
                  " is outside 0..0x7FF (11 bits: " + (message ? "is_extended_id" : "extended") +
                  "=False)",
              py::str("value_out_of_range"));
    }
    const auto f =
        can::make_frame(static_cast<std::uint32_t>(id),
                        {reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()},
                        extended ? can::id_format::extended : can::id_format::standard);
    if (!f) raise_code(types().decode_error, "frame", f.error());
    return *f;
}

// A can.Message is extended unless told otherwise (python-can's is_extended_id=True): for an
// extended frame that a keypad would read as a standard one, what to write instead.
std::string standard_id_hint(const can::frame& f, canopen::node_id node, model m) {
    if (!f.is_extended() || f.raw_id() > 0x7FF) return {};
    const auto d = f.data();
    const auto standard = can::make_frame(f.raw_id(), d, can::id_format::standard);
    if (!standard) return {};
    const auto r = decode(*standard, node, m);
    if (!r) return {};
    char id[8];
    std::snprintf(id, sizeof id, "%03Xh", static_cast<unsigned>(f.raw_id()));
    return std::string(
               " (the frame is extended: can.Message is, unless given "
               "is_extended_id=False; as a standard frame ") +
           id + " is " + std::string(kind_of(*r)) + ")";
}

can::frame frame_from_args(py::handle msg_or_id, py::handle data, py::handle extended) {
    if (data.is_none()) return frame_from_py(msg_or_id);
    if (extended.is_none()) return frame_from_py(py::make_tuple(msg_or_id, data));
    return frame_from_py(py::make_tuple(msg_or_id, data, extended));
}

// A frame as powerkey._types.to_frame makes it: a can.Message (a powerkey.Frame without
// python-can).
py::object frame_to_py(const can::frame& f) {
    const auto d = f.data();
    return types().to_frame(
        f.raw_id(), py::bytes(reinterpret_cast<const char*>(d.data()), d.size()), f.is_extended());
}

py::object optional_frame(const std::optional<can::frame>& f) {
    if (!f) return py::none();
    return frame_to_py(*f);
}

// --- accessors ------------------------------------------------------------------------------

py::dict leds_to_py(const leds& l) {
    py::dict d;
    d["red"] = index_list(l.red);
    d["green"] = index_list(l.green);
    d["blue"] = index_list(l.blue);
    return d;
}

leds leds_from_py(py::handle o, std::string_view what) {
    leds l;
    if (o.is_none()) return l;
    if (!py::isinstance<py::dict>(o))
        throw py::type_error(std::string(what) + ": expected a dict like {'green': [3]}, not " +
                             py_repr(o));
    for (const auto& [k, v] : py::reinterpret_borrow<py::dict>(o)) {
        const auto p = enum_from_py<plane>(k, "plane", true);
        from_py(l.of(p), v, what);
    }
    return l;
}

py::object led_map_to_py(const std::optional<led_map_update>& u) {
    if (!u) return py::none();
    return types().led_map_update(leds_to_py(u->map), leds_to_py(u->covered));
}

model message_model(const py_message& m, py::handle given) {
    if (!given.is_none()) return model_from_py(given);
    if (m.md) return *m.md;
    argument_error("this message has no model: give model=");
}

// --- session, virtual keypad, controller -----------------------------------------------------

struct py_session {
    session<> s;
    py_session(model m, canopen::node_id n, j1939::keypad_address a) : s(m, n) {
        s.narrow_j1939(a);
    }
};

py::str latin1(std::string_view s) {
    return py::reinterpret_steal<py::str>(
        PyUnicode_DecodeLatin1(s.data(), static_cast<Py_ssize_t>(s.size()), nullptr));
}

py::dict session_event_to_py(const py_session& ps, const session_event& e) {
    py::dict d;
    d["function"] = enum_to_py(e.cls.fn);
    d["node"] = e.node.value();
    if (e.decoded) {
        d["message"] = py_message{*e.decoded, ps.s.model(), e.node.value()};
        d["error"] = py::none();
    } else {
        d["message"] = py::none();
        d["error"] = enum_to_py(e.decoded.error());
    }
    d["sdo"] = enum_to_py(e.sdo);
    d["request"] = e.sdo == sdo_pairing::reply
                       ? py::object(py::make_tuple(e.request.index, e.request.subindex))
                       : py::object(py::none());
    d["upload_done"] = e.upload_done;
    d["text"] = e.upload_done ? py::object(latin1(ps.s.text())) : py::object(py::none());
    d["upload_error"] =
        e.upload_error != errc{} ? enum_to_py(e.upload_error) : py::object(py::none());
    d["new_node"] = e.new_node ? py::object(py::int_(e.new_node->value())) : py::none();
    d["new_protocol"] = e.new_protocol ? enum_to_py(*e.new_protocol) : py::object(py::none());
    d["new_address"] = e.new_address ? py::object(py::int_(*e.new_address)) : py::none();
    return d;
}

// A key number: any int; one the model lacks (0, 99, 2**64) is False from press/release, as in C++.
unsigned key_arg(py::handle o) {
    expect_int(o, "key");
    return int_within(o, 1, key_set::max) ? static_cast<unsigned>(o.cast<std::uint64_t>()) : 0u;
}

using keypad_type = pb::virtual_keypad<64>;
using controller_type = pb::controller<64, 128>;

// The controller reads its configuration list from caller-owned storage: the list lives next to
// it, constructed first, and neither moves.
struct py_controller {
    std::vector<message> list;
    controller_type c;
    py_controller(pb::controller_config cfg, std::vector<message> l)
        : list(std::move(l)), c((cfg.configuration = list, cfg)) {}
    py_controller(const py_controller&) = delete;
    py_controller& operator=(const py_controller&) = delete;
};

// The colours a controller's keypad shows, for its refusals: "off, red, green, amber".
std::string shown_colours(const py_controller& c) {
    std::string names;
    for (const colour v : enum_values<colour>())
        if (c.c.shows(v)) names.append(names.empty() ? "" : ", ").append(to_string(v));
    return names;
}

[[noreturn]] void refuse_colour(const py_controller& c, colour cl) {
    raise(types().argument_error,
          "colour: a " + std::string(to_string(c.c.model())) + " shows no " +
              std::string(to_string(cl)) + " (" + shown_colours(c) + ")",
          py::str("value_out_of_range"));
}

// An LED map names only the planes and LEDs the keypad has (else set_leds would be refused).
void check_leds(const py_controller& c, const leds& l, const char* what) {
    const auto row = info(c.c.model()).value();
    for (const plane p : enum_values<plane>()) {
        const auto& set = l.of(p);
        if (set.empty()) continue;
        if (static_cast<unsigned>(p) >= row.planes)
            raise(types().argument_error,
                  std::string(what) + ": a " + std::string(to_string(c.c.model())) + " has no " +
                      std::string(to_string(p)) + " LEDs (" + shown_colours(c) + ")",
                  py::str("value_out_of_range"));
        for (unsigned k = 1; k <= 32; ++k)
            if (set.contains(k) && (k > row.leds || ((row.led_mask >> (k - 1)) & 1u) == 0))
                raise(types().argument_error,
                      std::string(what) + ": " + std::string(to_string(p)) + ": a " +
                          std::string(to_string(c.c.model())) + " has no LED " + std::to_string(k),
                      py::str("value_out_of_range"));
    }
}

py::dict controller_event_to_py(const pb::controller_event& e) {
    py::dict d;
    d["kind"] = enum_to_py(e.kind);
    d["key"] = e.key;
    d["node"] = e.node.value();
    d["origin"] = enum_to_py(e.origin);
    d["step"] = e.step;
    d["what"] = enum_to_py(e.what);
    d["value"] = e.value;
    return d;
}

// The enums powerkey.names() lists: a name and the list of its values' names, from the enum's one
// name table (enum_values, to_string).
template <class E>
py::list names_of() {
    py::list l;
    for (const E v : enum_values<E>()) l.append(std::string(to_string(v)));
    return l;
}
struct enum_list {
    std::string_view name;
    py::list (*names)();
};
constexpr enum_list enum_lists[] = {
    {"model", names_of<model>},
    {"object", names_of<object>},
    {"errc", names_of<errc>},
    {"colour", names_of<colour>},
    {"backlight_colour", names_of<backlight_colour>},
    {"led_state", names_of<led_state>},
    {"baud_rate", names_of<baud_rate>},
    {"nmt_command", names_of<canopen::nmt_command>},
    {"nmt_state", names_of<canopen::nmt_state>},
    {"command_code", names_of<command_code>},
    {"event_kind", names_of<pb::event_kind>},
};

}  // namespace

PYBIND11_MODULE(_powerkey, mod) {
    mod.doc() = "powerkey: every CAN frame of Blink Marine PowerKey keypads (docs/python.md)";
    {
        const auto t = py::module_::import("powerkey._types");
        auto& ty = types();
        ty.error = t.attr("Error");
        ty.decode_error = t.attr("DecodeError");
        ty.encode_error = t.attr("EncodeError");
        ty.argument_error = t.attr("ArgumentError");
        ty.led_map_update = t.attr("LedMapUpdate");
        ty.backlight_update = t.attr("BacklightUpdate");
        ty.to_frame = t.attr("to_frame");
    }

    py::enum_<model> model_enum(mod, "Model", "The keypad models, by their tool names");
    for (const model m : enum_values<model>())
        model_enum.value(std::string(to_string(m)).c_str(), m);

    mod.def("model_info", [](py::handle m) {
        const auto mi = info(model_from_py(m)).value();
        py::dict d;
        d["model"] = enum_to_py(mi.id);
        d["dictionary"] = enum_to_py(mi.dictionary);
        d["keys"] = mi.keys;
        d["leds"] = mi.leds;
        d["planes"] = mi.planes;
        d["stride"] = mi.stride;
        d["led_mask"] = mi.led_mask;
        d["brightness_pdo"] = mi.brightness_pdo;
        d["encoder_leds_pdo"] = mi.encoder_leds_pdo;
        d["backlight_pdo"] = mi.backlight_pdo;
        d["backlight_colour"] = mi.backlight_colour;
        d["encoders"] = mi.encoders;
        d["j1939"] = mi.j1939;
        d["replies_from_new_id"] = mi.replies_from_new_id;
        return d;
    });
    mod.def("parse_model", [](py::handle m) { return model_from_py(m); });
    mod.def("kinds", [] {
        py::list l;
        for_each_alternative<message>([&]<class S>(std::type_identity<S>) {
            l.append(std::string(S::kind));
            return false;
        });
        return l;
    });
    mod.def("names", [](const std::string& what) -> py::list {
        for (const auto& e : enum_lists)
            if (what == e.name) return e.names();
        std::string known;
        for (const auto& e : enum_lists) known += (known.empty() ? "" : ", ") + std::string(e.name);
        argument_error("names: unknown enum '" + what + "' (one of: " + known + ")");
    });

    py::class_<py_message>(mod, "Message", "A decoded (or built) keypad message")
        .def_property_readonly("kind",
                               [](const py_message& m) { return std::string(kind_of(m.m)); })
        .def_property_readonly(
            "form", [](const py_message& m) { return std::string(to_string(form_of(m.m))); },
            "\"manual\", or \"trimmed\" / \"padded\" for a frame not in the manual's form")
        .def_property_readonly("model",
                               [](const py_message& m) -> py::object {
                                   return m.md ? py::object(py::cast(*m.md))
                                               : py::object(py::none());
                               })
        .def_property_readonly("node",
                               [](const py_message& m) -> py::object {
                                   return m.node ? py::object(py::int_(*m.node))
                                                 : py::object(py::none());
                               })
        .def(
            "to_dict", [](const py_message& m) { return fields_of(m.m); },
            "The fields, as the tool's JSON `fields`")
        .def("__getattr__",
             [](const py_message& m, const std::string& name) {
                 py::object found;
                 for_each_field(m.m, [&](std::string_view n, const auto& v) {
                     if (!found && n == name) found = to_py(v);
                 });
                 if (!found)
                     throw py::attribute_error("'" + std::string(kind_of(m.m)) +
                                               "' message has no field '" + name + "'");
                 return found;
             })
        .def("__dir__",
             [](const py_message& m) {
                 py::list l;
                 for (const char* a :
                      {"kind", "model", "node", "to_dict", "describe", "pressed_keys", "led_on_map",
                       "led_blink_map", "led_brightness_level", "backlight_change",
                       "node_id_change", "reported_nmt_state"})
                     l.append(a);
                 for_each_field(
                     m.m, [&l](std::string_view n, const auto&) { l.append(std::string(n)); });
                 return l;
             })
        .def("__eq__",
             [](const py_message& a, py::handle b) {
                 return py::isinstance<py_message>(b) && a.m == b.cast<const py_message&>().m;
             })
        .def("__hash__",
             [](const py_message& m) { return py::hash(py::str(std::string(kind_of(m.m)))); })
        .def("__repr__",
             [](const py_message& m) {
                 std::string s = "Message('" + std::string(kind_of(m.m)) + "'";
                 for_each_field(m.m, [&s](std::string_view n, const auto& v) {
                     s.append(", ").append(n).append("=").append(py_repr(to_py(v)));
                 });
                 return s + ")";
             })
        .def(
            "describe",
            [](const py_message& m, py::handle node) {
                const auto n = node.is_none()
                                   ? canopen::node_id::make(m.node.value_or(0x15)).value()
                                   : node_from_py(node);
                std::array<char, description_capacity> buf{};
                const auto t = describe(m.m, n, buf);
                if (!t) raise_code(types().error, "describe", t.error());
                return std::string(*t);
            },
            py::arg("node") = py::none(), "The library's one-line description (describe.hpp)")
        .def("pressed_keys",
             [](const py_message& m) -> py::object {
                 const auto k = pressed_keys(m.m);
                 return k ? py::object(index_list(*k)) : py::object(py::none());
             })
        .def(
            "key_change",
            [](const py_message& m, py::handle md) -> py::object {
                const auto u = key_change(m.m, message_model(m, md));
                if (!u) return py::none();
                py::dict d;
                d["pressed"] = index_list(u->pressed);
                d["covered"] = index_list(u->covered);
                return d;
            },
            py::arg("model") = py::none(),
            "The keys the message states ('covered') and which of them are pressed")
        .def("address_change",
             [](const py_message& m) -> py::object {
                 const auto a = address_change(m.m);
                 return a ? py::object(py::int_(*a)) : py::object(py::none());
             })
        .def(
            "led_on_map",
            [](const py_message& m, py::handle md) {
                return led_map_to_py(led_on_map(m.m, message_model(m, md)));
            },
            py::arg("model") = py::none())
        .def(
            "led_blink_map",
            [](const py_message& m, py::handle md) {
                return led_map_to_py(led_blink_map(m.m, message_model(m, md)));
            },
            py::arg("model") = py::none())
        .def("led_brightness_level",
             [](const py_message& m) -> py::object {
                 const auto l = led_brightness_level(m.m);
                 return l ? py::object(py::int_(l->value())) : py::object(py::none());
             })
        .def("backlight_change",
             [](const py_message& m) -> py::object {
                 const auto u = backlight_change(m.m);
                 if (!u) return py::none();
                 return types().backlight_update(
                     u->level ? py::object(py::int_(u->level->value())) : py::object(py::none()),
                     u->colour ? enum_to_py(*u->colour) : py::object(py::none()));
             })
        .def("node_id_change",
             [](const py_message& m) -> py::object {
                 const auto n = node_id_change(m.m);
                 return n ? py::object(py::int_(n->value())) : py::object(py::none());
             })
        .def("reported_nmt_state", [](const py_message& m) -> py::object {
            const auto s = reported_nmt_state(m.m);
            return s ? enum_to_py(*s) : py::object(py::none());
        });

    mod.def(
        "decode",
        [](py::handle msg_or_id, py::handle data, py::handle md, py::handle node,
           py::handle extended, py::handle address) {
            const auto f = frame_from_args(msg_or_id, data, extended);
            const auto m = model_from_py(md);
            const auto n = node_from_py(node);
            const auto r = decode(f, n, m, address_from_py(address));
            if (!r) {
                std::string what = "decode ";
                what += f.is_extended() ? "extended " : "";
                what += "frame as " + std::string(to_string(m));
                what += ": " + std::string(to_string(r.error()));
                what += standard_id_hint(f, n, m);
                raise(types().decode_error, what, py::str(std::string(to_string(r.error()))));
            }
            return py_message{*r, m, n.value()};
        },
        py::arg("msg_or_id"), py::arg("data") = py::none(), py::kw_only(), py::arg("model"),
        py::arg("node") = 0x15, py::arg("extended") = py::none(), py::arg("address") = py::none());

    mod.def(
        "message",
        [](const std::string& kind, py::handle md, py::handle node, const py::dict& fields) {
            std::optional<canopen::node_id> n;
            if (!node.is_none()) n = node_from_py(node);
            py_message m{build_message(kind, fields, n), std::nullopt, std::nullopt};
            if (!md.is_none()) m.md = model_from_py(md);
            if (n) m.node = n->value();
            return m;
        },
        py::arg("kind"), py::kw_only(), py::arg("model") = py::none(), py::arg("node") = py::none(),
        py::arg("fields") = py::dict());

    mod.def(
        "encode_frame",
        [](const py_message& m, py::handle md, py::handle node, py::handle address) {
            const auto mm = message_model(m, md);
            const auto n = node.is_none() ? canopen::node_id::make(m.node.value_or(0x15)).value()
                                          : node_from_py(node);
            const auto a = address_from_py(address);
            const auto f = encode(n, mm, m.m, a);
            if (!f) refused(m.m, mm, n, a, f.error());
            return frame_to_py(*f);
        },
        py::arg("message"), py::kw_only(), py::arg("model") = py::none(),
        py::arg("node") = py::none(), py::arg("address") = py::none());

    // --- the session follower ------------------------------------------------------------------
    py::class_<py_session>(mod, "Session")
        .def(py::init([](py::handle md, py::handle node, py::handle address) {
                 return new py_session(model_from_py(md), node_from_py(node),
                                       address_from_py(address));
             }),
             py::kw_only(), py::arg("model"), py::arg("node") = 0x15,
             py::arg("address") = py::none())
        .def(
            "step",
            [](py_session& ps, py::handle msg_or_id, py::handle data, py::handle extended) {
                const auto f = frame_from_args(msg_or_id, data, extended);
                return session_event_to_py(ps, ps.s.step(f));
            },
            py::arg("msg_or_id"), py::arg("data") = py::none(), py::kw_only(),
            py::arg("extended") = py::none())
        .def_property_readonly("model", [](const py_session& ps) { return ps.s.model(); })
        .def_property_readonly("node", [](const py_session& ps) { return ps.s.node().value(); })
        .def_property_readonly("protocol",
                               [](const py_session& ps) { return enum_to_py(ps.s.protocol()); })
        .def_property_readonly("text", [](const py_session& ps) { return latin1(ps.s.text()); });

    // --- the virtual keypad --------------------------------------------------------------------
    py::class_<keypad_type>(mod, "VirtualKeypad")
        .def(py::init([](py::handle md, py::handle node, bool drop, py::handle response_ms,
                         bool j1939, py::handle j1939_address) {
                 // 01h..FDh, as 70h takes it.
                 const auto address =
                     pb::j1939_source_address::make(address_arg(j1939_address, "j1939_address"))
                         .value();
                 return new keypad_type(
                     model_from_py(md), node_from_py(node),
                     pb::keypad_options{
                         .drop_sdo_while_busy = drop,
                         .sdo_response_ms = duration_arg(response_ms, "sdo_response_ms").value,
                         .start_in_j1939 = j1939,
                         .j1939_address = address});
             }),
             py::kw_only(), py::arg("model"), py::arg("node") = 0x15,
             py::arg("drop_sdo_while_busy") = true, py::arg("sdo_response_ms") = 1,
             py::arg("start_in_j1939") = false, py::arg("j1939_address") = 0x21)
        .def("power_on", [](keypad_type& k, py::handle t) { k.power_on(millis_arg(t)); })
        .def("power_off", [](keypad_type& k) { k.power_off(); })
        .def("power_cycle", [](keypad_type& k, py::handle t) { k.power_cycle(millis_arg(t)); })
        .def("silence", [](keypad_type& k, py::handle t,
                           py::handle d) { k.silence(millis_arg(t), duration_arg(d, "ms")); })
        .def("drop_received",
             [](keypad_type& k, py::handle n) {
                 k.drop_received(static_cast<std::uint32_t>(int_arg(n, "n", 0, 0xFFFF'FFFFu)));
             })
        .def("drop_transmitted",
             [](keypad_type& k, py::handle n) {
                 k.drop_transmitted(static_cast<std::uint32_t>(int_arg(n, "n", 0, 0xFFFF'FFFFu)));
             })
        .def("receive", [](keypad_type& k, py::handle frame,
                           py::handle t) { k.receive(frame_from_py(frame), millis_arg(t)); })
        .def("advance", [](keypad_type& k, py::handle t) { k.advance(millis_arg(t)); })
        .def("press", [](keypad_type& k, py::handle key,
                         py::handle t) { return k.press(key_arg(key), millis_arg(t)); })
        .def("release", [](keypad_type& k, py::handle key,
                           py::handle t) { return k.release(key_arg(key), millis_arg(t)); })
        .def("set_keys",
             [](keypad_type& k, py::handle keys, py::handle t) {
                 key_set s;
                 from_py(s, keys, "keys");
                 k.set_keys(s, millis_arg(t));
             })
        .def("transmit", [](keypad_type& k) { return optional_frame(k.transmit()); })
        .def_property_readonly(
            "state", [](const keypad_type& k) { return std::string(to_string(k.state())); })
        .def_property_readonly("model", [](const keypad_type& k) { return k.model(); })
        .def_property_readonly("node", [](const keypad_type& k) { return k.node().value(); })
        .def_property_readonly("keys", [](const keypad_type& k) { return index_list(k.keys()); })
        .def_property_readonly("led_on",
                               [](const keypad_type& k) { return leds_to_py(k.led_on()); })
        .def_property_readonly("led_blink",
                               [](const keypad_type& k) { return leds_to_py(k.led_blink()); })
        .def_property_readonly("brightness",
                               [](const keypad_type& k) { return k.brightness().value(); })
        .def_property_readonly("backlight",
                               [](const keypad_type& k) {
                                   const auto b = k.backlight();
                                   return types().backlight_update(b.level.value(),
                                                                   enum_to_py(b.colour));
                               })
        .def_property_readonly("baud", [](const keypad_type& k) { return enum_to_py(k.baud()); })
        // Its J1939 side (behaviour/j1939_keypad.hpp): the address it sends from, and each LED
        // that is not off as the last single-LED command or multiple-LED frames set it.
        .def_property_readonly("j1939_address",
                               [](const keypad_type& k) { return k.j1939().address(); })
        .def_property_readonly("j1939_leds",
                               [](const keypad_type& k) {
                                   py::dict out;
                                   for (unsigned i = 1; i <= 16; ++i) {
                                       const auto l = k.j1939().led(i);
                                       if (l.mode == led_mode::off) continue;
                                       py::dict look;
                                       look["mode"] = enum_to_py(l.mode);
                                       look["colour"] = enum_to_py(l.colour);
                                       look["secondary"] = enum_to_py(l.secondary);
                                       out[py::int_(i)] = look;
                                   }
                                   return out;
                               })
        .def("tick", [](const keypad_type& k, py::handle t) { return k.tick(millis_arg(t)); })
        .def("read",
             [](const keypad_type& k, py::handle o) -> py::object {
                 const auto v = k.read(enum_from_py<object>(o, "object", true));
                 return v ? py::object(py::int_(*v)) : py::object(py::none());
             })
        .def_property_readonly("overflowed", [](const keypad_type& k) { return k.overflowed(); });

    // --- the controller ------------------------------------------------------------------------
    py::class_<py_controller>(mod, "Controller")
        .def(py::init([](py::handle md, py::handle node, const py::list& configuration,
                         bool any_node, bool identify, py::handle start, py::handle heartbeat,
                         py::handle lost_after, py::handle sdo_timeout, py::handle sdo_retries,
                         py::handle probe_period, py::handle refresh_period, py::handle long_press,
                         py::handle repeat_delay, py::handle repeat_period) {
                 pb::controller_config cfg;
                 cfg.keypad_model = model_from_py(md);
                 cfg.node = node_from_py(node);
                 cfg.any_node = any_node;
                 cfg.identify = identify;
                 cfg.start = enum_from_py<pb::start_mode>(start, "start", true);
                 // 1017h holds 16 bits (PK1000 29, PKP 17).
                 cfg.keypad_heartbeat = pb::duration_ms{static_cast<std::uint32_t>(
                     int_arg(heartbeat, "keypad_heartbeat", 0, 0xFFFF, " ms (1017h: 16 bits)"))};
                 cfg.lost_after = duration_arg(lost_after, "lost_after");
                 cfg.sdo_timeout = duration_arg(sdo_timeout, "sdo_timeout");
                 cfg.sdo_retries =
                     static_cast<std::uint8_t>(int_arg(sdo_retries, "sdo_retries", 0, 255));
                 cfg.probe_period = duration_arg(probe_period, "probe_period");
                 cfg.refresh_period = duration_arg(refresh_period, "refresh_period");
                 cfg.long_press = duration_arg(long_press, "long_press");
                 cfg.repeat_delay = duration_arg(repeat_delay, "repeat_delay");
                 cfg.repeat_period = duration_arg(repeat_period, "repeat_period");
                 if (configuration.size() > pb::max_configuration)
                     raise(types().argument_error,
                           "configuration: " + std::to_string(configuration.size()) +
                               " entries, more than the controller runs (" +
                               std::to_string(pb::max_configuration) + ": events number them)",
                           py::str("value_out_of_range"));
                 std::vector<message> list;
                 for (const auto item : configuration) {
                     if (!py::isinstance<py_message>(item))
                         throw py::type_error(
                             "configuration: expected powerkey.message(...) entries, not " +
                             py_repr(item));
                     list.push_back(item.cast<const py_message&>().m);
                 }
                 return new py_controller(cfg, std::move(list));
             }),
             py::kw_only(), py::arg("model"), py::arg("node") = 0x15,
             py::arg("configuration") = py::list(), py::arg("any_node") = false,
             py::arg("identify") = true, py::arg("start") = "nmt_start",
             py::arg("keypad_heartbeat") = 200, py::arg("lost_after") = 600,
             py::arg("sdo_timeout") = 300, py::arg("sdo_retries") = 2,
             py::arg("probe_period") = 1000, py::arg("refresh_period") = 1000,
             py::arg("long_press") = 800, py::arg("repeat_delay") = 500,
             py::arg("repeat_period") = 200)
        .def("step", [](py_controller& c, py::handle frame,
                        py::handle t) { c.c.step(frame_from_py(frame), millis_arg(t)); })
        .def("tick", [](py_controller& c, py::handle t) { c.c.tick(millis_arg(t)); })
        .def("next_frame", [](py_controller& c) { return optional_frame(c.c.next_frame()); })
        .def("poll",
             [](py_controller& c) -> py::object {
                 const auto e = c.c.poll();
                 return e ? py::object(controller_event_to_py(*e)) : py::object(py::none());
             })
        .def(
            "set_led",
            [](py_controller& c, py::handle k, py::handle col, bool blink) {
                const auto cl = enum_from_py<colour>(col, "colour", true);
                if (!c.c.shows(cl)) refuse_colour(c, cl);
                return c.c.set_led(key_arg(k), cl, blink);
            },
            py::arg("key"), py::arg("colour"), py::arg("blink") = false)
        .def(
            "set_leds",
            [](py_controller& c, py::handle on, py::handle blink) {
                const auto o = leds_from_py(on, "on"), b = leds_from_py(blink, "blink");
                for (const auto& [map, what] : {std::pair{&o, "on"}, std::pair{&b, "blink"}})
                    check_leds(c, *map, what);
                (void)c.c.set_leds(o, b);
            },
            py::arg("on"), py::arg("blink") = py::none())
        .def("set_brightness",
             [](py_controller& c, py::handle l) {
                 level v;
                 from_py(v, l, "level");
                 c.c.set_brightness(v);
             })
        .def(
            "set_backlight",
            [](py_controller& c, py::handle l, py::handle col) {
                level v;
                from_py(v, l, "level");
                c.c.set_backlight(v, enum_from_py<backlight_colour>(col, "colour", true));
            },
            py::arg("level"), py::arg("colour") = "keep")
        .def("change_node",
             [](py_controller& c, py::handle n) { c.c.change_node(node_from_py(n)); })
        .def_property_readonly("state",
                               [](const py_controller& c) { return enum_to_py(c.c.state()); })
        .def_property_readonly("node", [](const py_controller& c) { return c.c.node().value(); })
        .def_property_readonly("model", [](const py_controller& c) { return c.c.model(); })
        .def_property_readonly("keypad_state",
                               [](const py_controller& c) -> py::object {
                                   const auto s = c.c.keypad_state();
                                   return s ? enum_to_py(*s) : py::object(py::none());
                               })
        .def_property_readonly("keys",
                               [](const py_controller& c) { return index_list(c.c.keys()); })
        .def_property_readonly("led_on",
                               [](const py_controller& c) { return leds_to_py(c.c.led_on()); })
        .def_property_readonly("led_blink",
                               [](const py_controller& c) { return leds_to_py(c.c.led_blink()); })
        .def_property_readonly("text", [](const py_controller& c) { return latin1(c.c.text()); })
        .def_property_readonly("sdo_outstanding",
                               [](const py_controller& c) { return c.c.sdo_outstanding(); })
        .def_property_readonly("events_dropped",
                               [](const py_controller& c) { return c.c.events_dropped(); });
}
