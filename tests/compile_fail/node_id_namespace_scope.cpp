// A node id literal outside 1..127 must not compile at namespace scope either, constexpr or not
// (clang 14 took `node_id g = 0x80;` there as 128 before bounded.hpp's diagnose_if).
#include <powerkey/canopen/node_id.hpp>

powerkey::canopen::node_id ok = 0x7F;
#ifdef POWERKEY_COMPILE_FAIL
powerkey::canopen::node_id bad = 0x80;
#endif
int main() { return ok.value() == 0x7F ? 0 : 1; }
