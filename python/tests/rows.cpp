// The C++ reference for python/tests/test_rows.py: every manual row of the test tables
// (tests/codec_rows.hpp and the tables of both manuals and the SI family), for every model the
// row names, as one JSON line each, written with the powerkey tool's own JSON writer
// (tools/powerkey/json_writer.hpp, field_value.hpp), so the fields are exactly the tool's:
//
//   {"table":..,"section":..,"model":..,"node":..,"id":"195","ext":false,"data":"040000002A",
//    then for a frame row:   "kind":..,"fields":{..},"encoded":"HEX" (or "encode_error":..)
//         for an error row:  "error":"wrong_length"
//         for an encode error row: "kind":..,"fields":{..},"encode_error":..}
//
// The rows' expected values are not printed: the C++ results are (the doctest suite proves them
// equal to the rows), and the Python module must give the same.
#include <powerkey/can/candump.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/keypad/accessors.hpp>
#include <powerkey/keypad/codec.hpp>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

// The tables first: the tool's headers bring <unistd.h>, whose ::sync() would make the tables'
// sync() ambiguous.
#include "codec_rows.hpp"
#include "pk1000_rows.hpp"
#include "pkp_rows.hpp"
#include "si_reference_rows.hpp"
#include "si_rows.hpp"
// clang-format off
#include "field_value.hpp"
#include "json_writer.hpp"
#include "text.hpp"
// clang-format on

namespace {
using namespace powerkey;

void put_fields(tool::json::object_writer& w, std::string& out, const message& m) {
    w.field("kind", kind_of(m));
    w.key("fields");
    tool::json::object_writer fw(out);
    for_each_field(m, [&fw](std::string_view name, const auto& v) {
        fw.key(name);
        tool::write_json_value(fw, v);
    });
    fw.close();
}

// The line's head; false (and nothing written) when the row's frame text does not parse.
bool put_head(tool::json::object_writer& w, std::string& out, std::string_view table,
              std::string_view section, model m, std::uint8_t node, std::string_view text) {
    w.field("table", table);
    w.field("section", section);
    w.field("model", to_string(m));
    w.field("node", node);
    if (text.empty()) return true;
    const auto f = can::parse_candump(text);
    if (!f) return false;
    w.key("id");
    out += '"';
    tool::append_hex(out, f->raw_id(), f->is_extended() ? 8 : 3);
    out += '"';
    w.field_bool("ext", f->is_extended());
    w.key("data");
    out += '"';
    tool::append_hex_bytes(out, f->data().data(), f->data().size());
    out += '"';
    return true;
}

void put_leds(std::string& out, const leds& l) {
    tool::json::object_writer w(out);
    w.key("red");
    tool::write_json_value(w, l.red);
    w.key("green");
    tool::write_json_value(w, l.green);
    w.key("blue");
    tool::write_json_value(w, l.blue);
    w.close();
}

void put_map(tool::json::object_writer& w, std::string& out, std::string_view name,
             const std::optional<led_map_update>& u) {
    w.key(name);
    if (!u) {
        out += "null";
        return;
    }
    tool::json::object_writer mw(out);
    mw.key("map");
    put_leds(out, u->map);
    mw.key("covered");
    put_leds(out, u->covered);
    mw.close();
}

// What the accessors (accessors.hpp) answer for a message; null where they answer nothing.
void put_accessors(tool::json::object_writer& w, std::string& out, const message& m, model md) {
    w.key("accessors");
    tool::json::object_writer aw(out);
    aw.key("pressed_keys");
    if (const auto k = pressed_keys(m))
        tool::write_json_value(aw, *k);
    else
        out += "null";
    put_map(aw, out, "led_on_map", led_on_map(m, md));
    put_map(aw, out, "led_blink_map", led_blink_map(m, md));
    aw.key("led_brightness_level");
    if (const auto b = led_brightness_level(m))
        aw.number(b->value());
    else
        out += "null";
    aw.key("backlight_change");
    if (const auto b = backlight_change(m)) {
        tool::json::object_writer bw(out);
        bw.key("level");
        if (b->level)
            bw.number(b->level->value());
        else
            out += "null";
        bw.key("colour");
        if (b->colour)
            tool::write_json_value(bw, *b->colour);
        else
            out += "null";
        bw.close();
    } else {
        out += "null";
    }
    aw.key("node_id_change");
    if (const auto n = node_id_change(m))
        aw.number(n->value());
    else
        out += "null";
    aw.key("reported_nmt_state");
    if (const auto st = reported_nmt_state(m))
        tool::write_json_value(aw, *st);
    else
        out += "null";
    aw.close();
}

int lines = 0;
void emit(std::string& line) {
    std::fputs(line.c_str(), stdout);
    std::fputc('\n', stdout);
    line.clear();
    ++lines;
}

// Calls f(row, model) for every row and every model the row applies to.
template <class Rows, class F>
void each_row_and_model(const Rows& rows, F f) {
    for (const auto& r : rows)
        for (std::size_t i = 0; i < model_count; ++i)
            if (r.models.contains(static_cast<model>(i))) f(r, static_cast<model>(i));
}

// The encoded frame's data as hex, or the encode error.
void put_encoded(tool::json::object_writer& w, std::string& out, const result<can::frame>& e) {
    if (e) {
        w.key("encoded");
        out += '"';
        tool::append_hex_bytes(out, e->data().data(), e->data().size());
        out += '"';
    } else {
        w.field("encode_error", to_string(e.error()));
    }
}

template <class Rows>
void frame_rows(std::string_view table, const Rows& rows) {
    each_row_and_model(rows, [table](const auto& r, model m) {
        std::string out;
        tool::json::object_writer w(out);
        const auto node = canopen::node_id::make(r.node).value();
        if (!put_head(w, out, table, r.section, m, r.node, r.frame)) {
            std::fprintf(stderr, "%.*s: unreadable frame\n", static_cast<int>(r.section.size()),
                         r.section.data());
            std::exit(1);
        }
        const auto d = decode(*can::parse_candump(r.frame), node, m);
        if (d) {
            put_fields(w, out, *d);
            put_accessors(w, out, *d, m);
            put_encoded(w, out, encode(node, m, *d));
        } else {
            w.field("error", to_string(d.error()));
        }
        w.close();
        emit(out);
    });
}

// The message `kind` with the fields of a JSON object, read by the tool's reader (the way
// `powerkey encode --json` builds one): what a Python bench can say of a message is its fields.
message from_fields(std::string_view kind, const nlohmann::json& fields) {
    message out;
    (void)for_each_alternative<message>([&]<class S>(std::type_identity<S>) {
        if (S::kind != kind) return false;
        S s{};
        S::fields(s, [&](std::string_view name, auto& value) {
            if (const auto j = fields.find(std::string(name)); j != fields.end())
                (void)tool::set_from_json(value, *j, name);
        });
        out = s;
        return true;
    });
    return out;
}

// An encode-error row: the message's kind and fields, and what encode makes of the message those
// fields describe. Some rows hold a raw value no field shows (a flag of 2 reads "enabled": true);
// for them `same_message` is false and the reference is the C++ encode of the message the fields
// describe, which is what powerkey.encode(kind, **fields) must give.
template <class Rows>
void encode_error_rows(std::string_view table, const Rows& rows) {
    each_row_and_model(rows, [table](const auto& r, model m) {
        std::string out;
        tool::json::object_writer w(out);
        (void)put_head(w, out, table, r.section, m, r.node, "");
        const auto start = out.size();
        put_fields(w, out, r.msg);
        const auto fields_at = out.find("\"fields\":", start) + 9;
        const auto fields = nlohmann::json::parse(out.substr(fields_at));
        const auto rebuilt = from_fields(kind_of(r.msg), fields);
        w.field_bool("same_message", rebuilt == r.msg);
        put_encoded(w, out, encode(canopen::node_id::make(r.node).value(), m, rebuilt));
        w.close();
        emit(out);
    });
}

}  // namespace

int main() {
    frame_rows("core_rows", codec_rows::core_rows);
    frame_rows("core_error_rows", codec_rows::core_error_rows);
    frame_rows("pk1000_rows", pk1000_rows::rows);
    frame_rows("pk1000_error_rows", pk1000_rows::error_rows);
    encode_error_rows("pk1000_encode_error_rows", pk1000_rows::encode_error_rows);
    frame_rows("pkp_rows", pkp_rows::rows);
    frame_rows("pkp_error_rows", pkp_rows::error_rows);
    encode_error_rows("pkp_encode_error_rows", pkp_rows::encode_error_rows);
    frame_rows("si_rows", si_rows::rows);
    frame_rows("si_error_rows", si_rows::error_rows);
    frame_rows("si_errata_rows", si_rows::errata_rows);
    frame_rows("si_reference_rows", si_reference_rows::rows);
    frame_rows("si_reference_error_rows", si_reference_rows::error_rows);
    std::fprintf(stderr, "%d lines\n", lines);
    return 0;
}
