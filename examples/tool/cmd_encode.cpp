// powerkey encode: a frame from MESSAGE FIELD=VALUE..., or every frame of decode --json lines.
#include "common.hpp"
#include "log_formats.hpp"

#include <nlohmann/json.hpp>
#include <powerkey/can/candump.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace tool {

namespace {
using namespace powerkey;

// Builds the message of kind `kind` (one alternative of the flat message, found through
// for_each_alternative); get(name, value) sets each field and returns "" or an error. The fields
// of an SDO value follow its object, which is set first. Returns false for an unknown kind.
template <class Get>
bool build_any(model, std::string_view kind, const options& o, Get&& get, message& out,
               std::string& error) {
    return for_each_alternative<message>([&]<class S>(std::type_identity<S>) {
        if (S::kind != current_kind(kind)) return false;
        S s{};
        apply_defaults(s, o);
        S::fields(s, [&](std::string_view name, auto& value) {
            if (!error.empty()) return;
            const auto e = get(name, value);
            if (!e.empty()) error = std::string(kind) + ": " + std::string(name) + ": " + e;
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
    const auto& kind_name = kind->get_ref<const std::string&>();
    const auto fields = v.find("fields");
    if (fields != v.end() && !fields->is_object()) return "fields: expected an object";
    // Built for the line's node and checked against the logged frame; then, when --node names
    // another node, built again for that node with an NMT target of the line's node moved too.
    const bool retarget = o.node_given && o.node != line_node;
    auto get_for = [&](bool moved) {
        return [&, moved](std::string_view name, auto& value) -> std::string {
            if (fields == v.end()) return "missing";
            const auto j = fields->find(name);
            if (j == fields->end()) return "missing";
            auto e = set_from_json(value, *j, name);
            if (e.empty() && moved && name == "target" && j->is_number_unsigned() &&
                j->get<std::uint64_t>() == line_node.value())
                e = set_from_number(value, o.node.value(), name);
            return e;
        };
    };
    options line_options = o;
    line_options.node = line_node;
    message msg;
    std::string error;
    if (!build_any(m, kind_name, line_options, get_for(false), msg, error))
        return "kind: no message '" + escape(kind_name, 40) + "' for " + std::string(to_string(m)) +
               " (powerkey list --model " + std::string(to_string(m)) + " shows them)";
    if (!error.empty()) return "fields: " + error;
    const auto f = encode(line_node, m, msg);
    if (!f) return "cannot encode " + kind_name + ": " + std::string(to_string(f.error()));
    if (logged && *logged != *f)
        return "rebuilt " + cansend(*f) + " differs from the logged " + cansend(*logged);
    if (!retarget) {
        out = *f;
        return "";
    }
    message moved;
    if (!build_any(m, kind_name, o, get_for(true), moved, error) || !error.empty())
        return "fields: " + error;
    const auto g = encode(o.node, m, moved);
    if (!g)
        return "cannot encode " + kind_name + " for node " + std::to_string(o.node.value()) + ": " +
               std::string(to_string(g.error()));
    out = *g;
    return "";
}

// Calls f(line_number, text) for every line of a file ("-" = standard input).
template <class F>
bool for_each_line(const std::string& path, F&& f) {
    const int fd = path == "-" ? 0 : ::open(path.c_str(), O_RDONLY);
    if (fd < 0) return false;
    std::vector<char> chunk(1u << 16);
    std::string carry;
    std::size_t number = 0;
    bool ok = true;
    for (;;) {
        const auto n = ::read(fd, chunk.data(), chunk.size());
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            ok = false;
            break;
        }
        if (n == 0) break;
        std::string_view data(chunk.data(), static_cast<std::size_t>(n));
        while (!data.empty()) {
            const auto nl = data.find('\n');
            if (nl == std::string_view::npos) {
                carry.append(data);
                break;
            }
            carry.append(data.substr(0, nl));
            f(++number, std::string_view(carry));
            carry.clear();
            data.remove_prefix(nl + 1);
        }
    }
    if (!carry.empty()) f(++number, std::string_view(carry));
    const int saved = errno;
    if (fd != 0) ::close(fd);
    errno = saved;
    return ok;
}

}  // namespace

int run_encode(const options& o) {
    if (o.args.empty()) {
        report("encode", "a MESSAGE is needed (powerkey list shows them)");
        return 2;
    }
    std::string name = o.args[0];
    for (char& c : name)
        if (c == '-') c = '_';
    std::vector<std::pair<std::string, std::string>> assignments;
    for (std::size_t i = 1; i < o.args.size(); ++i) {
        const auto eq = o.args[i].find('=');
        if (eq == std::string::npos) {
            report("encode", "expected FIELD=VALUE, got '" + escape(o.args[i], 40) + "'");
            return 2;
        }
        assignments.emplace_back(o.args[i].substr(0, eq), o.args[i].substr(eq + 1));
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
    message msg;
    std::string error;
    bool found = false;
    // The kinds of the old profiles ("pk1000_led_on", "pkp_led_on") are the same message.
    for (std::string_view prefix : {"pk1000_", "pkp_"})
        if (name.starts_with(prefix)) name.erase(0, prefix.size());
    found = build_any(o.keypad, name, o, get, msg, error);
    if (!found) {
        report("encode", "no message '" + escape(o.args[0], 40) + "' for " +
                             std::string(to_string(o.keypad)) + " (powerkey list --model " +
                             std::string(to_string(o.keypad)) + " shows them)");
        return 2;
    }
    for (std::size_t i = 0; i < assignments.size(); ++i)
        if (!used[i]) {
            report("encode", "no field '" + escape(assignments[i].first, 40) + "' in " +
                                 std::string(kind_of(msg)) + " (fields: " + field_names(msg) + ")");
            return 2;
        }
    if (!error.empty()) {
        report("encode", error);
        return 1;
    }
    const auto f = encode(o.node, o.keypad, msg);
    if (!f) {
        // The type took every value, the model did not (a key above a PKP-2200's four): find the
        // field by leaving out one assignment at a time, then the values this model takes.
        const std::string kind(kind_of(msg));
        // A kind the model does not speak at all (the PKP-3500-MT's encoder messages elsewhere).
        auto none = [](std::string_view, auto&) { return std::string(); };
        message plain;
        std::string ignored;
        if (!kind.starts_with("sdo_") && kind != "command" &&
            build_any(o.keypad, kind, o, none, plain, ignored) &&
            !encode(o.node, o.keypad, plain).has_value()) {
            report("encode", kind + " is not a message of a " + std::string(to_string(o.keypad)) +
                                 " (powerkey list --model " + std::string(to_string(o.keypad)) +
                                 " shows its messages)");
            return 1;
        }
        auto encodes = [&](std::size_t skip, const std::string* replacement) {
            auto g = [&](std::string_view field, auto& value) -> std::string {
                for (std::size_t i = assignments.size(); i-- > 0;) {
                    if (assignments[i].first != field) continue;
                    if (i == skip && replacement == nullptr) return "";
                    return set_from_text(value, i == skip ? *replacement : assignments[i].second,
                                         field);
                }
                return "";
            };
            message m;
            std::string e;
            return build_any(o.keypad, kind, o, g, m, e) && e.empty() &&
                   encode(o.node, o.keypad, m).has_value();
        };
        for (std::size_t i = 0; i < assignments.size(); ++i) {
            if (!encodes(i, nullptr)) continue;
            unsigned most = 0;
            for (unsigned n = 1; n <= 64; ++n) {
                const std::string t = std::to_string(n);
                if (encodes(i, &t)) most = n;
            }
            report("encode", kind + ": " + assignments[i].first + ": '" +
                                 escape(assignments[i].second, 32) + "' is more than a " +
                                 std::string(to_string(o.keypad)) + " takes" +
                                 (most > 0 ? " (1.." + std::to_string(most) + ")" : ""));
            return 1;
        }
        report("encode", "cannot encode " + std::string(kind_of(msg)) + ": " +
                             std::string(to_string(f.error())) + " (fields: " + field_names(msg) +
                             ")");
        return 1;
    }
    std::printf("%s\n", cansend(*f).c_str());
    return 0;
}

int run_encode_json(const options& o) {
    output out;
    std::vector<std::string> files = o.args;
    if (files.empty()) files.push_back("-");
    for (const auto& path : files) {
        const auto label = file_label(path);
        struct stat st {};
        const bool live = path == "-" && (::fstat(0, &st) != 0 || !S_ISREG(st.st_mode));
        const bool ok = for_each_line(path, [&](std::size_t number, std::string_view text) {
            while (!text.empty() && (text.back() == '\r' || text.back() == ' '))
                text.remove_suffix(1);
            if (text.find_first_not_of(" \t") == std::string_view::npos) return;
            std::string error;
            can::frame f;
            if (nesting(text) > 4) {
                error = "JSON nested too deeply (decode --json lines nest 2 deep)";
            } else {
                const auto v = nlohmann::json::parse(text, nullptr, false);
                if (v.is_discarded())
                    error = "not a JSON object: '" + escape(text, 40) + "'";
                else
                    error = frame_of_json(o, v, f);
            }
            if (!error.empty()) {
                out.flush();
                report(label + ":" + std::to_string(number), error);
                return;
            }
            out.buffer() += can::format_candump(f).view();
            out.buffer() += '\n';
            if (live)
                out.flush();  // a replay through a pipe sends each frame as it comes
            else
                out.maybe_flush();
        });
        if (!ok) {
            out.flush();
            report(label, std::strerror(errno));
        }
    }
    return failures == 0 ? 0 : 1;
}

}  // namespace tool
