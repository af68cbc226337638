// powerkey: CANopen node ids (CiA 301 7.2.1). A device's node id is 1..127; the NMT command
// alone may address node 0, meaning every node, so it takes an nmt_target instead.
#ifndef POWERKEY_CANOPEN_NODE_ID_HPP
#define POWERKEY_CANOPEN_NODE_ID_HPP

#include <powerkey/bounded.hpp>

#include <cstdint>

namespace powerkey::canopen {

struct node_id_tag;
struct nmt_target_tag;

// Node id of one device: 01h..7Fh. Every keypad ships with 15h (both manuals, section 3).
using node_id = bounded<node_id_tag, std::uint8_t, 1, 127>;
// Addressee of an NMT command: 00h = all nodes, else one node id.
using nmt_target = bounded<nmt_target_tag, std::uint8_t, 0, 127>;

inline constexpr node_id default_node_id = 0x15;
inline constexpr nmt_target all_nodes = 0;

}  // namespace powerkey::canopen

#endif  // POWERKEY_CANOPEN_NODE_ID_HPP
