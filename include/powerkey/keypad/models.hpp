// powerkey: the keypads as data. One row per model says everything the codec needs: its object
// dictionary, its keys, its LED planes and the one LED-map rule's stride, the PDOs it has, and how
// it changes node id. Adding a keypad of a known layout is adding a row (and its names).
//
// The LED-map rule, for every keypad: LED (plane c, number k), c = 0 red, 1 green, 2 blue, is
// bit c * stride + (k - 1) of a little-endian bit string (byte i / 8, bit i % 8). PK1000 sections
// 12, 13 (stride 32: red in bytes 0..3, green in 4..7); PKP sections 11, 12, 15, 16 and
// docs/pkp.md for the 12-key PKP-2600 (stride = key count); docs/si-family.md for the SI family
// (the PKP-3500-MT's stride is 16 and keys 1 and 11, the encoder pushes, have no LED; the
// PKP-2200/2300/2400-SI's stride of 8 is inferred).
#ifndef POWERKEY_KEYPAD_MODELS_HPP
#define POWERKEY_KEYPAD_MODELS_HPP

#include <powerkey/detail/enum_table.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/keypad/values.hpp>
#include <powerkey/result.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace powerkey {

enum class model : std::uint8_t {
    pk1000,
    pkp2200,
    pkp2400,
    pkp2600,
    // The SI family (docs/si-family.md)
    pkp2600si,
    pkp3500mt,
    pkp3500si,
    pkp2500si,
    pkp1500li,
    pkp2200si,
    pkp2300si,
    pkp2400si,
    // PKP-1600-SI: its J1939 side only so far (j1939/models.hpp); no row in this table yet.
    pkp1600si,
};

struct model_info {
    powerkey::model id;
    powerkey::dictionary dictionary;
    std::uint8_t keys;       // keys 1..keys
    std::uint8_t leds;       // LEDs 1..leds in each colour plane (some may be missing: led_mask)
    std::uint8_t planes;     // colour planes: 2 red and green, 3 RGB
    std::uint8_t stride;     // bits from one plane to the next in an LED map
    std::uint32_t led_mask;  // the LEDs of one plane: bit k-1 for LED k (PKP-3500-MT: no 1, 11)
    bool brightness_pdo;     // RPDO3 400h + node: LED brightness (PK1000 section 14)
    bool encoder_leds_pdo;   // RPDO3 400h + node: the encoder LED rings (PKP-3500-MT 17)
    bool backlight_pdo;      // RPDO4 500h + node: backlight level (PK1000 section 15)
    bool backlight_colour;   // ... and colour in byte 1 (a level-only keypad needs byte 1 00h)
    bool encoders;           // TPDO2/3 encoder states, TPDO4 analog inputs (PKP-3500-MT 12-14)
    bool j1939;              // the switch to J1939 (object protocol_j1939) and back (PK1000 49)
    // After a node-id change the keypad answers from the new id (PK1000 section 23) or from the
    // old one, then boots up with the new one (PKP section 13 h).
    bool replies_from_new_id;
    // Colour 00h in the backlight PDO returns to the default colour (2003h sub 4) rather than
    // keeping the current one: PKP2600SI manual section 15 (PK1000 15 and PKP3500-MT 18: keep).
    bool backlight_zero_is_default = false;
    // Derived from the fields above, for the PDO decoders (docs/performance.md): the bits of the
    // key-state PDO's bytes 0..3 that name no key, and every bit of an LED map that names an LED.
    std::uint32_t not_keys = keys >= 32 ? 0u : ~((std::uint32_t{1} << keys) - 1);
    std::uint64_t led_bits = std::uint64_t{led_mask} |
                             (planes > 1 ? std::uint64_t{led_mask} << (stride % 64) : 0) |
                             (planes > 2 ? std::uint64_t{led_mask} << (2 * stride % 64) : 0);

    // Colour planes an LED object of 4 bytes (PKP 6001h/6002h) carries: those that fit 32 bits.
    [[nodiscard]] constexpr unsigned object_planes() const noexcept {
        const unsigned fit = 32u / stride;
        return fit < planes ? fit : planes;
    }
};

namespace detail {
using dict = dictionary;
//                                             keys leds planes stride led_mask     brightness
//                                                                                  rings
//                                                                                  backlight colour
//                                                                                  encoders j1939
//                                                                                  new-id
inline constexpr model_info model_table[] = {
    {model::pk1000, dict::pk1000, 10, 28, 2, 32, 0x0FFF'FFFF, true, false, true, true, false, true,
     true},
    {model::pkp2200, dict::pkp_li, 4, 4, 3, 4, 0xF, false, false, false, false, false, false,
     false},
    {model::pkp2400, dict::pkp_li, 8, 8, 3, 8, 0xFF, false, false, false, false, false, false,
     false},
    {model::pkp2600, dict::pkp_li, 12, 12, 3, 12, 0xFFF, false, false, false, false, false, false,
     false},
    {model::pkp2600si, dict::si_packed, 12, 12, 3, 12, 0xFFF, true, false, true, true, false, true,
     true, true},
    {model::pkp3500mt, dict::si_mt, 15, 15, 3, 16, 0x7BFE, false, true, true, true, true, true,
     true},
    {model::pkp3500si, dict::si_per_colour, 15, 15, 3, 16, 0x7FFF, true, false, true, false, false,
     true, true},
    {model::pkp2500si, dict::si_per_colour, 10, 10, 3, 16, 0x3FF, true, false, true, false, false,
     true, true},
    {model::pkp1500li, dict::si_per_colour, 5, 5, 3, 8, 0x1F, false, false, true, false, false,
     true, true},
    {model::pkp2200si, dict::si_per_colour, 4, 4, 3, 8, 0xF, false, false, true, false, false, true,
     true},
    {model::pkp2300si, dict::si_per_colour, 6, 6, 3, 8, 0x3F, false, false, true, false, false,
     true, true},
    {model::pkp2400si, dict::si_per_colour, 8, 8, 3, 8, 0xFF, false, false, true, false, false,
     true, true},
};
constexpr bool models_in_enum_order() noexcept {
    for (std::size_t i = 0; i < std::size(model_table); ++i)
        if (static_cast<std::size_t>(model_table[i].id) != i) return false;
    return true;
}
static_assert(models_in_enum_order());
// The LED-map rule's planes do not overlap (each fits its stride) and end within 64 bits: what
// the codec's LED PDO decoder (two shifts by the stride, a test against led_bits) relies on.
constexpr bool planes_apart() noexcept {
    for (const auto& m : model_table)
        if (m.planes < 1 || m.planes > 3 || m.stride == 0 ||
            (std::uint64_t{m.led_mask} >> m.stride) != 0 || m.stride * m.planes > 64)
            return false;
    return true;
}
static_assert(planes_apart());
}  // namespace detail

inline constexpr std::size_t model_count = std::size(detail::model_table);

// The row of a model; errc::value_out_of_range for a value outside the enum.
[[nodiscard]] constexpr result<model_info> info(model m) noexcept {
    const auto i = static_cast<std::size_t>(m);
    if (i >= model_count) return errc::value_out_of_range;
    return detail::model_table[i];
}

namespace detail {
// The row of a model the caller has checked is one (no copy: the decoders' hot path).
constexpr const model_info& row_of(model m) noexcept {
    return model_table[static_cast<std::size_t>(m)];
}
constexpr bool is_model(model m) noexcept { return static_cast<std::size_t>(m) < model_count; }
}  // namespace detail

// --- the LED-map and key-map rule ---------------------------------------------------------------

// The first `planes` planes of l as the model's bit string. LEDs the model lacks are dropped:
// callers that must refuse them compare with unpack_leds (the codec does).
[[nodiscard]] constexpr std::uint64_t pack_leds(const model_info& m, const leds& l,
                                                unsigned planes) noexcept {
    std::uint64_t v = 0;
    for (unsigned c = 0; c < planes; ++c)
        v |= (l.of(static_cast<plane>(c)).mask() & m.led_mask) << (c * m.stride);
    return v;
}

// The map in a bit string of the model; errc::reserved_not_zero for a set bit that names no LED.
// The planes written out rather than looped: this runs for every LED PDO (docs/performance.md).
[[nodiscard]] constexpr result<leds> unpack_leds(const model_info& m, std::uint64_t v,
                                                 unsigned planes) noexcept {
    const std::uint64_t one = m.led_mask;
    const unsigned s = m.stride;
    std::uint64_t used = one;
    leds l;
    l.red = led_set::from_mask(v & one);
    if (planes > 1) {
        used |= one << s;
        l.green = led_set::from_mask((v >> s) & one);
    }
    if (planes > 2) {
        used |= one << (2 * s);
        l.blue = led_set::from_mask((v >> (2 * s)) & one);
    }
    if ((v & ~used) != 0) return errc::reserved_not_zero;
    return l;
}

// Keys 1..N as bits 0..N-1; errc::reserved_not_zero for a bit above the model's keys.
[[nodiscard]] constexpr result<key_set> unpack_keys(const model_info& m, std::uint64_t v) noexcept {
    if ((v >> m.keys) != 0) return errc::reserved_not_zero;
    return key_set::from_mask(v);
}

// --- names ----------------------------------------------------------------------------------

template <>
struct enum_names<model> {
    static constexpr enum_name_entry<model> entries[] = {
        {model::pk1000, "pk1000"},       {model::pkp2200, "pkp2200"},
        {model::pkp2400, "pkp2400"},     {model::pkp2600, "pkp2600"},
        {model::pkp2600si, "pkp2600si"}, {model::pkp3500mt, "pkp3500mt"},
        {model::pkp3500si, "pkp3500si"}, {model::pkp2500si, "pkp2500si"},
        {model::pkp1500li, "pkp1500li"}, {model::pkp2200si, "pkp2200si"},
        {model::pkp2300si, "pkp2300si"}, {model::pkp2400si, "pkp2400si"},
    };
};

// How the manuals name each keypad, and the model string it reports in 100Bh where a manual
// shows one (PK1000 section 35 "PK1000"; PKP section 22 "PKU2400"; PKP2600SI manual section 33
// "PKP2600SI"; PKP3500-MT manual section 39 "PKP3500MT"; docs/si-family.md for the others).
struct model_names {
    model id;
    std::string_view manual;    // "PKP-2400-LI"
    std::string_view reported;  // 100Bh model id, "" where no manual shows it
};

inline constexpr model_names model_name_table[] = {
    {model::pk1000, "PK1000", "PK1000"},
    {model::pkp2200, "PKP-2200-LI", ""},
    {model::pkp2400, "PKP-2400-LI", "PKU2400"},
    {model::pkp2600, "PKP-2600", ""},
    {model::pkp2600si, "PKP-2600-SI", "PKP2600SI"},
    {model::pkp3500mt, "PKP-3500-MT", "PKP3500MT"},
    {model::pkp3500si, "PKP-3500-SI", "PKP3500SI"},
    {model::pkp2500si, "PKP-2500-SI", ""},
    {model::pkp1500li, "PKP-1500-LI", "PKP1500LI"},
    {model::pkp2200si, "PKP-2200-SI", ""},
    {model::pkp2300si, "PKP-2300-SI", ""},
    {model::pkp2400si, "PKP-2400-SI", ""},
};

namespace detail {
// Lower case, without '-', '_' and spaces: "PKP-2400-LI" -> "pkp2400li".
constexpr bool same_name(std::string_view a, std::string_view b) noexcept {
    auto next = [](std::string_view s, std::size_t& i) -> int {
        while (i < s.size() && (s[i] == '-' || s[i] == '_' || s[i] == ' ')) ++i;
        if (i == s.size()) return -1;
        const char c = s[i++];
        return c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c;
    };
    std::size_t i = 0, j = 0;
    for (;;) {
        const int x = next(a, i), y = next(b, j);
        if (x != y) return false;
        if (x < 0) return true;
    }
}
}  // namespace detail

// A model from any of its names, case and '-' / '_' ignored: "pkp2400", "PKP-2400",
// "PKP-2400-LI", the reported "PKU2400". errc::value_out_of_range for any other text.
[[nodiscard]] constexpr result<model> parse_model(std::string_view text) noexcept {
    for (const auto& n : enum_names<model>::entries)
        if (detail::same_name(n.name, text)) return n.value;
    for (const auto& n : model_name_table)
        if (detail::same_name(n.manual, text) ||
            (!n.reported.empty() && detail::same_name(n.reported, text)))
            return n.id;
    return errc::value_out_of_range;
}

// The model a keypad's reported model string (100Bh, PKP 6100h sub 2) names, if a manual shows it.
[[nodiscard]] constexpr result<model> model_from_report(std::string_view reported) noexcept {
    for (const auto& n : model_name_table)
        if (!n.reported.empty() && n.reported == reported) return n.id;
    return errc::value_out_of_range;
}

}  // namespace powerkey

#endif  // POWERKEY_KEYPAD_MODELS_HPP
