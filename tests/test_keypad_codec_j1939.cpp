// keypad/codec.hpp on J1939 frames: the one vocabulary. Every row of tests/j1939_rows.hpp through
// powerkey::decode and powerkey::encode (any node id: a 29-bit frame is the J1939 codec's), with
// any keypad address and narrowed to the row's; the refusals the same as j1939::decode's; the
// accessors answering J1939 frames; the description bound.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/keypad/accessors.hpp>
#include <powerkey/keypad/codec.hpp>

#include "j1939_rows.hpp"
#include "support.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <variant>

namespace {
using namespace j1939_rows;
using powerkey_tests::check_rows;
using powerkey_tests::first_failing;
using powerkey_tests::frame_of;
namespace pk = powerkey;
namespace can = powerkey::can;

// Two node ids: the J1939 reading does not depend on the CANopen one.
constexpr std::array<pk::canopen::node_id, 2> nodes = {pk::canopen::node_id{0x15},
                                                       pk::canopen::node_id{0x21}};

constexpr bool round_trips_in_vocabulary(const j1939_rows::row& r) {
    const auto f = can::parse_candump(r.frame);
    if (!f) return false;
    const pk::message expected = pk::to_message(r.expected);
    return for_models(r.models, [&](model m) {
        for (const auto node : nodes) {
            const auto d = pk::decode(*f, node, m);
            if (!d || !(*d == expected)) return false;
            if (pk::form_of(*d) != pk::frame_form::manual) return false;
            const auto e = pk::encode(node, m, expected);
            if (!e || !(*e == *f)) return false;
            const auto narrowed = pk::decode(*f, node, m, keypad_address{r.keypad});
            if (!narrowed || !(*narrowed == expected)) return false;
            const auto e2 = pk::encode(node, m, expected, keypad_address{r.keypad});
            if (!e2 || !(*e2 == *f)) return false;
        }
        return true;
    });
}

// A refusal of the J1939 codec is the vocabulary's too (29-bit rows: an 11-bit frame is a CANopen
// one there), with the tolerant and the strict reading.
constexpr bool refused_in_vocabulary(const j1939_rows::error_row& r) {
    const auto f = can::parse_candump(r.frame);
    if (!f) return false;
    if (!f->is_extended()) return true;
    return for_models(r.models, [&](model m) {
        return pk::decode(*f, nodes[0], m, r.keypad) == r.error &&
               pk::decode(*f, nodes[0], m, r.keypad, pk::reading::strict) == r.error;
    });
}

constexpr bool encode_refused_in_vocabulary(const j1939_rows::encode_error_row& r) {
    return for_models(r.models, [&](model m) {
        return pk::encode(nodes[0], m, pk::to_message(r.msg), r.keypad) == r.error;
    });
}

static_assert(powerkey_tests::all_rows_pass<
              first_failing(pkp1600si_rows, round_trips_in_vocabulary), std::size(pkp1600si_rows)>);
static_assert(powerkey_tests::all_rows_pass<first_failing(error_rows, refused_in_vocabulary),
                                            std::size(error_rows)>);

constexpr pk::canopen::node_id node15{0x15};

constexpr pk::message decoded(std::string_view frame, model m = model::pkp1600si) {
    return *pk::decode(*can::parse_candump(frame), node15, m);
}

// --- the accessors ------------------------------------------------------------------------------

constexpr auto key3_down = "18EFFF21#041B01030121FFFF";
constexpr auto key3_up = "18EFFF21#041B01030021FFFF";
constexpr auto beat_key4 = "18EFFF21#041BF9030800FF21";
// The decoded frames (named: get_if on a temporary is no constant expression for g++).
constexpr pk::message msg0 = decoded(key3_down);
constexpr pk::message msg1 = decoded(key3_up);
constexpr pk::message msg2 = decoded(beat_key4);
constexpr pk::message msg3 = decoded("18EF2100#041B021FFFFFFFFF");
constexpr pk::message msg4 = decoded("18EF2100#041B033FFFFFFFFF");
constexpr pk::message msg5 = decoded("18EF2100#041B7C3FFFFFFFFF");
constexpr pk::message msg6 = decoded("18EF2100#041B7B1FFFFFFFFF");
constexpr pk::message msg7 = decoded("18EF2100#041B70FDFDFFFFFF");
constexpr pk::message msg8 = decoded("18EF2100#041B70FF05FFFFFF");
constexpr pk::message msg9 = decoded("18EF2100#041B0102010100FF");
constexpr pk::message msg10 = decoded("18EF2100#041B8000FFFFFFFF");

// PKP1600SI 6: key 3 pressed, then released (one key: the others are not in the frame).
static_assert(pk::pressed_keys(msg0) == key_set{3});
static_assert(pk::pressed_keys(msg1) == key_set{});
static_assert(pk::key_change(msg0, model::pkp1600si) == pk::key_update{key_set{3}, key_set{3}});
static_assert(pk::key_change(msg1, model::pkp1600si) == pk::key_update{key_set{}, key_set{3}});
// PKP1600SI 21: the heartbeat says every key (key 4 down).
static_assert(pk::pressed_keys(msg2) == key_set{4});
static_assert(pk::key_change(msg2, model::pkp1600si) ==
              pk::key_update{key_set{4}, key_set{1, 2, 3, 4, 5, 6}});
// The same fact from a CANopen key-state PDO (PKP section 10 layout, keys 2 and 7).
constexpr pk::message key_state_pdo =
    *pk::decode(can::candump("195#42000000FE"), node15, model::pkp2400);
static_assert(pk::pressed_keys(key_state_pdo) == key_set{2, 7});
// PKP1600SI 8, 9: LED brightness and backlight level now; 24, 25 are defaults, no change now.
static_assert(pk::led_brightness_level(msg3) == pk::level{0x1F});
static_assert(pk::backlight_change(msg4) == pk::backlight_update{pk::level{0x3F}, std::nullopt});
static_assert(pk::led_brightness_level(msg5) == std::nullopt);
static_assert(pk::backlight_change(msg6) == std::nullopt);
// PKP1600SI 16: the keypad moves to address FDh; FFh keeps the address.
static_assert(pk::address_change(msg7) == std::uint8_t{0xFD});
static_assert(pk::address_change(msg8) == std::nullopt);
static_assert(pk::node_id_change(msg7) == std::nullopt);
// An LED command answers no LED-map accessor (colours, not planes).
static_assert(!pk::led_on_map(msg9, model::pkp1600si));

// The J1939 kinds in the one vocabulary: "j1939_" before the struct's name.
static_assert(pk::kind_of(msg0) == "j1939_key_contact");
static_assert(pk::kind_of(msg10) == "j1939_switch_to_canopen");

// The longest description: an address claim with every NAME field at its widest, at node 7Fh.
constexpr std::size_t widest_claim_description() {
    pk::j1939::address_claimed a{.source = 0xFD, .destination = 0xFF, .priority = 7, .name = {}};
    a.name = {0x1F'FFFF, 0x7FF, 7, 0x1F, 0xFF, 0x7F, 0xF, 7, true};
    std::array<char, pk::description_capacity> buf{};
    const auto text = pk::describe(pk::message{a}, pk::canopen::node_id{0x7F}, buf);
    return text ? text->size() : 0;
}
static_assert(widest_claim_description() == 288);
static_assert(widest_claim_description() <= pk::description_capacity);

bool describes_within_capacity(const j1939_rows::row& r) {
    const auto f = frame_of(r.frame);
    return for_models(r.models, [&](model m) {
        const auto d = pk::decode(f, node15, m);
        std::array<char, pk::description_capacity> buf{};
        return d && pk::describe(*d, node15, buf).has_value();
    });
}
}  // namespace

TEST_CASE("j1939 frames in the one vocabulary: every manual row both ways") {
    check_rows(pkp1600si_rows, round_trips_in_vocabulary);
    check_rows(pkp2600si_rows, round_trips_in_vocabulary);
    check_rows(other_rows, round_trips_in_vocabulary);
}

TEST_CASE("j1939 frames in the one vocabulary: the J1939 codec's refusals") {
    check_rows(error_rows, refused_in_vocabulary);
    check_rows(encode_error_rows, encode_refused_in_vocabulary);
    // Another PGN is not a keypad frame; narrowed to 30h, keypad 21h's frame is another keypad's.
    CHECK(pk::decode(frame_of("18FEF100#FFFFFFFFFFFFFFFF"), node15, model::pkp1600si) ==
          pk::errc::wrong_id);
    CHECK(pk::decode(frame_of(key3_down), node15, model::pkp1600si, keypad_address{0x30}) ==
          pk::errc::wrong_id);
    // The switch to the global address: refused by both decoders (docs/j1939.md).
    CHECK(pk::decode(frame_of("18EFFF00#041B8000FFFFFFFF"), node15, model::pk1000) ==
          pk::errc::undocumented);
}

TEST_CASE("j1939 accessors and descriptions") {
    CHECK(pk::pressed_keys(decoded(key3_down)) == key_set{3});
    CHECK(pk::pressed_keys(decoded(beat_key4)) == key_set{4});
    CHECK(pk::address_change(decoded("18EF2100#041B70FDFDFFFFFF")) == std::uint8_t{0xFD});
    // widest_claim_description() is proved by its static_assert only: called at run time it
    // crashes clang 14's code generation (ConstantEmitter::tryEmitPrivate).
    check_rows(pkp1600si_rows, describes_within_capacity);
    check_rows(pkp2600si_rows, describes_within_capacity);
    check_rows(other_rows, describes_within_capacity);
}
