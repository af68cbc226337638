// canopen/sdo_upload.hpp: the segmented-upload reader over every string read of both manuals,
// frame by frame: the requests it produces must be the manual's requests, and the value the
// manual's value; faults, frames of others, and a short segment.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/canopen/sdo_upload.hpp>

#include "support.hpp"

#include <array>
#include <string_view>

namespace {
using namespace powerkey;
using namespace std::string_view_literals;
using canopen::upload_notes;

constexpr canopen::node_id keypad = 0x15;

// One transcript: the client's requests and the keypad's replies, alternating, as printed.
struct transcript {
    std::string_view section;
    canopen::sdo_address address;
    std::array<std::string_view, 6> frames;  // request, reply, request, reply, ... ("" = none)
    std::string_view bytes;                  // every byte received, NULs included
    std::string_view text;                   // the text, NULs left out
    upload_notes notes;
};

constexpr upload_notes clean{};
constexpr upload_notes nul_only{.contains_nul = true};

constexpr transcript transcripts[] = {
    {"PK1000 32 (1008h device name)",
     {0x1008, 0},
     {"615#4008100000000000", "595#410810000B000000", "615#6000000000000000",
      "595#00426C696E6B4D61", "615#7000000000000000", "595#1772696E65000000"},
     "BlinkMarine",
     "BlinkMarine",
     clean},
    {"PK1000 33 (1009h hardware revision, expedited)",
     {0x1009, 0},
     {"615#4009100000000000", "595#43091000565F3033"},
     "V_03",
     "V_03",
     clean},
    {"PK1000 34 (100Ah firmware revision, expedited)",
     {0x100A, 0},
     {"615#400A100000000000", "595#430A100056322E38"},
     "V2.8",
     "V2.8",
     clean},
    {"PK1000 35 (100Bh model id)",
     {0x100B, 0},
     {"615#400B100000000000", "595#410B100007000000", "615#6000000000000000",
      "595#01504B3130303000"},
     "PK1000\0"sv,
     "PK1000",
     nul_only},
    {"PK1000 48 (2200h serial number); E-CORE-1",
     {0x2200, 0},
     {"615#4000220000000000", "595#4100220008000000", "615#6000000000000000",
      "595#0046464646464646", "615#7000000000000000", "595#1D46000000000000"},
     "FFFFFFFF",
     "FFFFFFFF",
     clean},
    {"PKP 19 (1008h device name)",
     {0x1008, 0},
     {"615#4008100000000000", "595#410810000B000000", "615#6000000000000000",
      "595#00426C696E6B4D61", "615#7000000000000000", "595#1772696E65000000"},
     "BlinkMarine",
     "BlinkMarine",
     clean},
    {"PKP 20 (1009h hardware revision); E-CORE-5",
     {0x1009, 0},
     {"615#4009100000000000", "595#410910000A000000", "615#6000000000000000",
      "595#0052657620312E30", "615#7000000000000000", "595#1900440000000000"},
     "Rev 1.0\0D\0"sv,
     "Rev 1.0D",
     nul_only},
    {"PKP 21 (100Ah firmware revision); E-CORE-5",
     {0x100A, 0},
     {"615#400A100000000000", "595#410A10000A000000", "615#6000000000000000",
      "595#0052657620312E30", "615#7000000000000000", "595#1900520000000000"},
     "Rev 1.0\0R\0"sv,
     "Rev 1.0R",
     nul_only},
    {"PKP 22 (100Bh model id); E-CORE-2",
     {0x100B, 0},
     {"615#400B100000000000", "595#410B100007000000", "615#6000000000000000",
      "595#00504B5532343030", "615#7000000000000000", "595#1D00000000000000"},
     "PKU2400\0"sv,
     "PKU2400",
     {.size_mismatch = true, .continued_past_size = true, .contains_nul = true}},
    {"PKP 29 (6100h sub 2 model id); E-CORE-3",
     {0x6100, 2},
     {"615#4000610200000000", "595#4000610208000000", "615#6000000000000000",
      "595#00504B5532343030", "615#7000000000000000", "595#1D00000000000000"},
     "PKU2400\0"sv,
     "PKU2400",
     {.size_not_indicated = true, .contains_nul = true}},
    // The manual prints the request as 41h (E-CORE-4); the reader sends 40h.
    {"PKP 31 (6300h serial number); E-CORE-4",
     {0x6300, 0},
     {"615#4000630000000000", "595#4100630006000000", "615#6000000000000000",
      "595#0030303030303000", "615#7000000000000000", "595#1D00000000000000"},
     "000000\0\0"sv,
     "000000",
     {.size_mismatch = true, .continued_past_size = true, .contains_nul = true}},
};

// Runs one transcript through a reader; true when every request and the result match.
template <std::size_t Capacity>
constexpr bool replay(const transcript& t, canopen::upload_policy policy, errc expected_error) {
    canopen::segmented_upload<Capacity> r(keypad, policy);
    if (r.start(t.address) != can::parse_candump(t.frames[0]).value()) return false;
    for (std::size_t i = 1; i < t.frames.size() && !t.frames[i].empty(); i += 2) {
        const auto step = r.step(can::parse_candump(t.frames[i]).value());
        if (!step)
            return step.error() == expected_error && r.state() == canopen::upload_state::failed;
        const bool more = i + 1 < t.frames.size() && !t.frames[i + 1].empty();
        if (more != step->request.has_value()) return false;
        if (more && *step->request != can::parse_candump(t.frames[i + 1]).value()) return false;
    }
    if (expected_error != errc{}) return false;
    if (r.state() != canopen::upload_state::done) return false;
    if (r.bytes().size() != t.bytes.size()) return false;
    for (std::size_t i = 0; i < t.bytes.size(); ++i)
        if (r.bytes()[i] != static_cast<std::uint8_t>(t.bytes[i])) return false;
    return r.text() == t.text && r.notes() == t.notes;
}

using powerkey_tests::first_failing;

constexpr bool reports(const transcript& t) {
    return replay<32>(t, canopen::upload_policy::report, errc{});
}
static_assert(first_failing(transcripts, reports) == std::size(transcripts));

// Strict mode: the transcripts that break the size rules end in size_mismatch; the others pass.
constexpr bool strict(const transcript& t) {
    const bool breaks = t.notes.size_mismatch || t.notes.continued_past_size;
    return replay<32>(t, canopen::upload_policy::strict, breaks ? errc::size_mismatch : errc{});
}
static_assert(first_failing(transcripts, strict) == std::size(transcripts));

// A buffer one byte too small for "BlinkMarine" ends in buffer_too_small, never past the end.
static_assert(replay<10>(transcripts[0], canopen::upload_policy::report, errc::buffer_too_small));
static_assert(replay<11>(transcripts[0], canopen::upload_policy::report, errc{}));
static_assert(replay<3>(transcripts[1], canopen::upload_policy::report, errc::buffer_too_small));

// Faults injected into the 1008h transcript.
struct fault {
    std::string_view what;
    std::array<std::string_view, 6> frames;
    errc error;
};
constexpr fault faults[] = {
    {"second segment repeats toggle 0",
     {"615#4008100000000000", "595#410810000B000000", "615#6000000000000000",
      "595#00426C696E6B4D61", "615#7000000000000000", "595#0772696E65000000"},
     errc::toggle_error},
    {"first segment with toggle 1",
     {"615#4008100000000000", "595#410810000B000000", "615#6000000000000000",
      "595#10426C696E6B4D61"},
     errc::toggle_error},
    {"keypad aborts: object does not exist",
     {"615#4008100000000000", "595#8008100000000206"},
     errc::sdo_aborted},
    {"reply for another object",
     {"615#4008100000000000", "595#410910000B000000"},
     errc::index_mismatch},
    {"a download response where an upload was asked",
     {"615#4008100000000000", "595#6008100000000000"},
     errc::unexpected_frame},
    {"a segment before the initiate response",
     {"615#4008100000000000", "595#00426C696E6B4D61"},
     errc::unexpected_frame},
    {"an initiate response in the middle of the segments",
     {"615#4008100000000000", "595#410810000B000000", "615#6000000000000000",
      "595#410810000B000000"},
     errc::unexpected_frame},
    {"a short SDO frame", {"615#4008100000000000", "595#410810000B"}, errc::wrong_length},
};

constexpr bool fault_ends_in(const fault& f) {
    return replay<32>({f.what, {0x1008, 0}, f.frames, "", "", clean},
                      canopen::upload_policy::report, f.error);
}
constexpr bool all_faults() { return first_failing(faults, fault_ends_in) == std::size(faults); }
static_assert(all_faults());
}  // namespace

TEST_CASE("segmented reader: every string read of both manuals") {
    for (const auto& t : transcripts) {
        CAPTURE(t.section);
        CHECK(reports(t));
        CHECK(strict(t));
    }
}

TEST_CASE("segmented reader: what the keypad sends is kept and reported") {
    canopen::segmented_upload<32> r(keypad);
    (void)r.start({0x100B, 0});
    REQUIRE(r.step(can::candump("595#410B100007000000")).has_value());
    REQUIRE(r.step(can::candump("595#00504B5532343030")).has_value());
    CHECK(r.notes().continued_past_size);
    CHECK_FALSE(r.notes().size_mismatch);  // 7 of 7 so far
    const auto last = r.step(can::candump("595#1D00000000000000"));
    REQUIRE(last.has_value());
    CHECK_FALSE(last->request.has_value());
    CHECK(r.notes().size_mismatch);  // 8 received, 7 announced
    CHECK(r.announced_size() == 7u);
    CHECK(r.bytes().size() == 8);
    CHECK(r.text() == "PKU2400");
}

TEST_CASE("segmented reader: faults end the transfer with a clear error") {
    for (const auto& f : faults) {
        CAPTURE(f.what);
        CHECK(fault_ends_in(f));
    }
    canopen::segmented_upload<32> r(keypad);
    (void)r.start({0x1008, 0});
    CHECK(r.step(can::candump("595#8008100000000206")).error() == errc::sdo_aborted);
    CHECK(r.abort_code() == canopen::sdo_abort_code::object_does_not_exist);
    CHECK(r.error() == errc::sdo_aborted);
    // Once failed, nothing more is accepted.
    CHECK(r.step(can::candump("595#410810000B000000")).error() == errc::unexpected_frame);
}

TEST_CASE("segmented reader: frames of other nodes and functions are refused and change nothing") {
    canopen::segmented_upload<32> r(keypad);
    CHECK(r.step(can::candump("595#410810000B000000")).error() == errc::unexpected_frame);  // idle
    (void)r.start({0x1008, 0});
    CHECK(r.step(can::candump("596#410810000B000000")).error() == errc::wrong_id);
    CHECK(r.step(can::candump("00000595#410810000B000000")).error() == errc::wrong_id_format);
    CHECK(r.step(can::candump("195#0100000012")).error() == errc::wrong_id);
    CHECK(r.state() == canopen::upload_state::running);
    const auto step = r.step(can::candump("595#410810000B000000"));
    REQUIRE(step.has_value());
    CHECK(step->request == can::candump("615#6000000000000000"));
}

TEST_CASE("a segment other than the last that carries fewer than 7 bytes is noted") {
    // CiA 301 7.2.4.3.7: only the last segment may leave bytes unused (n > 0).
    canopen::segmented_upload<32> u(canopen::node_id::make(0x15).value());
    CHECK(u.start({0x1008, 0}) == can::candump("615#4008100000000000"));
    REQUIRE(u.step(can::candump("595#410810000B000000")).has_value());
    const auto s = u.step(can::candump("595#02426C696E6B4D00"));  // "BlinkM", n = 1, not the last
    REQUIRE(s.has_value());
    CHECK(u.notes().short_segment);
    canopen::segmented_upload<32> strict(canopen::node_id::make(0x15).value(),
                                         canopen::upload_policy::strict);
    (void)strict.start({0x1008, 0});
    REQUIRE(strict.step(can::candump("595#410810000B000000")).has_value());
    CHECK(strict.step(can::candump("595#02426C696E6B4D00")) == errc::size_mismatch);
}

// The size rules at their boundaries: an upload of 1008h announcing 11 bytes, a first segment of
// 7 bytes, then a last segment of 1..7 bytes (n = 7 - bytes): 4 bytes end it exactly; fewer end
// it short of the size, more run past it; both are size_mismatch, and neither is
// continued_past_size (the last segment ends the transfer). Then segments without the last flag:
// one that reaches the size exactly is continued_past_size, one short of it is not. Strictly read,
// each discrepancy ends the transfer with size_mismatch; the exact one completes. The capacity at
// its boundary: 11 bytes fit a reader of 11, not of 10.
namespace {
can::frame segment(bool toggle, unsigned bytes, bool last) {
    can::payload p{};
    p[0] =
        static_cast<std::uint8_t>((toggle ? 0x10u : 0u) | ((7u - bytes) << 1) | (last ? 1u : 0u));
    for (unsigned i = 0; i < bytes; ++i) p[1 + i] = static_cast<std::uint8_t>('a' + i);
    return can::frame(can::standard_id::make(0x595).value(), can::dlc::make(8).value(), p);
}
template <std::size_t Capacity = 32>
struct upload_of_11 {
    canopen::segmented_upload<Capacity> u;
    explicit upload_of_11(canopen::upload_policy p = canopen::upload_policy::report)
        : u(keypad, p) {
        (void)u.start({0x1008, 0});
        REQUIRE(u.step(can::candump("595#410810000B000000")).has_value());
    }
};
}  // namespace

TEST_CASE("segmented reader: the announced size at its boundary, one byte short and one past") {
    for (unsigned last = 1; last <= 7; ++last) {
        CAPTURE(last);
        const bool exact = 7 + last == 11;
        upload_of_11<> r;
        REQUIRE(r.u.step(segment(false, 7, false)).has_value());
        CHECK_FALSE(r.u.notes().continued_past_size);
        const auto end = r.u.step(segment(true, last, true));
        REQUIRE(end.has_value());
        CHECK(r.u.state() == canopen::upload_state::done);
        CHECK(r.u.bytes().size() == 7 + last);
        CHECK(r.u.notes().size_mismatch == !exact);
        CHECK_FALSE(r.u.notes().continued_past_size);
        CHECK_FALSE(r.u.notes().short_segment);

        upload_of_11<> s(canopen::upload_policy::strict);
        REQUIRE(s.u.step(segment(false, 7, false)).has_value());
        const auto strict_end = s.u.step(segment(true, last, true));
        if (exact) {
            CHECK(strict_end.has_value());
            CHECK(s.u.state() == canopen::upload_state::done);
        } else {
            CHECK(strict_end == errc::size_mismatch);
            CHECK(s.u.state() == canopen::upload_state::failed);
        }
    }
    // Without the last flag: 7 + 3 bytes stay short of 11, 7 + 4 reach it, 7 + 5 run past.
    for (unsigned second = 3; second <= 5; ++second) {
        CAPTURE(second);
        upload_of_11<> r;
        REQUIRE(r.u.step(segment(false, 7, false)).has_value());
        REQUIRE(r.u.step(segment(true, second, false)).has_value());
        CHECK(r.u.notes().continued_past_size == (7 + second >= 11));
        CHECK(r.u.notes().size_mismatch == (7 + second > 11));
        CHECK(r.u.notes().short_segment);  // fewer than 7 bytes and not the last
        CHECK(r.u.state() == canopen::upload_state::running);
    }
    // A segment other than the last with n = 1 is short; with n = 0 it is not.
    upload_of_11<> full;
    REQUIRE(full.u.step(segment(false, 7, false)).has_value());
    CHECK_FALSE(full.u.notes().short_segment);
    upload_of_11<> six;
    REQUIRE(six.u.step(segment(false, 6, false)).has_value());
    CHECK(six.u.notes().short_segment);
    CHECK_FALSE(six.u.notes().size_mismatch);
}

TEST_CASE("segmented reader: the capacity at its boundary") {
    upload_of_11<11> fits;
    REQUIRE(fits.u.step(segment(false, 7, false)).has_value());
    CHECK(fits.u.step(segment(true, 4, true)).has_value());
    CHECK(fits.u.bytes().size() == 11);
    upload_of_11<10> over;
    REQUIRE(over.u.step(segment(false, 7, false)).has_value());
    CHECK(over.u.step(segment(true, 4, true)) == errc::buffer_too_small);
}
