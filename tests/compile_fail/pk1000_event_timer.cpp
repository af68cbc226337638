// A PK1000 event timer literal above FEFFh must not compile (manual section 46 b).
#include <powerkey/pk1000/objects.hpp>

constexpr powerkey::pk1000::event_timer_value ok{true, 0xFEFF};
#ifdef POWERKEY_COMPILE_FAIL
constexpr powerkey::pk1000::event_timer_value bad{true, 0xFF00};
#endif
int main() { return ok.period_ms.value() == 0xFEFF ? 0 : 1; }
