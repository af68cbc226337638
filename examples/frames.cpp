// Prints, in candump form, frames that the library built at compile time: the CiA 301 pieces
// directly, the keypad's own frames through encode(node, model, message), which checks each one
// by decoding it back.
#include <powerkey/powerkey.hpp>

#include <cstdio>

namespace {
using namespace powerkey;
constexpr canopen::node_id keypad = canopen::default_node_id;

// A keypad message as a frame; a message the model cannot carry does not compile.
consteval can::frame frame_of(model m, const message& msg) {
    return encode(keypad, m, msg).value();
}

constexpr can::frame frames[] = {
    canopen::encode(canopen::nmt_message{canopen::nmt_command::start, keypad.value()}),
    canopen::encode(canopen::sync_message{}),
    canopen::encode(keypad, canopen::heartbeat_message{canopen::nmt_state::operational}),
    frame_of(model::pkp2400, led_on{leds{}.set(3, colour::green).set(7, colour::white)}),
    frame_of(model::pk1000, backlight{0x20, backlight_colour::blue}),
    frame_of(model::pk1000, sdo_read{object::device_name}),
    frame_of(model::pk1000, sdo_write{object::heartbeat_time, number_value(500)}),
    frame_of(model::pkp2600, command{.code = command_code::set_led_state,
                                     .key = 12,
                                     .state = led_state::blue_alternate_blink}),
    j1939::encode(j1939::switch_to_canopen{}),
};
static_assert(frames[0] == can::candump("000#0115"));
static_assert(frames[3] == can::candump("215#4044400000000000"));
static_assert(frames[4] == can::candump("515#2003000000000000"));
static_assert(frames[6] == can::candump("615#2B171000F4010000"));
static_assert(frames[7] == can::candump("615#23006501010C0900"));
static_assert(frames[8] == can::candump("18EF2100#041B8000FFFFFFFF"));
}  // namespace

int main() {
    for (const auto& f : frames) {
        const auto text = can::format_candump(f);
        std::printf("%.*s\n", static_cast<int>(text.view().size()), text.view().data());
    }
}
