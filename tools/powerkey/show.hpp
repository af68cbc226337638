// powerkey tool: `decode --show` draws the keypad after every frame that changes it: each key
// with its LED colour (ANSI colours on a terminal, letters otherwise) and pressed keys marked.
// It reads the messages through the library's accessors (pressed_keys, led_on_map,
// led_blink_map) and the model table (keys, LED mask, encoder rings), so every model is drawn.
#ifndef POWERKEY_TOOL_SHOW_HPP
#define POWERKEY_TOOL_SHOW_HPP

#include <powerkey/keypad/accessors.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/names.hpp>

#include <unistd.h>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <variant>

namespace tool {

class keypad_picture {
public:
    explicit keypad_picture(powerkey::model m)
        : model_(m),
          info_(powerkey::info(m).value_or(powerkey::model_info{})),
          ansi_(isatty(1) != 0) {}

    // Takes in a decoded message; true when the picture changed. Keys from key_change (only the
    // keys a frame covers change: a J1939 key contact state its one key), LED maps from
    // led_on_map / led_blink_map (only the LEDs a frame covers change), a PKP command 6500h/01h
    // and a J1939 single-LED command (SI form) by key and state, the PKP-3500-MT's rings from
    // encoder_leds. The J1939 multiple-LED frames are not drawn: one frame alone is half a state.
    bool update(const powerkey::message& msg) {
        const auto before = state_;
        if (const auto k = powerkey::key_change(msg, model_))
            state_.keys = (state_.keys & ~k->covered.mask()) | k->pressed.mask();
        auto apply = [](std::uint64_t* planes, const powerkey::led_map_update& u) {
            for (int p = 0; p < 3; ++p) {
                const auto pl = static_cast<powerkey::plane>(p);
                const std::uint64_t covered = u.covered.of(pl).mask();
                planes[p] = (planes[p] & ~covered) | (u.map.of(pl).mask() & covered);
            }
        };
        if (const auto u = powerkey::led_on_map(msg, model_)) apply(state_.on, *u);
        if (const auto u = powerkey::led_blink_map(msg, model_)) apply(state_.blink, *u);
        if (const auto* c = std::get_if<powerkey::command>(&msg);
            c && c->code == powerkey::command_code::set_led_state && c->key >= 1 && c->key <= 64)
            set_key(c->key - 1u, powerkey::to_string(c->state));
        if (const auto* l = std::get_if<powerkey::j1939::set_led>(&msg);
            l && l->key >= 1 && l->key <= 64)
            set_j1939_led(l->key - 1u, *l);
        if (const auto* r = std::get_if<powerkey::encoder_leds>(&msg))
            state_.rings = r->leds.mask();
        return !(before == state_);
    }

    // One cell per key (and per further LED, PK1000 11..28): rows as the keypad has them (up to
    // 8 keys one row, 10 and 12 two, 15 three), a cell with no LED (PKP-3500-MT 1 and 11) shows
    // no colour, then the PKP-3500-MT's two encoder rings of 16 LEDs.
    [[nodiscard]] std::string draw() const {
        const unsigned keys = info_.keys;
        unsigned highest = 0;
        for (unsigned i = 0; i < 32; ++i)
            if ((info_.led_mask >> i) & 1u) highest = i + 1;
        const unsigned cells = highest > keys ? highest : keys;
        const unsigned rows = keys <= 8 ? 1 : keys <= 12 ? 2 : 3;
        const unsigned per_row = keys == 0 ? 8 : (keys + rows - 1) / rows;
        std::string s = "    ";
        for (unsigned i = 0; i < cells; ++i) {
            if (i != 0 && ((i < keys && i % per_row == 0) || (i >= keys && (i - keys) % 10 == 0)))
                s += "\n    ";
            const bool has_led = ((info_.led_mask >> i) & 1u) != 0;
            const unsigned planes =
                bit(state_.on[0], i) | (bit(state_.on[1], i) << 1) | (bit(state_.on[2], i) << 2);
            const unsigned blink = bit(state_.blink[0], i) | (bit(state_.blink[1], i) << 1) |
                                   (bit(state_.blink[2], i) << 2);
            const bool pressed = i < keys && bit(state_.keys, i) != 0;
            char label[12];
            std::snprintf(label, sizeof label, "%2u", i + 1);
            if (ansi_) {
                static constexpr int bg[8] = {0, 41, 42, 43, 44, 45, 46, 47};
                const unsigned shown = has_led ? planes | blink : 0;
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
                s += has_led ? c : ' ';
                s += "]";
            }
        }
        s += "\n";
        if (info_.encoder_leds_pdo) {
            for (unsigned r = 0; r < 2; ++r) {
                s += r == 0 ? "    ring 1 " : "  ring 2 ";
                for (unsigned i = 0; i < 16; ++i) s += bit(state_.rings, 16 * r + i) ? '*' : '.';
            }
            s += "\n";
        }
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

    // A J1939 colour as planes (bit 0 red, 1 green, 2 blue): the mixed colours as their parts,
    // amber and yellow-green as yellow (the picture has eight colours).
    static unsigned planes_of(powerkey::j1939::led_colour c) {
        static constexpr unsigned planes[10] = {0, 1, 2, 4, 3, 6, 5, 7, 3, 3};
        const auto i = static_cast<unsigned>(c);
        return i < 10 ? planes[i] : 0;
    }
    // J1939 01h (SI form): on shows the colour, blink blinks it, alternate blink shows the colour
    // with the secondary blinking (as the PKP's two-colour blinks).
    void set_j1939_led(unsigned i, const powerkey::j1939::set_led& l) {
        const std::uint64_t bit_i = std::uint64_t{1} << i;
        for (auto* plane : {state_.on, state_.blink})
            for (int p = 0; p < 3; ++p) plane[p] &= ~bit_i;
        using powerkey::led_mode;
        const unsigned c = planes_of(l.colour), s = planes_of(l.secondary);
        for (int p = 0; p < 3; ++p) {
            const unsigned b = 1u << p;
            if ((l.mode == led_mode::on || l.mode == led_mode::alternate_blink) && (c & b))
                state_.on[p] |= bit_i;
            if ((l.mode == led_mode::blink && (c & b)) ||
                (l.mode == led_mode::alternate_blink && (s & b)))
                state_.blink[p] |= bit_i;
        }
    }
    static unsigned bit(std::uint64_t m, unsigned i) {
        return static_cast<unsigned>((m >> i) & 1u);
    }

    struct state {
        std::uint64_t keys = 0;
        std::uint64_t on[3] = {0, 0, 0};
        std::uint64_t blink[3] = {0, 0, 0};
        std::uint64_t rings = 0;
        bool operator==(const state&) const = default;
    };
    powerkey::model model_;
    powerkey::model_info info_;
    bool ansi_;
    state state_;
};

}  // namespace tool

#endif
