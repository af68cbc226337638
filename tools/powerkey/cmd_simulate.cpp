// powerkey simulate --model M [--node N] [--press T:K] [--release T:K] [--until T] [FILE...]
//
// Runs the virtual keypad (include/powerkey/behaviour/virtual_keypad.hpp) as a filter: reads the
// frames a controller sends, as candump log lines "(time) can0 ID#DATA" (or bare "ID#DATA", or
// candump's "can0  615   [8]  40 00 .." form; blank lines and lines starting with # or // are
// skipped), from the files in order or standard input ("-" or none), and writes
// the frames the keypad sends as candump log lines in time order, starting with its boot-up.
//
//   --model M       any of the twelve models (any name parse_model takes)
//   --node N        the keypad's node id: decimal, 0x15 or 15h (default 15h)
//   --press T:K     press key K at T seconds after power-on (repeatable)
//   --release T:K   release key K at T seconds after power-on (repeatable)
//   --until T       run until T seconds after power-on (default: 100 ms after the last input
//                   or key event, time for the replies to the last requests)
//
// The keypad powers on at the time of the first input frame (0 when there is none); times are
// honoured to the millisecond. Exit status: 0, 1 when an input line could not be read (reported
// on stderr with file and line, the rest is still simulated), 2 for a usage error.
#include <powerkey/behaviour/virtual_keypad.hpp>
#include <powerkey/can/candump.hpp>
#include <powerkey/keypad/models.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

using namespace powerkey;

struct input_frame {
    double time;  // seconds, as in the log (absolute); NaN when the line has none
    can::frame frame;
};

struct key_event {
    std::uint32_t at_ms;
    unsigned key;
    bool press;
};

int usage(const char* why) {
    std::fprintf(stderr,
                 "powerkey simulate: %s\n"
                 "usage: powerkey simulate --model M [--node N] [--press T:K] [--release T:K] "
                 "[--until T] [FILE...]\n",
                 why);
    return 2;
}

std::optional<unsigned> parse_number(std::string_view s) {
    unsigned base = 10;
    if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        s.remove_prefix(2);
        base = 16;
    } else if (s.size() > 1 && (s.back() == 'h' || s.back() == 'H')) {
        s.remove_suffix(1);
        base = 16;
    }
    if (s.empty()) return std::nullopt;
    const std::string str(s);
    char* end = nullptr;
    const unsigned long v = std::strtoul(str.c_str(), &end, static_cast<int>(base));
    if (*end != '\0' || v > 0xFFFF'FFFFul) return std::nullopt;
    return static_cast<unsigned>(v);
}

std::optional<double> parse_seconds(std::string_view s) {
    if (s.empty()) return std::nullopt;
    const std::string str(s);
    char* end = nullptr;
    const double v = std::strtod(str.c_str(), &end);
    if (*end != '\0' || !(v >= 0)) return std::nullopt;
    return v;
}

std::uint32_t to_ms(double seconds) {
    return static_cast<std::uint32_t>(std::llround(seconds * 1000.0));
}

// One line of a log: nullopt for a blank or comment line; an error message for a bad line.
struct line_result {
    std::optional<input_frame> frame;
    std::string error;
};

line_result parse_line(std::string_view line) {
    const auto trim = [](std::string_view s) {
        while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
        while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
            s.remove_suffix(1);
        return s;
    };
    line = trim(line);
    if (line.empty() || line.front() == '#' || line.substr(0, 2) == "//") return {};
    double time = std::nan("");
    if (line.front() == '(') {
        const auto close = line.find(')');
        if (close == std::string_view::npos) return {std::nullopt, "no ')' after the timestamp"};
        const auto t = parse_seconds(line.substr(1, close - 1));
        if (!t) return {std::nullopt, "bad timestamp"};
        time = *t;
        line = trim(line.substr(close + 1));
    }
    // split into words
    std::vector<std::string_view> words;
    while (!line.empty()) {
        const auto sp = line.find_first_of(" \t");
        words.push_back(line.substr(0, sp));
        if (sp == std::string_view::npos) break;
        line = trim(line.substr(sp));
    }
    if (words.empty()) return {std::nullopt, "no frame"};
    // "ID#DATA", possibly after an interface name
    for (const auto w : words) {
        if (w.find('#') == std::string_view::npos) continue;
        const auto f = can::parse_candump(w);
        if (!f) return {std::nullopt, "bad frame '" + std::string(w) + "'"};
        return {input_frame{time, *f}, {}};
    }
    // candump's default form: "can0  615   [8]  40 00 20 01 00 00 00 00"
    if (words.size() >= 3 && words[2].size() == 3 && words[2].front() == '[') {
        std::string text(words[1]);
        text += '#';
        for (std::size_t i = 3; i < words.size(); ++i) text += std::string(words[i]);
        const auto f = can::parse_candump(text);
        if (!f) return {std::nullopt, "bad frame '" + text + "'"};
        return {input_frame{time, *f}, {}};
    }
    return {std::nullopt, "no frame in the line"};
}

bool read_log(std::istream& in, std::string_view name, std::vector<input_frame>& out) {
    bool ok = true;
    std::string line;
    for (std::size_t n = 1; std::getline(in, line); ++n) {
        const auto r = parse_line(line);
        if (!r.error.empty()) {
            std::fprintf(stderr, "%.*s:%zu: error: %s\n", static_cast<int>(name.size()),
                         name.data(), n, r.error.c_str());
            ok = false;
            continue;
        }
        if (r.frame) out.push_back(*r.frame);
    }
    return ok;
}

}  // namespace

int run_simulate(int argc, char** argv) {
    std::optional<model> m;
    canopen::node_id node = canopen::default_node_id;
    std::vector<key_event> keys;
    std::optional<double> until;
    std::vector<std::string> files;
    for (int i = 0; i < argc; ++i) {
        const std::string_view a = argv[i];
        const auto next = [&]() -> std::optional<std::string_view> {
            if (i + 1 >= argc) return std::nullopt;
            return std::string_view(argv[++i]);
        };
        if (a == "--model") {
            const auto v = next();
            if (!v) return usage("--model needs a model");
            const auto r = parse_model(*v);
            if (!r) return usage("unknown model");
            m = *r;
        } else if (a == "--node") {
            const auto v = next();
            const auto n = v ? parse_number(*v) : std::nullopt;
            const auto id =
                n ? canopen::node_id::make(*n) : result<canopen::node_id>(errc::value_out_of_range);
            if (!id) return usage("--node needs a node id 1..127");
            node = *id;
        } else if (a == "--press" || a == "--release") {
            const auto v = next();
            if (!v) return usage("--press/--release need T:K");
            const auto colon = v->find(':');
            const auto t =
                colon == std::string_view::npos ? std::nullopt : parse_seconds(v->substr(0, colon));
            const auto k =
                colon == std::string_view::npos ? std::nullopt : parse_number(v->substr(colon + 1));
            if (!t || !k) return usage("--press/--release need T:K, e.g. 2.5:3");
            keys.push_back({to_ms(*t), *k, a == "--press"});
        } else if (a == "--until") {
            const auto v = next();
            until = v ? parse_seconds(*v) : std::nullopt;
            if (!until) return usage("--until needs seconds");
        } else if (a == "-h" || a == "--help") {
            usage("runs a virtual keypad on the frames a controller sends");
            return 0;
        } else if (a.size() > 1 && a.front() == '-') {
            return usage("unknown option");
        } else {
            files.emplace_back(a);
        }
    }
    if (!m) return usage("--model is required");
    const auto mi = info(*m);
    for (const auto& k : keys)
        if (k.key < 1 || k.key > mi->keys) return usage("a scripted key the model does not have");

    std::vector<input_frame> frames;
    bool ok = true;
    if (files.empty()) files.emplace_back("-");
    {
        for (const auto& f : files) {
            if (f == "-") {
                ok = read_log(std::cin, "<stdin>", frames) && ok;
                continue;
            }
            std::ifstream in(f);
            if (!in) {
                std::fprintf(stderr, "powerkey simulate: cannot read %s\n", f.c_str());
                return 2;
            }
            ok = read_log(in, f, frames) && ok;
        }
    }

    // Times: the keypad powers on at the first timestamp; a line without one takes the time of
    // the line before it.
    double origin = 0;
    for (const auto& f : frames)
        if (!std::isnan(f.time)) {
            origin = f.time;
            break;
        }
    std::vector<std::uint32_t> at(frames.size());
    double last = origin;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        if (!std::isnan(frames[i].time)) last = std::max(last, frames[i].time);
        at[i] = to_ms(last - origin);
    }
    std::stable_sort(keys.begin(), keys.end(),
                     [](const key_event& a, const key_event& b) { return a.at_ms < b.at_ms; });
    std::uint32_t end = 0;
    if (!at.empty()) end = at.back();
    if (!keys.empty()) end = std::max(end, keys.back().at_ms);
    end += 100;
    if (until) end = to_ms(*until);

    behaviour::virtual_keypad<64> k(*m, node);
    const auto print = [&](std::uint32_t t) {
        while (const auto f = k.transmit()) {
            const double s = origin + t / 1000.0;
            std::printf("(%.6f) can0 %s\n", s, std::string(can::format_candump(*f).view()).c_str());
        }
    };
    k.power_on(behaviour::millis{0});
    print(0);
    std::size_t fi = 0, ki = 0;
    for (std::uint32_t t = 0; t <= end; ++t) {
        const behaviour::millis now{t};
        k.advance(now);
        while (ki < keys.size() && keys[ki].at_ms == t) {
            if (keys[ki].press)
                (void)k.press(keys[ki].key, now);
            else
                (void)k.release(keys[ki].key, now);
            ++ki;
        }
        while (fi < frames.size() && at[fi] == t) {
            print(t);  // what the keypad sent before this frame came
            k.receive(frames[fi].frame, now);
            ++fi;
        }
        print(t);
    }
    return ok ? 0 : 1;
}
