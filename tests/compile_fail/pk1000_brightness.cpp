// An LED brightness literal above 3Fh must not compile (PK1000 sections 14, 15, 19; PKP 13 b, 30).
#include <powerkey/keypad/messages.hpp>

constexpr powerkey::led_brightness ok{0x3F};
#ifdef POWERKEY_COMPILE_FAIL
constexpr powerkey::led_brightness bad{0x40};
#endif
int main() { return ok.level.value() == 0x3F ? 0 : 1; }
