// Footprint firmware (a): a PK1000 host that only reads key states and builds LED frames, the
// smallest useful program (issue 7: must fit in 1 KiB of flash with no .data and no .bss).
// Each pressed key lights its red LED; key 10 makes every lit LED blink.
// It uses the model table's bit-map rule (models.hpp: unpack_keys, pack_leds) and the COB-IDs
// directly, with the checks the codec makes on these two PDOs; the same program through the
// codec's decode/encode is firmware (a_codec).
// Each library call sits in its own function of namespace `calls`, so that scripts/footprint.sh
// can report the stack each one needs.
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/detail/bytes.hpp>
#include <powerkey/keypad/models.hpp>

#include "mailbox.hpp"

namespace co = powerkey::canopen;
namespace pc = powerkey::can;
namespace pk = powerkey;

namespace {
constexpr pk::model_info keypad = pk::info(pk::model::pk1000).value();
}  // namespace

namespace calls {
// The key-state PDO (PK1000 section 11): 180h + node, 5 bytes, bytes 2..3 zero, keys the model has.
[[gnu::noinline]] pk::result<pk::key_set> read_keys(const pc::frame& f, co::node_id n) {
    if (f.is_extended() || f.raw_id() != co::cob_id(co::function::tpdo1, n).value())
        return pk::errc::wrong_id;
    if (f.size() != 5) return pk::errc::wrong_length;
    if (f[2] != 0 || f[3] != 0) return pk::errc::reserved_not_zero;
    return pk::unpack_keys(keypad, pk::detail::load_le<2>(f.bytes(), 0));
}
[[gnu::noinline]] pc::frame build_leds(co::function fn, co::node_id n, const pk::leds& l) {
    pc::payload p{};
    pk::detail::store_le<8>(p, 0, pk::pack_leds(keypad, l, keypad.planes));
    return pc::frame(co::cob_id(fn, n), 8, p);
}
}  // namespace calls

[[noreturn]] void firmware_main() {
    constexpr co::node_id node = co::default_node_id;
    for (;;) {
        const auto f = firmware::receive();
        if (!f) continue;
        const auto keys = calls::read_keys(*f, node);
        if (!keys) continue;
        const auto lit = pk::led_set::from_mask(keys->mask());
        firmware::transmit(calls::build_leds(co::function::rpdo1, node, pk::leds{lit, {}, {}}));
        firmware::transmit(calls::build_leds(
            co::function::rpdo2, node, pk::leds{keys->contains(10) ? lit : pk::led_set{}, {}, {}}));
    }
}
