// powerkey tool: reading the inputs (input.hpp).
#include "input.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace tool {

std::string file_label(const std::string& path) {
    return path == "-" ? std::string("<stdin>") : escape(path, logs::limits::label_bytes);
}

// --- problem_cap --------------------------------------------------------------------------------

void problem_cap::add(std::size_t line, std::string_view why, std::string_view text, bool hold,
                      std::string_view kind) {
    ++count_;
    if (kind.empty()) kind = why;
    auto it = by_why_.find(kind);
    if (it == by_why_.end()) it = by_why_.emplace(std::string(kind), 0).first;
    if (++it->second > shown_per_kind) {
        if (failures_) ++failures;  // counted, said at the end
        return;
    }
    std::string m = label_;
    if (line != 0) m += (objects_ ? ": object " : ":") + std::to_string(line);
    m += ": ";
    m += why;
    if (!text.empty()) m += ": '" + escape(text, logs::limits::echo_bytes) + "'";
    if (hold) {
        held_.push_back(std::move(m));
        if (failures_) ++failures;
    } else {
        report("", m, failures_);
    }
}

void problem_cap::release() {
    for (const auto& m : held_) report("", m, false);
    held_.clear();
}

std::string problem_cap::first_held() const {
    if (held_.empty()) return {};
    std::string first = held_.front();
    if (first.starts_with(label_ + ":")) first.erase(0, label_.size() + 1);
    if (first.starts_with(" ")) first.erase(0, 1);
    return first;
}

void problem_cap::finish() {
    for (const auto& [why, n] : by_why_)
        if (n > shown_per_kind)
            report(label_,
                   std::to_string(n - shown_per_kind) + " more lines like that (" + why + ")",
                   false);
}

namespace {

// --- one input --------------------------------------------------------------------------------

std::string advice(std::string_view looks) {
    if (looks.find("pcap") != std::string_view::npos)
        return "record the bus with candump -l, or export the capture's CAN frames as a candump "
               "log";
    if (looks.find("MDF") != std::string_view::npos)
        return "export it as Vector ASC or BLF (CANoe, asammdf)";
    if (looks.find("gzip") != std::string_view::npos)
        return "unpack it: zcat FILE | powerkey decode";
    if (looks.find("zip") != std::string_view::npos) return "unpack it first";
    if (looks.find("JSON") != std::string_view::npos)
        return "powerkey encode --json reads JSON lines";
    return "it reads candump and cansend lines, Vector ASC, PEAK TRC, python-can CSV and Vector "
           "BLF";
}

// Turns a reader's findings into the handler's frames and capped messages; holds the first
// problems back until a frame shows that the file is a log.
class input_sink final : public logs::sink {
public:
    input_sink(std::string label, frame_handler& h, output& out)
        : problems_(std::move(label)), handler_(h), out_(out) {}

    void frame(const logs::record& r) override {
        if (!any_frame_) {
            any_frame_ = true;
            out_.flush();
            problems_.release();
        }
        handler_.frame(r);
    }
    void other(const logs::other_record& r) override {
        if (handler_.other(r)) ++used_[static_cast<std::size_t>(r.kind)];
    }
    void problem(std::size_t line, std::string_view why, std::string_view text) override {
        if (any_frame_) out_.flush();
        problems_.count_objects(blf());
        problems_.add(line, why, text, !any_frame_);
    }
    // Said at once, after what was held back: the reader reads no more of this input.
    void stop(std::size_t line, std::string_view why, std::string_view text) override {
        stopped_ = true;
        out_.flush();
        problems_.release();
        problems_.count_objects(blf());
        problems_.add(line, why, text, false, "the reader stopped");
    }
    void watch(const logs::reader& r) { reader_ = &r; }

    // At the end of the input: the notes, or the one message for a file that is no log.
    void finish(const logs::reader& r, input_counts& c) {
        c.bad_lines += problems_.count();
        const auto& label = problems_.label();
        for (std::size_t k = 0; k < logs::skip_kinds; ++k) {
            const auto s = static_cast<logs::skip>(k);
            const auto n = r.skipped(s) - used_[k];
            c.skipped[k] += n;
            if (n == 0) continue;
            out_.flush();
            report(label,
                   std::to_string(n) + " " + std::string(to_string(s)) + (n == 1 ? "" : "s") + " " +
                       std::string(handler_.skipped_note()) + ", the first at " +
                       (blf() ? "object " : "line ") + std::to_string(r.first_skipped(s)),
                   false);
        }
        if (r.detected() == logs::format::not_a_log) {
            out_.flush();
            report(label, "looks like " + r.looks_like() + ", not a CAN log powerkey reads; " +
                              advice(r.looks_like()));
            return;
        }
        // A file of text lines none of which is a frame: one message (it is probably no log).
        // A file of a known form (ASC, TRC, CSV, BLF) says what is wrong with it instead.
        const bool lines =
            r.detected() == logs::format::unknown || r.detected() == logs::format::candump;
        if (!any_frame_ && problems_.count() > 0 && lines && !stopped_) {
            out_.flush();
            const std::string first = problems_.first_held();
            problems_.drop_held();
            report(label,
                   "no line is a CAN frame powerkey reads (line " + first +
                       "); it reads candump and cansend lines, Vector ASC, PEAK TRC, "
                       "python-can CSV and Vector BLF (powerkey help lists the forms)",
                   false);
            return;
        }
        out_.flush();
        problems_.release();
        problems_.finish();
    }

private:
    bool blf() const { return reader_ != nullptr && reader_->detected() == logs::format::blf; }

    problem_cap problems_;
    frame_handler& handler_;
    output& out_;
    const logs::reader* reader_ = nullptr;
    bool any_frame_ = false;
    bool stopped_ = false;
    std::array<std::size_t, logs::skip_kinds> used_{};
};

}  // namespace

namespace {

// Reads one input in 64 KiB blocks: opened() once it is open, then feed(bytes) for each block
// until feed returns false (the reader needs no more) or the input ends; false after reporting
// why it could not be opened.
template <class Opened, class Feed>
bool read_file(const std::string& path, const std::string& label, output& out, Opened&& opened,
               Feed&& feed) {
    const int fd = path == "-" ? 0 : ::open(path.c_str(), O_RDONLY);
    if (fd < 0) {
        out.flush();
        report(label, std::strerror(errno));
        return false;
    }
    opened();
    struct stat st {};
    const bool live = ::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || isatty(1) != 0;
    static std::vector<char> buf(1u << 16);
    for (;;) {
        const auto n = ::read(fd, buf.data(), buf.size());
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            out.flush();
            report(label, std::strerror(errno));
            break;
        }
        if (n == 0) break;
        const bool more = feed(std::string_view(buf.data(), static_cast<std::size_t>(n)));
        if (live) out.flush();
        if (!more) break;
    }
    if (fd != 0) ::close(fd);
    return true;
}

std::vector<std::string> or_stdin(const std::vector<std::string>& paths) {
    if (paths.empty()) return {"-"};
    return paths;
}

}  // namespace

void read_inputs(const std::vector<std::string>& paths, frame_handler& handler, output& out,
                 input_counts& counts) {
    const auto files = or_stdin(paths);
    for (std::size_t i = 0; i < files.size(); ++i) {
        const auto label = file_label(files[i]);
        input_sink sink(label, handler, out);
        logs::reader reader(sink);
        sink.watch(reader);
        if (!read_file(
                files[i], label, out, [&] { handler.begin(i, label); },
                [&](std::string_view b) {
                    reader.feed(b);
                    return !reader.done();
                }))
            continue;
        reader.finish();
        counts.frames += reader.frames();
        sink.finish(reader, counts);
        handler.end(i);
    }
}

void read_lines(
    const std::vector<std::string>& paths, output& out,
    const std::function<void(const std::string&, std::size_t, std::string_view)>& on_line) {
    constexpr std::size_t most = logs::limits::json_line_bytes;
    for (const auto& path : or_stdin(paths)) {
        const auto label = file_label(path);
        std::string carry;
        std::size_t number = 0;
        bool start = true, stopped = false;
        const auto line = [&](std::string_view text) {
            if (start && text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
            start = false;
            if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
            on_line(label, ++number, text);
        };
        // A line past the limit: its beginning quoted, the rest of the input not read.
        const auto too_long = [&](std::string_view rest) {
            carry.append(rest.substr(0, logs::limits::echo_bytes + 1));
            out.flush();
            report(label + ":" + std::to_string(number + 1),
                   "a line longer than " + std::to_string(most) +
                       " bytes, the limit of a JSON line (the rest of the input is not read): '" +
                       escape(carry, logs::limits::echo_bytes) + "'");
            carry.clear();
            stopped = true;
            return false;
        };
        read_file(
            path, label, out, [] {},
            [&](std::string_view data) {
                while (!data.empty()) {
                    const auto nl = data.find('\n');
                    if (nl == std::string_view::npos) {
                        if (carry.size() + data.size() > most) return too_long(data);
                        carry.append(data);
                        break;
                    }
                    if (carry.size() + nl > most) return too_long(data.substr(0, nl));
                    if (carry.empty()) {
                        line(data.substr(0, nl));
                    } else {
                        carry.append(data.substr(0, nl));
                        line(carry);
                        carry.clear();
                    }
                    data.remove_prefix(nl + 1);
                }
                return true;
            });
        if (!carry.empty() && !stopped) line(carry);
    }
}

}  // namespace tool
