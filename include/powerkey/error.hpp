// powerkey: the one-byte error code every decoder returns on untrusted input.
// docs/errors.md lists each code and the decoders that can return it; keep the two in step.
#ifndef POWERKEY_ERROR_HPP
#define POWERKEY_ERROR_HPP

#include <powerkey/enum_names.hpp>

#include <cstdint>

namespace powerkey {

// clang-format off
#define POWERKEY_ERRC_LIST(X) \
    X(wrong_id_format, 1)  /* an 11-bit identifier where a 29-bit one was expected, or the reverse */ \
    X(wrong_id)  /* the identifier is not the one this message uses (function code or node) */ \
    X(wrong_length)  /* the dlc is not the one this message has */ \
    X(unknown_command)  /* a command / specifier byte this message family does not define */ \
    X(index_mismatch)  /* an SDO index or sub-index that is not the expected one */ \
    X(value_out_of_range)  /* a field holds a value outside its documented range */ \
    X(reserved_not_zero)  /* a byte or bit the protocol reserves is not zero */ \
    X(toggle_error)  /* an SDO segment with the wrong toggle bit */ \
    X(size_mismatch)  /* an SDO transfer whose byte count differs from the announced size */ \
    X(buffer_too_small)  /* the caller's buffer cannot hold the result */ \
    X(sdo_aborted)  /* the peer answered with an SDO abort (80h) */ \
    X(unexpected_frame)  /* a valid frame that does not fit the current state of a transfer */ \
    X(syntax_error)  /* malformed text (candump form, numbers) */ \
    X(unknown_object)  /* an SDO index or sub-index the keypad's dictionary does not define */ \
    X(reserved_not_ff)  /* a byte or bit J1939 sends as all 1's ("not used", FFh) is not */ \
    X(undocumented)  /* a frame whose layout on this model no public source shows */
// clang-format on
enum class errc : std::uint8_t { POWERKEY_ERRC_LIST(POWERKEY_DETAIL_ENUMERATOR) };

}  // namespace powerkey

POWERKEY_DETAIL_ENUM_NAMES(powerkey::errc, POWERKEY_ERRC_LIST);

#endif  // POWERKEY_ERROR_HPP
