// Footprint firmware (a_codec): firmware (a)'s program written with the one codec and the model a
// template argument: decode_key_state<model::pk1000> reads the key states, encode<model::pk1000>
// of the LED PDOs' own types builds the LED maps (each checks its own fields). Both read the
// model's layout as a constant and share the run-time codec's engine, so neither the model table
// nor the decoder is in the program: it is measured next to (a) to show what the codec costs a
// firmware that only needs the PDOs. Each pressed key lights its red LED; key 10 makes every lit
// LED blink. Each library call sits in its own function of namespace `calls`, so that
// scripts/footprint.sh can report the stack each one needs.
#include <powerkey/keypad/codec.hpp>

#include "mailbox.hpp"

namespace co = powerkey::canopen;
namespace pc = powerkey::can;
namespace pk = powerkey;

namespace {
constexpr pk::model keypad_model = pk::model::pk1000;
}  // namespace

namespace calls {
[[gnu::noinline]] std::optional<pk::key_set> read_keys(const pc::frame& f, co::node_id n) {
    const auto m = pk::decode_key_state<keypad_model>(f, n);
    if (!m) return std::nullopt;
    return m->keys;
}
[[gnu::noinline]] pk::result<pc::frame> build_led_on(co::node_id n, const pk::led_on& m) {
    return pk::encode<keypad_model>(n, m);
}
[[gnu::noinline]] pk::result<pc::frame> build_led_blink(co::node_id n, const pk::led_blink& m) {
    return pk::encode<keypad_model>(n, m);
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
