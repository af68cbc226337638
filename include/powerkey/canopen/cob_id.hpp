// powerkey: COB-ID arithmetic of the CiA 301 predefined connection set, as the keypads use it
// (docs/canopen.md, "COB-IDs").
#ifndef POWERKEY_CANOPEN_COB_ID_HPP
#define POWERKEY_CANOPEN_COB_ID_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/error.hpp>

#include <cstdint>

namespace powerkey::canopen {

// clang-format off
#define POWERKEY_CANOPEN_FUNCTION_LIST(X) \
    X(nmt)  /* 000h */ \
    X(sync)  /* 080h */ \
    X(tpdo1)  /* 180h + node: keypad -> host (key state) */ \
    X(tpdo2)  /* 280h + node: keypad -> host (PKP-3500-MT encoder 1) */ \
    X(tpdo3)  /* 380h + node: keypad -> host (PKP-3500-MT encoder 2) */ \
    X(tpdo4)  /* 480h + node: keypad -> host (PKP-3500-MT analog inputs) */ \
    X(rpdo1)  /* 200h + node: host -> keypad (LED on) */ \
    X(rpdo2)  /* 300h + node: host -> keypad (LED blink) */ \
    X(rpdo3)  /* 400h + node: host -> keypad (LED brightness) */ \
    X(rpdo4)  /* 500h + node: host -> keypad (backlight) */ \
    X(sdo_tx)  /* 580h + node: SDO server (keypad) -> client */ \
    X(sdo_rx)  /* 600h + node: SDO client -> server (keypad) */ \
    X(heartbeat)  /* 700h + node: boot-up and heartbeat (NMT error control) */ \
    X(j1939)  /* any 29-bit identifier: J1939, where the keypads' protocol switch lives */ \
    X(other)  /* any other identifier (EMCY, TIME, TPDO2.., LSS, ...) */
// clang-format on
enum class function : std::uint8_t { POWERKEY_CANOPEN_FUNCTION_LIST(POWERKEY_DETAIL_ENUMERATOR) };

}  // namespace powerkey::canopen

POWERKEY_DETAIL_ENUM_NAMES(powerkey::canopen::function, POWERKEY_CANOPEN_FUNCTION_LIST);

namespace powerkey::canopen {

namespace detail {
// Function code base (bits 10..7 of the COB-ID) of each per-node function; 0 for the others.
constexpr std::uint16_t per_node_base(function f) noexcept {
    switch (f) {
        case function::tpdo1: return 0x180;
        case function::tpdo2: return 0x280;
        case function::tpdo3: return 0x380;
        case function::tpdo4: return 0x480;
        case function::rpdo1: return 0x200;
        case function::rpdo2: return 0x300;
        case function::rpdo3: return 0x400;
        case function::rpdo4: return 0x500;
        case function::sdo_tx: return 0x580;
        case function::sdo_rx: return 0x600;
        case function::heartbeat: return 0x700;
        default: return 0;
    }
}
}  // namespace detail

inline constexpr can::standard_id nmt_cob_id = 0x000;
inline constexpr can::standard_id sync_cob_id = 0x080;

// COB-ID of a per-node function (tpdo1 .. heartbeat) for one node. For nmt and sync, which have
// no node, use nmt_cob_id and sync_cob_id; for them and for `other` this returns 000h.
[[nodiscard]] constexpr can::standard_id cob_id(function f, node_id node) noexcept {
    const auto base = detail::per_node_base(f);
    if (base == 0) return nmt_cob_id;
    return can::standard_id::make(base + node.value()).value();
}

// Which function and (for per-node functions) which node an identifier belongs to.
struct cob_info {
    function fn = function::other;
    std::uint8_t node = 0;  // 1..127 for per-node functions, 0 for nmt, sync, j1939 and other
    friend constexpr bool operator==(const cob_info&, const cob_info&) noexcept = default;
};

[[nodiscard]] constexpr cob_info classify(can::standard_id id) noexcept {
    const std::uint16_t v = id.value();
    if (v == 0x000) return {function::nmt, 0};
    if (v == 0x080) return {function::sync, 0};
    const auto node = static_cast<std::uint8_t>(v & 0x7F);
    // Bits 10..7 are the function code (580h is code 11): one table lookup, not a scan of the
    // bases (every decoder starts here).
    constexpr function by_code[16] = {
        function::other,  function::other, function::other,     function::tpdo1,
        function::rpdo1,  function::tpdo2, function::rpdo2,     function::tpdo3,
        function::rpdo3,  function::tpdo4, function::rpdo4,     function::sdo_tx,
        function::sdo_rx, function::other, function::heartbeat, function::other};
    const function f = by_code[(v >> 7) & 0xF];
    if (node == 0 || f == function::other) return {function::other, 0};
    return {f, node};
}

// The same for any frame: every 29-bit identifier is `j1939` (node 0).
[[nodiscard]] constexpr cob_info classify(const can::frame& f) noexcept {
    if (f.is_extended()) return {function::j1939, 0};
    return classify(can::standard_id::make(f.raw_id() & 0x7FF).value());
}

// True when the frame is addressed to or sent by the keypad `node` (docs/canopen.md, "COB-IDs").
[[nodiscard]] constexpr bool concerns(const cob_info& c, node_id node) noexcept {
    switch (c.fn) {
        case function::nmt:
        case function::sync:
        case function::j1939: return true;
        case function::other: return false;
        default: return c.node == node.value();
    }
}

namespace detail {
// errc{} when f has the standard identifier `id` and exactly `length` data bytes: the checks
// every CiA 301 decoder starts with, in one order (format, then id, then length), so that every
// decoder reports the same errc for the same fault.
constexpr errc check_frame(const can::frame& f, can::standard_id id, std::uint8_t length) noexcept {
    if (f.is_extended()) return errc::wrong_id_format;
    if (f.raw_id() != id.value()) return errc::wrong_id;
    if (f.size() != length) return errc::wrong_length;
    return errc{};
}
}  // namespace detail

}  // namespace powerkey::canopen

#endif  // POWERKEY_CANOPEN_COB_ID_HPP
