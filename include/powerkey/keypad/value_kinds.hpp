// powerkey: what each value kind of an SDO object means, one home per kind: its fields, check,
// value, packing, size, used bits, covered LEDs and abort (docs/decoder.md, "SDO values").
#ifndef POWERKEY_KEYPAD_VALUE_KINDS_HPP
#define POWERKEY_KEYPAD_VALUE_KINDS_HPP

#include <powerkey/can/frame.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/detail/bytes.hpp>
#include <powerkey/detail/inline.hpp>
#include <powerkey/detail/proxy.hpp>
#include <powerkey/keypad/lookup.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/keypad/values.hpp>
#include <powerkey/names.hpp>
#include <powerkey/result.hpp>

#include <array>
#include <bit>
#include <cstdint>
#include <string_view>
#include <type_traits>

namespace powerkey {

// The value of an object, as it travels (docs/decoder.md, "SDO values").
struct object_value {
    std::uint32_t raw = 0;
    leds map{};
    std::uint8_t size = 0;
    friend constexpr bool operator==(const object_value&, const object_value&) noexcept = default;
};

// The "load" signature of a restore (1011h sub 1, PK1000 section 36), little endian.
inline constexpr std::uint32_t load_signature = 0x6461'6F6C;

namespace detail {
using m_layout = model_layout;

// What every kind does unless it says otherwise.
struct kind_defaults {
    static constexpr bool common = false;  // decoded inline by the codec (the frequent kinds)
    static constexpr bool led = false;     // an LED kind: the value is a map (covered())
    static constexpr std::uint8_t size(const m_layout&, const codec_row& r,
                                       std::uint8_t carried) noexcept {
        return r.size() != 0 ? r.size() : carried;
    }
    static constexpr errc check(const m_layout&, const codec_row&, std::uint8_t, std::uint32_t,
                                bool) noexcept {
        return errc{};
    }
    static constexpr object_value value(const m_layout&, const codec_row&, std::uint8_t,
                                        std::uint32_t data) noexcept {
        return {data, {}, 0};
    }
    static constexpr std::uint32_t pack(const m_layout&, const codec_row&,
                                        const object_value& v) noexcept {
        return v.raw;
    }
    static constexpr leds covered(const m_layout&, const codec_row&) noexcept { return {}; }
    static constexpr std::uint32_t used_bits(const m_layout&, const codec_row&) noexcept {
        return 0xFFFF'FFFF;
    }
    // A refused write's abort: invalid_value, or too low or too high (CiA 301 table 22).
    static constexpr canopen::sdo_abort_code abort_for(errc e, std::uint32_t data,
                                                       const codec_row& r) noexcept {
        if (e != errc::value_out_of_range) return canopen::sdo_abort_code::invalid_value;
        return data < value_ranges[r.a].min ? canopen::sdo_abort_code::value_too_low
                                            : canopen::sdo_abort_code::value_too_high;
    }
};

// Bits [at, at + n) of raw as a T, and back (a field of a packed value).
template <class T, class V, class F>
constexpr void bits_field(V& v, F& f, std::string_view name, unsigned at, unsigned n) {
    using u32 = std::uint32_t;
    const u32 mask = static_cast<u32>(low_bits(n));
    proxy_field<T>(
        v, f, name, [at, mask](const auto& s) { return static_cast<T>((s.raw >> at) & mask); },
        [at, mask](auto& s, T x) {
            s.raw = (s.raw & ~(mask << at)) | ((static_cast<u32>(x) & mask) << at);
        });
}
// The same for a checked type (a level, a node id): a value it refuses shows as its default.
template <class T, class V, class F>
constexpr void checked_field(V& v, F& f, std::string_view name, unsigned at, unsigned n) {
    using u32 = std::uint32_t;
    const u32 mask = static_cast<u32>(low_bits(n));
    proxy_field<T>(
        v, f, name,
        [at, mask](const auto& s) { return T::make((s.raw >> at) & mask).value_or(T{}); },
        [at, mask](auto& s, T x) {
            s.raw = (s.raw & ~(mask << at)) | ((u32{x.value()} & mask) << at);
        });
}
template <class V, class F>
constexpr void map_fields(V& map, F& f) {
    f("red", map.red);
    f("green", map.green);
    f("blue", map.blue);
}

// The bits of the numbers of row r's range (its largest value's, and of `also` when it has one).
constexpr std::uint32_t range_bits(const codec_row& r) noexcept {
    const value_range& v = value_ranges[r.a];
    const std::uint32_t top = v.min + v.span < v.min ? 0xFFFF'FFFF : v.min + v.span;
    const std::uint32_t most = v.also != 0xFFFF'FFFF && v.also > top ? v.also : top;
    return static_cast<std::uint32_t>(low_bits(static_cast<unsigned>(std::bit_width(most))));
}

// A value that is one number within the row's range.
struct one_number : kind_defaults {
    static constexpr bool common = true;
    static constexpr errc check(const m_layout&, const codec_row& r, std::uint8_t,
                                std::uint32_t data, bool) noexcept {
        return value_ranges[r.a].contains(data) ? errc{} : errc::value_out_of_range;
    }
    static constexpr std::uint32_t used_bits(const m_layout&, const codec_row& r) noexcept {
        return range_bits(r);
    }
};

// Every LED of the model's planes in `planes` (a plane k, or the first `n` planes).
constexpr leds planes_of(const m_layout& keypad, unsigned first, unsigned count) noexcept {
    leds c;
    for (unsigned p = first; p < first + count && p < 3; ++p)
        c.of(static_cast<plane>(p)) = led_set::from_mask(keypad.led_mask);
    return c;
}
}  // namespace detail

// --- the kinds ----------------------------------------------------------------------------------

namespace value_kinds {
using detail::codec_row;
using detail::m_layout;

// "value": an unsigned number (counts, identity words, times, types), within the row's range.
struct number : detail::one_number {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        f("value", v.raw);
    }
};
// "enabled": 00h off, 01h on.
struct flag : detail::one_number {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::bits_field<bool>(v, f, "enabled", 0, 32);
    }
};
// "level": 00h..3Fh.
struct brightness : detail::one_number {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::checked_field<level>(v, f, "level", 0, 8);
    }
};
// "colour": a backlight colour, 01h..09h.
struct colour : detail::one_number {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::bits_field<backlight_colour>(v, f, "colour", 0, 8);
    }
};
// "baud_rate": the PK1000's codes of 2010h.
struct baud : detail::one_number {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::bits_field<baud_rate>(v, f, "baud_rate", 0, 8);
    }
};
// "startup_show": the PK1000's codes of 2014h.
struct show : detail::one_number {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::bits_field<startup_show>(v, f, "startup_show", 0, 8);
    }
};
// "node_id": 01h..7Fh.
struct node : detail::one_number {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::checked_field<canopen::node_id>(v, f, "node_id", 0, 8);
    }
};
// "period_ms": 0 is off, any other value within the row's range (E-PK-8, E-PKP-7).
struct period : detail::one_number {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        f("period_ms", v.raw);
    }
    static constexpr errc check(const m_layout&, const codec_row& r, std::uint8_t,
                                std::uint32_t data, bool) noexcept {
        if (data != 0 && !detail::value_ranges[r.a].contains(data)) return errc::value_out_of_range;
        return errc{};
    }
};
// "keys": key bits 0..N-1; a bit above the model's keys is reserved.
struct keys : detail::kind_defaults {
    static constexpr bool common = true;
    // "size" only where it is not the row's one size: 1 for the 1-byte reply below (a reader
    // sees it only then; a writer may always set it).
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::proxy_field<key_set>(
            v, f, "keys", [](const auto& s) { return key_set::from_mask(s.raw); },
            [](auto& s, key_set x) { s.raw = static_cast<std::uint32_t>(x.mask()); });
        if (!std::is_const_v<V> || v.size != 0) f("size", v.size);
    }
    // A row of size 0 (the SI keys): 2 bytes, or 1 on 8 keys or fewer (inferred;
    // docs/si-family.md).
    static constexpr std::uint8_t size(const m_layout& keypad, const codec_row& r,
                                       std::uint8_t carried) noexcept {
        if (r.size() != 0) return r.size();
        return carried == 1 && keypad.keys <= 8 ? 1 : 2;
    }
    // The size's low bit: 1 only for the 1-byte reply (keys_rows_even; docs/performance.md).
    static constexpr object_value value(const m_layout&, const codec_row&, std::uint8_t size,
                                        std::uint32_t data) noexcept {
        return {data, {}, static_cast<std::uint8_t>(size & 1)};
    }
    // The size of a row of two sizes is checked here (the decoder takes what it carries).
    static constexpr errc check(const m_layout& keypad, const codec_row& r, std::uint8_t size,
                                std::uint32_t data, bool) noexcept {
        if (size != keys::size(keypad, r, size)) return errc::size_mismatch;
        return (data & keypad.not_keys) != 0 ? errc::reserved_not_zero : errc{};
    }
    static constexpr std::uint32_t used_bits(const m_layout& keypad, const codec_row&) noexcept {
        return ~keypad.not_keys;
    }
};
constexpr bool keys_rows_even() noexcept {
    for (const codec_row& r : detail::codec_rows)
        if (r.kind == value_kind::keys && (r.size() & 1) != 0) return false;
    return true;
}
static_assert(keys_rows_even(), "keys::value reads the 1-byte reply by the size's low bit");
// "red" | "green" | "blue": one plane of an LED map (PK1000 2001h/2002h per colour, SI planes).
struct led_plane : detail::kind_defaults {
    static constexpr bool common = true;
    static constexpr bool led = true;
    template <class V, class F>
    static constexpr void fields(const object_info& o, V& v, F& f) {
        f(to_string(o.holds), v.map.of(o.holds));
    }
    static constexpr std::uint8_t size(const m_layout& keypad, const codec_row& r,
                                       std::uint8_t) noexcept {
        return r.size() != 0 ? r.size() : static_cast<std::uint8_t>(keypad.stride / 8);
    }
    // The one plane r.a (no leds::of: its address would be taken).
    static constexpr errc check(const m_layout& keypad, const codec_row&, std::uint8_t,
                                std::uint32_t data, bool) noexcept {
        return (data & ~keypad.led_mask) != 0 ? errc::reserved_not_zero : errc{};
    }
    static constexpr std::uint32_t used_bits(const m_layout& keypad, const codec_row&) noexcept {
        return keypad.led_mask;
    }
    static constexpr object_value value(const m_layout&, const codec_row& r, std::uint8_t,
                                        std::uint32_t data) noexcept {
        const auto in = [data, &r](plane p) {
            return led_set::from_mask(static_cast<plane>(r.a) == p ? data : 0);
        };
        return {0, {in(plane::red), in(plane::green), in(plane::blue)}, 0};
    }
    static constexpr std::uint32_t pack(const m_layout&, const codec_row& r,
                                        const object_value& v) noexcept {
        return static_cast<std::uint32_t>(v.map.of(static_cast<plane>(r.a)).mask());
    }
    static constexpr leds covered(const m_layout& keypad, const codec_row& r) noexcept {
        return detail::planes_of(keypad, r.a, 1);
    }
};
// "red", "green", "blue": the planes of the model's map that fit 32 bits (PKP 6001h/6002h).
struct led_map : detail::kind_defaults {
    static constexpr bool common = true;
    static constexpr bool led = true;
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::map_fields(v.map, f);
    }
    // unpack_leds(m, data, m.object_planes()), against the complement of the LED bits (one AND)
    static constexpr errc check(const m_layout& keypad, const codec_row&, std::uint8_t,
                                std::uint32_t data, bool) noexcept {
        return (data & keypad.object_not_leds) != 0 ? errc::reserved_not_zero : errc{};
    }
    static constexpr std::uint32_t used_bits(const m_layout& keypad, const codec_row&) noexcept {
        return ~keypad.object_not_leds;
    }
    static constexpr object_value value(const m_layout& keypad, const codec_row&, std::uint8_t,
                                        std::uint32_t data) noexcept {
        const std::uint64_t up = std::uint64_t{data} >> keypad.stride;
        return {
            0,
            {led_set::from_mask(data & keypad.led_mask), led_set::from_mask(up & keypad.led_mask),
             led_set::from_mask((up >> keypad.stride) & keypad.led_mask)},
            0};
    }
    static constexpr std::uint32_t pack(const m_layout& keypad, const codec_row&,
                                        const object_value& v) noexcept {
        return static_cast<std::uint32_t>(pack_leds(keypad, v.map, keypad.object_planes()));
    }
    static constexpr leds covered(const m_layout& keypad, const codec_row&) noexcept {
        return detail::planes_of(keypad, 0, keypad.object_planes());
    }
};
// "period_ms", "producer": a consumer heartbeat (1016h sub 1): period 0 (off) or within the
// row's range, the producer a node id, byte 3 reserved.
struct consumer_heartbeat : detail::kind_defaults {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::bits_field<std::uint16_t>(v, f, "period_ms", 0, 16);
        detail::checked_field<canopen::node_id>(v, f, "producer", 16, 8);
    }
    static constexpr errc check(const m_layout&, const codec_row& r, std::uint8_t,
                                std::uint32_t data, bool) noexcept {
        if ((data >> 24) != 0) return errc::reserved_not_zero;
        const auto time = data & 0xFFFF;
        if (!canopen::node_id::make((data >> 16) & 0xFF) ||
            (time != 0 && !detail::value_ranges[r.a].contains(time)))
            return errc::value_out_of_range;
        return errc{};
    }
    static constexpr std::uint32_t used_bits(const m_layout&, const codec_row&) noexcept {
        return 0x00FF'FFFF;  // byte 3 reserved
    }
    // PK1000 28: a producer that is no node id is an invalid value, a period below 10 ms too low.
    static constexpr canopen::sdo_abort_code abort_for(errc e, std::uint32_t data,
                                                       const codec_row&) noexcept {
        if (e == errc::value_out_of_range && canopen::node_id::make((data >> 16) & 0xFF))
            return canopen::sdo_abort_code::value_too_low;
        return canopen::sdo_abort_code::invalid_value;
    }
};
// "invalid", "no_rtr", "can_id": a PDO COB-ID (CiA 301 7.5.2.35); bits 11..29 reserved.
struct cob_id : detail::kind_defaults {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::bits_field<bool>(v, f, "invalid", 31, 1);
        detail::bits_field<bool>(v, f, "no_rtr", 30, 1);
        detail::checked_field<can::standard_id>(v, f, "can_id", 0, 11);
    }
    static constexpr errc check(const m_layout&, const codec_row&, std::uint8_t, std::uint32_t data,
                                bool) noexcept {
        return (data & 0x3FFF'F800u) != 0 ? errc::reserved_not_zero : errc{};
    }
};
// "index", "subindex", "bits": a PDO mapping entry.
struct pdo_mapping : detail::kind_defaults {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::bits_field<std::uint16_t>(v, f, "index", 16, 16);
        detail::bits_field<std::uint8_t>(v, f, "subindex", 8, 8);
        detail::bits_field<std::uint8_t>(v, f, "bits", 0, 8);
    }
};
// "profile", "digital_input", ...: 1000h (CiA 401 I/O functionality in bits 16..19).
struct device_type : detail::kind_defaults {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::bits_field<std::uint16_t>(v, f, "profile", 0, 16);
        detail::bits_field<bool>(v, f, "digital_input", 16, 1);
        detail::bits_field<bool>(v, f, "digital_output", 17, 1);
        detail::bits_field<bool>(v, f, "analogue_input", 18, 1);
        detail::bits_field<bool>(v, f, "analogue_output", 19, 1);
    }
    static constexpr errc check(const m_layout&, const codec_row&, std::uint8_t, std::uint32_t data,
                                bool) noexcept {
        return (data >> 20) != 0 ? errc::reserved_not_zero : errc{};
    }
    static constexpr std::uint32_t used_bits(const m_layout&, const codec_row&) noexcept {
        return 0x000F'FFFF;
    }
};
// "size", "bytes": up to 4 bytes of a string expedited (more come by segments).
struct string : detail::kind_defaults {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        f("size", v.size);
        detail::proxy_field<std::array<std::uint8_t, 4>>(
            v, f, "bytes",
            [](const auto& s) {
                std::array<std::uint8_t, 4> b{};
                detail::store_le<4>(b, 0, s.raw);
                return b;
            },
            [](auto& s, const std::array<std::uint8_t, 4>& b) {
                s.raw = static_cast<std::uint32_t>(detail::load_le<4>(b, 0));
            });
    }
    static constexpr object_value value(const m_layout&, const codec_row&, std::uint8_t size,
                                        std::uint32_t data) noexcept {
        return {data, {}, size};
    }
};
// "value": a write carries "load" (load_signature); a read the restore flags.
struct restore : detail::kind_defaults {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        f("value", v.raw);
    }
    static constexpr errc check(const m_layout&, const codec_row&, std::uint8_t, std::uint32_t data,
                                bool write) noexcept {
        return write && data != load_signature ? errc::value_out_of_range : errc{};
    }
    static constexpr canopen::sdo_abort_code abort_for(errc, std::uint32_t,
                                                       const codec_row&) noexcept {
        return canopen::sdo_abort_code::cannot_store;  // PK1000 36: only "load"
    }
};
// "red", "green", "blue": bits [offset, offset + width) of the model's LED string (PKP-2600-SI
// 2001h/2002h in three pieces).
struct led_part : detail::kind_defaults {
    static constexpr bool led = true;
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::map_fields(v.map, f);
    }
    static constexpr errc check(const m_layout& keypad, const codec_row& r, std::uint8_t,
                                std::uint32_t data, bool) noexcept {
        // A bit past the piece, or one that names no LED of the model's planes (led_bits).
        if ((data & ~detail::low_bits(r.part_width())) != 0 ||
            ((std::uint64_t{data} << r.a) & ~keypad.led_bits) != 0)
            return errc::reserved_not_zero;
        return errc{};
    }
    static constexpr std::uint32_t used_bits(const m_layout& keypad, const codec_row& r) noexcept {
        return static_cast<std::uint32_t>(detail::low_bits(r.part_width()) &
                                          (keypad.led_bits >> r.a));
    }
    static constexpr object_value value(const m_layout& keypad, const codec_row& r, std::uint8_t,
                                        std::uint32_t data) noexcept {
        return {0, unpack_leds(keypad, std::uint64_t{data} << r.a, keypad.planes).value_or(leds{}),
                0};
    }
    static constexpr std::uint32_t pack(const m_layout& keypad, const codec_row& r,
                                        const object_value& v) noexcept {
        return static_cast<std::uint32_t>((pack_leds(keypad, v.map, keypad.planes) >> r.a) &
                                          detail::low_bits(r.part_width()));
    }
    static constexpr leds covered(const m_layout& keypad, const codec_row& r) noexcept {
        return unpack_leds(keypad, (detail::low_bits(r.part_width()) << r.a) & keypad.led_bits,
                           keypad.planes)
            .value_or(leds{});
    }
};
// "leds": the encoder ring LEDs 1..32 (PKP-3500-MT 2001h/2002h sub 4).
struct ring : detail::kind_defaults {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::proxy_field<led_set>(
            v, f, "leds", [](const auto& s) { return led_set::from_mask(s.raw); },
            [](auto& s, led_set x) { s.raw = static_cast<std::uint32_t>(x.mask()); });
    }
};
// "counterclockwise", "ticks": an encoder's ticks since its last TPDO (PKP-3500-MT 19 b, d).
struct direction_counter : detail::kind_defaults {
    template <class V, class F>
    static constexpr void fields(const object_info&, V& v, F& f) {
        detail::bits_field<bool>(v, f, "counterclockwise", 7, 1);
        detail::bits_field<std::uint8_t>(v, f, "ticks", 0, 7);
    }
    static constexpr std::uint32_t used_bits(const m_layout&, const codec_row&) noexcept {
        return 0xFF;
    }
};
// No value: the keypad aborts a read (1001h, PK1000 31).
struct none : detail::kind_defaults {
    template <class V, class F>
    static constexpr void fields(const object_info&, V&, F&) {}
    static constexpr errc check(const m_layout&, const codec_row&, std::uint8_t, std::uint32_t,
                                bool) noexcept {
        return errc::unknown_object;
    }
};
// The command module (6500h sub 1): a `command` message, not a value (commands.hpp).
struct commands : none {};
}  // namespace value_kinds

// Calls f(value_kinds::K{}) for the kind k (value_kinds::none for a value outside the enum).
template <class F>
POWERKEY_DETAIL_INLINE constexpr decltype(auto) visit_kind(value_kind k, F&& f) {
    switch (k) {
#define POWERKEY_DETAIL_KIND_CASE(name) \
    case value_kind::name: return f(value_kinds::name{});
        POWERKEY_VALUE_KINDS(POWERKEY_DETAIL_KIND_CASE)
#undef POWERKEY_DETAIL_KIND_CASE
    }
    return f(value_kinds::none{});
}

// visit_kind of a row of keypad's dictionary: for a fixed_layout, only its dictionary's kinds (any
// other k is none's).
template <class Layout, class F>
POWERKEY_DETAIL_INLINE constexpr decltype(auto) visit_row_kind(const Layout&, value_kind k, F&& f) {
    if constexpr (detail::is_fixed_layout<Layout>) {
        constexpr std::uint64_t has = detail::kinds_of(Layout::dictionary_value);
        switch (k) {
#define POWERKEY_DETAIL_KIND_CASE(name)                                           \
    case value_kind::name:                                                        \
        if constexpr ((has >> static_cast<unsigned>(value_kind::name) & 1u) != 0) \
            return f(value_kinds::name{});                                        \
        break;
            POWERKEY_VALUE_KINDS(POWERKEY_DETAIL_KIND_CASE)
#undef POWERKEY_DETAIL_KIND_CASE
        }
        return f(value_kinds::none{});
    } else {
        return visit_kind(k, static_cast<F&&>(f));
    }
}

// The fields of v as the kind of object `id` shows them.
template <class V, class F>
constexpr void value_fields(object id, V& v, F& f) {
    const object_info o = info(id);
    visit_kind(o.kind, [&o, &v, &f](auto k) { decltype(k)::fields(o, v, f); });
}

// --- building values (docs/decoder.md, "SDO values": kinds of several fields use fields()) -------

[[nodiscard]] constexpr object_value number_value(std::uint32_t v) noexcept { return {v, {}, 0}; }
[[nodiscard]] constexpr object_value flag_value(bool on) noexcept { return {on ? 1u : 0u, {}, 0}; }
[[nodiscard]] constexpr object_value level_value(level l) noexcept { return {l.value(), {}, 0}; }
[[nodiscard]] constexpr object_value colour_value(backlight_colour c) noexcept {
    return {static_cast<std::uint32_t>(c), {}, 0};
}
[[nodiscard]] constexpr object_value baud_value(baud_rate b) noexcept {
    return {static_cast<std::uint32_t>(b), {}, 0};
}
[[nodiscard]] constexpr object_value show_value(startup_show s) noexcept {
    return {static_cast<std::uint32_t>(s), {}, 0};
}
[[nodiscard]] constexpr object_value node_value(canopen::node_id n) noexcept {
    return {n.value(), {}, 0};
}
[[nodiscard]] constexpr object_value keys_value(key_set k) noexcept {
    return {static_cast<std::uint32_t>(k.mask()), {}, 0};
}
[[nodiscard]] constexpr object_value leds_value(const leds& l) noexcept { return {0, l, 0}; }
[[nodiscard]] constexpr object_value consumer_heartbeat_value(std::uint16_t period_ms,
                                                              canopen::node_id producer) noexcept {
    return {period_ms | (std::uint32_t{producer.value()} << 16), {}, 0};
}
[[nodiscard]] constexpr object_value string_value(std::uint8_t size,
                                                  std::array<std::uint8_t, 4> b) noexcept {
    return {static_cast<std::uint32_t>(detail::load_le<4>(b, 0)), {}, size};
}

}  // namespace powerkey

#endif  // POWERKEY_KEYPAD_VALUE_KINDS_HPP
