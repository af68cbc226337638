// An 11-bit and a 29-bit identifier are different types and do not compare.
#include <powerkey/can/frame.hpp>

constexpr powerkey::can::standard_id s = 0x615;
constexpr powerkey::can::extended_id e = 0x18EF2100;
#ifdef POWERKEY_COMPILE_FAIL
constexpr bool same = (s == e);
#endif
int main() { return s.value() == 0x615 && e.value() == 0x18EF2100 ? 0 : 1; }
