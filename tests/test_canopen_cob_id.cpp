// canopen/cob_id.hpp: the predefined connection set of CiA 301 as the keypads use it (PK1000 and
// PKP sections 4-10): the COB-ID of each function and node both ways, which frames concern a
// keypad, and the names of the functions.
#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/names.hpp>

#include "support.hpp"

#include <string_view>

namespace {
using namespace powerkey;
using namespace powerkey::canopen;

using namespace powerkey_tests;

constexpr node_id keypad = 0x15;

struct cob_row {
    std::string_view section;
    std::string_view frame;  // the COB-ID, as a frame without data
    cob_info info;
};
constexpr cob_row cob_rows[] = {
    {"NMT", "000#", {function::nmt, 0}},
    {"SYNC", "080#", {function::sync, 0}},
    {"key state", "195#", {function::tpdo1, 0x15}},
    {"LED on", "215#", {function::rpdo1, 0x15}},
    {"LED blink", "315#", {function::rpdo2, 0x15}},
    {"LED brightness", "415#", {function::rpdo3, 0x15}},
    {"backlight", "515#", {function::rpdo4, 0x15}},
    {"SDO reply", "595#", {function::sdo_tx, 0x15}},
    {"SDO request", "615#", {function::sdo_rx, 0x15}},
    {"heartbeat", "715#", {function::heartbeat, 0x15}},
    {"key state of node 1", "181#", {function::tpdo1, 1}},
    {"heartbeat of node 7Fh", "77F#", {function::heartbeat, 0x7F}},
    {"EMCY 080h + node: not used by the keypads", "095#", {function::other, 0}},
    {"TIME", "100#", {function::other, 0}},
    {"TPDO2 base, no node", "280#", {function::other, 0}},
    {"TPDO2..4: the PKP-3500-MT's encoders and inputs", "295#", {function::tpdo2, 0x15}},
    {"TPDO3", "395#", {function::tpdo3, 0x15}},
    {"TPDO4", "495#", {function::tpdo4, 0x15}},
    {"SDO reply of node 7Fh", "5FF#", {function::sdo_tx, 0x7F}},
    {"SDO request of node 7Fh", "67F#", {function::sdo_rx, 0x7F}},
    {"SDO request base, no node", "600#", {function::other, 0}},
    {"LSS: past 77Fh, the last heartbeat COB-ID", "7E5#", {function::other, 0}},
};
// Classified as the row says; the per-node functions give the identifier back, and the others
// (NMT, SYNC and any other identifier: CiA 301 7.3.5) have no per-node COB-ID: 000h.
constexpr bool classifies(const cob_row& r) {
    const auto f = frame_of(r.frame);
    if (classify(f) != r.info) return false;
    if (classify(f.std_id().value()) != r.info) return false;
    const bool per_node =
        r.info.fn != function::nmt && r.info.fn != function::sync && r.info.fn != function::other;
    return cob_id(r.info.fn, node_id::make(r.info.node).value_or(keypad)).value() ==
           (per_node ? f.raw_id() : 0x000);
}
static_assert(first_failing(cob_rows, classifies) == std::size(cob_rows));
// Every 29-bit identifier is J1939 (where the keypads' protocol switch lives), with no node and
// no per-node COB-ID.
constexpr bool j1939_has_no_node() {
    return classify(can::candump("18EF2100#041B8000FFFFFFFF")) == cob_info{function::j1939, 0} &&
           classify(can::candump("00000615#00")) == cob_info{function::j1939, 0} &&
           cob_id(function::j1939, keypad).value() == 0x000;
}
static_assert(j1939_has_no_node());

// Which frames concern a keypad: NMT, SYNC and J1939 every node, the per-node ids only their own.
struct concerns_row {
    std::string_view section;
    std::string_view frame;
    bool expected;
};
constexpr concerns_row concerns_rows[] = {
    {"NMT", "000#0115", true},
    {"SYNC", "080#", true},
    {"J1939", "18EF2100#041B8000FFFFFFFF", true},
    {"SDO request, this node", "615#4000100000000000", true},
    {"SDO request, node 16h", "616#4000100000000000", false},
    {"heartbeat, this node", "715#05", true},
    {"no predefined function", "7E5#00", false},
};
constexpr bool concerns_right(const concerns_row& r) {
    return concerns(classify(frame_of(r.frame)), keypad) == r.expected;
}
static_assert(first_failing(concerns_rows, concerns_right) == std::size(concerns_rows));

// The names the session and the tool print for the functions, in enum order.
constexpr name_row function_rows[] = {
    {"000h", 0, "nmt"},        {"080h", 1, "sync"},     {"180h", 2, "tpdo1"},
    {"280h", 3, "tpdo2"},      {"380h", 4, "tpdo3"},    {"480h", 5, "tpdo4"},
    {"200h", 6, "rpdo1"},      {"300h", 7, "rpdo2"},    {"400h", 8, "rpdo3"},
    {"500h", 9, "rpdo4"},      {"580h", 10, "sdo_tx"},  {"600h", 11, "sdo_rx"},
    {"700h", 12, "heartbeat"}, {"29-bit", 13, "j1939"}, {"any other", 14, "other"},
};
static_assert(name_table_is<function>(function_rows, 15));
}  // namespace

TEST_CASE("COB-IDs both ways") {
    check_rows(cob_rows, classifies);
    CHECK(j1939_has_no_node());
}

TEST_CASE("which frames concern a keypad") { check_rows(concerns_rows, concerns_right); }

TEST_CASE("the names of the functions") { CHECK(name_table_is<function>(function_rows, 15)); }
