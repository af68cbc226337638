// powerkey: the host side of one keypad, a state machine the caller steps with each frame received
// and the time, that sends from an outbox and reports events (docs/controller.md: the loop, and
// each behaviour with the manual section it comes from).
#ifndef POWERKEY_BEHAVIOUR_CONTROLLER_HPP
#define POWERKEY_BEHAVIOUR_CONTROLLER_HPP

#include <powerkey/behaviour/clock.hpp>
#include <powerkey/behaviour/key_timing.hpp>
#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/canopen/sdo_upload.hpp>
#include <powerkey/detail/inline.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/keypad/accessors.hpp>
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
#include <type_traits>
#include <variant>

namespace powerkey::behaviour {

// How the controller makes the keypad operational.
// clang-format off
#define POWERKEY_BEHAVIOUR_START_MODE_LIST(X) \
    X(nmt_start)  /* NMT start after every boot-up (PK1000 4, PKP 4) */ \
    X(active_on_startup)  /* also set "active on startup" once (PK1000 2012h, PKP command 10h), so the */ \
    /* keypad comes up operational by itself after a power cycle */
// clang-format on
enum class start_mode : std::uint8_t {
    POWERKEY_BEHAVIOUR_START_MODE_LIST(POWERKEY_DETAIL_ENUMERATOR)
};

// Entry: what the configuration list holds: messages for controller<>, configuration_entry<M> for
// a controller of model_constant<M> (docs/controller.md, "Configuration").
template <class Entry>
struct basic_controller_config {
    model keypad_model = model::pk1000;  // used unless 100Bh names another model
    canopen::node_id node = canopen::default_node_id;
    bool any_node = false;  // adopt the first boot-up of any node instead of `node`'s
    bool identify = true;   // read 100Bh and take the model it reports
    start_mode start = start_mode::nmt_start;
    // Run in order after the keypad is found and after each reboot (others than sdo_read,
    // sdo_write and command are skipped). Caller-owned.
    std::span<const Entry> configuration{};
    duration_ms keypad_heartbeat{200};  // written to 1017h during setup; 0: leave 1017h alone
    duration_ms lost_after{600};        // silence that makes the keypad lost; 0: never lost
    duration_ms sdo_timeout{300};       // per request
    std::uint8_t sdo_retries = 2;       // sends after the first, for a timed-out request
    duration_ms probe_period{1000};     // SDO read of 1000h to `node` while searching; 0: off
    duration_ms refresh_period{1000};   // resend the LED PDOs this often; 0: only on change
    duration_ms long_press{800};        // held this long: key_long_press (once); 0: off
    duration_ms repeat_delay{500};      // held this long: the first key_repeat; 0: no repeats
    duration_ms repeat_period{200};     // then every repeat_period
};
using controller_config = basic_controller_config<message>;

// What the controller tells the application.
// clang-format off
#define POWERKEY_BEHAVIOUR_EVENT_KIND_LIST(X) \
    X(found)  /* the keypad answered: `node` */ \
    X(ready)  /* set up and started: `node`, the model in `model` */ \
    X(rebooted)  /* a boot-up while it was set up; the setup runs again */ \
    X(lost)  /* silent for longer than lost_after: go to a safe state */ \
    X(node_changed)  /* it moved to `node` */ \
    X(sdo_done)  /* an SDO request was answered (`step`, `what`; `value` of a read) */ \
    X(sdo_aborted)  /* the keypad aborted it: `value` is the CiA 301 abort code */ \
    X(sdo_timed_out)  /* no reply after the retries */ \
    X(sdo_refused)  /* not sent (the model cannot carry it), or a string read past 16 bytes: */ \
    /* `value` is the errc */ \
    X(key_pressed)  /* `key` */ \
    X(key_released)  /* `key` */ \
    X(key_long_press)  /* `key`, held for long_press */ \
    X(key_repeat)  /* `key`, held: repeat_delay, then every repeat_period */
// clang-format on
enum class event_kind : std::uint8_t {
    POWERKEY_BEHAVIOUR_EVENT_KIND_LIST(POWERKEY_DETAIL_ENUMERATOR)
};

// Which request an SDO event is about: an entry of the configuration list, or the controller's own.
// clang-format off
#define POWERKEY_BEHAVIOUR_SDO_ORIGIN_LIST(X) \
    X(configuration)  /* configuration[step] */ \
    X(identify)  /* the 100Bh read */ \
    X(heartbeat)  /* the 1017h write */ \
    X(start)  /* active on startup */ \
    X(shadow)  /* LED brightness or backlight (PKP: no PDO for them) */ \
    X(node_change)  /* change_node() */
// clang-format on
enum class sdo_origin : std::uint8_t {
    POWERKEY_BEHAVIOUR_SDO_ORIGIN_LIST(POWERKEY_DETAIL_ENUMERATOR)
};

struct controller_event {
    event_kind kind = event_kind::found;
    std::uint8_t key = 0;  // key events: 1..the model's keys
    canopen::node_id node = canopen::default_node_id;
    sdo_origin origin = sdo_origin::configuration;
    std::uint16_t step = 0;      // configuration index (origin configuration)
    object what = object::keys;  // SDO events: the object
    std::uint32_t value = 0;     // sdo_done: the value read (little endian); sdo_aborted: the code
    friend constexpr bool operator==(const controller_event&,
                                     const controller_event&) noexcept = default;
};

// clang-format off
#define POWERKEY_BEHAVIOUR_CONTROLLER_STATE_LIST(X) \
    X(searching)  /* waiting for a boot-up or heartbeat (probing the SDO server) */ \
    X(setting_up)  /* identifying and configuring, one SDO request at a time */ \
    X(running)  /* started; the shadow is kept and key events flow */
// clang-format on
enum class controller_state : std::uint8_t {
    POWERKEY_BEHAVIOUR_CONTROLLER_STATE_LIST(POWERKEY_DETAIL_ENUMERATOR)
};

// The most events one call reports for a keypad with `keys` keys (docs/controller.md, "Events").
[[nodiscard]] constexpr std::size_t events_per_call(std::size_t keys) noexcept {
    return 2 * keys + 13;
}
// Enough for any model: a key set holds 16 keys (the table's largest keypads have 15).
inline constexpr std::size_t default_event_capacity = events_per_call(key_set::max);

// The longest configuration list the controller runs (controller_event::step numbers 0..65534);
// past it, one sdo_refused with step max_configuration and value_out_of_range (docs/controller.md).
inline constexpr std::size_t max_configuration = 65535;

// An entry of the configuration list of a controller of model_constant<M>: a request checked and
// built for M when the entry is made (docs/controller.md, "One model").
template <model M>
class configuration_entry {
public:
    constexpr configuration_entry(const sdo_read& r) noexcept : configuration_entry(r, r.object) {}
    constexpr configuration_entry(const sdo_write& w) noexcept : configuration_entry(w, w.object) {}
    constexpr configuration_entry(const command& c) noexcept
        : configuration_entry(c, object::command_module) {}
    constexpr configuration_entry(const message& m) noexcept {
        if (std::holds_alternative<sdo_read>(m))
            *this = configuration_entry(std::get<sdo_read>(m));
        else if (std::holds_alternative<sdo_write>(m))
            *this = configuration_entry(std::get<sdo_write>(m));
        else if (std::holds_alternative<command>(m))
            *this = configuration_entry(std::get<command>(m));
    }

    // Not an SDO request: the controller skips it.
    [[nodiscard]] constexpr bool skipped() const noexcept { return skipped_; }
    [[nodiscard]] constexpr object what() const noexcept { return what_; }
    [[nodiscard]] constexpr bool read() const noexcept { return read_; }
    // The request's frame to `node`, or why M cannot carry it.
    [[nodiscard]] constexpr result<can::frame> frame(canopen::node_id node) const noexcept {
        if (refused_ != errc{}) return refused_;
        return can::frame(canopen::cob_id(canopen::function::sdo_rx, node),
                          can::dlc::make(8).value(), data_);
    }
    friend constexpr bool operator==(const configuration_entry&,
                                     const configuration_entry&) noexcept = default;

private:
    template <class T>
    constexpr configuration_entry(const T& msg, object o) noexcept
        : what_(o), read_(std::is_same_v<T, sdo_read>), skipped_(false) {
        // (the request's bytes are the same to every node: built to one; an object the model
        // lacks is unknown_object there)
        const auto f = powerkey::detail::own_frame(powerkey::detail::fixed_layout_v<M>,
                                                   canopen::default_node_id, msg);
        if (f)
            data_ = f->bytes();
        else
            refused_ = f.error();
    }

    can::payload data_{};
    object what_ = object::command_module;
    bool read_ = false;
    bool skipped_ = true;
    errc refused_{};
};

namespace detail {

// The controller's own requests as functions of one value: the read of O, write of O, command C.
template <object O>
constexpr sdo_read read_of(std::monostate) noexcept {
    return sdo_read{O};
}
// (one function, not overloads: a bool would convert to a node id's consteval constructor)
template <class V>
constexpr object_value value_of(V v) noexcept {
    if constexpr (std::is_same_v<V, level>)
        return level_value(v);
    else if constexpr (std::is_same_v<V, backlight_colour>)
        return colour_value(v);
    else if constexpr (std::is_same_v<V, canopen::node_id>)
        return node_value(v);
    else if constexpr (std::is_same_v<V, bool>)
        return flag_value(v);
    else
        return number_value(v.value);  // a duration
}
template <object O, class V>
constexpr sdo_write write_of(V v) noexcept {
    return sdo_write{O, value_of(v)};
}
template <command_code C, class V>
constexpr command command_of(V v) noexcept {
    command c;
    c.code = C;
    if constexpr (std::is_same_v<V, backlight_colour>)
        c.colour = v;
    else if constexpr (std::is_same_v<V, canopen::node_id>)
        c.node_id = v;
    else
        c.enabled = v;
    return c;
}

// The values of a small type, by their byte: every one is tried when the program is built.
template <class V>
struct small_values;  // (a duration: too many; its request checks itself)
template <>
struct small_values<std::monostate> {
    static constexpr unsigned first = 0, last = 0;
    static constexpr std::monostate of(unsigned) noexcept { return {}; }
};
template <>
struct small_values<bool> {
    static constexpr unsigned first = 0, last = 1;
    static constexpr bool of(unsigned r) noexcept { return r != 0; }
};
template <>
struct small_values<level> {
    static constexpr unsigned first = level::min, last = level::max;
    static constexpr level of(unsigned r) noexcept { return level::make(r).value(); }
};
template <>
struct small_values<canopen::node_id> {
    static constexpr unsigned first = canopen::node_id::min, last = canopen::node_id::max;
    static constexpr canopen::node_id of(unsigned r) noexcept {
        return canopen::node_id::make(r).value();
    }
};
template <>
struct small_values<backlight_colour> {
    static constexpr unsigned first = 0, last = 0xFF;
    static constexpr backlight_colour of(unsigned r) noexcept {
        return static_cast<backlight_colour>(r);
    }
};
template <class V>
constexpr std::uint8_t raw_of(V v) noexcept {
    if constexpr (std::is_same_v<V, std::monostate>)
        return 0;
    else if constexpr (std::is_same_v<V, bool>)
        return v ? 1 : 0;
    else if constexpr (std::is_same_v<V, backlight_colour>)
        return static_cast<std::uint8_t>(v);
    else
        return v.value();  // a level or a node id
}

// A request of one small value proven when the program is built (docs/controller.md, "One model,
// known when the program is built"): the bytes `data` with the value's byte at `at` for the values
// lo..hi, the one refusal `refused` for every other; proven false when that is not so.
struct byte_request {
    bool proven = false;
    can::payload data{};
    std::uint8_t at = 0;
    std::uint8_t lo = 1, hi = 0;  // (none accepted)
    errc refused{};

    [[nodiscard]] constexpr result<can::frame> frame(canopen::node_id node,
                                                     std::uint8_t raw) const noexcept {
        if (raw < lo || raw > hi) return refused;
        can::payload d = data;
        d[at] = raw;
        return can::frame(canopen::cob_id(canopen::function::sdo_rx, node),
                          can::dlc::make(8).value(), d);
    }
};
template <class V, class Build>
constexpr byte_request prove(Build build) noexcept {
    using values = small_values<V>;
    byte_request p;
    bool any = false, gap = false, refusal = false;
    for (unsigned r = values::first; r <= values::last; ++r) {
        const result<can::frame> f = build(values::of(r));
        if (!f) {
            if (refusal && f.error() != p.refused) return {};  // two refusals
            refusal = true;
            p.refused = f.error();
            gap = any;
            continue;
        }
        if (gap) return {};  // the values taken are not one range
        const auto raw = static_cast<std::uint8_t>(r);
        if (!any) {
            any = true;
            p.lo = raw;
            p.data = f->bytes();
            // where the value goes: the byte that is the value's in this frame and differs from
            // the next value's frame there (a single value: any byte that is the value)
            p.at = 8;
            for (std::uint8_t i = 0; i < 8 && p.at == 8; ++i)
                if (p.data[i] == raw) {
                    if (r == values::last) {
                        p.at = i;
                    } else if (const auto g = build(values::of(r + 1));
                               !g || g->bytes()[i] != p.data[i]) {
                        p.at = i;
                    }
                }
            if (p.at == 8) return {};
        }
        p.hi = raw;
        const auto expected = p.frame(canopen::default_node_id, raw);
        if (!(expected && *f == *expected)) return {};
    }
    p.proven = true;
    return p;
}
template <model M, auto Make, class V>
inline constexpr byte_request own_proof = [] {
    if constexpr (requires { small_values<V>::last; })
        return prove<V>([](V v) {
            return powerkey::detail::own_frame(powerkey::detail::fixed_layout_v<M>,
                                               canopen::default_node_id, Make(v));
        });
    else
        return byte_request{};
}();

// The entries of the configuration list of a controller of Keypad.
template <class Keypad>
struct entry_of {
    using type = configuration_entry<Keypad::value>;
};
template <>
struct entry_of<any_model> {
    using type = message;
};

}  // namespace detail

// Keypad: any_model, or model_constant<M>, a controller of model M alone (docs/controller.md, "One
// model, known when the program is built").
template <std::size_t OutboxCapacity = 8, std::size_t EventCapacity = default_event_capacity,
          class Keypad = any_model>
class controller {
    static constexpr bool fixed = !std::is_same_v<Keypad, any_model>;

public:
    // Its configuration: messages for any_model, configuration_entry<M> for model_constant<M>.
    using entry = typename detail::entry_of<Keypad>::type;
    using config = basic_controller_config<entry>;

    constexpr explicit controller(const config& c) noexcept
        : cfg_(c), model_(model_of(c)), layout_(layout_of(c)), node_(c.node), upload_(c.node) {}

    // --- driving it -------------------------------------------------------------------------

    // A frame received from the bus at `now` (any frame: the controller picks its keypad's).
    constexpr void step(const can::frame& f, millis now) noexcept {
        now_ = now;
        if (!f.is_extended()) on_frame(f);
        run();
    }
    // Time passed without a frame: timers (SDO timeout, lost, refresh, long press, repeat).
    constexpr void tick(millis now) noexcept {
        now_ = now;
        run();
    }
    // The next frame to send, oldest first.
    [[nodiscard]] constexpr std::optional<can::frame> next_frame() noexcept {
        return outbox_.pop();
    }
    [[nodiscard]] constexpr frame_queue<OutboxCapacity>& outbox() noexcept { return outbox_; }
    // The next event, oldest first.
    [[nodiscard]] constexpr std::optional<controller_event> poll() noexcept {
        return events_.pop();
    }
    // Events refused because the queue was full (see events_per_call).
    [[nodiscard]] constexpr std::size_t events_dropped() const noexcept {
        return events_.dropped();
    }
    [[nodiscard]] static constexpr std::size_t event_capacity() noexcept { return EventCapacity; }

    // --- what the application shows ---------------------------------------------------------

    // LED k (1..the model's LEDs) in colour c, steady or blinking; false (nothing changed) for
    // an LED it lacks, or a colour its planes cannot show.
    constexpr bool set_led(unsigned k, colour c, bool blink = false) noexcept {
        if (k < 1 || k > keypad().leds || ((keypad().led_mask >> (k - 1)) & 1u) == 0) return false;
        if (!shows(c)) return false;
        leds on = on_, bl = blink_;
        on.set(k, blink ? colour::off : c);
        bl.set(k, blink ? c : colour::off);
        return set_leds(on, bl);
    }
    // The whole picture: the LEDs on, and those that blink (both: alternate, PK1000 13); false
    // (nothing changed) when a map names an LED or a colour plane the keypad lacks.
    constexpr bool set_leds(const leds& on, const leds& blink) noexcept {
        if (!fits(on) || !fits(blink)) return false;
        if (!(on == on_)) dirty_ |= dirty_on;
        if (!(blink == blink_)) dirty_ |= dirty_blink;
        on_ = on;
        blink_ = blink;
        return true;
    }
    constexpr void set_brightness(level l) noexcept {
        if (!has_brightness_ || !(l == brightness_)) dirty_ |= dirty_brightness;
        has_brightness_ = true;
        brightness_ = l;
    }
    // The backlight level, and its colour (keep: leave the keypad's colour).
    constexpr void set_backlight(level l, backlight_colour c = backlight_colour::keep) noexcept {
        if (!has_backlight_ || !(l == backlight_level_)) dirty_ |= dirty_level;
        if (!has_backlight_ || c != backlight_colour_) dirty_ |= dirty_colour;
        has_backlight_ = true;
        backlight_level_ = l;
        backlight_colour_ = c;
    }
    // Whether an LED map holds only LEDs and colour planes the keypad has.
    [[nodiscard]] constexpr bool fits(const leds& l) const noexcept {
        for (unsigned p = 0; p < 3; ++p) {
            const std::uint64_t mask = l.of(static_cast<plane>(p)).mask();
            const std::uint64_t has = p < keypad().planes ? keypad().led_mask : 0u;
            if ((mask & ~has) != 0) return false;
        }
        return true;
    }
    // Whether the keypad can show colour c: a named colour within its colour planes.
    [[nodiscard]] constexpr bool shows(colour c) const noexcept {
        const auto planes = powerkey::detail::planes_of(c);
        return is_named(c) && (planes >> keypad().planes) == 0;
    }
    // Move the keypad to node id n (PK1000 2013h, PKP command 70h), after the requests before it.
    constexpr void change_node(canopen::node_id n) noexcept { pending_node_change_ = n; }

    // --- what it knows ----------------------------------------------------------------------

    [[nodiscard]] constexpr controller_state state() const noexcept { return state_; }
    [[nodiscard]] constexpr canopen::node_id node() const noexcept { return node_; }
    [[nodiscard]] constexpr powerkey::model model() const noexcept { return model_; }
    // The keypad's NMT state as last reported or commanded (nullopt: not known).
    [[nodiscard]] constexpr std::optional<canopen::nmt_state> keypad_state() const noexcept {
        return keypad_state_;
    }
    [[nodiscard]] constexpr key_set keys() const noexcept { return keys_.held(); }
    [[nodiscard]] constexpr const leds& led_on() const noexcept { return on_; }
    [[nodiscard]] constexpr const leds& led_blink() const noexcept { return blink_; }
    // The text of the last string read (100Bh ...), up to 16 bytes.
    [[nodiscard]] constexpr std::string_view text() const noexcept { return upload_.text(); }
    // Whether an SDO request is waiting for its reply (the controller never sends a second one).
    [[nodiscard]] constexpr bool sdo_outstanding() const noexcept { return job_.has_value(); }

private:
    // Setup steps before the configuration list, in order.
    enum setup_step : std::uint8_t { setup_identify, setup_heartbeat, setup_active, setup_list };
    static constexpr std::uint8_t dirty_on = 1, dirty_blink = 2, dirty_brightness = 4,
                                  dirty_level = 8, dirty_colour = 16, dirty_all = 31;

    struct sdo_job {
        can::frame request;  // built once: a retry sends it again
        sdo_origin origin = sdo_origin::configuration;
        std::uint16_t step = 0;
        object what = object::keys;
        canopen::sdo_address address{};
        bool read = false;
        canopen::node_id reply_node = canopen::default_node_id;  // where the reply comes from
        canopen::node_id new_node = canopen::default_node_id;    // origin node_change: the node id
    };

    // --- events -----------------------------------------------------------------------------

    // A full queue refuses the event and counts it (events_dropped).
    constexpr void emit(controller_event e) noexcept {
        if (!events_.full()) e.node = node_;  // (stamped only when kept: smaller firmware)
        (void)events_.push(e);
    }
    constexpr void emit(event_kind k) noexcept { emit(controller_event{k}); }
    constexpr void emit_key(event_kind k, unsigned key) noexcept {
        controller_event e{k};
        e.key = static_cast<std::uint8_t>(key);
        emit(e);
    }
    constexpr void emit_sdo(event_kind k, const sdo_job& j, std::uint32_t value) noexcept {
        controller_event e{k};
        e.origin = j.origin;
        e.step = j.step;
        e.what = j.what;
        e.value = value;
        emit(e);
    }

    // --- received frames --------------------------------------------------------------------

    constexpr void on_frame(const can::frame& f) noexcept {
        const auto c = canopen::classify(f);
        if (c.fn == canopen::function::heartbeat) {
            on_heartbeat(f, c.node);
        } else if (c.fn == canopen::function::sdo_tx) {
            on_sdo_reply(f, c.node);
        } else if (c.fn == canopen::function::tpdo1 && c.node == node_.value() &&
                   state_ != controller_state::searching) {
            const auto k = read_keys(f);
            if (!k) return;
            heard();
            // A keypad sends key states only when operational (PK1000 11, PKP 10).
            keypad_state_ = canopen::nmt_state::operational;
            on_keys(*k);
        }
    }

    constexpr void heard() noexcept { last_heard_ = now_; }

    constexpr void on_heartbeat(const can::frame& f, std::uint8_t from) noexcept {
        const bool ours = from == node_.value();
        if (!ours && !(cfg_.any_node && state_ == controller_state::searching)) return;
        const auto n = canopen::node_id::make(from);
        if (!n) return;
        const auto h = canopen::decode_heartbeat(f, *n);
        if (!h) return;
        const bool boot = h->state == canopen::nmt_state::boot_up;
        if (!ours && !boot) return;  // any_node adopts a boot-up only: heartbeats are everyone's
        if (!ours) {
            node_ = *n;
            upload_ = canopen::segmented_upload<16>(node_);
        }
        heard();
        keypad_state_ = boot ? canopen::nmt_state::pre_operational : h->state;
        if (state_ == controller_state::searching) {
            found(boot);
            return;
        }
        if (boot) {  // it rebooted (power, reset, node change): everything again
            if (!awaiting_boot_from_new_) emit(event_kind::rebooted);
            awaiting_boot_from_new_ = false;
            release_all();
            begin_setup(false);
            return;
        }
        // Not operational while it should be (stopped, or pre-operational after its consumer
        // heartbeat timed out, PK1000 28 note 2): start it again and resend the picture.
        if (state_ == controller_state::running && h->state != canopen::nmt_state::operational)
            start_keypad();
    }

    constexpr void found(bool boot) noexcept {
        emit(event_kind::found);
        release_all();
        // A keypad that was only silent (frames lost) and is still operational needs no setup.
        if (!boot && done_setup_once_ && keypad_state_ == canopen::nmt_state::operational) {
            state_ = controller_state::running;
            dirty_ = dirty_all;
            emit(event_kind::ready);
            return;
        }
        begin_setup(!done_setup_once_);
    }

    constexpr void begin_setup(bool first) noexcept {
        state_ = controller_state::setting_up;
        job_.reset();
        setup_pos_ = first ? setup_identify : setup_heartbeat;
        list_pos_ = 0;
        list_cut_said_ = false;
        if (first) start_written_ = false;
    }

    constexpr void on_sdo_reply(const can::frame& f, std::uint8_t from) noexcept {
        if (state_ == controller_state::searching) {
            if (from != node_.value()) return;
            heard();  // the probe was answered: the keypad is there, in an unknown state
            keypad_state_ = std::nullopt;
            found(false);
            return;
        }
        if (!job_ || !sent_ || from != job_->reply_node.value()) return;
        heard();
        const auto r = canopen::decode_sdo_response(f, job_->reply_node);
        if (!r) return;
        if (const auto* a = std::get_if<canopen::sdo_abort>(&*r)) {
            if (a->address != job_->address) return;
            emit_sdo(event_kind::sdo_aborted, *job_, static_cast<std::uint32_t>(a->code));
            finish_job();
            return;
        }
        if (job_->read) {
            // Ignore a late reply to an earlier request (another object).
            if (const auto* u = std::get_if<canopen::sdo_upload_response>(&*r);
                u && u->address != job_->address)
                return;
            if (const auto* i = std::get_if<canopen::sdo_upload_initiate_response>(&*r);
                i && i->address != job_->address)
                return;
            const auto s = upload_.step(*r);  // the reply read above, not read again
            if (!s && s.error() == errc::buffer_too_small) {  // a string longer than 16 bytes
                emit_sdo(event_kind::sdo_refused, *job_, static_cast<std::uint32_t>(s.error()));
                finish_job();
                return;
            }
            if (!s) {
                // A malformed or out-of-turn reply: keep waiting; the timeout resends.
                (void)upload_.start(job_->address);
                return;
            }
            if (s->request) {  // the next segment
                send_frame(*s->request);
                deadline_ = now_ + cfg_.sdo_timeout;
                return;
            }
            std::uint32_t v = 0;
            const auto b = upload_.bytes();
            for (std::size_t i = 0; i < b.size() && i < 4; ++i) v |= std::uint32_t{b[i]} << (8 * i);
            if constexpr (!fixed) {  // a model_constant keeps its model
                if (job_->origin == sdo_origin::identify) {
                    if (const auto m = model_from_report(upload_.text())) set_model(*m);
                }
            }
            emit_sdo(event_kind::sdo_done, *job_, v);
            finish_job();
            return;
        }
        const auto* d = std::get_if<canopen::sdo_download_response>(&*r);
        if (d == nullptr || d->address != job_->address) return;
        if (job_->origin == sdo_origin::node_change) {
            node_ = job_->new_node;
            upload_ = canopen::segmented_upload<16>(node_);
            // PKP 13 h: a boot-up from the new id follows; it is not a reboot to report.
            awaiting_boot_from_new_ = !replies_from_new_id();
            emit(event_kind::node_changed);
        }
        emit_sdo(event_kind::sdo_done, *job_, 0);
        finish_job();
    }

    constexpr void set_model(powerkey::model m) noexcept {
        if (!powerkey::detail::is_model(m)) return;
        if constexpr (!fixed) {
            model_ = m;
            layout_ = &powerkey::detail::layout(m);
        }
    }

    // --- keys -------------------------------------------------------------------------------

    constexpr void on_keys(key_set now_pressed) noexcept {
        keys_.update(now_pressed, keypad().keys, now_, cfg_,
                     [this](event_kind k, unsigned key) { emit_key(k, key); });
    }
    constexpr void key_timers() noexcept {
        keys_.tick(keypad().keys, now_, cfg_,
                   [this](event_kind k, unsigned key) { emit_key(k, key); });
    }

    // Keys held when the keypad went away are released for the application.
    constexpr void release_all() noexcept { on_keys(key_set{}); }

    // --- the time-driven part ---------------------------------------------------------------

    constexpr void run() noexcept {
        if (state_ != controller_state::searching &&
            silent_for_longer(last_heard_, now_, cfg_.lost_after)) {
            emit(event_kind::lost);
            release_all();
            state_ = controller_state::searching;
            keypad_state_ = std::nullopt;
            job_.reset();
            next_probe_ = now_;
        }
        if (state_ == controller_state::searching) probe();
        if (state_ == controller_state::setting_up) {
            sdo_timer();
            // (The timeout may have ended the setup: then it is not run again.)
            if (!job_ && state_ == controller_state::setting_up) next_setup_job();
        }
        // Not `else`: the setup may have just finished, and the picture goes out at once.
        if (state_ == controller_state::running) {
            sdo_timer();
            if (!job_) next_running_job();
            send_shadow();
            key_timers();
        }
    }

    constexpr void probe() noexcept {
        if (cfg_.probe_period.value == 0 || !reached(next_probe_, now_)) return;
        next_probe_ = now_ + cfg_.probe_period;
        if (const auto a = address_of(object::device_type))
            send_frame(canopen::encode(node_, canopen::sdo_upload_request{*a}));
    }

    constexpr void sdo_timer() noexcept {
        if (!job_) return;
        if (!sent_) {  // the outbox was full: try again
            send_job();
            return;
        }
        if (!reached(deadline_, now_)) return;
        if (attempts_ <= cfg_.sdo_retries) {
            send_job();
            return;
        }
        emit_sdo(event_kind::sdo_timed_out, *job_, 0);
        finish_job();
    }

    // The request in flight is over. The next one starts in run(), in the same call: not from
    // here, so that the reply's reading is off the stack then (firmware (c)'s worst stack).
    constexpr void finish_job() noexcept { job_.reset(); }

    constexpr void next_setup_job() noexcept {
        while (setup_pos_ < setup_list) {
            const auto s = setup_pos_;
            setup_pos_ = static_cast<std::uint8_t>(setup_pos_ + 1);
            if (s == setup_identify && cfg_.identify) {
                if (begin_read<object::model_name>(sdo_origin::identify)) return;
            } else if (s == setup_heartbeat && cfg_.keypad_heartbeat.value != 0) {
                if (begin_write<object::heartbeat_time>(cfg_.keypad_heartbeat,
                                                        sdo_origin::heartbeat))
                    return;
            } else if (s == setup_active && cfg_.start == start_mode::active_on_startup &&
                       !start_written_) {
                start_written_ = true;
                if (begin_active()) return;
            }
        }
        const std::size_t entries = cfg_.configuration.size() < max_configuration
                                        ? cfg_.configuration.size()
                                        : max_configuration;
        while (list_pos_ < entries) {
            // A refused entry is an event: with the queue full, the setup waits for a poll.
            if (events_.full()) return;
            const auto i = list_pos_++;
            if (begin_job(cfg_.configuration[i], sdo_origin::configuration,
                          static_cast<std::uint16_t>(i)))
                return;
        }
        if (cfg_.configuration.size() > max_configuration && !list_cut_said_) {
            if (events_.full()) return;
            list_cut_said_ = true;
            controller_event e{event_kind::sdo_refused};
            e.step = static_cast<std::uint16_t>(max_configuration);
            e.value = static_cast<std::uint32_t>(errc::value_out_of_range);
            emit(e);
        }
        // Ready is an event too: it waits for room as the refusals do.
        if (events_.full()) return;
        // Set up: start it and show the picture.
        done_setup_once_ = true;
        state_ = controller_state::running;
        start_keypad();
        emit(event_kind::ready);
        // (run() goes on to the running state's jobs and the picture in the same call.)
    }

    // Active on startup: the PKP-LI's command 7Ah, 2012h elsewhere.
    constexpr bool begin_active() noexcept {
        if (keypad().dictionary == dictionary::pkp_li) {
            return begin_command<command_code::set_active_on_startup>(true, sdo_origin::start);
        }
        return begin_write<object::active_on_startup>(true, sdo_origin::start);
    }

    constexpr void start_keypad() noexcept {
        const auto target = canopen::nmt_target::make(node_.value()).value();
        if (send_frame(
                canopen::encode(canopen::nmt_message{canopen::nmt_command::start, target}))) {
            keypad_state_ = canopen::nmt_state::operational;
            dirty_ = dirty_all;  // a started keypad shows what it was last sent, or its defaults
        }
    }

    // While running: a node change, then the shadow values that travel by SDO (PKP).
    constexpr void next_running_job() noexcept {
        if (pending_node_change_ && begin_node_change()) return;
        // The shadow values this model takes by SDO only (no RPDO3/RPDO4 for them).
        if (take(dirty_brightness, !keypad().brightness_pdo && has_brightness_)) {
            // By SDO write of the object. (The command module 6500h could set it too, but the one
            // dictionary with the module, the PKP's, also has the objects: 6201h sub 1 and 2.)
            if (has<object::led_brightness>() &&
                begin_write<object::led_brightness>(brightness_, sdo_origin::shadow))
                return;
        }
        if (take(dirty_level, !keypad().backlight_pdo && has_backlight_)) {
            if (has<object::backlight_level>() &&
                begin_write<object::backlight_level>(backlight_level_, sdo_origin::shadow))
                return;
        }
        if (take(dirty_colour, !colour_by_pdo() && has_backlight_ &&
                                   backlight_colour_ != backlight_colour::keep)) {
            if (has<object::backlight_colour>()) {
                if (begin_write<object::backlight_colour>(backlight_colour_, sdo_origin::shadow))
                    return;
            } else if (has<object::command_module>()) {
                if (begin_command<command_code::set_backlight_colour>(backlight_colour_,
                                                                      sdo_origin::shadow))
                    return;
            }
        }
    }

    // The node change asked for (change_node): started, or refused (reported).
    constexpr bool begin_node_change() noexcept {
        const auto n = *pending_node_change_;
        pending_node_change_.reset();
        if (!(keypad().dictionary == dictionary::pkp_li
                  ? begin_command<command_code::set_node_id>(n, sdo_origin::node_change)
                  : begin_write<object::node_id>(n, sdo_origin::node_change)))
            return false;
        job_->new_node = n;
        if (replies_from_new_id()) job_->reply_node = n;  // PK1000 23
        return true;
    }

    // Clears dirty bit `bit` when `mine` (the SDO path owns it) or there is nothing to send.
    constexpr bool take(std::uint8_t bit, bool mine) noexcept {
        if ((dirty_ & bit) == 0) return false;
        const bool pdo_owned = (bit == dirty_brightness && keypad().brightness_pdo) ||
                               (bit == dirty_level && keypad().backlight_pdo) ||
                               (bit == dirty_colour && colour_by_pdo());
        if (pdo_owned) return false;  // send_shadow's
        dirty_ = static_cast<std::uint8_t>(dirty_ & ~bit);
        return mine;
    }
    // Whether the model's dictionary has object O (a constant for a model_constant); o's address.
    template <object O>
    constexpr bool has() const noexcept {
        if constexpr (fixed) {
            constexpr bool known = powerkey::detail::find_codec_row(
                                       powerkey::detail::fixed_layout_v<Keypad::value>, O) != 0;
            return known;
        } else {
            return powerkey::detail::find_codec_row(keypad(), O) != 0;
        }
    }
    constexpr std::optional<canopen::sdo_address> address_of(object o) const noexcept {
        const std::uint8_t i = powerkey::detail::find_codec_row(keypad(), o);
        if (i == 0) return std::nullopt;
        return powerkey::detail::codec_row_at(keypad(), i).address();
    }
    constexpr bool colour_by_pdo() const noexcept {
        return keypad().backlight_pdo && keypad().backlight_colour;
    }

    // Starts a configuration entry's request; false when refused (reported) or skipped.
    constexpr bool begin_job(const entry& e, sdo_origin origin, std::uint16_t step) noexcept {
        if constexpr (fixed) {
            if (e.skipped()) return false;
            return begin_request(e.frame(node_), e.what(), e.read(), origin, step);
        } else {
            object o = object::command_module;
            bool read = false;
            if (const auto* r = std::get_if<sdo_read>(&e)) {
                o = r->object;
                read = true;
            } else if (const auto* w = std::get_if<sdo_write>(&e)) {
                o = w->object;
            } else if (!std::holds_alternative<command>(e)) {
                return false;  // not an SDO request: skipped
            }
            return begin_request(frame_of(e), o, read, origin, step);
        }
    }
    // The controller's own requests, each a function of one value (detail::read_of, write_of,
    // command_of): for a model_constant proven when the program is built where they can be
    // (detail::own_proof), else checked with M's constants (docs/controller.md, "One model").
    template <object O>
    constexpr bool begin_read(sdo_origin origin) noexcept {
        return begin_request(own<&detail::read_of<O>>(std::monostate{}), O, true, origin, 0);
    }
    template <object O, class V>
    constexpr bool begin_write(V v, sdo_origin origin) noexcept {
        return begin_request(own<&detail::write_of<O, V>>(v), O, false, origin, 0);
    }
    template <command_code C, class V>
    constexpr bool begin_command(V v, sdo_origin origin) noexcept {
        return begin_request(own<&detail::command_of<C, V>>(v), object::command_module, false,
                             origin, 0);
    }
    template <auto Make, class V>
    constexpr result<can::frame> own(V v) const noexcept {
        if constexpr (!fixed)
            return frame_of(Make(v));
        else if constexpr (detail::own_proof<Keypad::value, Make, V>.proven)
            return detail::own_proof<Keypad::value, Make, V>.frame(node_, detail::raw_of(v));
        else
            return own_checked<Make>(v);
    }
    template <auto Make, class V>
    POWERKEY_DETAIL_FLATTEN constexpr result<can::frame> own_checked(V v) const noexcept {
        return powerkey::detail::own_frame(keypad(), node_, Make(v));
    }

    // Starts an SDO request of object `what` with its frame f, or reports the error in f.
    constexpr bool begin_request(const result<can::frame>& f, object what, bool read,
                                 sdo_origin origin, std::uint16_t step) noexcept {
        // Built in place (no request is in flight here): a copy on the stack cost firmware (c)'s
        // deepest call its size.
        sdo_job& j = job_.emplace();
        j.origin = origin;
        j.step = step;
        j.reply_node = node_;
        j.read = read;
        j.what = what;
        const auto address = address_of(what);
        if (!address || !f) {
            emit_sdo(event_kind::sdo_refused, j,
                     static_cast<std::uint32_t>(f ? errc::unknown_object : f.error()));
            job_.reset();
            return false;
        }
        j.address = *address;
        j.request = *f;
        attempts_ = 0;
        sent_ = false;
        transmit_job(*f);
        return true;
    }

    // The request again (a retry, or the outbox was full).
    constexpr void send_job() noexcept {
        if (job_) transmit_job(job_->request);
    }
    constexpr void transmit_job(const can::frame& f) noexcept {
        if (job_->read) (void)upload_.start(job_->address);
        if (!send_frame(f)) return;
        sent_ = true;
        ++attempts_;
        deadline_ = now_ + cfg_.sdo_timeout;
    }

    // The shadow's PDOs, only to an operational keypad (it ignores PDOs otherwise, PK1000 11).
    constexpr void send_shadow() noexcept {
        if (keypad_state_ != canopen::nmt_state::operational) return;
        if (cfg_.refresh_period.value != 0 && reached(next_refresh_, now_)) {
            dirty_ |= dirty_on | dirty_blink;
            next_refresh_ = now_ + cfg_.refresh_period;
        }
        if ((dirty_ & dirty_on) != 0 && send_message(powerkey::led_on{on_}))
            dirty_ = static_cast<std::uint8_t>(dirty_ & ~dirty_on);
        if ((dirty_ & dirty_blink) != 0 && send_message(powerkey::led_blink{blink_}))
            dirty_ = static_cast<std::uint8_t>(dirty_ & ~dirty_blink);
        if (keypad().brightness_pdo && (dirty_ & dirty_brightness) != 0 &&
            (!has_brightness_ || send_message(led_brightness{brightness_})))
            dirty_ = static_cast<std::uint8_t>(dirty_ & ~dirty_brightness);
        const std::uint8_t pdo_bits =
            static_cast<std::uint8_t>(dirty_level | (colour_by_pdo() ? dirty_colour : 0));
        if (keypad().backlight_pdo && (dirty_ & pdo_bits) != 0 &&
            (!has_backlight_ ||
             send_message(backlight{backlight_level_,
                                    colour_by_pdo() ? backlight_colour_ : backlight_colour::keep})))
            dirty_ = static_cast<std::uint8_t>(dirty_ & ~pdo_bits);
    }

    template <class T>
    constexpr bool send_message(const T& msg) noexcept {
        const auto f = frame_of(msg);
        if (!f) return true;  // nothing this model can carry: not retried
        return send_frame(*f);
    }
    constexpr bool send_frame(const can::frame& f) noexcept { return outbox_.push(f); }

    // The model's layout (the codec's part of its row): M's alone for a model_constant.
    constexpr const auto& keypad() const noexcept {
        if constexpr (fixed)
            return powerkey::detail::fixed_layout_v<Keypad::value>;
        else
            return *layout_;
    }
    // After a node-id change the keypad answers from the new id (model_info::replies_from_new_id).
    constexpr bool replies_from_new_id() const noexcept {
        if constexpr (fixed)
            return powerkey::detail::row_of(Keypad::value).replies_from_new_id;
        else
            return powerkey::detail::row_or_none(model_).replies_from_new_id;
    }
    // The run-time model's layout; nothing for a model_constant (no member bytes).
    struct no_layout {};
    using layout_pointer =
        std::conditional_t<fixed, no_layout, const powerkey::detail::model_layout*>;
    static constexpr layout_pointer layout_of(const config& c) noexcept {
        if constexpr (fixed)
            return {};
        else
            return &powerkey::detail::layout_or_none(c.keypad_model);
    }
    static constexpr powerkey::model model_of(const config& c) noexcept {
        if constexpr (fixed)
            return Keypad::value;
        else
            return c.keypad_model;
    }
    // The keys of the keypad's key-state PDO (TPDO1), as decode reads it; nullopt for a frame
    // decode refuses. One of model M reads the key state alone (decode_key_state<M>).
    constexpr std::optional<key_set> read_keys(const can::frame& f) const noexcept {
        if constexpr (fixed) {
            const auto k = decode_key_state<Keypad::value>(f, node_);
            if (!k) return std::nullopt;
            return k->keys;
        } else {
            const auto m = decode_canopen(f, node_, model_);
            if (!m) return std::nullopt;
            return powerkey::pressed_keys(*m);  // TPDO1 decodes as a key state or not at all
        }
    }
    // Every message it sends checks its own fields (encode's own checks): no decoder needed.
    template <class T>
    constexpr result<can::frame> frame_of(const T& msg) const noexcept {
        if (!fixed && !powerkey::detail::is_model(model_)) return errc::value_out_of_range;
        return powerkey::detail::own_frame(keypad(), node_, msg);
    }
    // An SDO request: sdo_read, sdo_write or command (begin_job takes no other).
    constexpr result<can::frame> frame_of(const message& msg) const noexcept {
        if (std::holds_alternative<sdo_read>(msg)) return frame_of(std::get<sdo_read>(msg));
        if (std::holds_alternative<sdo_write>(msg)) return frame_of(std::get<sdo_write>(msg));
        if (std::holds_alternative<command>(msg)) return frame_of(std::get<command>(msg));
        return errc::unknown_command;
    }

    // (Members in an order that leaves no padding between them: firmware (c) keeps the
    // controller on its stack.)
    config cfg_;
    powerkey::model model_;
    [[no_unique_address]] layout_pointer layout_;  // any_model: detail::layout_or_none
    canopen::node_id node_;
    controller_state state_ = controller_state::searching;
    std::optional<canopen::nmt_state> keypad_state_;
    bool done_setup_once_ = false;
    bool start_written_ = false;
    bool awaiting_boot_from_new_ = false;
    std::uint8_t setup_pos_ = setup_identify;
    bool list_cut_said_ = false;
    millis now_{};
    millis last_heard_{};
    millis next_probe_{};
    millis next_refresh_{};
    std::size_t list_pos_ = 0;

    // The one SDO request in flight, and the node change asked for.
    std::optional<sdo_job> job_;
    bool sent_ = false;
    std::uint8_t attempts_ = 0;
    std::optional<canopen::node_id> pending_node_change_;
    millis deadline_{};
    canopen::segmented_upload<16> upload_;

    // The shadow.
    leds on_{};
    leds blink_{};
    level brightness_ = 0x3F;
    level backlight_level_ = 0;
    backlight_colour backlight_colour_ = backlight_colour::keep;
    bool has_brightness_ = false;
    bool has_backlight_ = false;
    std::uint8_t dirty_ = dirty_all;

    // Keys.
    key_timing<event_kind> keys_{};

    frame_queue<OutboxCapacity> outbox_{};
    fixed_queue<controller_event, EventCapacity> events_{};
};

}  // namespace powerkey::behaviour

POWERKEY_DETAIL_ENUM_NAMES(powerkey::behaviour::event_kind, POWERKEY_BEHAVIOUR_EVENT_KIND_LIST);
POWERKEY_DETAIL_ENUM_NAMES(powerkey::behaviour::sdo_origin, POWERKEY_BEHAVIOUR_SDO_ORIGIN_LIST);
POWERKEY_DETAIL_ENUM_NAMES(powerkey::behaviour::controller_state,
                           POWERKEY_BEHAVIOUR_CONTROLLER_STATE_LIST);
POWERKEY_DETAIL_ENUM_NAMES(powerkey::behaviour::start_mode, POWERKEY_BEHAVIOUR_START_MODE_LIST);

#endif  // POWERKEY_BEHAVIOUR_CONTROLLER_HPP
