// powerkey: a bus-log checker: it follows one keypad through a log (session.hpp) and reports what
// the host or the keypad did that breaks the keypad's behaviour, each with its input line
// (docs/checker.md: each kind, with the manual behaviour it comes from).
#ifndef POWERKEY_BEHAVIOUR_CHECKER_HPP
#define POWERKEY_BEHAVIOUR_CHECKER_HPP

#include <powerkey/behaviour/clock.hpp>
#include <powerkey/behaviour/j1939_checks.hpp>
#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/error.hpp>
#include <powerkey/frame_form.hpp>
#include <powerkey/keypad/commands.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/result.hpp>
#include <powerkey/session.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <variant>

namespace powerkey::behaviour {

// How much a kind weighs: a problem fails a check (powerkey check's exit status), a warning does
// not.
// clang-format off
#define POWERKEY_BEHAVIOUR_SEVERITY_LIST(X) \
    X(problem) \
    X(warning)
// clang-format on
enum class severity : std::uint8_t { POWERKEY_BEHAVIOUR_SEVERITY_LIST(POWERKEY_DETAIL_ENUMERATOR) };

// X(name, severity, what it means, its explanation): the explanation is text with the details
// in braces: {N} detail N in decimal, {N:xW} in hex of W digits, {N:at} the object index N and
// sub-index N+1, {N:frame} "frame <id>h of <dlc> bytes" (id N, dlc N+1), {N:abort}, {N:nmt},
// {N:errc}, {N:model}, {N:form} the name of detail N, {N?a|b} a when detail N is 0, else b. The
// J1939 kinds are explained by j1939_checks.hpp.
// clang-format off
#define POWERKEY_BEHAVIOUR_PROBLEM_KIND_LIST(X) \
    X(sdo_overlap, problem, "a request while another is outstanding: the keypad drops it", \
      "SDO request sent while the request of line {0} ({1:at}) is unanswered: the keypad drops it (one request at a time)") \
    X(sdo_no_reply, problem, "a request never answered within the SDO timeout", \
      "SDO request {0:at} never answered ({2} ms without a reply)") \
    X(sdo_abort, problem, "the keypad aborted a request", \
      "the keypad aborted {1:at} with {0:x8}h: {0:abort}") \
    X(pdo_not_operational, problem, "an RPDO to a keypad that is not operational: it ignores it", \
      "PDO {0:x3}h sent while the keypad is {1:nmt}: it ignores PDOs until an NMT start") \
    X(heartbeat_silence, problem, "no heartbeat for longer than the configured period allows", \
      "no heartbeat for {0} ms since line {2}, the configured period is {1} ms") \
    X(key_state_silence, problem, "no key state for longer than the periodic transmission allows", \
      "no key state for {0} ms since line {2}, the configured period is {1} ms") \
    X(old_node_traffic, problem, "a frame to the node id the keypad left", \
      "frame {0:x3}h to the old node id {1:x2}h: the keypad moved to {2:x2}h and does not answer it") \
    X(segment_toggle, problem, "a segment request or response with the wrong toggle bit", \
      "{2?segment request|segment response} with toggle bit {1}, expected {0}" \
      "{2?: the keypad aborts with 05030000h|: the keypad repeated or skipped a segment}") \
    X(segment_size, problem, "a segmented upload whose bytes do not match the size it announced", \
      "segmented upload of {2:x4}h announced {0} bytes and sent {1}") \
    X(refused_frame, problem, "a frame to the keypad that the decoder refuses: the keypad does not act on it", \
      "{1:frame} refused ({0:errc}): the keypad does not act on it") \
    X(wrong_model, problem, "most keypad frames of the log are refused: the keypad is likely another model", \
      "{0} of {1} keypad frames refused as {2:model} frames: the keypad is likely another model") \
    X(not_manual_form, warning, "a frame trimmed or padded: the keypads act on it, a strict reader refuses it", \
      "{0:frame} is {2:form}, not the manual's form: read as the manual's form, as the keypads do") \
    X(j1939_bad_header, problem, "a J1939 frame to the keypad without the 04 1B header, or with a command byte no keypad has", \
      "") /* detail: identifier, bytes 0..2, 0 */ \
    X(j1939_multiple_leds_off, problem, "a J1939 multiple-LED command while LED management (37h) is single LED only", \
      "") /* detail: identifier, line of the 37h (0: the default), 0 */ \
    X(j1939_no_keypad, problem, "a J1939 command to an address no keypad holds", \
      "") /* detail: identifier, destination, the keypad's address */ \
    X(j1939_address_conflict, problem, "two J1939 address claims of one address with different NAMEs", \
      "") /* detail: identifier, the address, line of the other claim */ \
    X(j1939_bad_source, problem, "a J1939 keypad frame from the global address FFh, or from the null address FEh other than an address claim", \
      "") /* detail: identifier, the source address, 0 */
// clang-format on
#define POWERKEY_BEHAVIOUR_DETAIL_KIND_ENUMERATOR(name, ...) name,
enum class problem_kind : std::uint8_t {
    POWERKEY_BEHAVIOUR_PROBLEM_KIND_LIST(POWERKEY_BEHAVIOUR_DETAIL_KIND_ENUMERATOR)
};
#undef POWERKEY_BEHAVIOUR_DETAIL_KIND_ENUMERATOR

// The row of a kind: its severity and what it means (one sentence, for reports' headings).
struct problem_kind_info {
    problem_kind kind;
    behaviour::severity severity;
    std::string_view summary;
};

#define POWERKEY_BEHAVIOUR_DETAIL_KIND_ROW(name, sev, text, ...) \
    problem_kind_info{problem_kind::name, severity::sev, text},
inline constexpr problem_kind_info problem_kinds[] = {
    POWERKEY_BEHAVIOUR_PROBLEM_KIND_LIST(POWERKEY_BEHAVIOUR_DETAIL_KIND_ROW)};
#undef POWERKEY_BEHAVIOUR_DETAIL_KIND_ROW
inline constexpr std::size_t problem_kind_count = std::size(problem_kinds);
static_assert([] {
    for (std::size_t i = 0; i < problem_kind_count; ++i)
        if (static_cast<std::size_t>(problem_kinds[i].kind) != i) return false;
    return true;
}());

namespace detail {
// The J1939 kinds are the last, in j1939_fault's order: kind = offset + fault.
inline constexpr std::size_t j1939_kind_offset =
    static_cast<std::size_t>(problem_kind::j1939_bad_header);
constexpr problem_kind j1939_kind(j1939_fault f) noexcept {
    return static_cast<problem_kind>(j1939_kind_offset + static_cast<std::size_t>(f));
}
static_assert(j1939_kind(j1939_fault::multiple_leds_off) == problem_kind::j1939_multiple_leds_off &&
              j1939_kind(j1939_fault::no_keypad) == problem_kind::j1939_no_keypad &&
              j1939_kind(j1939_fault::address_conflict) == problem_kind::j1939_address_conflict &&
              j1939_kind(j1939_fault::bad_source) == problem_kind::j1939_bad_source &&
              problem_kind_count == j1939_kind_offset + 5);
}  // namespace detail

[[nodiscard]] constexpr severity severity_of(problem_kind k) noexcept {
    return problem_kinds[static_cast<std::size_t>(k) % problem_kind_count].severity;
}
[[nodiscard]] constexpr std::string_view summary_of(problem_kind k) noexcept {
    return problem_kinds[static_cast<std::size_t>(k) % problem_kind_count].summary;
}

struct problem {
    std::uint32_t line = 0;
    problem_kind kind = problem_kind::sdo_overlap;
    std::array<std::uint32_t, 3> detail{};
    friend constexpr bool operator==(const problem&, const problem&) noexcept = default;
};

struct checker_config {
    model keypad_model = model::pk1000;
    canopen::node_id node = canopen::default_node_id;
    // Unanswered this long, a request is sdo_no_reply, and one after it no overlap (checker.md).
    duration_ms sdo_timeout{200};
    // Silence allowed beyond a configured period, in percent of it (50: 1.5 periods).
    std::uint32_t tolerance_percent = 50;
    // Periods in force before the log starts (0: not known; the log's own writes set them).
    duration_ms heartbeat_period{0};  // 1017h
    duration_ms key_state_period{0};  // PK1000 1800h sub 5, PKP command 12h
    // The keypad's J1939 address (session::narrow_j1939), or nullopt for any (docs/checker.md).
    j1939::keypad_address j1939_address = std::nullopt;
};

template <std::size_t TextCapacity = 64>
class checker {
public:
    // The most problems one step() finds: the five the time brings (sdo_no_reply, and
    // heartbeat_silence and key_state_silence of CANopen and of J1939, timed apart) and two the
    // frame does (a segment response with the wrong toggle that ends an upload of the wrong size,
    // which is never trimmed or padded: it uses all 8 bytes; a refused request sent while
    // another is outstanding; any other frame shows at most one). finish() finds at most six:
    // the five of the time and wrong_model.
    static constexpr std::size_t max_problems_per_frame = 7;

    constexpr explicit checker(const checker_config& c) noexcept
        : cfg_(c),
          session_(make_session(c)),
          j1939_(c.keypad_model, session_.j1939_address()),
          hb_{c.heartbeat_period.value, std::nullopt, false},
          ks_{c.key_state_period.value, std::nullopt, false} {}

    // One frame of the log, received at `t`, from input line `line`: the problems it shows.
    [[nodiscard]] constexpr std::span<const problem> step(const can::frame& f, millis t,
                                                          std::uint32_t line) noexcept {
        count_ = 0;
        now_ = t;
        line_ = line;
        timers();
        const auto c = canopen::classify(f);
        old_node(f, c);
        const canopen::node_id before = session_.node();
        const std::uint8_t address = session_.j1939_address();
        const auto e = session_.step(f);
        if (c.fn == canopen::function::j1939)
            j1939(f, e, address);
        else
            form(f, e);
        if (e.sdo == sdo_pairing::request) {
            on_request(e);
        } else if (e.cls.fn == canopen::function::sdo_tx &&
                   (e.sdo == sdo_pairing::reply || e.sdo == sdo_pairing::unanswered)) {
            on_response(e);
        }
        if (c.fn == canopen::function::heartbeat && c.node == consumer_producer_ &&
            consumer_period_ != 0 && f.size() == 1 && f[0] != 0x00)
            consumer_last_ = now_;  // the heartbeat the keypad consumes (1016h), a boot-up not
        if (e.decoded) on_message(*e.decoded, c);
        if (e.new_node && *e.new_node != before) {
            old_ = before;
            if (old_ == session_.node()) old_.reset();
        }
        return {found_.data(), count_};
    }

    // The end of the log at `t` (the last frame's time): requests still unanswered.
    [[nodiscard]] constexpr std::span<const problem> finish(millis t) noexcept {
        count_ = 0;
        now_ = t;
        timers();
        // The same rule as powerkey decode's hint: at least 3, and at least a fifth, refused.
        if (refused_ >= 3 && std::uint64_t{refused_} * 5 >= keypad_frames_ && !model_reported_) {
            model_reported_ = true;
            report(first_refused_line_, problem_kind::wrong_model, refused_, keypad_frames_,
                   static_cast<std::uint32_t>(cfg_.keypad_model));
        }
        return {found_.data(), count_};
    }

    // How many problems (or warnings) of kind k the log showed so far, those dropped included.
    [[nodiscard]] constexpr std::uint32_t count(problem_kind k) const noexcept {
        return counts_[static_cast<std::size_t>(k) % problem_kind_count];
    }
    // The frames of the keypad seen, and how many of them the decoder refused (docs/checker.md).
    [[nodiscard]] constexpr std::uint32_t keypad_frames() const noexcept { return keypad_frames_; }
    [[nodiscard]] constexpr std::uint32_t refused_frames() const noexcept { return refused_; }

    // Problems a step() or finish() found past max_problems_per_frame, not returned (0 unless
    // the bound above is wrong: the fuzz target `behaviour` checks it).
    [[nodiscard]] constexpr std::size_t problems_dropped() const noexcept { return dropped_; }

    [[nodiscard]] constexpr const session<TextCapacity>& follower() const noexcept {
        return session_;
    }
    [[nodiscard]] constexpr std::optional<canopen::nmt_state> keypad_state() const noexcept {
        return state_;
    }

private:
    static constexpr session<TextCapacity> make_session(const checker_config& c) noexcept {
        session<TextCapacity> s(c.keypad_model, c.node);
        s.narrow_j1939(c.j1939_address);
        return s;
    }

    constexpr void report(std::uint32_t line, problem_kind k, std::uint32_t a, std::uint32_t b,
                          std::uint32_t c) noexcept {
        ++counts_[static_cast<std::size_t>(k) % problem_kind_count];
        if (count_ < found_.size())
            found_[count_++] = problem{line, k, {a, b, c}};
        else
            ++dropped_;
    }

    constexpr std::uint32_t allowed(std::uint32_t period) const noexcept {
        return period +
               static_cast<std::uint32_t>(std::uint64_t{period} * cfg_.tolerance_percent / 100);
    }

    // Deadlines that passed before this frame. A time before the last one (a log that goes back,
    // or two logs in a row) restarts the timers rather than reading as a 49-day silence.
    constexpr void timers() noexcept {
        if (before(now_, last_time_)) {
            if (pending_) pending_->sent = now_;
            if (consumer_last_) consumer_last_ = now_;
            hb_.restart(now_);
            ks_.restart(now_);
            for (const auto t : {j1939_timer::heartbeat, j1939_timer::key_state})
                j1939_.timer(t).restart(now_);
        }
        last_time_ = now_;
        if (pending_ && elapsed(pending_->sent, now_).value >= cfg_.sdo_timeout.value) {
            report(pending_->line, problem_kind::sdo_no_reply, pending_->address.index,
                   pending_->address.subindex, elapsed(pending_->sent, now_).value);
            pending_.reset();
        }
        silence(hb_, problem_kind::heartbeat_silence, allowed(hb_.period));
        // PK1000 28 note 2: the heartbeat the keypad consumes (1016h) stopped: pre-operational.
        if (consumer_period_ != 0 && consumer_last_ &&
            elapsed(*consumer_last_, now_).value > consumer_period_) {
            consumer_last_.reset();
            if (state_ == canopen::nmt_state::operational)
                set_state(canopen::nmt_state::pre_operational);
        }
        if (state_ == canopen::nmt_state::operational)
            silence(ks_, problem_kind::key_state_silence, allowed(ks_.period));
        // J1939 (j1939_checks.hpp): the same kinds, from 75h, 71h and 77h.
        auto& jh = j1939_.timer(j1939_timer::heartbeat);
        silence(jh, problem_kind::heartbeat_silence, allowed(jh.period));
        auto& jk = j1939_.timer(j1939_timer::key_state);
        silence(jk, problem_kind::key_state_silence, allowed(jk.period));
    }
    // A silence of s longer than `limit` ms: a problem of kind k.
    constexpr void silence(silence_timer& s, problem_kind k, std::uint32_t limit) noexcept {
        if (const auto d = s.overdue(now_, limit)) report(line_, k, (*d)[0], (*d)[1], (*d)[2]);
    }

    // How the frame was written, and whether the keypad can act on it: refused_frame (not a SYNC
    // with data), wrong_model's count, not_manual_form (docs/checker.md, the table).
    constexpr void form(const can::frame& f, const session_event& e) noexcept {
        if (e.decoded) {
            ++keypad_frames_;
            const auto how = form_of(*e.decoded);
            if (how != frame_form::manual)
                report(line_, problem_kind::not_manual_form, f.raw_id(), f.size(),
                       static_cast<std::uint32_t>(how));
            return;
        }
        const errc why = e.decoded.error();
        if (why == errc::wrong_id && !canopen::concerns(e.cls, e.node))
            return;  // not the keypad's: another node's, or no keypad function
        count_refused();
        if (from_host(e.cls.fn))
            report(line_, problem_kind::refused_frame, static_cast<std::uint32_t>(why), f.raw_id(),
                   f.size());
    }
    // What the host sends the keypad: NMT, its SDO requests and its RPDOs.
    static constexpr bool from_host(canopen::function fn) noexcept {
        using canopen::function;
        return fn == function::nmt || fn == function::sdo_rx || fn == function::rpdo1 ||
               fn == function::rpdo2 || fn == function::rpdo3 || fn == function::rpdo4;
    }

    constexpr void count_refused() noexcept {
        ++keypad_frames_;
        if (refused_++ == 0) first_refused_line_ = line_;
    }

    // A 29-bit frame (j1939_checks.hpp; docs/checker.md, "J1939").
    constexpr void j1939(const can::frame& f, const session_event& e,
                         std::uint8_t address) noexcept {
        const auto r = j1939_.step(f, e, address, session_.j1939_address(), line_, now_);
        if (e.decoded)
            ++keypad_frames_;
        else if (r.keypads && e.decoded.error() != errc::wrong_id)  // not another keypad's
            count_refused();
        if (r.finding) {
            report(line_, detail::j1939_kind(r.finding->fault), r.finding->detail[0],
                   r.finding->detail[1], r.finding->detail[2]);
        } else if (r.to_keypad && !e.decoded && e.decoded.error() != errc::wrong_id) {
            report(line_, problem_kind::refused_frame,
                   static_cast<std::uint32_t>(e.decoded.error()), f.raw_id(), f.size());
        }
    }

    // A host frame to the node id the keypad left (PK1000 23, PKP 13 h): nobody answers it.
    constexpr void old_node(const can::frame& f, const canopen::cob_info& c) noexcept {
        if (!old_) return;
        const std::uint8_t o = old_->value();
        if (c.fn == canopen::function::nmt ? f.size() == 2 && f[1] == o
                                           : from_host(c.fn) && c.node == o)
            report(line_, problem_kind::old_node_traffic, f.raw_id(), o, session_.node().value());
    }

    // The SDO frames as the session read them (e.sdo_frame), with what decode returned.
    constexpr void on_request(const session_event& e) noexcept {
        if (!e.sdo_frame) return;
        const auto op = e.sdo_frame->op;
        if (op == canopen::sdo_op::abort_request) {  // the host ends the transfer
            pending_.reset();
            segmented_ = false;
            return;
        }
        const auto* s =
            e.decoded ? std::get_if<canopen::sdo_segment_request>(&*e.decoded) : nullptr;
        const canopen::sdo_address a =
            op == canopen::sdo_op::segment_request ? segment_address_ : e.sdo_frame->address;
        if (pending_) {  // the keypad still owes a reply: it drops this one
            report(line_, problem_kind::sdo_overlap, pending_->line, pending_->address.index,
                   pending_->address.subindex);
            return;
        }
        if (s != nullptr && segmented_) {
            if (s->toggle != expect_toggle_)
                report(line_, problem_kind::segment_toggle, expect_toggle_ ? 1u : 0u,
                       s->toggle ? 1u : 0u, 0);
            request_toggle_ = s->toggle;
            expect_toggle_ = !s->toggle;
        }
        if (op != canopen::sdo_op::segment_request) segmented_ = false;  // a new transfer
        pending_ = outstanding{line_, now_, a};
    }

    constexpr void on_response(const session_event& e) noexcept {
        if (!e.sdo_frame) return;
        const bool answers = pending_.has_value();
        pending_.reset();
        const auto* msg = e.decoded ? &*e.decoded : nullptr;
        switch (e.sdo_frame->op) {
            case canopen::sdo_op::abort_response: {
                const auto* a = msg ? std::get_if<canopen::sdo_abort_response>(msg) : nullptr;
                report(line_, problem_kind::sdo_abort,
                       a ? static_cast<std::uint32_t>(a->abort.code) : 0u,
                       e.sdo_frame->address.index, e.sdo_frame->address.subindex);
                segmented_ = false;
                return;
            }
            case canopen::sdo_op::upload_initiate:
                segmented_ = answers;
                expect_toggle_ = false;
                segment_address_ = e.sdo_frame->address;
                return;
            case canopen::sdo_op::segment: {
                const auto* s = msg ? std::get_if<canopen::sdo_segment_response>(msg) : nullptr;
                if (!segmented_ || s == nullptr) return;
                if (s->toggle != request_toggle_)
                    report(line_, problem_kind::segment_toggle, request_toggle_ ? 1u : 0u,
                           s->toggle ? 1u : 0u, 1);
                if (s->last) {
                    segmented_ = false;
                    if (e.upload_done) upload_size();
                }
                return;
            }
            default: return;
        }
    }

    // The keypads pad strings with NUL bytes past the announced size (E-CORE-2, E-CORE-5): only
    // a count that matches neither with nor without them is a size error.
    constexpr void upload_size() noexcept {
        const auto& u = session_.upload();
        const auto announced = u.announced_size();
        if (!announced) return;
        std::uint32_t nul = 0;
        for (const auto b : u.bytes()) nul += b == 0 ? 1u : 0u;
        const auto got = static_cast<std::uint32_t>(u.bytes().size());
        if (got != *announced && got - nul != *announced)
            report(line_, problem_kind::segment_size, *announced, got, u.address().index);
    }

    constexpr void set_state(canopen::nmt_state s) noexcept {
        if (state_ != s) pdo_reported_ = false;
        if (s != canopen::nmt_state::operational) ks_.last.reset();
        state_ = s;
    }

    constexpr void on_message(const message& msg, const canopen::cob_info& c) noexcept {
        const auto node = session_.node();
        if (const auto* n = std::get_if<canopen::nmt_message>(&msg)) {
            if (n->target.value() != 0 && n->target.value() != node.value()) return;
            using cmd = canopen::nmt_command;
            // A reset (node or communication) ends in pre-operational too.
            set_state(n->command == cmd::start ? canopen::nmt_state::operational
                      : n->command == cmd::stop || n->command == cmd::legacy_stop
                          ? canopen::nmt_state::stopped
                          : canopen::nmt_state::pre_operational);
            return;
        }
        if (c.node != node.value()) return;
        if (const auto* h = std::get_if<canopen::heartbeat_message>(&msg)) {
            if (h->state == canopen::nmt_state::boot_up) {
                // Booted into pre-operational, or operational when set active on startup (PK1000
                // 22, PKP 13 d). A reboot loses the request in progress and restarts monitoring.
                set_state(active_ ? canopen::nmt_state::operational
                                  : canopen::nmt_state::pre_operational);
                pending_.reset();
                segmented_ = false;
                hb_.last.reset();
                hb_.reported = false;
            } else {
                set_state(h->state);
                hb_.heard(now_, line_);
            }
            return;
        }
        if (std::holds_alternative<key_state>(msg)) {
            set_state(canopen::nmt_state::operational);  // it sends key states only then
            ks_.heard(now_, line_);
            return;
        }
        if (std::holds_alternative<led_on>(msg) || std::holds_alternative<led_blink>(msg) ||
            std::holds_alternative<led_brightness>(msg) || std::holds_alternative<backlight>(msg)) {
            if (state_ && *state_ != canopen::nmt_state::operational && !pdo_reported_) {
                pdo_reported_ = true;
                report(line_, problem_kind::pdo_not_operational,
                       canopen::cob_id(c.fn, node).value(), static_cast<std::uint32_t>(*state_), 0);
            }
            return;
        }
        // The settings the checker follows, from the host's writes.
        if (const auto* w = std::get_if<sdo_write>(&msg)) {
            if (w->object == object::heartbeat_time) {
                hb_.period = w->value.raw;
                hb_.reported = false;
            } else if (w->object == object::tpdo1_event_timer) {
                ks_.period = w->value.raw;
                ks_.reported = false;
            } else if (w->object == object::active_on_startup) {
                active_ = w->value.raw != 0;
            } else if (w->object == object::consumer_heartbeat) {
                consumer_period_ = w->value.raw & 0xFFFFu;
                consumer_producer_ = static_cast<std::uint8_t>((w->value.raw >> 16) & 0x7Fu);
                consumer_last_.reset();  // monitoring starts at the first heartbeat (PK1000 28)
            }
        } else if (const auto* k = std::get_if<command>(&msg)) {
            if (k->code == command_code::set_periodic_transmission) {
                ks_.period = k->enabled ? 10u * k->period_10ms : 0u;
                ks_.reported = false;
            } else if (k->code == command_code::set_active_on_startup) {
                active_ = k->enabled;
            }
        }
    }

    struct outstanding {
        std::uint32_t line;
        millis sent;
        canopen::sdo_address address;
    };
    checker_config cfg_;
    session<TextCapacity> session_;
    j1939_checks j1939_;
    millis now_{};
    millis last_time_{};
    std::uint32_t line_ = 0;
    std::optional<outstanding> pending_;
    bool segmented_ = false;
    bool expect_toggle_ = false;
    bool request_toggle_ = false;
    canopen::sdo_address segment_address_{};
    std::optional<canopen::nmt_state> state_;
    bool active_ = false;
    bool pdo_reported_ = false;
    std::optional<canopen::node_id> old_;
    silence_timer hb_;                   // the CANopen heartbeat (1017h)
    std::uint32_t consumer_period_ = 0;  // 1016h sub 1: the heartbeat the keypad consumes
    std::uint8_t consumer_producer_ = 0;
    std::optional<millis> consumer_last_;
    silence_timer ks_;  // the key state (PK1000 1800h sub 5, PKP command 12h)
    std::uint32_t keypad_frames_ = 0;
    std::uint32_t refused_ = 0;
    std::uint32_t first_refused_line_ = 0;
    bool model_reported_ = false;
    std::array<std::uint32_t, problem_kind_count> counts_{};
    std::array<problem, max_problems_per_frame> found_{};
    std::size_t count_ = 0;
    std::size_t dropped_ = 0;
};

// --- explanations -------------------------------------------------------------------------------

// The CiA 301 meaning of an abort code (POWERKEY_CANOPEN_SDO_ABORT_CODE_LIST, canopen/sdo.hpp);
// "" for a code CiA 301 does not define.
[[nodiscard]] constexpr std::string_view abort_meaning_of(std::uint32_t code) noexcept {
#define POWERKEY_BEHAVIOUR_DETAIL_ABORT_MEANING(name, value, meaning) \
    case value: return meaning;
    switch (code) { POWERKEY_CANOPEN_SDO_ABORT_CODE_LIST(POWERKEY_BEHAVIOUR_DETAIL_ABORT_MEANING) }
#undef POWERKEY_BEHAVIOUR_DETAIL_ABORT_MEANING
    return {};
}

namespace detail {
#define POWERKEY_BEHAVIOUR_DETAIL_KIND_EXPLANATION(name, sev, text, explanation) explanation,
inline constexpr std::string_view explanations[] = {
    POWERKEY_BEHAVIOUR_PROBLEM_KIND_LIST(POWERKEY_BEHAVIOUR_DETAIL_KIND_EXPLANATION)};
#undef POWERKEY_BEHAVIOUR_DETAIL_KIND_EXPLANATION

// A name, or what stands for a value without one.
constexpr void put_name(text_writer& w, std::string_view name, std::string_view unknown) noexcept {
    w.put(name.empty() ? unknown : name);
}
// One {...} of an explanation (POWERKEY_BEHAVIOUR_PROBLEM_KIND_LIST): "N", "N:spec" or "N?a|b".
constexpr void put_field(text_writer& w, std::string_view f,
                         const std::array<std::uint32_t, 3>& d) noexcept {
    const auto n = static_cast<std::size_t>(f[0] - '0');
    const std::uint32_t v = d[n];
    const std::string_view spec = f.substr(f.size() > 1 ? 2 : 1);
    if (f.size() == 1) {
        w.put_decimal(v);
    } else if (f[1] == '?') {
        const auto bar = spec.find('|');
        w.put(v == 0 ? spec.substr(0, bar) : spec.substr(bar + 1));
    } else if (spec[0] == 'x') {
        w.put_hex(v, spec[1] - '0');
    } else if (spec == "at") {
        w.put_hex(v, 4);
        w.put("h/");
        w.put_decimal(d[n + 1]);
    } else if (spec == "frame") {  // a 29-bit identifier with 8 digits
        w.put("frame ");
        w.put_hex(v, v > 0x7FF ? 8 : 3);
        w.put("h of ");
        w.put_decimal(d[n + 1]);
        w.put(d[n + 1] == 1 ? " byte" : " bytes");
    } else if (spec == "abort") {
        put_name(w, abort_meaning_of(v), "a code CiA 301 does not define");
    } else if (spec == "nmt") {
        put_name(w, to_string(static_cast<canopen::nmt_state>(v)), "not operational");
    } else if (spec == "errc") {
        put_name(w, to_string(static_cast<errc>(v)), "an unknown error");
    } else if (spec == "model") {
        put_name(w, to_string(static_cast<model>(v)), "this model's");
    } else if (spec == "form") {
        put_name(w, to_string(static_cast<frame_form>(v)), "not");
    }
}
}  // namespace detail

// The explanation of p, one sentence without the line number (the caller prints that first).
constexpr void explain(const problem& p, text_writer& w) noexcept {
    const auto k = static_cast<std::size_t>(p.kind);
    if (k >= problem_kind_count) return;
    if (k >= detail::j1939_kind_offset)
        return explain_j1939(static_cast<j1939_fault>(k - detail::j1939_kind_offset), p.detail, w);
    const std::string_view text = detail::explanations[k];
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '{') {
            w.put(text[i]);
            continue;
        }
        const std::size_t end = text.find('}', i);
        detail::put_field(w, text.substr(i + 1, end - i - 1), p.detail);
        i = end;
    }
}

// The same into a buffer: the text, or errc::buffer_too_small (the buffer holds the beginning).
// 160 characters hold every explanation.
[[nodiscard]] constexpr result<std::string_view> explain(const problem& p,
                                                         std::span<char> out) noexcept {
    text_writer w(out);
    explain(p, w);
    if (w.overflow()) return errc::buffer_too_small;
    return w.view();
}

}  // namespace powerkey::behaviour

POWERKEY_DETAIL_ENUM_NAMES(powerkey::behaviour::problem_kind, POWERKEY_BEHAVIOUR_PROBLEM_KIND_LIST);
POWERKEY_DETAIL_ENUM_NAMES(powerkey::behaviour::severity, POWERKEY_BEHAVIOUR_SEVERITY_LIST);

#endif  // POWERKEY_BEHAVIOUR_CHECKER_HPP
