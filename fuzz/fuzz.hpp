// Shared pieces of the fuzz targets: reading values out of the fuzzer's bytes, the binary form of
// a frame in corpus files, a check that aborts with the offending frame, ASan poisoning of the
// bytes past a frame's dlc, and a filler that builds any message from raw field values.
// Not part of the library: this may use the heap and stdio.
#ifndef POWERKEY_FUZZ_FUZZ_HPP
#define POWERKEY_FUZZ_FUZZ_HPP

#include <powerkey/powerkey.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define POWERKEY_FUZZ_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) && !defined(POWERKEY_FUZZ_ASAN)
#define POWERKEY_FUZZ_ASAN 1
#endif
#ifdef POWERKEY_FUZZ_ASAN
#include <sanitizer/asan_interface.h>
#endif

namespace powerkey_fuzz {

using namespace powerkey;

// --- failing loudly ---------------------------------------------------------------------------

[[noreturn]] inline void fail(const char* what, const char* file, int line,
                              const can::frame* f = nullptr) {
    std::fprintf(stderr, "%s:%d: fuzz check failed: %s", file, line, what);
    if (f != nullptr) {
        const auto text = can::format_candump(*f);
        std::fprintf(stderr, " (frame %.*s)", static_cast<int>(text.view().size()),
                     text.view().data());
    }
    std::fprintf(stderr, "\n");
    std::abort();
}

}  // namespace powerkey_fuzz

// A property that must hold for every input; on failure prints the frame and aborts, which both
// libFuzzer and the replay main report as a crash.
#define POWERKEY_FUZZ_CHECK(cond) \
    ((cond) ? (void)0 : ::powerkey_fuzz::fail(#cond, __FILE__, __LINE__))
#define POWERKEY_FUZZ_CHECK_FRAME(cond, frame) \
    ((cond) ? (void)0 : ::powerkey_fuzz::fail(#cond, __FILE__, __LINE__, &(frame)))

namespace powerkey_fuzz {

// --- reading the fuzzer's bytes -----------------------------------------------------------------

// Reads little-endian values off the front of the input; past the end every read is zero, so a
// short input is still a complete (if dull) test case.
class input {
public:
    input(const std::uint8_t* data, std::size_t size) noexcept : bytes_(data, size) {}

    [[nodiscard]] bool empty() const noexcept { return pos_ >= bytes_.size(); }
    [[nodiscard]] std::size_t remaining() const noexcept {
        return empty() ? 0 : bytes_.size() - pos_;
    }
    std::uint8_t u8() noexcept { return empty() ? 0 : bytes_[pos_++]; }

    template <class T>
    T integer() noexcept {
        static_assert(std::is_unsigned_v<T>);
        std::uint64_t v = 0;
        for (std::size_t i = 0; i < sizeof(T); ++i) v |= std::uint64_t{u8()} << (8 * i);
        return static_cast<T>(v);
    }
    // The rest of the input.
    std::span<const std::uint8_t> rest() noexcept {
        const auto r = empty() ? std::span<const std::uint8_t>{} : bytes_.subspan(pos_);
        pos_ = bytes_.size();
        return r;
    }

private:
    std::span<const std::uint8_t> bytes_;
    std::size_t pos_ = 0;
};

// A node id from one byte: every byte maps to one of 1..127.
inline canopen::node_id take_node(input& in) noexcept {
    return canopen::node_id::make(in.u8() % 127 + 1).value();
}

// The binary form of a frame in corpus files:
//   byte 0    bit 7 extended identifier, bits 3..0 dlc (9..15 read as 8)
//   then      the identifier, 2 bytes (standard, masked to 11 bits) or 4 bytes (extended,
//             masked to 29 bits), little endian
//   then      dlc data bytes
// Every byte string reads as some frame, so the fuzzer never wastes an input on a parse error.
inline can::frame take_frame(input& in) noexcept {
    const std::uint8_t flags = in.u8();
    const bool extended = (flags & 0x80) != 0;
    const auto n = static_cast<std::uint8_t>(std::min(flags & 0x0F, 8));
    const auto id = extended ? in.integer<std::uint32_t>() & 0x1FFF'FFFFu
                             : std::uint32_t{in.integer<std::uint16_t>()} & 0x7FFu;
    can::payload p{};
    for (std::size_t i = 0; i < n; ++i) p[i] = in.u8();
    const auto length = can::dlc::make(n).value();
    if (extended) return can::frame(can::extended_id::make(id).value(), length, p);
    return can::frame(can::standard_id::make(id).value(), length, p);
}

// The inverse of take_frame, for the seed writer.
inline void put_frame(std::vector<std::uint8_t>& out, const can::frame& f) {
    out.push_back(static_cast<std::uint8_t>((f.is_extended() ? 0x80 : 0) | f.size()));
    const std::uint32_t id = f.raw_id();
    const std::size_t id_bytes = f.is_extended() ? 4 : 2;
    for (std::size_t i = 0; i < id_bytes; ++i)
        out.push_back(static_cast<std::uint8_t>(id >> (8 * i)));
    for (std::uint8_t b : f.data()) out.push_back(b);
}

// --- the bytes past the dlc ---------------------------------------------------------------------

// While alive, makes every byte of a frame's storage at and past its dlc unreadable under
// AddressSanitizer, so a decoder that looks at a byte the frame does not carry (through
// operator[], bytes() or data()) is reported as a use-after-poison. Without ASan it does nothing.
// The frame must be 8-byte aligned (ASan poisons the tail of an 8-byte granule, never the head).
class poison_past_dlc {
public:
    explicit poison_past_dlc(const can::frame& f) noexcept : f_(f) {
#ifdef POWERKEY_FUZZ_ASAN
        if (reinterpret_cast<std::uintptr_t>(&f) % 8 != 0)
            fail("frame to poison is not 8-byte aligned", __FILE__, __LINE__);
        __asan_poison_memory_region(begin(), length());
#endif
    }
    ~poison_past_dlc() {
#ifdef POWERKEY_FUZZ_ASAN
        __asan_unpoison_memory_region(begin(), length());
#endif
    }
    poison_past_dlc(const poison_past_dlc&) = delete;
    poison_past_dlc& operator=(const poison_past_dlc&) = delete;

    // True when poisoning is in effect and covers exactly the bytes past the dlc (a self-test of
    // the mechanism, so that a test relying on it cannot pass vacuously).
    [[nodiscard]] bool effective() const noexcept {
#ifdef POWERKEY_FUZZ_ASAN
        const auto* data = f_.bytes().data();
        for (std::size_t i = 0; i < 8; ++i) {
            const bool poisoned = __asan_address_is_poisoned(data + i) != 0;
            if (poisoned != (i >= f_.size())) return false;
        }
        return true;
#else
        return false;
#endif
    }

private:
    [[nodiscard]] const void* begin() const noexcept { return f_.bytes().data() + f_.size(); }
    [[nodiscard]] std::size_t length() const noexcept {
        // Up to the end of the object, padding included, so that the last granule is poisoned
        // through its end as ASan requires.
        const auto* object_end = reinterpret_cast<const unsigned char*>(&f_) + sizeof(can::frame);
        return static_cast<std::size_t>(object_end - static_cast<const unsigned char*>(begin()));
    }
    const can::frame& f_;
};

// A frame stored at an 8-byte boundary, as poison_past_dlc needs.
struct alignas(8) aligned_frame {
    can::frame f;
};

// --- filling messages from the input -----------------------------------------------------------
//
// Every field gets an arbitrary raw value, not only a valid one (issue 10: the encoders must
// refuse what their decoder could never return, so the fuzzer must be able to ask for it):
// enums get any value of their underlying type (static_cast<baud_rate>(0xFA)), LED and key sets
// any bits, an object_value any {raw, map, size}, a command any code and any member values.
// Only what the types themselves cannot hold is out of reach: a bounded<> (node id, level, ...)
// is always in its range, so it is drawn from its range.

template <class T>
struct is_std_array : std::false_type {};
template <std::size_t N>
struct is_std_array<std::array<std::uint8_t, N>> : std::true_type {};

template <class T>
struct is_index_set : std::false_type {};
template <std::size_t N>
struct is_index_set<index_set<N>> : std::true_type {};

template <class T>
concept bounded_like = requires {
    typename T::rep;
    T::min;
    T::max;
    T::make(typename T::rep{});
};

void fill_value(input& in, leds& l);
void fill_value(input& in, object_value& v);
void fill_value(input& in, command& c);
void fill_value(input& in, sdo_read& m);
void fill_value(input& in, sdo_write_reply& m);
void fill_value(input& in, sdo_read_reply& m);
void fill_value(input& in, sdo_write& m);
void fill_value(input& in, led_on& m);
void fill_value(input& in, led_blink& m);
void fill_value(input& in, j1939::command& c);
void fill_value(input& in, j1939::multiple_leds& m);

template <class T>
void fill_value(input& in, T& v) {
    if constexpr (std::is_same_v<T, bool>) {
        v = (in.u8() & 1) != 0;
    } else if constexpr (std::is_integral_v<T>) {
        v = in.integer<T>();
    } else if constexpr (std::is_enum_v<T>) {
        // Any raw value, named or not.
        using U = std::underlying_type_t<T>;
        v = static_cast<T>(in.integer<U>());
    } else if constexpr (bounded_like<T>) {
        using R = typename T::rep;
        const std::uint64_t span = std::uint64_t{T::max} - T::min + 1;
        const auto raw = static_cast<std::uint64_t>(in.integer<R>());
        v = T::make(static_cast<std::uint64_t>(T::min) + raw % span).value();
    } else if constexpr (is_std_array<T>::value) {
        for (auto& b : v) b = in.u8();
    } else if constexpr (is_index_set<T>::value) {
        // Any bits the set can hold (a PK1000 has 28 LEDs a plane, a PKP-2400 8, the set 32).
        v = T::from_mask(in.integer<std::uint64_t>());
    } else if constexpr (requires { T::fields(v, [](std::string_view, auto&) {}); }) {
        T::fields(v, [&in](std::string_view, auto& field) { fill_value(in, field); });
    } else {
        static_assert(!sizeof(T), "a field type the fuzzer cannot fill");
    }
}

inline void fill_value(input& in, leds& l) {
    fill_value(in, l.red);
    fill_value(in, l.green);
    fill_value(in, l.blue);
}

// A flags byte says which parts are arbitrary; the others stay zero, so that a value valid for
// its object (raw only, or map only) is one bit away and the accepting paths are reached too.
inline void fill_value(input& in, object_value& v) {
    const std::uint8_t flags = in.u8();
    v = {};
    if ((flags & 1) != 0) v.raw = in.integer<std::uint32_t>();
    if ((flags & 2) != 0) fill_value(in, v.map);
    if ((flags & 4) != 0) v.size = in.u8();
}

// Any command byte. With flag bit 0 only the members the command's row names are filled (the
// others keep their defaults, as encode requires); with it set, every member.
inline void fill_value(input& in, command& c) {
    const std::uint8_t flags = in.u8();
    c = command{};
    c.code = static_cast<command_code>(in.u8());
    if ((flags & 1) == 0) {
        command::fields(c, [&in](std::string_view name, auto& field) {
            if (name != "command") fill_value(in, field);
        });
        return;
    }
    fill_value(in, c.key);
    fill_value(in, c.state);
    fill_value(in, c.level);
    fill_value(in, c.colour);
    fill_value(in, c.enabled);
    fill_value(in, c.baud);
    fill_value(in, c.period_10ms);
    fill_value(in, c.node_id);
    fill_value(in, c.show);
}

// The SDO messages of the flat message type: the object (any byte) and the value, raw.
inline void fill_value(input& in, sdo_read& m) { fill_value(in, m.object); }
inline void fill_value(input& in, sdo_write_reply& m) { fill_value(in, m.object); }
inline void fill_value(input& in, sdo_read_reply& m) {
    fill_value(in, m.object);
    fill_value(in, m.value);
}
inline void fill_value(input& in, sdo_write& m) {
    fill_value(in, m.object);
    fill_value(in, m.value);
}
inline void fill_value(input& in, led_on& m) { fill_value(in, m.map); }
inline void fill_value(input& in, led_blink& m) { fill_value(in, m.map); }

// A J1939 command: as the CANopen command, flag bit 0 clear fills the members its row names,
// set fills every member (a member the command does not use makes it one encode refuses).
inline void fill_value(input& in, j1939::command& c) {
    const std::uint8_t flags = in.u8();
    c = j1939::command{};
    if ((flags & 1) == 0) {
        c.code = static_cast<j1939::command_code>(in.u8());
        j1939::command::fields(c, [&in](std::string_view name, auto& field) {
            if (name != "command") fill_value(in, field);
        });
        return;
    }
    fill_value(in, c.priority);
    fill_value(in, c.destination);
    fill_value(in, c.source);
    fill_value(in, c.code);
    fill_value(in, c.level);
    fill_value(in, c.enabled);
    fill_value(in, c.show);
    fill_value(in, c.multiple_leds);
    fill_value(in, c.address);
    fill_value(in, c.identifier);
    fill_value(in, c.baud);
    fill_value(in, c.period_10ms);
    fill_value(in, c.colour);
}

// A multiple-LED frame: flag bit 0 clear fills it through its fields (one LED set per code),
// set fills the stored nibbles raw (codes Ah..Eh, LEDs past the model's).
inline void fill_value(input& in, j1939::multiple_leds& m) {
    const std::uint8_t flags = in.u8();
    m = j1939::multiple_leds{};
    if ((flags & 1) == 0) {
        j1939::multiple_leds::fields(
            m, [&in](std::string_view, auto& field) { fill_value(in, field); });
        return;
    }
    fill_value(in, m.priority);
    fill_value(in, m.destination);
    fill_value(in, m.source);
    fill_value(in, m.frame);
    m.nibbles = j1939::multiple_leds::halves(in.integer<std::uint64_t>());
}

template <class T>
struct is_variant : std::false_type {};
template <class... T>
struct is_variant<std::variant<T...>> : std::true_type {};

// A default-constructed alternative of a variant, chosen by index.
template <class V, std::size_t I = 0>
V variant_alternative_at(std::size_t index) {
    if constexpr (I + 1 < std::variant_size_v<V>) {
        if (index != I) return variant_alternative_at<V, I + 1>(index);
    }
    return V{std::in_place_index<I>};
}

// A message: one input byte picks the alternative, the rest fill it.
template <class M>
void fill_any(input& in, M& m) {
    if constexpr (is_variant<M>::value) {
        m = variant_alternative_at<M>(in.u8() % std::variant_size_v<M>);
        std::visit([&](auto& alt) { fill_any(in, alt); }, m);
    } else {
        fill_value(in, m);
    }
}

// --- the inverse, for the seed writer ------------------------------------------------------------
// put_any(out, m) writes the bytes that fill_any reads back as m, so that the encoder's seeds are
// the manual's messages themselves.

template <class T>
void put_integer(std::vector<std::uint8_t>& out, T v, std::size_t bytes = sizeof(T)) {
    for (std::size_t i = 0; i < bytes; ++i)
        out.push_back(static_cast<std::uint8_t>(static_cast<std::uint64_t>(v) >> (8 * i)));
}

void put_value(std::vector<std::uint8_t>& out, const leds& l);
void put_value(std::vector<std::uint8_t>& out, const object_value& v);
void put_value(std::vector<std::uint8_t>& out, const command& c);
void put_value(std::vector<std::uint8_t>& out, const sdo_read& m);
void put_value(std::vector<std::uint8_t>& out, const sdo_write_reply& m);
void put_value(std::vector<std::uint8_t>& out, const sdo_read_reply& m);
void put_value(std::vector<std::uint8_t>& out, const sdo_write& m);
void put_value(std::vector<std::uint8_t>& out, const led_on& m);
void put_value(std::vector<std::uint8_t>& out, const led_blink& m);
void put_value(std::vector<std::uint8_t>& out, const j1939::command& c);
void put_value(std::vector<std::uint8_t>& out, const j1939::multiple_leds& m);

template <class T>
void put_value(std::vector<std::uint8_t>& out, const T& v) {
    if constexpr (std::is_same_v<T, bool>) {
        out.push_back(v ? 1 : 0);
    } else if constexpr (std::is_integral_v<T>) {
        put_integer(out, v);
    } else if constexpr (std::is_enum_v<T>) {
        put_integer(out, static_cast<std::underlying_type_t<T>>(v));
    } else if constexpr (bounded_like<T>) {
        put_integer(out, static_cast<typename T::rep>(v.value() - T::min));
    } else if constexpr (is_std_array<T>::value) {
        out.insert(out.end(), v.begin(), v.end());
    } else if constexpr (is_index_set<T>::value) {
        put_integer(out, v.mask(), 8);
    } else {
        T::fields(v, [&out](std::string_view, const auto& field) { put_value(out, field); });
    }
}

inline void put_value(std::vector<std::uint8_t>& out, const leds& l) {
    put_value(out, l.red);
    put_value(out, l.green);
    put_value(out, l.blue);
}
inline void put_value(std::vector<std::uint8_t>& out, const object_value& v) {
    out.push_back(7);
    put_integer(out, v.raw);
    put_value(out, v.map);
    out.push_back(v.size);
}
inline void put_value(std::vector<std::uint8_t>& out, const command& c) {
    out.push_back(1);
    put_value(out, c.code);
    put_value(out, c.key);
    put_value(out, c.state);
    put_value(out, c.level);
    put_value(out, c.colour);
    put_value(out, c.enabled);
    put_value(out, c.baud);
    put_value(out, c.period_10ms);
    put_value(out, c.node_id);
    put_value(out, c.show);
}
inline void put_value(std::vector<std::uint8_t>& out, const sdo_read& m) {
    put_value(out, m.object);
}
inline void put_value(std::vector<std::uint8_t>& out, const sdo_write_reply& m) {
    put_value(out, m.object);
}
inline void put_value(std::vector<std::uint8_t>& out, const sdo_read_reply& m) {
    put_value(out, m.object);
    put_value(out, m.value);
}
inline void put_value(std::vector<std::uint8_t>& out, const sdo_write& m) {
    put_value(out, m.object);
    put_value(out, m.value);
}
inline void put_value(std::vector<std::uint8_t>& out, const led_on& m) { put_value(out, m.map); }
inline void put_value(std::vector<std::uint8_t>& out, const led_blink& m) { put_value(out, m.map); }
inline void put_value(std::vector<std::uint8_t>& out, const j1939::command& c) {
    out.push_back(1);
    put_value(out, c.priority);
    put_value(out, c.destination);
    put_value(out, c.source);
    put_value(out, c.code);
    put_value(out, c.level);
    put_value(out, c.enabled);
    put_value(out, c.show);
    put_value(out, c.multiple_leds);
    put_value(out, c.address);
    put_value(out, c.identifier);
    put_value(out, c.baud);
    put_value(out, c.period_10ms);
    put_value(out, c.colour);
}
inline void put_value(std::vector<std::uint8_t>& out, const j1939::multiple_leds& m) {
    out.push_back(1);
    put_value(out, m.priority);
    put_value(out, m.destination);
    put_value(out, m.source);
    put_value(out, m.frame);
    put_integer(out, m.word());
}

template <class M>
void put_any(std::vector<std::uint8_t>& out, const M& m) {
    if constexpr (is_variant<M>::value) {
        out.push_back(static_cast<std::uint8_t>(m.index()));
        std::visit([&out](const auto& alt) { put_any(out, alt); }, m);
    } else {
        put_value(out, m);
    }
}

// Is the error one of the listed codes (a named errc)?
inline bool is_listed(errc e) {
    const auto all = enum_values<errc>();
    return is_named(e) && std::find(all.begin(), all.end(), e) != all.end();
}

}  // namespace powerkey_fuzz

#endif  // POWERKEY_FUZZ_FUZZ_HPP
