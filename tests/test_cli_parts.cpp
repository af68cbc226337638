// The pieces of the powerkey tool (examples/tool/): the log line reader, the JSON reader and the
// field values both ways. The tool itself is tested end to end by tests/test_cli.sh.
#include <doctest/doctest.h>

#include "../examples/tool/field_value.hpp"
#include "../examples/tool/json.hpp"
#include "../examples/tool/log_line.hpp"

#include <powerkey/can/candump.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/sdo.hpp>

#include <array>
#include <string>
#include <string_view>

namespace {
using namespace powerkey;

struct line_row {
    std::string_view text;
    tool::line_kind kind;
    std::string_view frame;  // candump form, for frames
    std::string_view time;
    std::string_view interface;
};

const line_row line_rows[] = {
    {"(1700000000.000000) can0 195#0900000012", tool::line_kind::frame, "195#0900000012",
     "1700000000.000000", "can0"},
    {"195#0900000012", tool::line_kind::frame, "195#0900000012", "", ""},
    {"  195#0900000012\r", tool::line_kind::frame, "195#0900000012", "", ""},
    {"(1700000000.000000)  can0  195   [5]  09 00 00 00 12", tool::line_kind::frame,
     "195#0900000012", "1700000000.000000", "can0"},
    {"  can0  080   [0]", tool::line_kind::frame, "080#", "", "can0"},
    {"  vcan0  18EF2100   [8]  04 1B 80 00 FF FF FF FF", tool::line_kind::frame,
     "18EF2100#041B8000FFFFFFFF", "", "vcan0"},
    {"(0.1) can0 18ef2100#041b8000ffffffff", tool::line_kind::frame, "18EF2100#041B8000FFFFFFFF",
     "0.1", "can0"},
    {"", tool::line_kind::skip, "", "", ""},
    {"   ", tool::line_kind::skip, "", "", ""},
    {"# a comment", tool::line_kind::skip, "", "", ""},
    {"// a comment", tool::line_kind::skip, "", "", ""},
    {"not a frame", tool::line_kind::bad, "", "", ""},
    {"195#090", tool::line_kind::bad, "", "", ""},
    {"195#000000000000000000", tool::line_kind::bad, "", "", ""},
    {"800#00", tool::line_kind::bad, "", "", ""},
    {"195#R", tool::line_kind::bad, "", "", ""},
    {"195##0112233", tool::line_kind::bad, "", "", ""},
    {"(1700000000.000000 can0 195#00", tool::line_kind::bad, "", "", ""},
    {"(1) can0 195#00 trailing", tool::line_kind::bad, "", "", ""},
    {"  can0  195   [2]  09 00 00", tool::line_kind::bad, "", "", ""},
    {"  can0  195   [9]  00 00 00 00 00 00 00 00 00", tool::line_kind::bad, "", "", ""},
    {"  can0  195   [1]  0G", tool::line_kind::bad, "", "", ""},
    {"  can0  1950   [1]  00", tool::line_kind::bad, "", "", ""},
};

}  // namespace

TEST_CASE("the three log line forms, comments, and malformed lines") {
    for (const auto& r : line_rows) {
        CAPTURE(r.text);
        const auto p = tool::parse_log_line(r.text);
        CHECK(p.kind == r.kind);
        if (r.kind == tool::line_kind::frame) {
            CHECK(p.line.frame == can::parse_candump(r.frame).value());
            CHECK(p.line.time == r.time);
            CHECK(p.line.interface == r.interface);
        }
        if (r.kind == tool::line_kind::bad) CHECK_FALSE(p.problem.empty());
    }
}

TEST_CASE("the JSON reader takes what decode --json writes and refuses the rest") {
    std::string out;
    {
        tool::json::object_writer w(out);
        w.field("id", "615");
        w.field_bool("ext", false);
        w.field("node", 21);
        w.field("text", "a \"quoted\"\\ \x01");
        w.key("fields");
        tool::json::object_writer f(out);
        f.key("keys");
        f.raw("[1,7]");
        f.close();
        w.close();
    }
    CHECK(
        out ==
        R"({"id":"615","ext":false,"node":21,"text":"a \"quoted\"\\ \u0001","fields":{"keys":[1,7]}})");
    tool::json::value v;
    std::string error;
    tool::json::parser p(out);
    REQUIRE(p.parse(v, error));
    REQUIRE(v.find("text") != nullptr);
    CHECK(v.find("text")->s == "a \"quoted\"\\ \x01");
    CHECK(v.find("node")->n == 21);
    CHECK(v.find("ext")->t == tool::json::value::type::boolean);
    const auto* keys = v.find("fields")->find("keys");
    REQUIRE(keys != nullptr);
    CHECK(keys->items.size() == 2);
    CHECK(v.find("missing") == nullptr);

    for (std::string_view bad :
         {"{", "{\"a\":}", "{\"a\":1,}", "{\"a\":-1}", "{\"a\":1.5}", "{\"a\":\"x}", "{\"a\":1} x",
          "[1,", "{\"a\":nul}", "{\"a\":[[[[[[1]]]]]]}", "{\"a\":\"\\u00e9\"}"}) {
        CAPTURE(bad);
        tool::json::value ignored;
        std::string why;
        tool::json::parser q(bad);
        CHECK_FALSE(q.parse(ignored, why));
        CHECK_FALSE(why.empty());
    }
}

TEST_CASE("numbers on the command line: decimal, 0x and h") {
    std::uint64_t n = 0;
    CHECK((tool::parse_number("58", n) && n == 58));
    CHECK((tool::parse_number("0x3A", n) && n == 58));
    CHECK((tool::parse_number("3Ah", n) && n == 58));
    CHECK_FALSE(tool::parse_number("3A", n));
    CHECK_FALSE(tool::parse_number("", n));
    CHECK_FALSE(tool::parse_number("0x", n));
    CHECK_FALSE(tool::parse_number("-1", n));
}

TEST_CASE("field values from text and JSON, with their range checks") {
    canopen::node_id node;
    CHECK(tool::set_from_text(node, "0x3A").empty());
    CHECK(node.value() == 0x3A);
    CHECK(tool::set_from_text(node, "0") == "value out of range");
    CHECK(tool::set_from_text(node, "128") == "value out of range");

    std::uint8_t byte = 0;
    CHECK(tool::set_from_text(byte, "255").empty());
    CHECK(tool::set_from_text(byte, "256") == "value out of range");

    bool b = false;
    CHECK((tool::set_from_text(b, "on").empty() && b));
    CHECK((tool::set_from_text(b, "no").empty() && !b));
    CHECK_FALSE(tool::set_from_text(b, "maybe").empty());

    index_set<8> set;
    CHECK(tool::set_from_text(set, "1,7").empty());
    CHECK(set == index_set<8>{1, 7});
    CHECK(tool::set_from_text(set, "-").empty());
    CHECK(set.empty());
    CHECK_FALSE(tool::set_from_text(set, "0").empty());
    CHECK_FALSE(tool::set_from_text(set, "9").empty());
    CHECK_FALSE(tool::set_from_text(set, "1,,2").empty());

    std::array<std::uint8_t, 4> bytes{};
    CHECK(tool::set_from_text(bytes, "0102AB").empty());
    CHECK(bytes == std::array<std::uint8_t, 4>{1, 2, 0xAB, 0});
    CHECK_FALSE(tool::set_from_text(bytes, "0102030405").empty());
    CHECK_FALSE(tool::set_from_text(bytes, "0G").empty());

    tool::json::value j;
    j.t = tool::json::value::type::array;
    j.items.resize(2);
    j.items[0].t = j.items[1].t = tool::json::value::type::number;
    j.items[0].n = 2;
    j.items[1].n = 8;
    CHECK(tool::set_from_json(set, j).empty());
    CHECK(set == index_set<8>{2, 8});
    j.items[1].n = 9;
    CHECK_FALSE(tool::set_from_json(set, j).empty());
}

TEST_CASE("enumerators by name, and by number where a name is not unique") {
    canopen::nmt_command c = canopen::nmt_command::start;
    // Two values print as "stop" (02h and the legacy 00h): the name means 02h.
    CHECK(tool::set_from_text(c, "stop").empty());
    CHECK(c == canopen::nmt_command::stop);
    CHECK(tool::set_from_text(c, "0").empty());
    CHECK(c == canopen::nmt_command::legacy_stop);
    CHECK(tool::set_from_text(c, "reset_node").empty());
    CHECK(c == canopen::nmt_command::reset_node);
    CHECK_FALSE(tool::set_from_text(c, "jump").empty());
    CHECK_FALSE(tool::set_from_text(c, "256").empty());

    auto json_of = [](auto v) {
        std::string out;
        tool::json::object_writer w(out);
        w.key("v");
        tool::write_json_value(w, v);
        w.close();
        return out;
    };
    CHECK(json_of(canopen::nmt_command::stop) == R"({"v":"stop"})");
    CHECK(json_of(canopen::nmt_command::legacy_stop) == R"({"v":0})");
    CHECK(json_of(canopen::nmt_state::pre_operational) == R"({"v":"pre_operational"})");
    CHECK(json_of(static_cast<canopen::nmt_state>(0x33)) == R"({"v":51})");

    // 32-bit SDO abort codes: names both ways, unnamed codes as numbers.
    canopen::sdo_abort_code a{};
    CHECK(tool::set_from_text(a, "object_does_not_exist").empty());
    CHECK(a == canopen::sdo_abort_code::object_does_not_exist);
    CHECK(tool::set_from_text(a, "no_data").empty());
    CHECK(a == canopen::sdo_abort_code::no_data);
    CHECK(json_of(canopen::sdo_abort_code::value_too_high) == R"({"v":"value_too_high"})");
    CHECK(json_of(static_cast<canopen::sdo_abort_code>(0x12345678)) == R"({"v":305419896})");
}
