// powerkey: what every behaviour role is stepped with. Roles own no clock and do no I/O: the caller
// passes the time to each call and drains the frames a role sends from its fixed-capacity outbox.
#ifndef POWERKEY_BEHAVIOUR_CLOCK_HPP
#define POWERKEY_BEHAVIOUR_CLOCK_HPP

#include <powerkey/can/frame.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace powerkey::behaviour {

// A point in time in milliseconds from a free-running 32-bit counter that wraps: compare points
// with before() / elapsed() (docs/controller.md, "Time and outboxes").
struct millis {
    std::uint32_t value = 0;
    friend constexpr bool operator==(millis, millis) noexcept = default;
};

// A span of time in milliseconds.
struct duration_ms {
    std::uint32_t value = 0;
    friend constexpr bool operator==(duration_ms, duration_ms) noexcept = default;
};

// t + d (wraps like the counter).
[[nodiscard]] constexpr millis operator+(millis t, duration_ms d) noexcept {
    return millis{static_cast<std::uint32_t>(t.value + d.value)};
}
// Time from `since` to `now` (wrap-safe).
[[nodiscard]] constexpr duration_ms elapsed(millis since, millis now) noexcept {
    return duration_ms{static_cast<std::uint32_t>(now.value - since.value)};
}
// Whether a comes strictly before b (wrap-safe: b - a taken as a signed 32-bit difference).
[[nodiscard]] constexpr bool before(millis a, millis b) noexcept {
    const auto diff = static_cast<std::uint32_t>(b.value - a.value);
    return diff != 0 && diff < 0x8000'0000u;
}
// Whether `deadline` has come at `now` (now == deadline counts).
[[nodiscard]] constexpr bool reached(millis deadline, millis now) noexcept {
    return !before(now, deadline);
}
// Whether a peer last heard at `since` is lost at `now`: silent for longer than `after` (0:
// never lost). Both controllers' lost_after.
[[nodiscard]] constexpr bool silent_for_longer(millis since, millis now,
                                               duration_ms after) noexcept {
    return after.value != 0 && elapsed(since, now).value > after.value;
}

// A peer's periodic frame as a checker times it: its period in ms (0: not judged), the last one
// heard (none before the first) and whether the present silence was said.
struct silence_timer {
    struct seen {
        millis time;
        std::uint32_t line;
    };
    std::uint32_t period = 0;
    std::optional<seen> last;
    bool reported = false;

    // The silence at `now` when longer than `allowed` ms and not said yet (said then, once per
    // silence): {ms silent, the period, line of the last frame}.
    [[nodiscard]] constexpr std::optional<std::array<std::uint32_t, 3>> overdue(
        millis now, std::uint32_t allowed) noexcept {
        if (period == 0 || !last || reported || elapsed(last->time, now).value <= allowed)
            return std::nullopt;
        reported = true;
        return std::array<std::uint32_t, 3>{elapsed(last->time, now).value, period, last->line};
    }
    // A periodic frame at `t`, from input line `line`.
    constexpr void heard(millis t, std::uint32_t line) noexcept {
        last = seen{t, line};
        reported = false;
    }
    // A time before the last one (two logs in a row): the silence counts from `now`.
    constexpr void restart(millis now) noexcept {
        if (last) last->time = now;
    }
};

// A fixed-capacity FIFO (outboxes, event queues): push() on a full queue refuses (returns false)
// and counts the item in dropped().
template <class T, std::size_t N>
class fixed_queue {
    static_assert(N > 0, "a fixed_queue holds at least one item");

public:
    [[nodiscard]] constexpr bool push(const T& x) noexcept {
        if (full()) {
            ++dropped_;
            return false;
        }
        items_[(head_ + size_) % N] = x;
        ++size_;
        return true;
    }
    // The oldest item, removed; nullopt when empty.
    [[nodiscard]] constexpr std::optional<T> pop() noexcept {
        if (size_ == 0) return std::nullopt;
        const T f = items_[head_];
        head_ = (head_ + 1) % N;
        --size_;
        return f;
    }
    // The oldest item, left in place.
    [[nodiscard]] constexpr std::optional<T> front() const noexcept {
        if (size_ == 0) return std::nullopt;
        return items_[head_];
    }
    constexpr void clear() noexcept { head_ = size_ = 0; }

    [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
    [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0; }
    [[nodiscard]] constexpr bool full() const noexcept { return size_ == N; }
    [[nodiscard]] static constexpr std::size_t capacity() noexcept { return N; }
    // Items refused by push() because the queue was full, since construction.
    [[nodiscard]] constexpr std::size_t dropped() const noexcept { return dropped_; }

private:
    std::array<T, N> items_{};
    std::size_t head_ = 0;
    std::size_t size_ = 0;
    std::size_t dropped_ = 0;
};
template <std::size_t N>
using frame_queue = fixed_queue<can::frame, N>;

}  // namespace powerkey::behaviour

#endif  // POWERKEY_BEHAVIOUR_CLOCK_HPP
