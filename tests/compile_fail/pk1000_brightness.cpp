// A PK1000 brightness literal above 3Fh must not compile (manual sections 14, 15, 19).
#include <powerkey/pk1000/pdo.hpp>

constexpr powerkey::pk1000::led_brightness ok{0x3F};
#ifdef POWERKEY_COMPILE_FAIL
constexpr powerkey::pk1000::led_brightness bad{0x40};
#endif
int main() { return ok.level.value() == 0x3F ? 0 : 1; }
