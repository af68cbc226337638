// The segmented SDO upload reader fed an arbitrary sequence of frames. Properties:
//  - no crash, no write past its buffer, no read of a data byte past a frame's dlc;
//  - every refusal is a listed errc; a frame of another node or format changes nothing;
//  - the state machine only moves idle -> running -> done | failed, and step() outside running
//    is unexpected_frame without any change;
//  - while running, each step asks for the next segment with the toggle alternating; done asks
//    for nothing;
//  - bytes() never exceeds the capacity, text() is bytes() without its NULs;
//  - under upload_policy::strict a completed transfer has exactly the announced size and no notes
//    on sizes or short segments.
#include "fuzz.hpp"

namespace {
using namespace powerkey;
using namespace powerkey_fuzz;

// Most replies go to the reader's own SDO response COB-ID with 8 bytes, so that the fuzzer spends
// its time inside the state machine; one in four is an arbitrary frame.
can::frame take_reply(input& in, canopen::node_id node) {
    if ((in.u8() & 3) == 0) return take_frame(in);
    can::payload p{};
    for (auto& b : p) b = in.u8();
    return can::frame(canopen::cob_id(canopen::function::sdo_tx, node), 8, p);
}

template <std::size_t Capacity>
void run(input& in, canopen::node_id node, canopen::upload_policy policy) {
    using canopen::upload_state;
    canopen::segmented_upload<Capacity> reader(node, policy);
    {  // not started: every frame is unexpected
        aligned_frame held{take_reply(in, node)};
        const poison_past_dlc guard(held.f);
        POWERKEY_FUZZ_CHECK(reader.step(held.f) == errc::unexpected_frame);
        POWERKEY_FUZZ_CHECK(reader.state() == upload_state::idle);
    }
    const canopen::sdo_address address{in.integer<std::uint16_t>(), in.u8()};
    const can::frame first = reader.start(address);
    POWERKEY_FUZZ_CHECK(first == canopen::encode(node, canopen::sdo_upload_request{address}));
    POWERKEY_FUZZ_CHECK(reader.state() == upload_state::running);

    bool expect_toggle = false;
    for (int steps = 0; !in.empty() && steps < 64; ++steps) {
        aligned_frame held{take_reply(in, node)};
        const can::frame& f = held.f;
        const upload_state before = reader.state();
        const std::size_t size_before = reader.bytes().size();
        const auto r = [&] {
            const poison_past_dlc guard(held.f);
            return reader.step(held.f);
        }();
        const upload_state after = reader.state();
        POWERKEY_FUZZ_CHECK_FRAME(reader.bytes().size() <= Capacity, f);
        POWERKEY_FUZZ_CHECK_FRAME(reader.bytes().size() >= size_before, f);
        if (before != upload_state::running) {
            POWERKEY_FUZZ_CHECK_FRAME(r == errc::unexpected_frame && after == before, f);
            POWERKEY_FUZZ_CHECK_FRAME(reader.bytes().size() == size_before, f);
            continue;
        }
        if (!r) {
            POWERKEY_FUZZ_CHECK_FRAME(is_listed(r.error()), f);
            if (r.error() == errc::wrong_id_format || r.error() == errc::wrong_id) {
                POWERKEY_FUZZ_CHECK_FRAME(after == upload_state::running, f);
                POWERKEY_FUZZ_CHECK_FRAME(reader.bytes().size() == size_before, f);
            } else {
                POWERKEY_FUZZ_CHECK_FRAME(after == upload_state::failed, f);
                POWERKEY_FUZZ_CHECK_FRAME(reader.error() == r.error(), f);
                POWERKEY_FUZZ_CHECK_FRAME(
                    (r.error() == errc::sdo_aborted) == reader.abort_code().has_value(), f);
                if (policy == canopen::upload_policy::report)
                    POWERKEY_FUZZ_CHECK_FRAME(r.error() != errc::size_mismatch, f);
            }
            continue;
        }
        POWERKEY_FUZZ_CHECK_FRAME(after == upload_state::running || after == upload_state::done, f);
        if (after == upload_state::running) {
            POWERKEY_FUZZ_CHECK_FRAME(r->request.has_value(), f);
            POWERKEY_FUZZ_CHECK_FRAME(
                *r->request == canopen::encode(node, canopen::sdo_segment_request{expect_toggle}),
                f);
            expect_toggle = !expect_toggle;
        } else {
            POWERKEY_FUZZ_CHECK_FRAME(!r->request.has_value(), f);
        }
    }

    // What was kept: text() is bytes() without NULs, in order.
    const auto bytes = reader.bytes();
    const auto text = reader.text();
    std::size_t t = 0;
    bool nul = false;
    for (std::uint8_t b : bytes) {
        if (b == 0) {
            nul = true;
            continue;
        }
        POWERKEY_FUZZ_CHECK(t < text.size() && static_cast<std::uint8_t>(text[t]) == b);
        ++t;
    }
    POWERKEY_FUZZ_CHECK(t == text.size());
    POWERKEY_FUZZ_CHECK(nul == reader.notes().contains_nul);
    POWERKEY_FUZZ_CHECK(reader.address() == address);
    if (reader.state() == upload_state::done && policy == canopen::upload_policy::strict) {
        const auto& n = reader.notes();
        POWERKEY_FUZZ_CHECK(!n.size_mismatch && !n.continued_past_size && !n.short_segment);
        if (const auto announced = reader.announced_size())
            POWERKEY_FUZZ_CHECK(bytes.size() == *announced);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    input in(data, size);
    const std::uint8_t mode = in.u8();
    const canopen::node_id node = take_node(in);
    const auto policy =
        (mode & 1) != 0 ? canopen::upload_policy::strict : canopen::upload_policy::report;
    // A small buffer reaches buffer_too_small often; a large one lets long texts complete.
    if ((mode & 2) != 0)
        run<64>(in, node, policy);
    else
        run<5>(in, node, policy);
    return 0;
}
