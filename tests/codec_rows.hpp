// The row types every frame table uses, the checks that run them, and the core rows: the frames
// every keypad speaks or hears whatever its dictionary (NMT, SYNC, boot-up, heartbeat, the SDOs of
// 1008h and 1017h, aborts, the J1939 switch back). tests/pk1000_rows.hpp and tests/pkp_rows.hpp
// hold the rest of the manuals' frames in the same row types, so that one check serves every
// table:
//
//   row               a frame of the manual: each model of `models` decodes it to `expected`, and
//                     encodes `expected` back to the same bytes
//   error_row         a frame each model of `models` refuses with `error`
//   encode_error_row  a message encode refuses for each model of `models` with `error`; `frame`
//                     is what a field-by-field encoder would build from the raw fields (decode
//                     refuses it or reads another meaning), "" where there is no frame at all
//
//   static_assert(first_failing(rows, round_trips) == std::size(rows));
//   TEST_CASE("...") { check_rows(rows, round_trips); }
#ifndef POWERKEY_TESTS_CODEC_ROWS_HPP
#define POWERKEY_TESTS_CODEC_ROWS_HPP

#include <powerkey/can/candump.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/keypad/models.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace codec_rows {
using namespace powerkey;
using canopen::nmt_command;
using canopen::nmt_state;

// --- row types and their checks -----------------------------------------------------------------

// The models a row applies to (models.hpp's model_set, sized from the table): `all` = the four
// keypads of the first manuals. The SI family (tests/si_rows.hpp, tests/si_reference_rows.hpp):
// `si` all nine, `si_s16` the per-colour sizes of stride 16, `si_s8` those of stride 8 (the
// PKP-1600-SI's CANopen side is the SI rule for six keys, inferred as the PKP-2300-SI's:
// docs/si-family.md).
inline constexpr model_set m1000{model::pk1000}, m2200{model::pkp2200}, m2400{model::pkp2400},
    m2600{model::pkp2600}, pkp = m2200 | m2400 | m2600, all = m1000 | pkp;
inline constexpr model_set m2600si{model::pkp2600si}, m3500mt{model::pkp3500mt},
    m3500si{model::pkp3500si}, m2500si{model::pkp2500si}, m1500li{model::pkp1500li},
    m2200si{model::pkp2200si}, m2300si{model::pkp2300si}, m2400si{model::pkp2400si},
    m1600si{model::pkp1600si}, si_s16 = m3500si | m2500si,
                               si_s8 = m1500li | m2200si | m2300si | m2400si | m1600si,
                               si = m2600si | m3500mt | si_s16 | si_s8;

struct row {
    std::string_view section;  // manual and section (PK1000 "n", PKP "PKP n", "ref" PKP-2600)
    model_set models;
    std::uint8_t node;  // the keypad's node id when the frame is sent
    std::string_view frame;
    message expected;
};

struct error_row {
    std::string_view section;
    model_set models;
    std::uint8_t node;
    std::string_view frame;
    errc error;
};

struct encode_error_row {
    std::string_view section;
    model_set models;
    std::uint8_t node;
    std::string_view frame;
    message msg;
    errc error;
};

constexpr canopen::node_id node_of(std::uint8_t n) noexcept {
    return canopen::node_id::make(n).value();
}

// Calls f(m) for every model of the mask; false when the mask names none or f fails once.
template <class F>
constexpr bool for_models(const model_set& models, F f) {
    bool any = false;
    for (std::size_t i = 0; i < model_count; ++i) {
        const auto m = static_cast<model>(i);
        if (!models.contains(m)) continue;
        any = true;
        if (!f(m)) return false;
    }
    return any;
}

// Decodes to its meaning and re-encodes byte for byte, for every model of the row.
constexpr bool round_trips(const row& r) {
    const auto f = can::parse_candump(r.frame);
    if (!f) return false;
    return for_models(r.models, [&](model m) {
        const auto d = decode(*f, node_of(r.node), m);
        if (!d || !(*d == r.expected)) return false;
        const auto e = encode(node_of(r.node), m, r.expected);
        return e && *e == *f;
    });
}

// Refused with the row's error by every model of the row.
constexpr bool refused(const error_row& r) {
    const auto f = can::parse_candump(r.frame);
    if (!f) return false;
    // Strictly: the rows pin the manual form (test_keypad_codec_form.cpp reads other lengths).
    return for_models(r.models, [&](model m) {
        return decode(*f, node_of(r.node), m, reading::strict) == r.error;
    });
}

// encode refuses the message with the row's error, and the frame a raw encoder would build does
// not decode to the message.
constexpr bool encode_refused(const encode_error_row& r) {
    return for_models(r.models, [&](model m) {
        if (!(encode(node_of(r.node), m, r.msg) == r.error)) return false;
        if (r.frame.empty()) return true;
        const auto f = can::parse_candump(r.frame);
        if (!f) return false;
        const auto d = decode(*f, node_of(r.node), m);
        return !d || !(*d == r.msg);
    });
}

// --- builders shared by the tables --------------------------------------------------------------

constexpr message nmt(nmt_command c, std::uint8_t target = 0x15) noexcept {
    return canopen::nmt_message{c, canopen::nmt_target::make(target).value()};
}
constexpr message hb(nmt_state s) noexcept { return canopen::heartbeat_message{s}; }
constexpr message sync() noexcept { return canopen::sync_message{}; }
constexpr message read(object o) noexcept { return sdo_read{o}; }
constexpr message written(object o) noexcept { return sdo_write_reply{o}; }
constexpr message write(object o, object_value v) noexcept { return sdo_write{o, v}; }
constexpr message reply(object o, object_value v) noexcept { return sdo_read_reply{o, v}; }
// A number write or reply (counts, identity, COB-ID and mapping words, times, levels).
constexpr message write(object o, std::uint32_t v) noexcept {
    return sdo_write{o, number_value(v)};
}
constexpr message value(object o, std::uint32_t v) noexcept {
    return sdo_read_reply{o, number_value(v)};
}
constexpr message initiate(std::uint16_t index, std::uint8_t sub, bool indicated,
                           std::uint32_t size) noexcept {
    return canopen::sdo_upload_initiate_response{{index, sub}, indicated, size};
}
constexpr message next(bool toggle) noexcept { return canopen::sdo_segment_request{toggle}; }
constexpr message segment(bool toggle, std::uint8_t unused, bool last,
                          std::array<std::uint8_t, 7> bytes) noexcept {
    return canopen::sdo_segment_response{toggle, canopen::segment_unused::make(unused).value(),
                                         last, bytes};
}
constexpr leds rgb(led_set r, led_set g = {}, led_set b = {}) noexcept { return {r, g, b}; }
// A key-state PDO (tick 2Ah, the manuals' examples), LED map PDOs, and one plane of an LED
// register (PK1000 2001h/2002h, the SI family's per-colour objects).
constexpr message keys(key_set k) noexcept { return key_state{k, 0x2A}; }
constexpr message on(led_set r, led_set g = {}, led_set b = {}) noexcept {
    return led_on{rgb(r, g, b)};
}
constexpr message blink(led_set r, led_set g = {}, led_set b = {}) noexcept {
    return led_blink{rgb(r, g, b)};
}
constexpr object_value red(led_set s) noexcept { return leds_value(rgb(s)); }
constexpr object_value green(led_set s) noexcept { return leds_value(rgb({}, s)); }
constexpr object_value blue(led_set s) noexcept { return leds_value(rgb({}, {}, s)); }
// Members from..to: LEDs by default, keys with key_span.
template <class Set = led_set>
constexpr Set span(unsigned from, unsigned to) noexcept {
    Set s;
    for (unsigned k = from; k <= to; ++k) s.insert(k);
    return s;
}
constexpr key_set key_span(unsigned from, unsigned to) noexcept { return span<key_set>(from, to); }

// --- the core rows ------------------------------------------------------------------------------

inline constexpr row core_rows[] = {
    {"PK1000 4", all, 0x15, "000#0115", nmt(nmt_command::start)},
    {"PK1000 5", all, 0x15, "000#8015", nmt(nmt_command::enter_pre_operational)},
    {"PK1000 6", all, 0x15, "000#8115", nmt(nmt_command::reset_node)},
    {"PK1000 7", all, 0x15, "000#0215", nmt(nmt_command::stop)},
    {"PK1000 7 (old sw)", all, 0x15, "000#0015", nmt(nmt_command::legacy_stop)},
    {"PKP 4", all, 0x15, "000#0100", nmt(nmt_command::start, 0)},
    {"PK1000 8", all, 0x15, "715#00", hb(nmt_state::boot_up)},
    {"PK1000 29", all, 0x15, "715#7F", hb(nmt_state::pre_operational)},
    {"PK1000 29", all, 0x15, "715#05", hb(nmt_state::operational)},
    {"PK1000 10", all, 0x15, "080#", sync()},
    {"PK1000 32", all, 0x15, "615#4008100000000000", read(object::device_name)},
    {"PK1000 32", all, 0x15, "595#410810000B000000", initiate(0x1008, 0, true, 11)},
    {"PK1000 32", all, 0x15, "615#6000000000000000", next(false)},
    {"PK1000 32", all, 0x15, "595#00426C696E6B4D61",
     segment(false, 0, false, {0x42, 0x6C, 0x69, 0x6E, 0x6B, 0x4D, 0x61})},
    {"PK1000 32", all, 0x15, "615#7000000000000000", next(true)},
    {"PK1000 32", all, 0x15, "595#1772696E65000000",
     segment(true, 3, true, {0x72, 0x69, 0x6E, 0x65, 0, 0, 0})},
    {"PK1000 29", all, 0x15, "615#4017100000000000", read(object::heartbeat_time)},
    {"PK1000 29", all, 0x15, "615#2B17100032000000", write(object::heartbeat_time, 50)},
    {"PK1000 29", all, 0x15, "615#2B171000F4010000", write(object::heartbeat_time, 500)},
    {"PK1000 29", all, 0x15, "595#6017100000000000", written(object::heartbeat_time)},
    {"PK1000 29", all, 0x15, "595#4B17100064000000", value(object::heartbeat_time, 100)},
    {"CiA 301 7.2.4.3.17 (PK1000 31: 1001h not implemented)", all, 0x15, "595#8001100000000206",
     canopen::sdo_abort_response{{{0x1001, 0}, canopen::sdo_abort_code::object_does_not_exist}}},
    {"CiA 301 7.2.4.3.17", all, 0x15, "615#8008100000000405",
     canopen::sdo_abort_request{{{0x1008, 0}, canopen::sdo_abort_code::timed_out}}},
    {"PK1000 49", m1000, 0x15, "18EF2100#041B8000FFFFFFFF", j1939::switch_to_canopen{}},
};

// Frames that are not keypad 15h's (another node, another function): classified, refused by
// every model, never mis-decoded.
struct foreign_row {
    std::string_view section;
    std::string_view frame;
    canopen::cob_info cls;
    errc error;
};

inline constexpr foreign_row foreign_rows[] = {
    {"SDO request to node 16h",
     "616#4008100000000000",
     {canopen::function::sdo_rx, 0x16},
     errc::wrong_id},
    {"SDO reply of node 3Ah",
     "5BA#6013200000000000",
     {canopen::function::sdo_tx, 0x3A},
     errc::wrong_id},
    {"heartbeat of node 18h", "718#00", {canopen::function::heartbeat, 0x18}, errc::wrong_id},
    {"key state of node 16h", "196#0100000000", {canopen::function::tpdo1, 0x16}, errc::wrong_id},
    {"EMCY of node 1", "081#00", {canopen::function::other, 0}, errc::wrong_id},
    {"TIME", "100#00", {canopen::function::other, 0}, errc::wrong_id},
    {"LSS", "7E5#0400000000000000", {canopen::function::other, 0}, errc::wrong_id},
    {"TPDO2 base, no node", "280#0102", {canopen::function::other, 0}, errc::wrong_id},
};

// Malformed frames of keypad 15h that no dictionary makes valid: the precise error.
inline constexpr error_row core_error_rows[] = {
    {"NMT of 1 byte", all, 0x15, "000#01", errc::wrong_length},
    {"NMT command 03h", all, 0x15, "000#0315", errc::unknown_command},
    {"NMT node 80h", all, 0x15, "000#0180", errc::value_out_of_range},
    {"SYNC with data", all, 0x15, "080#00", errc::wrong_length},
    {"the node id itself as a COB-ID (function code 0)", all, 0x15, "015#00", errc::wrong_id},
    {"heartbeat state 01h", all, 0x15, "715#01", errc::value_out_of_range},
    {"heartbeat of 2 bytes", all, 0x15, "715#0000", errc::wrong_length},
    {"SDO of 4 bytes", all, 0x15, "615#40081000", errc::wrong_length},
    {"E-CORE-4 upload request 41h", all, 0x15, "615#4108100000000000", errc::reserved_not_zero},
    {"segmented download 20h", all, 0x15, "615#2008100000000000", errc::unknown_command},
    {"SDO reply specifier E0h", all, 0x15, "595#E008100000000000", errc::unknown_command},
    // A 29-bit frame is read by the J1939 codec (keypad/j1939_codec.hpp) on every model.
    {"PK1000 49 switch, byte 7 not FFh (a J1939 'not used' byte)", m1000, 0x15,
     "18EF2100#041B8000FFFFFF00", errc::reserved_not_ff},
    {"PK1000 49 switch's bytes on PGN EE00h: a NAME with its reserved bit set", m1000, 0x15,
     "18EE2100#041B8000FFFFFFFF", errc::reserved_not_zero},
    {"PK1000 49 switch on PGN EA00h (no keypad frame)", all, 0x15, "18EA2100#041B8000FFFFFFFF",
     errc::wrong_id},
    // No PKP (LI) source shows 80h.
    {"PK1000 49 switch to a PKP (no source shows it)", pkp, 0x15, "18EF2100#041B8000FFFFFFFF",
     errc::undocumented},
};

}  // namespace codec_rows

#endif  // POWERKEY_TESTS_CODEC_ROWS_HPP
