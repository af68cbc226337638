// A firmware's receive loop: a key press lights that key's LED green. The frame comes from the
// CAN driver as an id and bytes, and the answer goes back through the driver. This is the
// firmware loop of docs/tutorial.md; here the "driver" is a key press of key 3 on a PKP-2400 at
// node 15h, and transmit() prints the frame it would send, 215#0004000000000000 (green LED #3 on);
// the program exits 0 only when it sent exactly that frame.
#include <powerkey/powerkey.hpp>

#include <cstdint>
#include <cstdio>

using namespace powerkey;

constexpr canopen::node_id keypad = canopen::default_node_id;  // 15h, as delivered
constexpr model keypad_model = model::pkp2400;

// What a CAN driver hands over (the shape varies; an id, the bytes and their count is typical).
struct rx_frame {
    std::uint32_t id;
    std::uint8_t data[8];
    std::uint8_t dlc;
};

// Stands in for the driver's send call.
can::frame last_sent;
void transmit(const can::frame& f) {
    last_sent = f;
    const auto text = can::format_candump(f);
    std::printf("%.*s\n", static_cast<int>(text.view().size()), text.view().data());
}

void on_receive(const rx_frame& rx) {
    const auto f = can::make_frame(rx.id, {rx.data, rx.dlc});
    if (!f) return;
    const auto m = decode(*f, keypad, keypad_model);  // any frame of this keypad
    if (!m) return;                                   // m.error() says why
    const auto keys = pressed_keys(*m);               // a key-state PDO, or a read of 6000h
    if (!keys) return;
    led_on lit;  // every pressed key green, every other LED off
    for (unsigned k = 1; k <= key_set::max; ++k)
        if (keys->contains(k)) lit.map.set(k, colour::green);
    if (const auto out = encode(keypad, keypad_model, lit)) transmit(*out);
}

int main() {
    on_receive({0x195, {0x04, 0x00, 0x00, 0x00, 0x2A}, 5});            // key 3 pressed, tick 2Ah
    return last_sent == can::candump("215#0004000000000000") ? 0 : 1;  // ctest checks this
}
