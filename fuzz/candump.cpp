// The candump text parser on arbitrary text. Properties: no crash; an error is one of the three
// the parser documents; text that parses formats back to itself in upper case, and that text
// parses to the same frame.
#include "fuzz.hpp"

#include <cctype>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace powerkey;
    const std::string text(reinterpret_cast<const char*>(data), size);
    const auto parsed = can::parse_candump(text);
    if (!parsed) {
        const errc e = parsed.error();
        POWERKEY_FUZZ_CHECK(e == errc::syntax_error || e == errc::value_out_of_range ||
                            e == errc::wrong_length);
        return 0;
    }
    const can::frame f = *parsed;
    POWERKEY_FUZZ_CHECK(f.size() <= 8);
    for (std::size_t i = f.size(); i < 8; ++i) POWERKEY_FUZZ_CHECK_FRAME(f.bytes()[i] == 0, f);
    std::string upper = text;
    for (auto& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const auto formatted = can::format_candump(f);
    POWERKEY_FUZZ_CHECK_FRAME(formatted.view() == upper, f);
    const auto again = can::parse_candump(formatted.view());
    POWERKEY_FUZZ_CHECK_FRAME(again.has_value() && *again == f, f);
    return 0;
}
