// fields.hpp: walking the one message type. Every struct a message can hold is visited once, has a
// kind of its own that kind_of returns for it, and its enumerator fields have names no other
// value of the same enum has (what the tool prints and `encode --json` parses).
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/names.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace {
using namespace powerkey;

// For an enum whose values fit one byte: every named value has a name no other value has.
// Returns the number of named values, or -1 on a duplicate.
template <class E>
int check_enum_names() {
    static_assert(sizeof(E) == 1);
    std::array<std::string_view, 256> names{};
    int named = 0;
    for (unsigned v = 0; v < 256; ++v) {
        names[v] = to_string(static_cast<E>(v));
        if (names[v].empty()) continue;
        ++named;
        for (unsigned w = 0; w < v; ++w)
            if (names[w] == names[v]) {
                MESSAGE("duplicate name " << names[v] << " for " << w << " and " << v);
                return -1;
            }
    }
    return named;
}

struct enum_census {
    int types = 0;
    int names = 0;
    bool duplicate = false;
};

template <class Message>
enum_census census() {
    enum_census c;
    for_each_alternative<Message>([&c]<class S>(std::type_identity<S>) {
        S s{};
        S::fields(s, [&c](std::string_view, const auto& v) {
            using F = std::remove_cvref_t<decltype(v)>;
            if constexpr (std::is_enum_v<F> && sizeof(F) == 1) {
                const int n = check_enum_names<F>();
                if (n < 0) c.duplicate = true;
                c.names += n > 0 ? n : 0;
                ++c.types;
            }
        });
        return false;
    });
    return c;
}

// Every kind once, and kind_of of a message holding S is S's kind.
template <class Message>
constexpr bool kinds_unique() {
    std::array<std::string_view, 256> kinds{};
    std::size_t n = 0;
    bool ok = true;
    for_each_alternative<Message>([&]<class S>(std::type_identity<S>) {
        for (std::size_t i = 0; i < n; ++i)
            if (kinds[i] == S::kind) ok = false;
        if (n < kinds.size()) kinds[n++] = S::kind;
        Message m{};
        ok = ok && assign_message(m, S{}) && kind_of(m) == S::kind;
        return false;
    });
    return ok && n > 0;
}
// At run time only: clang 14 cannot assign a std::variant of libstdc++ 12 to another alternative
// in a constant expression.
}  // namespace

TEST_CASE("enumerator names of every message field are unique") {
    const auto all = census<message>();
    CHECK_FALSE(all.duplicate);
    CHECK(all.types > 5);
}

TEST_CASE("message kinds are unique in the one message type, and kind_of names each") {
    CHECK(kinds_unique<message>());
    std::size_t n = 0;
    for_each_alternative<message>([&n]<class S>(std::type_identity<S>) {
        ++n;
        return false;
    });
    CHECK(n == std::variant_size_v<message>);
}

// --- every message's default-built fields, pinned ---------------------------------------------
// Each alternative of `message`, built with no argument, as describe() shows it: every field's
// default. Where a manual gives a default, the default is the manual's: the LED brightness 3Fh
// and the backlight level 00h (PK1000 section 3, "Default settings"; PK1000 14, 15), the colour
// 00h of the backlight PDO that keeps the stored colour (PK1000 15 note 2), the J1939 switch's
// priority 6 to the keypad's address 21h (PK1000 49), encoder 1 (TPDO2, MT 12); the J1939
// messages at priority 6, the keypad at its default address 21h, what it sends to the global
// address FFh and what a controller (00h) sends to it (PKP1600SI and PKP2600SI J1939 manuals).
// A kind added to `message` fails the count until its row is here.
namespace {
constexpr std::string_view default_messages[] = {
    "node 15h  NMT message  command: start  target: 00h",
    "node 15h  sync message",
    "node 15h  heartbeat message  state: boot_up",
    "node 15h  J1939 switch to CANopen  priority: 6  destination: 21h  source: 00h",
    "node 15h  key state  keys: -  tick: 0",
    "node 15h  LED on  red: -  green: -  blue: -",
    "node 15h  LED blink  red: -  green: -  blue: -",
    "node 15h  LED brightness  level: 3Fh",
    "node 15h  backlight  level: 00h  colour: keep",
    "node 15h  SDO read  object: keys",
    "node 15h  SDO read reply  object: keys  keys: -",
    "node 15h  SDO write  object: led_brightness  level: 00h",
    "node 15h  SDO write reply  object: led_brightness",
    "node 15h  command  command: set_led_state  key: 0  state: off",
    "node 15h  SDO upload initiate response  index: 0000h  subindex: 0  size_indicated: yes  size: "
    "0",
    "node 15h  SDO segment request  toggle: no",
    "node 15h  SDO segment response  toggle: no  unused: 0  last: no  data: 00 00 00 00 00 00 00",
    "node 15h  SDO abort request  index: 0000h  subindex: 0  code: general_error",
    "node 15h  SDO abort response  index: 0000h  subindex: 0  code: general_error",
    "node 15h  encoder state  encoder: 1  counterclockwise: no  ticks: 0  counter: 0  top: 0",
    "node 15h  analog inputs  in0_mv: 0  in1_mv: 0  in2_mv: 0  in3_mv: 0",
    "node 15h  encoder leds  leds: -",
    "node 15h  J1939 key contact  priority: 6  destination: FFh  source: 21h  key: 1  pressed: no  "
    "identifier: 21h",
    "node 15h  J1939 heartbeat  priority: 6  destination: FFh  source: 21h  counter: 0  keys: -  "
    "identifier: 21h",
    "node 15h  J1939 software revision  priority: 6  destination: FFh  source: 21h  bytes: 00 00 "
    "00 00 00",
    "node 15h  J1939 LED ack  priority: 6  destination: FFh  source: 21h  key: 1  mode: off  "
    "colour: off  secondary: off",
    "node 15h  J1939 LED ack code  priority: 6  destination: FFh  source: 21h  key: 1  code: 00h",
    "node 15h  J1939 address claimed  priority: 6  destination: FFh  source: 21h  identity_number: "
    "00h  manufacturer_code: 00h  ecu_instance: 00h  function_instance: 00h  function: 00h  "
    "vehicle_system: 00h  vehicle_system_instance: 00h  industry_group: 00h  "
    "arbitrary_address_capable: no",
    "node 15h  J1939 set LED  priority: 6  destination: 21h  source: 00h  key: 1  colour: off  "
    "mode: off  secondary: off",
    "node 15h  J1939 set LED code  priority: 6  destination: 21h  source: 00h  key: 1  code: 00h",
    "node 15h  J1939 multiple leds  priority: 6  destination: 21h  source: 00h  frame: 01h  red: - "
    " green: -  blue: -  yellow: -  cyan: -  violet: -  white: -  amber: -  yellow_green: -  "
    "blink: -",
    "node 15h  J1939 command  priority: 6  destination: 21h  source: 00h  command: "
    "set_led_brightness  level: 00h",
};
template <std::size_t... I>
void check_defaults(std::index_sequence<I...>) {
    (
        [] {
            const message m{std::variant_alternative_t<I, message>{}};
            std::array<char, description_capacity> buf{};
            const auto d = describe(m, canopen::default_node_id, buf);
            CAPTURE(I);
            REQUIRE(d.has_value());
            CHECK(std::string(*d) == std::string(default_messages[I]));
        }(),
        ...);
}
}  // namespace

TEST_CASE("every message built by default: its fields, pinned") {
    static_assert(std::size(default_messages) == std::variant_size_v<message>);
    check_defaults(std::make_index_sequence<std::variant_size_v<message>>{});
    // The defaults on the wire (PK1000 14, 15): full LED brightness, the backlight off.
    CHECK(encode(canopen::default_node_id, model::pk1000, led_brightness{}) ==
          can::candump("415#3F00000000000000"));
    CHECK(encode(canopen::default_node_id, model::pk1000, backlight{}) ==
          can::candump("515#0000000000000000"));
}
