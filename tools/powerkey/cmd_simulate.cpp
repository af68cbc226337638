// powerkey simulate --model M [--node N] [--j1939 [--address A]] [--press T:K] [--release T:K]
//                   [--until T] [FILE...]
//
// Runs the virtual keypad (include/powerkey/behaviour/virtual_keypad.hpp) as a filter: reads the
// frames a controller sends from any log (input.hpp), and writes the frames the keypad sends as
// candump log lines in time order, starting with its boot-up (docs/cli.md, docs/virtual-keypad.md).
// With --j1939 the keypad is a J1939 one from power-on (behaviour/j1939_keypad.hpp), at J1939
// address A (--address, default 21h): no boot-up, its key contact states, heartbeats and answers
// in J1939; every model, the PKP LI ones too (sold as J1939 keypads, no switch back).
//
// Time: the keypad powers on at the first time of the input (0 when it has none); times are
// honoured to the millisecond. A frame without a time comes `untimed_step` after the frame
// before it, so that each request of a log of bare ID#DATA lines meets an idle keypad. A request
// the keypad drops anyway (it came before the keypad answered the one before) is said on
// standard error, with the line of the request not yet answered.
//
// The keypad's clock is a 32-bit millisecond counter (behaviour::millis): a simulation spans at
// most `last_ms` from power-on. A time past it (--press, --release, --until, or a frame of the
// log) is refused, never wrapped: an option is a usage error; a frame is an error naming its
// line, and the simulation ends before it (status 1).
#include "cli.hpp"
#include "commands.hpp"
#include "input.hpp"

#include <powerkey/behaviour/checker.hpp>
#include <powerkey/behaviour/virtual_keypad.hpp>
#include <powerkey/can/candump.hpp>

#include <algorithm>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tool {
namespace {

using namespace powerkey;

// The time between two frames of the input that have no time, in ms: far more than the keypad
// takes to answer a request (keypad_options::sdo_response_ms, 1 ms).
constexpr std::int64_t untimed_step_ms = 10;

// The last millisecond of the keypad's clock: 4294967.295 s after power-on.
constexpr std::uint64_t last_ms = 0xFFFF'FFFFu;

// "4294967.295 s" for messages.
std::string seconds_text(std::uint64_t ms) {
    return std::to_string(ms / 1000) + "." + std::to_string(1000 + ms % 1000).substr(1) + " s";
}

struct simulate_options {
    std::vector<std::string> press, release;  // T:K
    std::string until;                        // T
    bool j1939 = false;                       // the keypad starts in J1939
    std::vector<std::string> files;
};

struct key_event {
    std::uint32_t at_ms;
    unsigned key;
    bool press;
};

struct input_frame {
    std::optional<std::int64_t> us;  // the log's time in microseconds, when the line has one
    can::frame frame;
    std::size_t input;  // index into the labels
    std::size_t line;
};

class collect final : public frame_handler {
public:
    std::vector<input_frame> frames;
    std::vector<std::string> labels;
    std::string interface;  // of the first frame that names one

    void begin(std::size_t, const std::string& label) override { labels.push_back(label); }
    void frame(const logs::record& r) override {
        std::optional<std::int64_t> us;
        if (!r.time.empty()) us = parse_seconds(r.time);
        if (interface.empty() && !r.interface.empty() && r.interface.size() <= 16 &&
            plain(r.interface))
            interface = r.interface;
        frames.push_back({us, r.frame, labels.size() - 1, r.line});
    }
};

int run_simulate(const options& c, const simulate_options& o) {
    std::vector<key_event> keys;
    const auto mi = info(c.keypad).value();
    if (o.j1939 && !behaviour::speaks_j1939(c.keypad))
        return usage_error("--j1939: the virtual " + std::string(to_string(c.keypad)) +
                           " does not speak J1939 (no source shows its J1939 key contact state; "
                           "docs/j1939.md)");
    // --address is where the keypad starts in J1939: only a keypad in J1939 from power-on has
    // one to start at (one switched by the log's 20FFh is at 21h, as the manuals' default).
    if (c.address && !o.j1939)
        return usage_error(
            "--address: the J1939 address the keypad starts at, with --j1939 only (without it "
            "the keypad starts in CANopen; a log's 20FFh switches it to J1939 at 21h)");
    std::optional<behaviour::j1939_source_address> address;
    if (c.address)  // main.cpp took 01h..FDh, 70h's range
        address = behaviour::j1939_source_address::make(*c.address).value();
    for (const auto* list : {&o.press, &o.release}) {
        for (const auto& text : *list) {
            const auto colon = text.find(':');
            const auto t =
                colon == std::string::npos ? std::nullopt : parse_seconds(text.substr(0, colon));
            std::uint64_t k = 0;
            const bool key = colon != std::string::npos && parse_number(text.substr(colon + 1), k);
            const std::string option = list == &o.press ? "--press" : "--release";
            if (!t || !key)
                return usage_error(option + ": expected T:K, seconds and a key (2.5:3), got '" +
                                   escape(text, 32) + "'");
            const auto ms = static_cast<std::uint64_t>((*t + 500) / 1000);
            if (ms > last_ms)
                return usage_error(option + ": " + escape(text.substr(0, colon), 32) +
                                   " s is past the keypad's clock (0.." + seconds_text(last_ms) +
                                   ", 32-bit milliseconds)");
            if (k < 1 || k > mi.keys)
                return usage_error(option + ": a " + std::string(to_string(c.keypad)) +
                                   " has keys 1.." + std::to_string(mi.keys) + ", not " +
                                   std::to_string(k));
            keys.push_back(
                {static_cast<std::uint32_t>(ms), static_cast<unsigned>(k), list == &o.press});
        }
    }
    std::optional<std::int64_t> until;
    if (!o.until.empty()) {
        until = parse_seconds(o.until);
        if (!until)
            return usage_error("--until: expected seconds (2.5), got '" + escape(o.until, 32) +
                               "'");
        if (static_cast<std::uint64_t>(*until / 1000) > last_ms)
            return usage_error("--until: " + escape(o.until, 32) +
                               " s is past the keypad's clock (0.." + seconds_text(last_ms) +
                               ", 32-bit milliseconds)");
    }

    collect in;
    output out;
    input_counts counts;
    read_inputs(o.files, in, out, counts);
    auto& frames = in.frames;

    // Times: the keypad powers on at the first time of the log; a frame without one comes
    // untimed_step_ms after the frame before it; a time that goes back counts as the last one.
    // A frame past the keypad's clock ends the simulation before it.
    std::int64_t origin = 0;
    for (const auto& f : frames)
        if (f.us) {
            origin = *f.us;
            break;
        }
    std::vector<std::uint32_t> at;
    at.reserve(frames.size());
    std::int64_t last = origin;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        if (frames[i].us)
            last = std::max(last, *frames[i].us);
        else if (i > 0)
            last += untimed_step_ms * 1000;
        const auto ms = static_cast<std::uint64_t>((last - origin + 500) / 1000);
        if (ms > last_ms) {
            out.flush();
            report(in.labels[frames[i].input] + ":" + std::to_string(frames[i].line),
                   "this frame comes " + seconds_text(ms) +
                       " after the first, past the keypad's clock (0.." + seconds_text(last_ms) +
                       ", 32-bit milliseconds): the simulation ends before it");
            frames.erase(frames.begin() + static_cast<std::ptrdiff_t>(i), frames.end());
            break;
        }
        at.push_back(static_cast<std::uint32_t>(ms));
    }
    std::stable_sort(keys.begin(), keys.end(),
                     [](const key_event& a, const key_event& b) { return a.at_ms < b.at_ms; });
    std::uint64_t end = 0;
    if (!at.empty()) end = at.back();
    if (!keys.empty()) end = std::max<std::uint64_t>(end, keys.back().at_ms);
    end = std::min(end + 100, last_ms);
    if (until) end = static_cast<std::uint64_t>(*until / 1000);

    const std::string iface = in.interface.empty() ? std::string("can0") : in.interface;
    behaviour::keypad_options ko;
    ko.start_in_j1939 = o.j1939;
    if (address) ko.j1939_address = *address;
    behaviour::virtual_keypad<64> k(c.keypad, c.node, ko);
    // The conversation as a checker sees it, to say which requests the keypad drops.
    behaviour::checker_config cc{.keypad_model = c.keypad, .node = c.node};
    cc.j1939_address = c.address;
    behaviour::checker<> conversation(cc);
    const auto where = [&](std::uint32_t index) {
        const auto& f = frames[index - 1];
        return in.labels[f.input] + ":" + std::to_string(f.line);
    };
    // Dropped requests are notes, not failures, capped per input as problems are.
    std::map<std::size_t, problem_cap> drops;
    const auto check = [&](const can::frame& f, std::uint32_t t, std::uint32_t index) {
        for (const auto& p : conversation.step(f, behaviour::millis{t}, index)) {
            if (p.kind != behaviour::problem_kind::sdo_overlap || index == 0) continue;
            std::string why =
                "the keypad drops this SDO request: the request of " + where(p.detail[0]) + " (";
            append_hex_h(why, p.detail[1], 4);
            why += " sub " + std::to_string(p.detail[2]) + ") is not answered yet";
            out.flush();
            const auto& from = frames[index - 1];
            auto cap = drops.try_emplace(from.input, in.labels[from.input], false).first;
            cap->second.add(from.line, why, {}, false, "the keypad drops an SDO request");
        }
    };
    const auto print = [&](std::uint32_t t) {
        while (const auto f = k.transmit()) {
            check(*f, t, 0);
            const auto us = origin + std::int64_t{t} * 1000;
            char head[48];
            const int n = std::snprintf(head, sizeof head, "(%" PRId64 ".%06" PRId64 ") ",
                                        us / 1'000'000, us % 1'000'000);
            auto& b = out.buffer();
            b.append(head, static_cast<std::size_t>(n));
            b += iface;
            b += ' ';
            b += can::format_candump(*f).view();
            b += '\n';
            out.maybe_flush();
        }
    };
    k.power_on(behaviour::millis{0});
    print(0);
    std::size_t fi = 0, ki = 0;
    // Millisecond by millisecond, skipping those in which nothing happens (no frame, no key, no
    // keypad timer: virtual_keypad::next_due); 64 bits, so that a loop to the clock's last
    // millisecond ends.
    for (std::uint64_t tick = 0; tick <= end;) {
        const auto t = static_cast<std::uint32_t>(tick);
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
            check(frames[fi].frame, t, static_cast<std::uint32_t>(fi + 1));
            k.receive(frames[fi].frame, now);
            ++fi;
        }
        print(t);
        std::uint64_t next = end + 1;
        if (fi < frames.size()) next = std::min<std::uint64_t>(next, at[fi]);
        if (ki < keys.size()) next = std::min<std::uint64_t>(next, keys[ki].at_ms);
        if (const auto due = k.next_due())  // (one already due: the next millisecond)
            next = std::min(
                next,
                tick + (behaviour::before(*due, now) ? 0 : behaviour::elapsed(now, *due).value));
        tick = std::max(next, tick + 1);
    }
    out.flush();
    for (auto& [input, cap] : drops) cap.finish();
    return status();
}

}  // namespace

void add_simulate(registry& r) {
    static simulate_options o;
    auto& sub = r.add(
        {"simulate",
         "--model M [--node N] [--j1939 [--address A]] [--press T:K]\n"
         "  [--release T:K] [--until T] [FILE...]",
         "a virtual keypad answering a controller's frames (docs/virtual-keypad.md)",
         "  --j1939      the keypad is in J1939 from power-on (no boot-up), any model\n"
         "  --press T:K  press key K at T seconds after power-on (repeatable)\n"
         "  --release T:K  release key K at T seconds (repeatable)\n"
         "  --until T    run until T seconds (default: 100 ms after the last input)\n",
         model_use::required, "with --j1939: the keypad's J1939 address, 01h..FDh (default 21h)"},
        [&r] { return run_simulate(r.common(), o); });
    sub.add_option("--press", o.press)->allow_extra_args(false);
    sub.add_option("--release", o.release)->allow_extra_args(false);
    sub.add_option("--until", o.until);
    sub.add_flag("--j1939", o.j1939);
    sub.add_option("FILE", o.files);
}

}  // namespace tool
