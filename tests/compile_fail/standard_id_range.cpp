// An 11-bit identifier literal above 7FFh must not compile.
#include <powerkey/can/frame.hpp>

constexpr powerkey::can::standard_id ok = 0x7FF;
#ifdef POWERKEY_COMPILE_FAIL
constexpr powerkey::can::standard_id bad = 0x800;
#endif
int main() { return ok.value() == 0x7FF ? 0 : 1; }
