// The DBC writer (tools/powerkey/dbc.hpp) against the library, for every model: what a DBC reader
// would not check (names, overlaps, multiplexor values) and what the library decides (each SDO
// multiplexor value is the request or reply it names; each number's range is the one the decoder
// accepts). tests/test_dbc.py reads the files with canmatrix and compares every sample-log frame.
#include <doctest/doctest.h>

#include "../tools/powerkey/dbc.hpp"
#include "j1939_rows.hpp"

#include <powerkey/can/candump.hpp>
#include <powerkey/can/frame.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/j1939_codec.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/names.hpp>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace {

using namespace powerkey;
namespace dbc = tool::dbc;

constexpr canopen::node_id nodes[] = {0x15, 0x7F};

bool identifier(std::string_view s) {
    if (s.empty() || s.size() > dbc::name_limit || (s[0] >= '0' && s[0] <= '9')) return false;
    return std::all_of(s.begin(), s.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_';
    });
}

std::uint64_t field_mask(const dbc::signal& s) {
    return (s.size >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << s.size) - 1) << s.start;
}

std::uint64_t place(const dbc::signal& s, std::uint64_t raw) {
    return (raw << s.start) & field_mask(s);
}

// The signals present when the multiplexor has value `mux` (nullopt: a message without one).
std::vector<const dbc::signal*> group(const dbc::message& m, std::optional<std::uint64_t> mux) {
    std::vector<const dbc::signal*> out;
    for (const auto& s : m.signals)
        if (!s.multiplexor && (!s.mux || s.mux == mux)) out.push_back(&s);
    return out;
}

const dbc::signal* multiplexor(const dbc::message& m) {
    for (const auto& s : m.signals)
        if (s.multiplexor) return &s;
    return nullptr;
}

can::frame frame_of(const dbc::message& m, std::uint64_t data) {
    can::payload p{};
    for (std::size_t i = 0; i < 8; ++i) p[i] = static_cast<std::uint8_t>(data >> (8 * i));
    return can::frame(can::standard_id::make(m.id).value(), can::dlc::make(m.dlc).value(), p);
}

std::string_view kind_of_message(const message& msg) {
    return std::visit([](const auto& v) -> std::string_view { return v.kind; }, msg);
}

std::optional<object> object_of(const message& msg) {
    return std::visit(
        [](const auto& v) -> std::optional<object> {
            if constexpr (requires { v.object; })
                return v.object;
            else
                return std::nullopt;
        },
        msg);
}

std::string label(model m, canopen::node_id n, const dbc::message& msg, std::string_view more) {
    return std::string(to_string(m)) + " node " + std::to_string(n.value()) + " " + msg.name + " " +
           std::string(more);
}

}  // namespace

TEST_CASE("dbc: every model's names, sizes and multiplexor values are well formed") {
    for (const auto m : enum_values<model>())
        for (const auto n : nodes) {
            const auto db = dbc::describe(m, n);
            CHECK(identifier(db.name));
            std::set<std::uint32_t> ids;
            for (const auto& msg : db.messages) {
                INFO(label(m, n, msg, ""));
                CHECK(identifier(msg.name));
                CHECK(ids.insert(msg.id).second);
                CHECK(msg.dlc <= 8);
                std::set<std::string> names;
                for (const auto& s : msg.signals) {
                    INFO(s.name);
                    CHECK(identifier(s.name));
                    CHECK(names.insert(s.name).second);
                    CHECK(s.size >= 1);
                    CHECK(s.start + s.size <= 8 * msg.dlc);
                    CHECK(s.minimum <= s.maximum);
                    CHECK(s.comment.find('"') == std::string::npos);
                }
                // Signals present together do not overlap; every multiplexed value is named.
                const auto* mux = multiplexor(msg);
                std::vector<std::optional<std::uint64_t>> groups{std::nullopt};
                if (mux) {
                    groups.clear();
                    std::set<std::uint64_t> named;
                    for (const auto& v : mux->values) CHECK(named.insert(v.value).second);
                    for (const auto& s : msg.signals)
                        if (s.mux) {
                            CHECK(named.count(*s.mux) == 1);
                            groups.push_back(*s.mux);
                        }
                }
                for (const auto& g : groups) {
                    std::uint64_t used = mux ? field_mask(*mux) : 0;
                    for (const auto* s : group(msg, g)) {
                        INFO(s->name);
                        CHECK((used & field_mask(*s)) == 0);
                        used |= field_mask(*s);
                    }
                }
            }
        }
}

TEST_CASE("dbc: each SDO multiplexor value is the request or reply it names") {
    std::size_t checked = 0;
    for (const auto m : enum_values<model>())
        for (const auto n : nodes) {
            const auto db = dbc::describe(m, n);
            const auto dictionary = info(m)->dictionary;
            for (const auto& msg : db.messages) {
                const auto* mux = multiplexor(msg);
                if (!mux || msg.extended) continue;  // J1939: below
                for (const auto& v : mux->values) {
                    INFO(label(m, n, msg, v.name));
                    const auto space = v.name.find(' ');
                    const std::string kind = v.name.substr(0, space);
                    const std::string object_name =
                        space == std::string::npos ? "" : v.name.substr(space + 1);
                    // Every value signal at its minimum, the rest zero.
                    std::uint64_t data = v.value;
                    for (const auto* s : group(msg, v.value))
                        data |= place(*s, static_cast<std::uint64_t>(s->minimum) / s->factor);
                    const auto got = decode(frame_of(msg, data), n, m);
                    if (kind == "command") {  // any command byte needs its parameters: the header
                        CHECK((got || got.error() == errc::value_out_of_range));
                        continue;
                    }
                    REQUIRE(got);
                    CHECK(kind_of_message(*got) == kind);
                    const auto o = from_string<object>(object_name);
                    REQUIRE(o);
                    if (const auto decoded = object_of(*got)) {
                        CHECK(*decoded == *o);
                    } else {  // the segmented read's first reply carries the address
                        const auto& r =
                            std::get<canopen::sdo_upload_initiate_response>(*got).address;
                        CHECK(r == find_row(dictionary, *o)->address);
                    }
                    ++checked;
                }
            }
        }
    CHECK(checked > 1000);
}

TEST_CASE("dbc: each number's range is the one the library accepts") {
    // For each group of signals (a PDO, or one SDO request or reply): every signal at its
    // minimum decodes; then each number at its maximum decodes, and one past either end (where
    // the bits can hold it) is refused. The command module's bytes depend on the command: left
    // out. Values inside a range that the library refuses (heartbeat state 01h, TOP 01h, the
    // transmission types F1h..FDh) are what a DBC range cannot say: docs/dbc.md.
    std::size_t checked = 0;
    for (const auto m : enum_values<model>())
        for (const auto n : nodes) {
            const auto db = dbc::describe(m, n);
            for (const auto& msg : db.messages) {
                if (msg.name == "sync" || msg.extended) continue;  // J1939: below
                const auto* mux = multiplexor(msg);
                std::vector<std::pair<std::optional<std::uint64_t>, std::string>> groups;
                if (mux)
                    for (const auto& v : mux->values) groups.push_back({v.value, v.name});
                else
                    groups.push_back({std::nullopt, ""});
                for (const auto& entry : groups) {
                    const auto& g = entry.first;
                    const std::string& what = entry.second;
                    if (what == "command") continue;
                    INFO(label(m, n, msg, what));
                    const auto members = group(msg, g);
                    std::uint64_t base = g.value_or(0);
                    for (const auto* s : members)
                        base |= place(*s, static_cast<std::uint64_t>(s->minimum) / s->factor);
                    REQUIRE(decode(frame_of(msg, base), n, m));
                    for (const auto* s : members) {
                        if (s->size == 1) continue;
                        INFO(s->name);
                        const auto lo = static_cast<std::uint64_t>(s->minimum) / s->factor;
                        const auto hi = static_cast<std::uint64_t>(s->maximum) / s->factor;
                        const auto with = [&](std::uint64_t raw) {
                            return frame_of(msg, (base & ~field_mask(*s)) | place(*s, raw));
                        };
                        CHECK(decode(with(hi), n, m));
                        if (s->size < 64 && hi + 1 < (std::uint64_t{1} << s->size))
                            CHECK(!decode(with(hi + 1), n, m));
                        if (lo > 0) CHECK(!decode(with(lo - 1), n, m));
                        ++checked;
                    }
                }
            }
        }
    CHECK(checked > 1000);
}

TEST_CASE("dbc: every key and LED the library encodes has its one-bit signal") {
    // The PDO maps: the signals are found by encoding one key or LED (dbc.cpp); here their count
    // is the model row's (keys, and the LEDs of led_mask in each plane).
    for (const auto m : enum_values<model>()) {
        const auto mi = *info(m);
        const auto db = dbc::describe(m, 0x15);
        const auto count = [&](std::string_view message) {
            for (const auto& msg : db.messages)
                if (msg.name == message)
                    return std::count_if(msg.signals.begin(), msg.signals.end(),
                                         [](const dbc::signal& s) { return s.size == 1; });
            return std::ptrdiff_t{-1};
        };
        INFO(to_string(m));
        CHECK(count("key_state") == mi.keys);
        const auto leds = static_cast<std::ptrdiff_t>(std::popcount(mi.led_mask)) * mi.planes;
        CHECK(count("led_on") == leds);
        CHECK(count("led_blink") == leds);
        CHECK(count("encoder_leds") == (mi.encoder_leds_pdo ? 32 : -1));
        CHECK(count("led_brightness") == (mi.brightness_pdo ? 0 : -1));
        CHECK(count("backlight") == (mi.backlight_pdo ? 0 : -1));
        CHECK(count("analog_inputs") == (mi.encoders ? 0 : -1));
    }
}

TEST_CASE("dbc: the text is the same for the same model and node, and names the node") {
    const auto a = dbc::text(dbc::describe(model::pkp2400, 0x3A));
    CHECK(a == dbc::text(dbc::describe(model::pkp2400, 0x3A)));
    CHECK(a != dbc::text(dbc::describe(model::pkp2400, 0x15)));
    CHECK(a.find("\nBO_ 442 key_state: 5 keypad\n") != std::string::npos);  // 180h + 3Ah
    CHECK(a.find("BA_ \"DBName\" \"pkp2400_3Ah\";") != std::string::npos);
}

TEST_CASE("dbc: each key and LED bit of an SDO value is that key or LED for the library") {
    // The SDO objects' one-bit signals, named OBJECT_MEMBERk (keys_key9, led_on_red_red3,
    // led_on_encoder_led17): the frame of the header and that one bit decodes to a value holding
    // exactly that key or LED.
    std::size_t checked = 0;
    for (const auto m : enum_values<model>()) {
        const auto db = dbc::describe(m, 0x15);
        for (const auto& msg : db.messages) {
            if (!multiplexor(msg) || msg.extended) continue;  // J1939: below
            for (const auto& s : msg.signals) {
                if (!s.mux || s.size != 1) continue;
                const auto member = s.name.substr(s.name.rfind('_') + 1);
                const auto digits = member.find_first_of("0123456789");
                if (digits == std::string::npos || digits == 0) continue;  // a flag: no_rtr ...
                INFO(label(m, 0x15, msg, s.name));
                const auto what = member.substr(0, digits);
                const auto k = static_cast<unsigned>(std::stoul(member.substr(digits)));
                const auto got = decode(frame_of(msg, *s.mux | place(s, 1)), 0x15, m);
                REQUIRE(got);
                const object_value* v = nullptr;
                if (const auto* r = std::get_if<sdo_read_reply>(&*got)) v = &r->value;
                if (const auto* w = std::get_if<sdo_write>(&*got)) v = &w->value;
                REQUIRE(v);
                if (what == "key" || what == "led") {
                    CHECK(v->raw == (std::uint32_t{1} << (k - 1)));
                } else {
                    const auto p = from_string<plane>(what);
                    REQUIRE(p);
                    leds want;
                    want.of(*p).insert(k);
                    CHECK(v->map == want);
                }
                ++checked;
            }
        }
    }
    CHECK(checked > 1000);
}

// --- J1939
// ----------------------------------------------------------------------------------------

namespace {

// The frame of a J1939 message: the header 04h 1Bh, the command byte `mux`, the signals given,
// the rest of a byte that holds a signal 0 (the heartbeat's key bits past the model's keys), every
// other byte FFh ("not used").
can::frame j1939_frame(const dbc::message& m, std::uint64_t mux,
                       const std::vector<std::pair<const dbc::signal*, std::uint64_t>>& values) {
    std::uint64_t data = ~std::uint64_t{0} & ~std::uint64_t{0xFF'FFFF};
    data |= j1939::header_0 | (std::uint64_t{j1939::header_1} << 8) | (mux << 16);
    for (const auto& [s, raw] : values) {
        for (unsigned b = s->start / 8; b <= (s->start + s->size - 1) / 8; ++b)
            data &= ~(std::uint64_t{0xFF} << (8 * b));
    }
    for (const auto& [s, raw] : values) data = (data & ~field_mask(*s)) | place(*s, raw);
    can::payload p{};
    for (std::size_t i = 0; i < 8; ++i) p[i] = static_cast<std::uint8_t>(data >> (8 * i));
    return can::frame(can::extended_id::make(m.id).value(), can::dlc::make(8).value(), p);
}

// What a multiplexor value names for a decoded J1939 message: its kind, or a command's code.
std::string j1939_name(const j1939::message& msg) {
    if (const auto* c = std::get_if<j1939::command>(&msg)) return std::string(to_string(c->code));
    return std::string(std::visit([](const auto& v) { return v.kind; }, msg));
}

}  // namespace

TEST_CASE("dbc: each J1939 command value is the frame it names, each range the codec's") {
    // For every model's J1939 messages and command byte: the frame of every signal at its minimum
    // decodes with the J1939 codec to the message the value names; each number at its maximum
    // decodes, one past either end (where the byte holds it) is refused; each heartbeat key bit
    // alone is that one key.
    std::size_t values = 0, numbers = 0, keys = 0;
    for (const auto m : enum_values<model>()) {
        const auto db = dbc::describe(m, 0x15);
        for (const auto& msg : db.messages) {
            if (!msg.extended) continue;
            const auto* mux = multiplexor(msg);
            REQUIRE(mux);
            CHECK(mux->start == 16);
            for (const auto& v : mux->values) {
                INFO(label(m, 0x15, msg, v.name));
                std::vector<std::pair<const dbc::signal*, std::uint64_t>> base;
                for (const auto* s : group(msg, v.value))
                    base.push_back({s, static_cast<std::uint64_t>(s->minimum) / s->factor});
                const auto got = j1939::decode(j1939_frame(msg, v.value, base), m);
                REQUIRE(got);
                CHECK(j1939_name(*got) == v.name);
                ++values;
                for (std::size_t i = 0; i < base.size(); ++i) {
                    const auto* s = base[i].first;
                    if (s->size == 1) continue;
                    INFO(s->name);
                    const auto with = [&](std::uint64_t raw) {
                        auto changed = base;
                        changed[i].second = raw;
                        return j1939::decode(j1939_frame(msg, v.value, changed), m);
                    };
                    const auto lo = static_cast<std::uint64_t>(s->minimum) / s->factor;
                    const auto hi = static_cast<std::uint64_t>(s->maximum) / s->factor;
                    CHECK(with(hi));
                    if (hi < 0xFF) CHECK(!with(hi + 1));
                    if (lo > 0) CHECK(!with(lo - 1));
                    ++numbers;
                }
                for (const auto* s : group(msg, v.value)) {
                    if (s->size != 1) continue;
                    INFO(s->name);
                    REQUIRE(s->name.starts_with("heartbeat_key"));
                    auto one = base;
                    for (auto& [t, raw] : one)
                        if (t == s) raw = 1;
                    const auto beat = j1939::decode(j1939_frame(msg, v.value, one), m);
                    REQUIRE(beat);
                    const auto k = static_cast<unsigned>(std::stoul(s->name.substr(13)));
                    CHECK(std::get<j1939::heartbeat>(*beat).keys == key_set{k});
                    ++keys;
                }
            }
        }
    }
    CHECK(values > 200);
    CHECK(numbers > 200);
    CHECK(keys > 100);
}

TEST_CASE("dbc: every J1939 frame of the manuals is described, with its values in range") {
    // The rows of tests/j1939_rows.hpp (both complete manuals, and the other models' frames): each
    // frame at the default addresses on PGN EF00h with the header is a value of the model's
    // message for its direction, named as the library decodes it, and each signal of that value
    // reads a value inside its range, a named one where the signal names its values. Frames the
    // files leave out (the multiple-LED command, the acknowledgement, the revision answer, the
    // address claim) are counted, and so are frames between other addresses than the defaults.
    std::size_t described = 0, left_out = 0, elsewhere = 0;
    std::vector<decltype(dbc::describe(model{}, 0x15))> files;  // each model's file, made once
    for (const auto m : enum_values<model>()) files.push_back(dbc::describe(m, 0x15));
    const auto check_rows = [&](std::span<const j1939_rows::row> rows) {
        for (const auto& r : rows)
            for (const auto m : enum_values<model>()) {
                if (!r.models.contains(m)) continue;
                const std::string where = std::string(to_string(m)) + " " + std::string(r.section) +
                                          " " + std::string(r.frame);
                INFO(where);
                const auto f = can::parse_candump(r.frame);
                REQUIRE(f);
                const auto got = j1939::decode(*f, m);
                REQUIRE(got);
                const auto& db = files[static_cast<std::size_t>(m)];
                const bool from_keypad = std::holds_alternative<j1939::key_contact>(*got) ||
                                         std::holds_alternative<j1939::heartbeat>(*got);
                const dbc::message* msg = nullptr;
                for (const auto& x : db.messages)
                    if (x.name == (from_keypad ? "j1939_from_keypad" : "j1939_to_keypad")) msg = &x;
                const std::string name = j1939_name(*got);
                const bool in_file = std::holds_alternative<j1939::key_contact>(*got) ||
                                     std::holds_alternative<j1939::heartbeat>(*got) ||
                                     std::holds_alternative<j1939::set_led>(*got) ||
                                     std::holds_alternative<j1939::set_led_code>(*got) ||
                                     std::holds_alternative<j1939::command>(*got) ||
                                     std::holds_alternative<j1939::switch_to_canopen>(*got);
                if (!in_file) {
                    ++left_out;
                    continue;
                }
                REQUIRE(msg);
                if (msg->id != f->raw_id()) {  // other addresses: a file describes the defaults
                    ++elsewhere;
                    continue;
                }
                const auto value = (*f)[2];
                const auto* mux = multiplexor(*msg);
                REQUIRE(mux);
                const auto named =
                    std::find_if(mux->values.begin(), mux->values.end(),
                                 [&](const dbc::value_name& v) { return v.value == value; });
                REQUIRE(named != mux->values.end());
                CHECK(named->name == name);
                const auto data = f->data_le();
                for (const auto* s : group(*msg, value)) {
                    INFO(s->name);
                    const auto raw = (data & field_mask(*s)) >> s->start;
                    const auto physical = static_cast<std::int64_t>(raw * s->factor);
                    CHECK(physical >= s->minimum);
                    CHECK(physical <= s->maximum);
                    if (!s->values.empty())
                        CHECK(
                            std::any_of(s->values.begin(), s->values.end(),
                                        [&](const dbc::value_name& v) { return v.value == raw; }));
                }
                ++described;
            }
    };
    check_rows(j1939_rows::pkp1600si_rows);
    check_rows(j1939_rows::pkp2600si_rows);
    check_rows(j1939_rows::other_rows);
    CHECK(described > 100);
    CHECK(left_out > 10);
    CHECK(elsewhere > 0);
}
