// behaviour/checker.hpp: the bus-log checker. Each problem kind from a small log, a clean log
// with none, and the explanations. A log row is (time in ms, frame); its line is its position
// from 1. The controller's own sessions against the virtual keypad are checked in
// test_behaviour_controller.cpp.
#include "support.hpp"

#include <powerkey/behaviour/checker.hpp>
#include <powerkey/names.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

using namespace powerkey;
using namespace powerkey::behaviour;

namespace {

struct entry {
    std::uint32_t ms;
    std::string_view frame;
};

struct case_row {
    std::string_view name;
    model m;
    std::vector<entry> log;
    std::vector<problem> expected;
};

std::vector<problem> check(model m, const std::vector<entry>& log, checker_config cfg = {}) {
    cfg.keypad_model = m;
    checker<> c(cfg);
    std::vector<problem> out;
    std::uint32_t line = 0;
    std::uint32_t last = 0;
    for (const auto& e : log) {
        const auto f = can::parse_candump(e.frame);
        REQUIRE(f.has_value());
        for (const auto& p : c.step(*f, millis{e.ms}, ++line)) out.push_back(p);
        last = e.ms;
    }
    for (const auto& p : c.finish(millis{last})) out.push_back(p);
    return out;
}

std::string text_of(const problem& p) {
    std::array<char, 160> buf{};
    const auto t = explain(p, buf);
    REQUIRE(t.has_value());
    return std::string(to_string(p.kind)) + " line " + std::to_string(p.line) + ": " +
           std::string(*t);
}

std::string text_of(const std::vector<problem>& ps) {
    std::string s;
    for (const auto& p : ps) s += text_of(p) + "\n";
    return s;
}

using pk = problem_kind;

}  // namespace

TEST_CASE("checker: one small log per problem kind") {
    const case_row rows[] = {
        {"an SDO request while another is outstanding (the keypad drops it)",
         model::pk1000,
         {{0, "715#00"},
          {10, "615#2F14200002000000"},
          {11, "615#4011200000000000"},
          {12, "595#6014200000000000"}},
         {{3, pk::sdo_overlap, {2, 0x2014, 0}}}},
        {"a request never answered",
         model::pk1000,
         {{0, "715#00"}, {10, "615#4011200000000000"}, {500, "715#7F"}},
         {{2, pk::sdo_no_reply, {0x2011, 0, 490}}}},
        {"a request never answered, at the end of the log",
         model::pkp2400,
         {{0, "715#00"},
          {10, "615#4001620100000000"},
          {400, "715#7F"},
          {410, "615#4001620200000000"}},
         {{2, pk::sdo_no_reply, {0x6201, 1, 390}}}},
        {"an abort with its CiA 301 meaning",
         model::pk1000,
         {{0, "715#00"}, {10, "615#4001100000000000"}, {11, "595#8001100000000206"}},
         {{3, pk::sdo_abort, {0x0602'0000, 0x1001, 0}}}},
        {"LEDs sent to a keypad that was never started",
         model::pkp2400,
         {{0, "715#00"}, {10, "215#0100000000000000"}, {20, "315#0100000000000000"}},
         {{2, pk::pdo_not_operational, {0x215, 0x7F, 0}}}},
        {"LEDs sent after a reboot without a new NMT start",
         model::pk1000,
         {{0, "715#00"},
          {5, "000#0115"},
          {10, "215#0100000000000000"},
          {900, "715#00"},
          {910, "215#0100000000000000"}},
         {{5, pk::pdo_not_operational, {0x215, 0x7F, 0}}}},
        {"LEDs sent to a stopped keypad (NMT stop to all nodes)",
         model::pkp2200,
         {{0, "000#0100"}, {10, "000#0200"}, {20, "215#0100000000000000"}},
         {{3, pk::pdo_not_operational, {0x215, 0x04, 0}}}},
        {"no problem: a keypad set active on startup is operational after its boot-up",
         model::pk1000,
         {{0, "615#2F12200001000000"},
          {1, "595#6012200000000000"},
          {500, "715#00"},
          {510, "215#0100000000000000"}},
         {}},
        {"LEDs after the heartbeat the keypad consumes stopped (PK1000 28 note 2)",
         model::pk1000,
         {{0, "615#2316100164007E00"},
          {1, "595#6016100100000000"},
          {2, "000#0115"},
          {10, "77E#05"},
          {110, "77E#05"},
          {150, "215#0100000000000000"},
          {300, "215#0100000000000000"}},
         {{7, pk::pdo_not_operational, {0x215, 0x7F, 0}}}},
        {"heartbeat silence longer than 1017h allows",
         model::pk1000,
         {{0, "615#2B17100064000000"},
          {1, "595#6017100000000000"},
          {100, "715#7F"},
          {200, "715#7F"},
          {400, "000#0115"}},
         {{5, pk::heartbeat_silence, {200, 100, 4}}}},
        {"key-state silence longer than the event timer allows",
         model::pk1000,
         {{0, "615#2B00180532000000"},
          {1, "595#6000180500000000"},
          {2, "000#0115"},
          {100, "195#0000000001"},
          {150, "195#0000000001"},
          {300, "215#0000000000000000"}},
         {{6, pk::key_state_silence, {150, 50, 5}}}},
        {"key-state silence, PKP periodic transmission (command 12h)",
         model::pkp2400,
         {{0, "615#2300650112010A00"},
          {1, "595#6000650100000000"},
          {2, "000#0115"},
          {100, "195#0000000001"},
          {300, "215#0000000000000000"}},
         {{5, pk::key_state_silence, {200, 100, 4}}}},
        {"traffic to the old node id after a node-id change (PK1000 23)",
         model::pk1000,
         {{0, "615#2F1320003A000000"}, {1, "5BA#6013200000000000"}, {10, "615#4013200000000000"}},
         {{3, pk::old_node_traffic, {0x615, 0x15, 0x3A}}}},
        {"traffic to the old node id after a node-id change (PKP 13 h)",
         model::pkp2400,
         {{0, "615#2300650170180000"},
          {1, "595#6000650100000000"},
          {2, "718#00"},
          {10, "000#0118"},
          {20, "215#0100000000000000"}},
         {{5, pk::old_node_traffic, {0x215, 0x15, 0x18}}}},
        {"a segment request with the wrong toggle bit",
         model::pk1000,
         {{0, "615#400B100000000000"},
          {1, "595#410B100007000000"},
          {2, "615#7000000000000000"},
          {3, "595#11504B3130303000"}},
         {{3, pk::segment_toggle, {0, 1, 0}}}},
        {"a segment response with the wrong toggle bit",
         model::pk1000,
         {{0, "615#400B100000000000"},
          {1, "595#410B100007000000"},
          {2, "615#6000000000000000"},
          {3, "595#11504B3130303000"}},
         {{4, pk::segment_toggle, {0, 1, 1}}}},
        {"a segmented upload shorter than announced",
         model::pk1000,
         {{0, "615#400B100000000000"},
          {1, "595#410B100009000000"},
          {2, "615#6000000000000000"},
          {3, "595#01504B3130303000"}},
         {{4, pk::segment_size, {9, 7, 0x100B}}}},
        // Issue 22: frames to the keypad that decode refuses, with its reason.
        {"a 4-byte write of a 1-byte object, never answered",
         model::pk1000,
         {{0, "715#00"}, {10, "615#2314200002000000"}, {500, "715#7F"}},
         {{2, pk::refused_frame, {static_cast<std::uint32_t>(errc::size_mismatch), 0x615, 8}},
          {2, pk::sdo_no_reply, {0x2014, 0, 490}}}},
        {"an LED map with a reserved bit set (PK1000: no LED 29)",
         model::pk1000,
         {{0, "000#0115"}, {10, "215#0000001000000000"}},
         {{2, pk::refused_frame, {static_cast<std::uint32_t>(errc::reserved_not_zero), 0x215, 8}}}},
        {"a brightness of 40h",
         model::pk1000,
         {{0, "000#0115"}, {10, "415#4000000000000000"}},
         {{2,
           pk::refused_frame,
           {static_cast<std::uint32_t>(errc::value_out_of_range), 0x415, 8}}}},
        {"an SDO write too short to carry its value, answered by nobody",
         model::pk1000,
         {{0, "715#00"}, {10, "615#2B171000"}, {300, "715#7F"}},
         {{2, pk::refused_frame, {static_cast<std::uint32_t>(errc::wrong_length), 0x615, 4}},
          {2, pk::sdo_no_reply, {0x1017, 0, 290}}}},
        {"a trimmed request without reply: a warning, and the request still unanswered",
         model::pk1000,
         {{0, "715#00"}, {10, "615#2B171000F401"}, {300, "715#7F"}},
         {{2, pk::not_manual_form, {0x615, 6, 1}}, {2, pk::sdo_no_reply, {0x1017, 0, 290}}}},
        {"a padded NMT start and a trimmed backlight: warnings only",
         model::pk1000,
         {{0, "000#0115000000000000"}, {10, "515#3F01"}, {20, "715#05"}},
         {{1, pk::not_manual_form, {0x000, 8, 2}}, {2, pk::not_manual_form, {0x515, 2, 1}}}},
        {"the keypad's own refused frames are no refused_frame (2 of 3: no wrong_model)",
         model::pkp2400si,
         {{0, "195#000100002A"}, {10, "195#000100002A"}, {20, "195#010000002A"}},
         {}},
        {"a log mostly refused under the model given",
         model::pkp2400si,
         {{0, "715#00"},
          {10, "195#000100002A"},
          {20, "195#000200002A"},
          {30, "215#0000000100000000"},
          {40, "195#010000002A"}},
         {{4, pk::refused_frame, {static_cast<std::uint32_t>(errc::reserved_not_zero), 0x215, 8}},
          {2, pk::wrong_model, {3, 5, static_cast<std::uint32_t>(model::pkp2400si)}}}},
        {"another node's frames are not the keypad's",
         model::pk1000,
         {{0, "216#FFFFFFFFFFFFFFFF"}, {1, "416#FF"}, {2, "616#2B"}, {3, "716#00"}},
         {}},
        // J1939 (docs/checker.md, "J1939"): frames of the PKP2600SI and PKP1600SI J1939 manuals.
        {"J1939: EF00h to the keypad without 04 1B, and a command byte no keypad has (section 4); "
         "another device's proprietary A to another address is none of the keypad's",
         model::pkp2600si,
         {{0, "18EF2100#0102030405060708"},
          {10, "18EF2100#041B55FFFFFFFFFF"},
          {20, "18EF3000#0102030405060708"},
          {30, "18EF2100#041B021FFFFFFFFF"}},
         {{1, pk::j1939_bad_header, {0x18EF2100, 0x010203, 0}},
          {2, pk::j1939_bad_header, {0x18EF2100, 0x041B55, 0}}}},
        {"J1939: multiple LEDs (7b) before 37h 02h (13), once; after 37h 00h again",
         model::pkp2600si,
         {{0, "18A72100#222222222222FFFF"},
          {10, "18A62100#000000007700FFFF"},
          {20, "18EF2100#041B3702FFFFFFFF"},
          {30, "18A72100#222222222222FFFF"},
          {40, "18EF2100#041B3700FFFFFFFF"},
          {50, "18A72100#222222222222FFFF"},
          {60, "18A62100#000000007700FFFF"}},
         {{1, pk::j1939_multiple_leds_off, {0x18A72100, 0, 0}},
          {6, pk::j1939_multiple_leds_off, {0x18A72100, 5, 0}}}},
        {"J1939: after 70h moved the keypad to 02h (16), an LED command (7a) to 21h; to 30h until "
         "a keypad speaks from there",
         model::pkp2600si,
         {{0, "18EF2100#041B700201FFFFFF"},
          {10, "18EF0200#041B0101010100FF"},
          {20, "18EF2100#041B0101010100FF"},
          {30, "18EF3000#041B0101010100FF"},
          {40, "18EFFF30#041B01010130FFFF"},
          {50, "18EF3000#041B0101010100FF"}},
         {{3, pk::j1939_no_keypad, {0x18EF2100, 0x21, 0x02}},
          {4, pk::j1939_no_keypad, {0x18EF3000, 0x30, 0x02}}}},
        {"J1939: frames to the keypad that decode refuses; the keypad's own are counted only",
         model::pkp1600si,
         {{0, "18EF2100#041B0107010100FF"},
          {10, "18EF2100#041B02"},
          {20, "18EFFF21#041B01070121FFFF"},
          {30, "18EFFF21#041B01020121FFFF"},
          {40, "18EFFF21#041B01020021FFFF"},
          {50, "18EFFF21#041B01030121FFFF"},
          {60, "18EFFF21#041B01030021FFFF"},
          {70, "18EF2100#041B0102010100FF"},
          {80, "18EF2100#041B0103010100FF"}},
         {{1,
           pk::refused_frame,
           {static_cast<std::uint32_t>(errc::value_out_of_range), 0x18EF2100, 8}},
          {2, pk::refused_frame, {static_cast<std::uint32_t>(errc::wrong_length), 0x18EF2100, 3}}}},
        // Issue 21: the J1939 keypad's periodic frames and address claims.
        {"J1939: heartbeat silence longer than 75h allows (section 21: 500 ms)",
         model::pkp2600si,
         {{0, "18EF2100#041B750132FFFFFF"},
          {10, "18EFFF21#041BF9038000FF21"},
          {500, "18EFFF21#041BF9038000FF21"},
          {1300, "18EF2100#041B0220FFFFFFFF"}},
         {{4, pk::heartbeat_silence, {800, 500, 3}}}},
        {"J1939: another keypad's heartbeat is not the followed keypad's",
         model::pkp2600si,
         {{0, "18EF2100#041B750132FFFFFF"},
          {10, "18EFFF21#041BF9038000FF21"},
          {500, "18EFFF22#041BF9038000FF22"},
          {800, "18EF2100#041B0220FFFFFFFF"}},
         {{4, pk::heartbeat_silence, {790, 500, 2}}}},
        {"J1939: no heartbeat judged before the log shows 75h, nor after 75h 00h",
         model::pkp2600si,
         {{0, "18EFFF21#041BF9038000FF21"},
          {5000, "18EFFF21#041BF9038000FF21"},
          {5001, "18EF2100#041B750132FFFFFF"},
          {5010, "18EFFF21#041BF9038000FF21"},
          {5100, "18EF2100#041B7500FFFFFFFF"},
          {9000, "18EFFF21#041BF9038000FF21"}},
         {}},
        {"J1939: 80h and the keypad's address claim restart the timing at its next frame",
         model::pkp2600si,
         {{0, "18EF2100#041B750132FFFFFF"},
          {10, "18EFFF21#041BF9038000FF21"},
          {20, "18EEFF21#3F426F1A00823CC0"},
          {1000, "18EF2100#041B0220FFFFFFFF"},
          {1010, "18EFFF21#041BF9038000FF21"},
          {1100, "18EF2100#041B8000FFFFFFFF"},
          {5000, "715#00"}},
         {}},
        {"J1939: the key contact states stop while 71h enables them (sections 17, 22: 100 ms)",
         model::pkp2600si,
         {{0, "18EF2100#041B7101FFFFFFFF"},
          {10, "18EFFF21#041B01010121FFFF"},
          {100, "18EFFF21#041B01010021FFFF"},
          {300, "18EF2100#041B0220FFFFFFFF"}},
         {{4, pk::key_state_silence, {200, 100, 3}}}},
        {"J1939: no key state judged while 71h is not shown, nor after 71h 00h",
         model::pkp2600si,
         {{0, "18EF2100#041B770AFFFFFFFF"},
          {10, "18EFFF21#041B01010121FFFF"},
          {2000, "18EFFF21#041B01010021FFFF"},
          {2001, "18EF2100#041B7101FFFFFFFF"},
          {2010, "18EFFF21#041B01010121FFFF"},
          {2100, "18EF2100#041B7100FFFFFFFF"},
          {9000, "18EFFF21#041B01010021FFFF"}},
         {}},
        {"J1939: two claims of 21h with different NAMEs (section 20); the same NAME again, another "
         "address and the cannot-claim address FEh are fine",
         model::pkp2600si,
         {{0, "18EEFF21#3F426F1A00823CC0"},
          {10, "18EEFF21#3F426F1A00823CC0"},
          {20, "18EEFF21#40426F1A00823CC0"},
          {30, "18EEFF22#40426F1A00823CC0"},
          {40, "18EEFFFE#3F426F1A00823CC0"},
          {50, "18EEFFFE#40426F1A00823CC0"},
          {60, "18EEFF21#3F426F1A00823CC0"}},
         {{3, pk::j1939_address_conflict, {0x18EEFF21, 0x21, 2}},
          {7, pk::j1939_address_conflict, {0x18EEFF21, 0x21, 3}}}},
        {"J1939: keypad frames from the null address FEh and the global address FFh (J1939-81: no "
         "sender's); an address claim from FEh (cannot claim) is fine; a frame with another "
         "problem says that one",
         model::pkp2600si,
         {{0, "18EFFFFE#041B01010121FFFF"},
          {10, "18EF21FF#041B0220FFFFFFFF"},
          {20, "18EEFFFE#3F426F1A00823CC0"},
          {30, "18EF2100#041B0220FFFFFFFF"},
          {40, "18EF30FF#041B0220FFFFFFFF"},
          {50, "18EFFE00#041B0220FFFFFFFF"}},
         {{1, pk::j1939_bad_source, {0x18EFFFFE, 0xFE, 0}},
          {2, pk::j1939_bad_source, {0x18EF21FF, 0xFF, 0}},
          {5, pk::j1939_no_keypad, {0x18EF30FF, 0x30, 0x21}},
          {6, pk::j1939_no_keypad, {0x18EFFE00, 0xFE, 0x21}}}},
        {"J1939: a command the model's manual does not have (37h on a PKP-2200-SI) is refused",
         model::pkp2200si,
         {{0, "18EF2100#041B3702FFFFFFFF"}, {10, "18EF2100#041B021FFFFFFFFF"}},
         {{1,
           pk::refused_frame,
           {static_cast<std::uint32_t>(errc::unknown_command), 0x18EF2100, 8}}}},
    };
    for (const auto& r : rows) {
        INFO(std::string(r.name));
        const auto got = check(r.m, r.log);
        CHECK_MESSAGE(got == r.expected, text_of(got));
    }
}

TEST_CASE("checker: every problem kind has a test row and a name") {
    for (const auto k : enum_values<problem_kind>()) {
        CHECK(!to_string(k).empty());
        CHECK(!summary_of(k).empty());
        CHECK(problem_kinds[static_cast<std::size_t>(k)].kind == k);
    }
    CHECK(enum_values<problem_kind>().size() == 17);
    CHECK(problem_kind_count == 17);
}

TEST_CASE("checker: severities: only frames not in the manual's form are warnings") {
    static_assert(severity_of(problem_kind::not_manual_form) == severity::warning);
    static_assert(severity_of(problem_kind::refused_frame) == severity::problem);
    static_assert(severity_of(problem_kind::wrong_model) == severity::problem);
    for (const auto k : enum_values<problem_kind>())
        CHECK((severity_of(k) == severity::warning) == (k == problem_kind::not_manual_form));
    CHECK(to_string(severity::problem) == "problem");
    CHECK(to_string(severity::warning) == "warning");
}

namespace {
// A constexpr scenario (checked at compile time and at run time): a controller that trims every
// frame gets a warning per frame, counted, and no problem.
constexpr bool trimmed_controller() {
    checker<> c({model::pk1000, canopen::default_node_id});
    const std::array<can::frame, 4> log = {
        can::frame(can::standard_id{0x000}, can::dlc{8}, {0x01, 0x15}),
        can::frame(can::standard_id{0x615}, can::dlc{6}, {0x2B, 0x17, 0x10, 0x00, 0xF4, 0x01}),
        can::frame(can::standard_id{0x595}, can::dlc{8}, {0x60, 0x17, 0x10}),
        can::frame(can::standard_id{0x515}, can::dlc{2}, {0x3F, 0x01})};
    std::uint32_t line = 0;
    std::size_t warnings = 0, problems = 0;
    for (const auto& f : log) {
        ++line;
        for (const auto& p : c.step(f, millis{line * 10}, line))
            (severity_of(p.kind) == severity::warning ? warnings : problems) += 1;
    }
    problems += c.finish(millis{100}).size();
    return warnings == 3 && problems == 0 && c.count(problem_kind::not_manual_form) == 3 &&
           c.keypad_frames() == 4 && c.refused_frames() == 0;
}
}  // namespace

TEST_CASE("checker: a controller that trims its frames has warnings, not problems") {
    static_assert(trimmed_controller());
    CHECK(trimmed_controller());
}

TEST_CASE("checker: a clean controller session has no problem") {
    // A PK1000 at 15h: boot-up, the model read (PK1000 35), the heartbeat (29), the start (4),
    // the LEDs (12, 13), heartbeats and key states, a brightness PDO (14).
    const std::vector<entry> clean = {
        {0, "715#00"},
        {2, "615#400B100000000000"},
        {3, "595#410B100007000000"},
        {4, "615#6000000000000000"},
        {5, "595#01504B3130303000"},
        {6, "615#2B17100064000000"},
        {7, "595#6017100000000000"},
        {8, "000#0115"},
        {9, "215#0000000000000000"},
        {10, "315#0000000000000000"},
        {106, "715#05"},
        {206, "715#05"},
        {250, "195#0100000002"},
        {251, "215#0100000000000000"},
        {306, "715#05"},
        {380, "195#0000000003"},
        {381, "215#0000000000000000"},
        {382, "415#1000000000000000"},
        {406, "715#05"},
        {506, "715#05"},
    };
    const auto got = check(model::pk1000, clean);
    CHECK_MESSAGE(got.empty(), text_of(got));
}

TEST_CASE("checker: the keypads' string padding is not a size error (E-CORE-2, E-CORE-5)") {
    // PKP 22 as the manual prints it: 7 bytes announced, "PKU2400" and a NUL sent.
    const std::vector<entry> log = {{0, "615#400B100000000000"}, {1, "595#410B100007000000"},
                                    {2, "615#6000000000000000"}, {3, "595#00504B5532343030"},
                                    {4, "615#7000000000000000"}, {5, "595#1D00000000000000"}};
    const auto got = check(model::pkp2400, log);
    CHECK_MESSAGE(got.empty(), text_of(got));
}

TEST_CASE("checker: periods and timeout from the configuration") {
    checker_config cfg;
    cfg.heartbeat_period = duration_ms{100};  // set before the log starts
    cfg.sdo_timeout = duration_ms{1000};
    const std::vector<entry> log = {{0, "715#05"},
                                    {10, "615#4011200000000000"},
                                    {300, "715#05"},
                                    {310, "595#4F11200001000000"}};
    const auto got = check(model::pk1000, log, cfg);
    REQUIRE(got.size() == 1);
    CHECK(got[0] == problem{3, pk::heartbeat_silence, {300, 100, 1}});
}

TEST_CASE("checker: explanations") {
    struct row {
        problem p;
        std::string_view text;
    };
    const row rows[] = {
        {{3, pk::sdo_overlap, {2, 0x2014, 0}},
         "SDO request sent while the request of line 2 (2014h/0) is unanswered: the keypad drops "
         "it (one request at a time)"},
        {{2, pk::sdo_no_reply, {0x2011, 0, 490}},
         "SDO request 2011h/0 never answered (490 ms without a reply)"},
        {{3, pk::sdo_abort, {0x0602'0000, 0x1001, 0}},
         "the keypad aborted 1001h/0 with 06020000h: object does not exist in the object "
         "dictionary"},
        {{3, pk::sdo_abort, {0x1234'5678, 0x1001, 0}},
         "the keypad aborted 1001h/0 with 12345678h: a code CiA 301 does not define"},
        {{2, pk::pdo_not_operational, {0x215, 0x7F, 0}},
         "PDO 215h sent while the keypad is pre_operational: it ignores PDOs until an NMT start"},
        {{5, pk::heartbeat_silence, {200, 100, 4}},
         "no heartbeat for 200 ms since line 4, the configured period is 100 ms"},
        {{6, pk::key_state_silence, {150, 50, 5}},
         "no key state for 150 ms since line 5, the configured period is 50 ms"},
        {{3, pk::old_node_traffic, {0x615, 0x15, 0x3A}},
         "frame 615h to the old node id 15h: the keypad moved to 3Ah and does not answer it"},
        {{3, pk::segment_toggle, {0, 1, 0}},
         "segment request with toggle bit 1, expected 0: the keypad aborts with 05030000h"},
        {{4, pk::segment_toggle, {0, 1, 1}},
         "segment response with toggle bit 1, expected 0: the keypad repeated or skipped a "
         "segment"},
        {{4, pk::segment_size, {9, 7, 0x100B}},
         "segmented upload of 100Bh announced 9 bytes and sent 7"},
        {{2, pk::refused_frame, {static_cast<std::uint32_t>(errc::size_mismatch), 0x615, 8}},
         "frame 615h of 8 bytes refused (size_mismatch): the keypad does not act on it"},
        {{2, pk::refused_frame, {static_cast<std::uint32_t>(errc::wrong_length), 0x415, 1}},
         "frame 415h of 1 byte refused (wrong_length): the keypad does not act on it"},
        {{2, pk::refused_frame, {0xEE, 0x18EF2100, 8}},
         "frame 18EF2100h of 8 bytes refused (an unknown error): the keypad does not act on it"},
        {{2, pk::wrong_model, {13, 58, static_cast<std::uint32_t>(model::pkp2400)}},
         "13 of 58 keypad frames refused as pkp2400 frames: the keypad is likely another model"},
        {{2, pk::not_manual_form, {0x615, 6, 1}},
         "frame 615h of 6 bytes is trimmed, not the manual's form: read as the manual's form, as "
         "the keypads do"},
        {{2, pk::not_manual_form, {0x000, 8, 2}},
         "frame 000h of 8 bytes is padded, not the manual's form: read as the manual's form, as "
         "the keypads do"},
        {{1, pk::j1939_bad_header, {0x18EF2100, 0x010203, 0}},
         "J1939 frame 18EF2100h to keypad 21h has header 0102h, not 041Bh: the keypad does not "
         "act on it"},
        {{2, pk::j1939_bad_header, {0x18EF2100, 0x041B55, 0}},
         "J1939 frame 18EF2100h to keypad 21h has command byte 55h, which no keypad has: the "
         "keypad does not act on it"},
        {{1, pk::j1939_multiple_leds_off, {0x18A72100, 0, 0}},
         "J1939 frame 18A72100h (multiple LEDs) while LED management 37h is single LED only (the "
         "default): the keypad ignores it until 37h 02h"},
        {{6, pk::j1939_multiple_leds_off, {0x18A62100, 5, 0}},
         "J1939 frame 18A62100h (multiple LEDs) while LED management 37h is single LED only (line "
         "5): the keypad ignores it until 37h 02h"},
        {{3, pk::j1939_no_keypad, {0x18EF2100, 0x21, 0x02}},
         "J1939 frame 18EF2100h to address 21h, which no keypad holds (the keypad is at 02h): "
         "nobody acts on it"},
        {{3, pk::j1939_address_conflict, {0x18EEFF21, 0x21, 2}},
         "J1939 frame 18EEFF21h claims address 21h, which line 2 claimed with another NAME: two "
         "devices want one address"},
        {{1, pk::j1939_bad_source, {0x18EFFFFE, 0xFE, 0}},
         "J1939 frame 18EFFFFEh is sent from FEh, the null address, which sends only the address "
         "claim of a device that cannot claim one (J1939-81)"},
        {{2, pk::j1939_bad_source, {0x18EF21FF, 0xFF, 0}},
         "J1939 frame 18EF21FFh is sent from FFh, the global address, which is no sender's "
         "(J1939-81)"},
    };
    for (const auto& r : rows) {
        std::array<char, 160> buf{};
        const auto t = explain(r.p, buf);
        REQUIRE(t.has_value());
        CHECK(*t == r.text);
    }
    std::array<char, 10> small{};
    CHECK(explain(rows[0].p, small).error() == errc::buffer_too_small);
    // Every CiA 301 code has a meaning.
    for (const auto c : enum_values<canopen::sdo_abort_code>())
        CHECK(!abort_meaning_of(static_cast<std::uint32_t>(c)).empty());
}

TEST_CASE("checker: a time that goes back restarts the timers") {
    // Two logs in a row: the second starts at 0 again; no silence of 49 days.
    const std::vector<entry> log = {{0, "615#2B17100064000000"},
                                    {1, "595#6017100000000000"},
                                    {100, "715#05"},
                                    {200, "715#05"},
                                    {50, "715#05"},
                                    {150, "715#05"}};
    const auto got = check(model::pk1000, log);
    CHECK_MESSAGE(got.empty(), text_of(got));
    // The same in J1939: the heartbeat of 75h (500 ms) and the key states of 71h (100 ms).
    const std::vector<entry> j1939 = {
        {0, "18EF2100#041B750132FFFFFF"},   {1, "18EF2100#041B7101FFFFFFFF"},
        {10, "18EFFF21#041BF9038000FF21"},  {500, "18EFFF21#041BF9038000FF21"},
        {501, "18EFFF21#041B01010121FFFF"}, {50, "18EF2100#041B0220FFFFFFFF"},
        {150, "18EFFF21#041B01010021FFFF"}, {250, "18EFFF21#041B01010121FFFF"},
        {350, "18EFFF21#041B01010021FFFF"}, {450, "18EFFF21#041B01010121FFFF"},
        {540, "18EFFF21#041BF9038000FF21"}, {550, "18EFFF21#041B01010021FFFF"}};
    const auto got_j1939 = check(model::pkp2600si, j1939);
    CHECK_MESSAGE(got_j1939.empty(), text_of(got_j1939));
}

TEST_CASE("checker: the last claims of 16 J1939 addresses are kept, the oldest given up") {
    // 17 addresses claimed with the manuals' NAME (section 20), then 01h and 11h with another:
    // 01h was forgotten for 11h, which is still known.
    std::vector<std::string> frames;
    for (unsigned a = 1; a <= 0x11; ++a) {
        std::array<char, 3> hex{};
        std::snprintf(hex.data(), hex.size(), "%02X", a);
        frames.push_back("18EEFF" + std::string(hex.data()) + "#3F426F1A00823CC0");
    }
    frames.push_back("18EEFF01#40426F1A00823CC0");
    frames.push_back("18EEFF11#40426F1A00823CC0");
    std::vector<entry> log;
    for (std::size_t i = 0; i < frames.size(); ++i)
        log.push_back({static_cast<std::uint32_t>(10 * i), frames[i]});
    CHECK(check(model::pkp2600si, log) ==
          std::vector<problem>{{19, pk::j1939_address_conflict, {0x18EEFF11, 0x11, 17}}});
}

TEST_CASE("checker: NMT pre-operational, reset node and reset communication stop the PDOs") {
    // PK1000 5, 6 (CiA 301 reset communication 82h): the keypad is pre-operational afterwards
    // and ignores PDOs until the next NMT start (PK1000 11).
    for (const std::string_view nmt : {"000#8015", "000#8115", "000#8215", "000#8000"}) {
        CAPTURE(std::string(nmt));
        const auto ps =
            check(model::pk1000,
                  {{0, "715#00"}, {5, "000#0115"}, {10, nmt}, {20, "215#0100000000000000"}});
        REQUIRE(ps.size() == 1);
        CHECK(ps[0] == problem{4, problem_kind::pdo_not_operational, {0x215, 0x7F, 0}});
    }
    // An NMT command to another node changes nothing.
    CHECK(check(model::pk1000,
                {{0, "715#00"}, {5, "000#0115"}, {10, "000#8016"}, {20, "215#0100000000000000"}})
              .empty());
}

TEST_CASE("checker: after the host's abort the next request is no overlap and none is unanswered") {
    CHECK(check(model::pk1000, {{0, "715#00"},
                                {10, "615#4008100000000000"},
                                {11, "615#8008100000000405"},
                                {20, "615#4011200000000000"},
                                {21, "595#4F11200001000000"},
                                {900, "715#7F"}})
              .empty());
}

// Each timer of the checker at its boundary: the millisecond before the deadline, the deadline,
// and the one after. The SDO timeout is reached at exactly sdo_timeout (>=); the silences are
// problems only past the period and its tolerance (>); the consumer heartbeat only past 1016h's
// period (PK1000 28 note 2).
TEST_CASE("checker: every timer the millisecond before, at and after its deadline") {
    SUBCASE("the SDO timeout: 200 ms by default") {
        CHECK(checker_config{}.sdo_timeout.value == 200);
        const auto at = [](std::uint32_t ms) {
            return check(model::pk1000,
                         {{0, "715#00"}, {10, "615#4011200000000000"}, {ms, "715#7F"}});
        };
        CHECK(at(209).empty());
        CHECK(at(210) == std::vector<problem>{{2, pk::sdo_no_reply, {0x2011, 0, 200}}});
        CHECK(at(211) == std::vector<problem>{{2, pk::sdo_no_reply, {0x2011, 0, 201}}});
        // A reply within the timeout answers the request.
        CHECK(check(model::pk1000,
                    {{0, "715#00"}, {10, "615#4011200000000000"}, {209, "595#4F11200001000000"}})
                  .empty());
    }
    SUBCASE("the heartbeat: 1.5 periods of silence allowed (tolerance 50 %)") {
        checker_config cfg;
        CHECK(cfg.tolerance_percent == 50);
        cfg.heartbeat_period = duration_ms{100};
        const auto at = [&cfg](std::uint32_t ms) {
            return check(model::pk1000, {{0, "715#05"}, {ms, "080#"}}, cfg);
        };
        CHECK(at(149).empty());
        CHECK(at(150).empty());
        CHECK(at(151) == std::vector<problem>{{2, pk::heartbeat_silence, {151, 100, 1}}});
        cfg.tolerance_percent = 0;
        CHECK(at(100).empty());
        CHECK(at(101) == std::vector<problem>{{2, pk::heartbeat_silence, {101, 100, 1}}});
    }
    SUBCASE("the key state: 1.5 event-timer periods of silence allowed") {
        checker_config cfg;
        cfg.key_state_period = duration_ms{50};
        const auto at = [&cfg](std::uint32_t ms) {
            return check(model::pk1000, {{0, "000#0115"}, {10, "195#0000000001"}, {ms, "080#"}},
                         cfg);
        };
        CHECK(at(84).empty());
        CHECK(at(85).empty());
        CHECK(at(86) == std::vector<problem>{{3, pk::key_state_silence, {76, 50, 2}}});
    }
    SUBCASE("the J1939 heartbeat: 1.5 periods of 75h (section 21)") {
        const auto at = [](std::uint32_t ms) {
            return check(model::pkp2600si, {{0, "18EF2100#041B750132FFFFFF"},
                                            {10, "18EFFF21#041BF9038000FF21"},
                                            {ms, "18EF2100#041B0220FFFFFFFF"}});
        };
        CHECK(at(759).empty());
        CHECK(at(760).empty());
        CHECK(at(761) == std::vector<problem>{{3, pk::heartbeat_silence, {751, 500, 2}}});
    }
    SUBCASE("the J1939 key state: 1.5 periods, 100 ms by default (sections 17, 22)") {
        const auto at = [](std::uint32_t ms) {
            return check(model::pkp2600si, {{0, "18EF2100#041B7101FFFFFFFF"},
                                            {10, "18EFFF21#041B01010121FFFF"},
                                            {ms, "18EF2100#041B0220FFFFFFFF"}});
        };
        CHECK(at(159).empty());
        CHECK(at(160).empty());
        CHECK(at(161) == std::vector<problem>{{3, pk::key_state_silence, {151, 100, 2}}});
    }
    SUBCASE("the J1939 key state: 1.5 periods of 77h (1 s, section 22)") {
        const auto at = [](std::uint32_t ms) {
            return check(model::pkp1600si, {{0, "18EF2100#041B7764FFFFFFFF"},
                                            {1, "18EF2100#041B7101FFFFFFFF"},
                                            {10, "18EFFF21#041B01010121FFFF"},
                                            {ms, "18EF2100#041B021FFFFFFFFF"}});
        };
        CHECK(at(1509).empty());
        CHECK(at(1510).empty());
        CHECK(at(1511) == std::vector<problem>{{4, pk::key_state_silence, {1501, 1000, 3}}});
    }
    SUBCASE("the consumer heartbeat (1016h): LEDs ignored only past its period") {
        const auto at = [](std::uint32_t ms) {
            return check(model::pk1000, {{0, "615#2316100164007E00"},
                                         {1, "595#6016100100000000"},
                                         {2, "000#0115"},
                                         {10, "77E#05"},
                                         {ms, "215#0100000000000000"}});
        };
        CHECK(at(109).empty());
        CHECK(at(110).empty());
        CHECK(at(111) == std::vector<problem>{{5, pk::pdo_not_operational, {0x215, 0x7F, 0}}});
    }
}

// The four timers share one silence_timer (clock.hpp): each says a silence once, says the next
// silence again once the keypad has spoken in between, restarts on a time that goes back, and a
// J1939 setting restarts its check at the keypad's next frame (docs/checker.md).
TEST_CASE("checker: each silence said once, the next one again; restarts") {
    SUBCASE("the CANopen heartbeat") {
        checker_config cfg;
        cfg.heartbeat_period = duration_ms{100};
        const auto got = check(model::pk1000,
                               {{0, "715#05"},
                                {200, "080#"},
                                {300, "080#"},  // the same silence: said once
                                {310, "715#05"},
                                {500, "080#"}},  // a new silence
                               cfg);
        CHECK(got == std::vector<problem>{{2, pk::heartbeat_silence, {200, 100, 1}},
                                          {5, pk::heartbeat_silence, {190, 100, 4}}});
    }
    SUBCASE("the CANopen key state") {
        checker_config cfg;
        cfg.key_state_period = duration_ms{50};
        const auto got = check(model::pk1000,
                               {{0, "000#0115"},
                                {10, "195#0000000001"},
                                {100, "080#"},
                                {150, "080#"},
                                {160, "195#0000000002"},
                                {300, "080#"}},
                               cfg);
        CHECK(got == std::vector<problem>{{3, pk::key_state_silence, {90, 50, 2}},
                                          {6, pk::key_state_silence, {140, 50, 5}}});
        // Two logs in a row: the key state's silence counts from the second log's first time.
        const auto back =
            check(model::pk1000,
                  {{0, "000#0115"}, {1000, "195#0000000001"}, {50, "080#"}, {100, "080#"}}, cfg);
        CHECK_MESSAGE(back.empty(), text_of(back));
    }
    SUBCASE("the J1939 heartbeat (75h, 500 ms)") {
        const auto got = check(model::pkp2600si, {{0, "18EF2100#041B750132FFFFFF"},
                                                  {10, "18EFFF21#041BF9038000FF21"},
                                                  {770, "18EF2100#041B0220FFFFFFFF"},
                                                  {800, "18EF2100#041B0220FFFFFFFF"},
                                                  {810, "18EFFF21#041BF9038000FF21"},
                                                  {1570, "18EF2100#041B0220FFFFFFFF"}});
        CHECK(got == std::vector<problem>{{3, pk::heartbeat_silence, {760, 500, 2}},
                                          {6, pk::heartbeat_silence, {760, 500, 5}}});
        // A 75h again: the silence counts from the keypad's next heartbeat, not the last one.
        const auto again = check(model::pkp2600si, {{0, "18EF2100#041B750132FFFFFF"},
                                                    {10, "18EFFF21#041BF9038000FF21"},
                                                    {600, "18EF2100#041B750132FFFFFF"},
                                                    {800, "18EF2100#041B0220FFFFFFFF"},
                                                    {810, "18EFFF21#041BF9038000FF21"},
                                                    {1570, "18EF2100#041B0220FFFFFFFF"}});
        CHECK(again == std::vector<problem>{{6, pk::heartbeat_silence, {760, 500, 5}}});
    }
    SUBCASE("the J1939 key state (71h, 100 ms)") {
        const auto got = check(model::pkp2600si, {{0, "18EF2100#041B7101FFFFFFFF"},
                                                  {10, "18EFFF21#041B01010121FFFF"},
                                                  {170, "18EF2100#041B0220FFFFFFFF"},
                                                  {200, "18EF2100#041B0220FFFFFFFF"},
                                                  {210, "18EFFF21#041B01010021FFFF"},
                                                  {370, "18EF2100#041B0220FFFFFFFF"}});
        CHECK(got == std::vector<problem>{{3, pk::key_state_silence, {160, 100, 2}},
                                          {6, pk::key_state_silence, {160, 100, 5}}});
    }
}
