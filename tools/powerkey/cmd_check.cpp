// powerkey check: the bus-log checker (include/powerkey/behaviour/checker.hpp) on candump logs.
//
//   powerkey check --model M [--node N] [--json] [--sdo-timeout MS] [--heartbeat MS]
//                  [--key-period MS] [FILE...]
//
// Checks each log on its own (`-` or no file: standard input), one frame per line in
// the candump log form `(1700000000.000000) can0 195#0900000012` or the bare `195#0900000012`
// (then the time stands still); blank lines and lines starting with `#` or `//` are skipped. It
// prints one line per problem, in line order, starting with the input line number:
//
//   12: sdo_overlap: SDO request sent while the request of line 11 (2003h/1) is unanswered: ...
//
// (with several files, `FILE:LINE: ...`), or with --json one object per line:
//   {"line":12,"kind":"sdo_overlap","detail":[11,8195,1],"text":"SDO request sent ..."}
// Exit status: 0 no problem, 1 a problem found (or a line that is not a frame, reported on
// standard error), 2 usage.
//
// Self-contained (the tool's other commands are in tools/powerkey/main.cpp): the integrator calls
// run_check(argc, argv) with the arguments after "check".
#include <powerkey/behaviour/checker.hpp>
#include <powerkey/can/candump.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/names.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace {

namespace pb = powerkey::behaviour;

struct options {
    powerkey::model model = powerkey::model::pk1000;
    bool model_given = false;
    powerkey::canopen::node_id node = powerkey::canopen::default_node_id;
    bool json = false;
    pb::checker_config config;
    std::vector<std::string> files;
};

void usage(std::ostream& out) {
    out << "usage: powerkey check --model M [--node N] [--json] [--sdo-timeout MS]\n"
           "                      [--heartbeat MS] [--key-period MS] [FILE...]\n";
}

std::optional<std::uint32_t> parse_number(std::string_view s) {
    int base = 10;
    if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        base = 16;
        s.remove_prefix(2);
    } else if (!s.empty() && (s.back() == 'h' || s.back() == 'H')) {
        base = 16;
        s.remove_suffix(1);
    }
    if (s.empty()) return std::nullopt;
    std::uint64_t v = 0;
    for (char c : s) {
        int d = -1;
        if (c >= '0' && c <= '9') d = c - '0';
        if (base == 16 && c >= 'a' && c <= 'f') d = c - 'a' + 10;
        if (base == 16 && c >= 'A' && c <= 'F') d = c - 'A' + 10;
        if (d < 0) return std::nullopt;
        v = v * static_cast<unsigned>(base) + static_cast<unsigned>(d);
        if (v > 0xFFFF'FFFFu) return std::nullopt;
    }
    return static_cast<std::uint32_t>(v);
}

// The options; nullopt after printing why they are wrong.
std::optional<options> parse_options(int argc, char** argv) {
    options o;
    for (int i = 0; i < argc; ++i) {
        const std::string_view a = argv[i];
        auto value = [&](std::string_view name) -> std::optional<std::string_view> {
            if (i + 1 >= argc) {
                std::cerr << "powerkey check: " << name << " needs a value\n";
                return std::nullopt;
            }
            return std::string_view(argv[++i]);
        };
        auto ms = [&](std::string_view name, powerkey::behaviour::duration_ms& out) {
            const auto v = value(name);
            if (!v) return false;
            const auto n = parse_number(*v);
            if (!n) {
                std::cerr << "powerkey check: " << name << ": not a number of ms: " << *v << "\n";
                return false;
            }
            out = powerkey::behaviour::duration_ms{*n};
            return true;
        };
        if (a == "--model") {
            const auto v = value(a);
            if (!v) return std::nullopt;
            const auto m = powerkey::parse_model(*v);
            if (!m) {
                std::cerr << "powerkey check: unknown model: " << *v << "\n";
                return std::nullopt;
            }
            o.model = *m;
            o.model_given = true;
        } else if (a == "--node") {
            const auto v = value(a);
            if (!v) return std::nullopt;
            const auto n = parse_number(*v);
            const auto id = n ? powerkey::canopen::node_id::make(*n)
                              : powerkey::result<powerkey::canopen::node_id>(
                                    powerkey::errc::value_out_of_range);
            if (!id) {
                std::cerr << "powerkey check: a node id is 1..127: " << *v << "\n";
                return std::nullopt;
            }
            o.node = *id;
        } else if (a == "--json") {
            o.json = true;
        } else if (a == "--sdo-timeout") {
            if (!ms(a, o.config.sdo_timeout)) return std::nullopt;
        } else if (a == "--heartbeat") {
            if (!ms(a, o.config.heartbeat_period)) return std::nullopt;
        } else if (a == "--key-period") {
            if (!ms(a, o.config.key_state_period)) return std::nullopt;
        } else if (a == "-h" || a == "--help") {
            usage(std::cout);
            std::exit(0);
        } else if (a.size() > 1 && a[0] == '-') {
            std::cerr << "powerkey check: unknown option: " << a << "\n";
            return std::nullopt;
        } else {
            o.files.emplace_back(a);
        }
    }
    if (!o.model_given) {
        std::cerr << "powerkey check: --model is required\n";
        return std::nullopt;
    }
    o.config.keypad_model = o.model;
    o.config.node = o.node;
    return o;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

struct line_frame {
    powerkey::can::frame frame;
    std::optional<std::uint32_t> ms;  // the timestamp in ms (wrapping like a firmware counter)
};

enum class line_result { frame, skip, bad };

// "(SECONDS.FRACTION) IFACE ID#DATA" or "ID#DATA".
line_result parse_line(std::string_view line, line_frame& out) {
    line = trim(line);
    if (line.empty() || line[0] == '#' || line.substr(0, 2) == "//") return line_result::skip;
    out.ms.reset();
    if (line[0] == '(') {
        const auto close = line.find(')');
        if (close == std::string_view::npos) return line_result::bad;
        const auto stamp = line.substr(1, close - 1);
        const auto dot = stamp.find('.');
        const auto sec = parse_number(stamp.substr(0, dot));
        if (!sec) return line_result::bad;
        std::uint64_t ms = std::uint64_t{*sec} * 1000;
        if (dot != std::string_view::npos) {
            auto frac = stamp.substr(dot + 1);
            std::uint32_t f = 0;
            for (std::size_t i = 0; i < 3; ++i) {
                const char c = i < frac.size() ? frac[i] : '0';
                if (c < '0' || c > '9') return line_result::bad;
                f = f * 10 + static_cast<std::uint32_t>(c - '0');
            }
            ms += f;
        }
        out.ms = static_cast<std::uint32_t>(ms);
        line = trim(line.substr(close + 1));
        const auto space = line.find_first_of(" \t");  // the interface
        if (space == std::string_view::npos) return line_result::bad;
        line = trim(line.substr(space));
    }
    const auto f = powerkey::can::parse_candump(line);
    if (!f) return line_result::bad;
    out.frame = *f;
    return line_result::frame;
}

struct found {
    std::size_t file;
    pb::problem problem;
};

void put_json_string(std::string& out, std::string_view s) {
    out += '"';
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    out += '"';
}

}  // namespace

int run_check(int argc, char** argv) {
    const auto opt = parse_options(argc, argv);
    if (!opt) {
        usage(std::cerr);
        return 2;
    }
    std::vector<std::string> files = opt->files;
    if (files.empty()) files.emplace_back("-");
    std::vector<found> problems;
    bool bad_input = false;
    for (std::size_t fi = 0; fi < files.size(); ++fi) {
        // Each file is a log of its own: its own time, its own keypad state.
        pb::checker<> checker(opt->config);
        std::uint32_t now = 0;
        std::ifstream file;
        std::istream* in = &std::cin;
        if (files[fi] != "-") {
            file.open(files[fi]);
            if (!file) {
                std::cerr << "powerkey: " << files[fi] << ": cannot open\n";
                bad_input = true;
                continue;
            }
            in = &file;
        }
        std::string text;
        std::uint32_t line = 0;
        while (std::getline(*in, text)) {
            ++line;
            line_frame lf;
            const auto r = parse_line(text, lf);
            if (r == line_result::skip) continue;
            if (r == line_result::bad) {
                std::cerr << "powerkey: " << files[fi] << ":" << line
                          << ": malformed line (expected (TIME) IFACE ID#DATA)\n";
                bad_input = true;
                continue;
            }
            if (lf.ms) now = *lf.ms;
            for (const auto& p : checker.step(lf.frame, pb::millis{now}, line))
                problems.push_back({fi, p});
        }
        // The end of the file: what is still unanswered there.
        for (const auto& p : checker.finish(pb::millis{now})) problems.push_back({fi, p});
    }
    std::stable_sort(problems.begin(), problems.end(), [](const found& a, const found& b) {
        return a.file != b.file ? a.file < b.file : a.problem.line < b.problem.line;
    });
    const bool several = files.size() > 1;
    for (const auto& f : problems) {
        std::array<char, 200> buf{};
        const auto t = pb::explain(f.problem, buf);
        const std::string_view text = t ? *t : std::string_view(buf.data(), buf.size());
        const auto kind = powerkey::to_string(f.problem.kind);
        if (opt->json) {
            std::string out = "{";
            if (several) {
                out += "\"file\":";
                put_json_string(out, files[f.file]);
                out += ',';
            }
            out += "\"line\":" + std::to_string(f.problem.line) + ",\"kind\":";
            put_json_string(out, kind);
            out += ",\"detail\":[" + std::to_string(f.problem.detail[0]) + "," +
                   std::to_string(f.problem.detail[1]) + "," + std::to_string(f.problem.detail[2]) +
                   "],\"text\":";
            put_json_string(out, text);
            out += "}";
            std::cout << out << "\n";
        } else {
            if (several) std::cout << files[f.file] << ":";
            std::cout << f.problem.line << ": " << kind << ": " << text << "\n";
        }
    }
    return problems.empty() && !bad_input ? 0 : 1;
}
