// powerkey tool: every bus-log form people have, told apart by their content, read into CAN
// frames. The readers know nothing of keypads: they give a frame, its time and interface as
// written (or computed, for the binary and millisecond forms) and the line it came from.
//
//   candump     (1700000000.000000) can0 195#0900000012 [R|T]   candump -l / -L, python-can,
//   asc2log
//               195#09.00.00.00.12                               cansend arguments (dots allowed)
//               (1700000000.000000)  can0  RX - -  195   [5]  09 00 00 00 12  '.....'
//                                            candump's screen form, with -t, -x and -a
//   asc         Vector ASC (CANoe, python-can, can-utils log2asc, also its -f CANFD form)
//   trc         PEAK TRC 1.0 to 1.3 and 2.0/2.1 (PCAN-View, python-can)
//   csv         python-can CSV (timestamp,arbitration_id,extended,remote,error,dlc,data)
//   blf         Vector BLF, objects CAN_MESSAGE/CAN_MESSAGE2/CAN_FD_MESSAGE(_64) in plain or zlib
//               compressed log containers
//
// Remote frames, CAN FD frames and error frames are valid log content the codec cannot decode;
// they are counted by kind (`skipped`), not reported per line, and remote and CAN FD frames are
// handed to the sink as far as the log gives them (`powerkey convert` writes them on).
//
// Untrusted input is bounded here: `limits` holds every cap the readers apply.
#ifndef POWERKEY_TOOL_LOG_FORMATS_HPP
#define POWERKEY_TOOL_LOG_FORMATS_HPP

#include <powerkey/can/frame.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tool::logs {

enum class format : std::uint8_t { unknown, candump, asc, trc, csv, blf, not_a_log };

[[nodiscard]] std::string_view to_string(format f) noexcept;

struct record {
    powerkey::can::frame frame;
    std::string_view time;       // seconds; empty when the log has none. Valid in the call only.
    std::string_view interface;  // empty when the log has none. Valid in the call only.
    std::size_t line = 0;        // line of a text log, object number of a BLF file
};

// What a reader passes over without a frame.
enum class skip : std::uint8_t { remote, fd, error_frame };
inline constexpr std::size_t skip_kinds = 3;
[[nodiscard]] std::string_view to_string(skip s) noexcept;

// A remote or CAN FD frame, as far as the log gives it.
struct other_record {
    skip kind = skip::remote;
    std::uint32_t id = 0;
    bool extended = false;
    std::uint8_t length = 0;             // remote: the length it asks for; CAN FD: data bytes
    std::span<const std::uint8_t> data;  // CAN FD: 0..64 bytes. Valid in the call only.
    bool bit_rate_switch = false;        // CAN FD: BRS, when the log says
    std::string_view time;               // as in record
    std::string_view interface;
    std::size_t line = 0;
};

// The caps on what untrusted input can make the tool hold or do: one place, so that each limit has
// one home (docs/security.md says what happens when each is hit). A reader that hits one stops
// reading its input and says so (sink::stop): an error naming the file, the line or object and
// the limit; the exit status is then 1.
struct limits {
    // A line of a text log (candump, ASC, TRC, CSV). The longest lines real writers make (an ASC
    // CAN FD line of 64 bytes, a TRC header) are under 1 KiB; a longer line is no log line.
    static constexpr std::size_t text_line_bytes = 64u << 10;
    // A JSON line of encode --json: decode --json writes lines of at most about 2 KiB.
    static constexpr std::size_t json_line_bytes = 64u << 10;
    // How deep the brackets of a JSON line may nest before nlohmann/json parses it (its parser
    // recurses): decode --json lines nest 2 deep. A deeper line is a bad line, not a stop.
    static constexpr std::size_t json_depth = 4;
    // The bytes of the first line in which a NUL makes the input a binary file (not a text log).
    static constexpr std::size_t binary_sniff_bytes = 512;
    // A BLF file header (the writers' is 144 bytes).
    static constexpr std::uint32_t blf_header_bytes = 4096;
    // A BLF log container is unpacked into memory: writers use about 128 KiB.
    static constexpr std::uint32_t blf_container_bytes = 16u << 20;
    // A BLF object at the top level of the file: a container with its packed data (zlib may make
    // incompressible data a little larger), or an object outside any container.
    static constexpr std::uint32_t blf_object_bytes = blf_container_bytes + (64u << 10);
    // An object inside a container, and so the unfinished object at the end of a container that
    // is carried into the next one (writers split objects across containers). CAN messages are
    // under 100 bytes; the largest objects writers put in containers are a few KiB.
    static constexpr std::uint32_t blf_tail_bytes = 1u << 20;
    // Containers inside containers: no writer nests them, and each level would keep a copy of
    // its data; a container found inside a container is refused.
    static constexpr unsigned blf_container_depth = 1;
    // What decode --model auto keeps of the frames it reads to choose the model before it
    // decodes them (a frame with its time and interface takes about 70 bytes, so about 900,000
    // frames): past that, the model is chosen from these frames, and the rest of the input is
    // decoded as it comes.
    static constexpr std::size_t model_auto_bytes = 64u << 20;
    // What an error message quotes of a line or value from the input (escaped, then "...").
    static constexpr std::size_t echo_bytes = 60;
    // What a message shows of a file name (escaped, then "...").
    static constexpr std::size_t label_bytes = 200;
};

// Receives what a reader finds. `problem` is a line that should have been a frame and is not:
// `why` is one short phrase (a constant), `text` the line (untrusted: escape before printing).
class sink {
public:
    virtual ~sink() = default;
    virtual void frame(const record& r) = 0;
    virtual void problem(std::size_t line, std::string_view why, std::string_view text) = 0;
    // A remote or CAN FD frame (already counted in skipped()); most sinks ignore them.
    virtual void other(const other_record&) {}
    // The reader stops reading this input: a limit was hit, or the input is damaged past
    // reading on (a BLF object without its signature). `line` as for problem (0: the file).
    virtual void stop(std::size_t line, std::string_view why, std::string_view text) {
        problem(line, why, text);
    }
};

// One input stream. Feed it the bytes in any chunks; finish() at the end.
class reader {
public:
    explicit reader(sink& out) : out_(out) {}
    void feed(std::string_view bytes);
    void finish();
    // True once the reader needs no more input: it stopped (sink::stop), or the input is no log.
    // The caller may stop reading then; finish() is still to be called.
    [[nodiscard]] bool done() const noexcept { return stopped_ || format_ == format::not_a_log; }

    [[nodiscard]] format detected() const noexcept { return format_; }
    [[nodiscard]] std::size_t frames() const noexcept { return frames_; }
    [[nodiscard]] std::size_t problems() const noexcept { return problems_; }
    [[nodiscard]] std::size_t skipped(skip s) const noexcept {
        return skipped_[static_cast<std::size_t>(s)];
    }
    [[nodiscard]] std::size_t first_skipped(skip s) const noexcept {
        return first_skipped_[static_cast<std::size_t>(s)];
    }
    // For a stream with no frames: what its first lines or bytes look like, as a phrase that
    // follows "looks like" (e.g. "a pcap capture"); empty when it looks like nothing known.
    [[nodiscard]] const std::string& looks_like() const noexcept { return looks_like_; }

private:
    void start();
    void text_feed(std::string_view bytes);
    void too_long(std::string_view rest);
    void line(std::string_view text);
    bool detect_binary(std::string_view first_bytes);
    void detect(std::string_view first);
    void candump_line(std::string_view s);
    bool candump_fast(std::string_view s);
    void asc_line(std::string_view s);
    void trc_line(std::string_view s);
    void csv_line(std::string_view s);
    void blf_feed(std::string_view bytes);
    void blf_objects(std::string_view data, bool top, bool final, std::size_t& used);
    void blf_object(std::string_view obj, std::uint32_t type, bool top);
    void emit(const powerkey::can::frame& f, std::string_view time, std::string_view interface);
    void emit_raw(std::uint32_t id, bool extended, std::span<const std::uint8_t> data,
                  std::string_view time, std::string_view interface);
    void skip_one(skip s);
    void other(skip s, std::uint32_t id, bool extended, std::size_t length,
               std::span<const std::uint8_t> data, std::string_view time,
               std::string_view interface, bool brs = false);
    void bad(std::string_view why, std::string_view text);
    void stop(std::size_t line, std::string_view why, std::string_view text = {});

    sink& out_;
    format format_ = format::unknown;
    std::string carry_;
    std::size_t line_ = 0;
    bool started_ = false;
    bool sniffed_ = false;  // the first line was looked at for NUL bytes
    bool stopped_ = false;
    std::string stop_why_;
    std::size_t frames_ = 0;
    std::size_t problems_ = 0;
    std::array<std::size_t, skip_kinds> skipped_{};
    std::array<std::size_t, skip_kinds> first_skipped_{};
    std::string looks_like_;
    std::string time_buf_;
    std::string iface_buf_;
    // ASC
    bool asc_decimal_ = false;
    // TRC: the column letters of a data line (N O T B I d R L l D), from the version or $COLUMNS
    std::string trc_columns_ = "NOILD";
    bool trc_v1_ = true;
    // CSV: column positions
    std::array<int, 7> csv_col_{0, 1, 2, 3, 4, 5, 6};
    // BLF
    std::string blf_in_;
    std::string blf_inner_;
    bool blf_header_done_ = false;
    double blf_start_ = 0;
};

// Helpers shared with the tests.
[[nodiscard]] bool base64_decode(std::string_view in, std::vector<std::uint8_t>& out);

}  // namespace tool::logs

#endif
