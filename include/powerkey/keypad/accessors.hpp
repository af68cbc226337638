// powerkey: the common questions, answered from whichever frame carries the answer. Each takes
// any decoded message and returns the fact when this message states it, nullopt otherwise:
//
//   if (const auto m = decode(f, node, model::pkp2400))
//       if (const auto keys = pressed_keys(*m); keys && keys->contains(3)) ...
//
//   pressed_keys     key-state PDO, or a read reply of `keys` (2000h sub 1, 6000h)
//   led_on_map       LED-on PDO, a write or read reply of the LED-on objects (PKP 6001h, PK1000
//   led_blink_map    2001h sub 1/2 per colour): the map, and which planes this frame sets
//   brightness       LED brightness PDO, a write or read reply of `led_brightness`, command 02h
//   backlight_of     backlight PDO, writes and read replies of the backlight objects, commands
//                    03h and 04h: the level and/or the colour the frame sets
//   node_id_change   a write of `node_id` (2013h) or command 70h
//   nmt_state_of     a heartbeat or boot-up message
// The "default_..." objects and commands set what the keypad shows after the next power on, not
// now, so they answer none of these.
#ifndef POWERKEY_KEYPAD_ACCESSORS_HPP
#define POWERKEY_KEYPAD_ACCESSORS_HPP

#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/messages.hpp>

#include <cstdint>
#include <optional>
#include <variant>

namespace powerkey {

[[nodiscard]] constexpr std::optional<key_set> pressed_keys(const message& m) noexcept {
    if (const auto* k = std::get_if<key_state>(&m)) return k->keys;
    if (const auto* r = std::get_if<sdo_read_reply>(&m); r && r->object == object::keys)
        return key_set::from_mask(r->value.raw);
    return std::nullopt;
}

// An LED map a frame carries, and the planes it sets (bit 0 red, 1 green, 2 blue): a PK1000
// register sets one plane, a PKP-2600's 6001h two, a PDO all the model has.
struct led_map_update {
    leds map;
    std::uint8_t planes = 0;
    friend constexpr bool operator==(const led_map_update&, const led_map_update&) noexcept = default;
};

namespace detail {
constexpr std::optional<led_map_update> map_of_object(object id, const object_value& v, object whole,
                                                      object red, object green) noexcept {
    if (id == whole) return led_map_update{v.map, 7};
    if (id == red) return led_map_update{v.map, 1};
    if (id == green) return led_map_update{v.map, 2};
    return std::nullopt;
}
template <class Pdo>
constexpr std::optional<led_map_update> led_map_of(const message& m, object whole, object red,
                                                   object green) noexcept {
    if (const auto* p = std::get_if<Pdo>(&m)) return led_map_update{p->map, 7};
    if (const auto* w = std::get_if<sdo_write>(&m))
        return map_of_object(w->object, w->value, whole, red, green);
    if (const auto* r = std::get_if<sdo_read_reply>(&m))
        return map_of_object(r->object, r->value, whole, red, green);
    return std::nullopt;
}
}  // namespace detail

[[nodiscard]] constexpr std::optional<led_map_update> led_on_map(const message& m) noexcept {
    return detail::led_map_of<led_on>(m, object::led_on, object::led_on_red, object::led_on_green);
}
[[nodiscard]] constexpr std::optional<led_map_update> led_blink_map(const message& m) noexcept {
    return detail::led_map_of<led_blink>(m, object::led_blink, object::led_blink_red,
                                         object::led_blink_green);
}

[[nodiscard]] constexpr std::optional<level> brightness(const message& m) noexcept {
    if (const auto* p = std::get_if<led_brightness>(&m)) return p->level;
    auto of = [](object o, const object_value& v) -> std::optional<level> {
        if (o != object::led_brightness) return std::nullopt;
        return level::make(v.raw).value_or(level{});
    };
    if (const auto* w = std::get_if<sdo_write>(&m)) return of(w->object, w->value);
    if (const auto* r = std::get_if<sdo_read_reply>(&m)) return of(r->object, r->value);
    if (const auto* c = std::get_if<command>(&m); c && c->code == command_code::set_led_brightness)
        return c->level;
    return std::nullopt;
}

// What a frame sets of the backlight: its level, its colour, or both.
struct backlight_update {
    std::optional<powerkey::level> level;
    std::optional<backlight_colour> colour;
    friend constexpr bool operator==(const backlight_update&,
                                     const backlight_update&) noexcept = default;
};

[[nodiscard]] constexpr std::optional<backlight_update> backlight_of(const message& m) noexcept {
    if (const auto* p = std::get_if<backlight>(&m)) {
        backlight_update u{p->level, std::nullopt};
        if (p->colour != backlight_colour::keep) u.colour = p->colour;
        return u;
    }
    auto of = [](object o, const object_value& v) -> std::optional<backlight_update> {
        if (o == object::backlight_level)
            return backlight_update{level::make(v.raw).value_or(level{}), std::nullopt};
        if (o == object::backlight_colour)
            return backlight_update{std::nullopt, static_cast<backlight_colour>(v.raw)};
        return std::nullopt;
    };
    if (const auto* w = std::get_if<sdo_write>(&m)) return of(w->object, w->value);
    if (const auto* r = std::get_if<sdo_read_reply>(&m)) return of(r->object, r->value);
    if (const auto* c = std::get_if<command>(&m)) {
        if (c->code == command_code::set_backlight_level)
            return backlight_update{c->level, std::nullopt};
        if (c->code == command_code::set_backlight_colour)
            return backlight_update{std::nullopt, c->colour};
    }
    return std::nullopt;
}

// The node id a message moves the keypad to (a write of 2013h, PKP command 70h), if it does.
[[nodiscard]] constexpr std::optional<canopen::node_id> node_id_change(const message& m) noexcept {
    if (const auto* w = std::get_if<sdo_write>(&m); w && w->object == object::node_id)
        return canopen::node_id::make(w->value.raw).value_or(canopen::default_node_id);
    if (const auto* c = std::get_if<command>(&m); c && c->code == command_code::set_node_id)
        return c->node_id;
    return std::nullopt;
}

[[nodiscard]] constexpr std::optional<canopen::nmt_state> nmt_state_of(const message& m) noexcept {
    if (const auto* h = std::get_if<canopen::heartbeat_message>(&m)) return h->state;
    return std::nullopt;
}

}  // namespace powerkey

#endif  // POWERKEY_KEYPAD_ACCESSORS_HPP
