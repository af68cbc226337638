// Footprint firmware (j1939): a controller of a PKP-2600-SI in J1939 (issue 21): each key pressed
// lights its LED green, each key released turns it off. It reads the keypad's key contact state
// (command 01h, j1939::decode_key_or_led) and sends the single-LED command (j1939::encode of a
// set_led, which checks its own fields), both with the model a template argument: only the
// PKP-2600-SI's paths of command 01h are in the program, with its row's facts as constants (no
// model table). The keypad is at its default address 21h, the controller at 00h.
// Each library call sits in its own function of namespace `calls`, so that scripts/footprint.sh
// can report the stack each one needs.
#include <powerkey/keypad/j1939_codec.hpp>

#include "mailbox.hpp"

namespace pc = powerkey::can;
namespace pj = powerkey::j1939;

namespace {
constexpr powerkey::model keypad_model = powerkey::model::pkp2600si;
constexpr std::uint8_t keypad_address = pj::keypad_default_address;
}  // namespace

namespace calls {
[[gnu::noinline]] powerkey::result<pj::key_contact> read_key(const pc::frame& f) {
    return pj::decode_key_contact<keypad_model>(f, keypad_address);
}
// LED `key` green and on, or off: the single-LED command from the controller (00h) to the keypad.
[[gnu::noinline]] powerkey::result<pc::frame> build_led(std::uint8_t key, bool on) {
    pj::set_led led;
    led.destination = keypad_address;
    led.key = key;
    led.colour = on ? pj::led_colour::green : pj::led_colour::off;
    led.mode = on ? powerkey::led_mode::on : powerkey::led_mode::off;
    return pj::encode<keypad_model>(led, keypad_address);
}
}  // namespace calls

[[noreturn]] void firmware_main() {
    for (;;) {
        const auto f = firmware::receive();
        if (!f) continue;
        const auto key = calls::read_key(*f);
        if (!key) continue;
        if (const auto out = calls::build_led(key->key, key->pressed)) firmware::transmit(*out);
    }
}
