// keypad/accessors.hpp: the common questions answered from whichever frame carries the answer:
// pressed keys, LED maps (and the LEDs a frame covers), brightness, backlight, node id, NMT state,
// each from every carrier of the dictionaries and nullopt from every other message; the LED and
// key accessors against every manual row; and the tutorial's firmware loop, byte for byte.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/can/frame.hpp>
#include <powerkey/keypad/accessors.hpp>
#include <powerkey/keypad/codec.hpp>

#include "codec_rows.hpp"
#include "pk1000_rows.hpp"
#include "pkp_rows.hpp"
#include "support.hpp"

#include <array>
#include <cstdint>
#include <iterator>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace {
using namespace powerkey;
using namespace powerkey_tests;
constexpr canopen::node_id keypad = canopen::default_node_id;

// One carrier of a fact: the frame, the model it is decoded for, and what the accessor answers.
template <class T>
struct carrier {
    std::string_view section;
    std::string_view frame;
    model keypad_model;
    std::optional<T> expected;
};

// The accessor's answer for a row: accessors of LED maps also take the model.
template <class T, class Accessor>
constexpr bool answers(const carrier<T>& r, Accessor get) {
    const auto m = decode(frame_of(r.frame), keypad, r.keypad_model);
    if (!m) return false;
    if constexpr (std::is_invocable_v<Accessor, const message&>)
        return get(*m) == r.expected;
    else
        return get(*m, r.keypad_model) == r.expected;
}
template <class T, std::size_t N, class Accessor>
constexpr std::size_t first_wrong(const carrier<T> (&rows)[N], Accessor get) {
    return first_failing(rows, [get](const carrier<T>& r) { return answers(r, get); });
}
template <class T, std::size_t N, class Accessor>
void check_carriers(const carrier<T> (&rows)[N], Accessor get) {
    powerkey_tests::check_rows(rows, [get](const carrier<T>& r) { return answers(r, get); });
}

// Messages that carry none of the facts, on each model.
constexpr std::string_view unrelated_pk1000[] = {
    "000#0115",
    "080#",
    "615#4003200100000000",
    "595#6003200100000000",
    "615#2F03200520000000",  // default_led_brightness: after the next power on, not now
    "615#2F03200620000000",  // default_backlight_level
    "615#2F03200407000000",  // default_backlight_colour
    "595#4B17100064000000",
    "18EF2100#041B8000FFFFFFFF",
    "595#8001100000000206",
};
constexpr std::string_view unrelated_pkp[] = {
    "000#0115",
    "080#",
    "615#4001620100000000",
    "595#6001620100000000",
    "615#230065017C200000",  // command 7Ch: default LED brightness
    "615#230065017B200000",  // command 7Bh: default backlight level
    "615#230065017D070000",  // command 7Dh: default backlight colour
    "615#2300650110010000",  // command 10h: active on startup
};

// --- pressed keys -----------------------------------------------------------------------------
constexpr carrier<key_set> key_rows[] = {
    {"PK1000 11", "195#090000002A", model::pk1000, key_set{1, 4}},
    {"PK1000 16", "595#4B00200100020000", model::pk1000, key_set{10}},
    {"PK1000 16", "595#4B00200188010000", model::pk1000, key_set{4, 8, 9}},
    {"PKP 10", "195#040000002A", model::pkp2400, key_set{3}},
    {"PKP 14", "595#4300600003000000", model::pkp2400, key_set{1, 2}},
    {"PKP 14", "595#4300600022000000", model::pkp2400, key_set{2, 6}},
    {"PKP-2600", "195#000800002A", model::pkp2600, key_set{12}},
    {"PKP3500-MT 11", "195#004100002A", model::pkp3500mt, key_set{9, 15}},
    {"not a read reply", "615#4000200100000000", model::pk1000, std::nullopt},
    {"sync", "080#", model::pk1000, std::nullopt},
};
static_assert(first_wrong(key_rows, pressed_keys) == std::size(key_rows));

// --- LED maps -----------------------------------------------------------------------------------
// LEDs 1..n of one plane; the LEDs a frame covers.
constexpr led_set upto(unsigned n) {
    led_set s;
    for (unsigned k = 1; k <= n; ++k) s.insert(k);
    return s;
}
constexpr leds pk_all{upto(28), upto(28), {}};
constexpr leds pk_red{upto(28), {}, {}};
constexpr leds pk_green{{}, upto(28), {}};
constexpr leds p24_all{upto(8), upto(8), upto(8)};

constexpr carrier<led_map_update> led_on_rows[] = {
    {"PK1000 12: the PDO covers both planes", "215#0400000004000000", model::pk1000,
     led_map_update{{{3}, {3}, {}}, pk_all}},
    {"PK1000 17: 2001h sub 1, the red plane", "615#2301200104000000", model::pk1000,
     led_map_update{{{3}, {}, {}}, pk_red}},
    {"PK1000 17: 2001h sub 2, the green plane", "615#2301200204000000", model::pk1000,
     led_map_update{{{}, {3}, {}}, pk_green}},
    {"PK1000 17: a read reply of 2001h sub 1", "595#4301200104000000", model::pk1000,
     led_map_update{{{3}, {}, {}}, pk_red}},
    {"PKP 11: the PDO", "215#0004000000000000", model::pkp2400,
     led_map_update{{{}, {3}, {}}, p24_all}},
    {"PKP 15: 6001h, three planes of a PKP-2400", "615#2301600004040400", model::pkp2400,
     led_map_update{{{3}, {3}, {3}}, p24_all}},
    {"PKP 15: a read reply of 6001h", "595#4301600001000000", model::pkp2400,
     led_map_update{{{1}, {}, {}}, p24_all}},
    {"PKP-2600 6001h: red and green only", "615#2301600040404000", model::pkp2600,
     led_map_update{{{7}, {3, 11}, {}}, {upto(12), upto(12), {}}}},
    {"PKP2600SI 17: 2001h sub 2 carries G5..G12", "615#2F01200240000000", model::pkp2600si,
     led_map_update{{{}, {11}, {}}, {{}, led_set{5, 6, 7, 8, 9, 10, 11, 12}, {}}}},
    {"PKP3500-MT 20 a: 2001h sub 3, the blue plane (no LEDs 1, 11)", "615#2B01200300400000",
     model::pkp3500mt,
     led_map_update{{{}, {}, {15}}, {{}, {}, led_set{2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 13, 14, 15}}}},
    {"the blink PDO is no LED-on map", "315#0400000000000000", model::pk1000, std::nullopt},
    {"2002h is no LED-on map", "615#2302200104000000", model::pk1000, std::nullopt},
};
static_assert(first_wrong(led_on_rows, led_on_map) == std::size(led_on_rows));

constexpr carrier<led_map_update> led_blink_rows[] = {
    {"PK1000 13: the PDO", "315#0200000000000000", model::pk1000,
     led_map_update{{{2}, {}, {}}, pk_all}},
    {"PK1000 18: 2002h sub 2, the green plane", "615#2302200202000000", model::pk1000,
     led_map_update{{{}, {2}, {}}, pk_green}},
    {"PKP 16: 6002h", "615#2302600000000400", model::pkp2400,
     led_map_update{{{}, {}, {3}}, p24_all}},
    {"the LED-on PDO is no blink map", "215#0400000000000000", model::pk1000, std::nullopt},
};
static_assert(first_wrong(led_blink_rows, led_blink_map) == std::size(led_blink_rows));

// --- brightness ----------------------------------------------------------------------------------
constexpr level quarter = 0x10;
constexpr level half = 0x20;
constexpr carrier<level> brightness_rows[] = {
    {"PK1000 14: the 400h PDO", "415#2000000000000000", model::pk1000, half},
    {"PK1000 19 a: write 2003h sub 1", "615#2F03200120000000", model::pk1000, half},
    {"PK1000 19 a: read reply of 2003h sub 1", "595#4F03200120000000", model::pk1000, half},
    {"PKP 30: write 6201h sub 1", "615#2F01620110000000", model::pkp2400, quarter},
    {"PKP 30: read reply of 6201h sub 1", "595#4F01620110000000", model::pkp2400, quarter},
    {"PKP 13 b: command 02h", "615#2300650102100000", model::pkp2400, quarter},
    {"the backlight level is no LED brightness", "615#2F03200220000000", model::pk1000,
     std::nullopt},
    {"command 03h is the backlight", "615#2300650103100000", model::pkp2400, std::nullopt},
};
static_assert(first_wrong(brightness_rows, led_brightness_level) == std::size(brightness_rows));

// --- backlight -----------------------------------------------------------------------------------
constexpr carrier<backlight_update> backlight_rows[] = {
    {"PK1000 15: level, colour keep: no colour", "515#2000000000000000", model::pk1000,
     backlight_update{half, std::nullopt}},
    {"PK1000 15: level and blue", "515#2003000000000000", model::pk1000,
     backlight_update{half, backlight_colour::blue}},
    {"PK1000 19 b: write backlight_level", "615#2F03200220000000", model::pk1000,
     backlight_update{half, std::nullopt}},
    {"PK1000 19 c: write backlight_colour", "615#2F03200307000000", model::pk1000,
     backlight_update{std::nullopt, backlight_colour::white}},
    {"PK1000 19 c: read reply of backlight_colour", "595#4F03200308000000", model::pk1000,
     backlight_update{std::nullopt, backlight_colour::amber}},
    {"PK1000 19 c, E-PK-2: the reply labelled cyan carries 04h, yellow; the bytes win",
     "595#4F03200304000000", model::pk1000,
     backlight_update{std::nullopt, backlight_colour::yellow}},
    {"PKP 30: write 6201h sub 2", "615#2F01620210000000", model::pkp2400,
     backlight_update{quarter, std::nullopt}},
    {"PKP 13 b: command 03h", "615#2300650103100000", model::pkp2400,
     backlight_update{quarter, std::nullopt}},
    {"PKP 13 c: command 04h", "615#2300650104070000", model::pkp2400,
     backlight_update{std::nullopt, backlight_colour::white}},
    {"the LED brightness is no backlight", "415#2000000000000000", model::pk1000, std::nullopt},
};
static_assert(first_wrong(backlight_rows, backlight_change) == std::size(backlight_rows));

// --- node id, NMT state --------------------------------------------------------------------------
constexpr canopen::node_id node_3a = 0x3A;
constexpr canopen::node_id node_18 = 0x18;
constexpr canopen::node_id node_19 = 0x19;
constexpr carrier<canopen::node_id> node_rows[] = {
    {"PK1000 23: write 2013h", "615#2F1320003A000000", model::pk1000, node_3a},
    {"PKP 13 h: command 70h", "615#2300650170180000", model::pkp2400, node_18},
    {"PKP3500-MT 29: write 2013h", "615#2F13200019000000", model::pkp3500mt, node_19},
    {"a read of 2013h moves nothing", "615#4013200000000000", model::pk1000, std::nullopt},
    {"a read reply of 2013h moves nothing", "595#4F1320003A000000", model::pk1000, std::nullopt},
    {"the acknowledgement moves nothing", "595#6013200000000000", model::pk1000, std::nullopt},
};
static_assert(first_wrong(node_rows, node_id_change) == std::size(node_rows));

constexpr carrier<canopen::nmt_state> nmt_rows[] = {
    {"PK1000 29: operational", "715#05", model::pk1000, canopen::nmt_state::operational},
    {"PK1000 8: boot-up", "715#00", model::pk1000, canopen::nmt_state::boot_up},
    {"PKP 9: pre-operational", "715#7F", model::pkp2400, canopen::nmt_state::pre_operational},
    {"an NMT command is not the keypad's state", "000#0115", model::pk1000, std::nullopt},
};
static_assert(first_wrong(nmt_rows, reported_nmt_state) == std::size(nmt_rows));

template <std::size_t N>
constexpr bool none_answers(model m, const std::string_view (&frames)[N]) {
    for (const auto text : frames) {
        const auto msg = decode(frame_of(text), keypad, m);
        if (!msg) return false;
        if (pressed_keys(*msg) || led_on_map(*msg, m) || led_blink_map(*msg, m) ||
            led_brightness_level(*msg) || backlight_change(*msg) || node_id_change(*msg) ||
            reported_nmt_state(*msg))
            return false;
    }
    return true;
}
static_assert(none_answers(model::pk1000, unrelated_pk1000));
static_assert(none_answers(model::pkp2400, unrelated_pkp));

// --- the LED and key accessors against every manual row -----------------------------------------

// For every model of the row, the accessors answer from the decoded message what its fields say:
// pressed_keys from a key-state PDO or a read reply of `keys`; led_on_map and led_blink_map from
// an LED PDO (every plane of the model) or a write or read reply of an LED object (the planes it
// carries), covering the model's LEDs of those planes; nothing from any other message.
constexpr std::uint8_t planes_of(object o, const model_info& mi) {
    switch (o) {
        case object::led_on:
        case object::led_blink: return mi.object_planes() == 2 ? 3 : 7;  // red, green (, blue)
        case object::led_on_red:
        case object::led_blink_red: return 1;
        case object::led_on_green:
        case object::led_blink_green: return 2;
        default: return 0;
    }
}
constexpr bool is_on(object o) {
    return o == object::led_on || o == object::led_on_red || o == object::led_on_green;
}
constexpr leds covering(std::uint8_t planes, const model_info& mi) {
    leds c;
    if (planes & 1) c.red = led_set::from_mask(mi.led_mask);
    if (planes & 2) c.green = led_set::from_mask(mi.led_mask);
    if (planes & 4) c.blue = led_set::from_mask(mi.led_mask);
    return c;
}

constexpr std::optional<led_map_update> want_map(const message& m, bool on, model md) {
    const auto mi = *info(md);
    const std::uint8_t all = mi.planes == 2 ? 3 : 7;
    if (const auto* p = std::get_if<powerkey::led_on>(&m); p && on)
        return led_map_update{p->map, covering(all, mi)};
    if (const auto* p = std::get_if<powerkey::led_blink>(&m); p && !on)
        return led_map_update{p->map, covering(all, mi)};
    auto of = [on, &mi](object o, const object_value& v) -> std::optional<led_map_update> {
        if (planes_of(o, mi) == 0 || is_on(o) != on) return std::nullopt;
        return led_map_update{v.map, covering(planes_of(o, mi), mi)};
    };
    if (const auto* w = std::get_if<sdo_write>(&m)) return of(w->object, w->value);
    if (const auto* r = std::get_if<sdo_read_reply>(&m)) return of(r->object, r->value);
    return std::nullopt;
}

constexpr std::optional<key_set> want_keys(const message& m) {
    if (const auto* k = std::get_if<key_state>(&m)) return k->keys;
    if (const auto* r = std::get_if<sdo_read_reply>(&m); r && r->object == object::keys)
        return key_set::from_mask(r->value.raw);
    return std::nullopt;
}

constexpr bool accessors_agree(const codec_rows::row& r) {
    return codec_rows::for_models(r.models, [&](model m) {
        const auto d = decode(frame_of(r.frame), codec_rows::node_of(r.node), m);
        if (!d) return false;
        return pressed_keys(*d) == want_keys(*d) && led_on_map(*d, m) == want_map(*d, true, m) &&
               led_blink_map(*d, m) == want_map(*d, false, m);
    });
}
static_assert(first_failing(codec_rows::core_rows, accessors_agree) ==
              std::size(codec_rows::core_rows));
static_assert(first_failing(pk1000_rows::rows, accessors_agree) == std::size(pk1000_rows::rows));
static_assert(first_failing(pkp_rows::rows, accessors_agree) == std::size(pkp_rows::rows));

// The same keys, whichever frame carries them: the key-state PDO and the read reply of `keys`
// (PK1000 2000h/1, PKP 6000h) answer pressed_keys alike, on every model.
constexpr bool keys_alike(model m, key_set k) {
    const auto pdo = decode(*encode(keypad, m, key_state{k, 0}), keypad, m);
    const auto sdo =
        decode(*encode(keypad, m, sdo_read_reply{object::keys, keys_value(k)}), keypad, m);
    return pdo && sdo && pressed_keys(*pdo) == k && pressed_keys(*sdo) == k;
}
static_assert(keys_alike(model::pk1000, {1, 4, 10}));
static_assert(keys_alike(model::pkp2200, {1, 4}));
static_assert(keys_alike(model::pkp2400, {2, 7, 8}));
static_assert(keys_alike(model::pkp2600, {9, 12}));

// --- the tutorial's firmware loop ---------------------------------------------------------------
// A key-state frame arrives as the raw id and bytes a CAN driver hands over; every pressed key
// lights its LED green. Returns the LED-on frame to send.
constexpr result<can::frame> firmware_step(model m, std::uint32_t rx_id,
                                           std::span<const std::uint8_t> rx_data) {
    const auto f = can::make_frame(rx_id, rx_data);
    if (!f) return f.error();
    const auto msg = decode(*f, keypad, m);
    if (!msg) return msg.error();
    const auto keys = pressed_keys(*msg);
    if (!keys) return errc::unexpected_frame;
    leds map;
    for (unsigned k = 1; k <= 16; ++k)
        if (keys->contains(k)) map.set(k, colour::green);
    return encode(keypad, m, led_on{map});
}

constexpr std::array<std::uint8_t, 5> key3_pressed{0x04, 0x00, 0x00, 0x00, 0x2A};
static_assert(firmware_step(model::pk1000, 0x195, key3_pressed).value() ==
              can::candump("215#0000000004000000"));
static_assert(firmware_step(model::pkp2400, 0x195, key3_pressed).value() ==
              can::candump("215#0004000000000000"));
}  // namespace

TEST_CASE("pressed keys from the key-state PDO and from a read of the keys object") {
    check_carriers(key_rows, pressed_keys);
}

TEST_CASE("LED maps from the PDOs and from the LED objects, with the planes each sets") {
    check_carriers(led_on_rows, led_on_map);
    check_carriers(led_blink_rows, led_blink_map);
}

TEST_CASE(
    "brightness from the PDO, SDO writes and read replies of both dictionaries, command 02h") {
    check_carriers(brightness_rows, led_brightness_level);
}

TEST_CASE("backlight from the PDO, the SDO objects and commands 03h/04h") {
    check_carriers(backlight_rows, backlight_change);
}

TEST_CASE("node id changes and NMT states") {
    check_carriers(node_rows, node_id_change);
    check_carriers(nmt_rows, reported_nmt_state);
}

TEST_CASE("every other message answers none of the questions") {
    CHECK(none_answers(model::pk1000, unrelated_pk1000));
    CHECK(none_answers(model::pkp2400, unrelated_pkp));
}

TEST_CASE("the firmware loop: a key press lights that key's LED green") {
    struct rx {
        model m;
        std::uint32_t id;
        std::array<std::uint8_t, 5> data;
        std::string_view sent;
    };
    const rx loop[] = {
        {model::pk1000, 0x195, {0x04, 0, 0, 0, 0x2A}, "215#0000000004000000"},
        {model::pkp2400, 0x195, {0x04, 0, 0, 0, 0x2A}, "215#0004000000000000"},
        {model::pk1000, 0x195, {0x01, 0x02, 0, 0, 0x2B}, "215#0000000001020000"},   // keys 1, 10
        {model::pkp2200, 0x195, {0x08, 0, 0, 0, 0x01}, "215#8000000000000000"},     // key 4
        {model::pkp2600, 0x195, {0x00, 0x08, 0, 0, 0x01}, "215#0000800000000000"},  // key 12
        {model::pk1000, 0x195, {0, 0, 0, 0, 0x2C}, "215#0000000000000000"},  // released: all off
    };
    for (const auto& r : loop) {
        CAPTURE(r.sent);
        const auto sent = firmware_step(r.m, r.id, r.data);
        REQUIRE(sent.has_value());
        CHECK(format_candump(*sent).view() == r.sent);
    }
    // A frame that is no key state gives no LED frame.
    const std::array<std::uint8_t, 1> boot{0x00};
    CHECK(firmware_step(model::pk1000, 0x715, boot) == errc::unexpected_frame);
    // Another node's key state is refused.
    CHECK(firmware_step(model::pk1000, 0x196, key3_pressed) == errc::wrong_id);
}

TEST_CASE("pressed_keys, led_on_map and led_blink_map answer every manual row as its fields do") {
    powerkey_tests::check_rows(codec_rows::core_rows, accessors_agree);
    powerkey_tests::check_rows(pk1000_rows::rows, accessors_agree);
    powerkey_tests::check_rows(pkp_rows::rows, accessors_agree);
}

TEST_CASE("a read reply of keys answers pressed_keys as the key-state PDO does") {
    CHECK(keys_alike(model::pk1000, {1, 4, 10}));
    CHECK(keys_alike(model::pkp2200, {1, 4}));
    CHECK(keys_alike(model::pkp2400, {2, 7, 8}));
    CHECK(keys_alike(model::pkp2600, {9, 12}));
}

// A PKP-2600's 6001h/6002h carry red and green only (model_info::object_planes() == 2): a frame
// that sets them leaves blue as it was, so the update covers red and green only. The PK1000's LED
// PDOs cover its two planes, LEDs 1..28.
TEST_CASE("led_on_map and led_blink_map cover the LEDs the frame states on the model") {
    for (const auto& r : pkp_rows::rows) {
        if (!r.models.contains(model::pkp2600)) continue;
        const auto d = decode(frame_of(r.frame), codec_rows::node_of(r.node), model::pkp2600);
        REQUIRE(d.has_value());
        const auto* w = std::get_if<sdo_write>(&*d);
        const auto* v = std::get_if<sdo_read_reply>(&*d);
        const object o = w ? w->object : v ? v->object : object::keys;
        if (o != object::led_on && o != object::led_blink) continue;
        INFO(std::string(r.section), "  ", std::string(r.frame));
        const auto u = o == object::led_on ? led_on_map(*d, model::pkp2600)
                                           : led_blink_map(*d, model::pkp2600);
        REQUIRE(u.has_value());
        CHECK(u->covered.red == upto(12));
        CHECK(u->covered.green == upto(12));
        CHECK(u->covered.blue.empty());
    }
    const auto pdo = decode(frame_of("215#0000010000000008"), keypad, model::pk1000);
    REQUIRE(pdo.has_value());
    const auto u = led_on_map(*pdo, model::pk1000);
    REQUIRE(u.has_value());
    CHECK(u->covered.red == upto(28));
    CHECK(u->covered.green == upto(28));
    CHECK(u->covered.blue.empty());
}
