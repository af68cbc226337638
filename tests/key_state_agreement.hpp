// decode_key_state<M> (keypad/codec.hpp) against decode(frame, node, M): decode's key state when
// it reads one, decode's error for a frame with the key-state PDO's identifier (180h + node, 11
// bits), wrong_id for any other frame. Shared by tests/test_keypad_codec_typed.cpp (every manual
// row and refusal, every model) and the `decode` fuzz target (every input, its model).
#ifndef POWERKEY_TESTS_KEY_STATE_AGREEMENT_HPP
#define POWERKEY_TESTS_KEY_STATE_AGREEMENT_HPP

#include <powerkey/keypad/codec.hpp>

#include <cstddef>
#include <utility>
#include <variant>

namespace key_state_agreement {

using namespace powerkey;

template <model M>
constexpr bool agrees(const can::frame& f, canopen::node_id node, reading how) {
    const auto k = decode_key_state<M>(f, node, how);
    const auto d = decode(f, node, M, how);
    if (d && std::holds_alternative<key_state>(*d)) return k && *k == std::get<key_state>(*d);
    if (!f.is_extended() && f.raw_id() == 0x180u + node.value()) return !d && k == d.error();
    return k == errc::wrong_id;
}

// The same for a run-time model m (true for a value that is no model), both readings.
template <std::size_t... I>
constexpr bool agrees_for(model m, const can::frame& f, canopen::node_id node,
                          std::index_sequence<I...>) {
    bool ok = true;
    ((m == static_cast<model>(I)
          ? (void)(ok = agrees<static_cast<model>(I)>(f, node, reading::tolerant) &&
                        agrees<static_cast<model>(I)>(f, node, reading::strict))
          : (void)0),
     ...);
    return ok;
}
constexpr bool agrees(model m, const can::frame& f, canopen::node_id node) {
    return agrees_for(m, f, node, std::make_index_sequence<model_count>{});
}

}  // namespace key_state_agreement

#endif  // POWERKEY_TESTS_KEY_STATE_AGREEMENT_HPP
