// powerkey tool: a DBC file for one keypad at one node id (`powerkey export dbc`, docs/dbc.md).
//
//   database describe(model, node)   the keypad's frames as messages and signals (data)
//   std::string text(const database&) the DBC file
//
// describe() reads the library and nothing else: which frames a model has comes from its row of
// the model table (models.hpp: brightness_pdo, backlight_colour, encoders, ...); every key and
// LED bit is found by encoding that one key or LED with the codec, so the bit layout is the
// model table's rule and is not written here again; the SDO objects are the rows of the model's
// dictionary (objects.hpp). Host-side: strings and vectors, nothing of include/'s freestanding
// promise.
#ifndef POWERKEY_TOOL_DBC_HPP
#define POWERKEY_TOOL_DBC_HPP

#include <powerkey/canopen/node_id.hpp>
#include <powerkey/j1939/protocol_switch.hpp>
#include <powerkey/keypad/models.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tool::dbc {

struct value_name {
    std::uint64_t value;
    std::string name;
};

// One signal, little endian (Intel) and unsigned: bits start .. start + size - 1 of the frame's
// data read as one little-endian number (bit i is bit i % 8 of byte i / 8).
struct signal {
    std::string name;
    unsigned start = 0;
    unsigned size = 1;
    std::uint32_t factor = 1;               // physical = raw x factor
    std::int64_t minimum = 0, maximum = 1;  // physical range, from the manuals
    std::string unit;
    std::string receiver;
    bool multiplexor = false;          // the message's multiplexor (M)
    std::optional<std::uint64_t> mux;  // present only when the multiplexor has this value
    std::string table;                 // the named value table `values` is, or ""
    std::vector<value_name> values;    // VAL_: names of raw values
    std::string comment;               // what it is, range, manual and section
};

struct message {
    std::uint32_t id = 0;
    bool extended = false;  // a 29-bit identifier (written with bit 31 set, as DBC does)
    std::string name;
    unsigned dlc = 8;
    std::string transmitter;
    std::string comment;
    std::vector<signal> signals;
};

struct database {
    std::string name;            // DBName, "pkp2400_15h"
    std::string keypad_comment;  // the keypad node's comment: model, node id, sources
    std::vector<message> messages;
    // The nodes' J1939 addresses (NmStationAddress), where the file has J1939 messages.
    std::uint8_t keypad_address = 0xFE, controller_address = 0xFE;
};

// The two nodes (BU_) of every file.
inline constexpr std::string_view keypad_node = "keypad";
inline constexpr std::string_view controller_node = "controller";

// Names longer than this are cut by some DBC tools (CANdb++ keeps 32 characters): describe()
// makes none.
inline constexpr std::size_t name_limit = 32;

// The DBC of a keypad of model m at node id `node`, and in J1939 at `j1939_address` (01h..FDh).
// m must be a model of the table.
database describe(powerkey::model m, powerkey::canopen::node_id node,
                  std::uint8_t j1939_address = powerkey::j1939::keypad_default_address);

// The database in the DBC format: deterministic (the same bytes for the same model and node).
std::string text(const database& db);

}  // namespace tool::dbc

#endif
