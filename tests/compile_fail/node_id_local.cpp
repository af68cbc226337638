// A node id literal outside 1..127 must not compile in a function, constexpr or not.
#include <powerkey/canopen/node_id.hpp>

int main() {
    powerkey::canopen::node_id ok = 0x7F;
#ifdef POWERKEY_COMPILE_FAIL
    powerkey::canopen::node_id bad = 0x80;
    (void)bad;
#endif
    return ok.value() == 0x7F ? 0 : 1;
}
