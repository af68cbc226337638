// The codec on the core rows (the frames every keypad speaks whatever its dictionary): decoding
// and encoding both ways per model, classification of foreign frames, malformed frames; and the
// model-independent accessors, which answer from every manual row as its PDO's fields do.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/keypad/accessors.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/names.hpp>

#include <iterator>
#include <optional>
#include <string>
#include <variant>

#include "codec_rows.hpp"
#include "pk1000_rows.hpp"
#include "pkp_rows.hpp"
#include "support.hpp"

namespace {
using namespace powerkey;
using namespace codec_rows;
using powerkey_tests::check_rows;
using powerkey_tests::first_failing;
using powerkey_tests::frame_of;
constexpr canopen::node_id keypad = canopen::default_node_id;

static_assert(first_failing(core_rows, round_trips) == std::size(core_rows));
static_assert(first_failing(core_error_rows, refused) == std::size(core_error_rows));

// Classified as the row says, of no concern to keypad 15h, refused by every model.
constexpr bool foreign(const foreign_row& r) {
    const auto f = frame_of(r.frame);
    if (!(canopen::classify(f) == r.cls) || canopen::concerns(canopen::classify(f), keypad))
        return false;
    return for_models(all, [&](model m) { return decode(f, keypad, m) == r.error; });
}
static_assert(first_failing(foreign_rows, foreign) == std::size(foreign_rows));

static_assert(canopen::classify(can::candump("615#00")) ==
              canopen::cob_info{canopen::function::sdo_rx, 0x15});
static_assert(canopen::classify(can::candump("18EF2100#00")) ==
              canopen::cob_info{canopen::function::j1939, 0});
static_assert(canopen::classify(can::candump("00000615#00")) ==
              canopen::cob_info{canopen::function::j1939, 0});
static_assert(parse_model("pkp2400") == model::pkp2400);
static_assert(parse_model("PKP-2400-LI") == model::pkp2400);
static_assert(parse_model("pkp2500") == errc::value_out_of_range);
static_assert(kind_of(message{canopen::sync_message{}}) == "sync_message");

// --- the accessors against the rows
// ---------------------------------------------------------------

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

constexpr bool accessors_agree(const row& r) {
    return for_models(r.models, [&](model m) {
        const auto d = decode(frame_of(r.frame), node_of(r.node), m);
        if (!d) return false;
        return pressed_keys(*d) == want_keys(*d) && led_on_map(*d, m) == want_map(*d, true, m) &&
               led_blink_map(*d, m) == want_map(*d, false, m);
    });
}
static_assert(first_failing(core_rows, accessors_agree) == std::size(core_rows));
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
}  // namespace

TEST_CASE("core rows decode to their meaning and encode back to the same bytes, per model") {
    check_rows(core_rows, round_trips);
}

TEST_CASE("frames of another node or function are classified and refused") {
    check_rows(foreign_rows, foreign);
}

TEST_CASE("malformed frames of the keypad give the precise error, per model") {
    check_rows(core_error_rows, refused);
}

TEST_CASE("pressed_keys, led_on_map and led_blink_map answer every row as its fields do") {
    check_rows(core_rows, accessors_agree);
    check_rows(pk1000_rows::rows, accessors_agree);
    check_rows(pkp_rows::rows, accessors_agree);
}

TEST_CASE("a read reply of keys answers pressed_keys as the key-state PDO does") {
    CHECK(keys_alike(model::pk1000, {1, 4, 10}));
    CHECK(keys_alike(model::pkp2200, {1, 4}));
    CHECK(keys_alike(model::pkp2400, {2, 7, 8}));
    CHECK(keys_alike(model::pkp2600, {9, 12}));
    // PK1000 16: 2000h/1 keys 4, 8, 9; PKP 14: 6000h keys 2, 6 on a PKP-2400.
    const auto pk = decode(frame_of("595#4B00200188010000"), keypad, model::pk1000);
    REQUIRE(pk.has_value());
    CHECK(pressed_keys(*pk) == key_set{4, 8, 9});
    const auto p2400 = decode(frame_of("595#4300600022000000"), keypad, model::pkp2400);
    REQUIRE(p2400.has_value());
    CHECK(pressed_keys(*p2400) == key_set{2, 6});
    CHECK_FALSE(pressed_keys(message{sdo_read{object::keys}}).has_value());
}

TEST_CASE("an abort keeps its direction") {
    const auto from_client = frame_of("615#8008100000000405");
    const auto from_keypad = frame_of("595#8008100000000405");
    for (std::size_t i = 0; i < model_count; ++i) {
        const auto m = static_cast<model>(i);
        CAPTURE(to_string(m));
        const auto a = decode(from_client, keypad, m);
        const auto b = decode(from_keypad, keypad, m);
        REQUIRE(a.has_value());
        REQUIRE(b.has_value());
        CHECK(kind_of(*a) == "sdo_abort_request");
        CHECK(kind_of(*b) == "sdo_abort_response");
        CHECK(encode(keypad, m, *a) == from_client);
        CHECK(encode(keypad, m, *b) == from_keypad);
    }
}

TEST_CASE("model names") {
    for (const auto m : enum_values<model>()) CHECK(parse_model(to_string(m)) == m);
    CHECK(parse_model("PK1000") == model::pk1000);
    CHECK(model_from_report("PKU2400") == model::pkp2400);
    CHECK(parse_model("") == errc::value_out_of_range);
}

// A PKP-2600's 6001h/6002h carry red and green only (model_info::object_planes() == 2): a frame
// that sets them leaves blue as it was, so the update covers red and green only. The PK1000's LED
// PDOs cover its two planes, LEDs 1..28.
TEST_CASE("led_on_map and led_blink_map cover the LEDs the frame states on the model") {
    for (const auto& r : pkp_rows::rows) {
        if (!applies(r.models, model::pkp2600)) continue;
        const auto d = decode(frame_of(r.frame), node_of(r.node), model::pkp2600);
        REQUIRE(d.has_value());
        const auto* w = std::get_if<sdo_write>(&*d);
        const auto* v = std::get_if<sdo_read_reply>(&*d);
        const object o = w ? w->object : v ? v->object : object::keys;
        if (o != object::led_on && o != object::led_blink) continue;
        INFO(std::string(r.section), "  ", std::string(r.frame));
        const auto u = o == object::led_on ? led_on_map(*d, model::pkp2600)
                                           : led_blink_map(*d, model::pkp2600);
        REQUIRE(u.has_value());
        CHECK(u->covered.red == span(1, 12));
        CHECK(u->covered.green == span(1, 12));
        CHECK(u->covered.blue.empty());
    }
    const auto pdo = decode(frame_of("215#0000010000000008"), keypad, model::pk1000);
    REQUIRE(pdo.has_value());
    const auto u = led_on_map(*pdo, model::pk1000);
    REQUIRE(u.has_value());
    CHECK(u->covered.red == span(1, 28));
    CHECK(u->covered.green == span(1, 28));
    CHECK(u->covered.blue.empty());
}
