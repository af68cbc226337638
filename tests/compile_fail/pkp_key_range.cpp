// A PKP-2200 has keys 1..4: a constant LED-on frame lighting key 5 must not compile (encode
// refuses an LED the model lacks, and the value of a refused result is no constant).
#include <powerkey/keypad/codec.hpp>

using namespace powerkey;
constexpr canopen::node_id node = 0x15;

constexpr auto ok = encode(node, model::pkp2200, led_on{leds{}.set(4, colour::amber)}).value();
#ifdef POWERKEY_COMPILE_FAIL
constexpr auto bad = encode(node, model::pkp2200, led_on{leds{}.set(5, colour::amber)}).value();
#endif
int main() { return ok.size() == 8 ? 0 : 1; }
