// A user's first program, through the installed or vendored library: a key press from the bytes a
// CAN driver hands over lights that key green (the tutorial's firmware loop), checked at compile
// time and run.
#include <powerkey/powerkey.hpp>

#include <array>
#include <cstdint>

namespace {
using namespace powerkey;

constexpr result<can::frame> light_pressed(std::uint32_t id,
                                           const std::array<std::uint8_t, 5>& data) {
    const auto f = can::make_frame(id, data);
    if (!f) return f.error();
    const auto m = decode(*f, canopen::default_node_id, model::pkp2400);
    if (!m) return m.error();
    const auto keys = pressed_keys(*m);
    if (!keys) return errc::unexpected_frame;
    leds map;
    for (unsigned k = 1; k <= 16; ++k)
        if (keys->contains(k)) map.set(k, colour::green);
    return encode(canopen::default_node_id, model::pkp2400, led_on{map});
}
}  // namespace

int main() {
    using namespace powerkey;
    constexpr auto start = canopen::encode(canopen::nmt_message{canopen::nmt_command::start, 0x15});
    static_assert(start == can::candump("000#0115"));
    constexpr std::array<std::uint8_t, 5> key3{0x04, 0x00, 0x00, 0x00, 0x2A};
    static_assert(light_pressed(0x195, key3).value() == can::candump("215#0004000000000000"));
    const auto sent = light_pressed(0x195, key3);
    return canopen::decode_nmt(start).has_value() && sent.has_value() &&
                   *sent == can::candump("215#0004000000000000")
               ? 0
               : 1;
}
