// The pieces of the powerkey tool (tools/powerkey/): the log readers, the field values both ways,
// numbers, model names, escaping, and why encode refuses a message. The tool itself is tested end
// to end by tests/test_tool.sh, tests/test_tool_log_formats.sh (files of the real writers) and
// tests/test_tool_live.sh.
#include <doctest/doctest.h>

#include "../tools/powerkey/common.hpp"
#include "../tools/powerkey/field_value.hpp"
#include "../tools/powerkey/log_formats.hpp"
#include "../tools/powerkey/numbers.hpp"
#include "../tools/powerkey/refusal.hpp"

#include <powerkey/keypad/messages.hpp>
#include <powerkey/names.hpp>

#include <powerkey/can/candump.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/sdo.hpp>

#include <zlib.h>

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace {
using namespace powerkey;

// Collects what a reader finds: "ID#DATA time interface line" per frame, "!line why" per problem.
struct collect final : tool::logs::sink {
    std::vector<std::string> got;
    void frame(const tool::logs::record& r) override {
        got.push_back(std::string(can::format_candump(r.frame).view()) + " " + std::string(r.time) +
                      " " + std::string(r.interface) + " " + std::to_string(r.line));
    }
    void problem(std::size_t line, std::string_view why, std::string_view) override {
        got.push_back("!" + std::to_string(line) + " " + std::string(why));
    }
    // Remote and CAN FD frames: "R id length" / "F id data [brs]", then the time and line.
    void other(const tool::logs::other_record& r) override {
        std::string s = r.kind == tool::logs::skip::remote ? "R " : "F ";
        tool::append_hex(s, r.id, r.extended ? 8 : 3);
        if (r.kind == tool::logs::skip::remote) s += " " + std::to_string(r.length);
        if (r.kind == tool::logs::skip::fd) {
            s += " ";
            tool::append_hex_bytes(s, r.data.data(), r.data.size());
            if (r.bit_rate_switch) s += " brs";
        }
        got.push_back(s + " " + std::string(r.time) + " " + std::to_string(r.line));
    }
};

// Reads `text` in pieces of `chunk` bytes.
std::vector<std::string> read_all(std::string_view text, std::size_t chunk = 3) {
    collect c;
    tool::logs::reader r(c);
    for (std::size_t i = 0; i < text.size(); i += chunk) r.feed(text.substr(i, chunk));
    r.finish();
    return c.got;
}

struct line_row {
    std::string_view text;
    std::string_view want;  // what collect writes; "" for a line that is no frame and no problem
};

const line_row line_rows[] = {
    {"(1700000000.000000) can0 195#0900000012", "195#0900000012 1700000000.000000 can0 1"},
    {"(1700000000.000000) can0 195#0900000012 R", "195#0900000012 1700000000.000000 can0 1"},
    {"(1700000000.000000) can0 195#0900000012 T", "195#0900000012 1700000000.000000 can0 1"},
    {"195#0900000012", "195#0900000012   1"},
    {"195#09.00.00.00.12", "195#0900000012   1"},
    {"  195#0900000012\r", "195#0900000012   1"},
    {"(1700000000.000000)  can0  195   [5]  09 00 00 00 12",
     "195#0900000012 1700000000.000000 can0 1"},
    {"  can0  RX - -  195   [5]  09 00 00 00 12", "195#0900000012  can0 1"},
    {"  can0  195   [2]  41 42                     'AB'", "195#4142  can0 1"},
    {"  can0  080   [0]", "080#  can0 1"},
    {"  vcan0  18EF2100   [8]  04 1B 80 00 FF FF FF FF", "18EF2100#041B8000FFFFFFFF  vcan0 1"},
    {"(0.1) can0 18ef2100#041b8000ffffffff", "18EF2100#041B8000FFFFFFFF 0.1 can0 1"},
    {"", ""},
    {"   ", ""},
    {"# a comment", ""},
    {"// a comment", ""},
    {"195#R", "R 195 0  1"},  // remote: passed on, not a problem
    {"195#R5", "R 195 5  1"},
    {"(2.5) can0 195#R", "R 195 0 2.5 1"},
    {"195#R9", "!1 malformed remote frame (expected ID#R or ID#R and a length 0..8)"},
    {"195##0112233", "F 195 112233  1"},  // CAN FD: flags digit, then the data
    {"195##1112233", "F 195 112233 brs  1"},
    {"195##", "!1 malformed CAN FD frame (expected ID##FLAGS DATA)"},
    {"  can0  195   [12]  00 01 02 03 04 05 06 07 08 09 0A 0B",
     "F 195 000102030405060708090A0B  1"},
    {"  can0  195   [08]  00 01 02 03 04 05 06 07", "F 195 0001020304050607  1"},
    {"  can0  615   [8]  remote request", "R 615 8  1"},
    {"(x) can0 195#00", "!1 malformed timestamp (expected seconds like 1700000000.000000)"},
    {"(1.5.5) can0 195#00", "!1 malformed timestamp (expected seconds like 1700000000.000000)"},
    {"(1) can0 20000080#0000000000000000", ""},  // an error frame
    {"not a frame", "!1 not a frame (expected ID#DATA or a candump line)"},
    {"195#090", "!1 odd number of hex digits in the data"},
    {"195#000000000000000000", "!1 more than 8 data bytes"},
    {"800#00", "!1 identifier out of range"},
    {"(1700000000.000000 can0 195#00", "!1 unclosed timestamp"},
    {"(1) can0 195#00 trailing", "!1 unexpected text after the frame"},
    {"  can0  195   [2]  09 00 00", "!1 the [length] does not match the data bytes"},
    {"  can0  195   [9]  00 00 00 00 00 00 00 00 00", "F 195 000000000000000000  1"},
    {"  can0  195   [1]  0G", "!1 data bytes must be two hex digits each"},
    {"  can0  1950   [1]  00", "!1 identifier of other than 3 or 8 hex digits"},
};

}  // namespace

TEST_CASE("candump, cansend and screen lines, comments, skipped and malformed lines") {
    for (const auto& r : line_rows) {
        CAPTURE(r.text);
        const auto got = read_all(r.text);
        if (r.want.empty()) {
            CHECK(got.empty());
        } else {
            REQUIRE(got.size() == 1);
            CHECK(got[0] == r.want);
        }
    }
}

TEST_CASE("the forms are told apart by content, in any chunks") {
    const std::string asc =
        "date Tue Nov 14 22:13:20 2023\nbase hex  timestamps absolute\nno internal events logged\n"
        "   0.500000 1  195             Rx   d 5 09 00 00 00 12\n"
        "   1.000000 2  18EF2100x       Tx   d 8 04 1B 80 00 FF FF FF FF\n"
        "   1.500000 1  615             Rx   r 8\n"
        "   1.600000 1  ErrorFrame\n"
        "   2.000000 CANFD   1 Rx         80                                   0 0 0  0   "
        "130000  130        0 0 0 0 0 0\n";
    for (std::size_t chunk : {1u, 7u, 4096u}) {
        CAPTURE(chunk);
        CHECK(read_all(asc, chunk) ==
              std::vector<std::string>{"195#0900000012 0.500000 can0 4",
                                       "18EF2100#041B8000FFFFFFFF 1.000000 can1 5",
                                       "R 615 8 1.500000 6", "080# 2.000000 can0 8"});
    }
    const std::string trc21 =
        ";$FILEVERSION=2.1\r\n;$COLUMNS=N,O,T,B,I,d,R,L,D\r\n"
        "      1      1500.250 DT  1     0195 Rx -  5    09 00 00 00 12\r\n"
        "      2      1600.000 RR  1     0615 Rx -  8\r\n";
    CHECK(read_all(trc21) ==
          std::vector<std::string>{"195#0900000012 1.500250 can0 3", "R 615 8 1.600000 4"});
    const std::string trc10 = "     1)       100 0195 5 09 00 00 00 12\n";
    CHECK(read_all(trc10) == std::vector<std::string>{"195#0900000012 0.100000  1"});
    const std::string csv =
        "timestamp,arbitration_id,extended,remote,error,dlc,data\n"
        "1700000000.5,0x195,0,0,0,5,CQAAABI=\n1700000001.0,0x18ef2100,1,0,0,8,BBuAAP////8=\n"
        "1700000001.5,0x615,0,1,0,8,\n";
    CHECK(read_all(csv) == std::vector<std::string>{"195#0900000012 1700000000.5  2",
                                                    "18EF2100#041B8000FFFFFFFF 1700000001.0  3",
                                                    "R 615 8 1700000001.5 4"});
    // Python's repr of a small float: read, and written out as seconds.
    CHECK(read_all("timestamp,arbitration_id,extended,remote,error,dlc,data\n"
                   "5e-05,0x195,0,0,0,1,AQ==\n") == std::vector<std::string>{"195#01 0.000050  2"});
    CHECK(read_all("\xEF\xBB\xBF"
                   "195#01\n") == std::vector<std::string>{"195#01   1"});
}

TEST_CASE("what a file that is no log looks like") {
    auto looks = [](std::string_view bytes) {
        collect c;
        tool::logs::reader r(c);
        r.feed(bytes);
        r.finish();
        CHECK(c.got.empty());
        return r.looks_like();
    };
    CHECK(looks(std::string_view("\xD4\xC3\xB2\xA1\x02\x00\x04\x00", 8)) == "a pcap capture");
    CHECK(looks(std::string_view("\x0A\x0D\x0D\x0A\x00\x00", 6)) == "a pcapng capture");
    CHECK(looks("MDF     4.10    ") == "an ASAM MDF (MF4) measurement file");
    CHECK(looks("{\"id\":\"195\"}\n") == "JSON lines (the output of powerkey decode --json?)");
    CHECK(looks(std::string_view("ab\0cd\n", 6)) == "a binary file that is not Vector BLF");
}

TEST_CASE("BLF: a truncated or damaged file is one problem, never a crash") {
    collect c;
    tool::logs::reader r(c);
    r.feed(std::string_view("LOGG\x90\x00\x00\x00", 8));
    r.finish();
    CHECK(c.got == std::vector<std::string>{"!0 the BLF file ends inside its header (truncated?)"});
    std::string blf("LOGG\x10\x00\x00\x00", 8);
    blf.resize(16);
    blf += "XXXXYYYYZZZZWWWWVVVV";
    collect d;
    tool::logs::reader s(d);
    s.feed(blf);
    s.finish();
    CHECK(d.got ==
          std::vector<std::string>{"!1 a BLF object without its LOBJ signature (damaged file?)"});
    CHECK(s.done());
}

namespace {

// --- hostile BLF files, made here (log_formats.cpp reads what these write) ---------------------

void put_le(std::string& s, std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) s += static_cast<char>((v >> (8 * i)) & 0xFF);
}
// The file header as the writers make it: "LOGG", 144 bytes, no start time.
std::string blf_header() {
    std::string s = "LOGG";
    put_le(s, 144, 4);
    s.resize(144, '\0');
    return s;
}
// A CAN_MESSAGE object (type 1): the base header, flags, client, version, time stamp (10 us),
// then channel 1, flags, dlc 2, id, 8 data bytes. `size`: what its header says (0: the truth).
std::string blf_can(std::uint32_t id, std::uint32_t size = 0) {
    std::string s = "LOBJ";
    put_le(s, 32, 2);
    put_le(s, 1, 2);
    put_le(s, size != 0 ? size : 48, 4);
    put_le(s, 1, 4);
    put_le(s, 1, 4);        // flags: 10 us
    put_le(s, 0, 4);        // client index, object version
    put_le(s, 100'000, 8);  // 1 s
    put_le(s, 1, 2);        // channel 1
    s += '\0';              // flags
    s += '\2';              // dlc
    put_le(s, id, 4);
    s += std::string("\x01\x15\0\0\0\0\0\0", 8);
    return s;
}
// A log container (type 10) of `data`: zlib-compressed (method 2) or stored (0), stating
// `unpacked` bytes (0: the truth); padded to 4 bytes as at the top level.
std::string blf_container(std::string_view data, bool zlib = true, std::uint32_t unpacked = 0) {
    std::string payload(data);
    if (zlib) {
        uLongf n = compressBound(static_cast<uLong>(data.size()));
        payload.resize(n);
        REQUIRE(compress(reinterpret_cast<Bytef*>(payload.data()), &n,
                         reinterpret_cast<const Bytef*>(data.data()),
                         static_cast<uLong>(data.size())) == Z_OK);
        payload.resize(n);
    }
    std::string s = "LOBJ";
    put_le(s, 16, 2);
    put_le(s, 1, 2);
    put_le(s, 32 + payload.size(), 4);
    put_le(s, 10, 4);
    put_le(s, zlib ? 2 : 0, 2);
    put_le(s, 0, 6);
    put_le(s, unpacked != 0 ? unpacked : data.size(), 4);
    put_le(s, 0, 4);
    s += payload;
    if (s.size() % 4 != 0) s.append(4 - s.size() % 4, '\0');
    return s;
}

// `inner` in `depth` stored containers, one inside the other (built outside in: no copies).
std::string blf_nested(std::string_view inner, std::size_t depth) {
    std::string s;
    s.reserve(depth * 32 + inner.size() + 3);
    for (std::size_t level = depth; level > 0; --level) {
        const std::size_t payload = inner.size() + 32 * (level - 1);
        s += "LOBJ";
        put_le(s, 16, 2);
        put_le(s, 1, 2);
        put_le(s, 32 + payload, 4);
        put_le(s, 10, 4);
        put_le(s, 0, 8);  // stored, reserved
        put_le(s, payload, 4);
        put_le(s, 0, 4);
    }
    s += inner;
    if (s.size() % 4 != 0) s.append(4 - s.size() % 4, '\0');
    return s;
}

// What a reader finds in `bytes` fed in pieces of `chunk` bytes, and whether it stopped.
struct read_result {
    std::vector<std::string> got;
    bool done;
};
read_result read_bytes(std::string_view bytes, std::size_t chunk) {
    collect c;
    tool::logs::reader r(c);
    for (std::size_t i = 0; i < bytes.size(); i += chunk) r.feed(bytes.substr(i, chunk));
    r.finish();
    return {c.got, r.done()};
}

}  // namespace

TEST_CASE("limits: a text line past limits::text_line_bytes ends the input, in any chunks") {
    constexpr auto most = tool::logs::limits::text_line_bytes;
    // A line of exactly the limit is a line (a bad one); one byte more ends the input there.
    const std::string at_limit = "195#01\n" + std::string(most, 'A') + "\n195#02\n";
    const std::string over = "195#01\n" + std::string(most + 1, 'A') + "\n195#02\n";
    for (const std::size_t chunk : {std::size_t{1000}, std::size_t{4096}, over.size()}) {
        CAPTURE(chunk);
        const auto a = read_bytes(at_limit, chunk);
        CHECK(a.got == std::vector<std::string>{
                           "195#01   1", "!2 not a frame (expected ID#DATA or a candump line)",
                           "195#02   3"});
        CHECK_FALSE(a.done);
        const auto b = read_bytes(over, chunk);
        CHECK(b.got ==
              std::vector<std::string>{"195#01   1",
                                       "!2 a line longer than 65536 bytes, the limit of a log "
                                       "line (the rest of the input is not read)"});
        CHECK(b.done);
    }
    // Without an end: stopped as soon as the limit is passed, not at the end of the input.
    collect c;
    tool::logs::reader r(c);
    r.feed("195#01\n");
    for (int i = 0; i < 20 && !r.done(); ++i) r.feed(std::string(8192, 'A'));
    CHECK(r.done());
    CHECK(c.got.size() == 2);
}

TEST_CASE("limits: a binary file is told by a NUL in its first line, however it arrives") {
    const std::string_view nul("abcd\0\0\0\n195#0115\n", 16);
    for (std::size_t chunk = 1; chunk <= nul.size(); ++chunk) {
        CAPTURE(chunk);
        collect c;
        tool::logs::reader r(c);
        for (std::size_t i = 0; i < nul.size(); i += chunk) r.feed(nul.substr(i, chunk));
        r.finish();
        CHECK(c.got.empty());
        CHECK(r.detected() == tool::logs::format::not_a_log);
        CHECK(r.looks_like() == "a binary file that is not Vector BLF");
    }
    // The byte-order mark and the signatures, one byte at a time.
    CHECK(read_all("\xEF\xBB\xBF"
                   "195#01\n",
                   1) == std::vector<std::string>{"195#01   1"});
    collect c;
    tool::logs::reader r(c);
    for (const char b : std::string_view("MDF     4.10    ")) r.feed(std::string_view(&b, 1));
    r.finish();
    CHECK(r.looks_like() == "an ASAM MDF (MF4) measurement file");
    // A first line of text: a NUL later is a bad line, not a binary file.
    CHECK(read_all(std::string_view("195#01\n19\0#01\n", 14)) ==
          std::vector<std::string>{"195#01   1", "!2 malformed frame (expected ID#DATA)"});
}

TEST_CASE("limits: BLF objects, the tail a container carries, nested containers") {
    const std::string two = blf_can(0x195) + blf_can(0x215);
    // The reference: two messages in one container, and split across two (the tail carried).
    CHECK(read_bytes(blf_header() + blf_container(two), 7).got ==
          std::vector<std::string>{"195#0115 1.000000 can0 2", "215#0115 1.000000 can0 3"});
    CHECK(read_bytes(blf_header() + blf_container(two.substr(0, 70)) +
                         blf_container(two.substr(70), false),
                     4096)
              .got ==
          std::vector<std::string>{"195#0115 1.000000 can0 2", "215#0115 1.000000 can0 4"});
    // An object in a container claiming 0xFFFFFFF0 bytes, then containers of 16 MiB of zeros:
    // refused at once, its containers never unpacked.
    std::string huge = blf_header() + blf_container(blf_can(0x195, 0xFFFF'FFF0));
    const std::string zeros(16u << 20, '\0');
    huge += blf_container(zeros);
    auto got = read_bytes(huge, 65536);
    CHECK(got.got == std::vector<std::string>{
                         "!2 a BLF object of 4294967280 bytes inside a container, more than the "
                         "1048576 the reader takes (damaged file?)"});
    CHECK(got.done);
    // At the top level: refused when its header is read, not after its bytes.
    got = read_bytes(blf_header() + blf_can(0x195, 0xFFFF'FFF0), 65536);
    CHECK(got.got == std::vector<std::string>{
                         "!1 a BLF object of 4294967280 bytes, more than the 16842752 the reader "
                         "takes (damaged file?)"});
    // A container stating more than 16 MiB unpacked.
    got = read_bytes(blf_header() + blf_container(two, true, (16u << 20) + 1), 4096);
    CHECK(got.got == std::vector<std::string>{
                         "!1 a BLF container of 16777217 bytes unpacked, more than the 16777216 "
                         "the reader takes (damaged file?)"});
    // Containers in containers, 10,000 deep and 2 deep: refused at the first inner one.
    got = read_bytes(blf_header() + blf_nested(blf_can(0x195), 10'000), 65536);
    CHECK(got.got == std::vector<std::string>{
                         "!2 a BLF container inside a container (no writer nests them; the reader "
                         "takes containers at the top level only)"});
    CHECK(got.done);
    got = read_bytes(blf_header() + blf_container(blf_container(two)), 65536);
    CHECK(got.got.size() == 1);
    // A message cut short in the last compressed container: said, not dropped.
    got = read_bytes(blf_header() + blf_container(two.substr(0, 70)), 4096);
    CHECK(got.got ==
          std::vector<std::string>{"195#0115 1.000000 can0 2",
                                   "!3 the BLF file ends inside this object, in its last container "
                                   "(truncated?)"});
    // Padding after the last message is no object.
    CHECK(read_bytes(blf_header() + blf_container(two + std::string(3, '\0')), 4096).got.size() ==
          2);
}

TEST_CASE("TRC: a version, columns or a time the reader cannot use is an error") {
    CHECK(read_all(";$FILEVERSION=3.0\n     1)  0.0  Rx  0195  1  01\n") ==
          std::vector<std::string>{"!1 a TRC file version powerkey does not read (it reads 1.0 to "
                                   "1.3, 2.0 and 2.1)"});
    const std::string unusable =
        "!2 unusable TRC columns (each of N,O,T,B,I,d,R,L,l,D at most once; a frame needs O, I, L "
        "or l, T in 2.x, and D last)";
    for (std::string_view columns :
         {"", "N,T,I,d,l,D", "N,O,T,I,d,l", "N,O,T,I,I,l,D", "N,O,T,I,x,l,D", "N,O,I,l,D"}) {
        CAPTURE(columns);
        CHECK(read_all(";$FILEVERSION=2.1\n;$COLUMNS=" + std::string(columns) +
                       "\n      1      1.0 DT  1     0195 Rx -  1    01\n") ==
              std::vector<std::string>{unusable});
    }
    // A column list of 30,000 letters (a line within the limit) costs one pass, not one per line.
    std::string many = ";$FILEVERSION=2.1\n;$COLUMNS=";
    for (int i = 0; i < 30'000; ++i) many += "N,";
    many += "\n";
    for (int i = 0; i < 1000; ++i) many += "      1      1.0 DT  1     0195 Rx -  1    01\n";
    CHECK(read_all(many, 4096) == std::vector<std::string>{unusable});
    for (std::string_view time : {"abc", "nan", "-inf", "1e308", "-1", "0x10"}) {
        CAPTURE(time);
        CHECK(
            read_all(";$FILEVERSION=1.1\n     1)  " + std::string(time) + "  Rx  0195  1  01\n") ==
            std::vector<std::string>{"!2 malformed TRC line (time)"});
    }
}

TEST_CASE("CSV: a time that is no number is an error, remote frames too") {
    const std::string head = "timestamp,arbitration_id,extended,remote,error,dlc,data\n";
    for (std::string_view time : {"abc", "nan", "inf", "-1", "1e12", "0x10", "1.5x"}) {
        CAPTURE(time);
        CHECK(read_all(head + std::string(time) + ",0x195,0,0,0,1,AQ==\n") ==
              std::vector<std::string>{"!2 malformed CSV line (timestamp)"});
        CHECK(read_all(head + std::string(time) + ",0x195,0,1,0,1,\n") ==
              std::vector<std::string>{"!2 malformed CSV line (timestamp)"});
    }
    CHECK(read_all(head + "1.5e-05,0x195,0,1,0,1,\n") ==
          std::vector<std::string>{"R 195 1 0.000015 2"});
}

TEST_CASE("base64 of python-can's CSV") {
    std::vector<std::uint8_t> out;
    CHECK(tool::logs::base64_decode("BBuAAP////8=", out));
    CHECK(out == std::vector<std::uint8_t>{0x04, 0x1B, 0x80, 0x00, 0xFF, 0xFF, 0xFF, 0xFF});
    CHECK(tool::logs::base64_decode("", out));
    CHECK(out.empty());
    CHECK_FALSE(tool::logs::base64_decode("AB$=", out));
}

TEST_CASE("seconds and log digits: the one number reader") {
    CHECK(tool::parse_seconds("1700000000.000000") == 1'700'000'000'000'000);
    CHECK(tool::parse_seconds("0.42") == 420'000);
    CHECK(tool::parse_seconds("3") == 3'000'000);
    CHECK(tool::parse_seconds(".5") == 500'000);
    CHECK(tool::parse_seconds("1.1234567") == 1'123'456);  // past microseconds: dropped
    CHECK(tool::parse_seconds("") == std::nullopt);
    CHECK(tool::parse_seconds(".") == std::nullopt);
    CHECK(tool::parse_seconds("-1") == std::nullopt);
    CHECK(tool::parse_seconds("1e3") == std::nullopt);
    CHECK(tool::parse_seconds("1.2.3") == std::nullopt);
    CHECK(tool::parse_seconds("99999999999999999999") == std::nullopt);
    std::uint32_t v = 0;
    CHECK((tool::parse_digits("7FF", v) && v == 0x7FF));
    CHECK((tool::parse_digits("1FFFFFFF", v) && v == 0x1FFF'FFFF));
    CHECK_FALSE(tool::parse_digits("100000000", v));  // 9 hex digits
    CHECK((tool::parse_digits("4294967295", v, 10) && v == 0xFFFF'FFFFu));
    CHECK_FALSE(tool::parse_digits("4294967296", v, 10));
    CHECK_FALSE(tool::parse_digits("0x7F", v));
    CHECK(tool::hex_digit('f') == 15);
    CHECK(tool::hex_digit('g') == -1);
}

TEST_CASE("message kinds as people write them") {
    CHECK(tool::kind_name("led-on") == "led_on");
    CHECK(tool::kind_name("pk1000_led_on") == "led_on");
    CHECK(tool::kind_name("pkp_led_on") == "led_on");
    CHECK(tool::kind_name("sdo-segment-response") == "sdo_segment_response");
}

TEST_CASE("why encode refuses a message: the field, and what the model takes") {
    const auto node = canopen::default_node_id;
    const auto none = [](auto&) {};
    // A key above a PKP-2200's four: the field, and 1..4.
    const message red5 = led_on{leds{led_set{5}, {}, {}}};
    auto why = tool::explain_refusal(red5, model::pkp2200, node, none);
    CHECK(why.kind == tool::refusal::what::field);
    CHECK(why.field == "red");
    CHECK(why.most == 4);
    why = tool::explain_refusal(message{led_on{leds{led_set{29}, {}, {}}}}, model::pk1000, node,
                                none);
    CHECK((why.kind == tool::refusal::what::field && why.field == "red" && why.most == 28));
    // A message the model has not: the PK1000 has no encoders.
    why = tool::explain_refusal(message{encoder_state{}}, model::pk1000, node, none);
    CHECK(why.kind == tool::refusal::what::not_for_model);
    // What list shows: the models that speak a kind.
    CHECK(tool::speaks(encoder_state{}, model::pkp3500mt, node));
    CHECK_FALSE(tool::speaks(encoder_state{}, model::pk1000, node));
    CHECK(tool::speaks(command{}, model::pkp2400, node));  // its default key 0 does not encode
    CHECK_FALSE(tool::speaks(command{}, model::pk1000, node));
    CHECK(tool::speaks(canopen::sdo_upload_initiate_response{}, model::pk1000, node));
}

TEST_CASE("numbers on the command line: decimal, 0x and h") {
    std::uint64_t n = 0;
    CHECK((tool::parse_number("58", n) && n == 58));
    CHECK((tool::parse_number("0x3A", n) && n == 58));
    CHECK((tool::parse_number("3Ah", n) && n == 58));
    CHECK((tool::parse_number("000003E2h", n) && n == 994));
    CHECK_FALSE(tool::parse_number("3A", n));
    CHECK_FALSE(tool::parse_number("", n));
    CHECK_FALSE(tool::parse_number("0x", n));
    CHECK_FALSE(tool::parse_number("-1", n));
    CHECK_FALSE(tool::parse_number("99999999999999999999", n));
}

TEST_CASE("model names as people and the manuals write them") {
    CHECK(tool::model_from_name("pk1000") == model::pk1000);
    CHECK(tool::model_from_name("PK1000") == model::pk1000);
    CHECK(tool::model_from_name("PKP-2400") == model::pkp2400);
    CHECK(tool::model_from_name("PKP-2400-LI") == model::pkp2400);
    CHECK(tool::model_from_name("pkp 2600") == model::pkp2600);
    CHECK(tool::model_from_name("PKP2200LI") == model::pkp2200);
    CHECK(tool::model_from_name("PKU2400") == model::pkp2400);  // as the keypad reports it
    CHECK(tool::model_from_name("PKP-3500-MT") == model::pkp3500mt);
    CHECK(tool::model_from_name("pkp2600si") == model::pkp2600si);
    CHECK(tool::model_from_name("PKP-1500-LI") == model::pkp1500li);
    CHECK(tool::model_from_name("pkp_2400_si") == model::pkp2400si);
    CHECK(tool::model_from_name("pkp3000") == std::nullopt);
    CHECK(tool::model_from_name("li") == std::nullopt);
    CHECK(tool::model_from_name("") == std::nullopt);
    // Every model of the table, by its own name, and all thirteen in the usage text.
    std::size_t n = 0;
    for (const auto m : enum_values<model>()) {
        CHECK(tool::model_from_name(to_string(m)) == m);
        CHECK(tool::model_names().find(to_string(m)) != std::string::npos);
        ++n;
    }
    CHECK(n == model_count);
    CHECK(n == 13);
}

TEST_CASE("escaping: control characters, DEL, quotes and bytes above 7Fh; long text cut") {
    CHECK(tool::escape("BlinkMarine") == "BlinkMarine");
    CHECK(tool::escape("\x1B]0;x\x07") == "\\x1B]0;x\\x07");
    CHECK(tool::escape("a\"b\\c\x7F\xC3") == "a\\x22b\\x5Cc\\x7F\\xC3");
    CHECK(tool::escape(std::string(100, 'a'), 10) == "aaaaaaaaaa...");
    // The one \xHH escape, which the JUnit XML of `check` shares.
    std::string hex;
    for (const int u : {0x00, 0x1F, 0x7F, 0xFF})
        tool::append_hex_escape(hex, static_cast<unsigned char>(u));
    CHECK(hex == "\\x00\\x1F\\x7F\\xFF");
}

TEST_CASE("field values from text and JSON, with their range checks named") {
    canopen::node_id node;
    CHECK(tool::set_from_text(node, "0x3A").empty());
    CHECK(node.value() == 0x3A);
    CHECK(tool::set_from_text(node, "3Ah").empty());
    CHECK(tool::set_from_text(node, "0", "node") == "0 is outside 01h..7Fh");
    CHECK(tool::set_from_text(node, "128", "node_id") == "128 is outside 01h..7Fh");
    CHECK(tool::set_from_text(node, "x", "node_id") ==
          "'x' is not a number (58, 0x3A or 3Ah; 01h..7Fh)");

    std::uint8_t byte = 0;
    CHECK(tool::set_from_text(byte, "255").empty());
    CHECK(tool::set_from_text(byte, "256", "level") == "256 is outside 00h..FFh");
    CHECK(tool::set_from_text(byte, "256", "tick") == "256 is outside 0..255");  // a count

    bool b = false;
    CHECK((tool::set_from_text(b, "yes").empty() && b));
    CHECK((tool::set_from_text(b, "off").empty() && !b));
    CHECK(tool::set_from_text(b, "maybe") ==
          "'maybe' is not yes or no (also true/false, on/off, 1/0)");

    index_set<28> set;
    for (std::string_view text : {"1,7", "1 7", " 7 1 "}) {
        CAPTURE(text);
        CHECK(tool::set_from_text(set, text).empty());
        CHECK(set == index_set<28>{1, 7});
    }
    CHECK(tool::set_from_text(set, "1-28").empty());
    CHECK(set.mask() == 0x0FFF'FFFFu);
    CHECK(tool::set_from_text(set, "-").empty());
    CHECK(set.empty());
    CHECK(tool::set_from_text(set, "0") == "'0' is outside 1..28");
    CHECK(tool::set_from_text(set, "5-29") == "'5-29' is outside 1..28");
    CHECK(tool::set_from_text(set, "a") == "'a' is not a list of numbers like 1,7 or 1-28 or -");

    std::array<std::uint8_t, 4> bytes{};
    CHECK(tool::set_from_text(bytes, "0102AB").empty());
    CHECK(bytes == std::array<std::uint8_t, 4>{1, 2, 0xAB, 0});
    CHECK(tool::set_from_text(bytes, "52 69 6E").empty());
    CHECK(bytes == std::array<std::uint8_t, 4>{0x52, 0x69, 0x6E, 0});
    CHECK(tool::set_from_text(bytes, "0102030405") ==
          "'0102030405' is not hex bytes (at most 4, like 72 69 6E or 72696E)");
    CHECK_FALSE(tool::set_from_text(bytes, "0G").empty());

    CHECK(tool::set_from_json(set, nlohmann::json::parse("[2,8]")).empty());
    CHECK(set == index_set<28>{2, 8});
    CHECK(tool::set_from_json(set, nlohmann::json::parse("[2,29]")) == "expected numbers 1..28");
    CHECK(tool::set_from_json(byte, nlohmann::json::parse("-1")) == "a negative number");
}

TEST_CASE("what the text prints, the text reader takes back") {
    auto text_of = [](std::string_view name, const auto& v) {
        std::string out;
        tool::write_text_value(out, name, v);
        return out;
    };
    CHECK(text_of("red", index_set<28>{1, 2, 3, 4, 9}) == "1-4 9");
    CHECK(text_of("target", canopen::nmt_target::make(0x3A).value()) == "3Ah");
    CHECK(text_of("level", std::uint8_t{63}) == "3Fh");  // describe(): hex but counts and times
    CHECK(text_of("tick", std::uint8_t{63}) == "63");
    CHECK(text_of("period_ms", std::uint32_t{1000}) == "1000");
    CHECK(text_of("data", std::array<std::uint8_t, 3>{0x72, 0x69, 0x6E}) == "72 69 6E");
    CHECK(text_of("command", canopen::nmt_command::legacy_stop) == "legacy_stop");
    index_set<28> set;
    CHECK(tool::set_from_text(set, "1-4 9").empty());
    CHECK(set == index_set<28>{1, 2, 3, 4, 9});
    canopen::nmt_command c{};
    CHECK(tool::set_from_text(c, "00h").empty());
    CHECK(c == canopen::nmt_command::legacy_stop);
    CHECK(tool::set_from_text(c, "legacy_stop").empty());
    CHECK(c == canopen::nmt_command::legacy_stop);
}

TEST_CASE("list and the text agree with describe(): the fields of a message as printed") {
    const message m = led_brightness{level{0x3F}};
    const auto fields = tool::described_fields(m, canopen::default_node_id);
    REQUIRE(fields.size() == 1);
    CHECK(fields[0].first == "level");
    CHECK(fields[0].second == "3Fh");
    std::string text;
    tool::append_message_text(text, message{led_on{leds{led_set{1, 7}, {}, {}}}},
                              canopen::default_node_id);
    CHECK(text == "node 15h  LED on  red: 1 7  green: -  blue: -");
}

TEST_CASE("enumerators by name from their tables, and by number") {
    canopen::nmt_command c = canopen::nmt_command::start;
    // 02h is "stop", the legacy 00h "legacy_stop" (names.hpp); a number is taken as it is.
    CHECK(tool::set_from_text(c, "stop").empty());
    CHECK(c == canopen::nmt_command::stop);
    CHECK(tool::set_from_text(c, "0").empty());
    CHECK(c == canopen::nmt_command::legacy_stop);
    CHECK(tool::set_from_text(c, "reset_node").empty());
    CHECK(c == canopen::nmt_command::reset_node);
    CHECK(tool::set_from_text(c, "jump") ==
          "unknown name 'jump' (start, stop, pre_operational, reset_node, reset_communication, "
          "legacy_stop)");
    CHECK(tool::set_from_text(c, "256") == "'256' is outside 0..255");

    auto json_of = [](auto v) {
        std::string out;
        tool::json::object_writer w(out);
        w.key("v");
        tool::write_json_value(w, v);
        w.close();
        return out;
    };
    CHECK(json_of(canopen::nmt_command::stop) == R"({"v":"stop"})");
    CHECK(json_of(canopen::nmt_command::legacy_stop) == R"({"v":"legacy_stop"})");
    CHECK(json_of(canopen::nmt_state::pre_operational) == R"({"v":"pre_operational"})");
    CHECK(json_of(static_cast<canopen::nmt_state>(0x33)) == R"({"v":51})");

    // 32-bit SDO abort codes: names both ways, unnamed codes as numbers.
    canopen::sdo_abort_code a{};
    CHECK(tool::set_from_text(a, "object_does_not_exist").empty());
    CHECK(a == canopen::sdo_abort_code::object_does_not_exist);
    CHECK(json_of(canopen::sdo_abort_code::value_too_high) == R"({"v":"value_too_high"})");
    CHECK(json_of(static_cast<canopen::sdo_abort_code>(0x12345678)) == R"({"v":305419896})");

    // The list in an error is the table's first names in order, cut after 12.
    const auto names = tool::enum_name_list<canopen::sdo_abort_code>();
    CHECK(names.starts_with(std::string(to_string(enum_values<canopen::sdo_abort_code>()[0]))));
    CHECK(names.find("names)") != std::string::npos);
}

TEST_CASE("the JSON writer escapes whatever the bus sent") {
    std::string out;
    tool::json::object_writer w(out);
    w.field("text", "a \"quoted\"\\ \x01\xC3");
    w.field("n", 21);
    w.field_bool("ext", false);
    w.close();
    CHECK(out == R"({"text":"a \"quoted\"\\ \u0001\u00C3","n":21,"ext":false})");
    CHECK_FALSE(nlohmann::json::parse(out, nullptr, false).is_discarded());
}
