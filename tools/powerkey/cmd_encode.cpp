// powerkey encode: a frame from MESSAGE FIELD=VALUE..., or every frame of decode --json lines.
#include "cli.hpp"
#include "commands.hpp"
#include "field_value.hpp"
#include "input.hpp"
#include "refusal.hpp"

#include <nlohmann/json.hpp>
#include <powerkey/can/candump.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <optional>
#include <string>
#include <vector>

namespace tool {

namespace {
using namespace powerkey;

struct encode_options {
    bool json = false;
    bool broadcast = false;
    std::vector<std::string> args;  // MESSAGE FIELD=VALUE..., or with --json the files
};

// Builds the message of kind `kind` (one alternative of the flat message, found through
// for_each_alternative); get(name, value) sets each field and returns "" or an error. The fields
// of an SDO value follow its object, which is set first. Returns false for an unknown kind.
template <class Get>
bool build_any(std::string_view kind, canopen::node_id node, bool broadcast, Get&& get,
               message& out, std::string& error, j1939::keypad_address address = std::nullopt) {
    return for_each_alternative<message>([&]<class S>(std::type_identity<S>) {
        if (S::kind != kind) return false;
        S s{};
        apply_defaults(s, node, broadcast, address);
        // Every field is looked at (so that each one given is known), the first error kept.
        S::fields(s, [&](std::string_view name, auto& value) {
            const auto e = get(name, value);
            if (!e.empty() && error.empty())
                error = std::string(kind) + ": " + std::string(name) + ": " + e;
        });
        out = s;
        return true;
    });
}

std::string field_names(const message& m) {
    std::string s;
    for_each_field(m, [&s](std::string_view name, const auto&) {
        s.append(s.empty() ? "" : ", ").append(name);
    });
    return s.empty() ? "none" : s;
}

std::string cansend(const can::frame& f) { return std::string(can::format_candump(f).view()); }

// How deep the brackets of a line nest, outside strings; the tool's own lines go 2 deep.
std::size_t nesting(std::string_view s) {
    std::size_t depth = 0, deepest = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (in_string) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '{' || c == '[') {
            deepest = ++depth > deepest ? depth : deepest;
        } else if ((c == '}' || c == ']') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

// The frame a JSON line describes; "" or the error.
std::string frame_of_json(const options& o, const nlohmann::json& v, can::frame& out) {
    if (!v.is_object()) return "expected a JSON object";
    model m = o.keypad;
    if (const auto j = v.find("model"); j != v.end() && !o.model_given) {
        if (!j->is_string()) return "model: expected a string";
        const auto pm = model_from_name(j->get_ref<const std::string&>());
        if (!pm)
            return "model: unknown model '" + escape(j->get_ref<const std::string&>(), 32) + "' (" +
                   model_names() + ")";
        m = *pm;
    }
    canopen::node_id line_node = o.node;
    if (const auto j = v.find("node"); j != v.end()) {
        if (!j->is_number_unsigned()) return "node: expected a number 1..127";
        const auto n = canopen::node_id::make(j->get<std::uint64_t>());
        if (!n) return "node: " + std::to_string(j->get<std::uint64_t>()) + " is outside 1..127";
        line_node = *n;
    }
    // The frame as logged, to check the rebuilt one against (and to copy undecoded frames).
    std::optional<can::frame> logged;
    const auto id = v.find("id");
    const auto data = v.find("data");
    if (id != v.end() || data != v.end()) {
        if (id == v.end() || data == v.end() || !id->is_string() || !data->is_string())
            return "id and data: expected hex strings";
        const auto text =
            id->get_ref<const std::string&>() + "#" + data->get_ref<const std::string&>();
        const auto f = can::parse_candump(text);
        if (!f) return "id/data: '" + escape(text, 40) + "' is not a frame";
        if (const auto ext = v.find("ext");
            ext != v.end() && ext->is_boolean() && ext->get<bool>() != f->is_extended())
            return "ext does not match the id";
        logged = *f;
    }
    const auto kind = v.find("kind");
    if (kind == v.end()) {
        // A frame the decoder could not read has no kind and no fields: it is copied as logged.
        if (v.find("error") == v.end() || !logged)
            return "no kind (and no id/data of an undecoded frame)";
        out = *logged;
        return "";
    }
    if (!kind->is_string()) return "kind: expected a string";
    const auto kind_text = kind_name(kind->get_ref<const std::string&>());
    const auto fields = v.find("fields");
    if (fields != v.end() && !fields->is_object()) return "fields: expected an object";
    // Built for the line's node and checked against the logged frame; then, when --node names
    // another node, built again for that node with an NMT target of the line's node moved too.
    const bool retarget = o.node_given && o.node != line_node;
    auto get_for = [&](bool moved) {
        return [&, moved](std::string_view name, auto& value) -> std::string {
            if (fields == v.end()) return "missing";
            const auto j = fields->find(name);
            // A keys value shows "size" only for a 1-byte reply (value_kinds::keys): absent, 0.
            if (j == fields->end())
                return name == "size" && !fields->contains("bytes") ? "" : "missing";
            auto e = set_from_json(value, *j, name);
            if (e.empty() && moved && name == "target" && j->is_number_unsigned() &&
                j->get<std::uint64_t>() == line_node.value())
                e = set_from_number(value, o.node.value(), name);
            return e;
        };
    };
    message msg;
    std::string error;
    if (!build_any(kind_text, line_node, false, get_for(false), msg, error))
        return "kind: no message '" + escape(kind_text, 40) + "' for " + std::string(to_string(m)) +
               " (powerkey list --model " + std::string(to_string(m)) + " shows them)";
    if (!error.empty()) return "fields: " + error;
    const auto f = encode(line_node, m, msg, o.address);
    if (!f) return "cannot encode " + kind_text + ": " + std::string(to_string(f.error()));
    if (logged && *logged != *f)
        return "rebuilt " + cansend(*f) + " differs from the logged " + cansend(*logged);
    if (!retarget) {
        out = *f;
        return "";
    }
    message moved;
    if (!build_any(kind_text, o.node, false, get_for(true), moved, error) || !error.empty())
        return "fields: " + error;
    const auto g = encode(o.node, m, moved, o.address);
    if (!g)
        return "cannot encode " + kind_text + " for node " + std::to_string(o.node.value()) + ": " +
               std::string(to_string(g.error()));
    out = *g;
    return "";
}

int run_encode(const options& o, const encode_options& eo) {
    if (eo.args.empty())
        return usage_error("encode: a MESSAGE is needed (powerkey list shows them)", false);
    const std::string name = kind_name(eo.args[0]);
    std::vector<std::pair<std::string, std::string>> assignments;
    for (std::size_t i = 1; i < eo.args.size(); ++i) {
        const auto eq = eo.args[i].find('=');
        if (eq == std::string::npos)
            return usage_error("encode: expected FIELD=VALUE, got '" + escape(eo.args[i], 40) +
                               "'");
        assignments.emplace_back(eo.args[i].substr(0, eq), eo.args[i].substr(eq + 1));
    }
    std::vector<bool> used(assignments.size());
    auto get = [&](std::string_view field, auto& value) -> std::string {
        for (std::size_t i = assignments.size(); i-- > 0;) {  // the last one given counts
            if (assignments[i].first != field) continue;
            used[i] = true;
            for (std::size_t k = 0; k < i; ++k)
                if (assignments[k].first == field) used[k] = true;
            return set_from_text(value, assignments[i].second, field);
        }
        return "";
    };
    const std::string model_name(to_string(o.keypad));
    message msg;
    std::string error;
    if (!build_any(name, o.node, eo.broadcast, get, msg, error, o.address))
        return usage_error("encode: no message '" + escape(eo.args[0], 40) + "' for " + model_name +
                               " (powerkey list --model " + model_name + " shows them)",
                           false);
    for (std::size_t i = 0; i < assignments.size(); ++i)
        if (!used[i])
            return usage_error("encode: no field '" + escape(assignments[i].first, 40) + "' in " +
                                   std::string(kind_of(msg)) + " (fields: " + field_names(msg) +
                                   ")",
                               false);
    if (!error.empty()) {
        report("encode", error);
        return status_input;
    }
    const auto f = encode(o.node, o.keypad, msg, o.address);
    if (f) {
        std::printf("%s\n", cansend(*f).c_str());
        return status_ok;
    }
    // Every field held a value of its type, the model refused the message: say which field.
    const std::string kind(kind_of(msg));
    if (const auto narrow = narrowing_needed(msg, o.keypad, o.node, o.address); !narrow.empty()) {
        report("encode", kind + ": " + narrow);
        return status_input;
    }
    const auto why = explain_refusal(
        msg, o.keypad, o.node, [&](auto& s) { apply_defaults(s, o.node, eo.broadcast, o.address); },
        o.address);
    if (why.kind == refusal::what::not_for_model) {
        report("encode", kind + " is not a message of a " + model_name +
                             " (powerkey list --model " + model_name + " shows its messages)");
    } else if (why.kind == refusal::what::field) {
        std::string given = "its value";
        for (const auto& [field, value] : assignments)
            if (field == why.field) given = "'" + escape(value, 32) + "'";
        report("encode",
               kind + ": " + std::string(why.field) + ": " + refusal_text(why, given, model_name));
    } else {
        report("encode", "cannot encode " + kind + " for a " + model_name + ": " +
                             std::string(to_string(f.error())) + " (fields: " + field_names(msg) +
                             ")");
    }
    return status_input;
}

int run_encode_json(const options& o, const encode_options& eo) {
    output out;
    struct stat st {};
    const bool live = ::fstat(0, &st) != 0 || !S_ISREG(st.st_mode);
    std::string current;
    std::optional<problem_cap> problems;
    read_lines(
        eo.args, out, [&](const std::string& label, std::size_t number, std::string_view text) {
            if (!problems || current != label) {
                if (problems) problems->finish();
                problems.emplace(label);
                current = label;
            }
            while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
            if (text.find_first_not_of(" \t") == std::string_view::npos) return;
            std::string error, why;
            can::frame f;
            if (nesting(text) > logs::limits::json_depth) {
                why = "JSON nested deeper than " + std::to_string(logs::limits::json_depth) +
                      " levels (decode --json lines nest 2 deep)";
            } else {
                const auto v = nlohmann::json::parse(text, nullptr, false);
                if (v.is_discarded()) {
                    why = "not a JSON object";
                    error = std::string(text);
                } else {
                    why = frame_of_json(o, v, f);
                }
            }
            if (!why.empty()) {
                out.flush();
                problems->add(number, why, error, false, why.substr(0, why.find_first_of(":'(")));
                return;
            }
            out.buffer() += can::format_candump(f).view();
            out.buffer() += '\n';
            if (live && eo.args.empty())
                out.flush();  // a replay through a pipe sends each frame as it comes
            else
                out.maybe_flush();
        });
    out.flush();
    if (problems) problems->finish();
    return status();
}

}  // namespace

void add_encode(registry& r) {
    static encode_options o;
    auto& sub = r.add(
        {"encode",
         "[--model M] [--node N] [--address A] [--broadcast] MESSAGE [FIELD=VALUE...]\n"
         "--json [--model M] [--node N] [--address A] [FILE...]",
         "a frame from a message and its fields, or the frames of decode --json lines",
         "  --json       read decode --json lines (with --node N the frames are re-targeted to\n"
         "               node N)\n"
         "  --broadcast  an NMT command for every node (target 0) instead of --node\n",
         model_use::optional,
         "the keypad's J1939 address (01h..FDh): a J1939 message's source or destination\n"
         "               when not given as a field, and the keypad its frame is read back as"},
        [&r] {
            if (o.json && o.broadcast) return usage_error("--broadcast is not an option of --json");
            return o.json ? run_encode_json(r.common(), o) : run_encode(r.common(), o);
        });
    sub.add_flag("--json", o.json);
    sub.add_flag("--broadcast", o.broadcast);
    sub.add_option("ARG", o.args);
}

}  // namespace tool
