// powerkey: read any frame of a PowerKey keypad, or build one.
//   powerkey decode [--model M] [--node N] [--json] [--show] [FILE...]
//   powerkey encode [--model M] [--node N] MESSAGE [FIELD=VALUE...]
//   powerkey encode --json [FILE...]
// docs/cli.md describes the options, the text and JSON output and the exit status.
#include "tool/field_value.hpp"
#include "tool/json.hpp"
#include "tool/log_line.hpp"
#include "tool/show.hpp"

#include <powerkey/decoder.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/powerkey.hpp>
#include <powerkey/session.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace {
using namespace powerkey;
namespace json = tool::json;

constexpr std::string_view usage_text =
    "usage: powerkey decode [--model M] [--node N] [--json] [--show] [FILE...]\n"
    "       powerkey encode [--model M] [--node N] MESSAGE [FIELD=VALUE...]\n"
    "       powerkey encode --json [--model M] [--node N] [FILE...]\n"
    "       powerkey list [--model M]\n"
    "models: pk1000 (default), pkp2200, pkp2400, pkp2600; node: 0x15 (default) or 21\n"
    "FILE - or none reads standard input. See docs/cli.md.\n";

struct options {
    std::string command;
    model keypad = model::pk1000;
    bool model_given = false;
    canopen::node_id node = canopen::default_node_id;
    bool node_given = false;
    bool json = false;
    bool show = false;
    // For the benchmark (scripts/bench_cli.sh): read and parse lines only, or decode without
    // output.
    bool parse_only = false;
    bool quiet = false;
    std::vector<std::string> args;
};

// --- output -------------------------------------------------------------------------------------

class output {
public:
    ~output() { flush(); }
    std::string& buffer() { return buf_; }
    void line(std::string_view s) {
        buf_ += s;
        buf_ += '\n';
        if (buf_.size() > (1u << 16)) flush();
    }
    void flush() {
        if (!buf_.empty()) std::fwrite(buf_.data(), 1, buf_.size(), stdout);
        buf_.clear();
        std::fflush(stdout);
    }

private:
    std::string buf_;
};

int failures = 0;

void report(std::string_view where, std::string_view what) {
    std::fprintf(stderr, "powerkey: %.*s: %.*s\n", static_cast<int>(where.size()), where.data(),
                 static_cast<int>(what.size()), what.data());
    ++failures;
}

// --- reading lines ------------------------------------------------------------------------------

// Calls f(line_number, text) for every line of a file ("-" = standard input). False when the
// file cannot be opened.
template <class F>
bool for_each_line(const std::string& path, F&& f) {
    std::FILE* in = path == "-" ? stdin : std::fopen(path.c_str(), "rb");
    if (in == nullptr) return false;
    std::vector<char> chunk(1u << 16);
    std::string carry;
    std::size_t number = 0;
    for (;;) {
        const std::size_t n = std::fread(chunk.data(), 1, chunk.size(), in);
        if (n == 0) break;
        std::string_view data(chunk.data(), n);
        while (!data.empty()) {
            const auto nl = data.find('\n');
            if (nl == std::string_view::npos) {
                carry.append(data);
                break;
            }
            if (!carry.empty()) {
                carry.append(data.substr(0, nl));
                f(++number, std::string_view(carry));
                carry.clear();
            } else {
                f(++number, data.substr(0, nl));
            }
            data.remove_prefix(nl + 1);
        }
    }
    if (!carry.empty()) f(++number, std::string_view(carry));
    const bool failed = std::ferror(in) != 0;  // e.g. a directory: EISDIR
    const int saved = errno;
    if (in != stdin) std::fclose(in);
    errno = saved;
    return !failed;
}

std::string where(const std::string& path, std::size_t line) {
    return (path == "-" ? std::string("<stdin>") : path) + ":" + std::to_string(line);
}

std::string hex_of(std::span<const std::uint8_t> bytes) {
    std::string s;
    for (auto b : bytes) {
        s += powerkey::detail::hex_digit(b >> 4u);
        s += powerkey::detail::hex_digit(b);
    }
    return s;
}

std::string id_of(const can::frame& f) {
    std::string s;
    const int digits = f.is_extended() ? 8 : 3;
    for (int i = digits - 1; i >= 0; --i) s += powerkey::detail::hex_digit(f.raw_id() >> (4 * i));
    return s;
}

// --- decode -------------------------------------------------------------------------------------

// The node a frame belongs to: the node of its COB-ID, or the keypad followed for the others.
std::uint8_t node_of(const session_event& e) {
    return e.cls.node != 0 ? e.cls.node : e.node.value();
}

void write_generic_fields(json::object_writer& w, const can::frame& f, const session_event& e) {
    switch (e.cls.function) {
        case bus_function::nmt:
            if (const auto m = canopen::decode_nmt(f)) {
                w.field("command", to_string(m->command));
                w.field("target", m->target.value());
            }
            break;
        case bus_function::heartbeat:
            if (const auto m = canopen::decode_heartbeat(f, e.node))
                w.field("state", to_string(m->state));
            break;
        case bus_function::sdo_rx:
        case bus_function::sdo_tx: {
            const auto n = canopen::node_id::make(e.cls.node).value();
            bool carries = false;
            if (e.cls.function == bus_function::sdo_rx) {
                const auto r = canopen::decode_sdo_request(f, n);
                carries = r && !std::holds_alternative<canopen::sdo_segment_request>(*r);
            } else {
                const auto r = canopen::decode_sdo_response(f, n);
                carries = r && !std::holds_alternative<canopen::sdo_segment_response>(*r);
            }
            if (carries) {
                w.field("index", powerkey::detail::load_le_u16(f.bytes(), 1));
                w.field("subindex", f[3]);
            }
            break;
        }
        case bus_function::j1939: {
            const auto id = j1939::parse_id(f).value();
            w.field("priority", id.priority.value());
            w.field("pgn", id.pgn.value());
            w.field("source", id.source);
            w.field("destination", id.destination);
            break;
        }
        default: break;
    }
}

template <std::size_t N>
void decode_json(std::string& out, const tool::log_line& l, const session_event& e,
                 const session<N>& s) {
    json::object_writer w(out);
    if (!l.time.empty()) w.field("time", l.time);
    if (!l.interface.empty()) w.field("interface", l.interface);
    w.field("id", id_of(l.frame));
    w.field_bool("ext", l.frame.is_extended());
    w.field("data", hex_of(l.frame.data()));
    w.field("function", to_string(e.cls.function));
    w.field("node", node_of(e));
    w.field("model", to_string(s.model()));
    if (e.decoded) {
        w.field("kind", kind_of(*e.decoded));
        w.key("fields");
        json::object_writer fw(out);
        for_each_field(*e.decoded, [&fw](std::string_view name, const auto& v) {
            fw.key(name);
            tool::write_json_value(fw, v);
        });
        fw.close();
    }
    write_generic_fields(w, l.frame, e);
    if (e.sdo != sdo_pairing::none) w.field("sdo", to_string(e.sdo));
    if (e.upload_done) w.field("text", s.text());
    if (e.upload_error != errc{}) w.field("upload_error", to_string(e.upload_error));
    if (e.new_node) w.field("new_node", e.new_node->value());
    if (e.new_protocol) w.field("protocol", to_string(*e.new_protocol));
    if (!e.decoded) w.field("error", to_string(e.decoded.error()));
    w.close();
}

template <std::size_t N>
void decode_text(std::string& out, const tool::log_line& l, const session_event& e,
                 const session<N>& s) {
    if (!l.time.empty()) out.append("(").append(l.time).append(") ");
    if (!l.interface.empty()) out.append(l.interface).append(" ");
    const auto text = can::format_candump(l.frame);
    out.append(text.view());
    out.append(text.view().size() < 25 ? 25 - text.view().size() : 0, ' ');
    out += "  ";
    if (e.decoded) {
        std::array<char, 512> buf{};
        const auto d = describe(*e.decoded, canopen::node_id::make(node_of(e)).value(), buf);
        out.append(d ? *d : std::string_view(buf.data(), buf.size()));
    } else {
        out.append("node ");
        const auto n = node_of(e);
        out += powerkey::detail::hex_digit(n >> 4u);
        out += powerkey::detail::hex_digit(n);
        out.append("h  ").append(to_string(e.cls.function)).append("  error: ");
        out.append(to_string(e.decoded.error()));
        if (e.decoded.error() == errc::wrong_id && !concerns(e.cls, s.node())) {
            out.append(" (not keypad ");
            out += powerkey::detail::hex_digit(s.node().value() >> 4u);
            out += powerkey::detail::hex_digit(s.node().value());
            out.append("h)");
        }
    }
    if (e.sdo == sdo_pairing::reply) {
        char b[40];
        std::snprintf(b, sizeof b, "  [reply to %04Xh sub %u]", e.request.index,
                      static_cast<unsigned>(e.request.subindex));
        out.append(b);
    } else if (e.sdo == sdo_pairing::unanswered) {
        out.append("  [reply to no request]");
    }
    if (e.upload_done) out.append("  [text: \"").append(s.text()).append("\"]");
    if (e.upload_error != errc{})
        out.append("  [upload failed: ").append(to_string(e.upload_error)).append("]");
    if (e.new_node) {
        char b[40];
        std::snprintf(b, sizeof b, "  [node id now %02Xh]", e.new_node->value());
        out.append(b);
    }
    if (e.new_protocol)
        out.append("  [protocol now ").append(to_string(*e.new_protocol)).append("]");
}

int run_decode(const options& o) {
    session<256> s(o.keypad, o.node);
    output out;
    tool::keypad_picture picture(o.keypad);
    std::vector<std::string> files = o.args;
    if (files.empty()) files.push_back("-");
    std::string line;
    std::size_t frames = 0, decoded = 0;
    for (const auto& path : files) {
        const bool ok = for_each_line(path, [&](std::size_t number, std::string_view text) {
            const auto p = tool::parse_log_line(text);
            if (p.kind == tool::line_kind::skip) return;
            if (p.kind == tool::line_kind::bad) {
                out.flush();
                report(where(path, number), p.problem);
                return;
            }
            ++frames;
            if (o.parse_only) return;
            const auto e = s.step(p.line.frame);
            if (o.quiet) {
                decoded += e.decoded.has_value() ? 1u : 0u;
                return;
            }
            line.clear();
            if (o.json)
                decode_json(line, p.line, e, s);
            else
                decode_text(line, p.line, e, s);
            out.line(line);
            if (o.show && e.decoded && picture.update(*e.decoded)) out.buffer() += picture.draw();
        });
        if (!ok) {
            out.flush();
            report(path, std::strerror(errno));
        }
    }
    if (o.parse_only || o.quiet) {
        out.flush();
        std::fprintf(stderr, "powerkey: %zu frames read, %zu decoded\n", frames, decoded);
    }
    return failures == 0 ? 0 : 1;
}

// --- encode -------------------------------------------------------------------------------------

// Builds the message of kind `kind` of one profile's message type PM; get(name, value) sets each
// field and returns "" or an error. Returns false when PM has no such kind.
template <class PM, class Get>
bool build(std::string_view kind, Get&& get, PM& out, std::string& error) {
    return for_each_alternative<PM>([&]<class S>(std::type_identity<S>) {
        if (S::kind != kind) return false;
        S s{};
        S::fields(s, [&](std::string_view name, auto& value) {
            if (!error.empty()) return;
            const auto e = get(name, value);
            if (!e.empty()) error = std::string(name) + ": " + e;
        });
        if (error.empty() && !assign_message(out, s))
            error = "internal: cannot hold " + std::string(kind);
        return true;
    });
}

template <class Get>
bool build_any(model m, std::string_view kind, Get&& get, message& out, std::string& error) {
    if (pkp_model(m)) {
        pkp::message pm;
        if (!build(kind, get, pm, error)) return false;
        out = pm;
        return true;
    }
    pk1000::message cm;
    if (!build(kind, get, cm, error)) return false;
    out = cm;
    return true;
}

std::string cansend(const can::frame& f) { return std::string(can::format_candump(f).view()); }

int run_encode_args(const options& o) {
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
            report("encode", "expected FIELD=VALUE, got '" + o.args[i] + "'");
            return 2;
        }
        assignments.emplace_back(o.args[i].substr(0, eq), o.args[i].substr(eq + 1));
    }
    std::vector<bool> used(assignments.size());
    auto get = [&](std::string_view field, auto& value) -> std::string {
        for (std::size_t i = 0; i < assignments.size(); ++i) {
            if (assignments[i].first != field) continue;
            used[i] = true;
            return tool::set_from_text(value, assignments[i].second);
        }
        return "";
    };
    message msg;
    std::string error;
    bool found = false;
    for (std::string prefix : {"", "pk1000_", "pkp_"}) {
        if (build_any(o.keypad, prefix + name, get, msg, error)) {
            found = true;
            break;
        }
    }
    if (!found) {
        report("encode", "no message '" + o.args[0] + "' for " + std::string(to_string(o.keypad)) +
                             " (powerkey list shows them)");
        return 1;
    }
    if (!error.empty()) {
        report("encode", error);
        return 1;
    }
    for (std::size_t i = 0; i < assignments.size(); ++i)
        if (!used[i]) {
            report("encode",
                   "no field '" + assignments[i].first + "' in " + std::string(kind_of(msg)));
            return 1;
        }
    const auto f = encode(o.node, o.keypad, msg);
    if (!f) {
        report("encode", std::string(to_string(f.error())));
        return 1;
    }
    std::printf("%s\n", cansend(*f).c_str());
    return 0;
}

// The frame a JSON line describes; "" or the error.
std::string frame_of_json(const options& o, const json::value& v, can::frame& out) {
    if (v.t != json::value::type::object) return "expected a JSON object";
    model m = o.keypad;
    if (const auto* j = v.find("model"); j && !o.model_given) {
        if (j->t != json::value::type::string) return "model: expected a string";
        const auto pm = parse_model(j->s);
        if (!pm) return "model: unknown model '" + j->s + "'";
        m = *pm;
    }
    canopen::node_id node = o.node;
    if (const auto* j = v.find("node"); j && !o.node_given) {
        if (j->t != json::value::type::number) return "node: expected a number";
        const auto n = canopen::node_id::make(j->n);
        if (!n) return "node: out of range";
        node = *n;
    }
    // The frame as logged, to check the rebuilt one against (and to rebuild undecoded frames).
    std::optional<can::frame> logged;
    const auto* id = v.find("id");
    const auto* data = v.find("data");
    if (id != nullptr || data != nullptr) {
        if (!id || !data || id->t != json::value::type::string ||
            data->t != json::value::type::string)
            return "id and data: expected hex strings";
        const auto f = can::parse_candump(id->s + "#" + data->s);
        if (!f) return "id/data: " + std::string(to_string(f.error()));
        if (const auto* ext = v.find("ext");
            ext && ext->t == json::value::type::boolean && ext->b != f->is_extended())
            return "ext does not match the id";
        logged = *f;
    }
    const auto* kind = v.find("kind");
    if (kind == nullptr) {
        // A frame the decoder could not read has no kind and no fields: it is copied as logged.
        if (!v.find("error") || !logged) return "no kind (and no id/data of an undecoded frame)";
        out = *logged;
        return "";
    }
    if (kind->t != json::value::type::string) return "kind: expected a string";
    const auto* fields = v.find("fields");
    if (fields && fields->t != json::value::type::object) return "fields: expected an object";
    auto get = [&](std::string_view name, auto& value) -> std::string {
        const auto* j = fields ? fields->find(name) : nullptr;
        if (j == nullptr) return "missing";
        return tool::set_from_json(value, *j);
    };
    message msg;
    std::string error;
    if (!build_any(m, kind->s, get, msg, error))
        return "kind: no message '" + kind->s + "' for " + std::string(to_string(m));
    if (!error.empty()) return "fields." + error;
    const auto f = encode(node, m, msg);
    if (!f) return "cannot encode: " + std::string(to_string(f.error()));
    if (logged && *logged != *f)
        return "rebuilt " + cansend(*f) + " differs from the logged " + cansend(*logged);
    out = *f;
    return "";
}

int run_encode_json(const options& o) {
    output out;
    std::vector<std::string> files = o.args;
    if (files.empty()) files.push_back("-");
    for (const auto& path : files) {
        const bool ok = for_each_line(path, [&](std::size_t number, std::string_view text) {
            if (tool::detail::trim(text).empty()) return;
            json::value v;
            std::string error;
            json::parser p(text);
            can::frame f;
            if (p.parse(v, error)) error = frame_of_json(o, v, f);
            if (!error.empty()) {
                out.flush();
                report(where(path, number), error);
                return;
            }
            out.line(can::format_candump(f).view());
        });
        if (!ok) {
            out.flush();
            report(path, std::strerror(errno));
        }
    }
    return failures == 0 ? 0 : 1;
}

// --- list ---------------------------------------------------------------------------------------

template <class PM>
void list_kinds() {
    for_each_alternative<PM>([]<class S>(std::type_identity<S>) {
        std::string line(S::kind);
        S s{};
        S::fields(s, [&line](std::string_view name, const auto&) {
            line.append(" ").append(name).append("=");
        });
        std::printf("%s\n", line.c_str());
        return false;
    });
}

int run_list(const options& o) {
    if (pkp_model(o.keypad))
        list_kinds<pkp::message>();
    else
        list_kinds<pk1000::message>();
    return 0;
}

// --- options ------------------------------------------------------------------------------------

int parse_options(int argc, char** argv, options& o) {
    if (argc < 2) return 2;
    o.command = argv[1];
    for (int i = 2; i < argc; ++i) {
        const std::string_view a = argv[i];
        auto value = [&](std::string_view opt, std::string_view& v) {
            if (a.substr(0, opt.size() + 1) == std::string(opt) + "=") {
                v = a.substr(opt.size() + 1);
                return true;
            }
            if (a == opt && i + 1 < argc) {
                v = argv[++i];
                return true;
            }
            return false;
        };
        std::string_view v;
        if (a == "--json") {
            o.json = true;
        } else if (a == "--show") {
            o.show = true;
        } else if (a == "--parse-only") {
            o.parse_only = true;
        } else if (a == "--quiet") {
            o.quiet = true;
        } else if (value("--model", v)) {
            const auto m = parse_model(v);
            if (!m) {
                report("--model", "unknown model '" + std::string(v) +
                                      "' (pk1000, pkp2200, pkp2400, pkp2600)");
                return 2;
            }
            o.keypad = *m;
            o.model_given = true;
        } else if (value("--node", v)) {
            std::uint64_t n = 0;
            const bool number = tool::parse_number(v, n);
            const auto id = canopen::node_id::make(number ? n : 0);
            if (!number || !id) {
                report("--node",
                       "expected a node id 1..127 (0x15 or 21), got '" + std::string(v) + "'");
                return 2;
            }
            o.node = *id;
            o.node_given = true;
        } else if (a == "--help" || a == "-h") {
            return 3;
        } else if (a.size() > 1 && a[0] == '-' && a != "-" && o.args.empty()) {
            report(a, "unknown option");
            return 2;
        } else {
            o.args.emplace_back(a);
        }
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    options o;
    const int parsed = parse_options(argc, argv, o);
    if (parsed == 3 || o.command == "help" || o.command == "--help" || o.command == "-h") {
        std::fputs(usage_text.data(), stdout);
        return 0;
    }
    if (o.command == "version" || o.command == "--version") {
        std::printf("powerkey %.*s\n", static_cast<int>(version.size()), version.data());
        return 0;
    }
    if (parsed != 0) {
        if (argc < 2) std::fputs(usage_text.data(), stderr);
        return 2;
    }
    if (o.command == "decode") return run_decode(o);
    if (o.command == "encode") return o.json ? run_encode_json(o) : run_encode_args(o);
    if (o.command == "list") return run_list(o);
    report(o.command, "unknown command (decode, encode, list)");
    std::fputs(usage_text.data(), stderr);
    return 2;
}
