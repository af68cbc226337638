// The any-frame decoder on a PKP-3500-MT mixed log (issue 11): the frames of a minute with the
// keypad's encoders turning, compressed to 64 frames. Key-state, encoder and analog-input TPDOs,
// LED and ring RPDOs, heartbeat, SYNC, a few configuration SDOs with their replies, and other
// devices' traffic the decoder must refuse. Every keypad frame is printed in the PKP3500-MT manual
// (tests/data/si_rows.txt) or follows its layouts; each is proved at compile time to decode.
#ifndef POWERKEY_BENCH_OPS_SI_HPP
#define POWERKEY_BENCH_OPS_SI_HPP

#include <powerkey/keypad/codec.hpp>

#include <array>
#include <cstddef>

#include "ops.hpp"

namespace bench {

inline constexpr std::array mt_mixed_log = {
    candump("000#0115"),
    candump("715#05"),
    candump("215#FE7B000000000000"),
    candump("195#000100002A"),
    candump("295#0103000000000000"),
    candump("495#F401000000000000"),
    candump("196#0100000000"),
    candump("315#0008000000000000"),
    candump("195#000000002B"),
    candump("080#"),
    candump("395#010A000000000000"),
    candump("415#0300000000000000"),
    candump("716#05"),
    candump("295#0104000500000000"),
    candump("615#2F03200306000000"),
    candump("595#6003200300000000"),
    candump("195#000100002C"),
    candump("18FEF100#FFFFFFFFFFFFFFFF"),
    candump("715#05"),
    candump("495#0000000000006400"),
    candump("215#0000000010000000"),
    candump("295#81FFFF0000000000"),
    candump("195#000000002D"),
    candump("315#0000000000000000"),
    candump("080#"),
    candump("395#81FEFF0000000000"),
    candump("216#0100000000000000"),
    candump("415#0000C00000000000"),
    candump("195#000100002E"),
    candump("715#05"),
    candump("615#4000200300000000"),
    candump("595#4B00200303000000"),
    candump("295#0105000500000000"),
    candump("495#F401000000000000"),
    candump("215#FE7BFE7BFE7B0000"),
    candump("195#000000002F"),
    candump("080#"),
    candump("196#0000000000"),
    candump("615#2B01200108000000"),
    candump("595#6001200100000000"),
    candump("395#0110001000000000"),
    candump("195#0001000030"),
    candump("715#05"),
    candump("295#0106000500000000"),
    candump("495#0000000000006400"),
    candump("315#0008000000000000"),
    candump("195#0000000031"),
    candump("215#0000000000000000"),
    candump("716#05"),
    candump("415#0300000000000000"),
    candump("295#0105000500000000"),
    candump("080#"),
    candump("195#0001000032"),
    candump("615#2301200400000040"),
    candump("595#6001200400000000"),
    candump("715#05"),
    candump("395#010A000000000000"),
    candump("195#0000000033"),
    candump("18FEF100#FFFFFFFFFFFFFFFF"),
    candump("495#F401000000000000"),
    candump("215#FE7B000000000000"),
    candump("195#0001000034"),
    candump("715#05"),
    candump("295#0104000500000000"),
};

inline constexpr powerkey::model mt_model = powerkey::model::pkp3500mt;

// How many frames belong to the keypad (the others: another node's or a foreign 29-bit frame).
inline constexpr std::size_t mt_mixed_log_keypad_frames = keypad_frames(mt_mixed_log, mt_model);
static_assert(mt_mixed_log.size() == 64);
static_assert(mt_mixed_log_keypad_frames == mt_mixed_log.size() - 7);

inline void any_decode_mt_mixed_log(std::size_t calls) {
    decode_all(mt_mixed_log, mt_model, calls);
}

inline constexpr op si_ops[] = {
    {"any/pkp3500mt/decode_mixed_log", any_decode_mt_mixed_log},
};

}  // namespace bench

#endif  // POWERKEY_BENCH_OPS_SI_HPP
