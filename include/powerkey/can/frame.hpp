// powerkey: a classic CAN data frame. An 11-bit (standard) and a 29-bit (extended) identifier
// are distinct types, so 615h and 18EF2100h can never be confused, and a frame compares equal
// only to a frame with the same kind of identifier, the same dlc and the same data bytes.
#ifndef POWERKEY_CAN_FRAME_HPP
#define POWERKEY_CAN_FRAME_HPP

#include <powerkey/bounded.hpp>
#include <powerkey/detail/bytes.hpp>
#include <powerkey/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace powerkey::can {

struct standard_id_tag;
struct extended_id_tag;
struct dlc_tag;

// 11-bit identifier, 000h..7FFh.
using standard_id = bounded<standard_id_tag, std::uint16_t, 0, 0x7FF>;
// 29-bit identifier, 0..1FFFFFFFh.
using extended_id = bounded<extended_id_tag, std::uint32_t, 0, 0x1FFF'FFFF>;
// Data length code of a classic CAN frame: 0..8 bytes.
using dlc = bounded<dlc_tag, std::uint8_t, 0, 8>;

using payload = std::array<std::uint8_t, 8>;

class frame {
public:
    // An empty frame with standard id 000h; exists so that frames fit in arrays and results.
    constexpr frame() noexcept = default;

    constexpr frame(standard_id id, dlc length, const payload& data) noexcept
        : id_(id.value()), dlc_(length.value()), data_(masked(data, length)) {}
    constexpr frame(extended_id id, dlc length, const payload& data) noexcept
        : id_(id.value() | extended_flag), dlc_(length.value()), data_(masked(data, length)) {}

    // Exactly N data bytes, N checked at compile time.
    template <std::size_t N>
    requires(N <= 8) constexpr frame(standard_id id,
                                     const std::array<std::uint8_t, N>& data) noexcept
        : frame(id, dlc::make(N).value(), widen(data)) {}
    template <std::size_t N>
    requires(N <= 8) constexpr frame(extended_id id,
                                     const std::array<std::uint8_t, N>& data) noexcept
        : frame(id, dlc::make(N).value(), widen(data)) {}

    // From bytes of run-time length: more than 8 is errc::wrong_length.
    template <class Id>
    [[nodiscard]] static constexpr result<frame> make(Id id,
                                                      std::span<const std::uint8_t> data) noexcept {
        const auto length = dlc::make(data.size());
        if (!length) return errc::wrong_length;
        payload p{};
        for (std::size_t i = 0; i < data.size(); ++i) p[i] = data[i];
        return frame(id, *length, p);
    }

    [[nodiscard]] constexpr bool is_extended() const noexcept { return (id_ & extended_flag) != 0; }
    // The identifier as a plain number (11 or 29 bits; see is_extended()).
    [[nodiscard]] constexpr std::uint32_t raw_id() const noexcept { return id_ & ~extended_flag; }
    // The identifier and its format in one word, as SocketCAN's can_id holds them: bit 31 set for
    // a 29-bit identifier (CAN_EFF_FLAG). A standard frame's word is its 11-bit id, at most 7FFh,
    // so one comparison classifies a frame (the keypad decoder's dispatch).
    [[nodiscard]] constexpr std::uint32_t id_word() const noexcept { return id_; }
    static constexpr std::uint32_t extended_flag = 0x8000'0000;
    [[nodiscard]] constexpr std::optional<standard_id> std_id() const noexcept {
        if (is_extended()) return std::nullopt;
        return standard_id::make(id_).value();
    }
    [[nodiscard]] constexpr std::optional<extended_id> ext_id() const noexcept {
        if (!is_extended()) return std::nullopt;
        return extended_id::make(raw_id()).value();
    }

    [[nodiscard]] constexpr std::uint8_t size() const noexcept { return dlc_; }
    // The dlc data bytes. Bytes past the dlc are always zero in the storage behind it.
    [[nodiscard]] constexpr std::span<const std::uint8_t> data() const noexcept {
        return {data_.data(), dlc_};
    }
    // All eight storage bytes; those at and past size() are zero.
    [[nodiscard]] constexpr const payload& bytes() const noexcept { return data_; }
    // The eight storage bytes as one little-endian number (bytes past the dlc are zero): an
    // 8-byte PDO's single read. It reads all eight, so a decoder calls it only once it has
    // checked that the dlc is 8 (no decoder reads past the dlc: the fuzz targets poison those
    // bytes). detail::load_le, the library's one little-endian load.
    [[nodiscard]] constexpr std::uint64_t data_le() const noexcept {
        return powerkey::detail::load_le<8>(data_, 0);
    }
    // Byte i; i must be < size().
    constexpr std::uint8_t operator[](std::size_t i) const noexcept { return data_[i]; }

    friend constexpr bool operator==(const frame&, const frame&) noexcept = default;

private:
    // The data with the bytes past the dlc cleared, as one 64-bit mask (a byte loop here cost
    // every encoder a dozen instructions).
    static constexpr payload masked(const payload& data, dlc length) noexcept {
        const std::uint64_t keep = powerkey::detail::low_bits(8u * length.value());
        payload p{};
        powerkey::detail::store_le<8>(p, 0, powerkey::detail::load_le<8>(data, 0) & keep);
        return p;
    }
    template <std::size_t N>
    static constexpr payload widen(const std::array<std::uint8_t, N>& data) noexcept {
        payload p{};
        for (std::size_t i = 0; i < N; ++i) p[i] = data[i];
        return p;
    }

    std::uint32_t id_ = 0;  // the id, | extended_flag for a 29-bit one
    std::uint8_t dlc_ = 0;
    payload data_{};
};

// Whether an identifier a CAN driver hands over is 11-bit or 29-bit.
enum class id_format : std::uint8_t { standard, extended };

// A frame from what a CAN driver hands over, in one call: the identifier as a number, its format
// and the data bytes. Errors: value_out_of_range (an identifier above 7FFh, or above 1FFFFFFFh
// for an extended one), wrong_length (more than 8 bytes).
//   if (const auto f = can::make_frame(rx.id, {rx.data, rx.dlc})) handle(*f);
[[nodiscard]] constexpr result<frame> make_frame(std::uint32_t id,
                                                 std::span<const std::uint8_t> data,
                                                 id_format format = id_format::standard) noexcept {
    if (format == id_format::extended) {
        const auto e = extended_id::make(id);
        if (!e) return e.error();
        return frame::make(*e, data);
    }
    const auto s = standard_id::make(id);
    if (!s) return s.error();
    return frame::make(*s, data);
}

}  // namespace powerkey::can

#endif  // POWERKEY_CAN_FRAME_HPP
