// powerkey: the bus-log checker's J1939 rules (docs/checker.md, "J1939"). checker.hpp holds one
// and steps it with every 29-bit frame after the session has; it says whether the frame is the
// keypad's (for wrong_model), whether it was sent to the keypad (a refused one is refused_frame)
// and which J1939 fault it shows, if any:
//   - bad_header: a frame on PGN EF00h to the keypad without the 04 1B header (section 4), or
//     with a command byte no keypad has;
//   - multiple_leds_off: a multiple-LED frame (A700h, A600h, section 7b) while LED management
//     (37h, section 13) is single LED only, its default;
//   - no_keypad: a command to an address no keypad holds: not the followed keypad's (the
//     session's, which a 70h moves), nor any address a keypad frame came from;
//   - address_conflict: an address claim (EE00h, section 20) for an address another NAME
//     claimed earlier in the log;
//   - bad_source: a frame on a keypad PGN from the global address FFh, or from the null address
//     FEh other than an address claim (J1939-81: neither is a sender's address).
// It also times the followed keypad's periodic frames (the heartbeat while 75h enables it, the
// key contact state while 71h does), which checker.hpp reports as heartbeat_silence and
// key_state_silence.
// It decodes each keypad-PGN frame once more, for any keypad address (the session may be
// narrowed to one), to see every keypad's frames and every command whatever its destination.
#ifndef POWERKEY_BEHAVIOUR_J1939_CHECKS_HPP
#define POWERKEY_BEHAVIOUR_J1939_CHECKS_HPP

#include <powerkey/behaviour/clock.hpp>
#include <powerkey/can/frame.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/j1939/id.hpp>
#include <powerkey/j1939/name.hpp>
#include <powerkey/keypad/j1939_codec.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/session.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <variant>

namespace powerkey::behaviour {

enum class j1939_fault : std::uint8_t {
    bad_header,
    multiple_leds_off,
    no_keypad,
    address_conflict,
    bad_source
};

// A fault and its detail, as checker.hpp's problem carries it:
//   bad_header         identifier, bytes 0..2 (byte 0 in bits 23..16), 0
//   multiple_leds_off  identifier, line of the 37h that turned it off (0: the default), 0
//   no_keypad          identifier, the destination, the followed keypad's address
//   address_conflict   identifier, the address, line of the other NAME's claim
//   bad_source         identifier, the source address, 0
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

// The followed keypad's periodic frames: the heartbeat (F9h, section 21) every 75h period while
// 75h enables it, and the key contact state (01h) of each key every 77h period (section 22,
// 100 ms by default) while 71h enables it (section 17). Both are off by default (section 5).
enum class j1939_timer : std::uint8_t { heartbeat, key_state };

class j1939_checks {
public:
    constexpr j1939_checks(model m, std::uint8_t address) noexcept : model_(m) { hold(address); }

    // Frame f, which the session has just stepped (event e), received at `now`; `before` is the
    // keypad's address before the step, `after` after it; `line` the input line.
    [[nodiscard]] constexpr j1939_reading step(const can::frame& f, const session_event& e,
                                               std::uint8_t before, std::uint8_t after,
                                               std::uint32_t line, millis now) noexcept {
        j1939_reading r;
        const auto id = j1939::parse_id(f);
        if (!id || !j1939::is_keypad_pgn(id->pgn)) return r;
        const auto any = j1939::decode(f, model_);
        if (any) {
            r.keypads = true;
            std::visit(
                [&](const auto& v) {
                    on_message(v, f.raw_id(), r, before, {now, line});
                },
                *any);
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
        if (!r.finding && (id->source == j1939::global_address ||
                           (id->source == j1939::null_address &&
                            id->pgn.value() != j1939::address_claim_pgn.value())))
            r.finding = j1939_finding{j1939_fault::bad_source, {f.raw_id(), id->source, 0}};
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

    // Timer t: its period in ms as the log set it (0 while off, or while the log has not shown
    // the setting: the keypad's is then not known, so it is not judged). The silence counts from
    // the first frame after the setting.
    [[nodiscard]] constexpr silence_timer& timer(j1939_timer t) noexcept {
        return timers_[static_cast<std::size_t>(t)];
    }

private:
    using seen = silence_timer::seen;
    struct claim_row {
        std::uint64_t name;  // pack_name: 8 bytes rather than the struct's 16
        std::uint32_t line;
        std::uint8_t address;
    };

    // A setting (75h, 71h, 77h): the new period counts from the keypad's next frame.
    constexpr void set_period(j1939_timer t, std::uint32_t ms) noexcept {
        timer(t) = silence_timer{ms, std::nullopt, false};
    }
    // A keypad that stops speaking J1939 (80h) or powers up (its address claim): its periodic
    // frames are timed again from the next one.
    constexpr void pause() noexcept {
        for (silence_timer& p : timers_) p.last.reset();
    }

    // Section 20: an address is one NAME's; a claim of it by another NAME is a conflict (J1939-81
    // sends the loser to another address). A keypad re-claiming with its NAME (at power-up) is
    // fine. FEh is the "cannot claim" address: any NAME may send from it. The last claims of
    // `claims_.size()` addresses are kept, the oldest given up for a new one.
    constexpr void claim(const j1939::address_claimed& v, std::uint32_t id, j1939_reading& r,
                         std::uint32_t line) noexcept {
        if (v.source == j1939::null_address) return;
        const std::uint64_t name = j1939::pack_name(v.name);
        for (std::size_t i = 0; i < claimed_; ++i) {
            claim_row& c = claims_[i];
            if (c.address != v.source) continue;
            if (c.name != name)
                r.finding = j1939_finding{j1939_fault::address_conflict, {id, v.source, c.line}};
            c.name = name;
            c.line = line;
            return;
        }
        claims_[next_claim_] = claim_row{name, line, v.source};
        next_claim_ = (next_claim_ + 1) % claims_.size();
        if (claimed_ < claims_.size()) ++claimed_;
    }

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
                              seen at) noexcept {
        namespace j = j1939;
        const std::uint32_t line = at.line;
        if constexpr (j::sent_by_keypad<T>) {
            if (v.source < j1939::null_address) hold(v.source);  // a keypad is there
            if constexpr (std::is_same_v<T, j::address_claimed>) {
                claim(v, id, r, line);
                if (v.source == keypad) pause();
            } else if constexpr (std::is_same_v<T, j::heartbeat>) {
                if (v.source == keypad) timer(j1939_timer::heartbeat).heard(at.time, line);
            } else if constexpr (std::is_same_v<T, j::key_contact>) {
                if (v.source == keypad) timer(j1939_timer::key_state).heard(at.time, line);
            }
        } else {
            command_to(v.destination, id, r, keypad);
            if (!r.to_keypad || r.finding) return;
            if constexpr (std::is_same_v<T, j::command>) {
                using c = j::command_code;
                if (v.code == c::set_led_management) {
                    multiple_leds_ = v.multiple_leds;
                    management_line_ = line;
                    leds_reported_ = false;
                } else if (v.code == c::set_heartbeat) {
                    set_period(j1939_timer::heartbeat, v.enabled ? 10u * v.period_10ms : 0u);
                } else if (v.code == c::set_periodic_transmission || v.code == c::set_key_period) {
                    if (v.code == c::set_periodic_transmission)
                        periodic_ = v.enabled;
                    else
                        key_period_10ms_ = v.period_10ms;
                    set_period(j1939_timer::key_state, periodic_ ? 10u * key_period_10ms_ : 0u);
                }
            } else if constexpr (std::is_same_v<T, j::switch_to_canopen>) {
                pause();
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
    std::array<std::uint32_t, 8> held_{};    // the addresses keypads hold, bit a for address a
    bool multiple_leds_ = false;             // section 13: single LED only by default
    std::uint32_t management_line_ = 0;      // the line of the last 37h, 0 for none
    bool leds_reported_ = false;             // multiple_leds_off said since that 37h
    std::array<silence_timer, 2> timers_{};  // by j1939_timer
    bool periodic_ = false;                  // 71h: periodic key states, off by default
    std::uint8_t key_period_10ms_ = 0x0A;    // 77h: 100 ms by default (section 22)
    std::array<claim_row, 16> claims_{};     // the last claim of each address; a ring, the oldest
                                             // address given up for a new one
    std::size_t claimed_ = 0;
    std::size_t next_claim_ = 0;
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
        case j1939_fault::address_conflict:
            w.put(" claims address ");
            w.put_hex(d[1], 2);
            w.put("h, which line ");
            w.put_decimal(d[2]);
            w.put(" claimed with another NAME: two devices want one address");
            break;
        case j1939_fault::bad_source:
            w.put(" is sent from ");
            w.put_hex(d[1], 2);
            w.put(d[1] == j1939::global_address
                      ? "h, the global address, which is no sender's (J1939-81)"
                      : "h, the null address, which sends only the address claim of a device "
                        "that cannot claim one (J1939-81)");
            break;
    }
}

}  // namespace powerkey::behaviour

#endif  // POWERKEY_BEHAVIOUR_J1939_CHECKS_HPP
