// Footprint firmware (b): a bus monitor of a CANopen bus that carries the whole any-frame decoder
// (decode_canopen: every 11-bit frame, no J1939 code), every object dictionary and every model (the
// model is read at run time from a configuration register, so nothing can be left out). For each
// frame it reports the kind of message, or the error, in a status register. Each library call sits
// in its own function of namespace `calls`, so that scripts/footprint.sh can report the stack each
// one needs. It reads tolerantly (decode's default); fw_b_strict.cpp is the same monitor reading
// strictly (powerkey::reading::strict).
#include <powerkey/keypad/codec.hpp>

#ifndef FW_B_READING
#define FW_B_READING tolerant
#endif

#include "mailbox.hpp"

namespace co = powerkey::canopen;
namespace pc = powerkey::can;

namespace {
struct monitor_registers {
    volatile std::uint32_t model;   // powerkey::model of the keypad watched
    volatile std::uint32_t node;    // its node id
    volatile std::uint32_t result;  // per frame: 1 + alternative index, or 0x100 + errc
};
monitor_registers& monitor() { return *reinterpret_cast<monitor_registers*>(0x4000'6440); }

// The alternative of the flat message: its index.
std::uint32_t kind_of(const powerkey::message& m) { return static_cast<std::uint32_t>(m.index()); }
}  // namespace

namespace calls {
[[gnu::noinline]] powerkey::result<powerkey::message> decode_any(const pc::frame& f, co::node_id n,
                                                                 powerkey::model m) {
    return powerkey::decode_canopen(f, n, m, powerkey::reading::FW_B_READING);
}
}  // namespace calls

[[noreturn]] void firmware_main() {
    for (;;) {
        const auto f = firmware::receive();
        if (!f) continue;
        const auto node = co::node_id::make(monitor().node);
        // (a register value that is no model: the decoder's value_out_of_range, reported)
        const auto model = static_cast<powerkey::model>(monitor().model & 0xFF);
        if (!node) continue;
        const auto r = calls::decode_any(*f, *node, model);
        monitor().result = r ? 1 + kind_of(*r) : 0x100 + static_cast<std::uint32_t>(r.error());
    }
}
