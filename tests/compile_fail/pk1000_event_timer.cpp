// A PK1000 event timer above FEFFh (manual section 46 b) must not compile where it is a constant:
// encode refuses it (value_out_of_range), and the value of a refused result is no constant.
#include <powerkey/keypad/codec.hpp>

using namespace powerkey;
constexpr canopen::node_id node = 0x15;

constexpr auto ok =
    encode(node, model::pk1000, sdo_write{object::tpdo1_event_timer, number_value(0xFEFF)}).value();
#ifdef POWERKEY_COMPILE_FAIL
constexpr auto bad =
    encode(node, model::pk1000, sdo_write{object::tpdo1_event_timer, number_value(0xFF00)}).value();
#endif
int main() { return ok.size() == 8 ? 0 : 1; }
