// The pieces of the powerkey tool (tools/powerkey/): the log readers, the field values both ways,
// numbers, model names, escaping, and why encode refuses a message. The tool itself is tested end
// to end by tests/test_cli.sh, tests/test_log_formats.sh (files of the real writers) and
// tests/test_cli_live.sh.
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
          std::vector<std::string>{"!0 a BLF object without its LOBJ signature (damaged file?)"});
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
