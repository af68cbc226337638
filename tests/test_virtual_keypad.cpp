// The virtual keypad (include/powerkey/behaviour/virtual_keypad.hpp): the manuals' transcripts
// replayed against it, model by model, and one test per behaviour.
#include "pk1000_rows.hpp"
#include "pkp_rows.hpp"
#include "support.hpp"

#include <powerkey/behaviour/virtual_keypad.hpp>

#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

using namespace powerkey;
using behaviour::millis;
using behaviour::duration_ms;
using behaviour::run_state;
using behaviour::virtual_keypad;
using powerkey_tests::frame_of;

namespace {

// --- the transcript runner ------------------------------------------------------------------------

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

std::string text_of(const can::frame& f) { return doctest::StringMaker<can::frame>::convert(f).c_str(); }

// The section a row belongs to: "17a" of "17a", "19f E-PK-3 corrected", "PKP 13a LED 8 red".
std::string_view section_of(std::string_view s) {
    if (s.substr(0, 4) == "PKP ") s.remove_prefix(4);
    return s.substr(0, s.find(' '));
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
    std::uint8_t models;
    std::string_view section;  // the row's full section text
    std::string_view frame;
    because why;
    std::string_view note;
};

using decoder_rows::m1000;
using decoder_rows::m2200;
using decoder_rows::m2400;
using decoder_rows::m2600;
constexpr std::uint8_t pkp_all = decoder_rows::pkp;
constexpr std::uint8_t not2200 = m2400 | m2600;

constexpr expected_difference differences[] = {
    // --- PK1000 ---
    {m1000, "11", "195#000000002A", because::presumed,
     "no key: printed after a release; at power-on no key has changed"},
    {m1000, "17b", "595#4301200108000000", because::presumed, "reads red LED 4 on, never set"},
    {m1000, "17b", "595#4301200200020000", because::presumed, "reads green LED 10 on, never set"},
    {m1000, "18b", "595#4302200108000000", because::presumed, "reads red LED 4 blinking, never set"},
    {m1000, "18b", "595#4302200200010000", because::presumed, "reads green LED 9 blinking, never set"},
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
     because::presumed, "reference/pkp-2600.md prints requests without their replies"},
    {m2600, "ref 6001h PKP-2600 read", "+595#6001600000000000", because::presumed,
     "reference/pkp-2600.md prints requests without their replies"},
    {m2600, "ref 6001h PKP-2600 read reply red 12, green 1 (layout)", "595#4301600000180000",
     because::presumed, "a layout example, not a transcript"},
    {m2600, "ref 6002h PKP-2600 green 5, 7", "+595#6002600000000000", because::presumed,
     "reference/pkp-2600.md prints requests without their replies"},
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
    {pkp_all, "PKP 17 100 ms", "595#4B17100064000000", because::presumed,
     "reads 100 ms: heartbeat_time is off at delivery (PKP 3)"},
};

std::optional<expected_difference> difference_of(model m, std::string_view section,
                                                 std::string_view frame) {
    for (const auto& d : differences)
        if (decoder_rows::applies(d.models, m) &&
            (d.frame == "*" ? d.section == section_of(section)
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
// sends with each reply the manual prints. The runner's rules (docs/behaviour.md):
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
            if (decoder_rows::applies(rows[j].models, m)) rs.push_back(&rows[j]);
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
            while (k.transmit()) {}
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
            if (!got && replied_since_request && last_request &&
                (f.raw_id() & 0x780u) == 0x580) {
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

std::string frame_text(std::string_view s) { return text_of(frame_of(s)); }

}  // namespace

// --- the manuals' transcripts -------------------------------------------------------------------

TEST_CASE("It answers like the manuals") {
    SUBCASE("PK1000") { report(model::pk1000, run_transcript(pk1000_rows::rows, model::pk1000)); }
    SUBCASE("PKP-2200") { report(model::pkp2200, run_transcript(pkp_rows::rows, model::pkp2200)); }
    SUBCASE("PKP-2400") { report(model::pkp2400, run_transcript(pkp_rows::rows, model::pkp2400)); }
    SUBCASE("PKP-2600") { report(model::pkp2600, run_transcript(pkp_rows::rows, model::pkp2600)); }
}
