// powerkey: the J1939 side of the virtual keypad (behaviour/virtual_keypad.hpp), after a switch
// to J1939 (20FFh) and until the switch back (80h), as the PKP1600SI and PKP2600SI J1939 manuals
// describe it: the address claim at power-up (74h), the key contact state on key events (72h)
// and periodically (71h, 77h), the heartbeat (75h, F9h), the LED commands (01h, and A700h/A600h
// after 37h) with their acknowledgement (73h), the levels (02h, 03h), the software revision
// (2Ah), the address change (70h) and the stored settings. Every frame it hears and sends goes
// through the J1939 codec (keypad/j1939_codec.hpp) with the model's J1939 row, so a frame no
// source shows on the model is neither heard nor sent. docs/virtual-keypad.md#j1939 lists what it
// does, section by section, and what is inferred.
//
// A keypad sold as a J1939 one starts here at power-on, on every model whose J1939 key contact
// state a source shows (speaks_j1939): the LI models too, whose CANopen side has no switch; they
// speak the frames their J1939 row covers, the LED command and acknowledgement in the LI (code)
// form, and, their 80h unknown to the codec, never switch back.
//
// It owns no outbox: each call that may send takes the caller's `send(const can::frame&)`.
#ifndef POWERKEY_BEHAVIOUR_J1939_KEYPAD_HPP
#define POWERKEY_BEHAVIOUR_J1939_KEYPAD_HPP

#include <powerkey/behaviour/clock.hpp>
#include <powerkey/bounded.hpp>
#include <powerkey/can/frame.hpp>
#include <powerkey/j1939/id.hpp>
#include <powerkey/j1939/name.hpp>
#include <powerkey/keypad/j1939_codec.hpp>
#include <powerkey/keypad/j1939_messages.hpp>
#include <powerkey/keypad/j1939_models.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/keypad/values.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <variant>

namespace powerkey::behaviour {

struct j1939_source_address_tag;
// An address a keypad may hold, as 70h takes it (section 16): 01h..FDh (FEh is J1939's null
// address, FFh the global one, and 70h refuses 00h).
using j1939_source_address = bounded<j1939_source_address_tag, std::uint8_t, 1, 0xFD>;

// A keypad of model m may be a J1939 keypad from power-on (every PowerKey keypad is
// sold in a CANopen and a J1939 version): its J1939 key contact state is documented or inferred
// (docs/j1939.md), whether or not its CANopen side has the switch (20FFh).
[[nodiscard]] constexpr bool speaks_j1939(powerkey::model m) noexcept {
    const auto r = j1939::row(m);
    return r && r->frames.has(j1939::feature::key_contact);
}

// The keypad's J1939 settings, at the defaults of section 5. All are stored (the manuals'
// "changes take effect immediately and are stored in non-volatile memory"): they survive a power
// cycle and a switch to CANopen and back, except the bit rate, which a switch sets to the J1939
// default (one PKP-2200-SI, docs/j1939.md).
struct j1939_settings {
    std::uint8_t address = j1939::keypad_default_address;       // 70h byte 3
    std::uint8_t identifier = j1939::keypad_default_address;    // 70h byte 4
    std::uint8_t destination = j1939::global_address;           // 6Eh: of the key contact state
    baud_rate baud = baud_rate::kbit_250;                       // 6Fh
    bool heartbeat = false;                                     // 75h byte 3
    std::uint8_t heartbeat_10ms = 0xFF;                         // 75h byte 4
    bool periodic = false;                                      // 71h
    std::uint8_t key_period_10ms = 0x0A;                        // 77h: 100 ms
    bool events = true;                                         // 72h
    bool led_ack = false;                                       // 73h
    bool address_claim = false;                                 // 74h
    bool startup_keys = false;                                  // 28h
    bool multiple_leds = false;                                 // 37h 02h
    startup_show show = startup_show::complete;                 // 34h (stored, not shown)
    bool demo = false;                                          // 7Ah (stored, not shown)
    powerkey::level default_brightness = 0x3F;                  // 7Ch
    powerkey::level default_backlight = 0;                      // 7Bh
    backlight_colour default_colour = backlight_colour::amber;  // 7Dh
    friend constexpr bool operator==(const j1939_settings&,
                                     const j1939_settings&) noexcept = default;
};

// The NAME of the manuals' address claim (section 20): 18EEFF21#3F426F1A00823CC0.
inline constexpr j1939::name keypad_name = {.identity_number = 999999,
                                            .manufacturer_code = 211,
                                            .ecu_instance = 0,
                                            .function_instance = 0,
                                            .function = 0x82,
                                            .vehicle_system = 30,
                                            .vehicle_system_instance = 0,
                                            .industry_group = 4,
                                            .arbitrary_address_capable = true};
// The answer to 2Ah: "V2.10", the PKP1600SI manual's example (section 11); the PKP2600SI manual
// prints "V2.XX". Every model answers it (inferred).
inline constexpr std::array<std::uint8_t, 5> keypad_revision = {'V', '2', '.', '1', '0'};
// How long the keypad waits after its address claim before it has claimed the address (section
// 20: "waits up to 250 ms").
inline constexpr duration_ms address_claim_wait{250};

class j1939_keypad {
public:
    enum class heard : std::uint8_t { nothing, to_canopen };

    // A keypad of model m whose J1939 address is `address` until a 70h moves it (its
    // identifier, 70h byte 4, stays 21h).
    constexpr explicit j1939_keypad(
        powerkey::model m,
        j1939_source_address address = j1939_source_address{j1939::keypad_default_address}) noexcept
        : model_(m), row_(j1939::row(m).value_or(j1939::model_row{})) {
        settings_.address = address.value();
    }

    // A start in J1939: a power-up with J1939 stored, or the switch from CANopen (then at the
    // J1939 default bit rate). The run-time state starts from the stored defaults (7Bh..7Dh);
    // with 74h the address claim goes out and nothing else for 250 ms.
    template <class Send>
    constexpr void boot(millis t, key_set keys, bool switched, Send&& send) noexcept {
        if (switched) settings_.baud = baud_rate::kbit_250;
        leds_ = {};
        codes_ = {};
        planes_ = {j1939::multiple_leds{}, j1939::multiple_leds{}};
        brightness_ = settings_.default_brightness;
        backlight_ = settings_.default_backlight;
        colour_ = settings_.default_colour;
        counter_ = 0;
        lost_address_ = false;
        claiming_ = settings_.address_claim && row_.frames.has(j1939::feature::address_claim);
        if (claiming_) {
            claimed_at_ = t + address_claim_wait;
            send_claim(send);
            return;
        }
        start(t, keys, send);
    }

    // A frame on the bus at t: the commands to the keypad's address, and address claims of its
    // address. to_canopen after the switch back (80h).
    template <class Send>
    constexpr heard receive(const can::frame& f, millis t, Send&& send) noexcept {
        const auto m = j1939::decode(f, model_, settings_.address);
        if (!m) return heard::nothing;
        if (const auto* c = std::get_if<j1939::address_claimed>(&*m)) {
            on_claim(*c, send);
            return heard::nothing;
        }
        if (std::holds_alternative<j1939::switch_to_canopen>(*m)) return heard::to_canopen;
        if (const auto* l = std::get_if<j1939::set_led>(&*m)) {
            set_led(l->key, {l->mode, l->colour, l->secondary, true});
            if (settings_.led_ack)
                emit(j1939::led_ack{.source = settings_.address,
                                    .destination = j1939::global_address,
                                    .priority = 6,
                                    .mode = l->mode,
                                    .key = l->key,
                                    .colour = l->colour,
                                    .secondary = l->secondary},
                     send);
        } else if (const auto* code = std::get_if<j1939::set_led_code>(&*m)) {
            // The LI form (inferred, docs/j1939.md): the code kept as it came, and repeated in
            // the LI acknowledgement.
            if (code->key >= 1 && code->key <= codes_.size()) codes_[code->key - 1u] = code->code;
            if (settings_.led_ack)
                emit(j1939::led_ack_code{.source = settings_.address,
                                         .destination = j1939::global_address,
                                         .priority = 6,
                                         .key = code->key,
                                         .code = code->code},
                     send);
        } else if (const auto* p = std::get_if<j1939::multiple_leds>(&*m)) {
            if (settings_.multiple_leds) set_planes(*p);
        } else if (const auto* c = std::get_if<j1939::command>(&*m)) {
            command(*c, t, send);
        }
        return heard::nothing;
    }

    // Runs the timers up to t: the end of the address claim, the heartbeat, the periodic key
    // state. A caller that wakes late gets one of each, not every missed one.
    template <class Send>
    constexpr void advance(millis t, key_set keys, Send&& send) noexcept {
        if (claiming_) {
            if (!reached(claimed_at_, t)) return;
            claiming_ = false;
            start(claimed_at_, keys, send);
        }
        if (lost_address_) return;
        if (heartbeat_ms() != 0 && reached(next_heartbeat_, t)) {
            send_heartbeat(keys, send);
            next_heartbeat_ = later(next_heartbeat_, heartbeat_ms(), t);
        }
        if (settings_.periodic && reached(next_periodic_, t)) {
            send_all_keys(keys, send);
            next_periodic_ = later(next_periodic_, period_ms(), t);
        }
    }

    // The keys changed from `was` to `now`: one key contact state per changed key, in key
    // order, while 72h enables it (sections 6, 18).
    template <class Send>
    constexpr void keys_changed(key_set was, key_set now, Send&& send) noexcept {
        if (!settings_.events || !sending()) return;
        for (unsigned k = 1; k <= row_.keys; ++k)
            if (was.contains(k) != now.contains(k)) send_key(k, now.contains(k), send);
    }

    // The earliest time at which advance() has something to do; nullopt when nothing is due.
    [[nodiscard]] constexpr std::optional<millis> next_due() const noexcept {
        if (claiming_) return claimed_at_;
        if (lost_address_) return std::nullopt;
        std::optional<millis> due;
        if (heartbeat_ms() != 0) due = next_heartbeat_;
        if (settings_.periodic && (!due || before(next_periodic_, *due))) due = next_periodic_;
        return due;
    }

    // --- what it shows ----------------------------------------------------------------------

    [[nodiscard]] constexpr const j1939_settings& settings() const noexcept { return settings_; }
    // The source address it sends from and answers at (70h).
    [[nodiscard]] constexpr std::uint8_t address() const noexcept { return settings_.address; }
    // LED k as the last single-LED command or the two multiple-LED frames set it (off outside
    // the model's LEDs).
    [[nodiscard]] constexpr j1939::led_look led(unsigned k) const noexcept {
        return k >= 1 && k <= leds_.size() ? leds_[k - 1] : j1939::led_look{};
    }
    // LED k's code as the last LI LED command (set_led_code) gave it: kept as it came, its table
    // being in no source (so led(k) stays off); nullopt before one since the start, or outside
    // the model's LEDs.
    [[nodiscard]] constexpr std::optional<std::uint8_t> led_code(unsigned k) const noexcept {
        return k >= 1 && k <= codes_.size() ? codes_[k - 1] : std::nullopt;
    }
    [[nodiscard]] constexpr powerkey::level brightness() const noexcept { return brightness_; }
    [[nodiscard]] constexpr powerkey::level backlight_level() const noexcept { return backlight_; }
    [[nodiscard]] constexpr backlight_colour backlight_colour_now() const noexcept {
        return colour_;
    }
    // Between the address claim and the end of its 250 ms wait.
    [[nodiscard]] constexpr bool claiming() const noexcept { return claiming_; }
    // Another device with a higher-priority NAME claimed the keypad's address: which address
    // the keypad picks then no source says; it sends nothing more until the next start.
    [[nodiscard]] constexpr bool lost_address() const noexcept { return lost_address_; }

private:
    [[nodiscard]] constexpr bool sending() const noexcept { return !claiming_ && !lost_address_; }
    [[nodiscard]] constexpr std::uint32_t heartbeat_ms() const noexcept {
        return settings_.heartbeat && settings_.heartbeat_10ms != 0xFF
                   ? std::uint32_t{settings_.heartbeat_10ms} * 10u
                   : 0u;
    }
    [[nodiscard]] constexpr std::uint32_t period_ms() const noexcept {
        return std::uint32_t{settings_.key_period_10ms} * 10u;
    }
    static constexpr millis later(millis due, std::uint32_t period, millis t) noexcept {
        const millis next = due + duration_ms{period};
        return reached(next, t) ? t + duration_ms{period} : next;
    }

    // The address is the keypad's: the start-up key states (28h) and the timers from t.
    template <class Send>
    constexpr void start(millis t, key_set keys, Send&& send) noexcept {
        next_heartbeat_ = t + duration_ms{heartbeat_ms()};
        next_periodic_ = t + duration_ms{period_ms()};
        if (settings_.startup_keys) send_all_keys(keys, send);
    }

    // An address claim of the keypad's address by another device (J1939-81, inferred: the
    // manual says only that the NAMEs are compared): the lower NAME wins. The keypad winning
    // claims again; losing, it falls silent.
    template <class Send>
    constexpr void on_claim(const j1939::address_claimed& c, Send&& send) noexcept {
        if (c.source != settings_.address || lost_address_) return;
        const std::uint64_t theirs = j1939::pack_name(c.name), ours = j1939::pack_name(keypad_name);
        if (theirs == ours) return;  // its own claim, heard back
        if (theirs < ours) {
            lost_address_ = true;
            claiming_ = false;
            return;
        }
        send_claim(send);
    }

    template <class Send>
    constexpr void command(const j1939::command& c, millis t, Send&& send) noexcept {
        using cc = j1939::command_code;
        j1939_settings& s = settings_;
        switch (c.code) {
            case cc::set_led_brightness: brightness_ = c.level; break;  // temporary (8)
            case cc::set_backlight_level: backlight_ = c.level; break;  // temporary (9)
            case cc::set_startup_keys: s.startup_keys = c.enabled; break;
            case cc::get_software_revision:
                emit(j1939::software_revision{.source = s.address,
                                              .destination = j1939::global_address,
                                              .priority = 6,
                                              .bytes = keypad_revision},
                     send);
                break;
            case cc::set_startup_show: s.show = c.show; break;
            case cc::set_led_management: s.multiple_leds = c.multiple_leds; break;
            case cc::set_destination_address: s.destination = c.address; break;
            case cc::set_baud_rate: s.baud = c.baud; break;
            case cc::set_source_address:  // FFh: no change (16)
                if (c.address != 0xFF) s.address = c.address;
                if (c.identifier != 0xFF) s.identifier = c.identifier;
                break;
            case cc::set_periodic_transmission:
                s.periodic = c.enabled;
                next_periodic_ = t + duration_ms{period_ms()};
                break;
            case cc::set_event_transmission: s.events = c.enabled; break;
            case cc::set_led_acknowledgement: s.led_ack = c.enabled; break;
            case cc::set_address_claim_at_boot: s.address_claim = c.enabled; break;
            case cc::set_heartbeat:
                s.heartbeat = c.enabled;
                s.heartbeat_10ms = c.period_10ms;
                next_heartbeat_ = t + duration_ms{heartbeat_ms()};
                break;
            case cc::set_key_period:
                s.key_period_10ms = c.period_10ms;
                next_periodic_ = t + duration_ms{period_ms()};
                break;
            case cc::set_demo_mode: s.demo = c.enabled; break;
            case cc::set_default_backlight_level: s.default_backlight = c.level; break;
            case cc::set_default_led_brightness: s.default_brightness = c.level; break;
            case cc::set_default_backlight_colour:  // at once too (inferred, docs)
                s.default_colour = c.colour;
                colour_ = c.colour;
                break;
        }
    }

    // One LED's look; the multiple-LED codes follow it, so that a later frame of one colour
    // combines with what the LED shows.
    constexpr void set_led(unsigned k, const j1939::led_look& look) noexcept {
        if (k < 1 || k > leds_.size()) return;
        leds_[k - 1] = look;
        const auto codes = j1939::codes_for(look.mode, look.colour, look.secondary);
        const j1939::code_pair p = codes.value_or(j1939::code_pair{});
        planes_[0].set(k, p.colour_1);
        planes_[1].set(k, p.colour_2);
    }
    // A multiple-LED frame (section 7b): its colour replaces that frame's codes; the other
    // colour's codes stay (inferred: not stated); each LED shows TABLE 3 of the two, and an LED
    // whose pair TABLE 3 does not define keeps its look.
    constexpr void set_planes(const j1939::multiple_leds& m) noexcept {
        planes_[m.frame.value() - 1u] = m;
        for (unsigned k = 1; k <= row_.plane_leds && k <= leds_.size(); ++k) {
            const auto look = j1939::combine(planes_[0], planes_[1], k);
            if (look.defined) leds_[k - 1] = look;
        }
    }

    // A frame of the keypad, once its address is claimed; none that the model's row lacks.
    template <class T, class Send>
    constexpr void emit(const T& msg, Send&& send) const noexcept {
        if (!sending()) return;
        if (const auto f = j1939::encode(model_, msg, settings_.address)) send(*f);
    }
    template <class Send>
    constexpr void send_claim(Send&& send) const noexcept {
        const auto f = j1939::encode(model_,
                                     j1939::address_claimed{.source = settings_.address,
                                                            .destination = j1939::global_address,
                                                            .priority = 6,
                                                            .name = keypad_name},
                                     settings_.address);
        if (f) send(*f);
    }
    template <class Send>
    constexpr void send_key(unsigned k, bool pressed, Send&& send) const noexcept {
        emit(j1939::key_contact{.source = settings_.address,
                                .destination = settings_.destination,
                                .priority = 6,
                                .key = static_cast<std::uint8_t>(k),
                                .pressed = pressed,
                                .identifier = settings_.identifier},
             send);
    }
    // One key contact state for each key of the model (sections 6, 10, 17).
    template <class Send>
    constexpr void send_all_keys(key_set keys, Send&& send) const noexcept {
        if (!sending()) return;
        for (unsigned k = 1; k <= row_.keys; ++k) send_key(k, keys.contains(k), send);
    }
    template <class Send>
    constexpr void send_heartbeat(key_set keys, Send&& send) noexcept {
        emit(j1939::heartbeat{.source = settings_.address,
                              .destination = j1939::global_address,
                              .priority = 6,
                              .counter = counter_,
                              .keys = keys,
                              .identifier = settings_.identifier},
             send);
        counter_ = static_cast<std::uint8_t>(counter_ + 1u);  // 8-bit wrap (inferred)
    }

    powerkey::model model_;
    j1939::model_row row_;
    j1939_settings settings_{};
    std::array<j1939::led_look, 16> leds_{};
    std::array<std::optional<std::uint8_t>, 16> codes_{};  // the LI form's LED codes
    std::array<j1939::multiple_leds, 2> planes_{};
    powerkey::level brightness_ = 0x3F;
    powerkey::level backlight_ = 0;
    backlight_colour colour_ = backlight_colour::amber;
    std::uint8_t counter_ = 0;
    bool claiming_ = false;
    bool lost_address_ = false;
    millis claimed_at_{};
    millis next_heartbeat_{};
    millis next_periodic_{};
};

}  // namespace powerkey::behaviour

#endif  // POWERKEY_BEHAVIOUR_J1939_KEYPAD_HPP
