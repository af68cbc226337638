// powerkey: how a decoded frame was written: in the manual's form, trimmed or padded
// (docs/decoder.md, "Tolerant and strict reading").
#ifndef POWERKEY_FRAME_FORM_HPP
#define POWERKEY_FRAME_FORM_HPP

#include <powerkey/enum_names.hpp>

#include <cstdint>

namespace powerkey {

// clang-format off
#define POWERKEY_FRAME_FORM_LIST(X) \
    X(manual)  /* the length the manual prints */ \
    X(trimmed)  /* shorter: only bytes the manual leaves unused (or the SDO size leaves out) missing */ \
    X(padded)  /* longer: the bytes past the manual's length all 00h */
// clang-format on
enum class frame_form : std::uint8_t { POWERKEY_FRAME_FORM_LIST(POWERKEY_DETAIL_ENUMERATOR) };

// How decode reads a frame whose length is not the manual's.
enum class reading : std::uint8_t {
    tolerant,  // trimmed and padded frames decode, their message's `form` says so (the default)
    strict,    // only the manual's form: any other length is errc::wrong_length
};

}  // namespace powerkey

POWERKEY_DETAIL_ENUM_NAMES(powerkey::frame_form, POWERKEY_FRAME_FORM_LIST);

#endif  // POWERKEY_FRAME_FORM_HPP
