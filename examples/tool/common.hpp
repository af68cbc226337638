// powerkey tool: what the subcommands share: the options, model names, error reporting, the
// output buffer, and the text of a message.
#ifndef POWERKEY_TOOL_COMMON_HPP
#define POWERKEY_TOOL_COMMON_HPP

#include "field_value.hpp"
#include "text.hpp"

#include <powerkey/canopen/node_id.hpp>
#include <powerkey/decoder.hpp>
#include <powerkey/fields.hpp>

#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_map>
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

// A model from a name as people write it: any case, with or without dashes, spaces or the
// manuals' "-LI" suffix: pk1000, PK1000, PK-1000, pkp2400, PKP-2400, PKP-2400-LI.
inline std::optional<powerkey::model> model_from_name(std::string_view name) {
    std::string n;
    for (char c : name) {
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
        if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) n += c;
    }
    if (n.size() > 2 && n.ends_with("li")) n.resize(n.size() - 2);
    for (auto m : powerkey::all_models)
        if (powerkey::to_string(m) == n) return m;
    return std::nullopt;
}

inline constexpr std::string_view model_names = "pk1000, pkp2200, pkp2400, pkp2600";

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

// The kind without its profile prefix, with spaces: "pk1000_led_on" -> "LED on".
inline void append_title(std::string& out, std::string_view kind) {
    constexpr std::string_view upper[] = {"led", "sdo",  "nmt",  "pdo", "rgb",  "j1939",
                                          "id",  "rpdo", "tpdo", "cob", "rs485"};
    for (std::string_view prefix : {std::string_view{"pk1000_"}, std::string_view{"pkp_"}})
        if (kind.starts_with(prefix)) kind.remove_prefix(prefix.size());
    bool first = true;
    while (!kind.empty()) {
        const auto end = kind.find('_');
        const auto word = kind.substr(0, end);
        if (!first) out += ' ';
        first = false;
        bool up = false;
        for (auto u : upper) up = up || u == word;
        for (char c : word)
            out += up && c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
        if (end == std::string_view::npos) break;
        kind.remove_prefix(end + 1);
    }
}

// The title of a kind, made once: kinds are the library's constants, so their address is a key.
inline const std::string& title_of(std::string_view kind) {
    static std::unordered_map<const char*, std::string> titles;
    auto [it, added] = titles.try_emplace(kind.data());
    if (added) append_title(it->second, kind);
    return it->second;
}

// "LED on  red: 17  green: 28": the title, then every field as `name: value` in the form encode
// takes back.
template <class M>
void append_message_text(std::string& out, const M& m) {
    out += title_of(powerkey::kind_of(m));
    std::string_view context;
    powerkey::for_each_field(m, [&](std::string_view name, const auto& v) {
        using T = std::decay_t<decltype(v)>;
        char b[72];  // "  name: " in one append
        std::size_t k = 0;
        b[k++] = ' ';
        b[k++] = ' ';
        for (std::size_t i = 0; i < name.size() && i < 64; ++i) b[k++] = name[i];
        b[k++] = ':';
        b[k++] = ' ';
        out.append(b, k);
        write_text_value(out, name, context, v);
        if constexpr (std::is_enum_v<T>) context = powerkey::enum_name(v);
    });
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

}  // namespace tool

#endif
