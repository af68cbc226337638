// powerkey: SDO frames (CiA 301 7.2.4), the subset the keypads speak, always 8 bytes: the
// commands, message types and byte layout are docs/canopen.md's table ("SDO").
#ifndef POWERKEY_CANOPEN_SDO_HPP
#define POWERKEY_CANOPEN_SDO_HPP

#include <powerkey/bounded.hpp>
#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/detail/bytes.hpp>
#include <powerkey/detail/inline.hpp>
#include <powerkey/detail/message.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/error.hpp>
#include <powerkey/frame_form.hpp>
#include <powerkey/result.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <variant>

namespace powerkey::canopen {

// Object dictionary entry: index and sub-index.
struct sdo_address {
    std::uint16_t index = 0;
    std::uint8_t subindex = 0;
    friend constexpr bool operator==(const sdo_address&, const sdo_address&) noexcept = default;
};

struct expedited_size_tag;
struct segment_unused_tag;
// Bytes carried by an expedited transfer: 1..4.
using expedited_size = bounded<expedited_size_tag, std::uint8_t, 1, 4>;
// Bytes of an upload segment that carry no data: 0..7.
using segment_unused = bounded<segment_unused_tag, std::uint8_t, 0, 7>;

// Four data bytes of an expedited transfer and how many of them count. Bytes past `size` are
// kept as received so that decode then encode gives back the same frame.
struct expedited_data {
    expedited_size size = 4;
    std::array<std::uint8_t, 4> bytes{};

    // The value of the `size` counted bytes, little endian (CiA 301: "least significant first").
    [[nodiscard]] constexpr std::uint32_t value() const noexcept {
        return static_cast<std::uint32_t>(powerkey::detail::load_le(bytes, 0, size.value()));
    }
    // The counted bytes.
    [[nodiscard]] constexpr std::span<const std::uint8_t> data() const noexcept {
        return {bytes.data(), size.value()};
    }
    [[nodiscard]] static constexpr expedited_data u8(std::uint8_t v) noexcept {
        return {1, {v, 0, 0, 0}};
    }
    [[nodiscard]] static constexpr expedited_data u16(std::uint16_t v) noexcept {
        expedited_data d{2, {}};
        powerkey::detail::store_le<2>(d.bytes, 0, v);
        return d;
    }
    [[nodiscard]] static constexpr expedited_data u32(std::uint32_t v) noexcept {
        expedited_data d{4, {}};
        powerkey::detail::store_le<4>(d.bytes, 0, v);
        return d;
    }
    friend constexpr bool operator==(const expedited_data&,
                                     const expedited_data&) noexcept = default;
};

// --- client -> server (600h + node) ---------------------------------------------------------

// Write 1..4 bytes (command 2Fh, 2Bh, 27h, 23h).
struct sdo_download_request {
    POWERKEY_DETAIL_MESSAGE(sdo_download_request);
    POWERKEY_DETAIL_FIELDS(f("index", self.address.index), f("subindex", self.address.subindex),
                           f("size", self.value.size), f("data", self.value.bytes));
    sdo_address address;
    expedited_data value;
};

// Read an entry (command 40h).
struct sdo_upload_request {
    POWERKEY_DETAIL_MESSAGE(sdo_upload_request);
    POWERKEY_DETAIL_FIELDS(f("index", self.address.index), f("subindex", self.address.subindex));
    sdo_address address;
};

// Ask for the next segment of a segmented upload (60h toggle 0, 70h toggle 1).
struct sdo_segment_request {
    POWERKEY_DETAIL_MESSAGE(sdo_segment_request);
    POWERKEY_DETAIL_FIELDS(f("toggle", self.toggle));
    bool toggle = false;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// --- server -> client (580h + node) ---------------------------------------------------------

// A write was done (60h).
struct sdo_download_response {
    POWERKEY_DETAIL_MESSAGE(sdo_download_response);
    POWERKEY_DETAIL_FIELDS(f("index", self.address.index), f("subindex", self.address.subindex));
    sdo_address address;
};

// The value read, 1..4 bytes (4Fh, 4Bh, 47h, 43h).
struct sdo_upload_response {
    POWERKEY_DETAIL_MESSAGE(sdo_upload_response);
    POWERKEY_DETAIL_FIELDS(f("index", self.address.index), f("subindex", self.address.subindex),
                           f("size", self.value.size), f("data", self.value.bytes));
    sdo_address address;
    expedited_data value;
};

// A segmented upload begins: 41h with the size in bytes 4..7, or 40h without a size (bytes 4..7
// are then reserved; what they held is kept in `size` so the frame re-encodes unchanged).
struct sdo_upload_initiate_response {
    POWERKEY_DETAIL_MESSAGE(sdo_upload_initiate_response);
    POWERKEY_DETAIL_FIELDS(f("index", self.address.index), f("subindex", self.address.subindex),
                           f("size_indicated", self.size_indicated), f("size", self.size));
    sdo_address address;
    bool size_indicated = true;
    std::uint32_t size = 0;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// One segment: byte 0 = 000t nnnc (t toggle, n bytes without data, c last segment), then 7 bytes
// of which the first 7 - n are data. The unused bytes are kept as received.
struct sdo_segment_response {
    POWERKEY_DETAIL_MESSAGE(sdo_segment_response);
    POWERKEY_DETAIL_FIELDS(f("toggle", self.toggle), f("unused", self.unused), f("last", self.last),
                           f("data", self.bytes));
    bool toggle = false;
    segment_unused unused = 0;
    bool last = false;
    std::array<std::uint8_t, 7> bytes{};

    [[nodiscard]] constexpr std::span<const std::uint8_t> data() const noexcept {
        return {bytes.data(), static_cast<std::size_t>(7 - unused.value())};
    }
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// --- both directions --------------------------------------------------------------------------

// CiA 301 table 22: the abort codes, each with its meaning; a decoded abort keeps any 32-bit
// code, named or not.
// clang-format off
#define POWERKEY_CANOPEN_SDO_ABORT_CODE_LIST(X) \
    X(toggle_bit_not_alternated, 0x0503'0000, "toggle bit not alternated") \
    X(timed_out, 0x0504'0000, "SDO protocol timed out") \
    X(invalid_command_specifier, 0x0504'0001, "client/server command specifier not valid or unknown") \
    X(invalid_block_size, 0x0504'0002, "invalid block size") \
    X(invalid_sequence_number, 0x0504'0003, "invalid sequence number") \
    X(crc_error, 0x0504'0004, "CRC error") \
    X(out_of_memory, 0x0504'0005, "out of memory") \
    X(unsupported_access, 0x0601'0000, "unsupported access to an object") \
    X(write_only, 0x0601'0001, "attempt to read a write only object") \
    X(read_only, 0x0601'0002, "attempt to write a read only object") \
    X(object_does_not_exist, 0x0602'0000, "object does not exist in the object dictionary") \
    X(cannot_be_mapped, 0x0604'0041, "object cannot be mapped to the PDO") \
    X(exceeds_pdo_length, 0x0604'0042, "the number and length of the objects to be mapped would exceed PDO length") \
    X(parameter_incompatibility, 0x0604'0043, "general parameter incompatibility") \
    X(internal_incompatibility, 0x0604'0047, "general internal incompatibility") \
    X(hardware_error, 0x0606'0000, "access failed due to a hardware error") \
    X(length_mismatch, 0x0607'0010, "data type does not match, length of service parameter does not match") \
    X(length_too_high, 0x0607'0012, "data type does not match, length of service parameter too high") \
    X(length_too_low, 0x0607'0013, "data type does not match, length of service parameter too low") \
    X(subindex_does_not_exist, 0x0609'0011, "sub-index does not exist") \
    X(invalid_value, 0x0609'0030, "invalid value for parameter (download only)") \
    X(value_too_high, 0x0609'0031, "value of parameter written too high") \
    X(value_too_low, 0x0609'0032, "value of parameter written too low") \
    X(max_less_than_min, 0x0609'0036, "maximum value is less than minimum value") \
    X(resource_not_available, 0x060A'0023, "resource not available: SDO connection") \
    X(general_error, 0x0800'0000, "general error") \
    X(cannot_store, 0x0800'0020, "data cannot be transferred or stored to the application") \
    X(cannot_store_local_control, 0x0800'0021, "data cannot be transferred or stored to the application because of local control") \
    X(cannot_store_device_state, 0x0800'0022, "data cannot be transferred or stored to the application because of the present device state") \
    X(no_object_dictionary, 0x0800'0023, "object dictionary dynamic generation fails or no object dictionary is present") \
    X(no_data, 0x0800'0024, "no data available")
// clang-format on
#define POWERKEY_CANOPEN_DETAIL_ABORT_ENUMERATOR(name, code, meaning) name = code,
enum class sdo_abort_code : std::uint32_t {
    POWERKEY_CANOPEN_SDO_ABORT_CODE_LIST(POWERKEY_CANOPEN_DETAIL_ABORT_ENUMERATOR)
};
#undef POWERKEY_CANOPEN_DETAIL_ABORT_ENUMERATOR

}  // namespace powerkey::canopen

// CiA 301 table 22's abort codes by name; a code CiA 301 does not name prints as "".
POWERKEY_DETAIL_ENUM_NAMES(powerkey::canopen::sdo_abort_code, POWERKEY_CANOPEN_SDO_ABORT_CODE_LIST);

namespace powerkey::canopen {

// Abort transfer (80h), index, sub-index and a 32-bit code.
struct sdo_abort {
    POWERKEY_DETAIL_MESSAGE(sdo_abort);
    POWERKEY_DETAIL_FIELDS(f("index", self.address.index), f("subindex", self.address.subindex),
                           f("code", self.code));
    sdo_address address;
    sdo_abort_code code = sdo_abort_code::general_error;
};

// The two directions of an abort as messages of their own: canopen::sdo_abort has no direction,
// and a message type that holds both needs them apart so that each re-encodes on its COB-ID.
// Sent by the client (600h + node):
struct sdo_abort_request {
    POWERKEY_DETAIL_MESSAGE(sdo_abort_request);
    POWERKEY_DETAIL_FIELDS(sdo_abort::fields(self.abort, f));
    sdo_abort abort;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

// Sent by the keypad (580h + node):
struct sdo_abort_response {
    POWERKEY_DETAIL_MESSAGE(sdo_abort_response);
    POWERKEY_DETAIL_FIELDS(sdo_abort::fields(self.abort, f));
    sdo_abort abort;
    powerkey::frame_form form = powerkey::frame_form::manual;  // as decode read it (frame_form.hpp)
};

using sdo_request =
    std::variant<sdo_download_request, sdo_upload_request, sdo_segment_request, sdo_abort>;
using sdo_response = std::variant<sdo_download_response, sdo_upload_response,
                                  sdo_upload_initiate_response, sdo_segment_response, sdo_abort>;

// --- encoding -----------------------------------------------------------------------------------

namespace detail {
constexpr can::payload with_address(std::uint8_t command, sdo_address a) noexcept {
    can::payload p{};
    p[0] = command;
    powerkey::detail::store_le<2>(p, 1, a.index);
    p[3] = a.subindex;
    return p;
}
constexpr can::frame sdo_frame(function f, node_id node, const can::payload& p) noexcept {
    return can::frame(cob_id(f, node), 8, p);
}
// An expedited transfer: `command` with 4 - size in bits 2..3, the address, the four data bytes.
constexpr can::payload expedited(std::uint8_t command, sdo_address a,
                                 const expedited_data& d) noexcept {
    const auto n = static_cast<std::uint8_t>((4 - d.size.value()) << 2);
    auto p = with_address(static_cast<std::uint8_t>(command | n), a);
    for (std::size_t i = 0; i < 4; ++i) p[4 + i] = d.bytes[i];
    return p;
}
}  // namespace detail

[[nodiscard]] constexpr can::frame encode(node_id node, const sdo_download_request& m) noexcept {
    return detail::sdo_frame(function::sdo_rx, node, detail::expedited(0x23, m.address, m.value));
}
[[nodiscard]] constexpr can::frame encode(node_id node, const sdo_upload_request& m) noexcept {
    return detail::sdo_frame(function::sdo_rx, node, detail::with_address(0x40, m.address));
}
[[nodiscard]] constexpr can::frame encode(node_id node, const sdo_segment_request& m) noexcept {
    can::payload p{};
    p[0] = m.toggle ? 0x70 : 0x60;
    return detail::sdo_frame(function::sdo_rx, node, p);
}
[[nodiscard]] constexpr can::frame encode(node_id node, const sdo_download_response& m) noexcept {
    return detail::sdo_frame(function::sdo_tx, node, detail::with_address(0x60, m.address));
}
[[nodiscard]] constexpr can::frame encode(node_id node, const sdo_upload_response& m) noexcept {
    return detail::sdo_frame(function::sdo_tx, node, detail::expedited(0x43, m.address, m.value));
}
[[nodiscard]] constexpr can::frame encode(node_id node,
                                          const sdo_upload_initiate_response& m) noexcept {
    auto p = detail::with_address(m.size_indicated ? 0x41 : 0x40, m.address);
    powerkey::detail::store_le<4>(p, 4, m.size);
    return detail::sdo_frame(function::sdo_tx, node, p);
}
[[nodiscard]] constexpr can::frame encode(node_id node, const sdo_segment_response& m) noexcept {
    can::payload p{};
    p[0] = static_cast<std::uint8_t>((m.toggle ? 0x10 : 0) | (m.unused.value() << 1) |
                                     (m.last ? 1 : 0));
    for (std::size_t i = 0; i < 7; ++i) p[1 + i] = m.bytes[i];
    return detail::sdo_frame(function::sdo_tx, node, p);
}

// Which way an abort travels: from the client (600h + node) or from the keypad (580h + node).
enum class sdo_direction : std::uint8_t { request, response };

[[nodiscard]] constexpr can::frame encode(node_id node, const sdo_abort& m,
                                          sdo_direction dir) noexcept {
    auto p = detail::with_address(0x80, m.address);
    powerkey::detail::store_le<4>(p, 4, static_cast<std::uint32_t>(m.code));
    return detail::sdo_frame(dir == sdo_direction::request ? function::sdo_rx : function::sdo_tx,
                             node, p);
}

[[nodiscard]] constexpr can::frame encode(node_id node, const sdo_abort_request& m) noexcept {
    return encode(node, m.abort, sdo_direction::request);
}
[[nodiscard]] constexpr can::frame encode(node_id node, const sdo_abort_response& m) noexcept {
    return encode(node, m.abort, sdo_direction::response);
}

namespace detail {
// A variant's frame; its sdo_abort travels in direction `dir`.
template <class Variant>
constexpr can::frame encode_either(node_id node, const Variant& m, sdo_direction dir) noexcept {
    return std::visit(
        [node, dir](const auto& v) -> can::frame {
            if constexpr (std::is_same_v<std::decay_t<decltype(v)>, sdo_abort>)
                return encode(node, v, dir);
            else
                return encode(node, v);
        },
        m);
}
}  // namespace detail

[[nodiscard]] constexpr can::frame encode_request(node_id node, const sdo_request& m) noexcept {
    return detail::encode_either(node, m, sdo_direction::request);
}
[[nodiscard]] constexpr can::frame encode_response(node_id node, const sdo_response& m) noexcept {
    return detail::encode_either(node, m, sdo_direction::response);
}

// --- the SDO engine -----------------------------------------------------------------------------
// Every SDO frame is read here, once and one way (docs/canopen.md, "One SDO parser"); the frames a
// bus carries most are tested first, the rest is out of line.

// Which SDO frame a word is.
enum class sdo_op : std::uint8_t {
    // client -> server (600h + node)
    expedited_download,  // 23h 27h 2Bh 2Fh: write 4, 3, 2, 1 bytes
    upload,              // 40h, bytes 4..7 zero: read
    segment_request,     // 60h / 70h, bytes 1..7 zero
    abort_request,       // 80h
    // server -> client (580h + node)
    download_response,  // 60h, bytes 4..7 zero
    expedited_upload,   // 43h 47h 4Bh 4Fh: the value read, 4, 3, 2, 1 bytes
    upload_initiate,    // 41h (size in bytes 4..7), 40h (no size)
    segment,            // 000t nnnc: toggle, unused bytes, last
    abort_response,     // 80h
};

// An SDO frame's 8 bytes, read once, and its parts.
struct sdo_word {
    std::uint64_t bits = 0;

    [[nodiscard]] static constexpr sdo_word of(const can::frame& f) noexcept {
        return {powerkey::detail::load_le<8>(f.bytes(), 0)};
    }
    [[nodiscard]] constexpr std::uint8_t specifier() const noexcept {
        return static_cast<std::uint8_t>(bits);
    }
    // Bytes 1..3, index | sub-index << 16: the key of the keypad dictionaries' lookup.
    [[nodiscard]] constexpr std::uint32_t key() const noexcept {
        return static_cast<std::uint32_t>(bits >> 8) & 0xFF'FFFF;
    }
    [[nodiscard]] constexpr sdo_address address() const noexcept {
        return {static_cast<std::uint16_t>(bits >> 8), static_cast<std::uint8_t>(bits >> 24)};
    }
    // Bytes 4..7, little endian.
    [[nodiscard]] constexpr std::uint32_t data() const noexcept {
        return static_cast<std::uint32_t>(bits >> 32);
    }
    // The bytes an expedited transfer carries (bits 2..3 of the specifier: 4 - n).
    [[nodiscard]] constexpr std::uint8_t size() const noexcept {
        return static_cast<std::uint8_t>(4 - ((specifier() >> 2) & 3));
    }
    [[nodiscard]] constexpr expedited_data expedited() const noexcept {
        expedited_data d{expedited_size::make(size()).value(), {}};
        powerkey::detail::store_le<4>(d.bytes, 0, data());
        return d;
    }
    [[nodiscard]] constexpr sdo_abort abort() const noexcept {
        return {address(), static_cast<sdo_abort_code>(data())};
    }
    [[nodiscard]] constexpr sdo_segment_request segment_request() const noexcept {
        return {(specifier() & 0x10) != 0};
    }
    [[nodiscard]] constexpr sdo_segment_response segment() const noexcept {
        const std::uint8_t c = specifier();
        sdo_segment_response s{
            (c & 0x10) != 0, segment_unused::make((c >> 1) & 7).value(), (c & 1) != 0, {}};
        powerkey::detail::store_le<7>(s.bytes, 0, bits >> 8);
        return s;
    }
    [[nodiscard]] constexpr sdo_upload_initiate_response upload_initiate() const noexcept {
        return {address(), (specifier() & 0x01) != 0, data()};
    }
};

// The requests visit_sdo_request does not take first: segment requests, aborts and the refusals.
POWERKEY_DETAIL_INLINE constexpr result<sdo_op> other_request_op(sdo_word w) noexcept {
    const std::uint8_t c = w.specifier();
    switch (c >> 5) {
        case 1: return errc::unknown_command;    // download: only expedited with size (e = s = 1)
        case 2: return errc::reserved_not_zero;  // upload: only 40h with bytes 4..7 zero
        case 3:                                  // upload segment
            if ((c & 0x0F) != 0 || (w.bits >> 8) != 0) return errc::reserved_not_zero;
            return sdo_op::segment_request;
        case 4:  // abort
            if (c != 0x80) return errc::reserved_not_zero;
            return sdo_op::abort_request;
        default: return errc::unknown_command;
    }
}
// The responses visit_sdo_response does not take first: segments, segmented-upload initiations,
// aborts and the refusals.
POWERKEY_DETAIL_INLINE constexpr result<sdo_op> other_response_op(sdo_word w) noexcept {
    const std::uint8_t c = w.specifier();
    switch (c >> 5) {
        case 0: return sdo_op::segment;
        case 2:  // initiate upload
            if ((c & 0x10) != 0) return errc::reserved_not_zero;
            if ((c & 0x02) != 0) return errc::unknown_command;    // expedited without size
            if ((c & 0x0C) != 0) return errc::reserved_not_zero;  // n is only for expedited
            return sdo_op::upload_initiate;
        case 3: return errc::reserved_not_zero;  // download response: only 60h, bytes 4..7 zero
        case 4:                                  // abort
            if (c != 0x80) return errc::reserved_not_zero;
            return sdo_op::abort_response;
        default: return errc::unknown_command;
    }
}

// The frame a client sends (600h + node), handed to the handler of its kind: download() (23h 27h
// 2Bh 2Fh), upload() (40h), other() for the rest, which other_request_op(w) tells apart. Called in
// place, so that a caller's common cases inline as if written here.
template <class R, class Download, class Upload, class Other>
[[nodiscard]] POWERKEY_DETAIL_INLINE constexpr R visit_sdo_request(sdo_word w, Download&& download,
                                                                   Upload&& upload,
                                                                   Other&& other) noexcept {
    const std::uint8_t c = w.specifier();
    if ((c & 0xF3) == 0x23) return download();
    if (c == 0x40 && w.data() == 0) return upload();
    return other();
}

// The frame a server sends (580h + node): download_response() (60h), expedited_upload() (43h 47h
// 4Bh 4Fh), other() for the rest, which other_response_op(w) tells apart.
template <class R, class DownloadResponse, class ExpeditedUpload, class Other>
[[nodiscard]] POWERKEY_DETAIL_INLINE constexpr R visit_sdo_response(
    sdo_word w, DownloadResponse&& download_response, ExpeditedUpload&& expedited_upload,
    Other&& other) noexcept {
    const std::uint8_t c = w.specifier();
    if (c == 0x60 && w.data() == 0) return download_response();
    if ((c & 0xF3) == 0x43) return expedited_upload();
    return other();
}

// Which frame a word is, or why it is none.
[[nodiscard]] constexpr result<sdo_op> sdo_request_op(sdo_word w) noexcept {
    using r = result<sdo_op>;
    return visit_sdo_request<r>(
        w, []() POWERKEY_DETAIL_INLINE_LAMBDA { return r{sdo_op::expedited_download}; },
        []() POWERKEY_DETAIL_INLINE_LAMBDA { return r{sdo_op::upload}; },
        [w]() POWERKEY_DETAIL_INLINE_LAMBDA { return other_request_op(w); });
}
[[nodiscard]] constexpr result<sdo_op> sdo_response_op(sdo_word w) noexcept {
    using r = result<sdo_op>;
    return visit_sdo_response<r>(
        w, []() POWERKEY_DETAIL_INLINE_LAMBDA { return r{sdo_op::download_response}; },
        []() POWERKEY_DETAIL_INLINE_LAMBDA { return r{sdo_op::expedited_upload}; },
        [w]() POWERKEY_DETAIL_INLINE_LAMBDA { return other_response_op(w); });
}

// --- decoding -----------------------------------------------------------------------------------
// The CiA 301 structs of a frame to or from the keypad `node`, read by the engine above; the
// errors are docs/canopen.md's ("SDO").

[[nodiscard]] constexpr result<sdo_request> decode_sdo_request(const can::frame& f,
                                                               node_id node) noexcept {
    using r = result<sdo_request>;
    if (const auto e = detail::check_frame(f, cob_id(function::sdo_rx, node), 8); e != errc{})
        return e;
    const sdo_word w = sdo_word::of(f);
    return visit_sdo_request<r>(
        w,
        [w]() POWERKEY_DETAIL_INLINE_LAMBDA {
            return r{sdo_download_request{w.address(), w.expedited()}};
        },
        [w]() POWERKEY_DETAIL_INLINE_LAMBDA { return r{sdo_upload_request{w.address()}}; },
        [w]() POWERKEY_DETAIL_INLINE_LAMBDA {
            const auto op = other_request_op(w);
            if (!op) return r{op.error()};
            if (*op == sdo_op::segment_request) return r{w.segment_request()};
            return r{w.abort()};
        });
}

[[nodiscard]] constexpr result<sdo_response> decode_sdo_response(const can::frame& f,
                                                                 node_id node) noexcept {
    using r = result<sdo_response>;
    if (const auto e = detail::check_frame(f, cob_id(function::sdo_tx, node), 8); e != errc{})
        return e;
    const sdo_word w = sdo_word::of(f);
    return visit_sdo_response<r>(
        w, [w]() POWERKEY_DETAIL_INLINE_LAMBDA { return r{sdo_download_response{w.address()}}; },
        [w]() POWERKEY_DETAIL_INLINE_LAMBDA {
            return r{sdo_upload_response{w.address(), w.expedited()}};
        },
        [w]() POWERKEY_DETAIL_INLINE_LAMBDA {
            const auto op = other_response_op(w);
            if (!op) return r{op.error()};
            if (*op == sdo_op::segment) return r{w.segment()};
            if (*op == sdo_op::upload_initiate) return r{w.upload_initiate()};
            return r{w.abort()};
        });
}

}  // namespace powerkey::canopen

#endif  // POWERKEY_CANOPEN_SDO_HPP
