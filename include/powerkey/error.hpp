// powerkey: the one-byte error code every decoder returns on untrusted input.
// docs/errors.md lists each code and the decoders that can return it; keep the two in step.
#ifndef POWERKEY_ERROR_HPP
#define POWERKEY_ERROR_HPP

#include <cstdint>
#include <string_view>

namespace powerkey {

enum class errc : std::uint8_t {
    wrong_id_format = 1,  // an 11-bit identifier where a 29-bit one was expected, or the reverse
    wrong_id,             // the identifier is not the one this message uses (function code or node)
    wrong_length,         // the dlc is not the one this message has
    unknown_command,      // a command / specifier byte this message family does not define
    index_mismatch,       // an SDO index or sub-index that is not the expected one
    value_out_of_range,   // a field holds a value outside its documented range
    reserved_not_zero,    // a byte or bit the protocol reserves is not zero
    toggle_error,         // an SDO segment with the wrong toggle bit
    size_mismatch,        // an SDO transfer whose byte count differs from the announced size
    buffer_too_small,     // the caller's buffer cannot hold the result
    sdo_aborted,          // the peer answered with an SDO abort (80h)
    unexpected_frame,     // a valid frame that does not fit the current state of a transfer
    syntax_error,         // malformed text (candump form, numbers)
    unknown_object,       // an SDO index or sub-index the keypad's profile does not define
};

// A short stable name for each code, e.g. "wrong_length"; "unknown" for a value outside the enum.
[[nodiscard]] constexpr std::string_view to_string(errc e) noexcept {
    switch (e) {
        case errc::wrong_id_format: return "wrong_id_format";
        case errc::wrong_id: return "wrong_id";
        case errc::wrong_length: return "wrong_length";
        case errc::unknown_command: return "unknown_command";
        case errc::index_mismatch: return "index_mismatch";
        case errc::value_out_of_range: return "value_out_of_range";
        case errc::reserved_not_zero: return "reserved_not_zero";
        case errc::toggle_error: return "toggle_error";
        case errc::size_mismatch: return "size_mismatch";
        case errc::buffer_too_small: return "buffer_too_small";
        case errc::sdo_aborted: return "sdo_aborted";
        case errc::unexpected_frame: return "unexpected_frame";
        case errc::syntax_error: return "syntax_error";
        case errc::unknown_object: return "unknown_object";
    }
    return "unknown";
}

// Every code, for tests and tools that enumerate them.
inline constexpr errc all_errc[] = {
    errc::wrong_id_format,   errc::wrong_id,       errc::wrong_length,
    errc::unknown_command,   errc::index_mismatch, errc::value_out_of_range,
    errc::reserved_not_zero, errc::toggle_error,   errc::size_mismatch,
    errc::buffer_too_small,  errc::sdo_aborted,    errc::unexpected_frame,
    errc::syntax_error,      errc::unknown_object,
};

}  // namespace powerkey

#endif  // POWERKEY_ERROR_HPP
