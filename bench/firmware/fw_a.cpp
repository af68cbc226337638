// Footprint firmware (a): a PK1000 host that only reads key states and builds LED frames, the
// smallest useful program (issue 7: must fit in 1 KiB of flash with no .data and no .bss).
// Each pressed key lights its red LED; key 10 makes every lit LED blink.
// Each library call sits in its own function of namespace `calls`, so that scripts/footprint.sh
// can report the stack each one needs.
#include <powerkey/pk1000/pdo.hpp>

#include "mailbox.hpp"

namespace co = powerkey::canopen;
namespace pc = powerkey::can;
namespace pk = powerkey::pk1000;

namespace calls {
[[gnu::noinline]] powerkey::result<pk::key_state> read_keys(const pc::frame& f, co::node_id n) {
    return pk::decode_key_state(f, n);
}
[[gnu::noinline]] pc::frame build_led_on(co::node_id n, const pk::led_on& m) {
    return pk::encode(n, m);
}
[[gnu::noinline]] pc::frame build_led_blink(co::node_id n, const pk::led_blink& m) {
    return pk::encode(n, m);
}
}  // namespace calls

[[noreturn]] void firmware_main() {
    constexpr co::node_id node = co::default_node_id;
    for (;;) {
        const auto f = firmware::receive();
        if (!f) continue;
        const auto keys = calls::read_keys(*f, node);
        if (!keys) continue;
        const auto lit = pk::led_set::from_mask(keys->pressed.mask());
        firmware::transmit(calls::build_led_on(node, pk::led_on{lit, {}}));
        firmware::transmit(calls::build_led_blink(
            node, pk::led_blink{keys->pressed.contains(10) ? lit : pk::led_set{}, {}}));
    }
}
