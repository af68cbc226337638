// keypad/value_kinds.hpp: each value kind's fields and builders against a manual frame: a message
// filled in through fields() (as `powerkey encode --json` does) or built with a *_value builder
// encodes to the manual's bytes and decodes back to itself; the fields a kind shows; the
// restore signature.
#include <doctest/doctest.h>

#include <powerkey/fields.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/commands.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/keypad/value_kinds.hpp>
#include <powerkey/keypad/values.hpp>

#include "support.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace {
using namespace powerkey;
using namespace powerkey_tests;

// --- filling a message through fields() ----------------------------------------------------------

struct field_value {
    std::string_view name;
    std::uint32_t number = 0;             // a number, a flag, an enum's byte, a set's mask
    std::array<std::uint8_t, 4> bytes{};  // a string piece's bytes
};

// Sets the field called `v.name` from v, whatever its type; counts the fields it set.
struct filler {
    field_value v;
    int set = 0;
    template <class T>
    constexpr void operator()(std::string_view name, T& field) {
        if (name != v.name) return;
        ++set;
        if constexpr (std::is_same_v<T, bool>)
            field = v.number != 0;
        else if constexpr (std::is_integral_v<T> || std::is_enum_v<T>)
            field = static_cast<T>(v.number);
        else if constexpr (is_bounded<T>::value)
            field = T::make(v.number).value();
        else if constexpr (is_index_set<T>::value)
            field = T::from_mask(v.number);
        else if constexpr (std::is_same_v<T, std::array<std::uint8_t, 4>>)
            field = v.bytes;
    }
};

// m with each of `values` set through fields(); false in `all_set` when a name matched no field.
constexpr message filled(message m, std::span<const field_value> values, bool& all_set) {
    all_set = true;
    for (const auto& v : values) {
        filler f{v};
        std::visit([&f](auto& s) { std::remove_cvref_t<decltype(s)>::fields(s, f); }, m);
        all_set = all_set && f.set == 1;
    }
    return m;
}

struct fill_row {
    std::string_view section;
    std::string_view frame;
    model id;
    message base;  // the kind, object or command code
    std::array<field_value, 5> values;
    std::size_t count;
};

constexpr fill_row fill_rows[] = {
    // PKP3500-MT 19 b: bit 7 counterclockwise, bits 0..6 the ticks
    {"PKP3500-MT 19 b",
     "595#4F00200281000000",
     model::pkp3500mt,
     sdo_read_reply{object::encoder1_direction_counter, {}},
     {{{"counterclockwise", 1}, {"ticks", 1}}},
     2},
    {"PKP3500-MT 19 d",
     "595#4F00200402000000",
     model::pkp3500mt,
     sdo_read_reply{object::encoder2_direction_counter, {}},
     {{{"counterclockwise", 0}, {"ticks", 2}}},
     2},
    // PKP3500-MT 20 c: the encoder ring LEDs, LED 8 = bit 7
    {"PKP3500-MT 20 c",
     "615#2301200480000000",
     model::pkp3500mt,
     sdo_write{object::led_on_encoder, {}},
     {{{"leds", 0x80}}},
     1},
    // PKP-1500-LI manual, 100Ah: "2.10" in one expedited reply (docs/si-family.md)
    {"PKP-1500-LI 100Ah",
     "595#430A1000322E3130",
     model::pkp1500li,
     sdo_read_reply{object::software_version, {}},
     {{{"size", 4}, {"bytes", 0, {'2', '.', '1', '0'}}}},
     2},
    // PK1000 28: 100 ms, producer node 7Eh
    {"PK1000 28",
     "615#2316100164007E00",
     model::pk1000,
     sdo_write{object::consumer_heartbeat, {}},
     {{{"period_ms", 100}, {"producer", 0x7E}}},
     2},
    // PK1000 38: the RPDO1 COB-ID, valid, no RTR, 215h
    {"PK1000 38",
     "595#4300140115020040",
     model::pk1000,
     sdo_read_reply{object::rpdo1_cob_id, {}},
     {{{"invalid", 0}, {"no_rtr", 1}, {"can_id", 0x215}}},
     3},
    // PK1000 30 (E-PK-6, E-PK-7): profile 0191h, digital input and output, analogue output
    {"PK1000 30",
     "595#4300100091010B00",
     model::pk1000,
     sdo_read_reply{object::device_type, {}},
     {{{"profile", 0x191},
       {"digital_input", 1},
       {"digital_output", 1},
       {"analogue_input", 0},
       {"analogue_output", 1}}},
     5},
    // PK1000 19 c, 20, 21, 23, 24: one field each
    {"PK1000 19 c",
     "615#2F03200305000000",
     model::pk1000,
     sdo_write{object::backlight_colour, {}},
     {{{"colour", 0x05}}},
     1},
    {"PK1000 20",
     "615#2F10200004000000",
     model::pk1000,
     sdo_write{object::baud_rate, {}},
     {{{"baud_rate", 0x04}}},
     1},
    {"PK1000 21",
     "615#2F11200001000000",
     model::pk1000,
     sdo_write{object::boot_up, {}},
     {{{"enabled", 1}}},
     1},
    {"PK1000 23",
     "615#2F1320003A000000",
     model::pk1000,
     sdo_write{object::node_id, {}},
     {{{"node_id", 0x3A}}},
     1},
    {"PK1000 24",
     "615#2F14200002000000",
     model::pk1000,
     sdo_write{object::startup_show, {}},
     {{{"startup_show", 0x02}}},
     1},
    // PK1000 17 a: red LED 3 (bit 2 of the red plane)
    {"PK1000 17 a",
     "615#2301200104000000",
     model::pk1000,
     sdo_write{object::led_on_red, {}},
     {{{"red", 0x04}}},
     1},
    // PK1000 46 b: event timer 500 ms
    {"PK1000 46 b",
     "615#2B001805F4010000",
     model::pk1000,
     sdo_write{object::tpdo1_event_timer, {}},
     {{{"period_ms", 500}}},
     1},
    // PKP2600SI 17 a sub 2: bits 16..23 of the string, green 5..12; 40h = green 11
    {"PKP2600SI 17 a sub 2",
     "615#2F01200240000000",
     model::pkp2600si,
     sdo_write{object::led_on_g5_12, {}},
     {{{"green", 1u << 10}}},
     1},
    // PKP 13 f: periodic key state every 32h x 10 ms; 13 a: LED 8 red
    {"PKP 13 f",
     "615#2300650112013200",
     model::pkp2400,
     command{command_code::set_periodic_transmission},
     {{{"enabled", 1}, {"period_10ms", 0x32}}},
     2},
    {"PKP 13 a",
     "615#2300650101080100",
     model::pkp2400,
     command{command_code::set_led_state},
     {{{"key", 8}, {"state", 0x01}}},
     2},
    {"PKP 13 e",
     "615#2300650111010000",
     model::pkp2400,
     command{command_code::set_baud_rate},
     {{{"baud_rate", static_cast<std::uint32_t>(baud_rate::kbit_250)}}},
     1},
    {"PKP 13 h",
     "615#2300650170180000",
     model::pkp2400,
     command{command_code::set_node_id},
     {{{"node_id", 0x18}}},
     1},
    {"PKP 13 m",
     "615#2300650150030000",
     model::pkp2400,
     command{command_code::set_startup_show},
     {{{"startup_show", static_cast<std::uint32_t>(startup_show::disabled)}}},
     1},
    {"PKP 13 k",
     "615#230065017D010000",
     model::pkp2400,
     command{command_code::set_default_backlight_colour},
     {{{"colour", 0x01}}},
     1},
    {"PKP 13 b",
     "615#2300650102100000",
     model::pkp2400,
     command{command_code::set_led_brightness},
     {{{"level", 0x10}}},
     1},
};

// Filled in through fields(), the message encodes to the manual's frame and decodes back.
constexpr bool fills(const fill_row& r) {
    bool all_set = false;
    const auto m = filled(r.base, std::span(r.values.data(), r.count), all_set);
    const auto node = canopen::default_node_id;
    const auto f = encode(node, r.id, m);
    const auto d = decode(frame_of(r.frame), node, r.id);
    return all_set && f && *f == frame_of(r.frame) && d && *d == m;
}
static_assert(powerkey_tests::all_rows_pass<first_failing(fill_rows, fills), std::size(fill_rows)>);

// --- the value builders --------------------------------------------------------------------------

struct builder_row {
    std::string_view section;
    std::string_view frame;
    model id;
    message msg;
};
constexpr builder_row builder_rows[] = {
    {"PK1000 20", "615#2F10200004000000", model::pk1000,
     sdo_write{object::baud_rate, baud_value(baud_rate::kbit_125)}},
    {"PK1000 24", "615#2F14200002000000", model::pk1000,
     sdo_write{object::startup_show, show_value(startup_show::fast_flash)}},
    {"PK1000 28", "615#23161001F4010100", model::pk1000,
     sdo_write{object::consumer_heartbeat, consumer_heartbeat_value(500, 0x01)}},
    {"PK1000 17 b", "595#4301200108000000", model::pk1000,
     sdo_read_reply{object::led_on_red, leds_value({{4}, {}, {}})}},
    {"PK1000 19 c", "615#2F03200305000000", model::pk1000,
     sdo_write{object::backlight_colour, colour_value(backlight_colour::cyan)}},
    {"PK1000 21", "595#4F11200001000000", model::pk1000,
     sdo_read_reply{object::boot_up, flag_value(true)}},
    {"PK1000 23", "615#2F1320003A000000", model::pk1000,
     sdo_write{object::node_id, node_value(0x3A)}},
    {"PKP 15 b: PKP-2200 green 2", "595#4301600020000000", model::pkp2200,
     sdo_read_reply{object::led_on, leds_value({{}, {2}, {}})}},
    {"PKP3500-MT 19 a", "595#4B002001FF7F0000", model::pkp3500mt,
     sdo_read_reply{object::keys, keys_value(key_set::from_mask(0x7FFF))}},
    {"PKP 30", "615#2F01620110000000", model::pkp2400,
     sdo_write{object::led_brightness, level_value(0x10)}},
    {"PKP-1500-LI 100Ah", "595#430A1000322E3130", model::pkp1500li,
     sdo_read_reply{object::software_version, string_value(4, {'2', '.', '1', '0'})}},
    {"PK1000 29", "615#2B17100032000000", model::pk1000,
     sdo_write{object::heartbeat_time, number_value(50)}},
};
constexpr bool builds(const builder_row& r) {
    const auto node = canopen::default_node_id;
    const auto f = encode(node, r.id, r.msg);
    const auto d = decode(frame_of(r.frame), node, r.id);
    return f && *f == frame_of(r.frame) && d && *d == r.msg;
}
static_assert(
    powerkey_tests::all_rows_pass<first_failing(builder_rows, builds), std::size(builder_rows)>);

// --- the fields each kind shows -----------------------------------------------------------------

// A value of no kind (1001h: PK1000 31, the keypad aborts) and the command module (6500h carries
// commands, not a value) show only their object; the encoders' kinds their own fields.
struct shown_row {
    std::string_view section;
    std::string_view frame;  // unused
    message msg;
    std::string_view names;  // the fields for_each_field walks, space-separated
};
constexpr shown_row shown_rows[] = {
    {"PK1000 31", "", sdo_read_reply{object::error_register, {}}, "object"},
    {"PKP 13", "", sdo_write{object::command_module, {}}, "object"},
    {"PKP3500-MT 19 b", "", sdo_read_reply{object::encoder1_direction_counter, {}},
     "object counterclockwise ticks"},
    {"PKP3500-MT 20 c", "", sdo_write{object::led_on_encoder, {}}, "object leds"},
    // One plane of an LED map shows under its plane's name.
    {"PK1000 17a", "", sdo_write{object::led_on_red, {}}, "object red"},
    {"PK1000 18a", "", sdo_read_reply{object::led_blink_green, {}}, "object green"},
    {"PKP3500-MT 20 a", "", sdo_write{object::led_on_blue, {}}, "object blue"},
};
constexpr bool shows(const shown_row& r) {
    std::string_view rest = r.names;
    bool ok = true;
    for_each_field(r.msg, [&](std::string_view name, const auto&) {
        const auto end = rest.find(' ');
        ok = ok && !rest.empty() && rest.substr(0, end) == name;
        rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end + 1);
    });
    return ok && rest.empty();
}
static_assert(
    powerkey_tests::all_rows_pass<first_failing(shown_rows, shows), std::size(shown_rows)>);

// PK1000 36: restore defaults takes "load" (6Ch 6Fh 61h 64h), little endian.
static_assert(load_signature == 0x6461'6F6C);
}  // namespace

TEST_CASE("messages filled in through fields() encode to the manual's frames") {
    powerkey_tests::check_rows(fill_rows, fills);
}

TEST_CASE("the value builders give the manual's frames") {
    powerkey_tests::check_rows(builder_rows, builds);
    // At run time too (the table above is built at compile time).
    const auto node = canopen::default_node_id;
    volatile std::uint8_t code = 0x04;
    const auto baud = static_cast<baud_rate>(code);
    CHECK(encode(node, model::pk1000, sdo_write{object::baud_rate, baud_value(baud)}) ==
          frame_of("615#2F10200004000000"));
    CHECK(
        encode(node, model::pk1000,
               sdo_write{object::startup_show, show_value(static_cast<startup_show>(code - 2))}) ==
        frame_of("615#2F14200002000000"));
    CHECK(encode(node, model::pk1000,
                 sdo_write{object::consumer_heartbeat,
                           consumer_heartbeat_value(static_cast<std::uint16_t>(code * 125),
                                                    canopen::node_id::make(code - 3).value())}) ==
          frame_of("615#23161001F4010100"));
    CHECK(encode(node, model::pk1000,
                 sdo_read_reply{object::led_on_red,
                                leds_value({led_set::from_mask(code * 2u), {}, {}})}) ==
          frame_of("595#4301200108000000"));
}

TEST_CASE("the fields each kind shows") { powerkey_tests::check_rows(shown_rows, shows); }

// --- every reserved bit on its own, walked from the dictionaries and the model table ------------
// For every model and every row of its dictionary whose kind gives bits a meaning, each bit of
// the value alone, written (600h) and read back (580h) as the row's access allows: a bit that
// names nothing is reserved_not_zero, any other is accepted. What a bit names comes from the
// model row's plain facts (keys, planes, stride, led_mask), not from the codec's derived masks:
//   keys        bit k - 1 for keys 1..keys (PK1000 16, PKP 14)
//   led_plane   bit k - 1 for an LED of led_mask (PK1000 17/18, the SI planes)
//   led_map     plane p at bits p * stride, for the planes that fit 32 bits (PKP 15/16)
//   cob_id      bits 11..29 reserved; 0..10 the identifier, 30 no RTR, 31 invalid (CiA 301
//               7.5.2.35)
//   device_type bits 20..31 reserved; 0..15 the profile, 16..19 the I/O kinds (CiA 401)
//   consumer_heartbeat  byte 3 reserved (PK1000 28), on a valid value (off, producer 01h)
namespace {
constexpr canopen::node_id bits_node = canopen::default_node_id;

constexpr bool led_bit(const model_info& k, unsigned plane_no, unsigned bit) {
    return plane_no < k.planes && bit < k.stride && ((k.led_mask >> bit) & 1u) != 0;
}
// Whether bit b (0..31) of row r's value names something on model k; nullopt for a kind whose
// bits this walk leaves to its own tests.
constexpr std::optional<bool> bit_named(const model_info& k, value_kind kind, unsigned b) {
    switch (kind) {
        case value_kind::keys: return b < k.keys;
        case value_kind::led_plane: return led_bit(k, 0, b);
        case value_kind::led_map: {
            const unsigned p = b / k.stride;
            return (p + 1) * k.stride <= 32 && led_bit(k, p, b % k.stride);
        }
        case value_kind::cob_id: return b < 11 || b > 29;
        case value_kind::device_type: return b < 20;
        case value_kind::consumer_heartbeat: return b < 24;
        default: return std::nullopt;
    }
}
constexpr std::uint8_t row_bytes(const model_info& k, const object_row& r) {
    return r.size != 0 ? r.size : static_cast<std::uint8_t>(k.stride / 8);
}
}  // namespace

TEST_CASE("every reserved bit of every row on its own, in every model, both ways") {
    std::size_t reserved = 0, named = 0;
    for (const model m : enum_values<model>()) {
        const model_info k = *info(m);
        CAPTURE(std::string(to_string(m)));
        for (const object_row& r : rows_of(k.dictionary)) {
            const value_kind kind = info(r.id).kind;
            if (!bit_named(k, kind, 0)) continue;
            CAPTURE(std::string(to_string(r.id)));
            const std::uint8_t size = row_bytes(k, r);
            // consumer_heartbeat: each bit of byte 3 on a valid value; the others: alone.
            const std::uint32_t base = kind == value_kind::consumer_heartbeat ? 0x0001'0000u : 0u;
            for (unsigned b = 0; b < 8u * size; ++b) {
                const bool is_named = *bit_named(k, kind, b);
                if (kind == value_kind::consumer_heartbeat && is_named) continue;
                CAPTURE(b);
                const std::uint32_t data = base | (std::uint32_t{1} << b);
                (is_named ? named : reserved) += 1;
                for (const bool write : {true, false}) {
                    if (write ? !r.writable() : !r.readable()) continue;
                    CAPTURE(write);
                    const auto got = decode(
                        powerkey_tests::expedited_frame(bits_node, r.address, size, data, write),
                        bits_node, m);
                    if (is_named)
                        CHECK(got.has_value());
                    else
                        CHECK(got == errc::reserved_not_zero);
                }
            }
        }
    }
    CHECK(reserved >= 500);
    CHECK(named >= 500);
}

// The PDOs' fields and reserved bits, from the model row: the key state (TPDO1, bytes 0..3 the
// keys, byte 4 the tick), the LED maps (RPDO1/RPDO2: plane p at bits p * stride), the brightness
// (RPDO3: byte 0, 00h..3Fh), the backlight (RPDO4: byte 0 the level, byte 1 the colour 00h..09h
// where the model has one), each bit alone and each range at its ends (PK1000 11-15, PKP 10-12,
// MT 12-18).
TEST_CASE("every PDO bit on its own and every PDO field at its ends, in every model") {
    const auto pdo = [](unsigned base, std::size_t dlc, std::uint64_t bits) {
        can::payload p{};
        for (std::size_t i = 0; i < 8; ++i) p[i] = static_cast<std::uint8_t>(bits >> (8 * i));
        return can::frame(can::standard_id::make(base + bits_node.value()).value(),
                          can::dlc::make(static_cast<std::uint8_t>(dlc)).value(), p);
    };
    for (const model m : enum_values<model>()) {
        const model_info k = *info(m);
        CAPTURE(std::string(to_string(m)));
        for (unsigned b = 0; b < 40; ++b) {
            CAPTURE(b);
            const auto got = decode(pdo(0x180, 5, std::uint64_t{1} << b), bits_node, m);
            if (b < k.keys || b >= 32)  // a key, or the tick in byte 4
                CHECK(got.has_value());
            else
                CHECK(got == errc::reserved_not_zero);
        }
        for (const unsigned base : {0x200u, 0x300u}) {
            for (unsigned b = 0; b < 64; ++b) {
                CAPTURE(base);
                CAPTURE(b);
                const auto got = decode(pdo(base, 8, std::uint64_t{1} << b), bits_node, m);
                if (led_bit(k, b / k.stride, b % k.stride))
                    CHECK(got.has_value());
                else
                    CHECK(got == errc::reserved_not_zero);
            }
        }
        if (k.brightness_pdo) {
            CHECK(decode(pdo(0x400, 8, 0x3F), bits_node, m).has_value());
            CHECK(decode(pdo(0x400, 8, 0x40), bits_node, m) == errc::value_out_of_range);
            for (unsigned b = 8; b < 64; ++b) {
                CAPTURE(b);
                CHECK(decode(pdo(0x400, 8, std::uint64_t{1} << b), bits_node, m) ==
                      errc::reserved_not_zero);
            }
        }
        if (k.backlight_pdo) {
            CHECK(decode(pdo(0x500, 8, 0x3F), bits_node, m).has_value());
            CHECK(decode(pdo(0x500, 8, 0x40), bits_node, m) == errc::value_out_of_range);
            if (k.backlight_colour) {
                CHECK(decode(pdo(0x500, 8, 0x09'3F), bits_node, m).has_value());
                CHECK(decode(pdo(0x500, 8, 0x0A'00), bits_node, m) == errc::value_out_of_range);
            } else {
                for (unsigned b = 8; b < 16; ++b) {
                    CAPTURE(b);
                    CHECK(decode(pdo(0x500, 8, std::uint64_t{1} << b), bits_node, m) ==
                          errc::reserved_not_zero);
                }
            }
            for (unsigned b = 16; b < 64; ++b) {
                CAPTURE(b);
                CHECK(decode(pdo(0x500, 8, std::uint64_t{1} << b), bits_node, m) ==
                      errc::reserved_not_zero);
            }
        }
        if (k.encoders) {
            // TPDO2/TPDO3: byte 3 TOP 00h or 02h..10h, bytes 4..7 reserved; TPDO4: 0..500 (x 10 mV)
            for (const unsigned base : {0x280u, 0x380u}) {
                for (const std::uint64_t top : {0x00u, 0x02u, 0x10u})
                    CHECK(decode(pdo(base, 8, top << 24), bits_node, m).has_value());
                for (const std::uint64_t top : {0x01u, 0x11u})
                    CHECK(decode(pdo(base, 8, top << 24), bits_node, m) ==
                          errc::value_out_of_range);
                for (unsigned b = 32; b < 64; ++b) {
                    CAPTURE(b);
                    CHECK(decode(pdo(base, 8, std::uint64_t{1} << b), bits_node, m) ==
                          errc::reserved_not_zero);
                }
            }
            for (unsigned input = 0; input < 4; ++input) {
                CAPTURE(input);
                const auto at = [&](std::uint64_t v) {
                    return decode(pdo(0x480, 8, v << (16 * input)), bits_node, m);
                };
                const auto full = at(500);
                REQUIRE(full.has_value());
                const auto* a = std::get_if<analog_inputs>(&*full);
                REQUIRE(a != nullptr);
                CHECK(a->mv[input] == 5000);
                CHECK(at(501) == errc::value_out_of_range);
            }
        }
    }
}
