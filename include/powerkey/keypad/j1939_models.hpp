// powerkey: the keypads in J1939 as data. One row per model (keyed by powerkey::model) says how
// many keys its heartbeat carries, which LEDs its LED commands address, the layout of its
// single-LED command, and, for every J1939 frame, what the sources say of it on that model:
// documented (a manual of the model prints it), inferred (decoded and encoded with the layout of
// the two complete manuals), absent (its manual does not have it: errc::unknown_command) or
// unknown (no source shows it: errc::undocumented). docs/j1939.md gives each row's sources.
#ifndef POWERKEY_KEYPAD_J1939_MODELS_HPP
#define POWERKEY_KEYPAD_J1939_MODELS_HPP

#include <powerkey/enum_names.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>

namespace powerkey::j1939 {

// Every J1939 frame of the keypads, by the section of the PKP1600SI and PKP2600SI J1939 manuals.
// clang-format off
#define POWERKEY_J1939_FEATURE_LIST(X) \
    X(key_contact)  /* 01h, keypad to bus (6) */ \
    X(led_command)  /* 01h, bus to keypad (7a) */ \
    X(multiple_leds)  /* PGNs A700h and A600h (7b) */ \
    X(led_brightness)  /* 02h (8) */ \
    X(backlight_level)  /* 03h (9) */ \
    X(startup_keys)  /* 28h (10) */ \
    X(software_revision)  /* 2Ah, the request and the answer (11) */ \
    X(startup_show)  /* 34h (12) */ \
    X(led_management)  /* 37h (13) */ \
    X(destination_address)  /* 6Eh (14) */ \
    X(baud_rate)  /* 6Fh (15) */ \
    X(source_address)  /* 70h (16) */ \
    X(periodic_transmission)  /* 71h (17) */ \
    X(event_transmission)  /* 72h (18) */ \
    X(led_acknowledgement)  /* 73h (19) */ \
    X(led_ack)  /* the LED acknowledgement itself, byte 0 00h (19) */ \
    X(address_claim_at_boot)  /* 74h (20) */ \
    X(address_claim)  /* PGN EE00h, the NAME (20) */ \
    X(heartbeat_setting)  /* 75h (21) */ \
    X(heartbeat)  /* F9h (21) */ \
    X(key_period)  /* 77h (22) */ \
    X(demo_mode)  /* 7Ah (23) */ \
    X(default_backlight_level)  /* 7Bh (24) */ \
    X(default_led_brightness)  /* 7Ch (25) */ \
    X(default_backlight_colour)  /* 7Dh (26) */ \
    X(switch_to_canopen)  /* 80h (27) */
// clang-format on
enum class feature : std::uint8_t { POWERKEY_J1939_FEATURE_LIST(POWERKEY_DETAIL_ENUMERATOR) };
inline constexpr std::size_t feature_count = 26;
static_assert(static_cast<std::size_t>(feature::switch_to_canopen) + 1 == feature_count);

// What the sources say of one frame on one model, and so what the codec does with it.
// clang-format off
#define POWERKEY_J1939_COVERAGE_LIST(X) \
    X(absent)  /* the model's manual does not have it: refused with errc::unknown_command */ \
    X(unknown)  /* no source shows it on this model: refused with errc::undocumented */ \
    X(inferred)  /* not printed for this model: decoded and encoded with the complete manuals' layout */ \
    X(documented)  /* printed in a manual of this model */
// clang-format on
enum class coverage : std::uint8_t { POWERKEY_J1939_COVERAGE_LIST(POWERKEY_DETAIL_ENUMERATOR) };

// The coverage of every feature, two bits each.
class feature_set {
public:
    constexpr feature_set() noexcept = default;  // every frame absent
    constexpr explicit feature_set(coverage all) noexcept {
        for (std::size_t i = 0; i < feature_count; ++i) bits_ |= std::uint64_t{raw(all)} << (2 * i);
    }
    // This set with the features fs at c.
    template <class... F>
    [[nodiscard]] constexpr feature_set with(coverage c, F... fs) const noexcept {
        feature_set s = *this;
        ((s.bits_ =
              (s.bits_ & ~(std::uint64_t{3} << shift(fs))) | (std::uint64_t{raw(c)} << shift(fs))),
         ...);
        return s;
    }
    [[nodiscard]] constexpr coverage of(feature f) const noexcept {
        return static_cast<coverage>((bits_ >> shift(f)) & 3u);
    }
    // Decoded and encoded (documented or inferred).
    [[nodiscard]] constexpr bool has(feature f) const noexcept {
        return of(f) >= coverage::inferred;
    }
    friend constexpr bool operator==(const feature_set&, const feature_set&) noexcept = default;

private:
    static constexpr unsigned raw(coverage c) noexcept { return static_cast<unsigned>(c) & 3u; }
    static constexpr unsigned shift(feature f) noexcept { return 2u * static_cast<unsigned>(f); }
    std::uint64_t bits_ = 0;
};

// The layout of the single-LED command (01h to the keypad) and of its acknowledgement.
// clang-format off
#define POWERKEY_J1939_LED_FORM_LIST(X) \
    X(si)  /* colour, state, secondary colour (PKP1600SI, PKP2600SI J1939 manuals, 7a and 19) */ \
    X(code)  /* one LED code, its table unknown (the LI keypads: PKP-2400-LI J1939 manual page 11) */
// clang-format on
enum class led_form : std::uint8_t { POWERKEY_J1939_LED_FORM_LIST(POWERKEY_DETAIL_ENUMERATOR) };

struct model_row {
    powerkey::model id = powerkey::model::pk1000;
    std::uint8_t keys = 1;        // keys 1..keys: the heartbeat's key bits (F9h bytes 4, 5), <= 16
    std::uint16_t leds = 0;       // the LEDs 01h and its acknowledgement address: bit k-1 for LED k
    std::uint8_t plane_leds = 0;  // LEDs 1..plane_leds in each multiple-LED frame; 0: no such frame
    led_form form = led_form::si;  // the layout of 01h to the keypad and of the acknowledgement
    feature_set frames;            // what the sources say of each frame
};

namespace detail {
using cov = coverage;
using ft = feature;
// The two complete manuals (PKP1600SI_J1939_UM_rev1.0, PKP2600SI_J1939_UM_rev1.5).
inline constexpr feature_set complete_manual = feature_set(cov::documented);
// An SI keypad whose J1939 manual was not available: every frame the manuals share, in the
// complete manuals' layout; the frames added by later revisions (the multiple-LED command and
// 37h, PKP2600SI revisions 1.1 and 1.4; 6Eh, revision 1.5) unknown.
inline constexpr feature_set si_family =
    feature_set(cov::inferred)
        .with(cov::unknown, ft::multiple_leds, ft::led_management, ft::destination_address);
// An LI keypad: as the SI family, LED command and acknowledgement in the code form; their
// CANopen manual has no switch to J1939 and no J1939 page shows 80h.
inline constexpr feature_set li_family = si_family.with(cov::unknown, ft::switch_to_canopen);

inline constexpr model_row model_rows[] = {
    // PK1000 J1939 UM REV1.0 (page summaries): the key contact state; the switch back is the
    // CANopen manual's section 49. Its LED command and acknowledgement pages were not seen; the
    // multiple-LED command, 37h and 6Eh are not in its table of contents.
    {.id = model::pk1000,
     .keys = 10,
     .leds = 0,
     .plane_leds = 0,
     .form = led_form::si,
     .frames =
         si_family.with(cov::documented, ft::key_contact, ft::switch_to_canopen)
             .with(cov::unknown, ft::led_command, ft::led_ack)
             .with(cov::absent, ft::multiple_leds, ft::led_management, ft::destination_address)},
    // No J1939 manual of the PKP-2200-LI: the PKP-2400-LI's layout.
    {.id = model::pkp2200,
     .keys = 4,
     .leds = 0xF,
     .plane_leds = 0,
     .form = led_form::code,
     .frames = li_family},
    // PKP-2400-LI J1939 UM REV1.0, pages 8, 9, 11, 13.
    {.id = model::pkp2400,
     .keys = 8,
     .leds = 0xFF,
     .plane_leds = 0,
     .form = led_form::code,
     .frames =
         li_family
             .with(cov::documented, ft::led_ack, ft::startup_keys, ft::software_revision,
                   ft::startup_show, ft::baud_rate, ft::source_address, ft::led_acknowledgement,
                   ft::address_claim_at_boot, ft::heartbeat_setting, ft::heartbeat)
             .with(cov::absent, ft::multiple_leds, ft::led_management, ft::destination_address)},
    // No J1939 manual of the PKP-2600 (LI): the PKP-2400-LI's layout.
    {.id = model::pkp2600,
     .keys = 12,
     .leds = 0xFFF,
     .plane_leds = 0,
     .form = led_form::code,
     .frames = li_family},
    {.id = model::pkp2600si,
     .keys = 12,
     .leds = 0xFFF,
     .plane_leds = 12,
     .form = led_form::si,
     .frames = complete_manual},
    // No J1939 page; the switch back is its CANopen manual's section 58. Keys 1 and 11 (the
    // encoder pushes) have no LED; the encoders' J1939 frames are in no source.
    {.id = model::pkp3500mt,
     .keys = 15,
     .leds = 0x7BFE,
     .plane_leds = 0,
     .form = led_form::si,
     .frames = si_family.with(cov::documented, ft::switch_to_canopen)},
    // PKP3500SI J1939UM REV1.0: its table of contents lists the multiple-LED command.
    {.id = model::pkp3500si,
     .keys = 15,
     .leds = 0x7FFF,
     .plane_leds = 15,
     .form = led_form::si,
     .frames = si_family.with(cov::inferred, ft::multiple_leds, ft::led_management)},
    {.id = model::pkp2500si,
     .keys = 10,
     .leds = 0x3FF,
     .plane_leds = 0,
     .form = led_form::si,
     .frames = si_family},
    // The 5-key J1939 manual may be this keypad's (not confirmed): the SI layout.
    {.id = model::pkp1500li,
     .keys = 5,
     .leds = 0x1F,
     .plane_leds = 0,
     .form = led_form::si,
     .frames = si_family},
    // PKP-2200-SI J1939 UM REV1.0, pages 2-4, 6, 7, 9-11, 13.
    {.id = model::pkp2200si,
     .keys = 4,
     .leds = 0xF,
     .plane_leds = 0,
     .form = led_form::si,
     .frames =
         si_family
             .with(cov::documented, ft::led_command, ft::led_ack, ft::led_brightness,
                   ft::backlight_level, ft::startup_keys, ft::baud_rate, ft::source_address,
                   ft::periodic_transmission, ft::event_transmission, ft::led_acknowledgement,
                   ft::address_claim_at_boot, ft::address_claim, ft::key_period, ft::demo_mode,
                   ft::default_backlight_level, ft::default_led_brightness)
             .with(cov::absent, ft::multiple_leds, ft::led_management, ft::destination_address)},
    {.id = model::pkp2300si,
     .keys = 6,
     .leds = 0x3F,
     .plane_leds = 0,
     .form = led_form::si,
     .frames = si_family},
    {.id = model::pkp2400si,
     .keys = 8,
     .leds = 0xFF,
     .plane_leds = 0,
     .form = led_form::si,
     .frames = si_family},
    {.id = model::pkp1600si,
     .keys = 6,
     .leds = 0x3F,
     .plane_leds = 6,
     .form = led_form::si,
     .frames = complete_manual},
};

constexpr bool rows_in_enum_order() noexcept {
    for (std::size_t i = 0; i < std::size(model_rows); ++i)
        if (static_cast<std::size_t>(model_rows[i].id) != i) return false;
    return true;
}
static_assert(rows_in_enum_order());
static_assert(std::size(model_rows) == static_cast<std::size_t>(model::pkp1600si) + 1,
              "every model has a J1939 row");
// What the codec relies on: at most 16 keys and LEDs (one key_set, two bytes of heartbeat, 16
// nibbles of a multiple-LED frame); a multiple-LED frame only where its LEDs are given.
constexpr bool rows_consistent() noexcept {
    for (const auto& r : model_rows) {
        if (r.keys < 1 || r.keys > 16 || r.plane_leds > 16) return false;
        if (r.frames.has(feature::multiple_leds) != (r.plane_leds != 0)) return false;
        if (r.frames.has(feature::led_command) != (r.leds != 0)) return false;
    }
    return true;
}
static_assert(rows_consistent());
}  // namespace detail

inline constexpr std::size_t model_row_count = std::size(detail::model_rows);

// The J1939 row of a model; errc::value_out_of_range for a value outside the enum.
[[nodiscard]] constexpr result<model_row> row(model m) noexcept {
    const auto i = static_cast<std::size_t>(m);
    if (i >= model_row_count) return errc::value_out_of_range;
    return detail::model_rows[i];
}

namespace detail {
constexpr bool is_j1939_model(model m) noexcept {
    return static_cast<std::size_t>(m) < model_row_count;
}
constexpr const model_row& j1939_row_of(model m) noexcept {
    return model_rows[static_cast<std::size_t>(m)];
}
// The rows and after them one of no frames (keys 0, which no model has), the row of every value
// outside the enum: row_or_none finds a row without a branch, so that a loop over frames of one
// run-time model finds it once, and a frame passes none of the decoder's tests of the row.
inline constexpr auto rows_or_none = [] {
    std::array<model_row, model_row_count + 1> a{};
    for (std::size_t i = 0; i < model_row_count; ++i) a[i] = model_rows[i];
    a[model_row_count] = model_row{.id = model::pk1000, .keys = 0, .frames = feature_set{}};
    return a;
}();
constexpr const model_row& row_or_none(model m) noexcept {
    const auto i = static_cast<std::size_t>(m);
    return rows_or_none[i < model_row_count ? i : model_row_count];
}
constexpr bool is_row(const model_row& r) noexcept { return r.keys != 0; }
}  // namespace detail

}  // namespace powerkey::j1939

POWERKEY_DETAIL_ENUM_NAMES(powerkey::j1939::feature, POWERKEY_J1939_FEATURE_LIST);
POWERKEY_DETAIL_ENUM_NAMES(powerkey::j1939::coverage, POWERKEY_J1939_COVERAGE_LIST);
POWERKEY_DETAIL_ENUM_NAMES(powerkey::j1939::led_form, POWERKEY_J1939_LED_FORM_LIST);

#endif  // POWERKEY_KEYPAD_J1939_MODELS_HPP
