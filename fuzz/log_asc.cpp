// The tool's log reader on Vector ASC text: a "date" line makes it ASC, the fuzzer writes the
// rest ("base hex/dec", data lines, CANFD lines, error frames, statistics). Properties:
// fuzz/log_reader.hpp.
#include "log_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return powerkey_fuzz::check_text("date Tue Nov 14 22:13:20 2023\n", data, size);
}
