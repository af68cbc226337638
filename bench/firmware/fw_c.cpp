// Footprint firmware (c): the controller (include/powerkey/behaviour/controller.hpp) driving one
// PKP-2400 at node 15h, as a firmware's receive loop runs it: it finds the keypad, reads its
// model, sets its heartbeat, runs a two-entry configuration list one SDO request at a time,
// starts it, keeps the LED picture and reports a lost keypad. Each key toggles its LED green
// (the key-modes helper), a lost keypad lights a status output (the application's safe state).
// Time comes from a free-running millisecond counter register; frames from the mailbox.
// The controller lives on the stack of firmware_main: no heap, no .data, no .bss. Its model is a
// template argument (model_constant): only the PKP-2400's dictionary is in the program
// (docs/howto-cortex-m0.md takes this firmware apart).
// Each library call sits in its own function of namespace `calls`, so that scripts/footprint.sh
// can report the stack each one needs.
#include <powerkey/behaviour/controller.hpp>
#include <powerkey/behaviour/key_modes.hpp>

#include "mailbox.hpp"

namespace pb = powerkey::behaviour;
namespace pc = powerkey::can;
namespace pk = powerkey;

namespace {
struct board_registers {
    volatile std::uint32_t millis;  // a free-running 1 kHz counter (SysTick or a timer)
    volatile std::uint32_t status;  // bit 0: keypad lost (the safe state), bit 1: keypad ready
};
board_registers& board() { return *reinterpret_cast<board_registers*>(0x4000'6460); }

// Frames ready in the receive mailbox, without waiting (the loop also runs the timers).
bool frame_waiting() { return firmware::rx().status != 0; }

using keypad_controller = pb::controller<4, 8, pk::model_constant<pk::model::pkp2400>>;

// Checked and built when the program is built (configuration_entry): the firmware holds the
// requests' bytes.
constexpr pb::configuration_entry<pk::model::pkp2400> configuration[] = {
    pk::sdo_write{pk::object::led_brightness, pk::level_value(pk::level{0x30})},
    pk::sdo_read{pk::object::device_type},
};

constexpr keypad_controller::config config() {
    keypad_controller::config c;
    c.keypad_model = pk::model::pkp2400;
    c.configuration = configuration;
    c.keypad_heartbeat = pb::duration_ms{100};
    c.lost_after = pb::duration_ms{300};
    return c;
}
}  // namespace

namespace calls {
[[gnu::noinline]] void step(keypad_controller& c, const pc::frame& f, pb::millis now) {
    c.step(f, now);
}
[[gnu::noinline]] void tick(keypad_controller& c, pb::millis now) { c.tick(now); }
[[gnu::noinline]] std::optional<pc::frame> next_frame(keypad_controller& c) {
    return c.next_frame();
}
[[gnu::noinline]] std::optional<pb::controller_event> poll(keypad_controller& c) {
    return c.poll();
}
[[gnu::noinline]] bool set_led(keypad_controller& c, unsigned k, bool on) {
    return c.set_led(k, on ? pk::colour::green : pk::colour::off);
}
}  // namespace calls

[[noreturn]] void firmware_main() {
    keypad_controller c(config());
    pb::key_modes<8> modes;
    for (unsigned k = 1; k <= 8; ++k) modes.set(k, pb::key_mode::toggle);
    for (;;) {
        const pb::millis now{board().millis};
        if (frame_waiting()) {
            if (const auto f = firmware::receive()) calls::step(c, *f, now);
        } else {
            calls::tick(c, now);
        }
        while (const auto out = calls::next_frame(c)) firmware::transmit(*out);
        while (const auto e = calls::poll(c)) {
            if (e->kind == pb::event_kind::lost) {
                board().status = 1;  // safe state
                modes.reset();
            } else if (e->kind == pb::event_kind::ready) {
                board().status = 2;
            } else if (const auto change = modes.on_event(*e)) {
                calls::set_led(c, change->key, change->state != 0);
            }
        }
    }
}
