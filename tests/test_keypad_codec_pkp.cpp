// keypad/codec.hpp on the PKP manual: the PKP-2200/2400/2600 through decode/encode(node, model,
// ...): every example frame of the PKP manual and the PKP-2600 rows of docs/pkp.md, both ways, for
// each model a row applies to; the frames each model refuses; the messages encode refuses
// (tests/pkp_rows.hpp); the errata; the LED-map rule through the codec. One runner per table,
// proved at compile time and run by doctest.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/models.hpp>

#include <cstddef>
#include <iterator>
#include <string_view>
#include <variant>

#include "pkp_rows.hpp"
#include "support.hpp"

namespace {
using namespace powerkey;
using namespace pkp_rows;
using namespace powerkey_tests;
constexpr canopen::node_id node = canopen::default_node_id;

static_assert(first_failing(pkp_rows::rows, round_trips) == std::size(pkp_rows::rows));
static_assert(first_failing(pkp_rows::error_rows, refused) == std::size(pkp_rows::error_rows));
static_assert(first_failing(pkp_rows::encode_error_rows, encode_refused) ==
              std::size(pkp_rows::encode_error_rows));

// Frames the PKP accepts that are not manual rows.
constexpr row behaviour_rows[] = {
    // One rule for both dictionaries: an expedited reply of a string object is a piece of it
    // (refused with unknown_object before issue 10).
    {"expedited reply of string 1008h", pkp, 0x15, "595#4308100042000000",
     reply(object::device_name, string_value(4, {0x42, 0, 0, 0}))},
    // E-PKP-5: 1400h/1 answers the COB-ID in 2 bytes (4Bh), base 200h without the node id.
    {"E-PKP-5 RPDO1 COB-ID", pkp, 0x15, "595#4B00140100020000", value(object::rpdo1_cob_id, 0x200)},
    // E-PKP-7: heartbeat 0 is off.
    {"E-PKP-7 heartbeat off", pkp, 0x15, "615#2B17100000000000", write(object::heartbeat_time, 0)},
    // E-PKP-8: PKP-2600 keys 9..12 in key-state byte 1.
    {"E-PKP-8 PKP-2600 keys 9-12", m2600, 0x15, "195#000F000000", pressed(span(9, 12), 0)},
    // ref: PKP-2600 white key 12 sets R12, G12, B12 (bits 11, 23, 35).
    {"ref PKP-2600 white 12", m2600, 0x15, "215#0008800008000000",
     led_on{leds{}.set(12, colour::white)}},
    // PKP 12, PKP-2200: all magenta LEDs blink, built LED by LED.
    {"PKP 12 PKP-2200 all magenta", m2200, 0x15, "315#0F0F000000000000",
     led_blink{leds{}
                   .set(1, colour::magenta)
                   .set(2, colour::magenta)
                   .set(3, colour::magenta)
                   .set(4, colour::magenta)}},
};
static_assert(first_failing(behaviour_rows, round_trips) == std::size(behaviour_rows));

// Each erratum of docs/errata.md (## PKP) and the behaviour chosen: errc{} = the frame decodes
// (its meaning pinned in pkp_rows.hpp or behaviour_rows), otherwise the error decode returns.
constexpr error_row errata[] = {
    {"E-PKP-1 reply printed with data", pkp, 0x15, "595#6000650100090700", errc::reserved_not_zero},
    {"E-PKP-1 LED 9 blue", m2600, 0x15, "615#2300650101090700", errc{}},
    {"E-PKP-2 reply printed on 195h", pkp, 0x15, "195#6000650100000000", errc::wrong_length},
    {"E-PKP-2 reply on 595h", pkp, 0x15, "595#6000650100000000", errc{}},
    {"E-PKP-3 node id 00h", pkp, 0x15, "615#2300650170000000", errc::value_out_of_range},
    {"E-PKP-4 (E-CORE-4) 41h", pkp, 0x15, "615#4100630000000000", errc::reserved_not_zero},
    {"E-PKP-4 (E-CORE-4) 40h", pkp, 0x15, "615#4000630000000000", errc{}},
    {"E-PKP-5 2-byte COB-ID", pkp, 0x15, "595#4B00140100020000", errc{}},
    {"E-PKP-5 4-byte COB-ID", pkp, 0x15, "595#4300140115020000", errc::size_mismatch},
    {"E-PKP-6 6302h/0 answers 2", pkp, 0x15, "595#4F02630002000000", errc{}},
    {"E-PKP-7 heartbeat off", pkp, 0x15, "615#2B17100000000000", errc{}},
    {"E-PKP-7 heartbeat 9 ms", pkp, 0x15, "615#2B17100009000000", errc::value_out_of_range},
    {"E-PKP-8 keys 9-12", m2600, 0x15, "195#000F000000", errc{}},
    {"E-PKP-8 6001h byte 7", m2600, 0x15, "615#23016000000000FF", errc::reserved_not_zero},
    {"E-PKP-9 (E-CORE-3) 40h", pkp, 0x15, "595#4000610208000000", errc{}},
    {"E-PKP-10 1800h/5 read back", pkp, 0x15, "595#4B00180500000000", errc{}},
    {"E-PKP-10 1800h/5 written", pkp, 0x15, "615#2B00180532000000", errc::unknown_command},
    {"E-PKP-10 period by command 12h", pkp, 0x15, "615#2300650112013200", errc{}},
};
constexpr bool erratum_holds(const error_row& r) {
    return for_models(r.models, [&](model m) {
        const auto d = decode(frame_of(r.frame), node_of(r.node), m, reading::strict);
        return r.error == errc{} ? d.has_value() : d == r.error;
    });
}
static_assert(first_failing(errata, erratum_holds) == std::size(errata));

// --- the one LED-map rule ------------------------------------------------------------------------

constexpr model pkps[] = {model::pkp2200, model::pkp2400, model::pkp2600};

// Bytes an LED-on PDO uses for a model when every LED is on (the reference's table).
constexpr std::size_t bytes_used(model m) {
    const auto keys = info(m)->keys;
    leds l;
    for (unsigned k = 1; k <= keys; ++k) l.set(k, colour::white);
    const auto f = encode(node, m, led_on{l});
    std::size_t used = 0;
    for (std::size_t i = 0; i < 8; ++i)
        if ((*f)[i] != 0) used = i + 1;
    return used;
}
static_assert(bytes_used(model::pkp2200) == 2);
static_assert(bytes_used(model::pkp2400) == 3);
static_assert(bytes_used(model::pkp2600) == 5);

// One LED on sets exactly bit c*N + (k-1) of the PDO, for every model, plane and key.
constexpr bool single_bits_follow_the_rule() {
    for (model m : pkps) {
        const unsigned n = info(m)->keys;
        for (unsigned c = 0; c < 3; ++c)
            for (unsigned k = 1; k <= n; ++k) {
                leds l;
                l.of(static_cast<plane>(c)).insert(k);
                const auto f = encode(node, m, led_on{l});
                if (!f) return false;
                const std::size_t want = c * n + (k - 1);
                for (std::size_t i = 0; i < 64; ++i) {
                    const bool set = (((*f)[i / 8] >> (i % 8)) & 1) != 0;
                    if (set != (i == want)) return false;
                }
                if (!(decode(*f, node, m) == result<message>{led_on{l}})) return false;
            }
    }
    return true;
}
static_assert(single_bits_follow_the_rule());
}  // namespace

TEST_CASE("PKP: every manual and reference row, both ways, per model") {
    check_rows(pkp_rows::rows, round_trips);
}

TEST_CASE("PKP: frames each model refuses, with the precise error") {
    check_rows(pkp_rows::error_rows, refused);
}

TEST_CASE("PKP: messages a model cannot carry do not encode") {
    check_rows(pkp_rows::encode_error_rows, encode_refused);
}

TEST_CASE("PKP: frames accepted beyond the manual's rows") {
    check_rows(behaviour_rows, round_trips);
}

TEST_CASE("PKP errata: the manual's frames pin the chosen behaviour") {
    check_rows(errata, erratum_holds);
}

TEST_CASE("PKP: the bit-map rule through the codec") {
    CHECK(bytes_used(model::pkp2200) == 2);
    CHECK(bytes_used(model::pkp2400) == 3);
    CHECK(bytes_used(model::pkp2600) == 5);
    CHECK(single_bits_follow_the_rule());
}

TEST_CASE("PKP: after a node change the keypad boots up from the new id (PKP 13 h)") {
    CHECK(decode(frame_of("718#00"), 0x15, model::pkp2400) == errc::wrong_id);
    CHECK(decode(frame_of("718#00"), 0x18, model::pkp2400).has_value());
}
