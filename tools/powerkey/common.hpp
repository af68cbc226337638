// powerkey tool: what the subcommands share: the common options, model names, error reporting
// and exit status, the output buffer, and the text of a message.
#ifndef POWERKEY_TOOL_COMMON_HPP
#define POWERKEY_TOOL_COMMON_HPP

#include "field_text.hpp"
#include "text.hpp"

#include <powerkey/canopen/node_id.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/j1939_codec.hpp>
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

// The options every subcommand shares (cli.hpp); each subcommand keeps its own beside it.
struct options {
    powerkey::model keypad = powerkey::model::pk1000;
    bool model_auto = false;   // --model auto (decode)
    bool model_given = false;  // --model named a model
    powerkey::canopen::node_id node = powerkey::canopen::default_node_id;
    bool node_given = false;
    // --address: the J1939 keypad address the J1939 frames are narrowed to (nullopt: any).
    powerkey::j1939::keypad_address address;
};

// The exit status, the same for every subcommand (docs/cli.md).
inline constexpr int status_ok = 0;     // every input read, nothing wrong found
inline constexpr int status_input = 1;  // input that could not be read, a value refused, or
                                        // (check) a problem found in the log
inline constexpr int status_usage = 2;  // the command line itself is wrong

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

// A usage error: one line, status 2; `hint` ends it with where the usage is, for messages that
// do not say themselves where to look.
inline int usage_error(std::string_view what, bool hint = true) {
    report("", std::string(what) + (hint ? " (powerkey help shows the usage)" : ""));
    return status_usage;
}

// The status after reading: 1 when anything was reported as a failure.
inline int status() { return failures == 0 ? status_ok : status_input; }

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
    std::array<char, powerkey::description_capacity> buf;  // holds every message
    const auto text = powerkey::describe(m, node, buf);
    if (text)
        out += *text;
    else  // cannot happen (description_capacity holds every message): the beginning, marked
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
// the bus, unless --broadcast (or target=0) says so; a J1939 message is of the keypad at
// --address, when given (the source of what the keypad sends, the destination of what it is
// sent: j1939::keypad_address_of).
template <class S>
void apply_defaults(S& s, powerkey::canopen::node_id node, bool broadcast = false,
                    powerkey::j1939::keypad_address address = std::nullopt) {
    S::fields(s, [&](std::string_view name, auto& value) {
        if (name == "target") (void)set_from_number(value, broadcast ? 0u : node.value(), name);
    });
    if constexpr (powerkey::j1939::message_alternative<S>) {
        if (!address) return;
        if constexpr (powerkey::j1939::sent_by_keypad<S>)
            s.source = *address;
        else
            s.destination = *address;
    }
}

}  // namespace tool

#endif
