// powerkey: a segmented SDO upload reader (CiA 301 7.2.4.3.5-7), an allocation-free state machine
// stepped one keypad reply at a time (docs/canopen.md, "Segmented string reads").
#ifndef POWERKEY_CANOPEN_SDO_UPLOAD_HPP
#define POWERKEY_CANOPEN_SDO_UPLOAD_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/canopen/sdo.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <variant>

namespace powerkey::canopen {

enum class upload_policy : std::uint8_t { report, strict };

enum class upload_state : std::uint8_t {
    idle,     // not started
    running,  // waiting for the keypad's next reply
    done,     // the whole value is in bytes()
    failed,   // error() says why; abort_code() too when the keypad aborted
};

// What the keypad did that the segment rules do not allow, but that the reader still decoded.
struct upload_notes {
    bool size_not_indicated = false;   // initiate response 40h: no size to check against
    bool size_mismatch = false;        // bytes received differ from the announced size
    bool continued_past_size = false;  // a segment without the last flag after the size was reached
    bool short_segment = false;        // a segment other than the last carried fewer than 7 bytes
    bool contains_nul = false;         // a NUL byte among the received bytes (text() drops them)

    [[nodiscard]] constexpr bool any() const noexcept {
        return size_not_indicated || size_mismatch || continued_past_size || short_segment ||
               contains_nul;
    }
    friend constexpr bool operator==(const upload_notes&, const upload_notes&) noexcept = default;
};

// The outcome of one step: the next request to send, or none when the transfer is complete.
struct upload_step {
    std::optional<can::frame> request;
};

template <std::size_t Capacity>
class segmented_upload {
    static_assert(Capacity > 0);

public:
    static constexpr std::size_t capacity = Capacity;

    constexpr explicit segmented_upload(node_id node,
                                        upload_policy policy = upload_policy::report) noexcept
        : node_(node), policy_(policy) {}

    // Begin reading `address` (any earlier transfer is forgotten); send the frame returned.
    [[nodiscard]] constexpr can::frame start(sdo_address address) noexcept {
        state_ = upload_state::running;
        error_ = errc{};
        address_ = address;
        initiated_ = false;
        toggle_ = false;
        size_indicated_ = false;
        announced_ = 0;
        aborted_ = false;
        notes_ = upload_notes{};
        size_ = 0;
        text_size_ = 0;
        return encode(node_, sdo_upload_request{address});
    }

    // Feed one frame received from the keypad; the errors are docs/canopen.md's ("Segmented string
    // reads"): wrong_id_format and wrong_id change nothing, any other ends the transfer.
    [[nodiscard]] constexpr result<upload_step> step(const can::frame& reply) noexcept {
        if (state_ != upload_state::running) return errc::unexpected_frame;
        const auto decoded = decode_sdo_response(reply, node_);
        if (!decoded) {
            if (decoded.error() == errc::wrong_id_format || decoded.error() == errc::wrong_id)
                return decoded.error();
            return fail(decoded.error());
        }
        return step(*decoded);
    }

    // The same for a response already decoded.
    [[nodiscard]] constexpr result<upload_step> step(const sdo_response& reply) noexcept {
        if (state_ != upload_state::running) return errc::unexpected_frame;
        if (const auto* a = std::get_if<sdo_abort>(&reply)) {
            aborted_ = true;
            abort_code_ = a->code;
            return fail(errc::sdo_aborted);
        }
        if (!initiated_) return on_initiate(reply);
        if (const auto* s = std::get_if<sdo_segment_response>(&reply)) return on_segment(*s);
        return fail(errc::unexpected_frame);
    }

    [[nodiscard]] constexpr upload_state state() const noexcept { return state_; }
    [[nodiscard]] constexpr errc error() const noexcept { return error_; }
    [[nodiscard]] constexpr sdo_address address() const noexcept { return address_; }
    // The keypad's abort code, when error() is sdo_aborted.
    [[nodiscard]] constexpr std::optional<sdo_abort_code> abort_code() const noexcept {
        if (!aborted_) return std::nullopt;
        return abort_code_;
    }
    // The size the keypad announced (41h or expedited), if it announced one.
    [[nodiscard]] constexpr std::optional<std::uint32_t> announced_size() const noexcept {
        if (!size_indicated_) return std::nullopt;
        return announced_;
    }
    [[nodiscard]] constexpr const upload_notes& notes() const noexcept { return notes_; }
    // Every byte received so far, NULs included.
    [[nodiscard]] constexpr std::span<const std::uint8_t> bytes() const noexcept {
        return {bytes_.data(), size_};
    }
    // The received bytes as text with NUL bytes left out; complete once state() is done.
    [[nodiscard]] constexpr std::string_view text() const noexcept {
        return {text_.data(), text_size_};
    }

private:
    constexpr errc fail(errc e) noexcept {
        state_ = upload_state::failed;
        error_ = e;
        return e;
    }

    constexpr bool append(std::span<const std::uint8_t> data) noexcept {
        if (data.size() > Capacity - size_) return false;
        for (std::uint8_t b : data) {
            bytes_[size_++] = b;
            if (b == 0) {
                notes_.contains_nul = true;
            } else {
                text_[text_size_++] = static_cast<char>(b);
            }
        }
        return true;
    }

    constexpr result<upload_step> finish() noexcept {
        state_ = upload_state::done;
        return upload_step{};
    }

    constexpr result<upload_step> on_initiate(const sdo_response& r) noexcept {
        if (const auto* e = std::get_if<sdo_upload_response>(&r)) {  // expedited: all at once
            if (e->address != address_) return fail(errc::index_mismatch);
            size_indicated_ = true;
            announced_ = e->value.size.value();
            if (!append(e->value.data())) return fail(errc::buffer_too_small);
            return finish();
        }
        const auto* i = std::get_if<sdo_upload_initiate_response>(&r);
        if (i == nullptr) return fail(errc::unexpected_frame);
        if (i->address != address_) return fail(errc::index_mismatch);
        if (i->size_indicated) {
            size_indicated_ = true;
            announced_ = i->size;
        } else {
            notes_.size_not_indicated = true;
        }
        initiated_ = true;
        return upload_step{encode(node_, sdo_segment_request{toggle_})};
    }

    constexpr result<upload_step> on_segment(const sdo_segment_response& s) noexcept {
        if (s.toggle != toggle_) return fail(errc::toggle_error);
        if (!append(s.data())) return fail(errc::buffer_too_small);
        bool discrepancy = false;
        if (size_indicated_) {
            if (size_ > announced_ || (s.last && size_ != announced_)) {
                notes_.size_mismatch = true;
                discrepancy = true;
            }
            if (!s.last && size_ >= announced_) {
                notes_.continued_past_size = true;
                discrepancy = true;
            }
        }
        if (!s.last && s.unused.value() != 0) {
            notes_.short_segment = true;
            discrepancy = true;
        }
        if (discrepancy && policy_ == upload_policy::strict) return fail(errc::size_mismatch);
        if (s.last) return finish();
        toggle_ = !toggle_;
        return upload_step{encode(node_, sdo_segment_request{toggle_})};
    }

    node_id node_;
    upload_policy policy_;
    upload_state state_ = upload_state::idle;
    errc error_{};
    sdo_address address_{};
    bool initiated_ = false;
    bool toggle_ = false;
    // Plain fields rather than std::optional: g++ 12 -O2 reports a false -Wmaybe-uninitialized
    // on an optional member here.
    bool size_indicated_ = false;
    std::uint32_t announced_ = 0;
    bool aborted_ = false;
    sdo_abort_code abort_code_ = sdo_abort_code::general_error;
    upload_notes notes_{};
    std::array<std::uint8_t, Capacity> bytes_{};
    std::size_t size_ = 0;
    std::array<char, Capacity> text_{};
    std::size_t text_size_ = 0;
};

}  // namespace powerkey::canopen

#endif  // POWERKEY_CANOPEN_SDO_UPLOAD_HPP
