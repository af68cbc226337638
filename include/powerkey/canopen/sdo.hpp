// powerkey: SDO frames (CiA 301 7.2.4), the subset the keypads speak. Every SDO frame has 8 bytes.
//   client -> keypad, COB-ID 600h + node          keypad -> client, COB-ID 580h + node
//   23/27/2B/2F  expedited download, 4/3/2/1 B     60     download response
//   40           upload request                    43/47/4B/4F expedited upload, 4/3/2/1 B
//   60 / 70      upload segment request, toggle    41     segmented upload, size in bytes 4..7
//   80           abort (either direction)          40     segmented upload, size not indicated
//                                                  0x     upload segment (toggle, unused, last)
// Bytes 1..2 hold the index (little endian), byte 3 the sub-index, bytes 4..7 the data.
#ifndef POWERKEY_CANOPEN_SDO_HPP
#define POWERKEY_CANOPEN_SDO_HPP

#include <powerkey/bounded.hpp>
#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/detail/bytes.hpp>
#include <powerkey/enum_names.hpp>

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
    static constexpr std::string_view kind = "sdo_download";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("index", self.address.index);
        f("subindex", self.address.subindex);
        f("size", self.value.size);
        f("data", self.value.bytes);
    }
    sdo_address address;
    expedited_data value;
    friend constexpr bool operator==(const sdo_download_request&,
                                     const sdo_download_request&) noexcept = default;
};

// Read an entry (command 40h).
struct sdo_upload_request {
    static constexpr std::string_view kind = "sdo_upload";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("index", self.address.index);
        f("subindex", self.address.subindex);
    }
    sdo_address address;
    friend constexpr bool operator==(const sdo_upload_request&,
                                     const sdo_upload_request&) noexcept = default;
};

// Ask for the next segment of a segmented upload (60h toggle 0, 70h toggle 1).
struct sdo_segment_request {
    static constexpr std::string_view kind = "sdo_segment_request";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("toggle", self.toggle);
    }
    bool toggle = false;
    friend constexpr bool operator==(const sdo_segment_request&,
                                     const sdo_segment_request&) noexcept = default;
};

// --- server -> client (580h + node) ---------------------------------------------------------

// A write was done (60h).
struct sdo_download_response {
    static constexpr std::string_view kind = "sdo_download_response";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("index", self.address.index);
        f("subindex", self.address.subindex);
    }
    sdo_address address;
    friend constexpr bool operator==(const sdo_download_response&,
                                     const sdo_download_response&) noexcept = default;
};

// The value read, 1..4 bytes (4Fh, 4Bh, 47h, 43h).
struct sdo_upload_response {
    static constexpr std::string_view kind = "sdo_upload_response";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("index", self.address.index);
        f("subindex", self.address.subindex);
        f("size", self.value.size);
        f("data", self.value.bytes);
    }
    sdo_address address;
    expedited_data value;
    friend constexpr bool operator==(const sdo_upload_response&,
                                     const sdo_upload_response&) noexcept = default;
};

// A segmented upload begins: 41h with the size in bytes 4..7, or 40h without a size (bytes 4..7
// are then reserved; what they held is kept in `size` so the frame re-encodes unchanged).
struct sdo_upload_initiate_response {
    static constexpr std::string_view kind = "sdo_upload_initiate_response";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("index", self.address.index);
        f("subindex", self.address.subindex);
        f("size_indicated", self.size_indicated);
        f("size", self.size);
    }
    sdo_address address;
    bool size_indicated = true;
    std::uint32_t size = 0;
    friend constexpr bool operator==(const sdo_upload_initiate_response&,
                                     const sdo_upload_initiate_response&) noexcept = default;
};

// One segment: byte 0 = 000t nnnc (t toggle, n bytes without data, c last segment), then 7 bytes
// of which the first 7 - n are data. The unused bytes are kept as received.
struct sdo_segment_response {
    static constexpr std::string_view kind = "sdo_segment_response";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("toggle", self.toggle);
        f("unused", self.unused);
        f("last", self.last);
        f("data", self.bytes);
    }
    bool toggle = false;
    segment_unused unused = 0;
    bool last = false;
    std::array<std::uint8_t, 7> bytes{};

    [[nodiscard]] constexpr std::span<const std::uint8_t> data() const noexcept {
        return {bytes.data(), static_cast<std::size_t>(7 - unused.value())};
    }
    friend constexpr bool operator==(const sdo_segment_response&,
                                     const sdo_segment_response&) noexcept = default;
};

// --- both directions --------------------------------------------------------------------------

// CiA 301 table 22, the abort codes; a decoded abort keeps any 32-bit code, named or not.
enum class sdo_abort_code : std::uint32_t {
    toggle_bit_not_alternated = 0x0503'0000,
    timed_out = 0x0504'0000,
    invalid_command_specifier = 0x0504'0001,
    invalid_block_size = 0x0504'0002,
    invalid_sequence_number = 0x0504'0003,
    crc_error = 0x0504'0004,
    out_of_memory = 0x0504'0005,
    unsupported_access = 0x0601'0000,
    write_only = 0x0601'0001,
    read_only = 0x0601'0002,
    object_does_not_exist = 0x0602'0000,
    cannot_be_mapped = 0x0604'0041,
    exceeds_pdo_length = 0x0604'0042,
    parameter_incompatibility = 0x0604'0043,
    internal_incompatibility = 0x0604'0047,
    hardware_error = 0x0606'0000,
    length_mismatch = 0x0607'0010,
    length_too_high = 0x0607'0012,
    length_too_low = 0x0607'0013,
    subindex_does_not_exist = 0x0609'0011,
    invalid_value = 0x0609'0030,
    value_too_high = 0x0609'0031,
    value_too_low = 0x0609'0032,
    max_less_than_min = 0x0609'0036,
    resource_not_available = 0x060A'0023,
    general_error = 0x0800'0000,
    cannot_store = 0x0800'0020,
    cannot_store_local_control = 0x0800'0021,
    cannot_store_device_state = 0x0800'0022,
    no_object_dictionary = 0x0800'0023,
    no_data = 0x0800'0024,
};

}  // namespace powerkey::canopen

// CiA 301 table 22's abort codes by name; a code CiA 301 does not name prints as "".
template <>
struct powerkey::enum_names<powerkey::canopen::sdo_abort_code> {
    using c = canopen::sdo_abort_code;
    static constexpr enum_name_entry<c> entries[] = {
        {c::toggle_bit_not_alternated, "toggle_bit_not_alternated"},
        {c::timed_out, "timed_out"},
        {c::invalid_command_specifier, "invalid_command_specifier"},
        {c::invalid_block_size, "invalid_block_size"},
        {c::invalid_sequence_number, "invalid_sequence_number"},
        {c::crc_error, "crc_error"},
        {c::out_of_memory, "out_of_memory"},
        {c::unsupported_access, "unsupported_access"},
        {c::write_only, "write_only"},
        {c::read_only, "read_only"},
        {c::object_does_not_exist, "object_does_not_exist"},
        {c::cannot_be_mapped, "cannot_be_mapped"},
        {c::exceeds_pdo_length, "exceeds_pdo_length"},
        {c::parameter_incompatibility, "parameter_incompatibility"},
        {c::internal_incompatibility, "internal_incompatibility"},
        {c::hardware_error, "hardware_error"},
        {c::length_mismatch, "length_mismatch"},
        {c::length_too_high, "length_too_high"},
        {c::length_too_low, "length_too_low"},
        {c::subindex_does_not_exist, "subindex_does_not_exist"},
        {c::invalid_value, "invalid_value"},
        {c::value_too_high, "value_too_high"},
        {c::value_too_low, "value_too_low"},
        {c::max_less_than_min, "max_less_than_min"},
        {c::resource_not_available, "resource_not_available"},
        {c::general_error, "general_error"},
        {c::cannot_store, "cannot_store"},
        {c::cannot_store_local_control, "cannot_store_local_control"},
        {c::cannot_store_device_state, "cannot_store_device_state"},
        {c::no_object_dictionary, "no_object_dictionary"},
        {c::no_data, "no_data"},
    };
};

namespace powerkey::canopen {

// Abort transfer (80h), index, sub-index and a 32-bit code.
struct sdo_abort {
    static constexpr std::string_view kind = "sdo_abort";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("index", self.address.index);
        f("subindex", self.address.subindex);
        f("code", self.code);
    }
    sdo_address address;
    sdo_abort_code code = sdo_abort_code::general_error;
    friend constexpr bool operator==(const sdo_abort&, const sdo_abort&) noexcept = default;
};

// The two directions of an abort as messages of their own: canopen::sdo_abort has no direction,
// and a message type that holds both needs them apart so that each re-encodes on its COB-ID.
// Sent by the client (600h + node):
struct sdo_abort_request {
    static constexpr std::string_view kind = "sdo_abort_request";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        sdo_abort::fields(self.abort, f);
    }
    sdo_abort abort;
    friend constexpr bool operator==(const sdo_abort_request&,
                                     const sdo_abort_request&) noexcept = default;
};

// Sent by the keypad (580h + node):
struct sdo_abort_response {
    static constexpr std::string_view kind = "sdo_abort_response";
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        sdo_abort::fields(self.abort, f);
    }
    sdo_abort abort;
    friend constexpr bool operator==(const sdo_abort_response&,
                                     const sdo_abort_response&) noexcept = default;
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
constexpr std::uint8_t size_bits(expedited_size s) noexcept {
    return static_cast<std::uint8_t>((4 - s.value()) << 2);
}
constexpr can::frame sdo_frame(function f, node_id node, const can::payload& p) noexcept {
    return can::frame(cob_id(f, node), 8, p);
}
constexpr can::payload with_data(std::uint8_t command, sdo_address a,
                                 const std::array<std::uint8_t, 4>& d) noexcept {
    auto p = with_address(command, a);
    for (std::size_t i = 0; i < 4; ++i) p[4 + i] = d[i];
    return p;
}
}  // namespace detail

[[nodiscard]] constexpr can::frame encode(node_id node, const sdo_download_request& m) noexcept {
    return detail::sdo_frame(
        function::sdo_rx, node,
        detail::with_data(static_cast<std::uint8_t>(0x23 | detail::size_bits(m.value.size)),
                          m.address, m.value.bytes));
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
    return detail::sdo_frame(
        function::sdo_tx, node,
        detail::with_data(static_cast<std::uint8_t>(0x43 | detail::size_bits(m.value.size)),
                          m.address, m.value.bytes));
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

[[nodiscard]] constexpr can::frame encode_request(node_id node, const sdo_request& m) noexcept {
    return std::visit(
        [node](const auto& v) -> can::frame {
            if constexpr (std::is_same_v<std::decay_t<decltype(v)>, sdo_abort>)
                return encode(node, v, sdo_direction::request);
            else
                return encode(node, v);
        },
        m);
}
[[nodiscard]] constexpr can::frame encode_response(node_id node, const sdo_response& m) noexcept {
    return std::visit(
        [node](const auto& v) -> can::frame {
            if constexpr (std::is_same_v<std::decay_t<decltype(v)>, sdo_abort>)
                return encode(node, v, sdo_direction::response);
            else
                return encode(node, v);
        },
        m);
}

// --- decoding -----------------------------------------------------------------------------------

namespace detail {
constexpr sdo_address address_of(const can::frame& f) noexcept {
    return {static_cast<std::uint16_t>(powerkey::detail::load_le<2>(f.bytes(), 1)), f[3]};
}
constexpr std::array<std::uint8_t, 4> data_of(const can::frame& f) noexcept {
    return {f[4], f[5], f[6], f[7]};
}
constexpr expedited_data expedited_of(const can::frame& f) noexcept {
    return {expedited_size::make(4 - ((f[0] >> 2) & 3)).value(), data_of(f)};
}
constexpr sdo_abort abort_of(const can::frame& f) noexcept {
    return {address_of(f), static_cast<sdo_abort_code>(static_cast<std::uint32_t>(
                               powerkey::detail::load_le<4>(f.bytes(), 4)))};
}
}  // namespace detail

// A frame from the client to the keypad `node`, handed to `on` as the struct it is
// (sdo_download_request, sdo_upload_request, sdo_segment_request or sdo_abort); `on` returns
// an R, and so does every refusal. decode_sdo_request below is this with R a variant; the
// keypad codec uses it to build its own message with no variant in between. Errors:
// wrong_id_format, wrong_id (not 600h + node), wrong_length (not 8 bytes), unknown_command (a
// specifier the keypads do not use: segmented or block download, expedited download without
// size), reserved_not_zero (an upload or segment request with reserved bits or bytes set, e.g.
// 41h for 40h).
template <class R, class F>
[[nodiscard]] constexpr R visit_sdo_request_data(const can::frame& f, F&& on) noexcept;
template <class R, class F>
[[nodiscard]] constexpr R visit_sdo_request(const can::frame& f, node_id node, F&& on) noexcept {
    if (const auto e = detail::check_frame(f, cob_id(function::sdo_rx, node), 8); e != errc{})
        return e;
    return visit_sdo_request_data<R>(f, on);
}

// The same for a frame whose identifier the caller has already checked (the keypad codec
// classifies every frame first): only the length and the data are checked here.
template <class R, class F>
[[nodiscard]] constexpr R visit_sdo_request_data(const can::frame& f, F&& on) noexcept {
    if (f.size() != 8) return errc::wrong_length;
    const std::uint8_t c = f[0];
    switch (c >> 5) {
        case 1:  // initiate download: only expedited with size indicated (e = s = 1)
            if ((c & 0x13) != 0x03) return errc::unknown_command;
            return on(sdo_download_request{detail::address_of(f), detail::expedited_of(f)});
        case 2:  // initiate upload
            if (c != 0x40 || !powerkey::detail::all_zero(f.bytes(), 4, 8))
                return errc::reserved_not_zero;
            return on(sdo_upload_request{detail::address_of(f)});
        case 3:  // upload segment
            if ((c & 0x0F) != 0 || !powerkey::detail::all_zero(f.bytes(), 1, 8))
                return errc::reserved_not_zero;
            return on(sdo_segment_request{(c & 0x10) != 0});
        case 4:  // abort
            if (c != 0x80) return errc::reserved_not_zero;
            return on(detail::abort_of(f));
        default: return errc::unknown_command;
    }
}

// A frame from the keypad `node` to the client, handed to `on` as sdo_segment_response,
// sdo_upload_response, sdo_upload_initiate_response, sdo_download_response or sdo_abort.
// Errors: wrong_id_format, wrong_id (not 580h + node), wrong_length (not 8 bytes),
// unknown_command (download segment, block transfer, expedited upload without size),
// reserved_not_zero (reserved bits or bytes set in a download response or abort).
template <class R, class F>
[[nodiscard]] constexpr R visit_sdo_response_data(const can::frame& f, F&& on) noexcept;
template <class R, class F>
[[nodiscard]] constexpr R visit_sdo_response(const can::frame& f, node_id node, F&& on) noexcept {
    if (const auto e = detail::check_frame(f, cob_id(function::sdo_tx, node), 8); e != errc{})
        return e;
    return visit_sdo_response_data<R>(f, on);
}

// The same for a frame whose identifier the caller has already checked.
template <class R, class F>
[[nodiscard]] constexpr R visit_sdo_response_data(const can::frame& f, F&& on) noexcept {
    if (f.size() != 8) return errc::wrong_length;
    const std::uint8_t c = f[0];
    switch (c >> 5) {
        case 0:  // upload segment
            return on(sdo_segment_response{(c & 0x10) != 0,
                                           segment_unused::make((c >> 1) & 7).value(),
                                           (c & 1) != 0,
                                           {f[1], f[2], f[3], f[4], f[5], f[6], f[7]}});
        case 2:  // initiate upload
            if ((c & 0x10) != 0) return errc::reserved_not_zero;
            if ((c & 0x02) != 0) {  // expedited
                if ((c & 0x01) == 0) return errc::unknown_command;
                return on(sdo_upload_response{detail::address_of(f), detail::expedited_of(f)});
            }
            if ((c & 0x0C) != 0) return errc::reserved_not_zero;  // n is only for expedited
            return on(sdo_upload_initiate_response{
                detail::address_of(f), (c & 0x01) != 0,
                static_cast<std::uint32_t>(powerkey::detail::load_le<4>(f.bytes(), 4))});
        case 3:  // initiate download response
            if (c != 0x60 || !powerkey::detail::all_zero(f.bytes(), 4, 8))
                return errc::reserved_not_zero;
            return on(sdo_download_response{detail::address_of(f)});
        case 4:  // abort
            if (c != 0x80) return errc::reserved_not_zero;
            return on(detail::abort_of(f));
        default: return errc::unknown_command;
    }
}

// The same as a variant of the structs.
[[nodiscard]] constexpr result<sdo_request> decode_sdo_request(const can::frame& f,
                                                               node_id node) noexcept {
    return visit_sdo_request<result<sdo_request>>(
        f, node, [](const auto& m) -> result<sdo_request> { return sdo_request{m}; });
}
[[nodiscard]] constexpr result<sdo_response> decode_sdo_response(const can::frame& f,
                                                                 node_id node) noexcept {
    return visit_sdo_response<result<sdo_response>>(
        f, node, [](const auto& m) -> result<sdo_response> { return sdo_response{m}; });
}

}  // namespace powerkey::canopen

#endif  // POWERKEY_CANOPEN_SDO_HPP
