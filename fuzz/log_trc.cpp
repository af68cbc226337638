// The tool's log reader on PEAK TRC text: a ";" line makes it TRC, the fuzzer writes the rest
// (";$FILEVERSION=", ";$COLUMNS=", data lines of every version). Properties: fuzz/log_reader.hpp.
#include "log_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return powerkey_fuzz::check_text(";\n", data, size);
}
