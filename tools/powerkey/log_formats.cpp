// powerkey tool: the log readers (log_formats.hpp). Written from the formats as their writers
// produce them (candump and log2asc of can-utils 2020.11, python-can 4.1's writers, PEAK's TRC
// file format document 1.0-2.1), and tested against files those writers make at test time
// (tests/test_tool_log_formats.sh).
#include "log_formats.hpp"

#include "numbers.hpp"

#include <zlib.h>

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

namespace tool::logs {
namespace {

using powerkey::can::frame;

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() &&
           (s.back() == ' ' || s.back() == '\t' || s.back() == '\r' || s.back() == '\n'))
        s.remove_suffix(1);
    return s;
}

// The next word of s (words are split by spaces and tabs), taken off s; `hash` is where its
// first '#' is (npos: none), found in the same pass. Called a few times for every line: always
// inlined.
[[gnu::always_inline]] inline std::string_view next_token(std::string_view& s, std::size_t& hash) {
    std::size_t i = 0;
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    std::size_t n = i;
    hash = std::string_view::npos;
    for (; n < s.size(); ++n) {
        const char c = s[n];
        if (c == ' ' || c == '\t') break;
        if (c == '#' && hash == std::string_view::npos) hash = n - i;
    }
    const auto t = s.substr(i, n - i);
    s.remove_prefix(n);
    return t;
}
[[gnu::always_inline]] inline std::string_view next_token(std::string_view& s) {
    std::size_t hash = 0;
    return next_token(s, hash);
}

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

// "1)" then a number: a TRC 1.x data line (a file without its ";" header).
bool trc_numbered(std::string_view s) {
    std::size_t i = 0;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return i > 0 && i + 1 < s.size() && s[i] == ')' && (s[i + 1] == ' ' || s[i + 1] == '\t');
}

// candump's error-frame flag in a 32-bit identifier (linux/can.h CAN_ERR_FLAG).
constexpr std::uint32_t can_err_flag = 0x2000'0000;

std::uint16_t le16(std::string_view d, std::size_t at) {
    return static_cast<std::uint16_t>(static_cast<unsigned char>(d[at]) |
                                      (static_cast<unsigned char>(d[at + 1]) << 8));
}
std::uint32_t le32(std::string_view d, std::size_t at) {
    return static_cast<std::uint32_t>(le16(d, at)) |
           (static_cast<std::uint32_t>(le16(d, at + 2)) << 16);
}
std::uint64_t le64(std::string_view d, std::size_t at) {
    return static_cast<std::uint64_t>(le32(d, at)) |
           (static_cast<std::uint64_t>(le32(d, at + 4)) << 32);
}
constexpr std::size_t blf_base_header = 16;  // "LOBJ", header size, version, object size, type

}  // namespace

std::string_view to_string(format f) noexcept {
    switch (f) {
        case format::unknown: return "unknown";
        case format::candump: return "candump";
        case format::asc: return "Vector ASC";
        case format::trc: return "PEAK TRC";
        case format::csv: return "python-can CSV";
        case format::blf: return "Vector BLF";
        case format::not_a_log: return "not a log";
    }
    return "unknown";
}

std::string_view to_string(skip s) noexcept {
    switch (s) {
        case skip::remote: return "remote frame";
        case skip::fd: return "CAN FD frame";
        case skip::error_frame: return "error frame";
    }
    return "frame";
}

bool base64_decode(std::string_view in, std::vector<std::uint8_t>& out) {
    out.clear();
    std::uint32_t acc = 0;
    int bits = 0;
    for (char c : in) {
        int v = 0;
        if (c >= 'A' && c <= 'Z')
            v = c - 'A';
        else if (c >= 'a' && c <= 'z')
            v = c - 'a' + 26;
        else if (c >= '0' && c <= '9')
            v = c - '0' + 52;
        else if (c == '+')
            v = 62;
        else if (c == '/')
            v = 63;
        else if (c == '=')
            break;
        else
            return false;
        acc = ((acc << 6) | static_cast<std::uint32_t>(v)) & 0xFFFFFFu;
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(static_cast<std::uint8_t>(acc >> bits));
        }
    }
    return true;
}

// --- the stream ---------------------------------------------------------------------------------

namespace {

// The first bytes that decide a form before any line is read: the binary forms' signatures, and
// the UTF-8 byte-order mark. The reader waits until the bytes it has can no longer begin one of
// them (or until 8 bytes), so that the form it finds does not depend on how the input arrives.
constexpr std::string_view signatures[] = {
    "LOGG",
    "\xD4\xC3\xB2\xA1",
    "\xA1\xB2\xC3\xD4",
    "\x4D\x3C\xB2\xA1",
    "\xA1\xB2\x3C\x4D",
    std::string_view("\x0A\x0D\x0D\x0A", 4),
    "MDF     ",
    "UnFinMF",
    "\x1F\x8B",
    "PK\x03\x04",
    "\xEF\xBB\xBF",
};
constexpr std::size_t longest_signature = 8;

// Whether `first` is a proper beginning of a signature (more bytes could complete it).
bool may_begin_signature(std::string_view first) {
    for (const auto sig : signatures)
        if (first.size() < sig.size() && sig.substr(0, first.size()) == first) return true;
    return false;
}

}  // namespace

void reader::feed(std::string_view bytes) {
    if (done()) return;
    if (!started_) {
        carry_.append(bytes);  // the first bytes, until the form can be told
        if (carry_.size() < longest_signature && may_begin_signature(carry_)) return;
        return start();
    }
    if (format_ == format::blf) return blf_feed(bytes);
    text_feed(bytes);
}

// The form, from the first bytes (carry_), then those bytes read in that form.
void reader::start() {
    started_ = true;
    std::string all = std::move(carry_);
    carry_.clear();
    std::string_view v = all;
    if (starts_with(v, "LOGG")) {
        format_ = format::blf;
        return blf_feed(v);
    }
    if (detect_binary(v)) return;
    if (starts_with(v, "\xEF\xBB\xBF")) v.remove_prefix(3);  // UTF-8 byte-order mark
    text_feed(v);
}

void reader::text_feed(std::string_view bytes) {
    while (!bytes.empty() && !done()) {
        const auto nl = bytes.find('\n');
        if (nl == std::string_view::npos) {
            if (carry_.size() + bytes.size() > limits::text_line_bytes) return too_long(bytes);
            carry_.append(bytes);
            return;
        }
        if (carry_.size() + nl > limits::text_line_bytes) return too_long(bytes.substr(0, nl));
        if (!carry_.empty()) {
            carry_.append(bytes.substr(0, nl));
            const std::string whole = std::move(carry_);
            carry_.clear();
            line(whole);
        } else {
            line(bytes.substr(0, nl));
        }
        bytes.remove_prefix(nl + 1);
    }
}

// A line past limits::text_line_bytes (carry_, then `rest`): no log has one. Its beginning is
// quoted and the input is read no further.
void reader::too_long(std::string_view rest) {
    // The line's first binary_sniff_bytes, however much of it was carried: the same text
    // whatever pieces the input came in.
    std::string start = std::move(carry_);
    carry_.clear();
    if (start.size() < limits::binary_sniff_bytes)
        start.append(rest.substr(0, limits::binary_sniff_bytes - start.size()));
    else
        start.resize(limits::binary_sniff_bytes);
    if (!sniffed_) {  // the first line: a binary file says so first
        sniffed_ = true;
        if (start.substr(0, limits::binary_sniff_bytes).find('\0') != std::string::npos) {
            format_ = format::not_a_log;
            looks_like_ = "a binary file that is not Vector BLF";
            return;
        }
    }
    stop(line_ + 1,
         "a line longer than " + std::to_string(limits::text_line_bytes) +
             " bytes, the limit of a log line (the rest of the input is not read)",
         start);
}

void reader::finish() {
    if (!started_) start();
    if (stopped_ || format_ == format::not_a_log) return;
    if (format_ == format::blf) {
        if (!blf_header_done_) return stop(0, "the BLF file ends inside its header (truncated?)");
        std::size_t used = 0;
        blf_objects(blf_in_, true, true, used);
        if (stopped_) return;
        if (used + 4 <= blf_in_.size())
            return stop(line_ + 1, "the BLF file ends inside this object (truncated?)");
        blf_in_.clear();
        // The last container's unfinished object (padding is at most 3 bytes).
        if (blf_inner_.size() >= 4)
            stop(line_ + 1,
                 "the BLF file ends inside this object, in its last container (truncated?)");
        blf_inner_.clear();
        return;
    }
    if (!carry_.empty()) {
        const std::string rest = std::move(carry_);
        carry_.clear();
        line(rest);
    }
}

void reader::emit(const frame& f, std::string_view time, std::string_view interface) {
    ++frames_;
    out_.frame(record{f, time, interface, line_});
}

void reader::emit_raw(std::uint32_t id, bool extended, std::span<const std::uint8_t> data,
                      std::string_view time, std::string_view interface) {
    powerkey::can::payload p{};
    const std::size_t n = data.size() < 8 ? data.size() : 8;
    for (std::size_t i = 0; i < n; ++i) p[i] = data[i];
    const auto length = powerkey::can::dlc::make(n).value();
    if (extended) {
        const auto i = powerkey::can::extended_id::make(id);
        if (!i) return bad("identifier out of range", "");
        emit(frame(*i, length, p), time, interface);
    } else {
        const auto i = powerkey::can::standard_id::make(id);
        if (!i) return bad("identifier out of range", "");
        emit(frame(*i, length, p), time, interface);
    }
}

void reader::skip_one(skip s) {
    const auto i = static_cast<std::size_t>(s);
    if (skipped_[i]++ == 0) first_skipped_[i] = line_;
}

void reader::other(skip s, std::uint32_t id, bool extended, std::size_t length,
                   std::span<const std::uint8_t> data, std::string_view time,
                   std::string_view interface, bool brs) {
    skip_one(s);
    if (extended ? id > 0x1FFF'FFFFu : id > 0x7FFu) return;  // counted, not passed on
    if (length > 64 || data.size() > 64) return;
    out_.other(other_record{s, id, extended, static_cast<std::uint8_t>(length), data, brs, time,
                            interface, line_});
}

void reader::bad(std::string_view why, std::string_view text) {
    ++problems_;
    out_.problem(line_, why, text);
}

void reader::stop(std::size_t line, std::string_view why, std::string_view text) {
    ++problems_;
    stopped_ = true;
    stop_why_ = why;  // `why` may be built for the message: the sink sees a stable copy
    out_.stop(line, stop_why_, text);
}

void reader::line(std::string_view text) {
    if (!sniffed_) {  // a NUL in the first line: a binary file, whichever way it arrives
        sniffed_ = true;
        if (text.substr(0, limits::binary_sniff_bytes).find('\0') != std::string_view::npos) {
            format_ = format::not_a_log;
            looks_like_ = "a binary file that is not Vector BLF";
            return;
        }
    }
    ++line_;
    const auto s = trim(text);
    if (s.empty()) return;
    if (format_ == format::unknown) {
        detect(s);
        if (format_ == format::not_a_log) return;
    }
    switch (format_) {
        case format::asc: return asc_line(s);
        case format::trc: return trc_line(s);
        case format::csv: return csv_line(s);
        default: return candump_line(s);
    }
}

// The forms that are no text, by their signatures (before any line is split: a pcapng file
// begins with a line feed).
bool reader::detect_binary(std::string_view s) {
    auto other = [&](std::string_view what) {
        format_ = format::not_a_log;
        looks_like_ = what;
        return true;
    };
    if (starts_with(s, "\xD4\xC3\xB2\xA1") || starts_with(s, "\xA1\xB2\xC3\xD4") ||
        starts_with(s, "\x4D\x3C\xB2\xA1") || starts_with(s, "\xA1\xB2\x3C\x4D"))
        return other("a pcap capture");
    if (starts_with(s, std::string_view("\x0A\x0D\x0D\x0A", 4))) return other("a pcapng capture");
    if (starts_with(s, "MDF     ") || starts_with(s, "UnFinMF"))
        return other("an ASAM MDF (MF4) measurement file");
    if (starts_with(s, "\x1F\x8B")) return other("a gzip-compressed file");
    if (starts_with(s, "PK\x03\x04")) return other("a zip archive");
    return false;  // a NUL in the first line says binary too (line())
}

void reader::detect(std::string_view s) {
    auto other = [&](std::string_view what) {
        format_ = format::not_a_log;
        looks_like_ = what;
    };
    if (starts_with(s, "date ") || starts_with(s, "base hex") || starts_with(s, "base dec") ||
        starts_with(s, "Begin Triggerblock") || starts_with(s, "// version")) {
        format_ = format::asc;
    } else if (s.front() == ';' || trc_numbered(s)) {
        format_ = format::trc;
    } else if (starts_with(s, "timestamp,")) {
        format_ = format::csv;
    } else if (s.front() == '{') {
        other("JSON lines (the output of powerkey decode --json?)");
    } else {
        format_ = format::candump;
    }
}

// --- candump, cansend and candump's screen form
// ---------------------------------------------------

// The form of nearly every line of a large log, candump -l's "(SECONDS) IFACE ID#DATA" (a 3- or
// 8-digit id, hex pairs, nothing after), read in one pass. Anything else, or anything odd, is
// left to candump_line's general way (false), which reads these lines the same.
bool reader::candump_fast(std::string_view s) {
    const std::size_t n = s.size();
    std::size_t i = 1;  // s[0] is '('
    std::size_t whole = 0, fraction = 0;
    bool point = false;
    for (; i < n; ++i) {
        const char c = s[i];
        if (c >= '0' && c <= '9')
            ++(point ? fraction : whole);
        else if (c == '.' && !point)
            point = true;
        else
            break;
    }
    if (i + 1 >= n || s[i] != ')' || s[i + 1] != ' ' || whole + fraction == 0 || whole > 12)
        return false;
    const auto time = s.substr(1, i - 1);
    i += 2;
    const std::size_t interface_at = i;
    while (i < n && s[i] != ' ' && s[i] != '\t' && s[i] != '#') ++i;
    if (i >= n || s[i] != ' ' || i == interface_at) return false;
    const auto interface = s.substr(interface_at, i - interface_at);
    const std::size_t id_at = ++i;
    std::uint32_t id = 0;
    for (int d = 0; i < n && (d = hex_digit(s[i])) >= 0; ++i)
        id = (id << 4) | static_cast<std::uint32_t>(d);
    const std::size_t digits = i - id_at;
    if (i >= n || s[i] != '#' || (digits != 3 && digits != 8)) return false;
    const bool extended = digits == 8;
    if (extended ? id > 0x1FFF'FFFFu : id > 0x7FFu) return false;  // error frames, bad ids
    ++i;
    std::array<std::uint8_t, 8> data{};
    std::size_t k = 0;
    for (; i + 1 < n && k < data.size(); i += 2) {
        const int hi = hex_digit(s[i]);
        const int lo = hex_digit(s[i + 1]);
        if (hi < 0 || lo < 0) break;
        data[k++] = static_cast<std::uint8_t>((hi << 4) | lo);
    }
    if (i != n) return false;  // a direction, dots, an odd digit, a ninth byte, R, #...
    emit_raw(id, extended, {data.data(), k}, time, interface);
    return true;
}

void reader::candump_line(std::string_view s) {
    if (s.front() == '(' && candump_fast(s)) return;
    if (s.front() == '#' || starts_with(s, "//")) return;
    const auto whole = s;
    std::string_view time;
    if (s.front() == '(') {
        const auto close = s.find(')');
        if (close == std::string_view::npos) return bad("unclosed timestamp", whole);
        time = trim(s.substr(1, close - 1));
        if (!is_seconds(time))
            return bad("malformed timestamp (expected seconds like 1700000000.000000)", whole);
        s.remove_prefix(close + 1);
    }
    std::string_view rest = s;
    std::size_t hash = 0;  // where the '#' of the frame's word is
    const std::string_view first = next_token(rest, hash);
    std::string_view interface;
    std::string_view frame_text;
    if (hash != std::string_view::npos) {
        frame_text = first;  // cansend form, maybe after a timestamp
    } else {
        interface = first;
        std::string_view second = next_token(rest, hash);
        if (hash != std::string_view::npos) {
            frame_text = second;  // candump -l / -L form
        } else {
            // The screen form: [RX|TX flag flag] ID [len] bytes... ['ascii'] or "remote request"
            if (second == "RX" || second == "TX") {  // candump -x: direction, BRS and ESI flags
                next_token(rest);
                next_token(rest);
                second = next_token(rest);
            }
            const std::string_view len = next_token(rest);
            std::uint32_t id = 0;
            if (len.size() < 3 || len.front() != '[' || len.back() != ']' ||
                !parse_digits(second, id))
                return bad("not a frame (expected ID#DATA or a candump line)", whole);
            if (second.size() != 3 && second.size() != 8)
                return bad("identifier of other than 3 or 8 hex digits", whole);
            std::uint32_t count = 0;
            if (!parse_digits(len.substr(1, len.size() - 2), count, 10))
                return bad("the [length] is not a number", whole);
            const bool extended = second.size() == 8;
            if (extended && (id & can_err_flag) != 0) return skip_one(skip::error_frame);
            // CAN FD: candump prints its length with two digits ([08], [64])
            const bool fd = count > 8 || len.size() == 4;
            const std::size_t most = fd ? 64 : 8;
            std::array<std::uint8_t, 64> data{};
            std::size_t n = 0;
            for (auto b = next_token(rest); !b.empty(); b = next_token(rest)) {
                if (b == "remote") {
                    if (fd || count > 8) return bad("a remote frame of more than 8 bytes", whole);
                    return other(skip::remote, id, extended, count, {}, time, interface);
                }
                if (b.front() == '\'' || b == "ERRORFRAME") break;  // -a text, -e marker
                if (b.size() != 2 || hex_digit(b[0]) < 0 || hex_digit(b[1]) < 0)
                    return bad("data bytes must be two hex digits each", whole);
                if (n == most) return bad("more data bytes than a CAN frame holds", whole);
                data[n++] = static_cast<std::uint8_t>((hex_digit(b[0]) << 4) | hex_digit(b[1]));
            }
            if (n != count) return bad("the [length] does not match the data bytes", whole);
            if (!extended && id > 0x7FF) return bad("identifier out of range", whole);
            if (extended && id > 0x1FFF'FFFF) return bad("identifier out of range", whole);
            if (fd) return other(skip::fd, id, extended, n, {data.data(), n}, time, interface);
            return emit_raw(id, extended, {data.data(), n}, time, interface);
        }
    }
    // ID#DATA, then maybe the direction python-can and asc2log write (R or T).
    const auto after = next_token(rest);
    if (!after.empty() && !((after == "R" || after == "T") && trim(rest).empty()))
        return bad("unexpected text after the frame", whole);
    const auto id_text = frame_text.substr(0, hash);
    std::string_view data_text = frame_text.substr(hash + 1);
    std::uint32_t id = 0;
    if (!parse_digits(id_text, id)) return bad("malformed frame (expected ID#DATA)", whole);
    if (id_text.size() != 3 && id_text.size() != 8)
        return bad("identifier of other than 3 or 8 hex digits", whole);
    const bool extended = id_text.size() == 8;
    if (extended && (id & can_err_flag) != 0) return skip_one(skip::error_frame);
    if (!extended && id > 0x7FF) return bad("identifier out of range", whole);
    if (extended && id > 0x1FFF'FFFF) return bad("identifier out of range", whole);
    // ID#R and ID#R5: a remote frame, with the length it asks for (can-utils lib.c)
    if (!data_text.empty() && (data_text.front() == 'R' || data_text.front() == 'r')) {
        const int asked = data_text.size() == 2 ? hex_digit(data_text[1]) : 0;
        if (data_text.size() > 2 || asked < 0 || asked > 8)
            return bad("malformed remote frame (expected ID#R or ID#R and a length 0..8)", whole);
        return other(skip::remote, id, extended, static_cast<std::size_t>(asked), {}, time,
                     interface);
    }
    // ID##FDATA: CAN FD, F the flags digit (1: bit-rate switch, 2: error state indicator)
    const bool fd = !data_text.empty() && data_text.front() == '#';
    int fd_flags = 0;
    if (fd) {
        fd_flags = data_text.size() > 1 ? hex_digit(data_text[1]) : -1;
        if (fd_flags < 0) return bad("malformed CAN FD frame (expected ID##FLAGS DATA)", whole);
        data_text.remove_prefix(2);
    }
    const std::size_t most = fd ? 64 : 8;
    std::array<std::uint8_t, 64> data{};
    std::size_t n = 0;
    for (std::size_t i = 0; i < data_text.size();) {
        if (data_text[i] == '.') {  // cansend's 01.02.03
            ++i;
            continue;
        }
        if (i + 1 >= data_text.size()) return bad("odd number of hex digits in the data", whole);
        const int hi = hex_digit(data_text[i]);
        const int lo = hex_digit(data_text[i + 1]);
        if (hi < 0 || lo < 0) return bad("malformed frame (expected ID#DATA)", whole);
        if (n == most) return bad(fd ? "more than 64 data bytes" : "more than 8 data bytes", whole);
        data[n++] = static_cast<std::uint8_t>((hi << 4) | lo);
        i += 2;
    }
    if (fd)
        return other(skip::fd, id, extended, n, {data.data(), n}, time, interface,
                     (fd_flags & 1) != 0);
    emit_raw(id, extended, {data.data(), n}, time, interface);
}

// --- Vector ASC
// -----------------------------------------------------------------------------------

void reader::asc_line(std::string_view s) {
    if (starts_with(s, "base ")) {
        asc_decimal_ = s.find("base dec") != std::string_view::npos;
        return;
    }
    std::string_view rest = s;
    const auto time = next_token(rest);
    if (time.empty() || time.front() < '0' || time.front() > '9') return;  // header, comments
    if (!is_seconds(time)) return bad("malformed ASC line (time)", s);
    auto channel = next_token(rest);
    const int base = asc_decimal_ ? 10 : 16;
    auto interface_of = [this](std::string_view ch) -> std::string_view {
        std::uint32_t n = 0;
        if (!parse_digits(ch, n, 10) || n == 0) return ch;
        iface_buf_ = "can" + std::to_string(n - 1);  // ASC channels count from 1, SocketCAN from 0
        return iface_buf_;
    };
    auto parse_id = [&](std::string_view t, std::uint32_t& id, bool& extended) {
        extended = !t.empty() && (t.back() == 'x' || t.back() == 'X');
        if (extended) t.remove_suffix(1);
        return parse_digits(t, id, base);
    };
    std::array<std::uint8_t, 64> data{};
    auto parse_bytes = [&](std::string_view& r, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
            std::uint32_t b = 0;
            if (!parse_digits(next_token(r), b, base) || b > 255) return false;
            data[i] = static_cast<std::uint8_t>(b);
        }
        return true;
    };
    if (channel == "CANFD") {
        // time CANFD channel dir id [name] brs esi dlc length data... duration bits flags crc ...
        channel = next_token(rest);
        next_token(rest);  // Rx / Tx
        std::uint32_t id = 0;
        bool extended = false;
        if (!parse_id(next_token(rest), id, extended))
            return bad("malformed ASC CANFD line (identifier)", s);
        auto brs = next_token(rest);
        if (brs != "0" && brs != "1") brs = next_token(rest);  // a symbolic name came first
        next_token(rest);                                      // esi
        std::uint32_t dlc = 0;
        if (!parse_digits(next_token(rest), dlc, 16) || dlc > 15)
            return bad("malformed ASC CANFD line (dlc)", s);
        std::uint32_t length = 0;
        if (!parse_digits(next_token(rest), length, 10) || length > 64)
            return bad("malformed ASC CANFD line (length)", s);
        if (!parse_bytes(rest, length)) return bad("malformed ASC CANFD line (data)", s);
        next_token(rest);  // message duration
        next_token(rest);  // bit count
        std::uint32_t flags = 0;
        if (!parse_digits(next_token(rest), flags))
            return bad("malformed ASC CANFD line (flags)", s);
        const auto iface = interface_of(channel);
        if ((flags & 0x1000u) != 0 || length > 8)  // EDL
            return other(skip::fd, id, extended, length, {data.data(), length}, time, iface,
                         brs == "1");
        if ((flags & 0x10u) != 0)
            return other(skip::remote, id, extended, dlc > 8 ? 8 : dlc, {}, time, iface);
        return emit_raw(id, extended, {data.data(), length}, time, iface);
    }
    const auto id_text = next_token(rest);
    if (id_text == "ErrorFrame") return skip_one(skip::error_frame);
    std::uint32_t id = 0;
    bool extended = false;
    if (!parse_id(id_text, id, extended)) return;  // statistics, events, markers ...
    const auto dir = next_token(rest);
    if (dir != "Rx" && dir != "Tx" && dir != "TxRq") return;
    const auto type = next_token(rest);
    if (type != "d" && type != "r")
        return bad("malformed ASC line (expected d or r after the direction)", s);
    std::uint32_t dlc = 0;
    if (!parse_digits(next_token(rest), dlc, 16) || dlc > 15)
        return bad("malformed ASC line (length)", s);
    if (type == "r")
        return other(skip::remote, id, extended, dlc > 8 ? 8 : dlc, {}, time,
                     interface_of(channel));
    const std::size_t n = dlc > 8 ? 8 : dlc;
    if (!parse_bytes(rest, n)) return bad("malformed ASC line (data)", s);
    emit_raw(id, extended, {data.data(), n}, time, interface_of(channel));
}

// --- PEAK TRC
// -------------------------------------------------------------------------------------

// The column letters of PEAK's TRC file format document: N number, O time offset, T type, B bus,
// I identifier, d direction, R reserved, L DLC, l length, D data bytes.
constexpr std::string_view trc_letters = "NOTBIdRLlD";

void reader::trc_line(std::string_view s) {
    if (s.front() == ';') {
        if (starts_with(s, ";$FILEVERSION=")) {
            const auto v = trim(s.substr(14));
            trc_v1_ = starts_with(v, "1.");
            trc_columns_ = v == "1.0"   ? "NOILD"
                           : v == "1.1" ? "NOTILD"
                           : v == "1.2" ? "NOBTILD"
                           : v == "1.3" ? "NOBTIRLD"
                           : v == "2.0" ? "NOTIdlD"
                           : v == "2.1" ? "NOTBIdRLD"
                                        : "";
            if (trc_columns_.empty())
                return stop(line_,
                            "a TRC file version powerkey does not read (it reads 1.0 to "
                            "1.3, 2.0 and 2.1)",
                            s);
        } else if (starts_with(s, ";$COLUMNS=")) {
            // The letters of trc_letters, separated by commas, each at most once: at most ten
            // columns, whatever the line holds.
            trc_columns_.clear();
            for (std::string_view rest = s.substr(10); !rest.empty();) {
                const auto comma = rest.find(',');
                const auto letter = trim(rest.substr(0, comma));
                rest.remove_prefix(comma == std::string_view::npos ? rest.size() : comma + 1);
                if (letter.size() != 1 || trc_letters.find(letter[0]) == std::string_view::npos ||
                    trc_columns_.find(letter[0]) != std::string::npos) {
                    trc_columns_.clear();
                    break;
                }
                trc_columns_ += letter[0];
            }
            // What a frame needs: its time, identifier, length and data (the data last), and in
            // a 2.x file its type (DT, RR, FD ...).
            const auto has = [this](char c) { return trc_columns_.find(c) != std::string::npos; };
            if (!has('O') || !has('I') || !(has('L') || has('l')) || trc_columns_.back() != 'D' ||
                (!trc_v1_ && !has('T')))
                return stop(line_,
                            "unusable TRC columns (each of N,O,T,B,I,d,R,L,l,D at most "
                            "once; a frame needs O, I, L or l, T in 2.x, and D last)",
                            s);
        }
        return;
    }
    std::string_view rest = s;
    std::string_view time, type, bus, id_text, dlc_text, len_text;
    for (char c : trc_columns_) {
        if (c == 'D') break;
        const auto t = next_token(rest);
        switch (c) {
            case 'O': time = t; break;
            case 'T': type = t; break;
            case 'B': bus = t; break;
            case 'I': id_text = t; break;
            case 'L': dlc_text = t; break;
            case 'l': len_text = t; break;
            default: break;  // N, d, R
        }
    }
    bool remote = false, fd = false, brs = false;
    if (trc_v1_) {
        if (!type.empty() && type != "Rx" && type != "Tx") return skip_one(skip::error_frame);
    } else if (type != "DT") {
        remote = type == "RR";
        fd = type == "FD" || type == "FB" || type == "FE" || type == "BI";  // B: bit-rate switch
        brs = type == "FB" || type == "BI";
        if (type == "ER") return skip_one(skip::error_frame);
        if (!remote && !fd) return;  // status, error counter and event lines
    }
    std::uint32_t id = 0;
    if (!parse_digits(id_text, id)) return bad("malformed TRC line (identifier)", s);
    if (trc_v1_ && trc_columns_ == "NOILD" && id == 0xFFFF'FFFFu) return;  // 1.0 bus information
    std::uint32_t length = 0;
    if (!parse_digits(len_text.empty() ? dlc_text : len_text, length, 10) || length > 64)
        return bad("malformed TRC line (length)", s);
    std::string_view data_rest = rest;
    remote = remote || next_token(data_rest) == "RTR";
    fd = fd || length > 8;
    std::array<std::uint8_t, 64> data{};
    for (std::uint32_t i = 0; !remote && i < length; ++i) {
        std::uint32_t b = 0;
        if (!parse_digits(next_token(rest), b) || b > 255)
            return bad("malformed TRC line (data)", s);
        data[i] = static_cast<std::uint8_t>(b);
    }
    // The offset is in milliseconds: read by the seconds reader, it is in thousandths of us.
    const auto thousandths = parse_seconds(time);
    if (!thousandths) return bad("malformed TRC line (time)", s);
    const long long us = *thousandths / 1000;
    char t[40];
    std::snprintf(t, sizeof t, "%lld.%06lld", us / 1'000'000, us % 1'000'000);
    time_buf_ = t;
    std::string_view interface;
    if (std::uint32_t n = 0; parse_digits(bus, n, 10) && n > 0) {
        iface_buf_ = "can" + std::to_string(n - 1);  // PEAK buses count from 1
        interface = iface_buf_;
    }
    const bool extended = id_text.size() > 4;
    if (remote)
        return other(skip::remote, id, extended, length > 8 ? 8 : length, {}, time_buf_, interface);
    if (fd)
        return other(skip::fd, id, extended, length, {data.data(), length}, time_buf_, interface,
                     brs);
    emit_raw(id, extended, {data.data(), length}, time_buf_, interface);
}

// --- python-can CSV
// -------------------------------------------------------------------------------

void reader::csv_line(std::string_view s) {
    std::array<std::string_view, 16> cells{};
    std::size_t n = 0;
    for (std::string_view r = s; n < cells.size();) {
        const auto comma = r.find(',');
        cells[n++] = trim(r.substr(0, comma));
        if (comma == std::string_view::npos) break;
        r.remove_prefix(comma + 1);
    }
    static constexpr std::string_view names[7] = {
        "timestamp", "arbitration_id", "extended", "remote", "error", "dlc", "data"};
    if (cells[0] == "timestamp") {
        for (std::size_t k = 0; k < 7; ++k) {
            csv_col_[k] = -1;
            for (std::size_t i = 0; i < n; ++i)
                if (cells[i] == names[k]) csv_col_[k] = static_cast<int>(i);
        }
        return;
    }
    auto cell = [&](std::size_t k) -> std::string_view {
        const int i = csv_col_[k];
        return i >= 0 && static_cast<std::size_t>(i) < n ? cells[static_cast<std::size_t>(i)]
                                                         : std::string_view{};
    };
    if (cell(4) == "1") return skip_one(skip::error_frame);
    auto id_text = cell(1);
    std::uint32_t id = 0;
    const bool hex = starts_with(id_text, "0x") || starts_with(id_text, "0X");
    if (hex) id_text.remove_prefix(2);
    if (!parse_digits(id_text, id, hex ? 16 : 10)) return bad("malformed CSV line (identifier)", s);
    const bool extended = cell(2) == "1";
    // python-can writes Python's repr of the float: 1700000000.5, or 5e-05 near 0.
    std::string_view time = cell(0);
    if (!time.empty() && !parse_seconds(time)) {
        double t = -1;  // the whole cell a number: no "abc" read as 0, no nan, no inf
        const auto r = std::from_chars(time.data(), time.data() + time.size(), t);
        if (r.ec != std::errc{} || r.ptr != time.data() + time.size() || !(t >= 0 && t < 1e12))
            return bad("malformed CSV line (timestamp)", s);
        char b[40];
        std::snprintf(b, sizeof b, "%.6f", t);
        time_buf_ = b;
        time = time_buf_;
    }
    if (cell(3) == "1") {
        std::uint32_t dlc = 0;
        if (!cell(5).empty() && (!parse_digits(cell(5), dlc, 10) || dlc > 15))
            return bad("malformed CSV line (dlc)", s);
        return other(skip::remote, id, extended, dlc > 8 ? 8 : dlc, {}, time, {});
    }
    std::vector<std::uint8_t> data;
    if (!base64_decode(cell(6), data)) return bad("malformed CSV line (data is not base64)", s);
    if (data.size() > 64) return bad("malformed CSV line (more than 64 data bytes)", s);
    if (data.size() > 8) return other(skip::fd, id, extended, data.size(), data, time, {});
    emit_raw(id, extended, data, time, {});
}

// --- Vector BLF
// -----------------------------------------------------------------------------------

void reader::blf_feed(std::string_view bytes) {
    if (stopped_) return;
    blf_in_.append(bytes);
    std::size_t pos = 0;
    if (!blf_header_done_) {
        if (blf_in_.size() < 8) return;
        const std::uint32_t header_size = le32(blf_in_, 4);
        if (header_size < 8 || header_size > limits::blf_header_bytes)
            return stop(0, "the BLF file header has an impossible size (" +
                               std::to_string(header_size) + " bytes; the limit is " +
                               std::to_string(limits::blf_header_bytes) + ")");
        if (blf_in_.size() < header_size) return;
        if (header_size >= 56 && le16(blf_in_, 40) >= 1970) {  // start: a SYSTEMTIME at byte 40
            std::tm t{};
            t.tm_year = le16(blf_in_, 40) - 1900;
            t.tm_mon = le16(blf_in_, 42) - 1;
            t.tm_mday = le16(blf_in_, 46);
            t.tm_hour = le16(blf_in_, 48);
            t.tm_min = le16(blf_in_, 50);
            t.tm_sec = le16(blf_in_, 52);
            blf_start_ = static_cast<double>(timegm(&t)) + le16(blf_in_, 54) / 1000.0;
        }
        blf_header_done_ = true;
        pos = header_size;
    }
    std::size_t used = 0;
    blf_objects(std::string_view(blf_in_).substr(pos), true, false, used);
    if (stopped_) return blf_in_.clear();
    blf_in_.erase(0, pos + used);
}

// Walks the objects of `data` (the file's top level, or a container's unpacked data); `used`
// says how far the complete ones reach. Objects are numbered in the order they come, those inside
// a container included (line_).
void reader::blf_objects(std::string_view data, bool top, bool final, std::size_t& used) {
    std::size_t pos = 0;
    used = 0;
    for (;;) {
        if (stopped_) return;
        // Objects are padded to 4 bytes (inside containers not always): find the next signature.
        std::size_t at = pos;
        bool found = false;
        for (; at < pos + 8 && at + 4 <= data.size(); ++at)
            if (data.substr(at, 4) == "LOBJ") {
                found = true;
                break;
            }
        if (!found && pos + 12 <= data.size())
            return stop(line_ + 1, "a BLF object without its LOBJ signature (damaged file?)");
        if (!found || at + blf_base_header > data.size()) {
            used = pos;
            return;
        }
        const std::uint32_t size = le32(data, at + 8);
        const std::uint32_t type = le32(data, at + 12);
        if (size < blf_base_header)
            return stop(line_ + 1, "a BLF object of " + std::to_string(size) +
                                       " bytes, less than its own header (damaged file?)");
        // The limits, before the reader waits for an object's bytes.
        const std::uint32_t most = top ? limits::blf_object_bytes : limits::blf_tail_bytes;
        if (size > most)
            return stop(line_ + 1, "a BLF object of " + std::to_string(size) + " bytes" +
                                       (top ? "" : " inside a container") + ", more than the " +
                                       std::to_string(most) + " the reader takes (damaged file?)");
        // Top-level objects are followed by size % 4 padding bytes (the last one maybe not).
        const std::size_t pad = top ? size % 4 : 0;
        if (at + size > data.size() || (top && !final && at + size + pad > data.size())) {
            used = pos;
            return;
        }
        ++line_;
        blf_object(data.substr(at, size), type, top);
        pos = at + size + pad;
        if (pos > data.size()) pos = data.size();
        used = pos;
    }
}

void reader::blf_object(std::string_view obj, std::uint32_t type, bool top) {
    constexpr std::uint32_t can_message = 1, log_container = 10, can_error_ext = 73,
                            can_message2 = 86, can_fd_message = 100, can_fd_message_64 = 101;
    if (type == log_container) {
        static_assert(limits::blf_container_depth == 1, "containers in containers are refused");
        if (!top)
            return stop(line_,
                        "a BLF container inside a container (no writer nests them; the reader "
                        "takes containers at the top level only)");
        if (obj.size() < blf_base_header + 16) return bad("a BLF container too short", "");
        const std::uint16_t method = le16(obj, blf_base_header);
        const std::uint32_t size = le32(obj, blf_base_header + 8);
        const auto payload = obj.substr(blf_base_header + 16);
        // Writers use containers of about 128 KiB; a size from a damaged file is not allocated.
        if (size > limits::blf_container_bytes ||
            (method == 0 && payload.size() > limits::blf_container_bytes))
            return stop(line_, "a BLF container of " +
                                   std::to_string(method == 0 ? payload.size() : size) +
                                   " bytes unpacked, more than the " +
                                   std::to_string(limits::blf_container_bytes) +
                                   " the reader takes (damaged file?)");
        // The data: the unfinished object of the previous container (blf_inner_, at most
        // limits::blf_tail_bytes: blf_objects refuses a larger object inside a container), then
        // this container's.
        std::string inner = std::move(blf_inner_);
        blf_inner_.clear();
        const std::size_t old = inner.size();
        if (method == 0) {
            inner.append(payload);
        } else if (method == 2) {
            inner.resize(old + size);
            uLongf out = size;
            const int rc = uncompress(reinterpret_cast<Bytef*>(inner.data() + old), &out,
                                      reinterpret_cast<const Bytef*>(payload.data()),
                                      static_cast<uLong>(payload.size()));
            if (rc != Z_OK) {
                blf_inner_ = inner.substr(0, old);
                return bad("a BLF container that zlib cannot uncompress (damaged file?)", "");
            }
            inner.resize(old + out);
        } else {
            blf_inner_ = std::move(inner);
            return bad("a BLF container compressed by an unknown method", "");
        }
        std::size_t used = 0;
        blf_objects(inner, false, false, used);
        if (!stopped_) blf_inner_.assign(inner, used);
        return;
    }
    if (type != can_message && type != can_message2 && type != can_error_ext &&
        type != can_fd_message && type != can_fd_message_64)
        return;  // markers, statistics, other buses
    const std::uint16_t header_size = le16(obj, 4);
    const std::uint16_t header_version = le16(obj, 6);
    if ((header_version != 1 && header_version != 2) || header_size < 32 ||
        header_size > obj.size())
        return bad("a BLF object header of an unknown version", "");
    const std::uint32_t flags = le32(obj, blf_base_header);
    const std::uint64_t stamp = le64(obj, blf_base_header + 8);
    const double seconds =
        blf_start_ + static_cast<double>(stamp) * (flags == 1 ? 1e-5 : 1e-9);  // 10 us or 1 ns
    char t[40];
    std::snprintf(t, sizeof t, "%.6f", seconds);
    time_buf_ = t;
    const auto body = obj.substr(header_size);
    auto interface = [this](unsigned channel) -> std::string_view {
        iface_buf_ = "can" + std::to_string(channel > 0 ? channel - 1 : 0);  // counted from 1
        return iface_buf_;
    };
    if (type == can_error_ext) return skip_one(skip::error_frame);
    std::array<std::uint8_t, 64> data{};
    if (type == can_message || type == can_message2) {
        // channel, flags (bit 0 transmitted, bit 7 remote), dlc, id (bit 31 extended), 8 bytes
        if (body.size() < 16) return bad("a BLF CAN message too short", "");
        const auto msg_flags = static_cast<unsigned char>(body[2]);
        const unsigned dlc = static_cast<unsigned char>(body[3]);
        const std::uint32_t id = le32(body, 4);
        const unsigned n = dlc > 8 ? 8 : dlc;
        const auto iface = interface(le16(body, 0));
        if ((msg_flags & 0x80u) != 0)
            return other(skip::remote, id & 0x1FFF'FFFFu, (id & 0x8000'0000u) != 0, n, {},
                         time_buf_, iface);
        for (unsigned i = 0; i < n; ++i) data[i] = static_cast<std::uint8_t>(body[8 + i]);
        return emit_raw(id & 0x1FFF'FFFFu, (id & 0x8000'0000u) != 0, {data.data(), n}, time_buf_,
                        iface);
    }
    if (type == can_fd_message) {
        // channel, flags, dlc, id, frame length, bit count, FD flags (EDL 1, BRS 2, ESI 4), valid
        // bytes, 5 reserved, 64 data bytes
        if (body.size() < 20) return bad("a BLF CAN FD message too short", "");
        const auto msg_flags = static_cast<unsigned char>(body[2]);
        const unsigned dlc = static_cast<unsigned char>(body[3]);
        const std::uint32_t id = le32(body, 4);
        const auto fd_flags = static_cast<unsigned char>(body[13]);
        const unsigned valid = static_cast<unsigned char>(body[14]);
        const auto iface = interface(le16(body, 0));
        if (valid > 64 || body.size() < 20 + valid)
            return bad("a BLF CAN FD message too short", "");
        for (unsigned i = 0; i < valid; ++i) data[i] = static_cast<std::uint8_t>(body[20 + i]);
        if ((msg_flags & 0x80u) != 0)
            return other(skip::remote, id & 0x1FFF'FFFFu, (id & 0x8000'0000u) != 0,
                         dlc > 8 ? 8 : dlc, {}, time_buf_, iface);
        if ((fd_flags & 0x1u) != 0 || valid > 8)
            return other(skip::fd, id & 0x1FFF'FFFFu, (id & 0x8000'0000u) != 0, valid,
                         {data.data(), valid}, time_buf_, iface, (fd_flags & 0x2u) != 0);
        return emit_raw(id & 0x1FFF'FFFFu, (id & 0x8000'0000u) != 0, {data.data(), valid},
                        time_buf_, iface);
    }
    // CAN_FD_MESSAGE_64: channel, dlc, valid bytes, tx count, id, frame length, flags (EDL 1000h,
    // BRS 2000h, remote 10h), ... 40 bytes, then the data.
    if (body.size() < 40) return bad("a BLF CAN FD message too short", "");
    const unsigned dlc = static_cast<unsigned char>(body[1]);
    const unsigned valid = static_cast<unsigned char>(body[2]);
    const std::uint32_t id = le32(body, 4);
    const std::uint32_t fd_flags = le32(body, 12);
    const auto iface = interface(static_cast<unsigned char>(body[0]));
    if (valid > 64 || body.size() < 40 + valid) return bad("a BLF CAN FD message too short", "");
    for (unsigned i = 0; i < valid; ++i) data[i] = static_cast<std::uint8_t>(body[40 + i]);
    if ((fd_flags & 0x10u) != 0)
        return other(skip::remote, id & 0x1FFF'FFFFu, (id & 0x8000'0000u) != 0, dlc > 8 ? 8 : dlc,
                     {}, time_buf_, iface);
    if ((fd_flags & 0x1000u) != 0 || valid > 8)
        return other(skip::fd, id & 0x1FFF'FFFFu, (id & 0x8000'0000u) != 0, valid,
                     {data.data(), valid}, time_buf_, iface, (fd_flags & 0x2000u) != 0);
    emit_raw(id & 0x1FFF'FFFFu, (id & 0x8000'0000u) != 0, {data.data(), valid}, time_buf_, iface);
}

}  // namespace tool::logs
