// A stand-in for a CAN controller: one receive and one transmit mailbox as memory-mapped
// registers (the layout of the common bxCAN-style peripherals: identifier, dlc, two data words).
// The firmwares read frames from it and write frames to it, so the optimiser keeps all the work.
#ifndef POWERKEY_BENCH_FIRMWARE_MAILBOX_HPP
#define POWERKEY_BENCH_FIRMWARE_MAILBOX_HPP

#include <powerkey/can/frame.hpp>

#include <cstdint>

namespace firmware {

struct mailbox {
    volatile std::uint32_t id;  // bit 31: extended identifier; bits 28..0: identifier
    volatile std::uint32_t dlc;
    volatile std::uint32_t low;     // data bytes 0..3, byte 0 least significant
    volatile std::uint32_t high;    // data bytes 4..7
    volatile std::uint32_t status;  // rx: a frame is waiting; tx: the mailbox is free
};

inline mailbox& rx() { return *reinterpret_cast<mailbox*>(0x4000'6400); }
inline mailbox& tx() { return *reinterpret_cast<mailbox*>(0x4000'6420); }

// Waits for a frame; a frame the controller reports as malformed comes back as errc.
[[gnu::noinline]] inline powerkey::result<powerkey::can::frame> receive() {
    mailbox& m = rx();
    while (m.status == 0) {
    }
    const std::uint32_t id = m.id;
    const std::uint32_t lo = m.low;
    const std::uint32_t hi = m.high;
    powerkey::can::payload p{};
    for (int i = 0; i < 4; ++i) {
        p[static_cast<unsigned>(i)] = static_cast<std::uint8_t>(lo >> (8 * i));
        p[static_cast<unsigned>(i + 4)] = static_cast<std::uint8_t>(hi >> (8 * i));
    }
    const auto length = powerkey::can::dlc::make(m.dlc);
    m.status = 0;
    if (!length) return powerkey::errc::wrong_length;
    if ((id & 0x8000'0000u) != 0) {
        const auto eid = powerkey::can::extended_id::make(id & 0x1FFF'FFFFu);
        if (!eid) return powerkey::errc::value_out_of_range;
        return powerkey::can::frame(*eid, *length, p);
    }
    const auto sid = powerkey::can::standard_id::make(id);
    if (!sid) return powerkey::errc::value_out_of_range;
    return powerkey::can::frame(*sid, *length, p);
}

[[gnu::noinline]] inline void transmit(const powerkey::can::frame& f) {
    mailbox& m = tx();
    while (m.status == 0) {
    }
    const auto& b = f.bytes();
    m.id = f.raw_id() | (f.is_extended() ? 0x8000'0000u : 0u);
    m.dlc = f.size();
    m.low = std::uint32_t{b[0]} | (std::uint32_t{b[1]} << 8) | (std::uint32_t{b[2]} << 16) |
            (std::uint32_t{b[3]} << 24);
    m.high = std::uint32_t{b[4]} | (std::uint32_t{b[5]} << 8) | (std::uint32_t{b[6]} << 16) |
             (std::uint32_t{b[7]} << 24);
    m.status = 0;
}

}  // namespace firmware

#endif
