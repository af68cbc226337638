// powerkey: key modes on top of the controller's key events, kept out of the core: momentary,
// toggle or a cycle of N states; the application feeds every controller event and reads back each
// key's state (docs/controller.md, the firmware loop).
#ifndef POWERKEY_BEHAVIOUR_KEY_MODES_HPP
#define POWERKEY_BEHAVIOUR_KEY_MODES_HPP

#include <powerkey/behaviour/controller.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/keypad/values.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace powerkey::behaviour {

// clang-format off
#define POWERKEY_BEHAVIOUR_KEY_MODE_LIST(X) \
    X(momentary)  /* state 1 while held, 0 when released */ \
    X(toggle)  /* each press flips 0 <-> 1 */ \
    X(cycle)  /* each press: state + 1, wrapping after states - 1 */
// clang-format on
enum class key_mode : std::uint8_t { POWERKEY_BEHAVIOUR_KEY_MODE_LIST(POWERKEY_DETAIL_ENUMERATOR) };

// A key whose state changed, and its new state.
struct key_mode_change {
    std::uint8_t key = 0;
    std::uint8_t state = 0;
    friend constexpr bool operator==(const key_mode_change&,
                                     const key_mode_change&) noexcept = default;
};

template <std::size_t Keys = key_set::max>
class key_modes {
public:
    // The mode of key k (1..Keys); `states` for cycle (2..255; toggle and momentary have 2).
    // False for a key outside 1..Keys or a cycle of fewer than 2 states. The state starts at 0.
    constexpr bool set(unsigned k, key_mode m, std::uint8_t states = 2) noexcept {
        if (k < 1 || k > Keys || (m == key_mode::cycle && states < 2)) return false;
        modes_[k - 1] = m;
        states_[k - 1] = m == key_mode::cycle ? states : std::uint8_t{2};
        state_[k - 1] = 0;
        return true;
    }
    [[nodiscard]] constexpr std::uint8_t state(unsigned k) const noexcept {
        return k >= 1 && k <= Keys ? state_[k - 1] : std::uint8_t{0};
    }
    [[nodiscard]] constexpr key_mode mode(unsigned k) const noexcept {
        return k >= 1 && k <= Keys ? modes_[k - 1] : key_mode::momentary;
    }
    // Every state back to 0 (e.g. on a lost keypad: the safe state).
    constexpr void reset() noexcept { state_ = {}; }

    // The change a controller event makes, if any: presses and releases only.
    [[nodiscard]] constexpr std::optional<key_mode_change> on_event(
        const controller_event& e) noexcept {
        const unsigned k = e.key;
        if (k < 1 || k > Keys) return std::nullopt;
        auto& s = state_[k - 1];
        const std::uint8_t before = s;
        if (e.kind == event_kind::key_pressed) {
            // A toggle is a cycle of 2 states.
            s = static_cast<std::uint8_t>(modes_[k - 1] == key_mode::momentary ? 1u
                                          : s + 1u >= states_[k - 1]           ? 0u
                                                                               : s + 1u);
        } else if (e.kind == event_kind::key_released && modes_[k - 1] == key_mode::momentary) {
            s = 0;
        }
        if (s == before) return std::nullopt;
        return key_mode_change{static_cast<std::uint8_t>(k), s};
    }

private:
    std::array<key_mode, Keys> modes_{};
    std::array<std::uint8_t, Keys> states_{};
    std::array<std::uint8_t, Keys> state_{};
};

}  // namespace powerkey::behaviour

POWERKEY_DETAIL_ENUM_NAMES(powerkey::behaviour::key_mode, POWERKEY_BEHAVIOUR_KEY_MODE_LIST);

#endif  // POWERKEY_BEHAVIOUR_KEY_MODES_HPP
