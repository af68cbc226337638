// A malformed candump literal must not compile.
#include <powerkey/can/candump.hpp>

constexpr auto ok = powerkey::can::candump("615#4000200100000000");
#ifdef POWERKEY_COMPILE_FAIL
constexpr auto bad = powerkey::can::candump("615#40002001000000000000");  // 10 bytes
#endif
int main() { return ok.size() == 8 ? 0 : 1; }
