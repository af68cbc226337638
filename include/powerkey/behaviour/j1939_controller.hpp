// powerkey: the host side of one keypad in J1939, as a state machine the caller steps, like the
// CANopen controller (behaviour/controller.hpp) and with its events. It owns no clock and does no
// I/O: the caller hands it each received frame and the time, drains the frames it sends, and
// polls its events. No heap, no exceptions, no callbacks.
//
//   j1939_controller<> c(cfg);                         // cfg: model, keypad address, settings ...
//   for (;;) {
//       if (const auto f = can_receive()) c.step(*f, now()); else c.tick(now());
//       while (const auto out = c.next_frame()) can_send(*out);
//       while (const auto e = c.poll()) handle(*e);    // key_pressed, lost, ready ...
//       c.set_led(3, j1939::led_colour::green);        // sent when it changes, refreshed, resent
//   }
//
// What it does (the PKP1600SI and PKP2600SI J1939 manuals' sections; docs/controller.md#j1939):
//   - finds the keypad by any frame from its address, or by asking its software revision (2Ah,
//     section 11: the one J1939 request with an answer) while searching;
//   - sends its start-up settings, then the caller's command list, to the keypad's address: the
//     heartbeat (75h, section 21) that tells it the keypad is there, the address claim at boot
//     (74h, section 20) that tells it the keypad restarted (J1939 has no boot-up message);
//   - keeps a shadow of the LEDs (01h, section 7a), the LED brightness (02h) and the backlight
//     level (03h) and colour (7Dh), sends what changes, refreshes the LEDs periodically and sends
//     everything again after the keypad restarted;
//   - reports a lost keypad when nothing came from its address for longer than configured;
//   - turns key contact states (section 6) and heartbeats (section 21) into key events: press,
//     release, long press and repeat;
//   - moves the keypad to another address (70h, section 16) and follows it there.
// Only frames the model's J1939 row has are sent (keypad/j1939_models.hpp): a model whose LED
// command is unknown (the PK1000) gets none.
#ifndef POWERKEY_BEHAVIOUR_J1939_CONTROLLER_HPP
#define POWERKEY_BEHAVIOUR_J1939_CONTROLLER_HPP

#include <powerkey/behaviour/clock.hpp>
#include <powerkey/behaviour/controller.hpp>
#include <powerkey/behaviour/key_timing.hpp>
#include <powerkey/can/frame.hpp>
#include <powerkey/keypad/j1939_codec.hpp>
#include <powerkey/keypad/j1939_messages.hpp>
#include <powerkey/keypad/j1939_models.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/keypad/values.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <variant>

namespace powerkey::behaviour {

struct j1939_controller_config {
    model keypad_model = model::pkp1600si;
    std::uint8_t keypad_address = j1939::keypad_default_address;  // 70h's; 21h at delivery
    std::uint8_t own_address = 0x00;  // the source address of its commands (the manuals' 00h)
    // Sent in order after the start-up settings, after the keypad is found and again after each
    // restart. Caller-owned.
    std::span<const j1939::command> configuration{};
    duration_ms keypad_heartbeat{200};  // 75h period (50..2540 ms, 10 ms steps); 0: leave 75h
    bool claim_at_boot = true;          // 74h 01h: each restart of the keypad announces itself
    duration_ms lost_after{600};        // silence that makes the keypad lost; 0: never lost
    duration_ms probe_period{1000};     // 2Ah to the keypad while searching; 0: off
    duration_ms refresh_period{1000};   // resend the LEDs this often; 0: only on change
    duration_ms long_press{800};        // held this long: key_long_press (once); 0: off
    duration_ms repeat_delay{500};      // held this long: the first key_repeat; 0: no repeats
    duration_ms repeat_period{200};     // then every repeat_period
};

template <std::size_t OutboxCapacity = 8, std::size_t EventCapacity = default_event_capacity>
class j1939_controller {
public:
    constexpr explicit j1939_controller(const j1939_controller_config& c) noexcept
        : cfg_(c),
          row_(j1939::row(c.keypad_model).value_or(j1939::model_row{})),
          address_(c.keypad_address) {}

    // --- driving it -------------------------------------------------------------------------

    // A frame received from the bus at `now` (any frame: the controller picks its keypad's).
    constexpr void step(const can::frame& f, millis now) noexcept {
        now_ = now;
        if (f.is_extended() && (f.raw_id() & 0xFFu) == address_) on_frame(f);
        run();
    }
    // Time passed without a frame: timers (lost, probe, refresh, long press, repeat).
    constexpr void tick(millis now) noexcept {
        now_ = now;
        run();
    }
    [[nodiscard]] constexpr std::optional<can::frame> next_frame() noexcept {
        return outbox_.pop();
    }
    [[nodiscard]] constexpr std::optional<controller_event> poll() noexcept {
        return events_.pop();
    }
    [[nodiscard]] constexpr std::size_t events_dropped() const noexcept {
        return events_.dropped();
    }

    // --- what the application shows ---------------------------------------------------------

    // LED k (one the model's LED command addresses) in colour c: on, blinking, or alternating
    // with `secondary` (section 7a). False (nothing changed) for an LED the model lacks, a model
    // without a known LED command, or a look the command cannot carry.
    constexpr bool set_led(unsigned k, j1939::led_colour c, led_mode mode = led_mode::on,
                           j1939::led_colour secondary = j1939::led_colour::off) noexcept {
        if (!row_.frames.has(j1939::feature::led_command) || row_.form != j1939::led_form::si ||
            k < 1 || k > 16 || ((row_.leds >> (k - 1)) & 1u) == 0)
            return false;
        const auto s = static_cast<std::uint8_t>(secondary);
        if (static_cast<std::uint8_t>(c) > 9 || (s > 9 && secondary != j1939::led_colour::not_used))
            return false;
        const j1939::led_look look{mode, c, secondary, true};
        if (!(wanted_[k - 1] == look)) dirty_leds_ |= bit(k);
        wanted_[k - 1] = look;
        return true;
    }
    constexpr void set_brightness(level l) noexcept {
        if (!brightness_ || !(*brightness_ == l)) dirty_ |= dirty_brightness;
        brightness_ = l;
    }
    // The backlight level, and its colour (keep: leave the keypad's). The colour goes by 7Dh,
    // the keypad's stored default (the J1939 manuals have no other colour command): it is sent
    // when it changes only, not at each refresh.
    constexpr void set_backlight(level l, backlight_colour c = backlight_colour::keep) noexcept {
        if (!backlight_ || !(*backlight_ == l)) dirty_ |= dirty_level;
        if (c != backlight_colour::keep && c != colour_) dirty_ |= dirty_colour;
        backlight_ = l;
        if (c != backlight_colour::keep) colour_ = c;
    }
    // Move the keypad to source address a (70h, section 16: 01h..FDh), after the setup.
    constexpr void change_address(std::uint8_t a) noexcept { pending_address_ = a; }

    // --- what it knows ----------------------------------------------------------------------

    [[nodiscard]] constexpr controller_state state() const noexcept { return state_; }
    [[nodiscard]] constexpr std::uint8_t address() const noexcept { return address_; }
    [[nodiscard]] constexpr powerkey::model model() const noexcept { return cfg_.keypad_model; }
    [[nodiscard]] constexpr key_set keys() const noexcept { return keys_.held(); }
    [[nodiscard]] constexpr j1939::led_look led(unsigned k) const noexcept {
        return k >= 1 && k <= 16 ? wanted_[k - 1] : j1939::led_look{};
    }

private:
    static constexpr std::uint8_t dirty_brightness = 1, dirty_level = 2, dirty_colour = 4;
    static constexpr std::uint16_t bit(unsigned k) noexcept {
        return static_cast<std::uint16_t>(1u << (k - 1));
    }

    constexpr void emit(event_kind k, unsigned key = 0) noexcept {
        controller_event e{k};
        e.key = static_cast<std::uint8_t>(key);
        (void)events_.push(e);
    }

    // --- received frames --------------------------------------------------------------------

    constexpr void on_frame(const can::frame& f) noexcept {
        const auto m = j1939::decode(f, cfg_.keypad_model, address_);
        if (!m) return;
        const bool claim = std::holds_alternative<j1939::address_claimed>(*m);
        const auto* contact = std::get_if<j1939::key_contact>(&*m);
        const auto* beat = std::get_if<j1939::heartbeat>(&*m);
        if (!claim && contact == nullptr && beat == nullptr &&
            !std::holds_alternative<j1939::software_revision>(*m) &&
            !std::holds_alternative<j1939::led_ack>(*m))
            return;  // a command to the keypad from its own address: not the keypad's
        last_heard_ = now_;
        if (state_ == controller_state::searching) {
            emit(event_kind::found);
            begin_setup();
        } else if (claim) {  // section 20: its claim at start-up, so it restarted
            emit(event_kind::rebooted);
            release_all();
            begin_setup();
        }
        if (contact != nullptr) {
            key_set s = keys_.held();
            if (contact->pressed)
                s.insert(contact->key);
            else
                s.erase(contact->key);
            on_keys(s);
        } else if (beat != nullptr) {
            on_keys(beat->keys);
        }
    }

    // --- keys (as the CANopen controller's) ------------------------------------------------

    constexpr void on_keys(key_set now_pressed) noexcept {
        keys_.update(key_set::from_mask(now_pressed.mask() & powerkey::detail::low_bits(row_.keys)),
                     row_.keys, now_, cfg_, [this](event_kind k, unsigned key) { emit(k, key); });
    }
    constexpr void key_timers() noexcept {
        keys_.tick(row_.keys, now_, cfg_, [this](event_kind k, unsigned key) { emit(k, key); });
    }
    constexpr void release_all() noexcept { on_keys(key_set{}); }

    // --- the time-driven part ---------------------------------------------------------------

    constexpr void run() noexcept {
        if (state_ != controller_state::searching &&
            silent_for_longer(last_heard_, now_, cfg_.lost_after)) {
            emit(event_kind::lost);
            release_all();
            state_ = controller_state::searching;
            next_probe_ = now_;
        }
        if (state_ == controller_state::searching) probe();
        if (state_ == controller_state::setting_up) setup();
        if (state_ == controller_state::running) {
            send_address_change();
            send_shadow();
            key_timers();
        }
    }

    constexpr void probe() noexcept {
        if (cfg_.probe_period.value == 0 || !reached(next_probe_, now_)) return;
        next_probe_ = now_ + cfg_.probe_period;
        j1939::command c = to_keypad();
        c.code = j1939::command_code::get_software_revision;
        (void)send(c);
    }

    constexpr void begin_setup() noexcept {
        state_ = controller_state::setting_up;
        setup_pos_ = 0;
    }

    // The start-up settings, then the list, as fast as the outbox takes them (no command has a
    // reply to wait for); then ready, and the whole picture.
    constexpr void setup() noexcept {
        using cc = j1939::command_code;
        while (true) {
            j1939::command c = to_keypad();
            if (setup_pos_ == 0) {
                const std::uint32_t p = cfg_.keypad_heartbeat.value / 10u;
                if (p == 0) {
                    ++setup_pos_;
                    continue;
                }
                c.code = cc::set_heartbeat;
                c.enabled = true;
                c.period_10ms = static_cast<std::uint8_t>(p < 5 ? 5 : p > 0xFE ? 0xFE : p);
            } else if (setup_pos_ == 1) {
                if (!cfg_.claim_at_boot) {
                    ++setup_pos_;
                    continue;
                }
                c.code = cc::set_address_claim_at_boot;
                c.enabled = true;
            } else if (setup_pos_ - 2u < cfg_.configuration.size()) {
                c = cfg_.configuration[setup_pos_ - 2u];
                c.destination = address_;
                c.source = cfg_.own_address;
            } else {
                break;
            }
            if (!send(c)) return;  // the outbox is full: the rest at the next call
            ++setup_pos_;
        }
        state_ = controller_state::running;
        emit(event_kind::ready);
        dirty_leds_ = row_.leds;
        dirty_ |= dirty_brightness | dirty_level;  // the colour is stored: only on change
        next_refresh_ = now_ + cfg_.refresh_period;
    }

    constexpr void send_address_change() noexcept {
        if (!pending_address_) return;
        j1939::command c = to_keypad();
        c.code = j1939::command_code::set_source_address;
        c.address = *pending_address_;
        c.identifier = 0xFF;  // no change
        if (!send(c)) return;
        pending_address_.reset();
        address_ = c.address;  // it answers at the new address at once (section 16)
        emit(event_kind::node_changed);
    }

    constexpr void send_shadow() noexcept {
        if (cfg_.refresh_period.value != 0 && reached(next_refresh_, now_)) {
            dirty_leds_ = row_.leds;
            next_refresh_ = now_ + cfg_.refresh_period;
        }
        for (unsigned k = 1; k <= 16 && dirty_leds_ != 0; ++k) {
            if ((dirty_leds_ & bit(k)) == 0) continue;
            if ((row_.leds & bit(k)) != 0 && row_.frames.has(j1939::feature::led_command)) {
                const j1939::led_look& l = wanted_[k - 1];
                const j1939::set_led m{.source = cfg_.own_address,
                                       .destination = address_,
                                       .priority = 6,
                                       .key = static_cast<std::uint8_t>(k),
                                       .colour = l.colour,
                                       .mode = l.mode,
                                       .secondary = l.secondary};
                if (!send(m)) return;
            }
            dirty_leds_ = static_cast<std::uint16_t>(dirty_leds_ & ~bit(k));
        }
        using cc = j1939::command_code;
        if (!send_level(dirty_brightness, cc::set_led_brightness, brightness_) ||
            !send_level(dirty_level, cc::set_backlight_level, backlight_) ||
            (dirty_ & dirty_colour) == 0)
            return;
        j1939::command c = to_keypad();
        c.code = cc::set_default_backlight_colour;
        c.colour = colour_;
        if (send(c)) dirty_ = static_cast<std::uint8_t>(dirty_ & ~dirty_colour);
    }
    // A level whose dirty bit is set, sent by `code` when there is one; false when the outbox is
    // full (the bit stays: sent at the next call).
    constexpr bool send_level(std::uint8_t bit, j1939::command_code code,
                              const std::optional<level>& l) noexcept {
        if ((dirty_ & bit) == 0) return true;
        if (l) {
            j1939::command c = to_keypad();
            c.code = code;
            c.level = *l;
            if (!send(c)) return false;
        }
        dirty_ = static_cast<std::uint8_t>(dirty_ & ~bit);
        return true;
    }

    constexpr j1939::command to_keypad() const noexcept {
        j1939::command c;
        c.destination = address_;
        c.source = cfg_.own_address;
        return c;
    }
    // False when the outbox is full (tried again later); true, and nothing sent, for a message
    // the model's J1939 row does not have (never retried).
    template <class T>
    constexpr bool send(const T& m) noexcept {
        const auto f = j1939::encode(cfg_.keypad_model, m, address_);
        if (!f) return true;
        return outbox_.push(*f);
    }

    j1939_controller_config cfg_;
    j1939::model_row row_;
    std::uint8_t address_;
    controller_state state_ = controller_state::searching;
    millis now_{};
    millis last_heard_{};
    millis next_probe_{};
    millis next_refresh_{};
    std::size_t setup_pos_ = 0;
    std::optional<std::uint8_t> pending_address_;

    std::array<j1939::led_look, 16> wanted_{};
    std::uint16_t dirty_leds_ = 0;
    std::optional<level> brightness_;
    std::optional<level> backlight_;
    backlight_colour colour_ = backlight_colour::keep;
    std::uint8_t dirty_ = 0;

    key_timing<event_kind> keys_{};

    frame_queue<OutboxCapacity> outbox_{};
    fixed_queue<controller_event, EventCapacity> events_{};
};

}  // namespace powerkey::behaviour

#endif  // POWERKEY_BEHAVIOUR_J1939_CONTROLLER_HPP
