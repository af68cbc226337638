// Footprint firmware (a_codec): firmware (a)'s program written with the one codec, decode_canopen
// and encode of the LED PDOs' own types with the model a constant, and the pressed_keys accessor.
// It carries the whole CANopen decoder (encode checks its frame by decoding it), so it is measured
// next to (a) to show what the codec costs a firmware that only needs the PDOs. Each pressed key
// lights its red LED; key 10 makes every lit LED blink. Each library call sits in its own function
// of namespace `calls`, so that scripts/footprint.sh can report the stack each one needs.
#include <powerkey/keypad/accessors.hpp>
#include <powerkey/keypad/codec.hpp>

#include "mailbox.hpp"

namespace co = powerkey::canopen;
namespace pc = powerkey::can;
namespace pk = powerkey;

namespace calls {
[[gnu::noinline]] std::optional<pk::key_set> read_keys(const pc::frame& f, co::node_id n) {
    const auto m = pk::decode_canopen(f, n, pk::model::pk1000);
    if (!m) return std::nullopt;
    return pk::pressed_keys(*m);
}
[[gnu::noinline]] pk::result<pc::frame> build_led_on(co::node_id n, const pk::led_on& m) {
    return pk::encode(n, pk::model::pk1000, m);
}
[[gnu::noinline]] pk::result<pc::frame> build_led_blink(co::node_id n, const pk::led_blink& m) {
    return pk::encode(n, pk::model::pk1000, m);
}
}  // namespace calls

[[noreturn]] void firmware_main() {
    constexpr co::node_id node = co::default_node_id;
    for (;;) {
        const auto f = firmware::receive();
        if (!f) continue;
        const auto keys = calls::read_keys(*f, node);
        if (!keys) continue;
        const auto lit = pk::led_set::from_mask(keys->mask());
        if (const auto on = calls::build_led_on(node, pk::led_on{{lit, {}, {}}}))
            firmware::transmit(*on);
        if (const auto blink = calls::build_led_blink(
                node, pk::led_blink{{keys->contains(10) ? lit : pk::led_set{}, {}, {}}}))
            firmware::transmit(*blink);
    }
}
