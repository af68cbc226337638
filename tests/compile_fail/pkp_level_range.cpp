// A brightness level is 00h..3Fh: the literal 40h must not compile.
#include <powerkey/pkp/command.hpp>

constexpr powerkey::pkp::set_led_brightness ok{0x3F};
#ifdef POWERKEY_COMPILE_FAIL
constexpr powerkey::pkp::set_led_brightness bad{0x40};
#endif
int main() { return ok.value.value() == 0x3F ? 0 : 1; }
