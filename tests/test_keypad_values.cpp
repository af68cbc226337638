// The shared values: LED maps set with a run-time key number, colours and modes, bit rates, and
// every enum's one name table (names unique, each value reads back, aliases, "" for no name).
#include <doctest/doctest.h>

#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/error.hpp>
#include <powerkey/keypad/commands.hpp>
#include <powerkey/keypad/lookup.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/keypad/values.hpp>
#include <powerkey/names.hpp>
#include <powerkey/session.hpp>

#include "support.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>

namespace {
using namespace powerkey;

// --- LED maps ---------------------------------------------------------------------------------

// A key number known only at run time (a function argument here, a CAN frame in firmware).
constexpr leds lit(unsigned k, colour c) {
    leds l;
    l.set(k, c);
    return l;
}
static_assert(lit(3, colour::green) == leds{{}, {3}, {}});
static_assert(lit(3, colour::amber) == leds{{3}, {3}, {}});
static_assert(lit(3, colour::magenta) == leds{{3}, {}, {3}});
static_assert(lit(3, colour::cyan) == leds{{}, {3}, {3}});
static_assert(lit(32, colour::white) == leds{{32}, {32}, {32}});
// Outside 1..32 changes nothing.
static_assert(lit(0, colour::white).empty());
static_assert(lit(33, colour::white).empty());
// off clears every plane; set replaces the colour, and leaves the other keys alone.
static_assert(leds{{3, 4}, {3}, {3}}.set(3, colour::off) == leds{{4}, {}, {}});
static_assert(leds{{3}, {}, {}}.set(3, colour::blue) == leds{{}, {}, {3}});
static_assert(leds{}.set(1, colour::red).set(2, colour::green) == leds{{1}, {2}, {}});

constexpr bool every_colour_reads_back() {
    for (const colour c : enum_values<colour>())
        for (unsigned k = 1; k <= 32; ++k)
            if (lit(k, c).colour_of(k) != c || lit(k, c).colour_of(k % 32 + 1) != colour::off)
                return false;
    return true;
}
static_assert(every_colour_reads_back());
static_assert(leds{}.colour_of(0) == colour::off);

static_assert(leds{{1}, {2}, {3}}.of(plane::red) == led_set{1});
static_assert(leds{{1}, {2}, {3}}.of(plane::green) == led_set{2});
static_assert(leds{{1}, {2}, {3}}.of(plane::blue) == led_set{3});

// On and blink together blink alternately (PK1000 12, 13; PKP 12, 16).
constexpr leds on_map{{1, 3}, {}, {}};
constexpr leds blink_map{{2, 3}, {}, {}};
static_assert(mode_of(on_map, blink_map, plane::red, 1) == led_mode::on);
static_assert(mode_of(on_map, blink_map, plane::red, 2) == led_mode::blink);
static_assert(mode_of(on_map, blink_map, plane::red, 3) == led_mode::alternate_blink);
static_assert(mode_of(on_map, blink_map, plane::red, 4) == led_mode::off);
static_assert(mode_of(on_map, blink_map, plane::green, 1) == led_mode::off);

// --- bit rates (PK1000 20: the reserved codes run at 125 kbit/s) ------------------------------
static_assert(bits_per_second(baud_rate::kbit_1000) == 1'000'000);
static_assert(bits_per_second(baud_rate::kbit_500) == 500'000);
static_assert(bits_per_second(baud_rate::kbit_250) == 250'000);
static_assert(bits_per_second(baud_rate::kbit_125) == 125'000);
static_assert(bits_per_second(baud_rate::kbit_50) == 50'000);
static_assert(bits_per_second(baud_rate::kbit_20) == 20'000);
static_assert(bits_per_second(baud_rate::reserved_1) == 125'000);
static_assert(bits_per_second(baud_rate::reserved_5) == 125'000);
static_assert(bits_per_second(static_cast<baud_rate>(0xFA)) == 125'000);

// --- name tables --------------------------------------------------------------------------------

// from_string<E>(name) == v, and nullopt for a name the table lacks (errc included).
template <named_enum E>
constexpr bool reads_back(std::string_view name, E v) {
    return from_string<E>(name) == std::optional<E>(v);
}
template <named_enum E>
constexpr bool refuses(std::string_view name) {
    return !from_string<E>(name).has_value();
}
static_assert(from_string<errc>("wrong_id") == errc::wrong_id);

// Every name of the table (aliases too) names one value only; every value reads back from its
// name; a named value prints a non-empty name.
template <named_enum E>
constexpr bool table_holds() {
    const auto& t = enum_names<E>::entries;
    for (std::size_t i = 0; i < std::size(t); ++i) {
        if (t[i].name.empty()) return false;
        for (std::size_t j = 0; j < i; ++j)
            if (t[j].name == t[i].name) return false;
        if (!reads_back<E>(t[i].name, t[i].value)) return false;  // aliases too
    }
    for (const E v : enum_values<E>()) {
        if (!is_named(v)) return false;
        if (!reads_back<E>(to_string(v), v)) return false;
    }
    return refuses<E>("") && refuses<E>("no such name");
}

// For the one-byte enums: exactly the values of enum_values are named, all others print "".
template <named_enum E>
constexpr bool unnamed_print_empty() {
    if constexpr (sizeof(E) == 1) {
        std::size_t named = 0;
        for (unsigned v = 0; v < 256; ++v) {
            const auto e = static_cast<E>(v);
            bool listed = false;
            for (const E w : enum_values<E>()) listed = listed || w == e;
            if (listed != is_named(e) || listed != !to_string(e).empty()) return false;
            named += listed ? 1 : 0;
        }
        return named == enum_values<E>().size();
    } else {
        return true;
    }
}

// At compile time the table itself; the sweep over every byte value runs at run time
// (check_names below), which keeps clang's constexpr step limit out of the way for `object`.
template <named_enum E>
constexpr bool names_hold() {
    return table_holds<E>();
}

static_assert(names_hold<errc>());
static_assert(names_hold<model>());
static_assert(names_hold<object>());
static_assert(names_hold<value_kind>());
static_assert(names_hold<access>());
static_assert(names_hold<dictionary>());
static_assert(names_hold<backlight_colour>());
static_assert(names_hold<baud_rate>());
static_assert(names_hold<startup_show>());
static_assert(names_hold<led_state>());
static_assert(names_hold<plane>());
static_assert(names_hold<colour>());
static_assert(names_hold<led_mode>());
static_assert(names_hold<command_code>());
static_assert(names_hold<canopen::function>());
static_assert(names_hold<canopen::nmt_command>());
static_assert(names_hold<canopen::nmt_state>());
static_assert(names_hold<canopen::sdo_abort_code>());
static_assert(names_hold<bus_protocol>());
static_assert(names_hold<sdo_pairing>());

// The manuals' other names are aliases: they read, but the one name is what prints.
static_assert(from_string<backlight_colour>("white_light_blue").value() == backlight_colour::white);
static_assert(from_string<backlight_colour>("amber_orange").value() == backlight_colour::amber);
static_assert(to_string(backlight_colour::white) == "white");
static_assert(to_string(backlight_colour::amber) == "amber");
static_assert(from_string<baud_rate>("125k").value() == baud_rate::kbit_125);
static_assert(from_string<baud_rate>("1000k").value() == baud_rate::kbit_1000);
static_assert(to_string(baud_rate::kbit_125) == "kbit_125");
static_assert(from_string<startup_show>("amber_fast_flash").value() == startup_show::fast_flash);
static_assert(to_string(startup_show::fast_flash) == "fast_flash");
// The aliases add no value: one value per colour of the table.
static_assert(enum_values<backlight_colour>().size() == 10);
static_assert(enum_values<baud_rate>().size() == 8);
static_assert(enum_values<startup_show>().size() == 3);
static_assert(enum_values<errc>().size() == 16);
// Unnamed values print "".
static_assert(to_string(static_cast<errc>(0)).empty());
static_assert(to_string(static_cast<backlight_colour>(0x0A)).empty());
static_assert(to_string(static_cast<led_state>(0x0B)).empty());
static_assert(to_string(static_cast<command_code>(0x05)).empty());
static_assert(to_string(static_cast<canopen::sdo_abort_code>(0x1234'5678)).empty());
static_assert(to_string(static_cast<model>(model_count)).empty());
}  // namespace

TEST_CASE("an LED map set with a run-time key number") {
    for (unsigned k = 0; k <= 33; ++k) {
        CAPTURE(k);
        leds l;
        l.set(k, colour::green);
        CHECK(l.green.contains(k) == (k >= 1 && k <= 32));
        CHECK(l.red.empty());
        CHECK(l.blue.empty());
        CHECK(l.colour_of(k) == (k >= 1 && k <= 32 ? colour::green : colour::off));
    }
    CHECK(every_colour_reads_back());
    CHECK(mode_of(on_map, blink_map, plane::red, 3) == led_mode::alternate_blink);
}

template <named_enum E>
void check_names(std::string_view what) {
    CAPTURE(what);
    CHECK(table_holds<E>());
    CHECK(unnamed_print_empty<E>());
    for (const E v : enum_values<E>()) {
        CAPTURE(to_string(v));
        CHECK(reads_back<E>(to_string(v), v));
    }
}

TEST_CASE("every enum: names unique, each value reads back, unnamed values print \"\"") {
    check_names<errc>("errc");
    check_names<model>("model");
    check_names<object>("object");
    check_names<value_kind>("value_kind");
    check_names<access>("access");
    check_names<dictionary>("dictionary");
    check_names<backlight_colour>("backlight_colour");
    check_names<baud_rate>("baud_rate");
    check_names<startup_show>("startup_show");
    check_names<led_state>("led_state");
    check_names<plane>("plane");
    check_names<colour>("colour");
    check_names<led_mode>("led_mode");
    check_names<command_code>("command_code");
    check_names<canopen::function>("canopen::function");
    check_names<canopen::nmt_command>("nmt_command");
    check_names<canopen::nmt_state>("nmt_state");
    check_names<canopen::sdo_abort_code>("sdo_abort_code");
    check_names<bus_protocol>("bus_protocol");
    check_names<sdo_pairing>("sdo_pairing");
    CHECK(from_string<backlight_colour>("white_light_blue") ==
          std::optional<backlight_colour>(backlight_colour::white));
    CHECK(from_string<backlight_colour>("amber_orange") ==
          std::optional<backlight_colour>(backlight_colour::amber));
    CHECK(from_string<baud_rate>("125k") == std::optional<baud_rate>(baud_rate::kbit_125));
    CHECK(from_string<startup_show>("amber_fast_flash") ==
          std::optional<startup_show>(startup_show::fast_flash));
}

// Every dictionary a model uses has a name (the tool prints it, and enum_values<dictionary>()
// must list it for code that walks every dictionary).
TEST_CASE("every model's dictionary is named") {
    for (const model m : enum_values<model>()) {
        CAPTURE(to_string(m));
        const auto i = info(m);
        REQUIRE(i.has_value());
        CHECK(is_named(i->dictionary));
    }
}
