// powerkey: how a decoded frame was written (docs/decoder.md, "Tolerant and strict reading").
// Controllers send frames the keypads act on but the manuals do not print: cut after their last
// used byte, or padded with zeros to eight bytes. The decoder reads them with the meaning of the
// manual's form and says so in each message's `form`; the strict reading refuses them.
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

template <>
struct enum_names<frame_form> {
    using value_type = frame_form;
    static constexpr enum_name_entry<value_type> entries[] = {
        POWERKEY_FRAME_FORM_LIST(POWERKEY_DETAIL_ENUM_NAME)};
};

// How decode reads a frame whose length is not the manual's.
enum class reading : std::uint8_t {
    tolerant,  // trimmed and padded frames decode, their message's `form` says so (the default)
    strict,    // only the manual's form: any other length is errc::wrong_length
};

}  // namespace powerkey

#endif  // POWERKEY_FRAME_FORM_HPP
