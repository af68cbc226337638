// powerkey: the bus-log checker's J1939 rules (docs/checker.md, "J1939"). checker.hpp holds one
// and steps it with every 29-bit frame after the session has; it says whether the frame is the
// keypad's (for wrong_model), whether it was sent to the keypad (a refused one is refused_frame)
// and which J1939 fault it shows, if any:
//   - bad_header: a frame on PGN EF00h to the keypad without the 04 1B header (section 4), or
//     with a command byte no keypad has;
//   - multiple_leds_off: a multiple-LED frame (A700h, A600h, section 7b) while LED management
//     (37h, section 13) is single LED only, its default;
//   - no_keypad: a command to an address no keypad holds: not the followed keypad's (the
//     session's, which a 70h moves), nor any address a keypad frame came from.
// It decodes each keypad-PGN frame once more, for any keypad address (the session may be
// narrowed to one), to see every keypad's frames and every command whatever its destination.
#ifndef POWERKEY_BEHAVIOUR_J1939_CHECKS_HPP
#define POWERKEY_BEHAVIOUR_J1939_CHECKS_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/j1939/id.hpp>
#include <powerkey/keypad/j1939_codec.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/session.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <variant>

namespace powerkey::behaviour {

enum class j1939_fault : std::uint8_t { bad_header, multiple_leds_off, no_keypad };

// A fault and its detail, as checker.hpp's problem carries it:
//   bad_header         identifier, bytes 0..2 (byte 0 in bits 23..16), 0
//   multiple_leds_off  identifier, line of the 37h that turned it off (0: the default), 0
//   no_keypad          identifier, the destination, the followed keypad's address
struct j1939_finding {
    j1939_fault fault;
    std::array<std::uint32_t, 3> detail{};
};

// What one 29-bit frame is to the checker.
struct j1939_reading {
    bool keypads = false;    // a keypad's frame or one to the keypad: counts for wrong_model
    bool to_keypad = false;  // sent to the followed keypad's address by another node
    std::optional<j1939_finding> finding;
};

class j1939_checks {
public:
    constexpr j1939_checks(model m, std::uint8_t address) noexcept : model_(m) { hold(address); }

    // Frame f, which the session has just stepped (event e); `before` is the keypad's address
    // before the step, `after` after it; `line` the input line.
    [[nodiscard]] constexpr j1939_reading step(const can::frame& f, const session_event& e,
                                               std::uint8_t before, std::uint8_t after,
                                               std::uint32_t line) noexcept {
        j1939_reading r;
        const auto id = j1939::parse_id(f);
        if (!id || !j1939::is_keypad_pgn(id->pgn)) return r;
        const auto any = j1939::decode(f, model_);
        if (any) {
            r.keypads = true;
            std::visit([&](const auto& v) { on_message(v, f.raw_id(), r, before, line); }, *any);
        } else if (any.error() != errc::wrong_id) {
            r.to_keypad = id->destination == before && id->source != before;
            r.keypads = r.to_keypad || id->source == before;
            if (r.to_keypad && any.error() == errc::unknown_command && f.size() == 8 &&
                !is_keypad_header(f))
                r.finding = j1939_finding{
                    j1939_fault::bad_header,
                    {f.raw_id(), (std::uint32_t{f[0]} << 16) | (std::uint32_t{f[1]} << 8) | f[2],
                     0}};
        }
        if (e.new_address) {  // a 70h leaves the old address; a claim only adds one
            if (e.decoded && std::holds_alternative<j1939::command>(*e.decoded)) release(before);
            hold(after);
        }
        return r;
    }

    // The followed keypad accepts the multiple-LED command (37h 02h seen).
    [[nodiscard]] constexpr bool multiple_leds() const noexcept { return multiple_leds_; }
    [[nodiscard]] constexpr bool holds(std::uint8_t a) const noexcept {
        return ((held_[a / 32] >> (a % 32)) & 1u) != 0;
    }

private:
    // Bytes 0..2 of an EF00h frame the codec calls unknown_command that a keypad could take:
    // the 04 1B header with a command byte some keypad has (absent on this model), or the LED
    // acknowledgement's 00h. Anything else is a bad header or a byte no keypad has.
    static constexpr bool is_keypad_header(const can::frame& f) noexcept {
        if (f[0] == 0x00) return true;
        if (f[0] != j1939::header_0 || f[1] != j1939::header_1) return false;
        const std::uint8_t code = f[2];
        return code == 0x01 || code == 0x80 || code == 0xF9 || j1939::find_command(code) != nullptr;
    }

    constexpr void hold(std::uint8_t a) noexcept { held_[a / 32] |= 1u << (a % 32); }
    constexpr void release(std::uint8_t a) noexcept { held_[a / 32] &= ~(1u << (a % 32)); }

    // A command: to an address some keypad holds; to the followed keypad, the multiple-LED
    // command only after 37h 02h.
    constexpr void command_to(std::uint8_t destination, std::uint32_t id, j1939_reading& r,
                              std::uint8_t keypad) noexcept {
        if (!holds(destination))
            r.finding = j1939_finding{j1939_fault::no_keypad, {id, destination, keypad}};
        r.to_keypad = destination == keypad;
    }

    template <class T>
    constexpr void on_message(const T& v, std::uint32_t id, j1939_reading& r, std::uint8_t keypad,
                              std::uint32_t line) noexcept {
        namespace j = j1939;
        if constexpr (std::is_same_v<T, j::key_contact> || std::is_same_v<T, j::heartbeat> ||
                      std::is_same_v<T, j::software_revision> || std::is_same_v<T, j::led_ack> ||
                      std::is_same_v<T, j::led_ack_code> || std::is_same_v<T, j::address_claimed>) {
            hold(v.source);  // a keypad is there
        } else {
            command_to(v.destination, id, r, keypad);
            if (!r.to_keypad || r.finding) return;
            if constexpr (std::is_same_v<T, j::command>) {
                if (v.code == j::command_code::set_led_management) {
                    multiple_leds_ = v.multiple_leds;
                    management_line_ = line;
                    leds_reported_ = false;
                }
            } else if constexpr (std::is_same_v<T, j::multiple_leds>) {
                if (!multiple_leds_ && !leds_reported_) {
                    leds_reported_ = true;
                    r.finding =
                        j1939_finding{j1939_fault::multiple_leds_off, {id, management_line_, 0}};
                }
            }
        }
    }

    model model_;
    std::array<std::uint32_t, 8> held_{};  // the addresses keypads hold, bit a for address a
    bool multiple_leds_ = false;           // section 13: single LED only by default
    std::uint32_t management_line_ = 0;    // the line of the last 37h, 0 for none
    bool leds_reported_ = false;           // multiple_leds_off said since that 37h
};

// The explanation of a J1939 fault with its detail (checker.hpp's explain()).
constexpr void explain_j1939(j1939_fault fault, const std::array<std::uint32_t, 3>& d,
                             text_writer& w) noexcept {
    w.put("J1939 frame ");
    w.put_hex(d[0], 8);
    w.put("h");
    switch (fault) {
        case j1939_fault::bad_header:
            w.put(" to keypad ");
            w.put_hex((d[0] >> 8) & 0xFF, 2);
            if ((d[1] >> 8) != 0x041B) {
                w.put("h has header ");
                w.put_hex(d[1] >> 8, 4);
                w.put("h, not 041Bh");
            } else {
                w.put("h has command byte ");
                w.put_hex(d[1] & 0xFF, 2);
                w.put("h, which no keypad has");
            }
            w.put(": the keypad does not act on it");
            break;
        case j1939_fault::multiple_leds_off:
            w.put(" (multiple LEDs) while LED management 37h is single LED only (");
            if (d[1] == 0) {
                w.put("the default");
            } else {
                w.put("line ");
                w.put_decimal(d[1]);
            }
            w.put("): the keypad ignores it until 37h 02h");
            break;
        case j1939_fault::no_keypad:
            w.put(" to address ");
            w.put_hex(d[1], 2);
            w.put("h, which no keypad holds (the keypad is at ");
            w.put_hex(d[2], 2);
            w.put("h): nobody acts on it");
            break;
    }
}

}  // namespace powerkey::behaviour

#endif  // POWERKEY_BEHAVIOUR_J1939_CHECKS_HPP
