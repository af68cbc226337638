// Adding a keypad is a row (docs/models.md, "Adding a keypad"): this translation unit, a program
// of its own, appends one made-up keypad to the model table and nothing else, and every part of
// the library serves it: the name tables, the codec (its LED maps by the one rule with its own
// stride, its key bits, its dictionary's SDOs), the virtual keypad (boot-up, key presses, the
// strings it reports), describe() and the session.
//
// The made-up keypad: a 6-key keypad of the LI generation on the PKP-LI dictionary, RGB LEDs by
// the LI rule (stride = keys), reporting "PKU2306" in 100Bh. No such keypad is sold.
#define POWERKEY_EXTRA_MODELS(X)                                                                 \
    X(pku2306, .manual = "PKU-2306 (made up)", .dictionary = dict::pkp_li, .keys = 6, .leds = 6, \
      .planes = 3, .stride = 6, .led_mask = 0x3F,                                                \
      .strings = {blinkmarine_pkp, pkp_hardware, pkp_software,                                   \
                  pkp_model_name("PKU2306\0"sv, "made up for tests/extra_model.cpp"),            \
                  pkp_device_model("PKU2306\0"sv, "made up for tests/extra_model.cpp"),          \
                  pkp_serial})

#include <doctest/doctest.h>
#include <powerkey/powerkey.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace {
using namespace powerkey;
using powerkey::behaviour::millis;
using powerkey::can::candump;
constexpr canopen::node_id node = canopen::default_node_id;
constexpr model made_up = model::pku2306;

// The frame of a message, as candump text.
std::string frame_of(const message& m) {
    const auto f = encode(node, made_up, m);
    REQUIRE(f.has_value());
    return std::string(can::format_candump(*f).view());
}

TEST_CASE("a made-up keypad is one row: its names") {
    CHECK(model_count == 14);
    CHECK(to_string(made_up) == "pku2306");
    CHECK(from_string<model>("pku2306") == made_up);
    CHECK(parse_model("PKU-2306") == result<model>(made_up));
    CHECK(model_from_report("PKU2306") == result<model>(made_up));
    CHECK(enum_values<model>().back() == made_up);
    const auto row = info(made_up);
    REQUIRE(row.has_value());
    CHECK(row->manual == "PKU-2306 (made up)");
    CHECK(row->reported() == "PKU2306");
    CHECK(model_set::all().contains(made_up));
}

TEST_CASE("a made-up keypad is one row: the codec reads and builds its frames") {
    // Key 6 pressed: bit 5 of the key-state PDO; key 7 is a bit the keypad does not have.
    const auto keys = decode(candump("195#2000000007"), node, made_up);
    REQUIRE(keys.has_value());
    CHECK(pressed_keys(*keys) == key_set{6});
    CHECK(decode(candump("195#4000000007"), node, made_up) == errc::reserved_not_zero);
    // The LI rule with stride 6: red 1..6 bits 0..5, green bits 6..11, blue bits 12..17; red 1
    // is bit 0, green 6 bit 11, blue 2 bit 13.
    leds l;
    l.set(1, colour::red).set(6, colour::green).set(2, colour::blue);
    CHECK(frame_of(led_on{l}) == "215#0128000000000000");
    const auto back = decode(candump("215#0128000000000000"), node, made_up);
    REQUIRE(back.has_value());
    CHECK(*back == message{led_on{l}});
    // An LED past the sixth, in any plane, is refused.
    CHECK(decode(candump("215#0000040000000000"), node, made_up) == errc::reserved_not_zero);
    // Its dictionary's objects: 6001h carries the three planes (18 bits fit 32).
    CHECK(frame_of(sdo_write{object::led_on, leds_value(l)}) == "615#2301600001280000");
    CHECK(decode(candump("615#2301600000000400"), node, made_up) == errc::reserved_not_zero);
    // The command module takes keys 1..6.
    command c;
    c.code = command_code::set_led_state;
    c.key = 6;
    c.state = led_state::green_on;
    CHECK(frame_of(c) == "615#2300650101060400");
    c.key = 7;
    CHECK(encode(node, made_up, c) == errc::value_out_of_range);
}

TEST_CASE("a made-up keypad is one row: the virtual keypad answers for it") {
    behaviour::virtual_keypad<> k(made_up);
    std::vector<std::string> out;
    auto drain = [&] {
        while (const auto f = k.transmit()) out.emplace_back(can::format_candump(*f).view());
    };
    k.power_on(millis{0});
    drain();
    CHECK(out == std::vector<std::string>{"715#00"});
    out.clear();
    k.receive(candump("000#0115"), millis{1});  // NMT start
    CHECK(k.press(6, millis{2}));
    CHECK_FALSE(k.press(7, millis{2}));
    k.advance(millis{3});
    drain();
    REQUIRE_FALSE(out.empty());
    CHECK(out.back().substr(0, 12) == "195#20000000");
    // The string it reports: 100Bh, 7 bytes announced (as the PKP-2400's, E-CORE-2).
    out.clear();
    k.receive(candump("615#400B100000000000"), millis{10});
    k.advance(millis{20});
    drain();
    CHECK(out == std::vector<std::string>{"595#410B100007000000"});
}

TEST_CASE("a made-up keypad is one row: describe and the session") {
    const auto m = decode(candump("195#2000000007"), node, made_up);
    REQUIRE(m.has_value());
    std::array<char, 160> buf{};
    const auto text = describe(*m, node, buf);
    REQUIRE(text.has_value());
    CHECK(*text == "node 15h  key state  keys: 6  tick: 7");
    session<> s(made_up, node);
    CHECK(s.step(candump("615#4000610200000000")).sdo == sdo_pairing::request);  // 6100h sub 2
    CHECK(s.step(candump("595#4000610208000000")).sdo == sdo_pairing::reply);
}
}  // namespace
