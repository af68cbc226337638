// A PKP-2200 has keys 1..4: a typed LED map naming key 5 must not compile.
#include <powerkey/pkp/pdo.hpp>

using powerkey::pkp::colour;
using powerkey::pkp::model;

constexpr powerkey::pkp::led_map<model::pkp2200> ok{{4, colour::amber}};
#ifdef POWERKEY_COMPILE_FAIL
constexpr powerkey::pkp::led_map<model::pkp2200> bad{{5, colour::amber}};
#endif
int main() { return ok.colour_of(4) == colour::amber ? 0 : 1; }
