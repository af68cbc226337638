// The tool's log reader on python-can CSV: "timestamp," makes it CSV, the fuzzer writes the rest
// of the header (the column order) and the lines (base64 data). Properties: fuzz/log_reader.hpp.
#include "log_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return powerkey_fuzz::check_text("timestamp,", data, size);
}
