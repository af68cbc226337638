// behaviour/virtual_keypad.hpp: the virtual keypad. The manuals' transcripts replayed against it,
// model by model; one test per behaviour; every model answering every readable object. Its runs
// against the controller are in test_behaviour_controller.cpp.
#include "behaviour_support.hpp"
#include "j1939_rows.hpp"
#include "pk1000_rows.hpp"
#include "pkp_rows.hpp"
#include "support.hpp"

#include <powerkey/behaviour/controller.hpp>
#include <powerkey/behaviour/virtual_keypad.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace doctest {
template <>
struct StringMaker<std::vector<std::string>> {
    static String convert(const std::vector<std::string>& v) {
        std::string s = "{";
        for (const auto& x : v) s += (s.size() > 1 ? ", \"" : "\"") + x + "\"";
        return (s + "}").c_str();
    }
};
}  // namespace doctest

using namespace powerkey;
using behaviour::duration_ms;
using behaviour::millis;
using behaviour::run_state;
using behaviour::virtual_keypad;
using powerkey_tests::frame_of;

namespace {

// --- the transcript runner -----------------------------------------------------------------------

// Whether the keypad sends a frame (heartbeat, TPDO, SDO reply) rather than hears it.
bool from_keypad(const can::frame& f) {
    if (f.is_extended()) return false;
    const auto fn = f.raw_id() & 0x780u;
    return fn == 0x180 || fn == 0x580 || fn == 0x700;
}

// The keys a keypad frame reports: the key-state PDO, or a read reply of 2000h/1 or 6000h/0.
std::optional<key_set> keys_in(const can::frame& f) {
    if (f.is_extended()) return std::nullopt;
    const auto fn = f.raw_id() & 0x780u;
    const auto bits = [&](std::size_t at) {
        return key_set::from_mask(detail::load_le<4>(f.bytes(), at));
    };
    if (fn == 0x180 && f.size() == 5) return bits(0);
    if (fn == 0x580 && (f[0] & 0xE0) == 0x40 && f[0] != 0x40 && f[0] != 0x41 &&
        ((f[1] == 0x00 && f[2] == 0x20 && f[3] == 0x01) ||
         (f[1] == 0x00 && f[2] == 0x60 && f[3] == 0x00)))
        return bits(4);
    return std::nullopt;
}

// Frames equal as the manual means them: the tick byte of the key-state PDO is printed XX.
bool same(const can::frame& want, const can::frame& got) {
    if ((want.raw_id() & 0x780u) == 0x180 && want.size() == 5 && got.size() == 5 &&
        want.raw_id() == got.raw_id()) {
        for (std::size_t i = 0; i < 4; ++i)
            if (want[i] != got[i]) return false;
        return true;
    }
    return want == got;
}

std::string text_of(const can::frame& f) {
    return doctest::StringMaker<can::frame>::convert(f).c_str();
}

// The section a row belongs to: the first word that starts with a digit, and a one-letter word
// after it: "17a" of "17a" and "19f E-PK-3 corrected", "13a" of "PKP 13a LED 8 red", "17 a" of
// "PKP2600SI 17 a"; "ref" for the reference rows of the PKP-2600.
std::string_view section_of(std::string_view s) {
    if (s.substr(0, 4) == "ref ") return "ref";
    std::size_t i = 0;
    while (i < s.size()) {
        const std::size_t end = std::min(s.find(' ', i), s.size());
        if (s[i] >= '0' && s[i] <= '9') {
            if (end + 2 <= s.size() && s[end + 1] >= 'a' && s[end + 1] <= 'z' &&
                (end + 2 == s.size() || s[end + 2] == ' '))
                return s.substr(i, end + 2 - i);
            return s.substr(i, end - i);
        }
        i = end + 1;
    }
    return s;
}

// Why a printed reply is not what a keypad at its defaults sends.
enum class because : std::uint8_t {
    erratum,      // the manual prints it wrongly (docs/errata.md)
    presumed,     // it shows a state the section does not set up (a read after other writes)
    other_model,  // the manual prints another model's value (the PKP manual's PKU2200/PKU2400)
};

// A printed row the keypad does not reproduce, and why. `frame` is the printed reply, or
// "+" and a frame the keypad sends where the manual prints no reply.
struct expected_difference {
    model_set models;
    std::string_view section;  // the row's full section text
    std::string_view frame;
    because why;
    std::string_view note;
};

using codec_rows::m1000;
using codec_rows::m2200;
using codec_rows::m2400;
using codec_rows::m2600;
constexpr model_set pkp_all = codec_rows::pkp;
constexpr model_set not2200 = m2400 | m2600;
constexpr model_set si2600 = codec_rows::m2600si;
constexpr model_set mt3500 = codec_rows::m3500mt;

constexpr expected_difference differences[] = {
    // --- PK1000 ---
    {m1000, "11", "195#000000002A", because::presumed,
     "no key: printed after a release; at power-on no key has changed"},
    {m1000, "17b", "595#4301200108000000", because::presumed, "reads red LED 4 on, never set"},
    {m1000, "17b", "595#4301200200020000", because::presumed, "reads green LED 10 on, never set"},
    {m1000, "18b", "595#4302200108000000", because::presumed,
     "reads red LED 4 blinking, never set"},
    {m1000, "18b", "595#4302200200010000", because::presumed,
     "reads green LED 9 blinking, never set"},
    {m1000, "19c E-PK-2", "595#4F03200304000000", because::erratum,
     "E-PK-2: 05h (cyan) was written, the manual reads 04h"},
    {m1000, "22", "595#4F12200000000000", because::presumed,
     "reads 00h right after writing 01h: the example of another keypad state"},
    {m1000, "29", "595#4B17100064000000", because::presumed,
     "reads 100 ms: heartbeat_time is 0 at delivery (section 3)"},
    {m1000, "36 E-PK-4", "595#4311100100000000", because::erratum,
     "E-PK-4: a download is acknowledged with 60h"},
    {m1000, "43 E-PK-5", "595#4301160120020220", because::erratum,
     "E-PK-5: the reply repeats the request's sub-index 02h"},
    {m1000, "6", "+715#00", because::presumed,
     "reset node: the keypad boots again and sends its boot-up (section 8); not printed in 6"},
    {m1000, "49", "+595#60FF200100000000", because::presumed,
     "the acknowledgement of the J1939 switch, sent before the keypad switches; not printed"},
    {m1000, "49", "+715#00", because::presumed,
     "back in CANopen the keypad boots (inferred); not printed"},
    // --- PKP ---
    {pkp_all, "PKP 6 reset node", "+715#00", because::presumed,
     "reset node: the keypad boots again and sends its boot-up (PKP 8); not printed in 6"},
    {pkp_all, "PKP 9 pre-operational", "715#7F", because::presumed,
     "heartbeats: heartbeat_time is off at delivery (PKP 3)"},
    {pkp_all, "PKP 9 operational", "715#05", because::presumed,
     "heartbeats: heartbeat_time is off at delivery (PKP 3)"},
    {m2200, "PKP 10 PKP-2200 no key (XX=00)", "195#0000000000", because::presumed,
     "no key: printed after a release; at power-on no key has changed"},
    {m2400, "PKP 10 PKP-2400 no key (XX=01)", "195#0000000001", because::presumed,
     "no key: printed after a release; at power-on no key has changed"},
    {m2200, "PKP 13a reply", "595#6000650100000000", because::other_model,
     "the reply to \"LED 8 red\", a request for the 8- and 12-key models"},
    {m2600, "PKP 13a LED 12 blue alternate blink", "+595#6000650100000000", because::presumed,
     "the manual prints two requests in one row and no reply between them"},
    {m2600, "PKP 13a LED 9 blue (E-PKP-1 corrected)", "+595#6000650100000000", because::erratum,
     "E-PKP-1: the reply to \"LED 9 green\" became the \"LED 9 blue\" request"},
    {m2600, "PKP 13a LED 12 green blink", "+595#6000650100000000", because::erratum,
     "E-PKP-1: the reply to \"LED 9 blue\" is the printed 595#6000650100090700"},
    {m2600, "ref 6001h PKP-2600 red 7, green 3, green 11", "+595#6001600000000000",
     because::presumed, "docs/pkp.md (PKP-2600) prints requests without their replies"},
    {m2600, "ref 6001h PKP-2600 read", "+595#6001600000000000", because::presumed,
     "docs/pkp.md (PKP-2600) prints requests without their replies"},
    {m2600, "ref 6001h PKP-2600 read reply red 12, green 1 (layout)", "595#4301600000180000",
     because::presumed, "a layout example, not a transcript"},
    {m2600, "ref 6002h PKP-2600 green 5, 7", "+595#6002600000000000", because::presumed,
     "docs/pkp.md (PKP-2600) prints requests without their replies"},
    {not2200 | m2200, "PKP 22 PKU2400", "595#00504B5532343030", because::other_model,
     "the PKU2400's model name; PKU2200 / PKU2600 inferred"},
    {not2200 | m2200, "PKP 29 PKU2400", "595#00504B5532343030", because::other_model,
     "the PKU2400's model name; PKU2200 / PKU2600 inferred"},
    {pkp_all, "PKP 32 present", "595#4F01630001000000", because::presumed,
     "a second keypad, with a boot loader"},
    {not2200, "PKP 32 6302h 4 keys", "595#4F02630104000000", because::other_model,
     "the PKU2200's count"},
    {not2200, "PKP 32 6302h 12 LEDs", "595#4F0263030C000000", because::other_model,
     "the PKU2200's count"},
    {not2200, "PKP 32 6302h 6 external LEDs", "595#4F02630406000000", because::other_model,
     "the PKU2200's count"},
    {pkp_all, "15b", "*", because::presumed,
     "each read shows another LED state (all red, red 4, ...) that no request sets"},
    {pkp_all, "16b", "*", because::presumed,
     "each read shows another LED state (all amber, ...) that no request sets"},
    // --- PKP-2600-SI (PKP2600SI n) and PKP-3500-MT (PKP3500-MT n), tests/si_rows.hpp ---
    {si2600, "PKP2600SI 6", "+715#00", because::presumed,
     "reset node: the keypad boots again and sends its boot-up (8); not printed in 6"},
    {mt3500, "PKP3500-MT 6", "+715#00", because::presumed,
     "reset node: the keypad boots again and sends its boot-up (8); not printed in 6"},
    {si2600, "PKP2600SI 11", "195#000000002A", because::presumed,
     "no key: printed after a release; at power-on no key has changed"},
    {mt3500, "PKP3500-MT 11", "195#000000002A", because::presumed,
     "no key: printed after a release; at power-on no key has changed"},
    {si2600, "17 b", "*", because::presumed, "reads LED states no request sets"},
    {si2600, "18 b", "*", because::presumed, "reads LED states no request sets"},
    {mt3500, "20 b", "*", because::presumed, "reads LED states no request sets"},
    {mt3500, "20 d", "*", because::presumed, "reads encoder ring LEDs no request sets"},
    {mt3500, "21 b", "*", because::presumed, "reads LED states no request sets"},
    {mt3500, "21 d", "*", because::presumed, "reads encoder ring LEDs no request sets"},
    {mt3500, "19 b", "*", because::presumed,
     "encoder direction counters: the virtual keypad has no encoders"},
    {mt3500, "19 d", "*", because::presumed,
     "encoder direction counters: the virtual keypad has no encoders"},
    {si2600, "PKP2600SI 19 c E-SI-4", "595#4F03200304000000", because::erratum,
     "E-SI-4: 05h (cyan) was written, the manual reads 04h"},
    {si2600, "PKP2600SI 22 E-SI-14", "595#4F12200000000000", because::erratum,
     "E-SI-14: reads 00h right after writing 01h"},
    {mt3500, "PKP3500-MT 25 E-SI-14", "595#4F06200008000000", because::erratum,
     "E-SI-14: reads 08h right after writing 64h"},
    {mt3500, "PKP3500-MT 24 E-SI-10", "595#4F05200400000000", because::erratum,
     "E-SI-10: the reply names sub-index 04h"},
    {mt3500, "24", "*", because::presumed,
     "analog inputs: the virtual keypad has none, they read 0"},
    {si2600, "PKP2600SI 27", "595#4B17100064000000", because::presumed,
     "reads 100 ms: heartbeat_time is 0 at delivery"},
    {mt3500, "PKP3500-MT 33", "595#4B17100064000000", because::presumed,
     "reads 100 ms: heartbeat_time is 0 at delivery"},
    {si2600, "PKP2600SI 34 E-SI-6", "595#4311100100000000", because::erratum,
     "E-SI-6: a download is acknowledged with 60h"},
    {mt3500, "PKP3500-MT 40 E-SI-6", "595#4311100100000000", because::erratum,
     "E-SI-6: a download is acknowledged with 60h"},
    {si2600, "PKP2600SI 47", "+595#60FF200100000000", because::presumed,
     "the acknowledgement of the J1939 switch, sent before the keypad switches; not printed"},
    {si2600, "PKP2600SI 47", "+715#00", because::presumed,
     "back in CANopen the keypad boots (inferred); not printed"},
    {mt3500, "PKP3500-MT 58", "+595#60FF200100000000", because::presumed,
     "the acknowledgement of the J1939 switch, sent before the keypad switches; not printed"},
    {mt3500, "PKP3500-MT 58", "+715#00", because::presumed,
     "back in CANopen the keypad boots (inferred); not printed"},
    {pkp_all, "PKP 17 100 ms", "595#4B17100064000000", because::presumed,
     "reads 100 ms: heartbeat_time is off at delivery (PKP 3)"},
};

std::optional<expected_difference> difference_of(model m, std::string_view section,
                                                 std::string_view frame) {
    for (const auto& d : differences)
        if (d.models.contains(m) && (d.frame == "*" ? d.section == section_of(section)
                                                    : d.section == section && d.frame == frame))
            return d;
    return std::nullopt;
}

struct transcript_result {
    std::size_t replies = 0, identical = 0, errata = 0, presumed = 0, other_model = 0, extra = 0;
    std::vector<std::string> mismatches;  // rows neither identical nor listed
    std::vector<std::string> listed;      // listed rows, with their reason
};

// Feeds each section's requests, in order, to a keypad at its defaults and compares what it
// sends with each reply the manual prints. The runner's rules (docs/virtual-keypad.md):
//   - each section starts with a keypad just powered on at node 15h; a section with PDOs and
//     no NMT frame starts it first (PDOs need operational, PK1000 11);
//   - the key state the manual describes ("key 1 pressed") is scripted: the keys of the next
//     reply are pressed before the request that the reply answers;
//   - several replies printed for one read are several reads;
//   - a boot-up printed with no request before it is a power-on;
//   - time runs in 1 ms steps, up to 3 s, until the keypad sends something.
template <class Row, std::size_t N>
transcript_result run_transcript(const Row (&rows)[N], model m) {
    transcript_result out;
    std::size_t i = 0;
    while (i < N) {
        const auto sec = section_of(rows[i].section);
        std::size_t end = i;
        while (end < N && section_of(rows[end].section) == sec) ++end;
        std::vector<const Row*> rs;
        for (std::size_t j = i; j < end; ++j)
            if (rows[j].models.contains(m)) rs.push_back(&rows[j]);
        i = end;
        if (rs.empty()) continue;

        virtual_keypad<64> k(m);
        millis t{0};
        k.power_on(t);
        bool has_nmt = false, has_pdo = false;
        for (const auto* r : rs) {
            const auto f = frame_of(r->frame);
            if (!f.is_extended() && f.raw_id() == 0) has_nmt = true;
            const auto fn = f.raw_id() & 0x780u;
            if (!f.is_extended() && (fn == 0x180 || (fn >= 0x200 && fn <= 0x500))) has_pdo = true;
        }
        const auto first = frame_of(rs.front()->frame);
        if (!(from_keypad(first) && first.raw_id() == 0x715 && first[0] == 0)) {
            if (has_pdo && !has_nmt) k.receive(frame_of("000#0115"), t);
            while (k.transmit()) {
            }
        }
        std::optional<can::frame> last_request;
        bool replied_since_request = false;
        // Frames the keypad sent that no printed reply accounts for.
        const auto extras = [&](auto& kp, std::string_view section) {
            while (const auto extra = kp.transmit()) {
                const auto key = "+" + text_of(*extra);
                if (const auto d = difference_of(m, section, key)) {
                    ++out.extra;
                    out.listed.push_back(std::string(section) + " " + key + ": " +
                                         std::string(d->note));
                } else {
                    out.mismatches.push_back(std::string(section) + ": unexpected " + key);
                }
            }
        };
        for (std::size_t j = 0; j < rs.size(); ++j) {
            const auto f = frame_of(rs[j]->frame);
            if (!from_keypad(f)) {
                // the keys the next reply reports are pressed before the request
                for (std::size_t n = j + 1; n < rs.size(); ++n) {
                    const auto g = frame_of(rs[n]->frame);
                    if (!from_keypad(g)) break;
                    if (const auto ks = keys_in(g)) k.set_keys(*ks, t);
                    break;
                }
                k.advance(t);
                extras(k, rs[j]->section);
                k.receive(f, t);
                t = t + duration_ms{1};
                last_request = f;
                replied_since_request = false;
                continue;
            }
            ++out.replies;
            if (const auto ks = keys_in(f)) {
                if (replied_since_request && last_request && (f.raw_id() & 0x780u) == 0x580) {
                    k.set_keys(*ks, t);
                } else if ((f.raw_id() & 0x780u) == 0x180) {
                    k.set_keys(*ks, t);
                }
            }
            std::optional<can::frame> got = k.transmit();
            if (!got && replied_since_request && last_request && (f.raw_id() & 0x780u) == 0x580) {
                k.receive(*last_request, t);  // one more read for one more printed reply
            }
            if (!got && (f.raw_id() & 0x780u) == 0x700 && f[0] == 0x00 &&
                !(last_request && !replied_since_request)) {
                k.power_cycle(t);  // a boot-up printed without a request: a power-on
            }
            for (int step = 0; !got && step < 3000; ++step) {
                t = t + duration_ms{1};
                k.advance(t);
                got = k.transmit();
            }
            replied_since_request = true;
            const bool ok = got && same(f, *got);
            const auto d = difference_of(m, rs[j]->section, rs[j]->frame);
            if (ok) {
                ++out.identical;
            } else if (d) {
                (d->why == because::erratum    ? out.errata
                 : d->why == because::presumed ? out.presumed
                                               : out.other_model) += 1;
                out.listed.push_back(std::string(rs[j]->section) + " " + std::string(rs[j]->frame) +
                                     ": " + std::string(d->note));
            } else {
                out.mismatches.push_back(std::string(rs[j]->section) + ": want " +
                                         std::string(rs[j]->frame) + " got " +
                                         (got ? text_of(*got) : std::string("nothing")));
            }
        }
        k.advance(t + duration_ms{5});
        extras(k, rs.back()->section);
    }
    return out;
}

void report(model m, const transcript_result& r) {
    std::ostringstream s;
    s << to_string(m) << ": " << r.identical << " of " << r.replies << " replies identical, "
      << r.errata << " errata, " << r.presumed << " presume a state the section does not set, "
      << r.other_model << " print another model's value; " << r.extra
      << " replies the manual does not print";
    MESSAGE(s.str());
    for (const auto& l : r.listed) MESSAGE("  listed: " << l);
    for (const auto& x : r.mismatches) MESSAGE("  MISMATCH " << x);
    CHECK(r.mismatches.empty());
    CHECK(r.identical + r.errata + r.presumed + r.other_model == r.replies);
}

// A keypad at node 15h, powered on at 0 and its boot-up drained.
template <std::size_t N = 16>
virtual_keypad<N> booted(model m, behaviour::keypad_options o = {}) {
    virtual_keypad<N> k(m, canopen::default_node_id, o);
    k.power_on(millis{0});
    (void)k.transmit();
    return k;
}

// Everything the keypad sends up to t (stepping 1 ms from `from`).
template <std::size_t N>
std::vector<std::string> run_until(virtual_keypad<N>& k, millis from, millis to) {
    std::vector<std::string> out;
    for (auto t = from; !behaviour::before(to, t); t = t + duration_ms{1}) {
        k.advance(t);
        while (const auto f = k.transmit())
            out.push_back(std::to_string(t.value) + " " + text_of(*f));
    }
    return out;
}

// The one reply to a request sent at t (1 ms later).
template <std::size_t N>
std::string ask(virtual_keypad<N>& k, std::string_view request, millis t = {10}) {
    k.receive(frame_of(request), t);
    k.advance(t + duration_ms{1});
    const auto f = k.transmit();
    return f ? text_of(*f) : std::string("nothing");
}

}  // namespace

// --- the manuals' transcripts -------------------------------------------------------------------

#if __has_include("si_rows.hpp")
#include "si_rows.hpp"
#define POWERKEY_TEST_SI_ROWS 1
#endif

TEST_CASE("It answers like the manuals") {
    SUBCASE("PK1000") { report(model::pk1000, run_transcript(pk1000_rows::rows, model::pk1000)); }
    SUBCASE("PKP-2200") { report(model::pkp2200, run_transcript(pkp_rows::rows, model::pkp2200)); }
    SUBCASE("PKP-2400") { report(model::pkp2400, run_transcript(pkp_rows::rows, model::pkp2400)); }
    SUBCASE("PKP-2600") { report(model::pkp2600, run_transcript(pkp_rows::rows, model::pkp2600)); }
#ifdef POWERKEY_TEST_SI_ROWS
    SUBCASE("PKP-2600-SI") {
        report(model::pkp2600si, run_transcript(si_rows::rows, model::pkp2600si));
    }
    SUBCASE("PKP-3500-MT") {
        report(model::pkp3500mt, run_transcript(si_rows::rows, model::pkp3500mt));
    }
#endif
}

// --- one test per behaviour ----------------------------------------------------------------------

using strings = std::vector<std::string>;

TEST_CASE("boot-up: into pre-operational, or operational when 2012h says so; none when 2011h = 0") {
    virtual_keypad<> k(model::pk1000);
    CHECK(k.state() == run_state::off);
    k.power_on(millis{0});
    CHECK(k.state() == run_state::pre_operational);
    CHECK(text_of(*k.transmit()) == "715#00");
    CHECK_FALSE(k.transmit());
    CHECK(ask(k, "615#2F12200001000000") == "595#6012200000000000");        // active on start-up
    CHECK(ask(k, "615#2F11200000000000", {20}) == "595#6011200000000000");  // no boot-up
    k.power_cycle(millis{100});
    CHECK(k.state() == run_state::operational);
    CHECK_FALSE(k.transmit());
    // PKP: commands 10h and 13h
    auto p = booted(model::pkp2400);
    CHECK(ask(p, "615#2300650110010000") == "595#6000650100000000");
    CHECK(ask(p, "615#2300650113000000", {20}) == "595#6000650100000000");
    p.power_cycle(millis{100});
    CHECK(p.state() == run_state::operational);
    CHECK_FALSE(p.transmit());
}

TEST_CASE("NMT: start, stop, legacy stop, pre-operational, reset node, reset communication") {
    for (const auto m : {model::pk1000, model::pkp2200, model::pkp2400, model::pkp2600}) {
        CAPTURE(m);
        auto k = booted(m);
        k.receive(frame_of("000#0116"), millis{1});  // another node
        CHECK(k.state() == run_state::pre_operational);
        k.receive(frame_of("000#0115"), millis{2});
        CHECK(k.state() == run_state::operational);
        k.receive(frame_of("000#0200"), millis{3});  // all nodes
        CHECK(k.state() == run_state::stopped);
        CHECK(ask(k, "615#4017100000000000", {4}) == "nothing");  // no SDO when stopped
        k.receive(frame_of("000#8015"), millis{10});
        CHECK(k.state() == run_state::pre_operational);
        k.receive(frame_of("000#0115"), millis{11});
        k.receive(frame_of("000#0015"), millis{12});  // 00h: stop, old software (section 7)
        CHECK(k.state() == run_state::stopped);
        // reset node: boots again, keeping the stored settings (the heartbeat time here)
        CHECK(ask(k, "000#8015", {20}) == "nothing");
        CHECK(ask(k, "615#2B17100064000000", {30}) == "595#6017100000000000");
        k.receive(frame_of("000#8115"), millis{40});
        CHECK(text_of(*k.transmit()) == "715#00");
        CHECK(k.state() == run_state::pre_operational);
        CHECK(run_until(k, millis{41}, millis{140}) == strings{"140 715#7F"});
        k.receive(frame_of("000#8215"), millis{150});  // reset communication
        CHECK(text_of(*k.transmit()) == "715#00");
    }
}

TEST_CASE("heartbeat producer: every heartbeat_time ms, the NMT state; 0 stops it") {
    auto k = booted(model::pk1000);
    CHECK(ask(k, "615#2B17100064000000", {10}) == "595#6017100000000000");
    CHECK(run_until(k, millis{12}, millis{310}) ==
          strings{"110 715#7F", "210 715#7F", "310 715#7F"});
    k.receive(frame_of("000#0115"), millis{350});
    CHECK(run_until(k, millis{351}, millis{410}) == strings{"410 715#05"});
    k.receive(frame_of("000#0215"), millis{420});
    CHECK(run_until(k, millis{421}, millis{510}) == strings{"510 715#04"});
    k.receive(frame_of("000#8015"), millis{520});
    CHECK(ask(k, "615#2B17100000000000", {530}) == "595#6017100000000000");
    CHECK(run_until(k, millis{532}, millis{2000}).empty());
    // a caller that wakes late gets one heartbeat, then the period again from then
    CHECK(ask(k, "615#2B1710000A000000", {2000}) == "595#6017100000000000");
    k.advance(millis{60'000});
    CHECK(text_of(*k.transmit()) == "715#7F");
    CHECK_FALSE(k.transmit());
    CHECK(run_until(k, millis{60'001}, millis{60'010}) == strings{"60010 715#7F"});
}

TEST_CASE("next_due: the time advance() next has work, nothing before it") {
    auto k = booted(model::pk1000);
    CHECK_FALSE(k.next_due());  // pre-operational, no heartbeat, nothing pending
    k.receive(frame_of("615#2B17100064000000"), millis{10});  // heartbeat 100 ms
    REQUIRE(k.next_due());
    CHECK(*k.next_due() == millis{11});  // the SDO reply (sdo_response_ms 1)
    k.advance(millis{11});
    CHECK(text_of(*k.transmit()) == "595#6017100000000000");
    // Each due time: advance() before it sends nothing, at it sends.
    for (int i = 0; i < 3; ++i) {
        const auto due = *k.next_due();
        k.advance(millis{due.value - 1});
        CHECK_FALSE(k.transmit());
        k.advance(due);
        CHECK(text_of(*k.transmit()) == "715#7F");
    }
    k.power_off();
    CHECK_FALSE(k.next_due());
}

TEST_CASE("heartbeat consumer: on a lost heartbeat LEDs and backlight off, pre-operational") {
    auto k = booted(model::pk1000);
    CHECK(ask(k, "615#2316100164000100") == "595#6016100100000000");  // 100 ms from node 1
    k.receive(frame_of("000#0115"), millis{20});
    k.receive(frame_of("215#0100000001000000"), millis{21});
    k.receive(frame_of("515#2003000000000000"), millis{22});
    CHECK(k.led_on().red.contains(1));
    CHECK(k.backlight().level == powerkey::level::make(0x20).value());
    // not monitored before the first heartbeat
    k.advance(millis{500});
    CHECK(k.state() == run_state::operational);
    k.receive(frame_of("701#05"), millis{600});
    k.receive(frame_of("701#05"), millis{690});
    k.advance(millis{789});
    CHECK(k.state() == run_state::operational);
    k.advance(millis{790});
    CHECK(k.state() == run_state::pre_operational);
    CHECK(k.led_on() == leds{});
    CHECK(k.backlight().level == powerkey::level::make(0).value());
    // the producer comes back: the keypad stays pre-operational until a new NMT start (NOTE 2)
    k.receive(frame_of("701#05"), millis{800});
    CHECK(k.state() == run_state::pre_operational);
    k.receive(frame_of("000#0115"), millis{810});
    CHECK(k.state() == run_state::operational);
}

TEST_CASE("heartbeat consumer time below the producer's: the keypad cannot stay operational") {
    auto k = booted(model::pk1000);                                   // NOTE 3 of PK1000 28
    CHECK(ask(k, "615#2316100132000100") == "595#6016100100000000");  // 50 ms from node 1
    for (std::uint32_t t = 100; t <= 1000; t += 100) {  // the producer beats every 100 ms
        k.receive(frame_of("701#05"), millis{t});
        if (t == 300) k.receive(frame_of("000#0115"), millis{t});
    }
    k.advance(millis{1000});
    CHECK(k.state() == run_state::pre_operational);
}

TEST_CASE("key-state TPDO: on change when operational, with the 100 ms tick timer") {
    auto k = booted(model::pk1000);
    CHECK(k.press(1, millis{10}));
    CHECK_FALSE(k.transmit());  // PDOs only when operational (section 11)
    k.receive(frame_of("000#0115"), millis{20});
    CHECK(k.press(4, millis{250}));
    CHECK(text_of(*k.transmit()) == "195#0900000002");  // keys 1 and 4, tick 2
    CHECK(k.release(1, millis{1000}));
    CHECK(text_of(*k.transmit()) == "195#080000000A");
    CHECK_FALSE(k.press(11, millis{1001}));  // the PK1000 has 10 keys
    CHECK(k.press(10, millis{1100}));
    CHECK(text_of(*k.transmit()) == "195#080200000B");
    CHECK(k.tick(millis{25'700}) == 1);  // wraps after 25.6 s
}

TEST_CASE("event timer (1800h/5) and PKP command 12h: the key state periodically") {
    auto k = booted(model::pk1000);
    CHECK(ask(k, "615#2B00180532000000") == "595#6000180500000000");  // 50 ms
    k.receive(frame_of("000#0115"), millis{100});
    CHECK(run_until(k, millis{100}, millis{200}) ==
          strings{"150 195#0000000001", "200 195#0000000002"});
    k.press(2, millis{220});  // an event restarts the timer
    CHECK(run_until(k, millis{220}, millis{270}) ==
          strings{"220 195#0200000002", "270 195#0200000002"});
    auto p = booted(model::pkp2400);
    CHECK(ask(p, "615#2300650112013200") == "595#6000650100000000");  // on, 50 x 10 ms
    CHECK(ask(p, "615#4000180500000000", {20}) == "595#4B001805F4010000");
    p.receive(frame_of("000#0115"), millis{100});
    CHECK(run_until(p, millis{100}, millis{1100}) ==
          strings{"600 195#0000000006", "1100 195#000000000B"});
}

TEST_CASE("SYNC: RPDOs of types 00h..F0h wait for the next SYNC, the TPDO every n-th SYNC") {
    auto k = booted(model::pk1000);
    CHECK(ask(k, "615#2F00140201000000") == "595#6000140200000000");
    CHECK(ask(k, "615#2F00180202000000", {20}) == "595#6000180200000000");  // every 2nd SYNC
    k.receive(frame_of("000#0115"), millis{30});
    k.receive(frame_of("215#0000000001000000"), millis{40});  // green 1, buffered
    CHECK(k.led_on() == leds{});
    k.receive(frame_of("315#0100000000000000"), millis{41});  // blink: type FEh, at once
    CHECK(k.led_blink().red.contains(1));
    k.press(3, millis{45});
    CHECK_FALSE(k.transmit());  // synchronous: no event
    k.receive(frame_of("080#"), millis{50});
    CHECK(k.led_on().green.contains(1));
    CHECK_FALSE(k.transmit());
    k.receive(frame_of("080#"), millis{60});
    CHECK(text_of(*k.transmit()) == "195#0400000000");
    k.receive(frame_of("080#"), millis{70});
    CHECK_FALSE(k.transmit());
    // The last synchronous type, F0h: buffered too, and the TPDO every 240th SYNC.
    auto f0 = booted(model::pk1000);
    CHECK(ask(f0, "615#2F011402F0000000") == "595#6001140200000000");
    CHECK(ask(f0, "615#2F001802F0000000", {20}) == "595#6000180200000000");
    f0.receive(frame_of("000#0115"), millis{30});
    f0.receive(frame_of("315#0100000000000000"), millis{40});
    CHECK(f0.led_blink() == leds{});
    for (std::uint32_t n = 1; n < 240; ++n) {
        f0.receive(frame_of("080#"), millis{40 + n});
        CHECK_FALSE(f0.transmit());
    }
    CHECK(f0.led_blink().red.contains(1));
    f0.receive(frame_of("080#"), millis{300});
    CHECK(text_of(*f0.transmit()).starts_with("195#"));
}

TEST_CASE("LEDs, brightness and backlight from PDOs, SDOs and the PKP command module") {
    auto k = booted(model::pk1000);
    CHECK(k.brightness() == powerkey::level::make(0x3F).value());
    CHECK(k.backlight() == behaviour::backlight_state{0, backlight_colour::amber});
    k.receive(frame_of("215#0500000000200000"), millis{1});
    CHECK(k.led_on() == leds{});  // pre-operational: PDOs ignored
    k.receive(frame_of("000#0115"), millis{2});
    k.receive(frame_of("215#0500000000200000"), millis{3});
    CHECK(k.led_on() == leds{{1, 3}, {14}, {}});
    k.receive(frame_of("415#0800000000000000"), millis{4});
    CHECK(k.brightness() == powerkey::level::make(8).value());
    k.receive(frame_of("515#2003000000000000"), millis{5});
    CHECK(k.backlight() == behaviour::backlight_state{0x20, backlight_colour::blue});
    k.receive(frame_of("515#1000000000000000"), millis{6});  // colour 0: keep
    CHECK(k.backlight() == behaviour::backlight_state{0x10, backlight_colour::blue});
    CHECK(ask(k, "615#2302200200008000", {10}) == "595#6002200200000000");
    CHECK(k.led_blink().green.contains(24));
    CHECK(ask(k, "615#4001200100000000", {20}) == "595#4301200105000000");
    CHECK(ask(k, "615#2F03200305000000", {30}) == "595#6003200300000000");
    CHECK(k.backlight().colour == backlight_colour::cyan);

    auto p = booted(model::pkp2600);
    CHECK(ask(p, "615#23006501010C0900") == "595#6000650100000000");  // 12 blue alternate
    CHECK(p.led_on().blue.contains(12));
    CHECK(p.led_blink().blue.contains(12));
    CHECK(ask(p, "615#2300650101020500", {20}) == "595#6000650100000000");  // 2 green blink
    CHECK(p.led_blink().green.contains(2));
    CHECK_FALSE(p.led_on().green.contains(2));
    CHECK(ask(p, "615#2300650102100000", {30}) == "595#6000650100000000");
    CHECK(p.brightness() == powerkey::level::make(0x10).value());
    CHECK(ask(p, "615#23006501032F0000", {40}) == "595#6000650100000000");
    CHECK(ask(p, "615#2300650104010000", {50}) == "595#6000650100000000");
    CHECK(p.backlight() == behaviour::backlight_state{0x2F, backlight_colour::red});
    CHECK(ask(p, "615#4001620200000000", {60}) == "595#4F0162022F000000");
    p.receive(frame_of("000#0115"), millis{70});
    p.receive(frame_of("215#0000000001000000"), millis{71});  // blue 9 (stride 12)
    CHECK(p.led_on() == leds{{}, {}, {9}});
}

TEST_CASE("SDO aborts with the CiA 301 codes") {
    auto k = booted(model::pk1000);
    CHECK(ask(k, "615#4004200000000000") == "595#8004200000000206");         // no object
    CHECK(ask(k, "615#4001200300000000", {20}) == "595#8001200311000906");   // no sub-index
    CHECK(ask(k, "615#2B00200101000000", {30}) == "595#8000200102000106");   // read only
    CHECK(ask(k, "615#2F03200140000000", {40}) == "595#8003200131000906");   // too high
    CHECK(ask(k, "615#2B17100005000000", {50}) == "595#8017100032000906");   // too low
    CHECK(ask(k, "615#2B03200109000000", {60}) == "595#8003200110000706");   // length
    CHECK(ask(k, "615#4001100000000000", {70}) == "595#8001100000000206");   // 1001h (31)
    CHECK(ask(k, "615#2311100161626364", {80}) == "595#8011100120000008");   // not "load"
    CHECK(ask(k, "615#2301200100000010", {90}) == "595#8001200130000906");   // LED 29
    CHECK(ask(k, "615#6000000000000000", {100}) == "595#8000000001000405");  // no upload
    CHECK(ask(k, "615#4008100000000000", {110}) == "595#410810000B000000");
    CHECK(ask(k, "615#7000000000000000", {120}) == "595#8008100000000305");  // toggle
    // PK1000 28: a consumer period below 10 ms is too low, a producer that is no node id invalid
    CHECK(ask(k, "615#2316100109000100", {130}) == "595#8016100132000906");
    CHECK(ask(k, "615#2316100164000000", {140}) == "595#8016100130000906");
    CHECK(ask(k, "615#231610010A000100", {150}) == "595#6016100100000000");  // 10 ms: taken
    CHECK(ask(k, "615#2F03200300000000", {170}) == "595#8003200332000906");  // colour 0: too low
    auto p = booted(model::pkp2400);
    CHECK(ask(p, "615#4000650100000000") == "595#8000650101000106");        // write only
    CHECK(ask(p, "615#2300650101090100", {20}) == "595#8000650130000906");  // key 9 of 8
    CHECK(ask(p, "615#2BFF200101000000", {30}) == "595#80FF200100000206");  // no J1939
    CHECK(ask(p, "615#2B00180532000000", {40}) == "595#8000180502000106");  // E-PKP-10
}

TEST_CASE("one SDO at a time: a request while the keypad is answering is dropped (option)") {
    auto k = booted(model::pk1000);
    k.receive(frame_of("615#4010200000000000"), millis{10});
    k.receive(frame_of("615#4011200000000000"), millis{10});  // still answering: dropped
    CHECK(run_until(k, millis{10}, millis{50}) == strings{"11 595#4F10200004000000"});
    behaviour::keypad_options o;
    o.drop_sdo_while_busy = false;
    auto q = booted(model::pk1000, o);
    q.receive(frame_of("615#4010200000000000"), millis{10});
    q.receive(frame_of("615#4011200000000000"), millis{10});
    CHECK(run_until(q, millis{10}, millis{50}) ==
          strings{"10 595#4F10200004000000", "11 595#4F11200001000000"});  // both, in order
}

TEST_CASE("node-id change: PK1000 answers from the new id, PKP from the old, then boots") {
    auto k = booted(model::pk1000);
    CHECK(ask(k, "615#2F1320003A000000") == "5BA#6013200000000000");
    CHECK(k.node() == canopen::node_id::make(0x3A).value());
    CHECK(ask(k, "615#4013200000000000", {20}) == "nothing");
    CHECK(ask(k, "63A#4013200000000000", {30}) == "5BA#4F1320003A000000");
    k.power_cycle(millis{40});
    CHECK(text_of(*k.transmit()) == "73A#00");

    auto p = booted(model::pkp2200);
    p.receive(frame_of("000#0115"), millis{5});
    p.receive(frame_of("615#2300650170180000"), millis{10});
    CHECK(run_until(p, millis{10}, millis{20}) == strings{"11 595#6000650100000000", "11 718#00"});
    CHECK(p.node() == canopen::node_id::make(0x18).value());
    CHECK(p.state() == run_state::pre_operational);
    CHECK(ask(p, "618#4017100000000000", {30}) == "598#4B17100000000000");
}

TEST_CASE("baud rate: a stored setting, effective after a reset") {
    auto k = booted(model::pk1000);
    CHECK(ask(k, "615#2F10200002000000") == "595#6010200000000000");
    CHECK(k.baud() == baud_rate::kbit_125);
    CHECK(ask(k, "615#4010200000000000", {20}) == "595#4F10200002000000");
    k.receive(frame_of("000#8115"), millis{30});
    CHECK(k.baud() == baud_rate::kbit_500);
    CHECK(text_of(*k.transmit()) == "715#00");
    CHECK(ask(k, "615#2F10200005000000", {40}) == "595#6010200000000000");  // reserved
    k.power_cycle(millis{50});
    CHECK(k.baud() == baud_rate::kbit_125);  // "force to 125k" (section 20)
    auto p = booted(model::pkp2400);
    CHECK(ask(p, "615#2300650111010000") == "595#6000650100000000");  // 250k
    p.power_cycle(millis{20});
    CHECK(p.baud() == baud_rate::kbit_250);
}

TEST_CASE("J1939: 20FFh/1 = 1 switches after the reply; 18EF2100h switches back") {
    auto k = booted(model::pk1000);
    CHECK(ask(k, "615#2BFF200101000000") == "595#60FF200100000000");
    CHECK(k.state() == run_state::j1939);
    CHECK(ask(k, "615#4010200000000000", {20}) == "nothing");
    k.power_cycle(millis{30});  // a stored setting
    CHECK(k.state() == run_state::j1939);
    CHECK_FALSE(k.transmit());
    k.receive(frame_of("18EF2100#041B8000FFFFFFFF"), millis{40});
    CHECK(k.state() == run_state::pre_operational);
    CHECK(text_of(*k.transmit()) == "715#00");
    CHECK(ask(k, "615#40FF200100000000", {50}) == "595#4BFF200100000000");
}

TEST_CASE("restore defaults: 1011h/1 \"load\", effective after the reset") {
    auto k = booted(model::pk1000);
    CHECK(ask(k, "615#2F03200513000000") == "595#6003200500000000");
    CHECK(ask(k, "615#2B17100064000000", {20}) == "595#6017100000000000");
    CHECK(ask(k, "615#2F1320003A000000", {30}) == "5BA#6013200000000000");
    CHECK(ask(k, "63A#231110016C6F6164", {40}) == "5BA#6011100100000000");
    CHECK(ask(k, "63A#4003200500000000", {50}) == "5BA#4F03200513000000");  // not yet
    k.receive(frame_of("000#813A"), millis{60});
    CHECK(text_of(*k.transmit()) == "715#00");
    CHECK(ask(k, "615#4003200500000000", {70}) == "595#4F0320053F000000");
    CHECK(ask(k, "615#4017100000000000", {80}) == "595#4B17100000000000");
}

TEST_CASE("faults: power cycle, silence, lost frames") {
    auto k = booted(model::pk1000);
    CHECK(ask(k, "615#2B17100064000000") == "595#6017100000000000");
    k.receive(frame_of("000#0115"), millis{20});
    k.receive(frame_of("215#0100000000000000"), millis{21});
    k.power_cycle(millis{50});  // reboots mid-session: LEDs off, pre-operational
    CHECK(k.led_on() == leds{});
    CHECK(k.state() == run_state::pre_operational);
    CHECK(run_until(k, millis{50}, millis{150}) == strings{"50 715#00", "150 715#7F"});
    k.silence(millis{151}, duration_ms{200});
    CHECK(run_until(k, millis{151}, millis{450}) == strings{"450 715#7F"});
    k.drop_transmitted(1);
    CHECK(run_until(k, millis{451}, millis{650}) == strings{"650 715#7F"});
    k.drop_received(1);
    CHECK(ask(k, "615#4010200000000000", {660}) == "nothing");
    CHECK(ask(k, "615#4010200000000000", {670}) == "595#4F10200004000000");
    k.power_off();
    CHECK(k.state() == run_state::off);
    CHECK(run_until(k, millis{700}, millis{1000}).empty());
}

TEST_CASE("segmented uploads of the strings, per model") {
    // after the last segment, a segment request is no transfer's: invalid command specifier
    const auto read_string = [](model m, std::string_view request) {
        auto k = booted(m);
        strings out{ask(k, request)};
        for (int i = 0; i < 4; ++i)
            out.push_back(ask(k, i % 2 == 0 ? "615#6000000000000000" : "615#7000000000000000",
                              millis{static_cast<std::uint32_t>(20 + 10 * i)}));
        return out;
    };
    CHECK(read_string(model::pk1000, "615#4008100000000000") ==
          strings{"595#410810000B000000", "595#00426C696E6B4D61", "595#1772696E65000000",
                  "595#8000000001000405", "595#8000000001000405"});
    CHECK(read_string(model::pkp2200, "615#400B100000000000") ==
          strings{"595#410B100007000000", "595#00504B5532323030", "595#1D00000000000000",
                  "595#8000000001000405", "595#8000000001000405"});
}

TEST_CASE("every model: boots, starts, sends keys, takes LEDs, answers every readable object") {
    for (const auto m : enum_values<model>()) {
        CAPTURE(m);
        const auto mi = info(m).value();
        auto k = booted(m);
        k.receive(frame_of("000#0115"), millis{1});
        CHECK(k.state() == run_state::operational);
        k.press(1, millis{2});
        const auto keys = k.transmit();
        REQUIRE(keys);
        CHECK(text_of(*keys) == "195#0100000000");
        // the lowest LED the model has, red, by the LED-on PDO
        const unsigned first = static_cast<unsigned>(std::countr_zero(mi.led_mask)) + 1;
        leds want;
        want.red.insert(first);
        const auto pdo = encode(canopen::default_node_id, m, message{led_on{want}});
        REQUIRE(pdo);
        k.receive(*pdo, millis{3});
        CHECK(k.led_on().red.contains(first));
        // every readable object: a reply the library's decoder reads as this object's
        millis t{10};
        for (const auto& r : rows_of(mi.dictionary)) {
            if (!r.readable() || info(r.id).kind == value_kind::none) continue;
            CAPTURE(r.id);
            can::payload req{0x40, static_cast<std::uint8_t>(r.address.index & 0xFF),
                             static_cast<std::uint8_t>(r.address.index >> 8), r.address.subindex};
            k.receive(
                can::frame(can::standard_id::make(0x615).value(), can::dlc::make(8).value(), req),
                t);
            t = t + duration_ms{2};
            k.advance(t);
            const auto reply = k.transmit();
            REQUIRE(reply);
            const auto d = decode(*reply, canopen::default_node_id, m);
            CHECK_MESSAGE(d.has_value(), text_of(*reply));
            CHECK((*reply)[0] != 0x80);  // no abort: every string has its bytes
            if (info(r.id).kind == value_kind::string) CHECK(info(m)->string_of(r.id));
            // a segmented upload to its end, each segment read by the decoder
            bool toggle = false, more = (*reply)[0] == 0x40 || (*reply)[0] == 0x41;
            while (more) {
                const std::string seg =
                    ask(k, toggle ? "615#7000000000000000" : "615#6000000000000000", t);
                t = t + duration_ms{2};
                CHECK(decode(frame_of(seg), canopen::default_node_id, m).has_value());
                more = (frame_of(seg)[0] & 0x01) == 0;
                toggle = !toggle;
            }
        }
        CHECK(ask(k, "615#40FF5F0000000000", t) == "595#80FF5F0000000206");
    }
}

TEST_CASE("every model: writing back what a read gives is acknowledged") {
    for (const auto m : enum_values<model>()) {
        CAPTURE(m);
        const auto mi = info(m).value();
        auto k = booted(m);
        millis t{10};
        for (const auto& r : rows_of(mi.dictionary)) {
            const auto kind = info(r.id).kind;
            if (!r.readable() || !r.writable() || kind == value_kind::restore) continue;
            CAPTURE(r.id);
            can::payload req{0x40, static_cast<std::uint8_t>(r.address.index & 0xFF),
                             static_cast<std::uint8_t>(r.address.index >> 8), r.address.subindex};
            k.receive(
                can::frame(can::standard_id::make(0x615).value(), can::dlc::make(8).value(), req),
                t);
            k.advance(t + duration_ms{1});
            const auto reply = k.transmit();
            REQUIRE(reply);
            REQUIRE(((*reply)[0] & 0xF3) == 0x43);  // expedited, size indicated
            const unsigned n = 4u - (((*reply)[0] >> 2) & 3u);
            can::payload w = reply->bytes();
            w[0] = static_cast<std::uint8_t>(0x23 | ((4u - n) << 2));
            const auto write =
                can::frame(can::standard_id::make(0x615).value(), can::dlc::make(8).value(), w);
            CHECK_MESSAGE(decode(write, canopen::default_node_id, m).has_value(), text_of(write));
            k.receive(write, t + duration_ms{2});
            k.advance(t + duration_ms{3});
            const auto ack = k.transmit();
            REQUIRE(ack);
            CHECK_MESSAGE((*ack)[0] == 0x60, text_of(*ack));
            t = t + duration_ms{10};
        }
        CHECK(k.state() == run_state::pre_operational);
        CHECK(k.node() == canopen::default_node_id);
    }
}

namespace {
// One session in a constant expression: boot, start, a key, an SDO read.
constexpr bool scenario() {
    virtual_keypad<8> k(model::pkp2400);
    k.power_on(millis{0});
    if (k.transmit() != frame_of("715#00")) return false;
    k.receive(frame_of("000#0115"), millis{1});
    k.press(3, millis{150});
    if (k.transmit() != frame_of("195#0400000001")) return false;
    k.receive(frame_of("615#4000600000000000"), millis{200});
    k.advance(millis{201});
    return k.transmit() == frame_of("595#4300600004000000") && !k.transmit();
}
static_assert(scenario());
}  // namespace

TEST_CASE("a whole session is a constant expression") { CHECK(scenario()); }

namespace {
// The frames a powered keypad sends within 50 ms of receiving `in`.
template <std::size_t N>
std::vector<std::string> answer(virtual_keypad<N>& k, std::string_view in, std::uint32_t& now) {
    k.receive(frame_of(in), millis{now});
    now += 50;
    k.advance(millis{now});
    return powerkey_tests::drain(k);
}
}  // namespace

TEST_CASE("SDO command specifiers it does not serve, and the host's abort") {
    virtual_keypad<> k(model::pk1000);
    std::uint32_t now = 0;
    k.power_on(millis{now});
    while (k.transmit()) {
    }
    using v = std::vector<std::string>;
    // ccs 5 (block upload, CiA 301 7.2.4.3.13): abort 05040001h, command specifier not valid.
    CHECK(answer(k, "615#A008100000000000", now) == v{"595#8008100001000405"});
    // A segmented download (21h) to the writable 2013h: abort 06010000h, unsupported access
    // (every object of the keypads fits an expedited transfer).
    CHECK(answer(k, "615#2113200004000000", now) == v{"595#8013200000000106"});
    // The device name (PK1000 32): 41h, 11 bytes; the host aborts: nothing answers the abort,
    // and the next segment request finds no transfer.
    CHECK(answer(k, "615#4008100000000000", now) == v{"595#410810000B000000"});
    CHECK(answer(k, "615#8008100000000405", now).empty());
}

TEST_CASE("the red/green blink of command 01h (PKP 13 a 0Ah, PKP 12)") {
    virtual_keypad<> k(model::pkp2400);
    std::uint32_t now = 0;
    k.power_on(millis{now});
    while (k.transmit()) {
    }
    // PKP 12: "Only LED #4 blinks red and green in alternate mode" is green on, red and green
    // blinking; command 01h state 0Ah sets LED 8 the same way.
    CHECK(answer(k, "615#2300650101080A00", now) ==
          std::vector<std::string>{"595#6000650100000000"});
    CHECK(k.led_on() == leds{{}, {8}, {}});
    CHECK(k.led_blink() == leds{{8}, {8}, {}});
}

// PKP2600SI manual 15: the backlight PDO's colour 00h is "default" (the colour of 2003h sub 04h),
// not the PK1000's and PKP-3500-MT's "keep the stored colour"
// (model_info::backlight_zero_is_default).
TEST_CASE("PKP-2600-SI: backlight PDO colour 00h is the default colour") {
    virtual_keypad<> k(model::pkp2600si);
    k.power_on(millis{0});
    k.receive(frame_of("000#0115"), millis{1});
    k.receive(frame_of("515#2001000000000000"), millis{2});  // 50 %, red
    CHECK(k.backlight().colour == backlight_colour::red);
    k.receive(frame_of("515#2000000000000000"), millis{3});  // 50 %, 00h: default
    CHECK(k.backlight().colour == backlight_colour::amber);  // 2003h sub 04h, factory 08h
}

namespace {
constexpr powerkey_tests::name_row run_state_rows[] = {{"", 0, "off"},
                                                       {"", 1, "pre_operational"},
                                                       {"", 2, "operational"},
                                                       {"", 3, "stopped"},
                                                       {"", 4, "j1939"}};
static_assert(powerkey_tests::name_table_is<run_state>(run_state_rows, 5));
}  // namespace

TEST_CASE("the keypad's run states have one name each") {
    CHECK(powerkey_tests::name_table_is<run_state>(run_state_rows, 5));
}

// The timers woken exactly at, and exactly one period after, their deadline: one frame, and the
// next deadline one period after the wake, not at it (PK1000 29 heartbeat, 46 b event timer).
TEST_CASE("timers woken at their deadline and exactly one period late") {
    SUBCASE("the heartbeat producer") {
        auto k = booted(model::pk1000);
        CHECK(ask(k, "615#2B17100064000000", {10}) == "595#6017100000000000");  // 100 ms
        REQUIRE(k.next_due());
        CHECK(*k.next_due() == millis{110});
        k.advance(millis{109});
        CHECK_FALSE(k.transmit());
        k.advance(millis{210});  // due at 110: one heartbeat, the next at 310
        CHECK(text_of(*k.transmit()) == "715#7F");
        CHECK_FALSE(k.transmit());
        REQUIRE(k.next_due());
        CHECK(*k.next_due() == millis{310});
        k.advance(millis{210});
        CHECK_FALSE(k.transmit());
    }
    SUBCASE("the event timer of the key state") {
        auto k = booted(model::pk1000);
        CHECK(ask(k, "615#2B00180532000000") == "595#6000180500000000");  // 50 ms
        k.receive(frame_of("000#0115"), millis{100});
        REQUIRE(k.next_due());
        CHECK(*k.next_due() == millis{150});
        k.advance(millis{149});
        CHECK_FALSE(k.transmit());
        k.advance(millis{200});  // due at 150: one key state, the next at 250
        REQUIRE(k.transmit());
        CHECK_FALSE(k.transmit());
        REQUIRE(k.next_due());
        CHECK(*k.next_due() == millis{250});
    }
    SUBCASE("the consumer heartbeat's deadline: operational until it, pre-operational at it") {
        auto k = booted(model::pk1000);
        CHECK(ask(k, "615#2316100164000100") == "595#6016100100000000");  // 100 ms from node 1
        k.receive(frame_of("000#0115"), millis{20});
        k.receive(frame_of("701#00"), millis{30});  // a boot-up (00h) starts no monitoring
        k.advance(millis{500});
        CHECK(k.state() == run_state::operational);
        k.receive(frame_of("701#05"), millis{600});
        k.advance(millis{699});
        CHECK(k.state() == run_state::operational);
        k.advance(millis{700});
        CHECK(k.state() == run_state::pre_operational);
    }
}

// The millisecond clock wraps after 2^32 ms (behaviour/clock.hpp): a time up to 2^31 - 1 ms ahead
// is after, 2^31 ms or more is taken as before; a deadline is reached at its own millisecond.
TEST_CASE("the clock across its wrap: before and reached at their bounds") {
    using behaviour::before;
    using behaviour::reached;
    constexpr millis zero{0}, near_end{0xFFFF'FFFFu};
    static_assert(!before(zero, zero) && reached(zero, zero));
    static_assert(before(zero, millis{1}) && !before(millis{1}, zero));
    static_assert(before(zero, millis{0x7FFF'FFFFu}) && !before(zero, millis{0x8000'0000u}));
    static_assert(before(zero, millis{0x4000'0000u}));
    static_assert(before(near_end, zero) && !before(zero, near_end));  // across the wrap
    static_assert(reached(near_end, zero) && !reached(zero, near_end));
    static_assert(!reached(millis{1}, zero) && reached(millis{1}, millis{1}));
    CHECK(before(zero, millis{0x7FFF'FFFFu}));
    CHECK_FALSE(before(zero, millis{0x8000'0000u}));
}

namespace {
// What a keypad of model M sends for each frame of the PK1000 and PKP manuals' rows (requests,
// replies and PDOs alike: it answers or ignores each), for every object of its dictionary a read
// and a write of the value read plus one, and an address no dictionary has.
template <class Keypad>
std::vector<std::string> answers(model m) {
    virtual_keypad<64, Keypad> k(m);
    std::vector<std::string> out;
    millis t{0};
    const auto take = [&](const can::frame& f) {
        k.receive(f, t);
        t = t + duration_ms{3};
        k.advance(t);
        while (const auto r = k.transmit()) out.emplace_back(text_of(*r));
    };
    k.power_on(t);
    take(frame_of("000#0100"));
    for (const auto& r : pk1000_rows::rows) take(frame_of(r.frame));
    for (const auto& r : pkp_rows::rows) take(frame_of(r.frame));
    for (const auto& r : rows_of(info(m)->dictionary)) {
        const auto a = r.address;
        const auto i = static_cast<std::uint8_t>(a.index & 0xFF);
        const auto h = static_cast<std::uint8_t>(a.index >> 8);
        const std::size_t before = out.size();
        take(can::frame(can::standard_id::make(0x615).value(), can::dlc::make(8).value(),
                        can::payload{0x40, i, h, a.subindex}));
        const std::uint8_t v = out.size() > before
                                   ? static_cast<std::uint8_t>(frame_of(out.back())[4] + 1)
                                   : std::uint8_t{1};
        take(can::frame(can::standard_id::make(0x615).value(), can::dlc::make(8).value(),
                        can::payload{0x2F, i, h, a.subindex, v}));
    }
    take(frame_of("615#40FF5F0000000000"));
    return out;
}
// The same for a keypad of model M in J1939 from power-on (keypad_options::start_in_j1939): the
// acknowledgements, the heartbeat and the periodic key state on, every frame of the J1939 rows (the
// manuals' and the other models', the LI forms among them) for keypad 21h, each key pressed and
// released, the timers run.
template <class Keypad>
std::vector<std::string> j1939_answers(model m) {
    behaviour::keypad_options o;
    o.start_in_j1939 = true;
    virtual_keypad<64, Keypad> k(m, canopen::default_node_id, o);
    std::vector<std::string> out;
    millis t{0};
    const auto drain_to = [&](millis until) {
        k.advance(until);
        while (const auto r = k.transmit()) out.emplace_back(text_of(*r));
    };
    const auto take = [&](std::string_view f) {
        k.receive(frame_of(f), t);
        t = t + duration_ms{3};
        drain_to(t);
    };
    k.power_on(t);
    take("18EF2100#041B7301FFFFFFFF");
    take("18EF2100#041B75010AFFFFFF");
    for (const auto& rows : {std::span<const j1939_rows::row>(j1939_rows::pkp1600si_rows),
                             std::span<const j1939_rows::row>(j1939_rows::pkp2600si_rows),
                             std::span<const j1939_rows::row>(j1939_rows::other_rows)})
        for (const auto& r : rows)
            // every frame for keypad 21h but 70h, 80h and address claims of 21h, which would
            // move it, switch it or silence it
            if (r.keypad == 0x21 && !r.frame.starts_with("18EE") &&
                r.frame.find("#041B70") == std::string_view::npos &&
                r.frame.find("#041B80") == std::string_view::npos)
                take(r.frame);
    // the rows turned the events and the heartbeat off: on again, and the periodic key state
    take("18EF2100#041B7201FFFFFFFF");
    take("18EF2100#041B75010AFFFFFF");
    take("18EF2100#041B7101FFFFFFFF");
    take("18EF2100#041B7301FFFFFFFF");
    take("18EF2100#041B0101010100FF");  // LED 1 red on, SI form
    take("18EF2100#041B010105FFFFFF");  // LED 1 code 05h, LI form
    for (unsigned key = 1; key <= info(m)->keys; ++key) {
        (void)k.press(key, t);
        t = t + duration_ms{1};
        (void)k.release(key, t);
        drain_to(t);
    }
    for (unsigned i = 0; i < 100; ++i) drain_to(t = t + duration_ms{10});
    return out;
}

template <std::size_t... I>
void one_model_keypads_agree(std::index_sequence<I...>) {
    (
        [] {
            constexpr model m = static_cast<model>(I);
            CAPTURE(m);
            const auto run_time = answers<any_model>(m);
            CHECK(run_time == answers<model_constant<m>>(m));
            CHECK(run_time.size() > 40);  // it answered
            const auto j1939_run_time = j1939_answers<any_model>(m);
            CHECK(j1939_run_time == j1939_answers<model_constant<m>>(m));
            CHECK(j1939_run_time.size() > 40);  // it answered in J1939
        }(),
        ...);
}
}  // namespace

// virtual_keypad<N, model_constant<M>> (M's dictionary alone) answers as virtual_keypad<N> of M.
TEST_CASE("a keypad of one model known at compile time answers as the same model at run time") {
    one_model_keypads_agree(std::make_index_sequence<model_count>{});
}
