// The description writer: generated from kind and fields, into a caller's buffer.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/describe.hpp>

#include "decoder_rows.hpp"

#include <array>
#include <cstdint>
#include <string_view>

namespace {
using namespace powerkey;
constexpr canopen::node_id keypad = canopen::default_node_id;

// A message shaped like the profiles' LED maps, to pin the example of the issue.
struct led_on_like {
    static constexpr std::string_view kind = "pkp_led_on";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("red", self.red);
        f("green", self.green);
        f("blue", self.blue);
    }
    index_set<8> red{1, 7};
    index_set<8> green{};
    index_set<8> blue{};
};

template <class M>
constexpr bool describes(const M& m, std::string_view expected) {
    std::array<char, 160> buf{};
    const auto r = describe(m, keypad, buf);
    return r.has_value() && *r == expected;
}

struct describe_row {
    std::string_view frame;
    std::string_view text;
};
constexpr describe_row rows[] = {
    {"000#0115", "node 15h  NMT  command: start  target: 21"},
    {"715#00", "node 15h  heartbeat  state: boot_up"},
    {"080#", "node 15h  sync"},
    {"615#4008100000000000", "node 15h  SDO upload  index: 1008h  subindex: 0"},
    {"595#1772696E65000000",
     "node 15h  SDO segment response  toggle: yes  unused: 3  last: yes  data: 72 69 6E 65 00 00 "
     "00"},
    {"595#8001100000000206",
     "node 15h  SDO abort response  index: 1001h  subindex: 0  code: object_does_not_exist"},
    {"595#8001100001000206",
     "node 15h  SDO abort response  index: 1001h  subindex: 0  code: 06020001h"},
    {"18EF2100#041B8000FFFFFFFF",
     "node 15h  J1939 switch to canopen  priority: 6  destination: 33  source: 0"},
};

constexpr bool every_row() {
    for (const auto& r : rows) {
        const auto m = core::decode(can::parse_candump(r.frame).value(), keypad);
        if (!m || !describes(*m, r.text)) return false;
    }
    return true;
}
static_assert(every_row());
static_assert(describes(led_on_like{}, "node 15h  LED on  red: 1 7  green: -  blue: -"));
// Three or more in a row are a range; two are not.
static_assert(describes(led_on_like{{1, 2, 3, 5, 6}, {1, 2, 3, 4, 5, 6, 7, 8}, {8}},
                        "node 15h  LED on  red: 1-3 5 6  green: 1-8  blue: 8"));
}  // namespace

TEST_CASE("descriptions of the core messages") {
    CHECK(every_row());
    for (const auto& r : rows) {
        CAPTURE(r.frame);
        const auto m = core::decode(can::parse_candump(r.frame).value(), keypad);
        REQUIRE(m.has_value());
        std::array<char, 160> buf{};
        const auto text = describe(*m, keypad, buf);
        REQUIRE(text.has_value());
        CHECK(*text == r.text);
    }
    CHECK(describes(led_on_like{}, "node 15h  LED on  red: 1 7  green: -  blue: -"));
}

TEST_CASE("a buffer too small is an error, and nothing is written past it") {
    std::array<char, 12> buf{};
    buf.back() = '!';
    const auto r = describe(core::message{canopen::sync_message{}}, keypad,
                            std::span<char>(buf.data(), buf.size() - 1));
    CHECK(r == errc::buffer_too_small);
    CHECK(buf.back() == '!');
    std::array<char, 14> exact{};  // "node 15h  sync": no terminator needed
    const auto fits = describe(core::message{canopen::sync_message{}}, keypad, exact);
    REQUIRE(fits.has_value());
    CHECK(*fits == "node 15h  sync");
}

TEST_CASE("every core row has a description that fits 160 characters") {
    for (const auto& r : decoder_rows::core_rows) {
        std::array<char, 160> buf{};
        CAPTURE(r.frame);
        CHECK(describe(r.expected, keypad, buf).has_value());
    }
}
