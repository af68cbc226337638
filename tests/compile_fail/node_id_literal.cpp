// A node id literal outside 1..127 must not compile.
#include <powerkey/canopen/node_id.hpp>

constexpr powerkey::canopen::node_id ok = 0x7F;
#ifdef POWERKEY_COMPILE_FAIL
constexpr powerkey::canopen::node_id bad = 0x80;
#endif
int main() { return ok.value() == 0x7F ? 0 : 1; }
