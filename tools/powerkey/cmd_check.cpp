// powerkey check: the bus-log checker (include/powerkey/behaviour/checker.hpp) on any log.
//
//   powerkey check --model M [--node N] [--address A] [--json] [--junit FILE] [--sdo-timeout MS]
//                  [--heartbeat MS] [--key-period MS] [FILE...]
//
// Checks each log on its own (`-` or no file: standard input), read like every input
// (input.hpp); a frame without a time keeps the time of the frame before it. It prints one line
// per problem or warning, in line order, starting with the input line number; a warning says so:
//
//   12: sdo_overlap: SDO request sent while the request of line 11 (2003h/1) is unanswered: ...
//   14: warning: not_manual_form: frame 615h of 6 bytes is trimmed, not the manual's form: ...
//
// (with several files, `FILE:LINE: ...`). The first three warnings of a kind are printed, then
// one line counts them all: `warnings: not_manual_form 57 (3 shown; --json lists each)`.
// With --json one object per problem and per warning:
//   {"line":12,"severity":"problem","kind":"sdo_overlap","detail":[11,8195,1],"text":"..."}
// --junit FILE also writes a JUnit XML report: a test suite per log, a test case per kind, a
// failure per problem, the warnings in their test case's system-out.
// Exit status: 0 no problem (warnings do not count), 1 a problem found or an input that could not
// be read, 2 usage.
#include "cli.hpp"
#include "commands.hpp"
#include "input.hpp"
#include "json_writer.hpp"

#include <powerkey/behaviour/checker.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tool {
namespace {

namespace pb = powerkey::behaviour;

struct check_options {
    bool json = false;
    std::string junit;                               // --junit FILE
    std::string sdo_timeout, heartbeat, key_period;  // ms
    std::vector<std::string> files;
};

// Warnings of one kind printed in text before the count stands for the rest.
constexpr std::size_t warnings_shown = 3;
// Failures of one kind a JUnit test case lists; the rest are counted in its system-out.
constexpr std::size_t junit_failures_listed = 1000;

// What the checker found in one log, for the JUnit report.
struct log_report {
    std::string name;  // the path as given (escaped by the XML writer), <stdin> for `-`
    std::vector<pb::problem> found;
    std::array<std::uint32_t, pb::problem_kind_count> counts{};
    std::vector<std::string> texts;  // the text of each of `found`
    bool unreadable = false;         // some of it could not be read (reported on stderr)
    std::size_t input = 0;           // its position among the inputs
};

// The text of p as printed: the library's explanation, and for wrong_model what to try.
std::string text_of(const pb::problem& p) {
    std::array<char, 200> buf{};
    const auto t = pb::explain(p, buf);
    std::string text(t ? *t : std::string_view(buf.data(), buf.size()));
    if (p.kind == pb::problem_kind::wrong_model)
        text += "; powerkey decode --model auto names the model that reads the log";
    return text;
}

// --- JUnit XML ----------------------------------------------------------------------------------

// s as XML character data or attribute value: the five markup characters as entities, control
// characters (which XML 1.0 cannot carry) and bytes above 7Eh as \xHH, at most `max` characters.
void append_xml(std::string& out, std::string_view s, std::size_t max = 4096) {
    const bool cut = s.size() > max;
    if (cut) s = s.substr(0, max);
    for (const char c : s) {
        const auto u = static_cast<unsigned char>(c);
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default:
                if (u < 0x20 || u >= 0x7F)
                    append_hex_escape(out, u);
                else
                    out += c;
        }
    }
    if (cut) out += "...";
}

void append_attribute(std::string& out, std::string_view name, std::string_view value) {
    out += ' ';
    out += name;
    out += "=\"";
    append_xml(out, value, 256);
    out += '"';
}

// One test suite per log; in it one test case per kind the checker checks (problem_kinds), with a
// failure per problem of that kind (its line and reason), the warnings of a warning kind in its
// system-out, and the count of each warning kind as a property. A log that could not be read
// wholly adds an `input` test case with an error.
std::string junit_xml(const std::vector<log_report>& logs, const pb::checker_config& config) {
    std::string body;
    std::size_t all_tests = 0, all_failures = 0, all_errors = 0;
    for (const auto& log : logs) {
        std::string cases;
        std::size_t tests = 0, failures = 0, errors = 0;
        for (const auto& info : pb::problem_kinds) {
            ++tests;
            const auto kind = powerkey::to_string(info.kind);
            cases += "    <testcase";
            append_attribute(cases, "classname", "powerkey.check");
            append_attribute(cases, "name", kind);
            std::string inner;  // the failures
            std::string out;    // system-out
            std::size_t listed = 0;
            for (std::size_t i = 0; i < log.found.size(); ++i) {
                const auto& p = log.found[i];
                if (p.kind != info.kind) continue;
                std::string line = "line " + std::to_string(p.line) + ": " + log.texts[i];
                if (info.severity == pb::severity::warning) {
                    if (listed++ < junit_failures_listed) {
                        append_xml(out, line);
                        out += '\n';
                    }
                    continue;
                }
                if (listed++ >= junit_failures_listed) continue;
                ++failures;
                inner += "      <failure";
                append_attribute(inner, "type", kind);
                append_attribute(inner, "message", line);
                inner += '>';
                append_xml(inner, line);
                inner += "</failure>\n";
            }
            const auto total = log.counts[static_cast<std::size_t>(info.kind)];
            if (total > junit_failures_listed)
                out += std::to_string(total - junit_failures_listed) + " more not listed\n";
            if (!out.empty()) inner += "      <system-out>" + out + "</system-out>\n";
            cases += inner.empty() ? "/>\n" : ">\n" + inner + "    </testcase>\n";
        }
        if (log.unreadable) {
            ++tests;
            ++errors;
            cases += "    <testcase classname=\"powerkey.check\" name=\"input\">\n";
            cases +=
                "      <error type=\"input\" message=\"some of the log could not be read "
                "(powerkey check's standard error says what)\"/>\n";
            cases += "    </testcase>\n";
        }
        body += "  <testsuite";
        append_attribute(body, "name", log.name);
        append_attribute(body, "tests", std::to_string(tests));
        append_attribute(body, "failures", std::to_string(failures));
        append_attribute(body, "errors", std::to_string(errors));
        append_attribute(body, "skipped", "0");
        body += ">\n    <properties>\n";
        auto property = [&body](std::string_view name, std::string_view value) {
            body += "      <property";
            append_attribute(body, "name", name);
            append_attribute(body, "value", value);
            body += "/>\n";
        };
        property("model", powerkey::to_string(config.keypad_model));
        std::string node;
        append_hex_h(node, config.node.value(), 2);
        property("node", node);
        for (const auto& info : pb::problem_kinds)
            if (info.severity == pb::severity::warning)
                property("warnings." + std::string(powerkey::to_string(info.kind)),
                         std::to_string(log.counts[static_cast<std::size_t>(info.kind)]));
        body += "    </properties>\n" + cases + "  </testsuite>\n";
        all_tests += tests;
        all_failures += failures;
        all_errors += errors;
    }
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites";
    append_attribute(xml, "name", "powerkey check");
    append_attribute(xml, "tests", std::to_string(all_tests));
    append_attribute(xml, "failures", std::to_string(all_failures));
    append_attribute(xml, "errors", std::to_string(all_errors));
    xml += ">\n" + body + "</testsuites>\n";
    return xml;
}

// --- the logs
// -------------------------------------------------------------------------------------

// Each input on its own: its own time, its own keypad state; the problems and warnings printed at
// its end, in line order.
class check_handler final : public frame_handler {
public:
    check_handler(const pb::checker_config& config, bool json, bool junit,
                  const std::vector<std::string>& files, output& out)
        : config_(config),
          json_(json),
          junit_(junit),
          files_(files),
          several_(files.size() > 1),
          out_(out) {}

    void begin(std::size_t input, const std::string& label) override {
        label_ = label;
        // JSON gets the name itself, escaped by the JSON writer (the label is escaped for text).
        path_ = input < files_.size() && files_[input] != "-" ? files_[input] : "<stdin>";
        checker_.emplace(config_);
        now_ = 0;
        problems_.clear();
        kept_ = {};
        failures_before_ = failures;
    }
    void frame(const logs::record& r) override {
        // The time in ms, wrapping like a firmware counter (the checker's millis).
        if (!r.time.empty())
            if (const auto us = parse_seconds(r.time))
                now_ = static_cast<std::uint32_t>(static_cast<std::uint64_t>(*us) / 1000);
        for (const auto& p :
             checker_->step(r.frame, pb::millis{now_}, static_cast<std::uint32_t>(r.line)))
            keep(p);
    }
    void end(std::size_t input) override {
        // The end of the log: what is still unanswered there, and whether the model fits.
        for (const auto& p : checker_->finish(pb::millis{now_})) keep(p);
        std::stable_sort(
            problems_.begin(), problems_.end(),
            [](const pb::problem& a, const pb::problem& b) { return a.line < b.line; });
        std::array<std::size_t, pb::problem_kind_count> printed{};
        log_report report;
        for (const auto& p : problems_) {
            const auto k = static_cast<std::size_t>(p.kind);
            const bool warning = pb::severity_of(p.kind) == pb::severity::warning;
            if (!warning) ++found_;
            std::string text = text_of(p);
            if (json_ || !warning || printed[k]++ < warnings_shown) print(p, text);
            if (junit_) report.texts.push_back(std::move(text));
        }
        if (!json_) counts_line();
        if (junit_) {
            report.name = path_;
            report.found = problems_;
            for (std::size_t k = 0; k < pb::problem_kind_count; ++k)
                report.counts[k] = checker_->count(static_cast<pb::problem_kind>(k));
            report.unreadable = failures != failures_before_;
            report.input = input;
            reports_.push_back(std::move(report));
        }
        out_.flush();
    }
    [[nodiscard]] std::size_t found() const noexcept { return found_; }
    [[nodiscard]] const std::vector<log_report>& reports() const noexcept { return reports_; }

private:
    // Problems are all kept; warnings only as many of a kind as an output shows (JSON: all), so
    // that a log of a million trimmed frames costs no memory in text or JUnit (the checker counts
    // them).
    void keep(const pb::problem& p) {
        auto& n = kept_[static_cast<std::size_t>(p.kind) % pb::problem_kind_count];
        const std::size_t most = junit_ ? junit_failures_listed : warnings_shown;
        if (pb::severity_of(p.kind) == pb::severity::warning && !json_ && n >= most) return;
        ++n;
        problems_.push_back(p);
    }

    void print(const pb::problem& p, const std::string& text) {
        const auto kind = powerkey::to_string(p.kind);
        const auto severity = powerkey::to_string(pb::severity_of(p.kind));
        auto& b = out_.buffer();
        if (json_) {
            json::object_writer w(b);
            if (several_) w.field("file", path_);
            w.field("line", p.line);
            w.field("severity", severity);
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
            if (pb::severity_of(p.kind) == pb::severity::warning) b += "warning: ";
            b += kind;
            b += ": ";
            b += text;
        }
        b += '\n';
    }

    // "warnings: not_manual_form 57 (3 shown; --json lists each)": every warning kind found.
    void counts_line() {
        std::string line;
        bool cut = false;
        for (const auto& info : pb::problem_kinds) {
            if (info.severity != pb::severity::warning) continue;
            const auto n = checker_->count(info.kind);
            if (n == 0) continue;
            line += line.empty() ? "" : ", ";
            line += powerkey::to_string(info.kind);
            line += ' ';
            append_decimal(line, n);
            cut = cut || n > warnings_shown;
        }
        if (line.empty()) return;
        auto& b = out_.buffer();
        if (several_) b += label_ + ": ";
        b += "warnings: " + line;
        if (cut) b += " (" + std::to_string(warnings_shown) + " of each shown; --json lists each)";
        b += '\n';
    }

    pb::checker_config config_;
    bool json_;
    bool junit_;
    const std::vector<std::string>& files_;
    bool several_;
    std::string path_;
    output& out_;
    std::string label_;
    std::optional<pb::checker<>> checker_;
    std::uint32_t now_ = 0;
    std::vector<pb::problem> problems_;
    std::array<std::size_t, pb::problem_kind_count> kept_{};
    std::size_t found_ = 0;
    int failures_before_ = 0;
    std::vector<log_report> reports_;
};

// Writes `text` to `path`; false (reported) when it cannot.
bool write_file(const std::string& path, const std::string& text) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) {
        report(file_label(path), std::strerror(errno));
        return false;
    }
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    const int saved = errno;
    if (std::fclose(f) != 0 || !ok) {
        report(file_label(path), std::strerror(ok ? errno : saved));
        return false;
    }
    return true;
}

int run_check(const options& c, const check_options& o) {
    pb::checker_config config;
    config.keypad_model = c.keypad;
    config.node = c.node;
    config.j1939_address = c.address;
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
    check_handler handler(config, o.json, !o.junit.empty(), o.files, out);
    read_inputs(o.files, handler, out, counts);
    out.flush();
    if (!o.junit.empty()) {
        // Every input has its suite: one that could not be opened or read to its end (no end())
        // has an empty one with the `input` error.
        const auto n = o.files.empty() ? std::size_t{1} : o.files.size();
        std::vector<log_report> all(n);
        for (std::size_t i = 0; i < n; ++i) {
            all[i].name = i < o.files.size() && o.files[i] != "-" ? o.files[i] : "<stdin>";
            all[i].unreadable = true;
        }
        for (const auto& r : handler.reports())
            if (r.input < n) all[r.input] = r;
        if (!write_file(o.junit, junit_xml(all, config))) return status_input;
    }
    return handler.found() > 0 ? status_input : status();
}

}  // namespace

void add_check(registry& r) {
    static check_options o;
    auto& sub =
        r.add({"check",
               "--model M [--node N] [--address A] [--json] [--junit FILE] [--sdo-timeout MS]\n"
               "  [--heartbeat MS] [--key-period MS] [FILE...]",
               "a bus log checked against the keypad's rules (docs/checker.md)",
               "  --json       one JSON object per problem and per warning\n"
               "  --junit FILE also write a JUnit XML report (a test case per kind checked)\n"
               "  --sdo-timeout MS  a request unanswered this long is sdo_no_reply (default 200)\n"
               "  --heartbeat MS, --key-period MS  the periods set before the log starts\n"
               "  Warnings (frames not in the manual's form) do not make the exit status 1.\n",
               model_use::required},
              [&r] { return run_check(r.common(), o); });
    sub.add_flag("--json", o.json);
    sub.add_option("--junit", o.junit);
    sub.add_option("--sdo-timeout", o.sdo_timeout);
    sub.add_option("--heartbeat", o.heartbeat);
    sub.add_option("--key-period", o.key_period);
    sub.add_option("FILE", o.files);
}

}  // namespace tool
