// The J1939 encoder j1939::encode(model, message, keypad), which checks each message's own fields
// rather than reading its frame back, fed every kind of j1939::message with arbitrary raw field
// values (fuzz.hpp: any enum value, any key and LED bits, any command code and members, raw
// multiple-LED nibbles), for every model (and a value that is no model), with any keypad or
// narrowed to one. Property: the message is refused with a listed errc, or it encodes to a frame
// that decodes back to exactly the same message.
// g++ 12 reports the keypad_address optional below as maybe uninitialised once the J1939 codec is
// inlined into this function (a false positive: its value is read only when it holds one; which
// file it hits changes with what the headers inline).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "properties.hpp"

#include <powerkey/keypad/j1939_codec.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace powerkey;
    using namespace powerkey_fuzz;
    input in(data, size);
    const auto m = static_cast<model>(in.u8() % (j1939::model_row_count + 1));
    const bool narrowed = (in.u8() & 1) != 0;
    const j1939::keypad_address keypad =
        narrowed ? j1939::keypad_address{in.u8()} : j1939::keypad_address{};
    const bool encoded = encode_accepted<j1939::message>(
        in, [&](const j1939::message& msg) { return j1939::encode(m, msg, keypad); },
        [&](const can::frame& f) { return j1939::decode(f, m, keypad); });
    if (!j1939::row(m)) POWERKEY_FUZZ_CHECK(!encoded);
    return 0;
}
