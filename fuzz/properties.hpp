// The two properties the keypad codec must have, written once for every target that uses them:
//  - decode_fixed_point: a frame that decodes re-encodes to the same bytes and decodes again to
//    the same value; a refusal carries a listed errc; no data byte past the dlc is read.
//  - encode_accepted: a message built from arbitrary raw field values (fuzz.hpp: any enum value,
//    any object, any LED or key bits, any command) is either refused with a listed errc, or
//    encodes to a frame its decoder accepts and decodes back to the same message.
#ifndef POWERKEY_FUZZ_PROPERTIES_HPP
#define POWERKEY_FUZZ_PROPERTIES_HPP

#include "fuzz.hpp"

#include <variant>

namespace powerkey_fuzz {

inline result<can::frame> as_result(const can::frame& f) { return f; }
inline result<can::frame> as_result(const result<can::frame>& r) { return r; }

// decode: frame -> result<M>; encode: M -> frame or result<frame>. Returns whether f decoded.
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

// Message is a std::variant; input bytes pick the alternative and fill it with raw values.
// Returns whether the message encoded.
template <class Message, class Encode, class Decode>
bool encode_accepted(input& in, Encode encode, Decode decode) {
    Message m{};
    fill_any(in, m);
    const auto encoded = as_result(encode(m));
    if (!encoded) {
        POWERKEY_FUZZ_CHECK(is_listed(encoded.error()));
        return false;
    }
    aligned_frame held{*encoded};
    const poison_past_dlc guard(held.f);
    const auto decoded = decode(held.f);
    if (!decoded || !(*decoded == m)) {
        const std::string_view kind = kind_of(m);
        std::fprintf(stderr, "message %.*s: %s\n", static_cast<int>(kind.size()), kind.data(),
                     decoded ? "decodes to another value" : to_string(decoded.error()).data());
    }
    POWERKEY_FUZZ_CHECK_FRAME(decoded.has_value(), held.f);
    POWERKEY_FUZZ_CHECK_FRAME(decoded->index() == m.index(), held.f);
    POWERKEY_FUZZ_CHECK_FRAME(*decoded == m, held.f);
    return true;
}

}  // namespace powerkey_fuzz

#endif  // POWERKEY_FUZZ_PROPERTIES_HPP
