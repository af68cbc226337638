// powerkey: the keypads as data, one row of POWERKEY_MODELS each (docs/models.md, "The model
// table"), and the LED-map rule every keypad follows ("The one bit-map rule").
#ifndef POWERKEY_KEYPAD_MODELS_HPP
#define POWERKEY_KEYPAD_MODELS_HPP

#include <powerkey/detail/bytes.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/keypad/values.hpp>
#include <powerkey/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string_view>

namespace powerkey {

enum class model : std::uint8_t;  // every keypad: POWERKEY_MODELS below

// A string object as the keypad sends it: the bytes exactly as the manual prints them (NUL
// padding and all, E-CORE-5), and what the initiate reply announces. Strings of up to 4 bytes go
// expedited (43h), longer ones segmented: 41h with `announced` in bytes 4..7, or 40h ("size not
// indicated") with `announced` still in byte 4 where the manual prints that (E-CORE-3).
struct keypad_string {
    powerkey::object id = object::keys;
    std::string_view bytes;  // empty: no string (the rest of a model's `strings`)
    std::uint32_t announced = 0;
    bool size_indicated = true;
    std::string_view section;  // where a manual prints it; "inferred ..." where none does
};

// The row of a model. Flags default to false, so a row names only what its keypad has.
struct model_info {
    powerkey::model id;
    std::string_view name;    // the tool's and the enum's name: "pkp2400"
    std::string_view manual;  // how its manual names it: "PKP-2400-LI"
    powerkey::dictionary dictionary;
    std::uint8_t keys;       // keys 1..keys
    std::uint8_t leds;       // LEDs 1..leds in each colour plane (some may be missing: led_mask)
    std::uint8_t planes;     // colour planes: 2 red and green, 3 RGB
    std::uint8_t stride;     // bits from one plane to the next in an LED map
    std::uint32_t led_mask;  // the LEDs of one plane: bit k-1 for LED k (PKP-3500-MT: no 1, 11)
    bool brightness_pdo = false;    // RPDO3 400h + node: LED brightness (PK1000 section 14)
    bool encoder_leds_pdo = false;  // RPDO3 400h + node: the encoder LED rings (PKP-3500-MT 17)
    bool backlight_pdo = false;     // RPDO4 500h + node: backlight level (PK1000 section 15)
    bool backlight_colour = false;  // ... and colour in byte 1 (a level-only keypad needs 00h)
    bool encoders = false;          // TPDO2/3 encoder states, TPDO4 analog inputs (MT 12-14)
    bool j1939 = false;             // the switch to J1939 (protocol_j1939) and back (PK1000 49)
    // After a node-id change: replies from the new id (PK1000 23), not the old one (PKP 13 h).
    bool replies_from_new_id = false;
    // Backlight PDO colour 00h: the default (2003h sub 4), PKP2600SI 15; not keep (PK1000 15, MT
    // 18).
    bool backlight_zero_is_default = false;
    // The strings the keypad reports (the virtual keypad sends them), at most six.
    std::array<keypad_string, 6> strings{};

    // Derived, for the PDO decoders (docs/models.md, "The model table").
    std::uint32_t not_keys = keys >= 32 ? 0u : ~((std::uint32_t{1} << keys) - 1);
    std::uint64_t led_bits = std::uint64_t{led_mask} |
                             (planes > 1 ? std::uint64_t{led_mask} << (stride % 64) : 0) |
                             (planes > 2 ? std::uint64_t{led_mask} << (2 * stride % 64) : 0);

    // Colour planes an LED object of 4 bytes (PKP 6001h/6002h) carries: those that fit 32 bits.
    [[nodiscard]] constexpr unsigned object_planes() const noexcept {
        const unsigned fit = 32u / stride;
        return fit < planes ? fit : planes;
    }
    // The string of object o the keypad reports; nullopt when it has none. (A copy, not a
    // pointer: a null test on the address of a member is not always a constant expression.)
    [[nodiscard]] constexpr std::optional<keypad_string> string_of(object o) const noexcept {
        for (const auto& s : strings)
            if (!s.bytes.empty() && s.id == o) return s;
        return std::nullopt;
    }
    // The model name it reports in 100Bh (PKP 6100h sub 2 too), up to its first NUL, where a
    // manual shows it; "" where none does.
    [[nodiscard]] constexpr std::string_view reported() const noexcept {
        const auto s = string_of(object::model_name);
        if (!s || s->section.starts_with("inferred")) return {};
        std::size_t n = 0;
        while (n < s->bytes.size() && s->bytes[n] != '\0') ++n;
        return {s->bytes.data(), n};
    }
};

namespace detail {
using namespace std::string_view_literals;  // "PK1000\0"sv keeps the NUL
using dict = dictionary;
// The strings the keypads of a family share, each once ("PKP n" the PKP-2200-2400-LI manual's
// section n, "PKP2600SI n" the PKP-2600-SI manual's, "MT n" the PKP-3500-MT manual's).
inline constexpr keypad_string blinkmarine_pk1000{object::device_name, "BlinkMarine"sv, 11, true,
                                                  "PK1000 32"};
inline constexpr keypad_string blinkmarine_pkp{object::device_name, "BlinkMarine"sv, 11, true,
                                               "PKP 19"};
inline constexpr keypad_string blinkmarine_si{object::device_name, "BlinkMarine"sv, 11, true,
                                              "PKP2600SI 30, MT 36"};
inline constexpr keypad_string pkp_hardware{object::hardware_version, "Rev 1.0\0D\0"sv, 10, true,
                                            "PKP 20 (E-CORE-5)"};
inline constexpr keypad_string pkp_software{object::software_version, "Rev 1.0\0R\0"sv, 10, true,
                                            "PKP 21 (E-CORE-5)"};
// 6 announced, 8 sent (E-CORE-4)
inline constexpr keypad_string pkp_serial{object::serial_number_string, "000000\0\0"sv, 6, true,
                                          "PKP 31 (E-CORE-4)"};
inline constexpr keypad_string si_hardware{object::hardware_version, "V_01"sv, 4, true,
                                           "inferred from PKP2600SI 31"};
inline constexpr keypad_string si_software{object::software_version, "V2.8"sv, 4, true,
                                           "inferred from PKP2600SI 32"};
inline constexpr keypad_string si_serial{object::serial_number_string, "FFFFFFFF"sv, 8, true,
                                         "PKP2600SI 46, MT 57; the others inferred"};
// The PKP-LI model strings: 7 announced and 8 sent (E-CORE-2); 40h, size not indicated, 08h in
// byte 4 (E-CORE-3).
constexpr keypad_string pkp_model_name(std::string_view bytes, std::string_view section) noexcept {
    return {object::model_name, bytes, 7, true, section};
}
constexpr keypad_string pkp_device_model(std::string_view bytes,
                                         std::string_view section) noexcept {
    return {object::device_model, bytes, 8, false, section};
}
constexpr keypad_string si_model_name(std::string_view bytes, std::string_view section) noexcept {
    return {object::model_name, bytes, 9, true, section};
}
}  // namespace detail

// Every keypad: X(name, designated initialisers of the rest of its row). Appending keeps the
// numbers of the models before it. The PKP-2200/2300/2400-SI's stride of 8, their backlight
// colour byte (a bench log of a PKP-2200-SI shows it, docs/si-family.md), their LED brightness
// PDO (controllers of the PKP-2400-SI send it; the 2600-SI, 3500-SI and 2500-SI have it), their
// 1-byte 2000h sub 01h besides the 2-byte one (dictionaries.hpp), what the SI sizes
// without a manual report, and the whole CANopen side of the PKP-1600-SI (whose only manual is
// its J1939 one: the SI family rule for six keys, as the PKP-2300-SI) are inferred
// (docs/si-family.md).
// clang-format off
#define POWERKEY_MODELS(X)                                                                         \
    X(pk1000, .manual = "PK1000", .dictionary = dict::pk1000,                                      \
      .keys = 10, .leds = 28, .planes = 2, .stride = 32, .led_mask = 0x0FFF'FFFF,                  \
      .brightness_pdo = true, .backlight_pdo = true, .backlight_colour = true, .j1939 = true,      \
      .replies_from_new_id = true,                                                                 \
      .strings = {blinkmarine_pk1000,                                                              \
                  {object::hardware_version, "V_03"sv, 4, true, "PK1000 33"},                      \
                  {object::software_version, "V2.8"sv, 4, true, "PK1000 34"},                      \
                  {object::model_name, "PK1000\0"sv, 7, true, "PK1000 35 (E-CORE-5)"},             \
                  {object::serial_number_string, "FFFFFFFF"sv, 8, true, "PK1000 48 (E-CORE-1)"}})  \
    X(pkp2200, .manual = "PKP-2200-LI", .dictionary = dict::pkp_li,                                \
      .keys = 4, .leds = 4, .planes = 3, .stride = 4, .led_mask = 0xF,                             \
      .strings = {blinkmarine_pkp, pkp_hardware, pkp_software,                                     \
                  pkp_model_name("PKU2200\0"sv, "inferred from PKP 22"),                           \
                  pkp_device_model("PKU2200\0"sv, "inferred from PKP 29"), pkp_serial})            \
    X(pkp2400, .manual = "PKP-2400-LI", .dictionary = dict::pkp_li,                                \
      .keys = 8, .leds = 8, .planes = 3, .stride = 8, .led_mask = 0xFF,                            \
      .strings = {blinkmarine_pkp, pkp_hardware, pkp_software,                                     \
                  pkp_model_name("PKU2400\0"sv, "PKP 22 (E-CORE-2)"),                              \
                  pkp_device_model("PKU2400\0"sv, "PKP 29 (E-CORE-3)"), pkp_serial})               \
    X(pkp2600, .manual = "PKP-2600", .dictionary = dict::pkp_li,                                   \
      .keys = 12, .leds = 12, .planes = 3, .stride = 12, .led_mask = 0xFFF,                        \
      .strings = {blinkmarine_pkp, pkp_hardware, pkp_software,                                     \
                  pkp_model_name("PKU2600\0"sv, "inferred from PKP 22"),                           \
                  pkp_device_model("PKU2600\0"sv, "inferred from PKP 29"), pkp_serial})            \
    X(pkp2600si, .manual = "PKP-2600-SI", .dictionary = dict::si_packed,                           \
      .keys = 12, .leds = 12, .planes = 3, .stride = 12, .led_mask = 0xFFF,                        \
      .brightness_pdo = true, .backlight_pdo = true, .backlight_colour = true, .j1939 = true,      \
      .replies_from_new_id = true, .backlight_zero_is_default = true,                              \
      .strings = {blinkmarine_si,                                                                  \
                  {object::hardware_version, "V_01"sv, 4, true, "PKP2600SI 31"},                   \
                  {object::software_version, "V2.8"sv, 4, true, "PKP2600SI 32"},                   \
                  si_model_name("PKP2600SI"sv, "PKP2600SI 33"), si_serial})                        \
    X(pkp3500mt, .manual = "PKP-3500-MT", .dictionary = dict::si_mt,                               \
      .keys = 15, .leds = 15, .planes = 3, .stride = 16, .led_mask = 0x7BFE,                       \
      .encoder_leds_pdo = true, .backlight_pdo = true, .backlight_colour = true,                   \
      .encoders = true, .j1939 = true, .replies_from_new_id = true,                                \
      .strings = {blinkmarine_si,                                                                  \
                  {object::hardware_version, "V_00"sv, 4, true, "MT 37"},                          \
                  {object::software_version, "1.00"sv, 4, true, "MT 38"},                          \
                  si_model_name("PKP3500MT"sv, "MT 39"), si_serial})                               \
    X(pkp3500si, .manual = "PKP-3500-SI", .dictionary = dict::si_per_colour,                       \
      .keys = 15, .leds = 15, .planes = 3, .stride = 16, .led_mask = 0x7FFF,                       \
      .brightness_pdo = true, .backlight_pdo = true, .j1939 = true, .replies_from_new_id = true,   \
      .strings = {blinkmarine_si, si_hardware, si_software,                                        \
                  si_model_name("PKP3500SI"sv, "docs/si-family.md"), si_serial})                   \
    X(pkp2500si, .manual = "PKP-2500-SI", .dictionary = dict::si_per_colour,                       \
      .keys = 10, .leds = 10, .planes = 3, .stride = 16, .led_mask = 0x3FF,                        \
      .brightness_pdo = true, .backlight_pdo = true, .j1939 = true, .replies_from_new_id = true,   \
      .strings = {blinkmarine_si, si_hardware, si_software,                                        \
                  si_model_name("PKP2500SI"sv, "inferred from the naming"), si_serial})            \
    X(pkp1500li, .manual = "PKP-1500-LI", .dictionary = dict::si_per_colour,                       \
      .keys = 5, .leds = 5, .planes = 3, .stride = 8, .led_mask = 0x1F,                            \
      .backlight_pdo = true, .j1939 = true, .replies_from_new_id = true,                           \
      .strings = {blinkmarine_si, si_hardware,                                                     \
                  {object::software_version, "2.10"sv, 4, true, "docs/si-family.md"},              \
                  si_model_name("PKP1500LI"sv, "docs/si-family.md"), si_serial})                   \
    X(pkp2200si, .manual = "PKP-2200-SI", .dictionary = dict::si_per_colour,                       \
      .keys = 4, .leds = 4, .planes = 3, .stride = 8, .led_mask = 0xF,                             \
      .brightness_pdo = true, .backlight_pdo = true, .backlight_colour = true, .j1939 = true,      \
      .replies_from_new_id = true,                                                                 \
      .strings = {blinkmarine_si, si_hardware, si_software,                                        \
                  si_model_name("PKP2200SI"sv, "inferred from the naming"), si_serial})            \
    X(pkp2300si, .manual = "PKP-2300-SI", .dictionary = dict::si_per_colour,                       \
      .keys = 6, .leds = 6, .planes = 3, .stride = 8, .led_mask = 0x3F,                            \
      .brightness_pdo = true, .backlight_pdo = true, .backlight_colour = true, .j1939 = true,      \
      .replies_from_new_id = true,                                                                 \
      .strings = {blinkmarine_si, si_hardware, si_software,                                        \
                  si_model_name("PKP2300SI"sv, "inferred from the naming"), si_serial})            \
    X(pkp2400si, .manual = "PKP-2400-SI", .dictionary = dict::si_per_colour,                       \
      .keys = 8, .leds = 8, .planes = 3, .stride = 8, .led_mask = 0xFF,                            \
      .brightness_pdo = true, .backlight_pdo = true, .backlight_colour = true, .j1939 = true,      \
      .replies_from_new_id = true,                                                                 \
      .strings = {blinkmarine_si, si_hardware, si_software,                                        \
                  si_model_name("PKP2400SI"sv, "inferred from the naming"), si_serial})            \
    X(pkp1600si, .manual = "PKP-1600-SI", .dictionary = dict::si_per_colour,                       \
      .keys = 6, .leds = 6, .planes = 3, .stride = 8, .led_mask = 0x3F,                            \
      .brightness_pdo = true, .backlight_pdo = true, .backlight_colour = true, .j1939 = true,      \
      .replies_from_new_id = true,                                                                 \
      .strings = {blinkmarine_si, si_hardware, si_software,                                        \
                  si_model_name("PKP1600SI"sv, "inferred from the naming"), si_serial})
// clang-format on

// A program may append keypads of its own, rows of the same form, by defining
// POWERKEY_EXTRA_MODELS(X) before it includes any powerkey header (in every translation unit
// alike: the tables are inline variables). tests/extra_model.cpp adds one this way.
#ifndef POWERKEY_EXTRA_MODELS
#define POWERKEY_EXTRA_MODELS(X)
#endif

enum class model : std::uint8_t {
#define POWERKEY_DETAIL_MODEL_ENUM(name, ...) name,
    POWERKEY_MODELS(POWERKEY_DETAIL_MODEL_ENUM) POWERKEY_EXTRA_MODELS(POWERKEY_DETAIL_MODEL_ENUM)
#undef POWERKEY_DETAIL_MODEL_ENUM
};

namespace detail {
#define POWERKEY_DETAIL_MODEL_ROW(M, ...) model_info{.id = model::M, .name = #M, __VA_ARGS__},
inline constexpr model_info model_table[] = {POWERKEY_MODELS(POWERKEY_DETAIL_MODEL_ROW)
                                                 POWERKEY_EXTRA_MODELS(POWERKEY_DETAIL_MODEL_ROW)};
#undef POWERKEY_DETAIL_MODEL_ROW
}  // namespace detail

inline constexpr std::size_t model_count = std::size(detail::model_table);

template <>
struct enum_names<model> {
    static constexpr auto entries = [] {
        std::array<enum_name_entry<model>, model_count> t{};
        for (std::size_t i = 0; i < t.size(); ++i)
            t[i] = {detail::model_table[i].id, detail::model_table[i].name};
        return t;
    }();
};

namespace detail {
// The LED-map rule's planes do not overlap (each fits its stride) and end within 64 bits: what
// the codec's LED PDO decoder (two shifts by the stride, a test against led_bits) relies on.
constexpr bool planes_apart() noexcept {
    for (const auto& keypad : model_table)
        if (keypad.planes < 1 || keypad.planes > 3 || keypad.stride == 0 ||
            (std::uint64_t{keypad.led_mask} >> keypad.stride) != 0 ||
            keypad.stride * keypad.planes > 64)
            return false;
    return true;
}
static_assert(planes_apart());
}  // namespace detail

// The row of a model; errc::value_out_of_range for a value outside the enum.
[[nodiscard]] constexpr result<model_info> info(model m) noexcept {
    const auto i = static_cast<std::size_t>(m);
    if (i >= model_count) return errc::value_out_of_range;
    return detail::model_table[i];
}

namespace detail {
// The row of a model the caller has checked is one (no copy).
constexpr const model_info& row_of(model m) noexcept {
    return model_table[static_cast<std::size_t>(m)];
}
constexpr bool is_model(model m) noexcept { return static_cast<std::size_t>(m) < model_count; }
// The row of a model; for a value that is not one, a row of zeros (no keys, no LEDs, no PDOs).
inline constexpr model_info no_model_row{};
constexpr const model_info& row_or_none(model m) noexcept {
    return is_model(m) ? row_of(m) : no_model_row;
}

// What the decoders need of a row, without the names and strings (docs/models.md, "The model
// table": a firmware that only decodes links these and not the model table).
struct model_layout {
    powerkey::model id;
    powerkey::dictionary dictionary;
    std::uint8_t keys, leds, planes, stride;
    bool brightness_pdo, encoder_leds_pdo, backlight_pdo, backlight_colour, encoders, j1939;
    std::uint32_t led_mask, not_keys;
    // The bits of a 4-byte LED-map object (PKP 6001h/6002h) that name no LED: all but those of
    // the planes object_planes() keeps (the complement, so that the test is one AND).
    std::uint32_t object_not_leds;
    std::uint64_t led_bits;
    [[nodiscard]] constexpr unsigned object_planes() const noexcept {
        const unsigned fit = 32u / stride;
        return fit < planes ? fit : planes;
    }
};
constexpr model_layout layout_of(const model_info& keypad) noexcept {
    return {keypad.id,
            keypad.dictionary,
            keypad.keys,
            keypad.leds,
            keypad.planes,
            keypad.stride,
            keypad.brightness_pdo,
            keypad.encoder_leds_pdo,
            keypad.backlight_pdo,
            keypad.backlight_colour,
            keypad.encoders,
            keypad.j1939,
            keypad.led_mask,
            keypad.not_keys,
            ~static_cast<std::uint32_t>(keypad.led_bits &
                                        low_bits(keypad.object_planes() * keypad.stride)),
            keypad.led_bits};
}
inline constexpr auto model_layouts = [] {
    std::array<model_layout, model_count> t{};
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = layout_of(model_table[i]);
    return t;
}();
constexpr const model_layout& layout(model m) noexcept {
    return model_layouts[static_cast<std::size_t>(m)];
}
// The row of a model known when the program is built, as a variable of its own: a program that
// names it links this row (its strings) and not the model table.
template <model M>
inline constexpr model_info model_row_v = row_of(M);

// The layout of a model; for a value that is not one, zeros (as row_or_none).
inline constexpr model_layout no_model_layout{};
constexpr const model_layout& layout_or_none(model m) noexcept {
    return is_model(m) ? layout(m) : no_model_layout;
}
}  // namespace detail

// A set of models, of any size the table has: the models a test row or a string applies to.
class model_set {
public:
    constexpr model_set() noexcept = default;
    constexpr model_set(std::initializer_list<model> models) noexcept {
        for (const model m : models) insert(m);
    }
    [[nodiscard]] static constexpr model_set all() noexcept {
        model_set s;
        for (std::size_t i = 0; i < model_count; ++i) s.insert(static_cast<model>(i));
        return s;
    }
    [[nodiscard]] constexpr bool contains(model m) const noexcept {
        const auto i = static_cast<std::size_t>(m);
        return i < model_count && ((words_[i / 64] >> (i % 64)) & 1u) != 0;
    }
    constexpr void insert(model m) noexcept {
        const auto i = static_cast<std::size_t>(m);
        if (i < model_count) words_[i / 64] |= std::uint64_t{1} << (i % 64);
    }
    [[nodiscard]] constexpr bool empty() const noexcept {
        for (const auto w : words_)
            if (w != 0) return false;
        return true;
    }
    friend constexpr model_set operator|(model_set a, const model_set& b) noexcept {
        for (std::size_t i = 0; i < a.words_.size(); ++i) a.words_[i] |= b.words_[i];
        return a;
    }
    friend constexpr model_set operator-(model_set a, const model_set& b) noexcept {
        for (std::size_t i = 0; i < a.words_.size(); ++i) a.words_[i] &= ~b.words_[i];
        return a;
    }
    friend constexpr bool operator==(const model_set&, const model_set&) noexcept = default;

private:
    std::array<std::uint64_t, (model_count + 63) / 64> words_{};
};

// --- the LED-map and key-map rule ---------------------------------------------------------------

// The first `planes` planes of l as the model's bit string. LEDs the model lacks are dropped:
// callers that must refuse them compare with unpack_leds (the codec does).
template <class Row>  // model_info, or the codec's detail::model_layout
[[nodiscard]] constexpr std::uint64_t pack_leds(const Row& keypad, const leds& l,
                                                unsigned planes) noexcept {
    // The planes written out rather than looped (the loop cost an LED encode 10 instructions).
    const std::uint64_t one = keypad.led_mask;
    std::uint64_t v = l.red.mask() & one;
    if (planes > 1) v |= (l.green.mask() & one) << (keypad.stride % 64);
    if (planes > 2) v |= (l.blue.mask() & one) << (2 * keypad.stride % 64);
    return v;
}

// The map in a bit string of the model; errc::reserved_not_zero for a set bit that names no LED.
// The planes written out rather than looped: this runs for every LED PDO (CHANGELOG.md).
template <class Row>
[[nodiscard]] constexpr result<leds> unpack_leds(const Row& keypad, std::uint64_t v,
                                                 unsigned planes) noexcept {
    const std::uint64_t one = keypad.led_mask;
    const unsigned s = keypad.stride;
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
template <class Row>
[[nodiscard]] constexpr result<key_set> unpack_keys(const Row& keypad, std::uint64_t v) noexcept {
    if ((v >> keypad.keys) != 0) return errc::reserved_not_zero;
    return key_set::from_mask(v);
}

// --- names ----------------------------------------------------------------------------------

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
    for (const auto& m : detail::model_table)
        if (detail::same_name(m.name, text)) return m.id;
    for (const auto& m : detail::model_table)
        if (detail::same_name(m.manual, text) ||
            (!m.reported().empty() && detail::same_name(m.reported(), text)))
            return m.id;
    return errc::value_out_of_range;
}

// The model a keypad's reported model string (100Bh, PKP 6100h sub 2) names, if a manual shows it.
[[nodiscard]] constexpr result<model> model_from_report(std::string_view reported) noexcept {
    for (const auto& m : detail::model_table)
        if (!m.reported().empty() && m.reported() == reported) return m.id;
    return errc::value_out_of_range;
}

}  // namespace powerkey

#endif  // POWERKEY_KEYPAD_MODELS_HPP
