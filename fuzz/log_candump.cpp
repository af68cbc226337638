// The tool's log reader on arbitrary text: candump -l and -L lines, cansend's ID#DATA, candump's
// screen form, comments, remote and CAN FD frames (fuzz/log_reader.hpp has the properties). The
// bytes are given as they are: the reader tells the form by content, so that the fuzzer also
// reaches the binary forms' detection and the other text forms.
#include "log_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return powerkey_fuzz::check_text("", data, size);
}
