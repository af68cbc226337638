// powerkey: the one-byte error code every decoder returns on untrusted input.
// docs/errors.md lists each code and the decoders that can return it; keep the two in step.
#ifndef POWERKEY_ERROR_HPP
#define POWERKEY_ERROR_HPP

#include <powerkey/enum_names.hpp>

#include <cstdint>

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
    unknown_object,       // an SDO index or sub-index the keypad's dictionary does not define
    reserved_not_ff,      // a byte or bit J1939 sends as all 1's ("not used", FFh) is not
    undocumented,         // a frame whose layout on this model no public source shows
};

template <>
struct enum_names<errc> {
    static constexpr enum_name_entry<errc> entries[] = {
        {errc::wrong_id_format, "wrong_id_format"},
        {errc::wrong_id, "wrong_id"},
        {errc::wrong_length, "wrong_length"},
        {errc::unknown_command, "unknown_command"},
        {errc::index_mismatch, "index_mismatch"},
        {errc::value_out_of_range, "value_out_of_range"},
        {errc::reserved_not_zero, "reserved_not_zero"},
        {errc::toggle_error, "toggle_error"},
        {errc::size_mismatch, "size_mismatch"},
        {errc::buffer_too_small, "buffer_too_small"},
        {errc::sdo_aborted, "sdo_aborted"},
        {errc::unexpected_frame, "unexpected_frame"},
        {errc::syntax_error, "syntax_error"},
        {errc::unknown_object, "unknown_object"},
        {errc::reserved_not_ff, "reserved_not_ff"},
        {errc::undocumented, "undocumented"},
    };
};

}  // namespace powerkey

#endif  // POWERKEY_ERROR_HPP
