// keypad/values.hpp: the values the keypads share. LED maps: a key's colour set with a run-time
// key number, the colours as mixes of the planes (PKP sections 11, 12) and the modes of on and
// blink together (PK1000 12, 13); the bit rates of the baud-rate codes (PK1000 20); and the
// name table of every value, row by row, with the aliases the other manual's wording gives.
#include <doctest/doctest.h>

#include <powerkey/keypad/values.hpp>
#include <powerkey/names.hpp>

#include "support.hpp"

#include <cstdint>
#include <string_view>

namespace {
using namespace powerkey;
using namespace powerkey_tests;

// --- LED maps ------------------------------------------------------------------------------------

// PKP sections 11, 12: amber = red + green, magenta = red + blue, cyan = green + blue, white all.
struct colour_row {
    std::string_view section;
    std::string_view frame;  // unused
    colour c;
    bool red, green, blue;
};
constexpr colour_row colour_rows[] = {
    {"PKP 11", "", colour::off, false, false, false},
    {"PKP 11", "", colour::red, true, false, false},
    {"PKP 11", "", colour::green, false, true, false},
    {"PKP 11", "", colour::blue, false, false, true},
    {"PKP 11: amber", "", colour::amber, true, true, false},
    {"PKP 11: cyan", "", colour::cyan, false, true, true},
    {"PKP 11: magenta", "", colour::magenta, true, false, true},
    {"PKP 11: white", "", colour::white, true, true, true},
};
// set() replaces the colour of its key (key 2 is white first: set() clears what c lacks) and
// leaves the other keys alone.
constexpr bool colour_holds(const colour_row& r) {
    leds l{{1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
    l.set(2, r.c);
    const leds& cl = l;
    return cl.of(plane::red).contains(2) == r.red && cl.of(plane::green).contains(2) == r.green &&
           cl.of(plane::blue).contains(2) == r.blue && l.colour_of(2) == r.c &&
           l.colour_of(1) == colour::white && l.colour_of(3) == colour::white && l.empty() == false;
}
static_assert(powerkey_tests::all_rows_pass<first_failing(colour_rows, colour_holds),
                                            std::size(colour_rows)>);

// A key number known only at run time (a function argument here, a CAN frame in firmware).
constexpr leds lit(unsigned k, colour c) {
    leds l;
    l.set(k, c);
    return l;
}
static_assert(lit(32, colour::white) == leds{{32}, {32}, {32}});
// Outside 1..32 changes nothing; a value outside the enum sets no plane.
static_assert(lit(0, colour::white).empty());
static_assert(lit(33, colour::white).empty());
static_assert(leds{{5}, {5}, {5}}.set(5, static_cast<colour>(8)).colour_of(5) == colour::off);
static_assert(leds{}.set(1, colour::red).set(2, colour::green) == leds{{1}, {2}, {}});
static_assert(leds{}.colour_of(0) == colour::off);

constexpr bool every_colour_reads_back() {
    for (const colour c : enum_values<colour>())
        for (unsigned k = 1; k <= 32; ++k)
            if (lit(k, c).colour_of(k) != c || lit(k, c).colour_of(k % 32 + 1) != colour::off)
                return false;
    return true;
}
static_assert(every_colour_reads_back());

// PK1000 sections 12, 13: on, blink, and both = alternate blink.
struct mode_row {
    std::string_view section;
    std::string_view frame;  // unused
    bool on, blink;
    led_mode mode;
};
constexpr mode_row mode_rows[] = {
    {"PK1000 12", "", false, false, led_mode::off},
    {"PK1000 12", "", true, false, led_mode::on},
    {"PK1000 13", "", false, true, led_mode::blink},
    {"PK1000 13", "", true, true, led_mode::alternate_blink},
};
constexpr bool mode_holds(const mode_row& r) {
    leds on, blink;
    if (r.on) on.of(plane::green).insert(7);
    if (r.blink) blink.of(plane::green).insert(7);
    return mode_of(on, blink, plane::green, 7) == r.mode &&
           mode_of(on, blink, plane::red, 7) == led_mode::off &&
           mode_of(on, blink, plane::blue, 7) == led_mode::off;
}
static_assert(
    powerkey_tests::all_rows_pass<first_failing(mode_rows, mode_holds), std::size(mode_rows)>);
// PKP 12: "LED #4 blinks red and green in alternate mode" is green on, red and green blinking:
// green blinks alternately, red blinks, blue is off.
constexpr leds on4 = leds{}.set(4, colour::green);
constexpr leds blink4 = leds{}.set(4, colour::amber);
static_assert(mode_of(on4, blink4, plane::green, 4) == led_mode::alternate_blink);
static_assert(mode_of(on4, blink4, plane::red, 4) == led_mode::blink);
static_assert(mode_of(on4, blink4, plane::blue, 4) == led_mode::off);

// --- bit rates -----------------------------------------------------------------------------------

// PK1000 section 20: "01h Reserved (force to 125k)", "05h Reserved (force to 125k)".
struct rate_row {
    std::uint8_t code;
    std::uint32_t bits_per_second;
};
constexpr rate_row rate_rows[] = {{0x00, 1'000'000}, {0x01, 125'000}, {0x02, 500'000},
                                  {0x03, 250'000},   {0x04, 125'000}, {0x05, 125'000},
                                  {0x06, 50'000},    {0x07, 20'000}};
constexpr bool rates_hold() {
    for (const auto& r : rate_rows)
        if (bits_per_second(static_cast<baud_rate>(r.code)) != r.bits_per_second) return false;
    // A code outside the table: the keypad's fallback, 125k.
    return bits_per_second(static_cast<baud_rate>(0x08)) == 125'000 &&
           bits_per_second(static_cast<baud_rate>(0xFF)) == 125'000;
}
static_assert(rates_hold());

// --- names ---------------------------------------------------------------------------------------

// PK1000 sections 15, 19 c/d (2003h sub 3, 4): 01h..09h; the manual's "white/light blue" and
// "amber/orange" are aliases; 00h only in the backlight PDO, where it keeps the colour (15 note 2).
constexpr name_row backlight_colour_rows[] = {
    {"PK1000 15 note 2", 0x00, "keep"},
    {"PK1000 19 c", 0x01, "red"},
    {"PK1000 19 c", 0x02, "green"},
    {"PK1000 19 c", 0x03, "blue"},
    {"PK1000 19 c", 0x04, "yellow"},
    {"PK1000 19 c", 0x05, "cyan"},
    {"PK1000 19 c", 0x06, "violet"},
    {"PKP 13 c (white)", 0x07, "white"},
    {"PKP 13 c (amber)", 0x08, "amber"},
    {"PK1000 19 c (yellow/green)", 0x09, "yellow_green"},
    {"PK1000 19 c white/light blue", 0x07, "white_light_blue", true},
    {"PK1000 19 c amber/orange", 0x08, "amber_orange", true},
};
static_assert(name_table_is<backlight_colour>(backlight_colour_rows, 0x0A));

// PK1000 section 20 (2010h): the codes; 01h and 05h are reserved. The "1000k" .. "20k" spellings
// are the manual's, accepted as aliases.
constexpr name_row baud_rate_rows[] = {
    {"PK1000 20", 0x00, "kbit_1000"},   {"PK1000 20", 0x02, "kbit_500"},
    {"PK1000 20", 0x03, "kbit_250"},    {"PK1000 20", 0x04, "kbit_125"},
    {"PK1000 20", 0x06, "kbit_50"},     {"PK1000 20", 0x07, "kbit_20"},
    {"PK1000 20", 0x01, "reserved_1"},  {"PK1000 20", 0x05, "reserved_5"},
    {"PK1000 20", 0x00, "1000k", true}, {"PK1000 20", 0x02, "500k", true},
    {"PK1000 20", 0x03, "250k", true},  {"PK1000 20", 0x04, "125k", true},
    {"PK1000 20", 0x06, "50k", true},   {"PK1000 20", 0x07, "20k", true},
};
static_assert(name_table_is<baud_rate>(baud_rate_rows, 0x08));

// PK1000 section 24 (2014h): 00h disable, 01h complete show, 02h fast flash; the PKP manual's
// command 50h calls the last "Amber fast flash" (PKP 13 m).
constexpr name_row startup_show_rows[] = {
    {"PK1000 24", 0x00, "disabled"},
    {"PK1000 24", 0x01, "complete"},
    {"PK1000 24", 0x02, "fast_flash"},
    {"PKP 13 m", 0x02, "amber_fast_flash", true},
};
static_assert(name_table_is<startup_show>(startup_show_rows, 0x03));

// PKP section 13 a, byte 6: 00h off, 01h..09h red/green/blue on, blink, alternate blink, 0Ah
// red/green, 0Ch amber/red, 0Eh green/amber blink (0Bh, 0Dh and 0Fh are not states).
constexpr name_row led_state_rows[] = {
    {"PKP 13 a", 0x00, "off"},
    {"PKP 13 a", 0x01, "red_on"},
    {"PKP 13 a", 0x02, "red_blink"},
    {"PKP 13 a", 0x03, "red_alternate_blink"},
    {"PKP 13 a", 0x04, "green_on"},
    {"PKP 13 a", 0x05, "green_blink"},
    {"PKP 13 a", 0x06, "green_alternate_blink"},
    {"PKP 13 a", 0x07, "blue_on"},
    {"PKP 13 a", 0x08, "blue_blink"},
    {"PKP 13 a", 0x09, "blue_alternate_blink"},
    {"PKP 13 a", 0x0A, "red_green_blink"},
    {"PKP 13 a", 0x0C, "amber_red_blink"},
    {"PKP 13 a", 0x0E, "green_amber_blink"},
};
static_assert(name_table_is<led_state>(led_state_rows, 0x0B));
static_assert(!is_named(static_cast<led_state>(0x0D)) && !is_named(static_cast<led_state>(0x0F)));

// The planes of an LED map in the one LED-map rule (models.hpp): red 0, green 1, blue 2.
constexpr name_row plane_rows[] = {
    {"PK1000 12", 0, "red"}, {"PK1000 12", 1, "green"}, {"PKP 11", 2, "blue"}};
static_assert(name_table_is<plane>(plane_rows, 3));

// The colours of one key's LEDs (PKP sections 11, 12).
constexpr name_row colour_name_rows[] = {
    {"PKP 11", 0, "off"},   {"PKP 11", 1, "red"},  {"PKP 11", 2, "green"},   {"PKP 11", 3, "blue"},
    {"PKP 11", 4, "amber"}, {"PKP 11", 5, "cyan"}, {"PKP 11", 6, "magenta"}, {"PKP 11", 7, "white"},
};
static_assert(name_table_is<colour>(colour_name_rows, 8));

// PK1000 sections 12, 13; PKP sections 12, 16: on, blink, and on + blink = alternate blink.
constexpr name_row led_mode_rows[] = {{"PK1000 12", 0, "off"},
                                      {"PK1000 12", 1, "on"},
                                      {"PK1000 13", 2, "blink"},
                                      {"PK1000 13", 3, "alternate_blink"}};
static_assert(name_table_is<led_mode>(led_mode_rows, 4));
}  // namespace

TEST_CASE("LED colours and modes") {
    powerkey_tests::check_rows(colour_rows, colour_holds);
    powerkey_tests::check_rows(mode_rows, mode_holds);
    CHECK(every_colour_reads_back());
}

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
}

TEST_CASE("bits per second of every PK1000 baud-rate code, reserved codes forced to 125k") {
    CHECK(rates_hold());
}

TEST_CASE("the name tables of the keypad values, row by row, with their aliases") {
    CHECK(name_table_is<backlight_colour>(backlight_colour_rows, 0x0A));
    CHECK(name_table_is<baud_rate>(baud_rate_rows, 0x08));
    CHECK(name_table_is<startup_show>(startup_show_rows, 0x03));
    CHECK(name_table_is<led_state>(led_state_rows, 0x0B));
    CHECK(name_table_is<plane>(plane_rows, 3));
    CHECK(name_table_is<colour>(colour_name_rows, 8));
    CHECK(name_table_is<led_mode>(led_mode_rows, 4));
}
