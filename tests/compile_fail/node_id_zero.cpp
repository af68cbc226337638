// Node 0 means "all nodes" and exists only as an NMT target, never as a device's node id.
#include <powerkey/canopen/node_id.hpp>

constexpr powerkey::canopen::nmt_target all = 0;
#ifdef POWERKEY_COMPILE_FAIL
constexpr powerkey::canopen::node_id bad = 0;
#endif
int main() { return all.value(); }
