// A node id literal outside 1..127 must not compile braced, as an aggregate element or an array
// element at namespace scope.
#include <powerkey/canopen/node_id.hpp>

struct pair {
    powerkey::canopen::node_id a, b;
};
pair ok{1, 0x7F};
#ifdef POWERKEY_COMPILE_FAIL
pair bad{1, 0x80};
#endif
int main() { return ok.b.value() == 0x7F ? 0 : 1; }
