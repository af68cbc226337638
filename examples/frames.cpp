// Prints, in candump form, frames that the library built at compile time.
#include <powerkey/powerkey.hpp>

#include <cstdio>

namespace {
using namespace powerkey;
constexpr canopen::node_id keypad = canopen::default_node_id;

constexpr can::frame frames[] = {
    canopen::encode(canopen::nmt_message{canopen::nmt_command::start, keypad.value()}),
    canopen::encode(canopen::sync_message{}),
    canopen::encode(keypad, canopen::heartbeat_message{canopen::nmt_state::operational}),
    canopen::encode(keypad, canopen::sdo_upload_request{{0x1008, 0x00}}),
    canopen::encode(
        keypad, canopen::sdo_download_request{{0x1017, 0x00}, canopen::expedited_data::u16(500)}),
    j1939::encode(j1939::switch_to_canopen{}),
};
static_assert(frames[0] == can::candump("000#0115"));
static_assert(frames[5] == can::candump("18EF2100#041B8000FFFFFFFF"));
}  // namespace

int main() {
    for (const auto& f : frames) {
        const auto text = can::format_candump(f);
        std::printf("%.*s\n", static_cast<int>(text.view().size()), text.view().data());
    }
}
