// powerkey tool: what the subcommands share: the options, model names, error reporting, the
// output buffer, and the text of a message.
#ifndef POWERKEY_TOOL_COMMON_HPP
#define POWERKEY_TOOL_COMMON_HPP

#include "field_value.hpp"
#include "text.hpp"

#include <powerkey/canopen/node_id.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/names.hpp>

#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace tool {

struct options {
    powerkey::model keypad = powerkey::model::pk1000;
    bool model_auto = false;
    bool model_given = false;
    powerkey::canopen::node_id node = powerkey::canopen::default_node_id;
    bool node_given = false;
    bool json = false;
    bool show = false;
    bool broadcast = false;
    // For the benchmark (scripts/bench_cli.sh): read and parse only, or decode without output.
    bool parse_only = false;
    bool quiet = false;
    bool nlohmann_writer = false;  // decode --json through nlohmann::json (for the benchmark)
    std::vector<std::string> args;
};

// A model from a name as people write it: any case, with or without dashes or underscores, as
// the manuals write it (PKP-2400-LI, PKP-3500-MT) or as the keypad reports it (PKU2400):
// parse_model of the library.
inline std::optional<powerkey::model> model_from_name(std::string_view name) {
    if (const auto m = powerkey::parse_model(name)) return *m;
    return std::nullopt;
}

// "pk1000, pkp2200, ..., pkp2400si": every model of the table, for usage errors and hints.
inline std::string model_names() {
    std::string s;
    for (const auto m : powerkey::enum_values<powerkey::model>())
        s.append(s.empty() ? "" : ", ").append(powerkey::to_string(m));
    return s;
}

// Problems go to standard error, one line each: "powerkey: WHERE: WHAT". WHAT that quotes
// input must have been escaped (escape()).
inline int failures = 0;

inline void report(std::string_view where, std::string_view what, bool failure = true) {
    std::string line = "powerkey: ";
    if (!where.empty()) line.append(where).append(": ");
    line.append(what).append("\n");
    std::fwrite(line.data(), 1, line.size(), stderr);
    if (failure) ++failures;
}

inline std::string file_label(const std::string& path) {
    return path == "-" ? std::string("<stdin>") : escape(path, 200);
}

// Standard output, buffered. Live mode (a pipe or terminal on either side) flushes after every
// chunk of input, so each frame's line appears as soon as the frame arrives.
class output {
public:
    ~output() { flush(); }
    std::string& buffer() { return buf_; }
    void maybe_flush() {
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

// --- the text of a message --------------------------------------------------------------------

// "node 15h  LED on  red: 1 7  green: -  blue: -": the library's describe() of the message, every
// field in the form encode takes back.
inline void append_message_text(std::string& out, const powerkey::message& m,
                                powerkey::canopen::node_id node) {
    std::array<char, 256> buf;  // describe() writes what it returns; 160 hold every message
    const auto text = powerkey::describe(m, node, buf);
    if (text)
        out += *text;
    else  // cannot happen (160 characters hold every message): the beginning, marked
        out.append(buf.data(), buf.size()).append("...");
}

// The fields of describe()'s text, name and value, in order: "level: 3Fh" -> {"level", "3Fh"}.
// (A value never holds two spaces in a row: sets are "1 7", bytes "72 69 6E".)
inline std::vector<std::pair<std::string, std::string>> described_fields(
    const powerkey::message& m, powerkey::canopen::node_id node) {
    std::string text;
    append_message_text(text, m, node);
    std::vector<std::pair<std::string, std::string>> fields;
    std::vector<std::string_view> parts;
    std::string_view t = text;
    while (!t.empty()) {
        const auto sep = t.find("  ");
        parts.push_back(t.substr(0, sep));
        t.remove_prefix(sep == std::string_view::npos ? t.size() : sep + 2);
    }
    // parts: "node 15h", the title, then "name: value" each
    for (std::size_t i = 2; i < parts.size(); ++i) {
        const auto colon = parts[i].find(": ");
        if (colon == std::string_view::npos) continue;
        fields.emplace_back(parts[i].substr(0, colon), parts[i].substr(colon + 2));
    }
    return fields;
}

// Defaults that depend on the command line: an NMT command goes to --node, not to every node on
// the bus, unless --broadcast (or target=0) says so.
template <class S>
void apply_defaults(S& s, const options& o) {
    S::fields(s, [&o](std::string_view name, auto& value) {
        if (name == "target") (void)set_from_number(value, o.broadcast ? 0u : o.node.value(), name);
    });
}

int run_decode(const options& o);
int run_encode(const options& o);
int run_encode_json(const options& o);
int run_list(const options& o);
int run_export_dbc(const options& o);  // cmd_export.cpp

}  // namespace tool

#endif
