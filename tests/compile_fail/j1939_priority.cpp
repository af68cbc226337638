// A J1939 priority literal above 7 must not compile.
#include <powerkey/j1939/id.hpp>

constexpr powerkey::j1939::priority ok = 7;
#ifdef POWERKEY_COMPILE_FAIL
constexpr powerkey::j1939::priority bad = 8;
#endif
int main() { return ok.value() == 7 ? 0 : 1; }
