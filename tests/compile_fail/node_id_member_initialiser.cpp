// A node id literal outside 1..127 must not compile as a default member initialiser.
#include <powerkey/canopen/node_id.hpp>

struct keypad_config {
    powerkey::canopen::node_id node = 0x7F;
#ifdef POWERKEY_COMPILE_FAIL
    powerkey::canopen::node_id other = 0x80;
#endif
};
int main() { return keypad_config{}.node.value() == 0x7F ? 0 : 1; }
