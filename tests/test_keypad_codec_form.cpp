// Frames not in the manual's form (docs/decoder.md, "Tolerant and strict reading"): a frame cut
// after its last used byte, or padded with 00h, decodes to the meaning of the manual's form with
// `form` trimmed or padded; reading::strict refuses it with wrong_length; encode builds the
// manual's form. One row per PDO and SDO kind of every model (and NMT, SYNC, heartbeat), each with
// the manual's frame it stands for and the meaning it must decode to; then every frame of every
// manual table, cut and padded at every length.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/keypad/codec.hpp>

#include "codec_rows.hpp"
#include "pk1000_rows.hpp"
#include "pkp_rows.hpp"
#include "si_reference_rows.hpp"
#include "si_rows.hpp"
#include "support.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace {
using namespace powerkey;
using namespace codec_rows;
using namespace powerkey_tests;

constexpr model_set every = all | si;
constexpr model_set colour = m1000 | m2600si | m3500mt | m2200si | m2300si | m2400si | m1600si;

// `frame` decodes for every model of the row to what `manual` (the manual's form) decodes to,
// described as `text` (which ends in its form), and strictly it is wrong_length; encode builds
// `manual` back.
struct form_row {
    std::string_view section;
    model_set models;
    std::string_view frame;
    std::string_view manual;
    std::string_view text;
};

constexpr form_row rows[] = {
    // NMT, SYNC, heartbeat (CiA 301; E-CORE-6: the manuals' tables list bytes 2..7 "not used")
    {"E-CORE-6 NMT padded to 8 bytes", every, "000#0115000000000000", "000#0115",
     "node 15h  NMT message  command: start  target: 15h  form: padded"},
    {"NMT padded to 3 bytes", every, "000#811500", "000#8115",
     "node 15h  NMT message  command: reset_node  target: 15h  form: padded"},
    {"SYNC with a 00h byte", every, "080#00", "080#", "node 15h  sync message  form: padded"},
    {"heartbeat padded", every, "715#0500000000000000", "715#05",
     "node 15h  heartbeat message  state: operational  form: padded"},
    // key state: bytes 0..1 keys, 2..3 00h, 4 the tick; padded only (the tick is used)
    {"key state padded to 8 bytes", every, "195#010000002A000000", "195#010000002A",
     "node 15h  key state  keys: 1  tick: 42  form: padded"},
    // LED maps: cut after the last byte with an LED of the model
    {"PKP-2200-LI LED on, 2 bytes (12 bits)", m2200, "215#0100", "215#0100000000000000",
     "node 15h  LED on  red: 1  green: -  blue: -  form: trimmed"},
    {"PKP-2400-LI LED on, 3 bytes (24 bits)", m2400, "215#010000", "215#0100000000000000",
     "node 15h  LED on  red: 1  green: -  blue: -  form: trimmed"},
    {"PKP-2400-LI LED blink, 3 bytes", m2400, "315#000080", "315#0000800000000000",
     "node 15h  LED blink  red: -  green: -  blue: 8  form: trimmed"},
    {"PKP-2600 LED on, 5 bytes (36 bits)", m2600 | m2600si, "215#0100000008",
     "215#0100000008000000", "node 15h  LED on  red: 1  green: -  blue: 12  form: trimmed"},
    {"15-key LED on, 6 bytes (S = 16, 47 bits)", m3500si, "215#010000000040",
     "215#0100000000400000", "node 15h  LED on  red: 1  green: -  blue: 15  form: trimmed"},
    {"S = 8 SI LED on, 3 bytes", m2400si, "215#010000", "215#0100000000000000",
     "node 15h  LED on  red: 1  green: -  blue: -  form: trimmed"},
    // LED brightness: the level in byte 0
    {"LED brightness, 1 byte", m1000 | m2600si | m3500si | m2500si, "415#08",
     "415#0800000000000000", "node 15h  LED brightness  level: 08h  form: trimmed"},
    // backlight: level and colour, or the level alone on a level-only keypad
    {"backlight level and colour, 2 bytes", colour, "515#3F01", "515#3F01000000000000",
     "node 15h  backlight  level: 3Fh  colour: red  form: trimmed"},
    {"level-only backlight, 1 byte", m3500si | m2500si | m1500li, "515#20", "515#2000000000000000",
     "node 15h  backlight  level: 20h  colour: keep  form: trimmed"},
    // the PKP-3500-MT's encoder, ring-LED PDOs (E-SI-19: 1A01h maps four bytes)
    {"E-SI-19 encoder 1, 4 bytes", m3500mt, "295#01040005", "295#0104000500000000",
     "node 15h  encoder state  encoder: 1  counterclockwise: no  ticks: 1  counter: 4  top: 5  "
     "form: trimmed"},
    {"encoder ring LEDs, 4 bytes", m3500mt, "415#01000080", "415#0100008000000000",
     "node 15h  encoder leds  leds: 1 32  form: trimmed"},
    // SDO: the specifier and address always, the value's bytes up to its last used one
    {"SDO read, 4 bytes", every, "615#40081000", "615#4008100000000000",
     "node 15h  SDO read  object: device_name  form: trimmed"},
    {"SDO write 1017h, 6 bytes (2Bh: 2 bytes)", every, "615#2B171000F401", "615#2B171000F4010000",
     "node 15h  SDO write  object: heartbeat_time  period_ms: 500  "
     "form: trimmed"},
    {"SDO write acknowledged, 4 bytes", every, "595#60171000", "595#6017100000000000",
     "node 15h  SDO write reply  object: heartbeat_time  form: trimmed"},
    {"SDO read reply 1017h, 6 bytes", every, "595#4B171000F401", "595#4B171000F4010000",
     "node 15h  SDO read reply  object: heartbeat_time  period_ms: 500  form: trimmed"},
    {"E-PK-10, E-SI-7 the switch to J1939, 5 bytes (01h the flag's one byte)",
     m1000 | m2600si | m3500mt, "615#2BFF200101", "615#2BFF200101000000",
     "node 15h  SDO write  object: protocol_j1939  enabled: yes  form: trimmed"},
    {"PK1000 20 baud rate, 5 bytes", m1000, "615#2F10200004", "615#2F10200004000000",
     "node 15h  SDO write  object: baud_rate  baud_rate: kbit_125  form: trimmed"},
    {"PK1000 28 consumer heartbeat, 7 bytes (byte 3 reserved)", m1000, "615#2316100164007E",
     "615#2316100164007E00",
     "node 15h  SDO write  object: consumer_heartbeat  period_ms: 100  producer: 7Eh  form: "
     "trimmed"},
    {"PK1000 2000h/1 keys read reply, 6 bytes (10 keys)", m1000, "595#4B0020010102",
     "595#4B00200101020000", "node 15h  SDO read reply  object: keys  keys: 1 10  form: trimmed"},
    {"PKP-3500-MT 2001h/1 red, 6 bytes", m3500mt, "615#2B0120010800", "615#2B01200108000000",
     "node 15h  SDO write  object: led_on_red  red: 4  form: trimmed"},
    {"S = 8 SI 2001h/1 red, 5 bytes", m2400si, "615#2F01200101", "615#2F01200101000000",
     "node 15h  SDO write  object: led_on_red  red: 1  form: trimmed"},
    {"PKP command 02h (one parameter), 6 bytes", pkp, "615#230065010210", "615#2300650102100000",
     "node 15h  command  command: set_led_brightness  level: 10h  form: trimmed"},
    {"PKP command 01h (two parameters), 7 bytes", m2400 | m2600, "615#23006501010801",
     "615#2300650101080100",
     "node 15h  command  command: set_led_state  key: 8  state: red_on  form: trimmed"},
};

constexpr canopen::node_id keypad = canopen::default_node_id;

constexpr bool describes(const message& msg, std::string_view text) {
    std::array<char, 200> buf{};
    const auto d = describe(msg, keypad, buf);
    return d && *d == text;
}

constexpr bool reads_as_manual(const form_row& r) {
    const auto f = can::parse_candump(r.frame);
    const auto manual = can::parse_candump(r.manual);
    if (!f || !manual) return false;
    return for_models(r.models, [&](model m) {
        const auto d = decode(*f, keypad, m);
        const auto printed = decode(*manual, keypad, m, reading::strict);
        if (!d || !printed || form_of(*printed) != frame_form::manual) return false;
        if (form_of(*d) == frame_form::manual || !describes(*d, r.text)) return false;
        if (!(detail::with_form(*d, frame_form::manual) == *printed)) return false;
        if (!(decode(*f, keypad, m, reading::strict) == errc::wrong_length)) return false;
        const auto back = encode(keypad, m, *d);  // the manual's form, whatever the message says
        return back && *back == *manual;
    });
}
static_assert(first_failing(rows, reads_as_manual) == std::size(rows));

// Frames that lack a byte their kind uses, or carry a byte past the manual's length that is not
// 00h: refused both ways with wrong_length (or, padded, the manual form's own refusal).
constexpr error_row refusals[] = {
    {"key state cut before the tick (E-PK-12)", every, 0x15, "195#0100", errc::wrong_length},
    {"key state cut just before the tick, 4 bytes", every, 0x15, "195#01000000",
     errc::wrong_length},
    {"key state padded with a byte set", every, 0x15, "195#010000002A01", errc::wrong_length},
    {"PK1000 LED map, 7 bytes (green LED 28 is in byte 7)", m1000, 0x15, "215#01000000000000",
     errc::wrong_length},
    {"PKP-2400-LI LED on, 2 bytes (blue is byte 2)", m2400, 0x15, "215#0100", errc::wrong_length},
    {"backlight cut before the colour", colour, 0x15, "515#20", errc::wrong_length},
    {"analog inputs, 4 bytes (inputs 2, 3 in bytes 4..7)", m3500mt, 0x15, "495#F4010000",
     errc::wrong_length},
    {"SDO write 1017h cut inside the value", every, 0x15, "615#2B171000F4", errc::wrong_length},
    {"SDO cut inside the address", every, 0x15, "615#4008", errc::wrong_length},
    {"SDO abort, 4 bytes (the code is bytes 4..7)", every, 0x15, "595#80171000",
     errc::wrong_length},
    {"PK1000 2001h/1, 7 bytes (LED 28 is in byte 7)", m1000, 0x15, "615#23012001040000",
     errc::wrong_length},
    {"PKP command 01h cut before its state", m2400, 0x15, "615#230065010108", errc::wrong_length},
    {"SYNC with a counter", every, 0x15, "080#01", errc::wrong_length},
    {"NMT padded with a byte set", every, 0x15, "000#011501", errc::wrong_length},
    {"NMT padded, command 03h: the manual form's refusal", every, 0x15, "000#0315000000000000",
     errc::unknown_command},
    {"heartbeat padded, state 01h: the manual form's refusal", every, 0x15, "715#0100",
     errc::value_out_of_range},
    {"LED brightness 40h, 1 byte: refused as the manual's form would not be (trimmed)",
     m1000 | m2600si, 0x15, "415#40", errc::wrong_length},
};
constexpr bool refused_both_ways(const error_row& r) {
    const auto f = can::parse_candump(r.frame);
    if (!f) return false;
    return for_models(r.models, [&](model m) {
        return decode(*f, keypad, m) == r.error &&
               decode(*f, keypad, m, reading::strict) == errc::wrong_length;
    });
}
static_assert(first_failing(refusals, refused_both_ways) == std::size(refusals));

TEST_CASE("frame form: trimmed and padded frames read as the manual's form, strictly refused") {
    check_rows(rows, reads_as_manual);
    check_rows(refusals, refused_both_ways);
}

// --- every frame of every manual table, at every other length ----------------------------------

// The tables of every manual: their frames, and the frames they refuse.
struct manual_tables {
    std::string_view name;
    std::span<const row> rows;
    std::span<const error_row> error_rows;
};
const manual_tables every_manual[] = {
    {"core", core_rows, core_error_rows},
    {"PK1000", pk1000_rows::rows, pk1000_rows::error_rows},
    {"PKP", pkp_rows::rows, pkp_rows::error_rows},
    {"SI", si_rows::rows, si_rows::error_rows},
    {"SI reference", si_reference_rows::rows, si_reference_rows::error_rows},
};

// f with `length` bytes (its first ones, then 00h).
can::frame resized(const can::frame& f, std::size_t length) {
    std::array<std::uint8_t, 8> b{};
    for (std::size_t i = 0; i < length && i < f.size(); ++i) b[i] = f[i];
    if (f.is_extended())
        return can::frame::make(*f.ext_id(), std::span<const std::uint8_t>(b.data(), length))
            .value();
    return can::frame::make(*f.std_id(), std::span<const std::uint8_t>(b.data(), length)).value();
}

// For each length k other than the frame's n: strictly wrong_length; tolerantly, padded (k > n)
// always the same meaning, form padded; cut (k < n) the same meaning, form trimmed, or
// wrong_length: wrong_length whenever a byte it lacks is not 00h, and once a cut decodes, every
// longer cut decodes too (the used bytes are a prefix).
void every_length(std::span<const row> table) {
    for (const auto& r : table) {
        const auto f = can::parse_candump(r.frame);
        REQUIRE(f);
        for (std::size_t i = 0; i < model_count; ++i) {
            const auto m = static_cast<model>(i);
            if (!r.models.contains(m)) continue;
            const auto node = node_of(r.node);
            const auto full = decode(*f, node, m);
            INFO(std::string(r.section), "  ", std::string(r.frame), "  ",
                 std::string(to_string(m)));
            REQUIRE(full);
            CHECK(form_of(*full) == frame_form::manual);
            const std::size_t n = f->size();
            bool decoded = false;
            for (std::size_t k = 0; k <= 8; ++k) {
                if (k == n) continue;
                const auto g = resized(*f, k);
                INFO("length ", k);
                CHECK(decode(g, node, m, reading::strict) == errc::wrong_length);
                const auto d = decode(g, node, m);
                if (k > n) {
                    REQUIRE(d);
                    CHECK(form_of(*d) == frame_form::padded);
                    CHECK(detail::with_form(*d, frame_form::manual) == *full);
                    continue;
                }
                bool lost = false;
                for (std::size_t b = k; b < n; ++b) lost = lost || (*f)[b] != 0;
                if (lost || !d) {
                    CHECK(d == errc::wrong_length);
                    CHECK(!decoded);  // a shorter cut decoded, this longer one must too
                    continue;
                }
                decoded = true;
                CHECK(form_of(*d) == frame_form::trimmed);
                CHECK(detail::with_form(*d, frame_form::manual) == *full);
            }
        }
    }
}

TEST_CASE("frame form: every manual frame, cut and padded at every length") {
    for (const auto& t : every_manual) {
        INFO(std::string(t.name));
        every_length(t.rows);
    }
}

// Tolerance changes no other refusal: every error row of the tables, read tolerantly, is refused
// the same way unless its strict refusal is wrong_length.
void same_refusals(std::span<const error_row> table) {
    for (const auto& r : table) {
        const auto f = can::parse_candump(r.frame);
        REQUIRE(f);
        for_models(r.models, [&](model m) {
            INFO(std::string(r.section), "  ", std::string(r.frame), "  ",
                 std::string(to_string(m)));
            if (r.error != errc::wrong_length) CHECK(decode(*f, node_of(r.node), m) == r.error);
            return true;
        });
    }
}

TEST_CASE("frame form: the tables' other refusals are the same read tolerantly") {
    for (const auto& t : every_manual) {
        INFO(std::string(t.name));
        same_refusals(t.error_rows);
    }
}

}  // namespace
