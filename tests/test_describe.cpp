// describe.hpp: the description writer, generated from kind and fields, into a caller's buffer.
// Numbers print in hex with h, except counts and times (tick, period_ms, size, key, subindex,
// unused, priority ...). The manuals' frames described; a buffer too small; every meaning any
// model reads from a manual row fits 160 characters; one field at a time.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/keypad/codec.hpp>

#include "codec_rows.hpp"
#include "pk1000_rows.hpp"
#include "pkp_rows.hpp"
#include "support.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace {
using namespace powerkey;
using namespace powerkey_tests;
constexpr canopen::node_id keypad = canopen::default_node_id;

// A message shaped like the LED maps, to pin the example of the issue.
struct led_on_like {
    static constexpr std::string_view kind = "led_on";
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
    std::string_view section;
    model keypad_model;
    std::string_view frame;
    std::string_view text;
};
constexpr describe_row rows[] = {
    {"PK1000 4", model::pk1000, "000#0115", "node 15h  NMT message  command: start  target: 15h"},
    {"PK1000 7", model::pk1000, "000#0015",
     "node 15h  NMT message  command: legacy_stop  target: 15h"},
    {"PK1000 8", model::pk1000, "715#00", "node 15h  heartbeat message  state: boot_up"},
    {"PK1000 10", model::pk1000, "080#", "node 15h  sync message"},
    {"PK1000 32", model::pk1000, "615#4008100000000000", "node 15h  SDO read  object: device_name"},
    {"PK1000 32", model::pk1000, "595#410810000B000000",
     "node 15h  SDO upload initiate response  index: 1008h  subindex: 0  size_indicated: yes  "
     "size: 11"},
    {"PK1000 32", model::pk1000, "595#1772696E65000000",
     "node 15h  SDO segment response  toggle: yes  unused: 3  last: yes  data: 72 69 6E 65 00 00 "
     "00"},
    {"CiA 301", model::pk1000, "595#8001100000000206",
     "node 15h  SDO abort response  index: 1001h  subindex: 0  code: object_does_not_exist"},
    {"CiA 301", model::pk1000, "595#8001100001000206",
     "node 15h  SDO abort response  index: 1001h  subindex: 0  code: 06020001h"},
    {"CiA 301", model::pk1000, "615#8000200100000405",
     "node 15h  SDO abort request  index: 2000h  subindex: 1  code: timed_out"},
    {"PK1000 49", model::pk1000, "18EF2100#041B8000FFFFFFFF",
     "node 15h  J1939 switch to CANopen  priority: 6  destination: 21h  source: 00h"},
    {"PK1000 11", model::pk1000, "195#090000002A", "node 15h  key state  keys: 1 4  tick: 42"},
    {"PK1000 12", model::pk1000, "215#0000010000000008",
     "node 15h  LED on  red: 17  green: 28  blue: -"},
    {"PK1000 13", model::pk1000, "315#FFFFFF0F00000000",
     "node 15h  LED blink  red: 1-28  green: -  blue: -"},
    {"PK1000 14", model::pk1000, "415#3F00000000000000", "node 15h  LED brightness  level: 3Fh"},
    {"PK1000 15", model::pk1000, "515#2000000000000000",
     "node 15h  backlight  level: 20h  colour: keep"},
    {"PK1000 19 a", model::pk1000, "615#2F0320013F000000",
     "node 15h  SDO write  object: led_brightness  level: 3Fh"},
    {"PK1000 23", model::pk1000, "615#2F1320003A000000",
     "node 15h  SDO write  object: node_id  node_id: 3Ah"},
    {"PK1000 23", model::pk1000, "595#6013200000000000",
     "node 15h  SDO write reply  object: node_id"},
    {"PK1000 29", model::pk1000, "595#4B17100064000000",
     "node 15h  SDO read reply  object: heartbeat_time  period_ms: 100"},
    {"PK1000 29", model::pk1000, "615#2B17100000000000",
     "node 15h  SDO write  object: heartbeat_time  period_ms: 0"},
    {"PK1000 41", model::pk1000, "595#4300180195010040",
     "node 15h  SDO read reply  object: tpdo1_cob_id  invalid: no  no_rtr: yes  can_id: 195h"},
    {"PK1000 47", model::pk1000, "595#43001A0110010020",
     "node 15h  SDO read reply  object: tpdo1_mapping_1  index: 2000h  subindex: 1  bits: 16"},
    {"PKP 11", model::pkp2400, "215#0100040000000000",
     "node 15h  LED on  red: 1  green: -  blue: 3"},
    {"PKP 13 a", model::pkp2400, "615#2300650101030400",
     "node 15h  command  command: set_led_state  key: 3  state: green_on"},
    {"PKP 13 h", model::pkp2400, "615#2300650170180000",
     "node 15h  command  command: set_node_id  node_id: 18h"},
    {"PKP 19", model::pkp2400, "595#4308100042000000",
     "node 15h  SDO read reply  object: device_name  size: 4  bytes: 42 00 00 00"},
    {"PKP 30", model::pkp2400, "615#2F01620110000000",
     "node 15h  SDO write  object: led_brightness  level: 10h"},
    {"PKP3500-MT 19 b: one tick counterclockwise", model::pkp3500mt, "595#4F00200281000000",
     "node 15h  SDO read reply  object: encoder1_direction_counter  counterclockwise: yes  "
     "ticks: 1"},
    {"PKP3500-MT 20 c: ring LED 8", model::pkp3500mt, "615#2301200480000000",
     "node 15h  SDO write  object: led_on_encoder  leds: 8"},
};

constexpr bool describes_row(const describe_row& r) {
    const auto m = decode(powerkey_tests::frame_of(r.frame), keypad, r.keypad_model);
    return m.has_value() && describes(*m, r.text);
}
static_assert(first_failing(rows, describes_row) == std::size(rows));
static_assert(describes(led_on_like{}, "node 15h  LED on  red: 1 7  green: -  blue: -"));
// Three or more in a row are a range; two are not.
static_assert(describes(led_on_like{{1, 2, 3, 5, 6}, {1, 2, 3, 4, 5, 6, 7, 8}, {8}},
                        "node 15h  LED on  red: 1-3 5 6  green: 1-8  blue: 8"));
// A message built in code, not decoded: the command's fields are its row's parameters only.
static_assert(describes(message{command{.code = command_code::set_periodic_transmission,
                                        .enabled = true,
                                        .period_10ms = 50}},
                        "node 15h  command  command: set_periodic_transmission  enabled: yes  "
                        "period_10ms: 50"));
static_assert(describes(message{sdo_read_reply{object::backlight_colour,
                                               colour_value(backlight_colour::white)}},
                        "node 15h  SDO read reply  object: backlight_colour  colour: white"));

// The description of every meaning any model reads from a manual row (the rows of the models it
// is not written for too) fits 160 characters.
bool every_meaning_fits(const codec_rows::row& r) {
    const auto f = powerkey_tests::frame_of(r.frame);
    for (std::size_t i = 0; i < model_count; ++i) {
        const auto m = static_cast<model>(i);
        const auto d = decode(f, codec_rows::node_of(r.node), m);
        if (!d) continue;
        std::array<char, 160> buf{};
        if (!describe(*d, codec_rows::node_of(r.node), buf)) return false;
    }
    return true;
}
}  // namespace

TEST_CASE("descriptions of the manual frames") {
    check_rows(rows, describes_row);
    CHECK(describes(led_on_like{}, "node 15h  LED on  red: 1 7  green: -  blue: -"));
}

TEST_CASE("a buffer too small is an error, and nothing is written past it") {
    std::array<char, 12> buf{};
    buf.back() = '!';
    const auto r = describe(message{canopen::sync_message{}}, keypad,
                            std::span<char>(buf.data(), buf.size() - 1));
    CHECK(r == errc::buffer_too_small);
    CHECK(buf.back() == '!');
    std::array<char, 22> exact{};  // "node 15h  sync message": no terminator needed
    const auto fits = describe(message{canopen::sync_message{}}, keypad, exact);
    REQUIRE(fits.has_value());
    CHECK(*fits == "node 15h  sync message");
}

TEST_CASE("every meaning a model reads from a manual row has a description of 160 characters") {
    check_rows(codec_rows::core_rows, every_meaning_fits);
    check_rows(pk1000_rows::rows, every_meaning_fits);
    check_rows(pkp_rows::rows, every_meaning_fits);
}

// One field at a time, as the tool and the Wireshark plugin show them: describe()'s own rule
// (counts and times in decimal, other numbers in hex with h, enumerators by name, sets as ranges).
constexpr std::string_view value_text(std::span<char> buf, std::string_view name, auto v) {
    text_writer w(buf);
    describe_value(w, name, v);
    return w.view();
}

TEST_CASE("describe_value writes one field as describe() does") {
    std::array<char, 40> buf{};
    CHECK(value_text(buf, "period_ms", std::uint16_t{100}) == "100");
    CHECK(value_text(buf, "supply_mv", std::uint16_t{12000}) == "12000");
    CHECK(value_text(buf, "index", std::uint16_t{0x2003}) == "2003h");
    CHECK(value_text(buf, "can_id", std::uint16_t{0x215}) == "215h");
    CHECK(value_text(buf, "level", std::uint8_t{0x20}) == "20h");
    CHECK(value_text(buf, "colour", backlight_colour::blue) == "blue");
    CHECK(value_text(buf, "colour", static_cast<backlight_colour>(0xEE)) == "EEh");
    CHECK(value_text(buf, "invalid", true) == "yes");
    CHECK(value_text(buf, "red", led_set{}) == "-");
    CHECK(value_text(buf, "red", led_set{1, 2, 3, 7}) == "1-3 7");
}

TEST_CASE("is_decimal_field: counts and times in decimal, every other number in hex") {
    for (const auto name :
         {"tick", "period_ms", "period_10ms", "size", "bits", "key", "subindex", "unused",
          "priority", "encoder", "ticks", "counter", "top", "event_timer_ms", "input_1_mv"})
        CHECK_MESSAGE(is_decimal_field(name), name);
    for (const auto name : {"level", "index", "can_id", "node_id", "target", "source", "raw", "ms"})
        CHECK_MESSAGE(!is_decimal_field(name), name);
}
