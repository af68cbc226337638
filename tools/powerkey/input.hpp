// powerkey tool: the one way every subcommand reads its inputs. Files in order (`-` or none:
// standard input, named <stdin> in messages), each through one log reader (log_formats.hpp, every
// log form told apart by content), with one way of reporting what is wrong in them:
//   - a file that cannot be opened or read: its system error, status 1, the next file is read;
//   - a line that should be a frame and is not: FILE:LINE: WHY: 'the line' (escaped, cut), at most
//     `shown_per_kind` lines of each kind per file, then "N more lines like that";
//   - a file in which no line is a frame, or that is no log at all: one message saying so;
//   - a limit of logs::limits hit, or a file damaged past reading on: one message naming the
//     file, the line or object and the limit, shown at once; the rest of the file is not read;
//   - remote, CAN FD and error frames: one note per kind and file, with the count.
// Live inputs (pipes, terminals) are read as the bytes come and the output is flushed after each
// read, so that a line per frame appears as the frame arrives.
#ifndef POWERKEY_TOOL_INPUT_HPP
#define POWERKEY_TOOL_INPUT_HPP

#include "common.hpp"
#include "log_formats.hpp"

#include <array>
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace tool {

// Problems of one input, reported as "powerkey: LABEL:LINE: WHY[: 'TEXT']" (in a BLF file
// "LABEL: object N: ..."): at most shown_per_kind of each WHY (a constant phrase), the others
// counted and said at the end. Lines can be held back until the input proves to be a log (a file
// of only bad lines gets one message). TEXT is escaped and cut to logs::limits::echo_bytes.
class problem_cap {
public:
    static constexpr std::size_t shown_per_kind = 3;

    // `count_failures`: whether the problems make the exit status 1 (false for notes on what is
    // not wrong in the input, such as the requests a simulated keypad drops).
    explicit problem_cap(std::string label, bool count_failures = true)
        : label_(std::move(label)), failures_(count_failures) {}

    // A problem at `line` (0: none): `why`, then `text` (untrusted, escaped here) when not empty.
    // Problems are capped per `kind` (default: why).
    void add(std::size_t line, std::string_view why, std::string_view text, bool hold = false,
             std::string_view kind = {});
    // Prints what was held back.
    void release();
    // The first held message (without the label), for a one-line summary of a file.
    [[nodiscard]] std::string first_held() const;
    void drop_held() { held_.clear(); }
    // Whether the numbers are objects of a BLF file rather than lines.
    void count_objects(bool objects) noexcept { objects_ = objects; }
    // "N more lines like that (WHY)" for every kind over the cap.
    void finish();

    [[nodiscard]] std::size_t count() const noexcept { return count_; }
    [[nodiscard]] const std::string& label() const noexcept { return label_; }

private:
    std::string label_;
    bool failures_;
    bool objects_ = false;
    std::size_t count_ = 0;
    std::map<std::string, std::size_t, std::less<>> by_why_;
    std::vector<std::string> held_;
};

struct input_counts {
    std::size_t frames = 0;
    std::size_t bad_lines = 0;
    std::array<std::size_t, logs::skip_kinds> skipped{};
};

// What a subcommand does with the frames of its inputs.
class frame_handler {
public:
    virtual ~frame_handler() = default;
    virtual void begin(std::size_t /*input*/, const std::string& /*label*/) {}
    virtual void frame(const logs::record& r) = 0;
    // A remote or CAN FD frame; true when the handler uses it (then it is not noted as skipped).
    virtual bool other(const logs::other_record&) { return false; }
    // What the note on frames passed over says they were not.
    [[nodiscard]] virtual std::string_view skipped_note() const {
        return "not decoded (not supported by powerkey)";
    }
    virtual void end(std::size_t /*input*/) {}
};

// Reads every input in order into `handler`. `out` is flushed before any message (so messages
// and output keep their order) and after every read of a live input.
void read_inputs(const std::vector<std::string>& paths, frame_handler& handler, output& out,
                 input_counts& counts);

// Reads every input in order as text lines (JSON lines for encode --json): on_line(label,
// number, text) per line, without its line end; a UTF-8 byte-order mark is dropped. Files that
// cannot be read are reported as read_inputs reports them; a line longer than
// logs::limits::json_line_bytes is reported (its beginning quoted) and ends its input. `out` as
// for read_inputs.
void read_lines(
    const std::vector<std::string>& paths, output& out,
    const std::function<void(const std::string&, std::size_t, std::string_view)>& on_line);

// The label of an input in messages: the path escaped, or <stdin> for `-`.
std::string file_label(const std::string& path);

}  // namespace tool

#endif
