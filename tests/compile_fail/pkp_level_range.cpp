// A brightness level is 00h..3Fh: the literal 40h in a command must not compile.
#include <powerkey/keypad/commands.hpp>

constexpr powerkey::command ok{.code = powerkey::command_code::set_led_brightness, .level = 0x3F};
#ifdef POWERKEY_COMPILE_FAIL
constexpr powerkey::command bad{.code = powerkey::command_code::set_led_brightness, .level = 0x40};
#endif
int main() { return ok.level.value() == 0x3F ? 0 : 1; }
