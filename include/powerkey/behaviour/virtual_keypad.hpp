// powerkey: a virtual keypad, the device side of every model, for testing controllers without a
// keypad. docs/virtual-keypad.md: how to step it, and what it does with the manual section (PK1000
// = PK1000_CANopen_UM_rev1.13, PKP = PKP-2200-2400-LI_CANopen_UM_rev1.1) each behaviour is from.
#ifndef POWERKEY_BEHAVIOUR_VIRTUAL_KEYPAD_HPP
#define POWERKEY_BEHAVIOUR_VIRTUAL_KEYPAD_HPP

#include <powerkey/behaviour/clock.hpp>
#include <powerkey/behaviour/j1939_keypad.hpp>
#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/detail/bytes.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/commands.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/keypad/values.hpp>
#include <powerkey/names.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>

namespace powerkey::behaviour {

// --- the keypad ---------------------------------------------------------------------------------

// Where the keypad is: off (no power), the CANopen NMT states (CiA 301 7.3.2, manuals 4-9), or
// in J1939 (PK1000 49, keypad_options), where behaviour/j1939_keypad.hpp speaks for it.
// clang-format off
#define POWERKEY_BEHAVIOUR_RUN_STATE_LIST(X) \
    X(off) \
    X(pre_operational) \
    X(operational) \
    X(stopped) \
    X(j1939)
// clang-format on
enum class run_state : std::uint8_t {
    POWERKEY_BEHAVIOUR_RUN_STATE_LIST(POWERKEY_DETAIL_ENUMERATOR)
};

struct keypad_options {
    // Drop an SDO request that arrives while it still answers another (issue 12: field logs); off,
    // the later request is answered after the earlier one.
    bool drop_sdo_while_busy = true;
    // How long the keypad takes to answer an SDO request, in ms (inferred); 0: at once.
    std::uint32_t sdo_response_ms = 1;
    // A J1939 keypad from power-on, on every model that speaks_j1939 (docs/virtual-keypad.md).
    bool start_in_j1939 = false;
    // The J1939 address it first speaks J1939 at, until a 70h moves it (21h: section 5).
    j1939_source_address j1939_address = j1939_source_address{j1939::keypad_default_address};
};

// The backlight as the keypad shows it (PK1000 15, 19 b/c; PKP 13 b/c, 30).
struct backlight_state {
    powerkey::level level = 0;
    backlight_colour colour = backlight_colour::amber;
    friend constexpr bool operator==(const backlight_state&,
                                     const backlight_state&) noexcept = default;
};

namespace detail {
// Every object's initial value: a dictionary's rows over the defaults common to both manuals
// (section 3), which the PK1000 rows carry; made at compile time for a model known then.
constexpr std::array<std::uint32_t, object_count> initial_values(
    std::span<const object_row> rows) noexcept {
    std::array<std::uint32_t, object_count> v{};
    for (const auto& r : rows_of(dictionary::pk1000)) v[static_cast<std::size_t>(r.id)] = r.initial;
    for (const auto& r : rows) v[static_cast<std::size_t>(r.id)] = r.initial;
    return v;
}
template <model M>
inline constexpr auto initial_values_v =
    initial_values(powerkey::detail::rows_of(powerkey::detail::fixed_layout_v<M>));
}  // namespace detail

// Keypad: any_model, or model_constant<M>, a keypad of model M that reads M's dictionary alone.
template <std::size_t Outbox = 16, class Keypad = any_model>
class virtual_keypad {
    static constexpr bool fixed = !std::is_same_v<Keypad, any_model>;

public:
    // A keypad of model m, unpowered, with the manual's default settings (PK1000 3, PKP 3) and
    // node id `node` (default 15h) as its stored node id.
    constexpr explicit virtual_keypad(powerkey::model m,
                                      canopen::node_id node = canopen::default_node_id,
                                      keypad_options options = {}) noexcept
        : model_(model_of(m)),
          info_(fixed ? nullptr : &powerkey::detail::row_of(model_)),
          options_(options),
          j1939_(model_, options.j1939_address) {
        factory_defaults();
        value_[idx(object::node_id)] = node.value();
        node_ = node;
        if (options.start_in_j1939 && speaks_j1939(model_)) value_[idx(object::protocol_j1939)] = 1;
    }

    // --- power and faults -------------------------------------------------------------------

    // Power on: boot with the stored settings (see boot()).
    constexpr void power_on(millis t) noexcept {
        now_ = t;
        boot(t);
    }
    // Power off: the keypad hears and sends nothing; what it was sending is lost.
    constexpr void power_off() noexcept {
        state_ = run_state::off;
        pending_.reset();
        upload_ = {};
        outbox_.clear();
    }
    // A power cycle at t (fault injection: the keypad reboots mid-session).
    constexpr void power_cycle(millis t) noexcept {
        power_off();
        power_on(t);
    }
    // Silence (fault injection): from t for d the keypad transmits nothing; timers run on.
    constexpr void silence(millis t, duration_ms d) noexcept {
        silent_until_ = t + d;
        silent_ = true;
    }
    // Lost frames (fault injection): the next n frames sent to the keypad are not received.
    constexpr void drop_received(std::uint32_t n) noexcept { drop_rx_ = n; }
    // Lost frames (fault injection): the next n frames the keypad sends are lost.
    constexpr void drop_transmitted(std::uint32_t n) noexcept { drop_tx_ = n; }

    // --- stepping ---------------------------------------------------------------------------

    // A frame on the bus at time t (any frame: the keypad picks out what concerns it).
    constexpr void receive(const can::frame& f, millis t) noexcept {
        advance(t);
        if (state_ == run_state::off) return;
        if (drop_rx_ > 0) {
            --drop_rx_;
            return;
        }
        if (state_ == run_state::j1939) {
            if (j1939_.receive(f, t, sink()) == j1939_keypad::heard::to_canopen) {
                value_[idx(object::protocol_j1939)] = 0;  // then boots in CANopen (inferred)
                boot(t);
            }
            return;
        }
        if (f.is_extended()) return;
        const std::uint32_t id = f.raw_id();
        if (id == 0x000) return on_nmt(f, t);
        if (id == 0x080) return on_sync(f, t);
        if ((id & 0x780) == 0x700) return on_heartbeat(f, t);
        if ((id & 0x7F) != node_.value()) return;
        const std::uint32_t fn = id & 0x780;
        if (fn >= 0x200 && fn <= 0x500) return on_rpdo(f, t);
        if (fn == 0x600) return on_sdo(f, t);
    }

    // Runs the timers up to t (SDO reply, heartbeat producer and consumer, periodic key state).
    constexpr void advance(millis t) noexcept {
        if (silent_ && reached(silent_until_, t)) silent_ = false;
        now_ = t;
        if (state_ == run_state::j1939) j1939_.advance(t, keys_, sink());
        if (state_ == run_state::off || state_ == run_state::j1939) return;
        release_reply(t);
        // heartbeat producer (PK1000 29, PKP 9/17); a caller that wakes late gets one heartbeat
        const std::uint32_t hb = value(object::heartbeat_time);
        if (hb != 0 && reached(next_heartbeat_, t)) {
            send_heartbeat(nmt_byte());
            next_heartbeat_ = next_heartbeat_ + duration_ms{hb};
            if (reached(next_heartbeat_, t)) next_heartbeat_ = t + duration_ms{hb};
        }
        // heartbeat consumer (PK1000 28, NOTE 2): on a loss, LEDs off, pre-operational
        if (monitoring_ && reached(consumer_deadline_, t)) {
            monitoring_ = false;
            on_ = {};
            blink_ = {};
            backlight_.level = 0;
            if (state_ == run_state::operational) state_ = run_state::pre_operational;
        }
        // periodic key state: the event timer (PK1000 46 b) or PKP command 12h (PKP 13 f)
        const std::uint32_t period = periodic_ms();
        if (state_ == run_state::operational && period != 0 && reached(next_periodic_, t)) {
            const millis due = next_periodic_;
            send_keys(due);  // reschedules to due + period
            if (reached(next_periodic_, t)) next_periodic_ = t + duration_ms{period};  // late
        }
    }

    // The earliest time at which advance() has something to do; nullopt when nothing is
    // scheduled. Until then advance() changes and sends nothing: a caller may sleep until then.
    [[nodiscard]] constexpr std::optional<millis> next_due() const noexcept {
        std::optional<millis> due;
        const auto take = [&](millis t) {
            if (!due || before(t, *due)) due = t;
        };
        if (silent_) take(silent_until_);
        if (state_ == run_state::j1939)
            if (const auto j = j1939_.next_due()) take(*j);
        if (state_ == run_state::off || state_ == run_state::j1939) return due;
        if (pending_) take(pending_->due);
        if (value(object::heartbeat_time) != 0) take(next_heartbeat_);
        if (monitoring_) take(consumer_deadline_);
        if (state_ == run_state::operational && periodic_ms() != 0) take(next_periodic_);
        return due;
    }

    // Scripted keys: key k (1..the model's keys) at t; false for a key the model lacks.
    constexpr bool press(unsigned k, millis t) noexcept { return set_key(k, true, t); }
    constexpr bool release(unsigned k, millis t) noexcept { return set_key(k, false, t); }
    constexpr bool set_key(unsigned k, bool pressed, millis t) noexcept {
        if (k < 1 || k > model_row().keys) return false;
        key_set s = keys_;
        if (pressed)
            s.insert(k);
        else
            s.erase(k);
        set_keys(s, t);
        return true;
    }
    // All keys at once (keys the model lacks are left out).
    constexpr void set_keys(key_set s, millis t) noexcept {
        advance(t);
        s = key_set::from_mask(s.mask() & powerkey::detail::low_bits(model_row().keys));
        if (s == keys_) return;
        if (state_ == run_state::j1939) j1939_.keys_changed(keys_, s, sink());
        keys_ = s;
        if (state_ == run_state::operational && event_driven()) send_keys(t);
    }

    // The next frame the keypad sends, oldest first; nullopt when it has nothing to send.
    [[nodiscard]] constexpr std::optional<can::frame> transmit() noexcept { return outbox_.pop(); }

    // --- what it shows ----------------------------------------------------------------------

    [[nodiscard]] constexpr run_state state() const noexcept { return state_; }
    [[nodiscard]] constexpr powerkey::model model() const noexcept { return model_; }
    // The node id it answers on now.
    [[nodiscard]] constexpr canopen::node_id node() const noexcept { return node_; }
    [[nodiscard]] constexpr key_set keys() const noexcept { return keys_; }
    // LED maps: on, blink (both: alternate blink) (PK1000 12, 13, 17, 18; PKP 11-13 a, 15, 16).
    [[nodiscard]] constexpr const leds& led_on() const noexcept { return on_; }
    [[nodiscard]] constexpr const leds& led_blink() const noexcept { return blink_; }
    // Key LED brightness 00h..3Fh (PK1000 14, 19 a; PKP 13 b, 30).
    [[nodiscard]] constexpr powerkey::level brightness() const noexcept { return brightness_; }
    [[nodiscard]] constexpr backlight_state backlight() const noexcept { return backlight_; }
    // The bit rate it runs at (as of the last reset; in J1939, 6Fh's).
    [[nodiscard]] constexpr baud_rate baud() const noexcept {
        return state_ == run_state::j1939 ? j1939_.settings().baud : baud_;
    }
    // The J1939 side: its settings, address, LEDs and levels (behaviour/j1939_keypad.hpp).
    [[nodiscard]] constexpr const j1939_keypad& j1939() const noexcept { return j1939_; }
    // The tick timer of the key-state PDO at t: +1 every 100 ms since power on (PK1000 11).
    [[nodiscard]] constexpr std::uint8_t tick(millis t) const noexcept {
        return static_cast<std::uint8_t>(elapsed(boot_time_, t).value / 100u);
    }
    // The number an SDO read of o would give now; nullopt for an object the dictionary lacks.
    [[nodiscard]] constexpr std::optional<std::uint32_t> read(object o) const noexcept {
        const auto row = powerkey::detail::find_row(layout(), o);
        if (!row) return std::nullopt;
        return current(*row);
    }
    // Frames the outbox could not hold (the caller drained too slowly).
    [[nodiscard]] constexpr std::size_t overflowed() const noexcept { return outbox_.dropped(); }
    [[nodiscard]] static constexpr std::size_t outbox_capacity() noexcept { return Outbox; }

private:
    // --- stored settings ----------------------------------------------------------------------

    // Every object's value, by object (not by row: the PKP keeps settings its dictionary does not
    // show, set by command); kept across resets (docs/virtual-keypad.md, "stored settings").
    static constexpr std::size_t idx(object o) noexcept { return static_cast<std::size_t>(o); }
    constexpr std::uint32_t value(object o) const noexcept { return value_[idx(o)]; }

    constexpr void factory_defaults() noexcept {
        if constexpr (fixed)
            value_ = behaviour::detail::initial_values_v<Keypad::value>;
        else
            value_ = behaviour::detail::initial_values(powerkey::detail::rows_of(layout()));
        value_[idx(object::node_id)] = canopen::default_node_id.value();
        if (powerkey::detail::find_row(layout(), object::total_keys)) {
            // PKP 32: the key and LED counts. The manual prints the PKU2200's: 4 keys, 0Ch LEDs
            // (4 keys x RGB), 6 external LEDs; the other models by the same rule (inferred),
            // with no external LEDs.
            value_[idx(object::total_keys)] = model_row().keys;
            value_[idx(object::total_leds)] = std::uint32_t{model_row().leds} * model_row().planes;
            value_[idx(object::external_leds)] = model_ == powerkey::model::pkp2200 ? 6u : 0u;
            value_[idx(object::tpdo1_event_timer)] = 0;  // PKP 3: periodic transmission off
        }
    }

    // The codec's row of a full row, and the model's layout: what the value kinds read.
    constexpr const powerkey::detail::codec_row& codec_row_of(const object_row& r) const noexcept {
        return powerkey::detail::codec_row_at(
            layout(),
            powerkey::detail::find_codec_row(layout(), powerkey::detail::wire_key(r.address)));
    }
    constexpr const auto& layout() const noexcept {
        if constexpr (fixed)
            return powerkey::detail::fixed_layout_v<Keypad::value>;
        else
            return powerkey::detail::layout(model_);
    }
    // The model's row (its strings, counts and flags).
    constexpr const model_info& model_row() const noexcept {
        if constexpr (fixed)
            return powerkey::detail::model_row_v<Keypad::value>;
        else
            return *info_;
    }
    static constexpr powerkey::model model_of(powerkey::model m) noexcept {
        if constexpr (fixed)
            return Keypad::value;
        else
            return powerkey::detail::is_model(m) ? m : powerkey::model::pk1000;
    }
    // The expedited size of a row, as the codec has it (value_kinds.hpp); 0 for a string.
    constexpr unsigned size_of(const object_row& r) const noexcept {
        return powerkey::detail::row_size(layout(), codec_row_of(r), 0);
    }
    // Whether an LED object is of the blink map (by its name: led_blink, led_blink_red, ...).
    static constexpr bool is_blink(object o) noexcept {
        return powerkey::to_string(o).find("blink") != std::string_view::npos;
    }
    constexpr leds& map_of(object o) noexcept { return is_blink(o) ? blink_ : on_; }
    constexpr const leds& map_of(object o) const noexcept { return is_blink(o) ? blink_ : on_; }

    // The value a read of row r gives now.
    constexpr std::uint32_t current(const object_row& r) const noexcept {
        const value_kind kind = info(r.id).kind;
        if (kind == value_kind::keys) return static_cast<std::uint32_t>(keys_.mask());
        if (kind == value_kind::cob_id) {
            // PK1000 38-41, 46: 4000 0000h + the identifier in use (the rows hold node 15h);
            // the PKP prints the function base without the node (E-PKP-5), as its rows do.
            if ((r.initial & 0x7Fu) != 0) return (r.initial & 0xFFFF'FF80u) | node_.value();
            return r.initial;
        }
        std::uint32_t led_value = 0;
        const bool led = visit_kind(kind, [&](auto k) {
            using K = decltype(k);
            if constexpr (K::led)
                led_value = K::pack(layout(), codec_row_of(r), object_value{0, map_of(r.id), 0});
            return K::led;
        });
        if (led) return led_value;
        switch (r.id) {
            case object::led_brightness: return brightness_.value();
            case object::backlight_level: return backlight_.level.value();
            case object::backlight_colour: return static_cast<std::uint32_t>(backlight_.colour);
            case object::node_id: return node_.value();
            default: return value(r.id);
        }
    }

    // --- boot and NMT -------------------------------------------------------------------------

    // Boot (power on, reset node, PKP node change; docs/virtual-keypad.md, "power on"): the
    // run-time state from the stored start-up values (PK1000 19 d-f, PKP 13 i-k).
    constexpr void boot(millis t) noexcept {
        if (restore_pending_) {
            factory_defaults();
            restore_pending_ = false;
        }
        on_ = {};
        blink_ = {};
        brightness_ = powerkey::level::make(value(object::default_led_brightness))
                          .value_or(powerkey::level{0x3F});
        backlight_.level = powerkey::level::make(value(object::default_backlight_level))
                               .value_or(powerkey::level{0});
        backlight_.colour = static_cast<backlight_colour>(value(object::default_backlight_colour));
        // keys_ stay: a key held through a reboot is still held
        boot_time_ = t;
        // J1939 stored: by 20FFh, or from the factory (keypad_options::start_in_j1939).
        if (value(object::protocol_j1939) != 0 && speaks_j1939(model_)) {
            reset_communication(t, run_state::j1939);
            j1939_.boot(t, keys_, false, sink());
            return;
        }
        reset_communication(t, value(object::active_on_startup) != 0 ? run_state::operational
                                                                     : run_state::pre_operational);
    }
    // Reset communication (CiA 301 7.3.2.2.1), alone or as part of a boot: LEDs and levels kept
    // (inferred: the manuals do not print 82h).
    constexpr void reset_communication(millis t,
                                       run_state to = run_state::pre_operational) noexcept {
        node_ = canopen::node_id::make(value(object::node_id)).value_or(canopen::default_node_id);
        baud_ = effective_baud();
        rpdo_buffer_ = {};
        sync_count_ = 0;
        monitoring_ = false;
        pending_.reset();
        upload_ = {};
        state_ = to;
        if (to == run_state::j1939) return;
        restart_timers(t);
        // "If a CANopen device starts with a heartbeat producer time unequal to 0 the boot-up
        // message is regarded as first heartbeat message" (PK1000 29, PKP 9).
        if (value(object::boot_up) != 0) send_heartbeat(0x00);
    }
    // 2010h codes 01h and 05h are "Reserved (force to 125k)" (PK1000 20).
    constexpr baud_rate effective_baud() const noexcept {
        const std::uint32_t code = value(object::baud_rate) & 7u;
        return code == 1 || code == 5 ? baud_rate::kbit_125 : static_cast<baud_rate>(code);
    }
    constexpr void restart_timers(millis t) noexcept {
        next_heartbeat_ = t + duration_ms{value(object::heartbeat_time)};
        const std::uint32_t p = periodic_ms();
        next_periodic_ = t + duration_ms{p};
    }

    // NMT (PK1000 4-7, PKP 4-7), to this node or to all (00h).
    constexpr void on_nmt(const can::frame& f, millis t) noexcept {
        const auto m = canopen::decode_nmt(f);
        if (!m) return;
        if (m->target.value() != 0 && m->target.value() != node_.value()) return;
        switch (m->command) {
            case canopen::nmt_command::start:
                if (state_ != run_state::operational) {
                    state_ = run_state::operational;
                    next_periodic_ = t + duration_ms{periodic_ms()};
                }
                break;
            case canopen::nmt_command::stop:
            case canopen::nmt_command::legacy_stop:
                state_ = run_state::stopped;
                pending_.reset();
                upload_ = {};
                break;
            case canopen::nmt_command::enter_pre_operational:
                state_ = run_state::pre_operational;
                break;
            case canopen::nmt_command::reset_node: boot(t); break;
            case canopen::nmt_command::reset_communication: reset_communication(t); break;
        }
    }
    constexpr std::uint8_t nmt_byte() const noexcept {
        return state_ == run_state::operational ? 0x05 : state_ == run_state::stopped ? 0x04 : 0x7F;
    }

    // Heartbeat consumer (PK1000 28): 1016h sub 1 = period (bits 0..15) and producer (16..23).
    constexpr void on_heartbeat(const can::frame& f, millis t) noexcept {
        if (f.size() != 1) return;  // 1016h is 0 (off) where the dictionary has none (PKP)
        const std::uint32_t c = value(object::consumer_heartbeat);
        const std::uint32_t period = c & 0xFFFFu;
        const std::uint32_t producer = (c >> 16) & 0x7Fu;
        if (period == 0 || (f.raw_id() & 0x7Fu) != producer || f[0] == 0x00) return;
        monitoring_ = true;
        consumer_deadline_ = t + duration_ms{period};
    }

    // --- PDOs ---------------------------------------------------------------------------------

    constexpr bool event_driven() const noexcept {
        // PK1000 46 a: FEh event-driven, 01h..F0h every n-th SYNC. The PKP's 1800h/2 reads FDh
        // but it sends on every change (PKP 10).
        const auto row = powerkey::detail::find_row(layout(), object::tpdo1_transmission_type);
        return !row || !row->writable() || value(object::tpdo1_transmission_type) >= 0xFE;
    }
    constexpr std::uint32_t periodic_ms() const noexcept {
        return event_driven() ? value(object::tpdo1_event_timer) : 0;
    }
    // The key-state PDO (PK1000 11, PKP 10): key bits in bytes 0..3, the tick in byte 4.
    constexpr void send_keys(millis t) noexcept {
        can::payload p{};
        powerkey::detail::store_le<4>(p, 0, static_cast<std::uint32_t>(keys_.mask()));
        p[4] = tick(t);
        send(0x180, 5, p);
        if (periodic_ms() != 0) next_periodic_ = t + duration_ms{periodic_ms()};
    }

    // SYNC (PK1000 10, 38, 39, 46): buffered RPDOs, and a synchronous TPDO every n-th SYNC.
    constexpr void on_sync(const can::frame& f, millis t) noexcept {
        if (f.size() != 0 || state_ != run_state::operational) return;
        for (auto& b : rpdo_buffer_) {
            if (b) apply_rpdo(*b);
            b.reset();
        }
        if (!event_driven()) {
            const std::uint32_t n = value(object::tpdo1_transmission_type);
            if (++sync_count_ >= n) {
                sync_count_ = 0;
                send_keys(t);
            }
        }
    }

    // RPDOs (PK1000 12-15, PKP 11-12), held until the next SYNC by types 00h..F0h (PK1000 10, 38).
    constexpr void on_rpdo(const can::frame& f, millis) noexcept {
        if (state_ != run_state::operational) return;
        const auto m = read_frame(f);
        if (!m) return;  // a PDO the keypad cannot read is ignored
        const std::uint32_t fn = f.raw_id() & 0x780;
        if (fn == 0x200 || fn == 0x300) {
            const object type_of =
                fn == 0x200 ? object::rpdo1_transmission_type : object::rpdo2_transmission_type;
            if (powerkey::detail::find_row(layout(), type_of) && value(type_of) <= 0xF0) {
                rpdo_buffer_[fn == 0x200 ? 0 : 1] = *m;
                return;
            }
        }
        apply_rpdo(*m);
    }
    constexpr void apply_rpdo(const message& msg) noexcept {
        if (const auto* on = std::get_if<powerkey::led_on>(&msg)) on_ = merge(on_, on->map);
        if (const auto* bl = std::get_if<powerkey::led_blink>(&msg))
            blink_ = merge(blink_, bl->map);
        if (const auto* b = std::get_if<powerkey::led_brightness>(&msg)) brightness_ = b->level;
        if (const auto* b = std::get_if<powerkey::backlight>(&msg)) {
            backlight_.level = b->level;
            // PK1000 15: 00h keeps the colour; PKP2600SI 15: 00h is the default colour.
            if (b->colour != backlight_colour::keep)
                backlight_.colour = b->colour;
            else if (model_row().backlight_zero_is_default)
                backlight_.colour =
                    static_cast<backlight_colour>(value(object::default_backlight_colour));
        }
    }
    // An LED PDO sets every plane the model has.
    constexpr leds merge(const leds&, const leds& in) const noexcept {
        leds out = in;
        if (model_row().planes < 3) out.blue = {};
        return out;
    }

    // --- SDO server (CiA 301 7.2.4; PK1000 16-48, PKP 13-32) ---------------------------------

    struct upload_state {
        bool active = false;
        canopen::sdo_address address{};
        std::string_view bytes{};
        std::size_t offset = 0;
        bool toggle = false;
    };
    enum class after_reply : std::uint8_t { none, to_j1939, reboot };

    constexpr void on_sdo(const can::frame& f, millis t) noexcept {
        if (state_ == run_state::stopped) return;  // CiA 301: no SDO when stopped
        if (f.size() != 8) return;
        if (pending_) {
            if (options_.drop_sdo_while_busy) return;  // busy: dropped, no reply, no abort
            flush_reply();  // not dropping: the earlier reply goes now, then this one
        }
        const std::uint8_t b0 = f[0];
        const canopen::sdo_address a{
            static_cast<std::uint16_t>(powerkey::detail::load_le<2>(f.bytes(), 1)), f[3]};
        switch (b0 >> 5) {
            case 2: return upload(a, t);
            case 1: return download(f, a, t);
            case 3: return segment(f, t);
            case 4: upload_ = {}; return;  // the client aborts: nothing to answer
            default: return abort(a, canopen::sdo_abort_code::invalid_command_specifier, t);
        }
    }

    // The abort for an address the dictionary lacks: the index exists -> no such sub-index.
    constexpr canopen::sdo_abort_code missing(canopen::sdo_address a) const noexcept {
        for (const auto& r : powerkey::detail::rows_of(layout()))
            if (r.address.index == a.index) return canopen::sdo_abort_code::subindex_does_not_exist;
        return canopen::sdo_abort_code::object_does_not_exist;
    }

    constexpr void upload(canopen::sdo_address a, millis t) noexcept {
        upload_ = {};
        const auto row = powerkey::detail::find_row(layout(), a);
        if (!row) return abort(a, missing(a), t);
        // 1001h: "not yet implemented in the device" (PK1000 31): object does not exist
        if (info(row->id).kind == value_kind::none)
            return abort(a, canopen::sdo_abort_code::object_does_not_exist, t);
        if (!row->readable()) return abort(a, canopen::sdo_abort_code::write_only, t);
        can::payload p = sdo_payload(0, a);
        const unsigned size = size_of(*row);
        if (size == 0) {
            const auto s = model_row().string_of(row->id);
            if (!s) return abort(a, canopen::sdo_abort_code::no_data, t);
            if (s->bytes.size() <= 4) {  // expedited (PK1000 33, 34)
                p[0] = static_cast<std::uint8_t>(0x43 | ((4 - s->bytes.size()) << 2));
                for (std::size_t i = 0; i < s->bytes.size(); ++i)
                    p[4 + i] = static_cast<std::uint8_t>(s->bytes[i]);
                return reply(p, t);
            }
            p[0] = s->size_indicated ? 0x41 : 0x40;
            powerkey::detail::store_le<4>(p, 4, s->announced);
            upload_ = {true, a, s->bytes, 0, false};
            return reply(p, t);
        }
        // expedited, the row's size: 4Fh one byte, 4Bh two, 43h four
        p[0] = static_cast<std::uint8_t>(0x43 | ((4u - size) << 2));
        powerkey::detail::store_le(p, 4, size, current(*row));
        reply(p, t);
    }

    constexpr void segment(const can::frame& f, millis t) noexcept {
        if (!upload_.active)
            return abort({}, canopen::sdo_abort_code::invalid_command_specifier, t);
        const bool toggle = (f[0] & 0x10) != 0;
        if (toggle != upload_.toggle) {
            const auto a = upload_.address;
            upload_ = {};
            return abort(a, canopen::sdo_abort_code::toggle_bit_not_alternated, t);
        }
        const std::size_t left = upload_.bytes.size() - upload_.offset;
        const std::size_t n = left < 7 ? left : 7;
        const bool last = left <= 7;
        can::payload p{};
        p[0] = static_cast<std::uint8_t>((toggle ? 0x10 : 0) | ((7 - n) << 1) | (last ? 1 : 0));
        for (std::size_t i = 0; i < n; ++i)
            p[1 + i] = static_cast<std::uint8_t>(upload_.bytes[upload_.offset + i]);
        upload_.offset += n;
        upload_.toggle = !upload_.toggle;
        if (last) upload_ = {};
        reply(p, t);
    }

    constexpr void download(const can::frame& f, canopen::sdo_address a, millis t) noexcept {
        upload_ = {};
        const std::uint8_t b0 = f[0];
        const auto row = powerkey::detail::find_row(layout(), a);
        if (!row) return abort(a, missing(a), t);
        if (!row->writable()) return abort(a, canopen::sdo_abort_code::read_only, t);
        if ((b0 & 0x02) == 0)  // segmented download: no object here takes one
            return abort(a, canopen::sdo_abort_code::unsupported_access, t);
        const unsigned size = size_of(*row);
        const unsigned n = (b0 & 0x01) != 0 ? 4u - ((b0 >> 2) & 3u) : size;
        if (n != size) return abort(a, canopen::sdo_abort_code::length_mismatch, t);
        const std::uint32_t v =
            static_cast<std::uint32_t>(powerkey::detail::load_le(f.bytes(), 4, n));
        after_reply then = after_reply::none;
        if (const auto code = check_and_apply(*row, f, v, then, t)) return abort(a, *code, t);
        if (row->id == object::node_id && model_row().replies_from_new_id) {
            // PK1000 23: the acknowledgement already comes from the new id
            node_ = canopen::node_id::make(v).value();
        }
        reply(sdo_payload(0x60, a), t, then);
    }

    // Checks a written value as the codec does (value_kinds.hpp), applies it; the abort, if any.
    using refusal = std::optional<canopen::sdo_abort_code>;
    constexpr refusal check_and_apply(const object_row& r, const can::frame& f, std::uint32_t v,
                                      after_reply& then, millis t) noexcept {
        const value_kind kind = info(r.id).kind;
        if (kind == value_kind::commands) return command(f, then);
        const auto& c = codec_row_of(r);
        refusal refused;
        const bool led = visit_kind(kind, [&](auto k) {
            using K = decltype(k);
            const auto size = static_cast<std::uint8_t>(size_of(r));
            if (const errc e = K::check(layout(), c, size, v, true); e != errc{}) {
                refused = K::abort_for(e, v, c);
            } else if constexpr (K::led) {
                leds& l = map_of(r.id);
                l = merged(l, K::value(layout(), c, size, v).map, K::covered(layout(), c));
            }
            return K::led;
        });
        if (refused || led) return refused;
        if (kind == value_kind::restore) {  // PK1000 36: effective after the reset
            restore_pending_ = true;
            return std::nullopt;
        }
        if (kind == value_kind::consumer_heartbeat)
            monitoring_ = false;  // starts again with the next heartbeat
        value_[idx(r.id)] = v;
        switch (r.id) {
            // the run-time levels (PK1000 19 a-c, PKP 30)
            case object::led_brightness: brightness_ = powerkey::level::make(v).value(); break;
            case object::backlight_level:
                backlight_.level = powerkey::level::make(v).value();
                break;
            case object::backlight_colour:
                backlight_.colour = static_cast<backlight_colour>(v);
                break;
            case object::heartbeat_time: next_heartbeat_ = t + duration_ms{v}; break;
            case object::tpdo1_event_timer:
            case object::tpdo1_transmission_type:
                next_periodic_ = t + duration_ms{periodic_ms()};
                sync_count_ = 0;
                break;
            case object::protocol_j1939:  // PK1000 49: the keypad answers, then speaks J1939
                if (v == 1 && model_row().j1939) then = after_reply::to_j1939;
                break;
            default: break;
        }
        return std::nullopt;
    }

    // The PKP command module, 6500h sub 1 (PKP 13 a-m).
    constexpr refusal command(const can::frame& f, after_reply& then) noexcept {
        const auto m = read_frame(f);
        const auto* c = m ? std::get_if<powerkey::command>(&*m) : nullptr;
        if (c == nullptr) return canopen::sdo_abort_code::invalid_value;
        using cc = command_code;
        const auto stored = [&](object o, std::uint32_t v) { value_[idx(o)] = v; };
        switch (c->code) {
            case cc::set_led_state: set_led_state(c->key, c->state); break;
            case cc::set_led_brightness: brightness_ = c->level; break;
            case cc::set_backlight_level: backlight_.level = c->level; break;
            case cc::set_backlight_colour: backlight_.colour = c->colour; break;
            case cc::set_active_on_startup: stored(object::active_on_startup, c->enabled); break;
            case cc::set_baud_rate:
                stored(object::baud_rate, static_cast<unsigned>(c->baud));
                break;
            case cc::set_periodic_transmission:  // PKP 13 f: period x 10 ms
                stored(object::tpdo1_event_timer, c->enabled ? c->period_10ms * 10u : 0u);
                next_periodic_ = now_ + duration_ms{periodic_ms()};
                break;
            case cc::set_boot_up: stored(object::boot_up, c->enabled); break;
            case cc::set_startup_show:
                stored(object::startup_show, static_cast<unsigned>(c->show));
                break;
            case cc::set_node_id:  // PKP 13 h: reply from the old id, then boot-up
                stored(object::node_id, c->node_id.value());
                then = after_reply::reboot;
                break;
            case cc::set_demo_mode: stored(object::demo_mode, c->enabled); break;
            case cc::set_default_backlight_level:
                stored(object::default_backlight_level, c->level.value());
                break;
            case cc::set_default_led_brightness:
                stored(object::default_led_brightness, c->level.value());
                break;
            case cc::set_default_backlight_colour:
                stored(object::default_backlight_colour, static_cast<unsigned>(c->colour));
                break;
        }
        return std::nullopt;
    }
    // PKP 13 a: one key's LED, in the on map, the blink map, or both (alternate blink, PKP 12).
    // The two-colour states are inferred (docs/virtual-keypad.md, "LED, level, backlight state"):
    // the on map holds green for red/green, red for amber/red, both (amber) for green/amber.
    constexpr void set_led_state(unsigned k, led_state s) noexcept {
        for (unsigned c = 0; c < 3; ++c) {
            on_.of(static_cast<plane>(c)).erase(k);
            blink_.of(static_cast<plane>(c)).erase(k);
        }
        const auto v = static_cast<unsigned>(s);
        if (v >= 1 && v <= 9) {
            const auto p = static_cast<plane>((v - 1) / 3);
            const unsigned how = (v - 1) % 3;  // 0 on, 1 blink, 2 alternate blink
            if (how != 1) on_.of(p).insert(k);
            if (how != 0) blink_.of(p).insert(k);
            return;
        }
        if (s == led_state::red_green_blink || s == led_state::amber_red_blink ||
            s == led_state::green_amber_blink) {
            blink_.red.insert(k);
            blink_.green.insert(k);
            if (s != led_state::amber_red_blink) on_.green.insert(k);
            if (s != led_state::red_green_blink) on_.red.insert(k);
        }
    }

    // --- sending ------------------------------------------------------------------------------

    // An SDO reply's first four bytes: the command specifier and the object's address.
    static constexpr can::payload sdo_payload(std::uint8_t cs, canopen::sdo_address a) noexcept {
        can::payload p{cs};
        powerkey::detail::store_le<2>(p, 1, a.index);
        p[3] = a.subindex;
        return p;
    }
    constexpr void abort(canopen::sdo_address a, canopen::sdo_abort_code c, millis t) noexcept {
        can::payload p = sdo_payload(0x80, a);
        powerkey::detail::store_le<4>(p, 4, static_cast<std::uint32_t>(c));
        reply(p, t);
    }
    // An SDO reply leaves sdo_response_ms after the request (released by advance()).
    constexpr void reply(const can::payload& p, millis t,
                         after_reply then = after_reply::none) noexcept {
        pending_ = pending_reply{p, t + duration_ms{options_.sdo_response_ms}, then, node_};
        release_reply(t);
    }
    constexpr void release_reply(millis t) noexcept {
        if (pending_ && reached(pending_->due, t)) flush_reply();
    }
    constexpr void flush_reply() noexcept {
        if (!pending_) return;
        const pending_reply r = *pending_;
        pending_.reset();
        send_from(r.from, 0x580, 8, r.payload);
        if (r.then == after_reply::to_j1939) {
            state_ = run_state::j1939;
            upload_ = {};
            j1939_.boot(r.due, keys_, true, sink());
        } else if (r.then == after_reply::reboot) {
            boot(r.due);
        }
    }
    constexpr void send_heartbeat(std::uint8_t state) noexcept {
        can::payload p{};
        p[0] = state;
        send(0x700, 1, p);
    }
    constexpr void send(std::uint16_t base, std::uint8_t n, const can::payload& p) noexcept {
        send_from(node_, base, n, p);
    }
    constexpr void send_from(canopen::node_id from, std::uint16_t base, std::uint8_t n,
                             const can::payload& p) noexcept {
        const auto id = can::standard_id::make(base + from.value()).value();
        emit(can::frame(id, can::dlc::make(n).value(), p));
    }
    // Every frame the keypad sends, CANopen or J1939, unless silenced or dropped.
    constexpr void emit(const can::frame& f) noexcept {
        if (silent_) return;
        if (drop_tx_ > 0) {
            --drop_tx_;
            return;
        }
        (void)outbox_.push(f);
    }
    // A frame as this keypad reads it (decode, with M's dictionary alone for a model_constant).
    constexpr result<message> read_frame(const can::frame& f) const noexcept {
        if constexpr (fixed)
            return powerkey::decode<Keypad::value>(f, node_);
        else
            return powerkey::decode(f, node_, model_);
    }

    constexpr auto sink() noexcept {
        return [this](const can::frame& f) { emit(f); };
    }

    struct pending_reply {
        can::payload payload;
        millis due;
        after_reply then;
        canopen::node_id from;
    };

    powerkey::model model_;
    const model_info* info_;  // the model's row (any_model)
    keypad_options options_;
    std::array<std::uint32_t, object_count> value_{};
    bool restore_pending_ = false;

    run_state state_ = run_state::off;
    canopen::node_id node_ = canopen::default_node_id;
    baud_rate baud_ = baud_rate::kbit_125;
    key_set keys_{};
    leds on_{};
    leds blink_{};
    powerkey::level brightness_ = 0x3F;
    backlight_state backlight_{};

    millis now_{};
    millis boot_time_{};
    millis next_heartbeat_{};
    millis next_periodic_{};
    millis consumer_deadline_{};
    bool monitoring_ = false;
    std::array<std::optional<message>, 2> rpdo_buffer_{};
    std::uint32_t sync_count_ = 0;

    std::optional<pending_reply> pending_{};
    upload_state upload_{};

    bool silent_ = false;
    millis silent_until_{};
    std::uint32_t drop_rx_ = 0;
    std::uint32_t drop_tx_ = 0;

    j1939_keypad j1939_;
    frame_queue<Outbox> outbox_{};
};

}  // namespace powerkey::behaviour

POWERKEY_DETAIL_ENUM_NAMES(powerkey::behaviour::run_state, POWERKEY_BEHAVIOUR_RUN_STATE_LIST);

#endif  // POWERKEY_BEHAVIOUR_VIRTUAL_KEYPAD_HPP
