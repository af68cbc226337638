// powerkey PKP: the three models (PKP-2200 4 keys, PKP-2400 8 keys, PKP-2600 12 keys, all RGB),
// key numbers, colours, and the one bit-map rule every PKP LED and key map follows:
//   LED (c, k), c = 0 red, 1 green, 2 blue, k = 1..N  ->  bit i = c*N + (k-1)
//   of a little-endian bit string (byte i / 8, bit i % 8).
// The 4- and 8-key rows are the tables of the PKP manual (sections 11, 12, 15, 16); the 12-key row
// is reference/pkp-2600.md (PowerKey Pro UM rev1.4 and PKP2600SI UM, which agree).
#ifndef POWERKEY_PKP_MODEL_HPP
#define POWERKEY_PKP_MODEL_HPP

#include <powerkey/bounded.hpp>
#include <powerkey/can/frame.hpp>
#include <powerkey/detail/bytes.hpp>
#include <powerkey/index_set.hpp>
#include <powerkey/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string_view>

namespace powerkey::pkp {

enum class model : std::uint8_t { pkp2200, pkp2400, pkp2600 };

inline constexpr model all_models[] = {model::pkp2200, model::pkp2400, model::pkp2600};

[[nodiscard]] constexpr std::string_view to_string(model m) noexcept {
    switch (m) {
        case model::pkp2200: return "pkp2200";
        case model::pkp2400: return "pkp2400";
        case model::pkp2600: return "pkp2600";
    }
    return "unknown";
}

// Keys (and RGB LEDs) of a model: 4, 8 or 12; 0 for a value that is not a model.
[[nodiscard]] constexpr std::uint8_t key_count(model m) noexcept {
    switch (m) {
        case model::pkp2200: return 4;
        case model::pkp2400: return 8;
        case model::pkp2600: return 12;
    }
    return 0;
}

inline constexpr std::uint8_t max_keys = 12;

struct key_tag;
// A key number of model M: 1..key_count(M). A literal out of range does not compile.
template <model M>
using key_number = bounded<key_tag, std::uint8_t, 1, key_count(M)>;
// A key number of any model, 1..12; encoders check it against the run-time model.
using key = key_number<model::pkp2600>;

// A set of keys (or of LEDs of one colour), numbered 1..12 as in the manual.
using key_set = index_set<max_keys>;

// The colour planes of the bit-map rule.
enum class plane : std::uint8_t { red = 0, green = 1, blue = 2 };

// Bit index of LED (c, k) for model m: the one rule for every PKP LED map.
[[nodiscard]] constexpr std::size_t led_bit(model m, plane c, unsigned k) noexcept {
    return static_cast<std::size_t>(c) * key_count(m) + (k - 1);
}

// What one RGB key LED shows: a plane or a mix of planes. The mixes are the manual's names
// (section 11: amber = red + green, white = all three; 12: magenta = red + blue; cyan =
// green + blue).
enum class colour : std::uint8_t { off, red, green, blue, amber, cyan, magenta, white };

[[nodiscard]] constexpr std::string_view to_string(colour c) noexcept {
    switch (c) {
        case colour::off: return "off";
        case colour::red: return "red";
        case colour::green: return "green";
        case colour::blue: return "blue";
        case colour::amber: return "amber";
        case colour::cyan: return "cyan";
        case colour::magenta: return "magenta";
        case colour::white: return "white";
    }
    return "unknown";
}

namespace detail {
// Planes of a colour as bits: 1 red, 2 green, 4 blue.
constexpr std::uint8_t planes_of(colour c) noexcept {
    constexpr std::uint8_t table[] = {0, 1, 2, 4, 3, 6, 5, 7};
    const auto i = static_cast<std::size_t>(c);
    return i < 8 ? table[i] : 0;
}
constexpr colour colour_of_planes(unsigned bits) noexcept {
    constexpr colour table[] = {colour::off,  colour::red,     colour::green, colour::amber,
                                colour::blue, colour::magenta, colour::cyan,  colour::white};
    return table[bits & 7u];
}
}  // namespace detail

// The red, green and blue LED of every key: one set per plane, keys 1..12. Used for the LED-on
// and LED-blink maps (RPDO 200h/300h, objects 6001h/6002h). An LED set in both the on map and the
// blink map blinks in alternate mode (manual sections 12 and 16).
struct leds {
    key_set red;
    key_set green;
    key_set blue;

    [[nodiscard]] constexpr const key_set& of(plane c) const noexcept {
        return c == plane::red ? red : c == plane::green ? green : blue;
    }
    constexpr key_set& of(plane c) noexcept {
        return c == plane::red ? red : c == plane::green ? green : blue;
    }
    // Key k shows colour c (off clears all three planes). k outside 1..12 is ignored.
    constexpr leds& set(unsigned k, colour c) noexcept {
        const auto bits = detail::planes_of(c);
        for (unsigned p = 0; p < 3; ++p) {
            if ((bits >> p) & 1u)
                of(static_cast<plane>(p)).insert(k);
            else
                of(static_cast<plane>(p)).erase(k);
        }
        return *this;
    }
    // The colour key k shows (the mix of its set planes).
    [[nodiscard]] constexpr colour colour_of(unsigned k) const noexcept {
        return detail::colour_of_planes((red.contains(k) ? 1u : 0u) |
                                        (green.contains(k) ? 2u : 0u) |
                                        (blue.contains(k) ? 4u : 0u));
    }
    // True when every LED named is one model m has, using only the first `planes` planes.
    [[nodiscard]] constexpr bool fits(model m, unsigned planes = 3) const noexcept {
        const auto n = key_count(m);
        for (unsigned p = 0; p < 3; ++p) {
            const auto mask = of(static_cast<plane>(p)).mask();
            if (p >= planes ? mask != 0 : (mask >> n) != 0) return false;
        }
        return true;
    }
    friend constexpr bool operator==(const leds&, const leds&) noexcept = default;
};

// A message that carries one LED map: the LED-on and LED-blink PDOs (200h/300h) and objects
// 6001h/6002h written or read. The six differ only in their kind, which the Tag names.
template <class Tag>
struct leds_message {
    static constexpr std::string_view kind = Tag::kind;
    template <class Self, class F>
    static constexpr void fields(Self& self, F&& f) {
        f("red", self.value.red);
        f("green", self.value.green);
        f("blue", self.value.blue);
    }
    leds value;
    friend constexpr bool operator==(const leds_message&, const leds_message&) noexcept = default;
};

// An LED map typed for model M: key numbers are checked at compile time, so encoding it for M
// cannot fail. `led_map<model::pkp2400>{{1, colour::red}, {4, colour::amber}}`.
template <model M>
class led_map {
public:
    struct entry {
        key_number<M> key;
        colour shows;
    };
    constexpr led_map() noexcept = default;
    constexpr led_map(std::initializer_list<entry> entries) noexcept {
        for (const auto& e : entries) set(e.key, e.shows);
    }
    constexpr led_map& set(key_number<M> k, colour c) noexcept {
        v_.set(k.value(), c);
        return *this;
    }
    [[nodiscard]] constexpr colour colour_of(key_number<M> k) const noexcept {
        return v_.colour_of(k.value());
    }
    [[nodiscard]] constexpr const leds& value() const noexcept { return v_; }
    friend constexpr bool operator==(const led_map&, const led_map&) noexcept = default;

private:
    leds v_;
};

// How an LED behaves given the LED-on and LED-blink maps (sections 12 and 16).
enum class led_mode : std::uint8_t { off, on, blink, alternate_blink };

[[nodiscard]] constexpr std::string_view to_string(led_mode m) noexcept {
    switch (m) {
        case led_mode::off: return "off";
        case led_mode::on: return "on";
        case led_mode::blink: return "blink";
        case led_mode::alternate_blink: return "alternate_blink";
    }
    return "unknown";
}

[[nodiscard]] constexpr led_mode mode_of(const leds& on, const leds& blink, plane c,
                                         unsigned k) noexcept {
    const bool o = on.of(c).contains(k);
    const bool b = blink.of(c).contains(k);
    return o && b ? led_mode::alternate_blink
           : b    ? led_mode::blink
           : o    ? led_mode::on
                  : led_mode::off;
}

namespace detail {

// Bytes [at, at + width) of p as one little-endian number (width <= 8). Only those bytes are
// read: a decoder never reads past the dlc (tests/test_invariants.cpp poisons them under ASan).
// A switch that falls through rather than a loop: g++ -O2 left the loop at ~55 instructions.
constexpr std::uint64_t load_bits(const can::payload& p, std::size_t at,
                                  std::size_t width) noexcept {
    std::uint64_t v = 0;
    const auto byte = [&p, at](std::size_t i) { return std::uint64_t{p[at + i]} << (8 * i); };
    switch (width) {
        case 8: v |= byte(7); [[fallthrough]];
        case 7: v |= byte(6); [[fallthrough]];
        case 6: v |= byte(5); [[fallthrough]];
        case 5: v |= byte(4); [[fallthrough]];
        case 4: v |= byte(3); [[fallthrough]];
        case 3: v |= byte(2); [[fallthrough]];
        case 2: v |= byte(1); [[fallthrough]];
        case 1: v |= byte(0); [[fallthrough]];
        default: break;
    }
    return v;
}
// ORs the low 8 * width bits of v into bytes [at, at + width) of p.
constexpr void store_bits(std::uint64_t v, can::payload& p, std::size_t at,
                          std::size_t width) noexcept {
    const std::uint64_t mask =
        width >= 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (8 * width)) - 1;
    powerkey::detail::store_le_u64(p, powerkey::detail::load_le_u64(p) | ((v & mask) << (8 * at)));
}
constexpr std::uint64_t key_mask(unsigned n) noexcept { return (std::uint64_t{1} << n) - 1; }

// Writes the first `planes` planes of `l` by the rule into bytes [at, at + width) of p. Callers
// check l.fits(m, planes) first; bits that do not fit are not written. Whole planes at a time:
// plane c is the key mask shifted by c * N (issue 7: a bit loop cost ~300 instructions).
constexpr void pack_leds(model m, const leds& l, unsigned planes, can::payload& p, std::size_t at,
                         std::size_t width) noexcept {
    const unsigned n = key_count(m);
    std::uint64_t v = 0;
    for (unsigned c = 0; c < planes; ++c)
        v |= (l.of(static_cast<plane>(c)).mask() & key_mask(n)) << (c * n);
    store_bits(v, p, at, width);
}

// Reads the first `planes` planes from bytes [at, at + width) of p; any other bit set there is
// errc::reserved_not_zero (it names no LED of the model).
constexpr result<leds> unpack_leds(model m, const can::payload& p, unsigned planes, std::size_t at,
                                   std::size_t width) noexcept {
    const unsigned n = key_count(m);
    if (n == 0) return errc::value_out_of_range;  // not a model
    const std::uint64_t v = load_bits(p, at, width);
    if ((v >> (planes * n)) != 0) return errc::reserved_not_zero;
    leds l;
    for (unsigned c = 0; c < planes; ++c)
        l.of(static_cast<plane>(c)) = key_set::from_mask((v >> (c * n)) & key_mask(n));
    return l;
}

// Keys 1..N as bits 0..N-1 of bytes [at, at + 2).
constexpr void pack_keys(const key_set& keys, can::payload& p, std::size_t at) noexcept {
    store_bits(keys.mask(), p, at, 2);
}

// Any bit above key N is errc::reserved_not_zero.
constexpr result<key_set> unpack_keys(model m, const can::payload& p, std::size_t at,
                                      std::size_t width) noexcept {
    const std::uint64_t v = load_bits(p, at, width);
    if ((v >> key_count(m)) != 0) return errc::reserved_not_zero;
    return key_set::from_mask(v);
}

constexpr bool keys_fit(model m, const key_set& keys) noexcept {
    return (keys.mask() >> key_count(m)) == 0;
}

}  // namespace detail
}  // namespace powerkey::pkp

#endif  // POWERKEY_PKP_MODEL_HPP
