// powerkey: the common questions, answered from whichever frame carries the answer: each takes
// any decoded message and returns the fact when it states it, nullopt otherwise (docs/decoder.md,
// "Accessors": which frames answer each).
#ifndef POWERKEY_KEYPAD_ACCESSORS_HPP
#define POWERKEY_KEYPAD_ACCESSORS_HPP

#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/detail/bytes.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/messages.hpp>

#include <cstdint>
#include <optional>
#include <variant>

namespace powerkey {

// The keys a frame says are pressed (a J1939 key contact state: its one key, or none).
[[nodiscard]] constexpr std::optional<key_set> pressed_keys(const message& msg) noexcept {
    if (const auto* k = std::get_if<key_state>(&msg)) return k->keys;
    if (const auto* r = std::get_if<sdo_read_reply>(&msg); r && r->object == object::keys)
        return key_set::from_mask(r->value.raw);
    if (const auto* h = std::get_if<j1939::heartbeat>(&msg)) return h->keys;
    if (const auto* c = std::get_if<j1939::key_contact>(&msg)) {
        key_set s;
        if (c->pressed) s.insert(c->key);
        return s;
    }
    return std::nullopt;
}

// The keys a frame states (`covered`) and which of them are pressed.
struct key_update {
    key_set pressed;
    key_set covered;
    friend constexpr bool operator==(const key_update&, const key_update&) noexcept = default;
};

[[nodiscard]] constexpr std::optional<key_update> key_change(const message& msg, model m) noexcept {
    const auto keys = pressed_keys(msg);
    if (!keys) return std::nullopt;
    key_set covered;
    if (const auto* c = std::get_if<j1939::key_contact>(&msg)) {
        covered.insert(c->key);
    } else if (const auto keypad = info(m)) {
        for (unsigned k = 1; k <= keypad->keys; ++k) covered.insert(k);
    }
    return key_update{*keys, covered};
}

// An LED map a frame carries: `map`, and `covered`, the LEDs whose state the frame states.
struct led_map_update {
    leds map;
    leds covered;
    friend constexpr bool operator==(const led_map_update&,
                                     const led_map_update&) noexcept = default;
};

namespace detail {
// The carriers of one map: its PDO type and its objects (whole, per plane, pieces).
struct led_objects {
    object whole, red, green, blue, part1, part2, part3;
};
inline constexpr led_objects on_objects{
    object::led_on,      object::led_on_red,        object::led_on_green,
    object::led_on_blue, object::led_on_r1_12_g1_4, object::led_on_g5_12,
    object::led_on_b1_12};
inline constexpr led_objects blink_objects{
    object::led_blink,      object::led_blink_red,        object::led_blink_green,
    object::led_blink_blue, object::led_blink_r1_12_g1_4, object::led_blink_g5_12,
    object::led_blink_b1_12};

constexpr std::optional<led_map_update> map_of_object(const model_info& keypad, object id,
                                                      const object_value& v,
                                                      const led_objects& o) noexcept {
    if (id != o.whole && id != o.red && id != o.green && id != o.blue && id != o.part1 &&
        id != o.part2 && id != o.part3)
        return std::nullopt;
    const auto row = detail::find_codec_row(keypad.dictionary, id);
    if (row == 0) return std::nullopt;
    const auto& r = detail::codec_rows[row];
    const auto& layout = detail::layout(keypad.id);
    return visit_kind(r.kind, [&](auto k) -> std::optional<led_map_update> {
        return led_map_update{v.map, decltype(k)::covered(layout, r)};
    });
}
template <class Pdo>
constexpr std::optional<led_map_update> led_map_of(const message& msg, model m,
                                                   const led_objects& o) noexcept {
    const auto keypad = info(m);
    if (!keypad) return std::nullopt;
    if (const auto* p = std::get_if<Pdo>(&msg))
        return led_map_update{p->map, planes_of(layout(m), 0, keypad->planes)};
    if (const auto* w = std::get_if<sdo_write>(&msg))
        return map_of_object(*keypad, w->object, w->value, o);
    if (const auto* r = std::get_if<sdo_read_reply>(&msg))
        return map_of_object(*keypad, r->object, r->value, o);
    return std::nullopt;
}
}  // namespace detail

// The LED-on (LED-blink) map a message of model m states, if it states one.
[[nodiscard]] constexpr std::optional<led_map_update> led_on_map(const message& msg,
                                                                 model m) noexcept {
    return detail::led_map_of<led_on>(msg, m, detail::on_objects);
}
[[nodiscard]] constexpr std::optional<led_map_update> led_blink_map(const message& msg,
                                                                    model m) noexcept {
    return detail::led_map_of<led_blink>(msg, m, detail::blink_objects);
}

[[nodiscard]] constexpr std::optional<level> led_brightness_level(const message& msg) noexcept {
    if (const auto* p = std::get_if<led_brightness>(&msg)) return p->level;
    auto of = [](object o, const object_value& v) -> std::optional<level> {
        if (o != object::led_brightness) return std::nullopt;
        return level::make(v.raw).value_or(level{});
    };
    if (const auto* w = std::get_if<sdo_write>(&msg)) return of(w->object, w->value);
    if (const auto* r = std::get_if<sdo_read_reply>(&msg)) return of(r->object, r->value);
    if (const auto* c = std::get_if<command>(&msg);
        c && c->code == command_code::set_led_brightness)
        return c->level;
    if (const auto* c = std::get_if<j1939::command>(&msg);
        c && c->code == j1939::command_code::set_led_brightness)
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

[[nodiscard]] constexpr std::optional<backlight_update> backlight_change(
    const message& msg) noexcept {
    if (const auto* p = std::get_if<backlight>(&msg)) {
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
    if (const auto* w = std::get_if<sdo_write>(&msg)) return of(w->object, w->value);
    if (const auto* r = std::get_if<sdo_read_reply>(&msg)) return of(r->object, r->value);
    if (const auto* c = std::get_if<command>(&msg)) {
        if (c->code == command_code::set_backlight_level)
            return backlight_update{c->level, std::nullopt};
        if (c->code == command_code::set_backlight_colour)
            return backlight_update{std::nullopt, c->colour};
    }
    if (const auto* c = std::get_if<j1939::command>(&msg);
        c && c->code == j1939::command_code::set_backlight_level)
        return backlight_update{c->level, std::nullopt};
    return std::nullopt;
}

// The node id a message moves the keypad to (a write of 2013h, PKP command 70h), if it does.
[[nodiscard]] constexpr std::optional<canopen::node_id> node_id_change(
    const message& msg) noexcept {
    if (const auto* w = std::get_if<sdo_write>(&msg); w && w->object == object::node_id)
        return canopen::node_id::make(w->value.raw).value_or(canopen::default_node_id);
    if (const auto* c = std::get_if<command>(&msg); c && c->code == command_code::set_node_id)
        return c->node_id;
    return std::nullopt;
}

// The J1939 source address a message moves the keypad to (command 70h; FFh keeps it), if any.
[[nodiscard]] constexpr std::optional<std::uint8_t> address_change(const message& msg) noexcept {
    if (const auto* c = std::get_if<j1939::command>(&msg);
        c && c->code == j1939::command_code::set_source_address && c->address != 0xFF)
        return c->address;
    return std::nullopt;
}

[[nodiscard]] constexpr std::optional<canopen::nmt_state> reported_nmt_state(
    const message& msg) noexcept {
    if (const auto* h = std::get_if<canopen::heartbeat_message>(&msg)) return h->state;
    return std::nullopt;
}

}  // namespace powerkey

#endif  // POWERKEY_KEYPAD_ACCESSORS_HPP
