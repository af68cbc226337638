// powerkey tool: `decode --show` draws the keypad after every frame that changes it: each key
// with its LED colour (ANSI colours on a terminal, letters otherwise) and pressed keys marked.
// It reads the messages through their fields: `keys` of a key-state message, and `red`, `green`,
// `blue` of the LED on / blink messages, so it follows whatever the profiles name that way.
#ifndef POWERKEY_TOOL_SHOW_HPP
#define POWERKEY_TOOL_SHOW_HPP

#include <powerkey/decoder.hpp>
#include <powerkey/fields.hpp>

#include <unistd.h>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <type_traits>

namespace tool {

class keypad_picture {
public:
    explicit keypad_picture(powerkey::model m)
        : keys_(m == powerkey::model::pk1000    ? 10
                : m == powerkey::model::pkp2200 ? 4
                : m == powerkey::model::pkp2400 ? 8
                                                : 12),
          leds_(m == powerkey::model::pk1000 ? 28 : keys_),
          ansi_(isatty(1) != 0) {}

    // Takes in a decoded message; true when the picture changed.
    template <class M>
    bool update(const M& msg) {
        const std::string_view kind = powerkey::kind_of(msg);
        const bool is_keys = kind.find("key_state") != std::string_view::npos ||
                             kind.find("keys_response") != std::string_view::npos ||
                             kind.ends_with("_keys");
        const bool is_on = kind.find("led_on") != std::string_view::npos;
        const bool is_blink = kind.find("led_blink") != std::string_view::npos;
        const bool is_state = kind.ends_with("set_led_state");
        if (!is_keys && !is_on && !is_blink && !is_state) return false;
        const auto before = state_;
        // Fields of one colour plane (PK1000 2001h/2002h: colour + leds), or of one key (PKP
        // command 6500h/01h: key + state), are gathered first.
        int colour = -1;
        std::uint64_t leds = 0;
        bool has_leds = false;
        unsigned key = 0;
        std::string_view led_state;
        powerkey::for_each_field(msg, [&](std::string_view name, const auto& v) {
            using T = std::decay_t<decltype(v)>;
            if constexpr (powerkey::is_index_set<T>::value) {
                if (is_keys && (name == "keys" || name == "pressed")) state_.keys = v.mask();
                const int plane = plane_of(name);
                if (plane >= 0 && is_on) state_.on[plane] = v.mask();
                if (plane >= 0 && is_blink) state_.blink[plane] = v.mask();
                if (name == "leds") {
                    leds = v.mask();
                    has_leds = true;
                }
            } else if constexpr (std::is_enum_v<T>) {
                if (name == "colour") colour = plane_of(powerkey::enum_name(v));
                if (name == "state") led_state = powerkey::enum_name(v);
            } else if constexpr (powerkey::is_bounded<T>::value) {
                if (name == "key") key = v.value();
            }
        });
        if (has_leds && colour >= 0 && is_on) state_.on[colour] = leds;
        if (has_leds && colour >= 0 && is_blink) state_.blink[colour] = leds;
        if (is_state && key >= 1 && key <= 64) set_key(key - 1, led_state);
        return !(before == state_);
    }

    [[nodiscard]] std::string draw() const {
        std::string s = "    ";
        for (unsigned i = 0; i < leds_; ++i) {
            const unsigned planes =
                bit(state_.on[0], i) | (bit(state_.on[1], i) << 1) | (bit(state_.on[2], i) << 2);
            const unsigned blink = bit(state_.blink[0], i) | (bit(state_.blink[1], i) << 1) |
                                   (bit(state_.blink[2], i) << 2);
            const bool pressed = i < keys_ && bit(state_.keys, i) != 0;
            char label[12];
            std::snprintf(label, sizeof label, "%2u", i + 1);
            if (ansi_) {
                static constexpr int bg[8] = {0, 41, 42, 43, 44, 45, 46, 47};
                const unsigned shown = planes | blink;
                s += "\x1b[";
                s += shown ? std::to_string(bg[shown]) : std::string("100");
                if (blink) s += ";5";
                if (pressed) s += ";7";
                s += "m";
                s += label;
                s += pressed ? "*" : " ";
                s += "\x1b[0m ";
            } else {
                static constexpr char name[8] = {'.', 'R', 'G', 'Y', 'B', 'M', 'C', 'W'};
                const unsigned shown = planes | blink;
                char c = name[shown];
                if (blink && c != '.') c = static_cast<char>(c - 'A' + 'a');
                s += "[";
                s += label;
                s += pressed ? '*' : ' ';
                s += c;
                s += "]";
            }
        }
        s += "\n";
        return s;
    }

private:
    static int plane_of(std::string_view name) {
        return name == "red" ? 0 : name == "green" ? 1 : name == "blue" ? 2 : -1;
    }

    // PKP command 01h: red_on, green_blink, blue_alternate_blink, off, and the two-colour
    // blinks (red_green_blink: red and green in turn, shown as red on + green blinking).
    void set_key(unsigned i, std::string_view s) {
        const std::uint64_t bit_i = std::uint64_t{1} << i;
        for (auto* plane : {state_.on, state_.blink})
            for (int p = 0; p < 3; ++p) plane[p] &= ~bit_i;
        const auto first = s.substr(0, s.find('_'));
        const auto rest = s.substr(first.size());
        int p = plane_of(first);
        if (first == "amber") {
            state_.on[0] |= bit_i;
            p = 1;
        }
        if (p < 0) return;  // off, or a state without a name
        if (rest == "_on" || rest == "_alternate_blink" || first == "amber") state_.on[p] |= bit_i;
        if (rest == "_blink" || rest == "_alternate_blink") state_.blink[p] |= bit_i;
        if (rest.starts_with("_green") || rest.starts_with("_amber")) {
            state_.on[p] |= bit_i;
            state_.blink[1] |= bit_i;
        }
        if (rest == "_red_blink") state_.blink[0] |= bit_i;
    }

    static unsigned bit(std::uint64_t m, unsigned i) {
        return static_cast<unsigned>((m >> i) & 1u);
    }

    struct state {
        std::uint64_t keys = 0;
        std::uint64_t on[3] = {0, 0, 0};
        std::uint64_t blink[3] = {0, 0, 0};
        bool operator==(const state&) const = default;
    };
    unsigned keys_;
    unsigned leds_;
    bool ansi_;
    state state_;
};

}  // namespace tool

#endif
