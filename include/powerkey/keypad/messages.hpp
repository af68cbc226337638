// powerkey: every message of every keypad, CANopen and J1939, as one flat type, each struct with
// its `kind` and `fields(self, f)` (docs/decoder.md, "The message type"; docs/j1939.md, "One
// vocabulary").
#ifndef POWERKEY_KEYPAD_MESSAGES_HPP
#define POWERKEY_KEYPAD_MESSAGES_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/canopen/sync.hpp>
#include <powerkey/detail/message.hpp>
#include <powerkey/frame_form.hpp>
#include <powerkey/j1939/protocol_switch.hpp>
#include <powerkey/keypad/commands.hpp>
#include <powerkey/keypad/j1939_messages.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/keypad/value_kinds.hpp>
#include <powerkey/keypad/values.hpp>

#include <array>
#include <cstdint>
#include <string_view>
#include <variant>

namespace powerkey {

// --- PDOs ---------------------------------------------------------------------------------------

// TPDO1 180h + node, keypad -> host: the pressed keys and the tick timer (+1 every 100 ms, wraps).
// PK1000 section 11, PKP section 10: bytes 0..1 keys, 2..3 00h, 4 the tick.
struct key_state {
    POWERKEY_DETAIL_MESSAGE(key_state);
    POWERKEY_DETAIL_FIELDS(f("keys", self.keys), f("tick", self.tick));
    key_set keys;
    std::uint8_t tick = 0;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// RPDO1 200h + node, host -> keypad: which LEDs are on (PK1000 section 12, PKP section 11).
struct led_on {
    POWERKEY_DETAIL_MESSAGE(led_on);
    POWERKEY_DETAIL_FIELDS(detail::map_fields(self.map, f));
    leds map;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// RPDO2 300h + node: which LEDs blink; on and blink together blink alternately (PK1000 13, PKP 12).
struct led_blink {
    POWERKEY_DETAIL_MESSAGE(led_blink);
    POWERKEY_DETAIL_FIELDS(detail::map_fields(self.map, f));
    leds map;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// RPDO3 400h + node: LED brightness until power off (PK1000 section 14): level | 00h x 7.
struct led_brightness {
    POWERKEY_DETAIL_MESSAGE(led_brightness);
    POWERKEY_DETAIL_FIELDS(f("level", self.level));
    powerkey::level level = 0x3F;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// RPDO4 500h + node: backlight level and colour until power off (PK1000 section 15):
// level | colour (00h keeps the stored colour) | 00h x 6.
struct backlight {
    POWERKEY_DETAIL_MESSAGE(backlight);
    POWERKEY_DETAIL_FIELDS(f("level", self.level), f("colour", self.colour));
    powerkey::level level = 0;
    backlight_colour colour = backlight_colour::keep;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// TPDO2 280h + node (encoder 1) and TPDO3 380h + node (encoder 2), PKP-3500-MT sections 12, 13:
// bit 7 counterclockwise, bits 0..6 ticks | counter LSB MSB | TOP | 00h x 4.
struct encoder_state {
    POWERKEY_DETAIL_MESSAGE(encoder_state);
    POWERKEY_DETAIL_FIELDS(f("encoder", self.encoder), f("counterclockwise", self.counterclockwise),
                           f("ticks", self.ticks), f("counter", self.counter), f("top", self.top));
    std::uint8_t encoder = 1;  // 1 (TPDO2) or 2 (TPDO3)
    bool counterclockwise = false;
    std::uint8_t ticks = 0;     // 0..127 since the last message
    std::uint16_t counter = 0;  // the tick counter, 0..65535 (or 0..TOP)
    std::uint8_t top = 0;       // 00h (none) or 02h..10h
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// TPDO4 480h + node, PKP-3500-MT section 14: the four 0..5 V inputs, each 16 bits little endian,
// 0000h..01F4h in units of 10 mV. The fields are in millivolts (0..5000, multiples of 10).
struct analog_inputs {
    POWERKEY_DETAIL_MESSAGE(analog_inputs);
    POWERKEY_DETAIL_FIELDS(f("in0_mv", self.mv[0]), f("in1_mv", self.mv[1]),
                           f("in2_mv", self.mv[2]), f("in3_mv", self.mv[3]));
    std::array<std::uint16_t, 4> mv{};
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// RPDO3 400h + node on the PKP-3500-MT (section 17): the encoder ring LEDs, 1..16 encoder 1,
// 17..32 encoder 2, as a 32-bit string in bytes 0..3 | 00h x 4.
struct encoder_leds {
    POWERKEY_DETAIL_MESSAGE(encoder_leds);
    POWERKEY_DETAIL_FIELDS(f("leds", self.leds));
    led_set leds;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// --- SDO reads and writes of the object dictionary ----------------------------------------------

// Host -> keypad, 600h + node: read an object (upload request 40h).
struct sdo_read {
    POWERKEY_DETAIL_MESSAGE(sdo_read);
    POWERKEY_DETAIL_FIELDS(f("object", self.object));
    powerkey::object object = powerkey::object::keys;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// Keypad -> host, 580h + node: the value read (expedited upload response 43h/47h/4Bh/4Fh).
struct sdo_read_reply {
    POWERKEY_DETAIL_MESSAGE(sdo_read_reply);
    POWERKEY_DETAIL_FIELDS(f("object", self.object), value_fields(self.object, self.value, f));
    powerkey::object object = powerkey::object::keys;
    object_value value;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// Host -> keypad, 600h + node: write an object (expedited download 23h/27h/2Bh/2Fh).
struct sdo_write {
    POWERKEY_DETAIL_MESSAGE(sdo_write);
    POWERKEY_DETAIL_FIELDS(f("object", self.object), value_fields(self.object, self.value, f));
    powerkey::object object = powerkey::object::led_brightness;
    object_value value;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// Keypad -> host, 580h + node: a write was done (60h); the manuals' "command accepted".
struct sdo_write_reply {
    POWERKEY_DETAIL_MESSAGE(sdo_write_reply);
    POWERKEY_DETAIL_FIELDS(f("object", self.object));
    powerkey::object object = powerkey::object::led_brightness;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// Every frame any keypad speaks or hears, in CANopen and in J1939.
using message =
    std::variant<canopen::nmt_message, canopen::sync_message, canopen::heartbeat_message,
                 j1939::switch_to_canopen, key_state, led_on, led_blink, led_brightness, backlight,
                 sdo_read, sdo_read_reply, sdo_write, sdo_write_reply, command,
                 canopen::sdo_upload_initiate_response, canopen::sdo_segment_request,
                 canopen::sdo_segment_response, canopen::sdo_abort_request,
                 canopen::sdo_abort_response, encoder_state, analog_inputs, encoder_leds,
                 j1939::key_contact, j1939::heartbeat, j1939::software_revision, j1939::led_ack,
                 j1939::led_ack_code, j1939::address_claimed, j1939::set_led, j1939::set_led_code,
                 j1939::multiple_leds, j1939::command>;

// A J1939 frame of the keypads: its message in the one vocabulary.
[[nodiscard]] constexpr message to_message(const j1939::message& msg) noexcept {
    return std::visit([](const auto& v) { return message{v}; }, msg);
}

// How msg's frame was written (docs/decoder.md, "Tolerant and strict reading"); a J1939 message
// without `form` always has the manual's.
[[nodiscard]] constexpr frame_form form_of(const message& msg) noexcept {
    return std::visit(
        [](const auto& s) {
            if constexpr (requires { s.form; })
                return s.form;
            else
                return frame_form::manual;
        },
        msg);
}

namespace detail {
// msg with its form set to `form` (a J1939 message without `form` unchanged).
constexpr message with_form(message msg, frame_form form) noexcept {
    std::visit(
        [form](auto& s) {
            if constexpr (requires { s.form; }) s.form = form;
        },
        msg);
    return msg;
}
}  // namespace detail

}  // namespace powerkey

#endif  // POWERKEY_KEYPAD_MESSAGES_HPP
