// What the log-reader fuzz targets share (log_candump, log_asc, log_trc, log_csv, log_blf): the
// tool's one log reader (tools/powerkey/log_formats.hpp) fed the same bytes whole and in chunks
// of sizes drawn from the input, and what it reports compared. Properties, each from
// docs/security.md:
//   - the same frames, problems and stops whatever the chunks (the form is told by content);
//   - nothing is reported after a stop, and done() says so;
//   - the counts (frames(), problems()) are what the sink saw;
//   - each frame is a CAN frame (0..8 bytes), each remote or CAN FD frame at most 64 bytes, each
//     time and interface no longer than a log line may be (limits::text_line_bytes);
//   - line and object numbers never go back, and a text input's name no line past its last;
//   - memory stays within the caps of logs::limits (libFuzzer's -rss_limit_mb,
//   fuzz/CMakeLists.txt).
#ifndef POWERKEY_FUZZ_LOG_READER_HPP
#define POWERKEY_FUZZ_LOG_READER_HPP

#include "fuzz.hpp"

#include "../tools/powerkey/log_formats.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace powerkey_fuzz {

namespace logs = tool::logs;

// Writes down everything a reader reports, one string each, and checks what each report can be.
class recorder final : public logs::sink {
public:
    std::vector<std::string> seen;
    std::size_t frames = 0, problems = 0;
    bool stopped = false;

    void frame(const logs::record& r) override {
        POWERKEY_FUZZ_CHECK_FRAME(!stopped, r.frame);
        POWERKEY_FUZZ_CHECK_FRAME(r.frame.size() <= 8, r.frame);
        text(r.time);
        text(r.interface);
        number(r.line);
        ++frames;
        seen.push_back("F " + std::string(can::format_candump(r.frame).view()) + " " +
                       std::string(r.time) + " " + std::string(r.interface) + " " +
                       std::to_string(r.line));
    }
    void problem(std::size_t line, std::string_view why, std::string_view text_) override {
        POWERKEY_FUZZ_CHECK(!stopped);
        POWERKEY_FUZZ_CHECK(!why.empty());
        text(text_);
        problem_line(line);
        ++problems;
        seen.push_back("P " + std::to_string(line) + " " + std::string(why) + " " +
                       std::string(text_));
    }
    void other(const logs::other_record& r) override {
        POWERKEY_FUZZ_CHECK(!stopped);
        POWERKEY_FUZZ_CHECK(r.length <= 64 && r.data.size() <= 64);
        POWERKEY_FUZZ_CHECK(r.extended ? r.id <= 0x1FFF'FFFFu : r.id <= 0x7FFu);
        text(r.time);
        text(r.interface);
        number(r.line);
        seen.push_back("O " + std::to_string(static_cast<int>(r.kind)) + " " +
                       std::to_string(r.id) + " " + std::to_string(r.length) + " " +
                       std::string(reinterpret_cast<const char*>(r.data.data()), r.data.size()) +
                       " " + std::string(r.time) + " " + std::to_string(r.line));
    }
    void stop(std::size_t line, std::string_view why, std::string_view text_) override {
        POWERKEY_FUZZ_CHECK(!stopped);
        POWERKEY_FUZZ_CHECK(!why.empty());
        text(text_);
        problem_line(line);
        stopped = true;
        ++problems;
        seen.push_back("S " + std::to_string(line) + " " + std::string(why) + " " +
                       std::string(text_));
    }

    // The most a line number can be: the lines of a text input (its line ends + 1).
    std::size_t max_line = static_cast<std::size_t>(-1);

private:
    static void text(std::string_view s) {
        POWERKEY_FUZZ_CHECK(s.size() <= logs::limits::text_line_bytes);
    }
    // Line and object numbers never go back, and name no line past the input's.
    void number(std::size_t line) {
        POWERKEY_FUZZ_CHECK(line >= last_ && line <= max_line);
        last_ = line;
    }
    // A problem: the same, but 0 (the file itself) may come anywhere.
    void problem_line(std::size_t line) {
        if (line != 0) number(line);
    }
    std::size_t last_ = 0;
};

struct reading {
    std::vector<std::string> seen;
    std::size_t frames, problems;
    bool done;
    logs::format form;
};

// The whole input at once, or in pieces of 1..`most` bytes drawn from `seed` (a fixed
// sequence, so that a failing input fails again). Bytes keep coming after done(): the reader
// must ignore them.
inline reading read(std::string_view bytes, std::uint32_t seed, std::size_t most,
                    std::size_t max_line) {
    recorder r;
    r.max_line = max_line;
    logs::reader reader(r);
    if (most == 0) {
        reader.feed(bytes);
    } else {
        std::uint32_t s = seed | 1u;
        while (!bytes.empty()) {
            s = s * 1664525u + 1013904223u;  // Numerical Recipes' LCG
            const std::size_t n = 1 + (s >> 8) % most;
            const auto piece = bytes.substr(0, n);
            reader.feed(piece);
            bytes.remove_prefix(piece.size());
        }
    }
    const bool done_before_finish = reader.done();
    reader.finish();
    POWERKEY_FUZZ_CHECK(r.stopped ==
                        (reader.done() && reader.detected() != logs::format::not_a_log));
    if (done_before_finish) POWERKEY_FUZZ_CHECK(reader.done());
    POWERKEY_FUZZ_CHECK(reader.frames() == r.frames);
    POWERKEY_FUZZ_CHECK(reader.problems() == r.problems);
    return {std::move(r.seen), r.frames, r.problems, reader.done(), reader.detected()};
}

// The properties above, for one input (`text`: the lines are counted for the line check).
inline void check_reader(std::string_view bytes, bool text) {
    std::size_t max_line = static_cast<std::size_t>(-1);
    if (text) {
        max_line = 1;
        for (const char c : bytes) max_line += c == '\n' ? 1 : 0;
    }
    const auto whole = read(bytes, 0, 0, max_line);
    std::uint32_t seed = 2166136261u;  // FNV-1a of the input: the chunks differ per input
    for (const char c : bytes.substr(0, 64))
        seed = (seed ^ static_cast<unsigned char>(c)) * 16777619u;
    for (const std::size_t most : {std::size_t{1}, std::size_t{7}, std::size_t{700}}) {
        const auto pieces = read(bytes, seed + static_cast<std::uint32_t>(most), most, max_line);
        POWERKEY_FUZZ_CHECK(pieces.form == whole.form);
        POWERKEY_FUZZ_CHECK(pieces.frames == whole.frames);
        POWERKEY_FUZZ_CHECK(pieces.problems == whole.problems);
        POWERKEY_FUZZ_CHECK(pieces.done == whole.done);
        POWERKEY_FUZZ_CHECK(pieces.seen == whole.seen);
    }
}

// A text target: `prefix` (what makes the reader take the form) and then the fuzzer's bytes.
inline int check_text(std::string_view prefix, const std::uint8_t* data, std::size_t size) {
    std::string bytes(prefix);
    bytes.append(reinterpret_cast<const char*>(data), size);
    check_reader(bytes, !bytes.starts_with("LOGG"));  // a BLF file counts objects
    return 0;
}

}  // namespace powerkey_fuzz

#endif
