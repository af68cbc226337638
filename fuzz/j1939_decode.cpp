// The J1939 decoder j1939::decode(frame, model, keypad) on arbitrary frames, for every model of
// the J1939 model table (and a value that is no model), with any keypad or narrowed to one.
// Properties: no crash, no read past the dlc, every refusal a listed errc, decode -> encode ->
// decode a fixed point (properties.hpp); what decodes carries the identifier's priority,
// destination and source; an 11-bit frame and a value outside the table are refused; narrowed,
// nothing decodes that is neither from nor to the keypad; the switch back agrees with
// decode_switch_to_canopen; decode_key_or_led agrees with decode; decode agrees with the checks
// alone (detail::decode_checked_only, without the in-place answers of the frequent frames).
// g++ 12 reports the keypad_address optional below as maybe uninitialised once the J1939 codec is
// inlined into this function (a false positive: its value is read only when it holds one; which
// file it hits changes with what the headers inline).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "properties.hpp"

#include <powerkey/keypad/j1939_codec.hpp>

#include <optional>
#include <type_traits>
#include <variant>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace powerkey;
    using namespace powerkey_fuzz;
    input in(data, size);
    // model_row_count + 1 choices: the last is a value outside the table (decode refuses it).
    const auto m = static_cast<model>(in.u8() % (j1939::model_row_count + 1));
    // Selector bit 0: narrowed to the keypad at the next byte.
    const bool narrowed = (in.u8() & 1) != 0;
    const j1939::keypad_address keypad =
        narrowed ? j1939::keypad_address{in.u8()} : j1939::keypad_address{};
    const can::frame f = take_frame(in);
    const bool decoded = decode_fixed_point(
        f, [&](const can::frame& x) { return j1939::decode(x, m, keypad); },
        [&](const j1939::message& msg) { return j1939::encode(m, msg, keypad); });
    // The frequent frames are answered in place: the same answer as the checks in order.
    POWERKEY_FUZZ_CHECK_FRAME(j1939::decode(f, m, keypad) ==
                                  j1939::detail::decode_checked_only<j1939::message>(f, m, keypad),
                              f);
    if (!j1939::row(m)) POWERKEY_FUZZ_CHECK_FRAME(!decoded, f);
    if (!f.is_extended()) POWERKEY_FUZZ_CHECK_FRAME(!decoded, f);
    // The reader of command 01h alone gives decode's answer for the three messages it reads,
    // and never a message decode does not give.
    const auto narrow = j1939::decode_key_or_led(f, m, keypad);
    if (narrow) {
        POWERKEY_FUZZ_CHECK_FRAME(decoded, f);
        const auto whole = *j1939::decode(f, m, keypad);
        POWERKEY_FUZZ_CHECK_FRAME(std::visit(
                                      [&whole](const auto& v) {
                                          using T = std::remove_cvref_t<decltype(v)>;
                                          const T* same = std::get_if<T>(&whole);
                                          return same != nullptr && *same == v;
                                      },
                                      *narrow),
                                  f);
    }
    if (!decoded) return 0;

    const auto msg = *j1939::decode(f, m, keypad);
    const auto id = j1939::parse_id(f);
    POWERKEY_FUZZ_CHECK_FRAME(id.has_value(), f);
    std::visit(
        [&](const auto& v) {
            POWERKEY_FUZZ_CHECK_FRAME(v.priority == id->priority, f);
            POWERKEY_FUZZ_CHECK_FRAME(v.destination == id->destination, f);
            POWERKEY_FUZZ_CHECK_FRAME(v.source == id->source, f);
            if (keypad)
                POWERKEY_FUZZ_CHECK_FRAME(v.source == *keypad || v.destination == *keypad, f);
        },
        msg);
    // The switch back decodes as the switch decoder of protocol_switch.hpp reads it.
    if (std::holds_alternative<j1939::switch_to_canopen>(msg)) {
        const auto s = j1939::decode_switch_to_canopen(f);
        POWERKEY_FUZZ_CHECK_FRAME(s.has_value() && *s == std::get<j1939::switch_to_canopen>(msg),
                                  f);
    }
    return 0;
}
