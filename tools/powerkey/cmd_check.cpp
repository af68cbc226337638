// powerkey check: the bus-log checker (include/powerkey/behaviour/checker.hpp) on any log.
//
//   powerkey check --model M [--node N] [--json] [--sdo-timeout MS] [--heartbeat MS]
//                  [--key-period MS] [FILE...]
//
// Checks each log on its own (`-` or no file: standard input), read like every input
// (input.hpp); a frame without a time keeps the time of the frame before it. It prints one line
// per problem, in line order, starting with the input line number:
//
//   12: sdo_overlap: SDO request sent while the request of line 11 (2003h/1) is unanswered: ...
//
// (with several files, `FILE:LINE: ...`), or with --json one object per line:
//   {"line":12,"kind":"sdo_overlap","detail":[11,8195,1],"text":"SDO request sent ..."}
// Exit status: 0 no problem, 1 a problem found or an input that could not be read, 2 usage.
#include "cli.hpp"
#include "commands.hpp"
#include "input.hpp"
#include "json_writer.hpp"

#include <powerkey/behaviour/checker.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tool {
namespace {

namespace pb = powerkey::behaviour;

struct check_options {
    bool json = false;
    std::string sdo_timeout, heartbeat, key_period;  // ms
    std::vector<std::string> files;
};

// Each input on its own: its own time, its own keypad state; the problems printed at its end,
// in line order.
class check_handler final : public frame_handler {
public:
    check_handler(const pb::checker_config& config, bool json,
                  const std::vector<std::string>& files, output& out)
        : config_(config), json_(json), files_(files), several_(files.size() > 1), out_(out) {}

    void begin(std::size_t input, const std::string& label) override {
        label_ = label;
        // JSON gets the name itself, escaped by the JSON writer (the label is escaped for text).
        path_ = input < files_.size() && files_[input] != "-" ? files_[input] : "<stdin>";
        checker_.emplace(config_);
        now_ = 0;
        problems_.clear();
    }
    void frame(const logs::record& r) override {
        // The time in ms, wrapping like a firmware counter (the checker's millis).
        if (!r.time.empty())
            if (const auto us = parse_seconds(r.time))
                now_ = static_cast<std::uint32_t>(static_cast<std::uint64_t>(*us) / 1000);
        for (const auto& p :
             checker_->step(r.frame, pb::millis{now_}, static_cast<std::uint32_t>(r.line)))
            problems_.push_back(p);
    }
    void end(std::size_t) override {
        // The end of the log: what is still unanswered there.
        for (const auto& p : checker_->finish(pb::millis{now_})) problems_.push_back(p);
        std::stable_sort(
            problems_.begin(), problems_.end(),
            [](const pb::problem& a, const pb::problem& b) { return a.line < b.line; });
        for (const auto& p : problems_) print(p);
        found_ += problems_.size();
        out_.flush();
    }
    [[nodiscard]] std::size_t found() const noexcept { return found_; }

private:
    void print(const pb::problem& p) {
        std::array<char, 200> buf{};
        const auto t = pb::explain(p, buf);
        const std::string_view text = t ? *t : std::string_view(buf.data(), buf.size());
        const auto kind = powerkey::to_string(p.kind);
        auto& b = out_.buffer();
        if (json_) {
            json::object_writer w(b);
            if (several_) w.field("file", path_);
            w.field("line", p.line);
            w.field("kind", kind);
            w.key("detail");
            b += '[';
            for (std::size_t i = 0; i < p.detail.size(); ++i) {
                if (i > 0) b += ',';
                append_decimal(b, p.detail[i]);
            }
            b += ']';
            w.field("text", text);
            w.close();
        } else {
            if (several_) b += label_ + ":";
            append_decimal(b, p.line);
            b += ": ";
            b += kind;
            b += ": ";
            b += text;
        }
        b += '\n';
    }

    pb::checker_config config_;
    bool json_;
    const std::vector<std::string>& files_;
    bool several_;
    std::string path_;
    output& out_;
    std::string label_;
    std::optional<pb::checker<>> checker_;
    std::uint32_t now_ = 0;
    std::vector<pb::problem> problems_;
    std::size_t found_ = 0;
};

int run_check(const options& c, const check_options& o) {
    pb::checker_config config;
    config.keypad_model = c.keypad;
    config.node = c.node;
    for (const auto& [name, text, into] :
         {std::tuple{"--sdo-timeout", &o.sdo_timeout, &config.sdo_timeout},
          std::tuple{"--heartbeat", &o.heartbeat, &config.heartbeat_period},
          std::tuple{"--key-period", &o.key_period, &config.key_state_period}}) {
        if (text->empty()) continue;
        std::uint64_t n = 0;
        if (!parse_number(*text, n) || n > 0xFFFF'FFFFu)
            return usage_error(std::string(name) + ": expected milliseconds (200), got '" +
                               escape(*text, 32) + "'");
        *into = pb::duration_ms{static_cast<std::uint32_t>(n)};
    }
    output out;
    input_counts counts;
    check_handler handler(config, o.json, o.files, out);
    read_inputs(o.files, handler, out, counts);
    out.flush();
    return handler.found() > 0 ? status_input : status();
}

}  // namespace

void add_check(registry& r) {
    static check_options o;
    auto& sub =
        r.add({"check",
               "--model M [--node N] [--json] [--sdo-timeout MS] [--heartbeat MS]\n"
               "  [--key-period MS] [FILE...]",
               "a bus log checked against the keypad's rules (docs/controller.md)",
               "  --json       one JSON object per problem\n"
               "  --sdo-timeout MS  a request unanswered this long is sdo_no_reply (default 200)\n"
               "  --heartbeat MS, --key-period MS  the periods set before the log starts\n",
               model_use::required},
              [&r] { return run_check(r.common(), o); });
    sub.add_flag("--json", o.json);
    sub.add_option("--sdo-timeout", o.sdo_timeout);
    sub.add_option("--heartbeat", o.heartbeat);
    sub.add_option("--key-period", o.key_period);
    sub.add_option("FILE", o.files);
}

}  // namespace tool
