// The two properties every message codec must have, written once for all of them:
//  - decode_fixed_point: a frame that decodes re-encodes to the same bytes and decodes again to
//    the same value; a refusal carries a listed errc; no data byte past the dlc is read.
//  - encode_accepted: a message built from arbitrary in-range field values either encodes to a
//    frame its decoder accepts and decodes back to the same message, or is refused with a listed
//    errc (a value the model does not have, e.g. key 13 on a 12-key keypad).
#ifndef POWERKEY_FUZZ_PROFILE_HPP
#define POWERKEY_FUZZ_PROFILE_HPP

#include "fuzz.hpp"

#include <variant>

namespace powerkey_fuzz {

inline result<can::frame> as_result(const can::frame& f) { return f; }
inline result<can::frame> as_result(const result<can::frame>& r) { return r; }

// decode: frame -> result<M>; encode: M -> frame or result<frame>.
template <class Decode, class Encode>
bool decode_fixed_point(const can::frame& f, Decode decode, Encode encode) {
    aligned_frame held{f};
    auto decoded = [&] {
        const poison_past_dlc guard(held.f);
#ifdef POWERKEY_FUZZ_ASAN
        POWERKEY_FUZZ_CHECK_FRAME(guard.effective(), f);
#endif
        return decode(held.f);
    }();
    if (!decoded) {
        POWERKEY_FUZZ_CHECK_FRAME(is_listed(decoded.error()), f);
        return false;
    }
    const auto encoded = as_result(encode(*decoded));
    POWERKEY_FUZZ_CHECK_FRAME(encoded.has_value(), f);
    POWERKEY_FUZZ_CHECK_FRAME(*encoded == f, f);
    const auto again = decode(*encoded);
    POWERKEY_FUZZ_CHECK_FRAME(again.has_value() && *again == *decoded, f);
    return true;
}

// The kind of the message a (possibly nested) variant holds.
template <class M>
std::string_view message_kind(const M& m) {
    if constexpr (is_variant<M>::value)
        return std::visit([](const auto& alt) { return message_kind(alt); }, m);
    else
        return M::kind;
}

// Message is a std::variant (maybe of variants); input bytes pick the alternative and fill it.
template <class Message, class Encode, class Decode>
void encode_accepted(input& in, Encode encode, Decode decode) {
    Message m{};
    if (!fill_any(in, m)) return;
    const auto encoded = as_result(encode(m));
    if (!encoded) {
        POWERKEY_FUZZ_CHECK(is_listed(encoded.error()));
        return;
    }
    aligned_frame held{*encoded};
    const poison_past_dlc guard(held.f);
    const auto decoded = decode(held.f);
    if (!decoded || !(*decoded == m)) {
        const std::string_view kind = message_kind(m);
        std::fprintf(stderr, "message %.*s: %s\n", static_cast<int>(kind.size()), kind.data(),
                     decoded ? "decodes to another value" : to_string(decoded.error()).data());
    }
    POWERKEY_FUZZ_CHECK_FRAME(decoded.has_value(), held.f);
    POWERKEY_FUZZ_CHECK_FRAME(decoded->index() == m.index(), held.f);
    POWERKEY_FUZZ_CHECK_FRAME(*decoded == m, held.f);
}

}  // namespace powerkey_fuzz

#endif  // POWERKEY_FUZZ_PROFILE_HPP
