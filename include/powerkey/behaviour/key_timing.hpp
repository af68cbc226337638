// powerkey: a controller's keys over time, shared by the CANopen and the J1939 controllers:
// presses, releases, long presses and repeats (docs/controller.md, "Events").
#ifndef POWERKEY_BEHAVIOUR_KEY_TIMING_HPP
#define POWERKEY_BEHAVIOUR_KEY_TIMING_HPP

#include <powerkey/behaviour/clock.hpp>
#include <powerkey/keypad/values.hpp>

#include <array>
#include <cstdint>

namespace powerkey::behaviour {

// Kind: the event enum (key_pressed, key_released, key_long_press, key_repeat). Config: any
// settings with long_press, repeat_delay and repeat_period (0: off; a repeat_period of 0 repeats
// every repeat_delay). Emit: called as emit(Kind, key) for each event.
template <class Kind>
class key_timing {
public:
    [[nodiscard]] constexpr key_set held() const noexcept { return held_; }

    // The keys held are now `now_held`: a press or release for each of keys 1..count that changed.
    template <class Config, class Emit>
    constexpr void update(key_set now_held, unsigned count, millis now, const Config& cfg,
                          Emit&& emit) noexcept {
        for (unsigned k = 1; k <= count; ++k) {
            const bool was = held_.contains(k), is = now_held.contains(k);
            if (is && !was) {
                pressed_at_[k - 1] = now;
                next_repeat_[k - 1] = now + cfg.repeat_delay;
                long_sent_ = static_cast<std::uint16_t>(long_sent_ & ~bit(k));
                emit(Kind::key_pressed, k);
            } else if (was && !is) {
                emit(Kind::key_released, k);
            }
        }
        held_ = now_held;
    }
    // Long presses and repeats due at `now` for the held keys among 1..count.
    template <class Config, class Emit>
    constexpr void tick(unsigned count, millis now, const Config& cfg, Emit&& emit) noexcept {
        for (unsigned k : held_) {
            if (k > count) continue;
            if (cfg.long_press.value != 0 && (long_sent_ & bit(k)) == 0 &&
                reached(pressed_at_[k - 1] + cfg.long_press, now)) {
                long_sent_ = static_cast<std::uint16_t>(long_sent_ | bit(k));
                emit(Kind::key_long_press, k);
            }
            if (cfg.repeat_delay.value != 0 && reached(next_repeat_[k - 1], now)) {
                emit(Kind::key_repeat, k);
                const duration_ms p =
                    cfg.repeat_period.value != 0 ? cfg.repeat_period : cfg.repeat_delay;
                next_repeat_[k - 1] = next_repeat_[k - 1] + p;
                if (reached(next_repeat_[k - 1], now)) next_repeat_[k - 1] = now + p;
            }
        }
    }

private:
    static constexpr std::uint16_t bit(unsigned k) noexcept {
        return static_cast<std::uint16_t>(1u << (k - 1));
    }

    key_set held_{};
    std::array<millis, key_set::max> pressed_at_{};
    std::array<millis, key_set::max> next_repeat_{};
    std::uint16_t long_sent_ = 0;
};

}  // namespace powerkey::behaviour

#endif  // POWERKEY_BEHAVIOUR_KEY_TIMING_HPP
