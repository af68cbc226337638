// powerkey: SYNC (CiA 301 7.2.5), COB-ID 080h, no data (PK1000 manual section 10). The keypads
// use SYNC to latch PDOs when a PDO's transmission type asks for it (objects 1400h, 1800h).
#ifndef POWERKEY_CANOPEN_SYNC_HPP
#define POWERKEY_CANOPEN_SYNC_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/detail/message.hpp>
#include <powerkey/frame_form.hpp>

#include <string_view>

namespace powerkey::canopen {

struct sync_message {
    POWERKEY_DETAIL_MESSAGE(sync_message);
    template <class Self, class F>
    static constexpr void fields(Self&, F&&) {}
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

[[nodiscard]] constexpr can::frame encode(const sync_message&) noexcept {
    return can::frame(sync_cob_id, std::array<std::uint8_t, 0>{});
}

// Errors: docs/canopen.md, "SYNC" (the keypads use no CiA 301 counter byte).
[[nodiscard]] constexpr result<sync_message> decode_sync(const can::frame& f) noexcept {
    if (const auto e = detail::check_frame(f, sync_cob_id, 0); e != errc{}) return e;
    return sync_message{};
}

}  // namespace powerkey::canopen

#endif  // POWERKEY_CANOPEN_SYNC_HPP
