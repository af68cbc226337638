#include <powerkey/powerkey.hpp>

int main() {
    using namespace powerkey;
    constexpr auto start = canopen::encode(canopen::nmt_message{canopen::nmt_command::start, 0x15});
    static_assert(start == can::candump("000#0115"));
    return canopen::decode_nmt(start).has_value() ? 0 : 1;
}
