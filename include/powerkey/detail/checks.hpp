// powerkey detail: the identifier and length checks every decoder starts with, in one place, so
// that every decoder reports the same errc for the same fault (format, then id, then length).
#ifndef POWERKEY_DETAIL_CHECKS_HPP
#define POWERKEY_DETAIL_CHECKS_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/error.hpp>

#include <cstdint>

namespace powerkey::detail {

// errc{} when f has the standard identifier `id` and exactly `length` data bytes.
constexpr errc check_frame(const can::frame& f, can::standard_id id, std::uint8_t length) noexcept {
    if (f.is_extended()) return errc::wrong_id_format;
    if (f.raw_id() != id.value()) return errc::wrong_id;
    if (f.size() != length) return errc::wrong_length;
    return errc{};
}

}  // namespace powerkey::detail

#endif  // POWERKEY_DETAIL_CHECKS_HPP
