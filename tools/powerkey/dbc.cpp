// powerkey tool: the DBC of a keypad (dbc.hpp; docs/dbc.md says what is in it and why).
#include "dbc.hpp"

#include "text.hpp"

#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/commands.hpp>
#include <powerkey/keypad/j1939_codec.hpp>
#include <powerkey/keypad/j1939_models.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/keypad/values.hpp>
#include <powerkey/names.hpp>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <span>
#include <type_traits>
#include <utility>

namespace tool::dbc {

namespace {

using namespace powerkey;
using canopen::function;
using canopen::node_id;
using keypad_message = powerkey::message;  // what the codec encodes (dbc::message is a DBC's)

// --- where each keypad's frames are described ----------------------------------------------------
// The manual of each model and the place of each frame in it, as docs/pk1000.md, docs/pkp.md and
// docs/si-family.md give them: "section n" (the manual's own numbering) or a note that names the
// docs page; "" where the manual has no such section (the comment then cites CiA 301 alone).
struct sources {
    model id;
    std::string_view manual;
    std::string_view nmt = {}, heartbeat = {}, sync = {};
    std::string_view key_state = {}, led_on = {}, led_blink = {}, rpdo3 = {}, backlight = {};
    std::string_view encoder1 = {}, encoder2 = {}, analog = {};
};

constexpr std::string_view other_sizes = "docs/si-family.md, The other sizes";

// One row per model. A model without one (a new row of the model table) still gets its file:
// its comments then name its manual without sections (context_of).
constexpr sources source_table[] = {
    {.id = model::pk1000,
     .manual = "PK1000 manual",
     .nmt = "sections 4 to 7",
     .heartbeat = "sections 8, 9, 29",
     .sync = "section 10",
     .key_state = "section 11",
     .led_on = "section 12",
     .led_blink = "section 13",
     .rpdo3 = "section 14",
     .backlight = "section 15"},
    {.id = model::pkp2200,
     .manual = "PKP manual",
     .nmt = "sections 4 to 7",
     .heartbeat = "sections 8, 9, 17",
     .key_state = "section 10",
     .led_on = "section 11",
     .led_blink = "section 12"},
    {.id = model::pkp2400,
     .manual = "PKP manual",
     .nmt = "sections 4 to 7",
     .heartbeat = "sections 8, 9, 17",
     .key_state = "section 10",
     .led_on = "section 11",
     .led_blink = "section 12"},
    {.id = model::pkp2600,
     .manual = "PKP manual",
     .nmt = "sections 4 to 7",
     .heartbeat = "sections 8, 9, 17",
     .key_state = "section 10; the 12-key layout: docs/pkp.md, The PKP-2600",
     .led_on = "section 11; the 12-key layout: docs/pkp.md, The PKP-2600",
     .led_blink = "section 12; the 12-key layout: docs/pkp.md, The PKP-2600"},
    {.id = model::pkp2600si,
     .manual = "PKP2600SI manual",
     .nmt = "sections 4 to 7",
     .heartbeat = "sections 8, 9, 27",
     .sync = "section 10",
     .key_state = "section 11",
     .led_on = "section 12",
     .led_blink = "section 13",
     .rpdo3 = "section 14",
     .backlight = "section 15"},
    {.id = model::pkp3500mt,
     .manual = "PKP3500-MT manual",
     .nmt = "sections 4 to 7",
     .heartbeat = "sections 8, 9, 33",
     .sync = "section 10",
     .key_state = "section 11",
     .led_on = "section 15",
     .led_blink = "section 16",
     .rpdo3 = "section 17",
     .backlight = "section 18",
     .encoder1 = "section 12",
     .encoder2 = "section 13",
     .analog = "section 14"},
    {.id = model::pkp3500si,
     .manual = "PKP3500SI manual",
     .key_state = other_sizes,
     .led_on = "section 12",
     .led_blink = "section 13",
     .rpdo3 = other_sizes,
     .backlight = "level only (docs/si-family.md, The other sizes)"},
    {.id = model::pkp2500si,
     .manual = "PKP2500SI manual",
     .key_state = "inferred: its key-state page was not available (docs/si-family.md)",
     .led_on = "inferred from section 13, the blink page (docs/si-family.md)",
     .led_blink = "section 13",
     .rpdo3 = "object 1402h (docs/si-family.md, The other sizes)",
     .backlight = "level only, object 1403h (docs/si-family.md, The other sizes)"},
    {.id = model::pkp1500li,
     .manual = "PKP-1500-LI manual",
     .key_state = other_sizes,
     .led_on = "section 12",
     .led_blink = "section 13",
     .backlight = "inferred: level only (docs/si-family.md, The other sizes)"},
    {.id = model::pkp2200si,
     .manual = "SI generic pages",
     .key_state = other_sizes,
     .led_on = "inferred: plane stride 8 (docs/si-family.md)",
     .led_blink = "inferred: plane stride 8 (docs/si-family.md)",
     .backlight = "inferred: level only (docs/si-family.md, The other sizes)"},
    {.id = model::pkp2300si,
     .manual = "SI generic pages",
     .key_state = other_sizes,
     .led_on = "inferred: plane stride 8 (docs/si-family.md)",
     .led_blink = "inferred: plane stride 8 (docs/si-family.md)",
     .backlight = "inferred: level only (docs/si-family.md, The other sizes)"},
    {.id = model::pkp2400si,
     .manual = "SI generic pages",
     .key_state = other_sizes,
     .led_on = "inferred: plane stride 8 (docs/si-family.md)",
     .led_blink = "inferred: plane stride 8 (docs/si-family.md)",
     .backlight = "inferred: level only (docs/si-family.md, The other sizes)"},
    // Only a J1939 manual exists: its CANopen side is the PKP-2300-SI's, inferred.
    {.id = model::pkp1600si,
     .manual = "SI generic pages",
     .key_state = "inferred: as the PKP-2300-SI (docs/si-family.md)",
     .led_on = "inferred: plane stride 8 (docs/si-family.md)",
     .led_blink = "inferred: plane stride 8 (docs/si-family.md)",
     .backlight = "inferred: level only (docs/si-family.md)"},
};

constexpr bool sources_once() {
    for (std::size_t i = 0; i < std::size(source_table); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (source_table[i].id == source_table[j].id) return false;
    return true;
}
static_assert(sources_once(), "at most one row of source_table per model");

// --- building ------------------------------------------------------------------------------------

// Everything the writer takes from the model table (keypad/models.hpp) is read here, in
// context_of; the rest of the file reads the context.
struct context {
    model id;
    node_id node;
    std::uint8_t j1939_address;  // the keypad's J1939 address
    model_info info;             // the row: names, dictionary, stride, which PDOs
    std::string name;            // "pkp2400"
    std::string manual_name;     // "PKP-2400-LI"
    std::string manual;          // the document: "PKP manual"
    sources src;
};

context context_of(model m, node_id node, std::uint8_t j1939_address) {
    const model_info row = *info(m);
    context c{m,
              node,
              j1939_address,
              row,
              std::string(row.name),
              std::string(row.manual),
              "",
              {.id = m, .manual = {}}};
    for (const auto& s : source_table)
        if (s.id == m) c.src = s;
    c.manual =
        c.src.manual.empty() ? "the " + c.manual_name + " manual" : std::string(c.src.manual);
    return c;
}

// "PK1000 manual section 11", "PKP2500SI manual, inferred ...", "" for no place.
std::string cite(const context& c, std::string_view where) {
    if (where.empty()) return "";
    std::string s = c.manual;
    s.append(where.starts_with("section") ? " " : ", ").append(where);
    return s;
}

// A comment: the text, then where it comes from.
std::string with_source(std::string text, const std::string& source) {
    if (!source.empty()) text.append(" (").append(source).append(")");
    return text;
}

std::string hex_h(std::uint64_t v, int digits) {
    std::string s;
    append_hex_h(s, v, digits);
    return s;
}

std::uint32_t cob(function f, node_id node) { return canopen::cob_id(f, node).value(); }

// A message's name in the file: its kind, the name decode --json gives it.
template <class T>
std::string name_of() {
    return std::string(T::kind);
}

// The bits the frame of `with` has that the frame of `without` lacks: the codec's place for one
// key, LED or ring LED. 0 when the model refuses either message (a key or LED it lacks).
std::uint64_t bits_added(const context& c, const keypad_message& with,
                         const keypad_message& without) {
    const auto a = encode(c.node, c.id, with);
    const auto b = encode(c.node, c.id, without);
    if (!a || !b) return 0;
    return a->data_le() & ~b->data_le();
}

// The one bit of `bits`, or nullopt for none or several.
std::optional<unsigned> one_bit(std::uint64_t bits) {
    if (std::popcount(bits) != 1) return std::nullopt;
    return static_cast<unsigned>(std::countr_zero(bits));
}

unsigned dlc_of(const context& c, const keypad_message& m) {
    const auto f = encode(c.node, c.id, m);
    return f ? f->size() : 8u;
}

signal flag(std::string name, unsigned at, std::string_view receiver, std::string comment) {
    signal s;
    s.name = std::move(name);
    s.start = at;
    s.size = 1;
    s.receiver = receiver;
    s.comment = std::move(comment);
    return s;
}

signal number(std::string name, unsigned at, unsigned size, std::int64_t lo, std::int64_t hi,
              std::string_view receiver, std::string comment) {
    signal s;
    s.name = std::move(name);
    s.start = at;
    s.size = size;
    s.minimum = lo;
    s.maximum = hi;
    s.receiver = receiver;
    s.comment = std::move(comment);
    return s;
}

// A named value table from a library enum: every named value, named as the library names it.
template <named_enum E>
void use_table(signal& s, std::string table) {
    s.table = std::move(table);
    for (const auto e : enum_values<E>())
        s.values.push_back({static_cast<std::uint64_t>(e), std::string(to_string(e))});
}

// The range of a signal whose values are all named: the lowest and highest name (an NMT command,
// a command byte), so that the range says no more than the table.
void range_of_table(signal& s) {
    const auto [lo, hi] = std::minmax_element(
        s.values.begin(), s.values.end(),
        [](const value_name& a, const value_name& b) { return a.value < b.value; });
    s.minimum = static_cast<std::int64_t>(lo->value);
    s.maximum = static_cast<std::int64_t>(hi->value);
}

// The encoders' direction bit (PKP3500-MT manual sections 12, 13, 19 b: 0 clockwise).
void use_direction_table(signal& s) {
    s.table = "encoder_direction";
    s.values = {{0, "clockwise"}, {1, "counterclockwise"}};
}

message new_message(std::uint32_t id, std::string name, unsigned dlc, std::string_view from,
                    std::string comment) {
    message m;
    m.id = id;
    m.name = std::move(name);
    m.dlc = dlc;
    m.transmitter = from;
    m.comment = std::move(comment);
    return m;
}

// --- NMT, SYNC, heartbeat (CiA 301) --------------------------------------------------------------

void add_nmt(const context& c, database& db) {
    auto m = new_message(
        canopen::nmt_cob_id.value(), name_of<canopen::nmt_message>(), 2, controller_node,
        with_source("NMT node control, 000h, controller to every node: a command and its target "
                    "node (00h: every node); CiA 301 7.2.8.3.1",
                    cite(c, c.src.nmt)));
    auto command =
        number("command", 0, 8, 0, 255, keypad_node, "NMT command specifier (value table)");
    use_table<canopen::nmt_command>(command, "nmt_command");
    range_of_table(command);
    m.signals.push_back(std::move(command));
    auto target = number("target", 8, 8, 0, 127, keypad_node,
                         "The node addressed: 01h..7Fh, or 00h for every node; this keypad is " +
                             hex_h(c.node.value(), 2));
    target.values = {{0, "all_nodes"}};
    m.signals.push_back(std::move(target));
    db.messages.push_back(std::move(m));
}

void add_sync(const context& c, database& db) {
    db.messages.push_back(new_message(
        canopen::sync_cob_id.value(), name_of<canopen::sync_message>(), 0, controller_node,
        with_source("SYNC, 080h, no data: the keypad latches the PDOs whose transmission type is "
                    "synchronous (objects 1400h, 1401h, 1800h); CiA 301 7.2.5",
                    cite(c, c.src.sync))));
}

void add_heartbeat(const context& c, database& db) {
    auto m = new_message(
        cob(function::heartbeat, c.node), name_of<canopen::heartbeat_message>(), 1, keypad_node,
        with_source("Boot-up and heartbeat, 700h + node: the keypad's NMT state, every producer "
                    "heartbeat time (object 1017h); the boot-up is state 00h; CiA 301 7.2.8.3.2",
                    cite(c, c.src.heartbeat)));
    auto state = number("state", 0, 8, 0, 127, controller_node,
                        "NMT state: 00h boot-up, 04h stopped, 05h operational, 7Fh "
                        "pre-operational; any other value is refused by the library");
    use_table<canopen::nmt_state>(state, "nmt_state");
    m.signals.push_back(std::move(state));
    db.messages.push_back(std::move(m));
}

// --- PDOs ----------------------------------------------------------------------------------------

void add_key_state(const context& c, database& db) {
    const keypad_message none{key_state{}};
    const auto source = cite(c, c.src.key_state);
    auto m = new_message(cob(function::tpdo1, c.node), name_of<key_state>(), dlc_of(c, none),
                         keypad_node,
                         with_source("TPDO1, 180h + node, keypad to controller: the pressed keys "
                                     "and the tick timer, sent on a change or as object 1800h "
                                     "sets",
                                     source));
    for (unsigned k = 1; k <= 16; ++k) {
        const auto bit = one_bit(bits_added(c, keypad_message{key_state{key_set{k}, 0}}, none));
        if (!bit) continue;  // no key k on this model
        m.signals.push_back(flag("key" + std::to_string(k), *bit, controller_node,
                                 with_source("Key " + std::to_string(k) + ": 1 pressed", source)));
    }
    m.signals.push_back(number("tick", 32, 8, 0, 255, controller_node,
                               with_source("Tick timer: +1 every 100 ms whether or not a key "
                                           "changed, wraps after FFh",
                                           source)));
    db.messages.push_back(std::move(m));
}

// LED on (RPDO1) or LED blink (RPDO2): one signal per LED and colour plane the model has, at the
// bit the codec puts it (the model's stride and LED mask).
void add_led_map(const context& c, database& db, bool blink) {
    const auto source = cite(c, blink ? c.src.led_blink : c.src.led_on);
    const auto make = [blink](const leds& l) {
        return blink ? keypad_message{led_blink{l}} : keypad_message{led_on{l}};
    };
    const keypad_message none = make(leds{});
    auto m = new_message(
        cob(blink ? function::rpdo2 : function::rpdo1, c.node),
        blink ? name_of<led_blink>() : name_of<led_on>(), dlc_of(c, none), controller_node,
        with_source(blink ? "RPDO2, 300h + node, controller to keypad: which LEDs blink; an LED "
                            "both on (RPDO1) and blinking blinks in alternate mode"
                          : "RPDO1, 200h + node, controller to keypad: which LEDs are on",
                    source + (source.empty() ? "" : "; ") + "plane stride " +
                        std::to_string(c.info.stride) + " bits"));
    for (const auto p : enum_values<plane>()) {
        const std::string colour(to_string(p));
        for (unsigned k = 1; k <= 32; ++k) {
            leds l;
            l.of(p).insert(k);
            const auto bit = one_bit(bits_added(c, make(l), none));
            if (!bit) continue;  // no such LED on this model
            std::string what = colour;
            what[0] = static_cast<char>(what[0] - 'a' + 'A');
            what += " LED " + std::to_string(k) + (blink ? ": 1 blinking" : ": 1 on");
            m.signals.push_back(
                flag(colour + std::to_string(k), *bit, keypad_node, with_source(what, source)));
        }
    }
    db.messages.push_back(std::move(m));
}

constexpr std::int64_t level_max = level::max;

void add_brightness(const context& c, database& db) {
    const auto source = cite(c, c.src.rpdo3);
    auto m = new_message(cob(function::rpdo3, c.node), name_of<led_brightness>(),
                         dlc_of(c, keypad_message{led_brightness{}}), controller_node,
                         with_source("RPDO3, 400h + node, controller to keypad: the LED "
                                     "brightness until the next start-up",
                                     source));
    m.signals.push_back(number("level", 0, 8, 0, level_max, keypad_node,
                               with_source("LED brightness 00h (minimum) .. 3Fh (100 %); above "
                                           "3Fh the keypad ignores the frame",
                                           source)));
    db.messages.push_back(std::move(m));
}

void add_encoder_leds(const context& c, database& db) {
    const auto source = cite(c, c.src.rpdo3);
    const keypad_message none{encoder_leds{}};
    auto m = new_message(cob(function::rpdo3, c.node), name_of<encoder_leds>(), dlc_of(c, none),
                         controller_node,
                         with_source("RPDO3, 400h + node, controller to keypad: the LEDs of the "
                                     "encoder rings that are on, 1..16 encoder 1, 17..32 encoder 2",
                                     source));
    for (unsigned k = 1; k <= 32; ++k) {
        const auto bit = one_bit(bits_added(c, keypad_message{encoder_leds{led_set{k}}}, none));
        if (!bit) continue;
        m.signals.push_back(
            flag("led" + std::to_string(k), *bit, keypad_node,
                 with_source("Encoder " + std::to_string((k - 1) / 16 + 1) + " ring LED " +
                                 std::to_string((k - 1) % 16 + 1) + ": 1 on",
                             source)));
    }
    db.messages.push_back(std::move(m));
}

void add_backlight(const context& c, database& db) {
    const auto source = cite(c, c.src.backlight);
    auto m = new_message(
        cob(function::rpdo4, c.node), name_of<backlight>(), dlc_of(c, keypad_message{backlight{}}),
        controller_node,
        with_source(c.info.backlight_colour ? "RPDO4, 500h + node, controller to keypad: backlight "
                                              "level and colour until the next start-up"
                                            : "RPDO4, 500h + node, controller to keypad: backlight "
                                              "level until the next start-up (byte 1 must be 00h)",
                    source));
    m.signals.push_back(number("level", 0, 8, 0, level_max, keypad_node,
                               with_source("Backlight level 00h (off) .. 3Fh (100 %)", source)));
    if (c.info.backlight_colour) {
        auto colour = number("colour", 8, 8, 0, 9, keypad_node,
                             with_source(c.info.backlight_zero_is_default
                                             ? "Backlight colour 01h..09h; 00h (keep) switches "
                                               "to the default colour, object 2003h sub 04h"
                                             : "Backlight colour 01h..09h; 00h (keep) keeps the "
                                               "colour stored",
                                         source));
        use_table<backlight_colour>(colour, "backlight_colour");
        m.signals.push_back(std::move(colour));
    }
    db.messages.push_back(std::move(m));
}

void add_encoder_state(const context& c, database& db, unsigned encoder) {
    const auto source = cite(c, encoder == 1 ? c.src.encoder1 : c.src.encoder2);
    const auto n = std::to_string(encoder);
    auto m = new_message(
        cob(encoder == 1 ? function::tpdo2 : function::tpdo3, c.node), "encoder" + n + "_state",
        dlc_of(c,
               keypad_message{encoder_state{static_cast<std::uint8_t>(encoder), false, 0, 0, 0}}),
        keypad_node,
        with_source(std::string(encoder == 1 ? "TPDO2, 280h" : "TPDO3, 380h") +
                        " + node, keypad to controller: encoder " + n +
                        " turned (16 ticks per turn)",
                    source));
    m.signals.push_back(
        number("ticks", 0, 7, 0, 127, controller_node,
               with_source("Ticks since the last message of this encoder", source)));
    auto direction =
        flag("counterclockwise", 7, controller_node,
             with_source("Direction of those ticks: 0 clockwise, 1 counterclockwise", source));
    use_direction_table(direction);
    m.signals.push_back(std::move(direction));
    m.signals.push_back(number("counter", 8, 16, 0, 65535, controller_node,
                               with_source("Tick counter: +1 clockwise, -1 counterclockwise, "
                                           "0..65535 wrapping, or 0..TOP",
                                           source)));
    auto top = number("top", 24, 8, 0, 16, controller_node,
                      with_source("TOP position 02h..10h, 00h none (object 2000h sub " +
                                      std::string(encoder == 1 ? "06h" : "07h") +
                                      "); 01h and above 10h are refused",
                                  source));
    top.values = {{0, "none"}};
    m.signals.push_back(std::move(top));
    db.messages.push_back(std::move(m));
}

void add_analog_inputs(const context& c, database& db) {
    const auto source = cite(c, c.src.analog);
    auto m = new_message(cob(function::tpdo4, c.node), name_of<analog_inputs>(),
                         dlc_of(c, keypad_message{analog_inputs{}}), keypad_node,
                         with_source("TPDO4, 480h + node, keypad to controller: the four 0..5 V "
                                     "inputs, every object 2006h x 10 ms (80 ms by default)",
                                     source));
    for (unsigned i = 0; i < 4; ++i) {
        auto s = number("in" + std::to_string(i) + "_mv", 16 * i, 16, 0, 5000, controller_node,
                        with_source("Input IN" + std::to_string(i) +
                                        ": 0000h..01F4h in units of 10 mV (0..5 V); above 01F4h "
                                        "is refused",
                                    source));
        s.factor = 10;
        s.unit = "mV";
        m.signals.push_back(std::move(s));
    }
    db.messages.push_back(std::move(m));
}

// --- SDO -----------------------------------------------------------------------------------------
// One message per direction, multiplexed on bytes 0..3 (the command specifier, the index and the
// sub-index) read as one 32-bit number: each value names one request or reply of one object, and
// the signals of that value are the object's value in bytes 4..7.

std::uint64_t header_of(const can::frame& f) { return f.data_le() & 0xFFFF'FFFFu; }

// The name of a signal of object `o` (at most name_limit characters).
std::string object_signal(std::string_view o, std::string_view field) {
    std::string s(o);
    if (field.empty()) return s;
    s.append("_").append(field);
    if (s.size() > name_limit && field == "counterclockwise") return std::string(o) + "_ccw";
    return s;
}

struct sdo_target {
    message& m;
    std::uint64_t mux;
    std::string_view receiver;
};

void add_value_signal(sdo_target& t, signal s) {
    s.mux = t.mux;
    s.receiver = t.receiver;
    t.m.signals.push_back(std::move(s));
}

// "2003h sub 01h; PK1000 manual, section Object 2003h": the manuals title each object's section
// so.
std::string object_place(const context& c, const object_row& r) {
    return hex_h(r.address.index, 4) + " sub " + hex_h(r.address.subindex, 2) + "; " + c.manual +
           ", section Object " + hex_h(r.address.index, 4);
}

// The expedited bytes of a row's value (objects.hpp, object_row::size: 0 for a per-colour LED
// plane, which has the model's stride / 8, and for the keys of the SI sizes without a manual,
// described in the SI manuals' 2 bytes: their 1-byte reply is not described).
unsigned value_bytes(const context& c, const object_row& r) {
    if (r.size != 0) return r.size;
    return info(r.id).kind == value_kind::keys ? 2u : c.info.stride / 8u;
}

// The value signals of row r: one per field of its value kind (messages.hpp, value_fields), one
// per key or LED for the set kinds (their bits found by encoding the object's value with one key
// or LED).
void add_value(const context& c, sdo_target& t, const object_row& r) {
    const auto kind = info(r.id).kind;
    const std::string o(to_string(r.id));
    const auto place = object_place(c, r);
    const unsigned bits = 8 * value_bytes(c, r);
    const std::int64_t size_max = bits >= 32 ? 0xFFFF'FFFFll : (std::int64_t{1} << bits) - 1;
    const auto numeric = [&](std::string what) {
        std::int64_t lo = r.min, hi = std::min<std::int64_t>(r.max, size_max);
        if (r.also != 0xFFFF'FFFFu) {
            lo = std::min<std::int64_t>(lo, r.also);
            hi = std::max<std::int64_t>(hi, r.also);
        }
        return number(o, 32, bits, lo, hi, t.receiver, with_source(std::move(what), place));
    };
    switch (kind) {
        case value_kind::number: {
            const int digits = static_cast<int>(bits / 4);
            std::string range =
                hex_h(r.min, digits) + ".." +
                hex_h(std::min<std::uint64_t>(r.max, std::uint64_t(size_max)), digits);
            if (r.also != 0xFFFF'FFFFu) range += " or " + hex_h(r.also, 2);
            auto s = numeric(o + ": " + range);
            if (r.also != 0xFFFF'FFFFu) {
                if (o.ends_with("_transmission_type")) s.values = {{r.also, "event_driven"}};
                if (o.ends_with("_top_position")) s.values = {{r.also, "none"}};
            }
            add_value_signal(t, std::move(s));
            return;
        }
        case value_kind::restore: {
            auto s = numeric(
                "Restore: a write carries the text load (6C6F6164h), a read the restore "
                "flags");
            if (t.receiver == keypad_node) s.minimum = s.maximum = load_signature;  // a write
            s.values = {{load_signature, "load"}};
            add_value_signal(t, std::move(s));
            return;
        }
        case value_kind::flag: {
            auto s = numeric(o + ": 00h off, 01h on");
            s.values = {{0, "off"}, {1, "on"}};
            add_value_signal(t, std::move(s));
            return;
        }
        case value_kind::brightness:
            add_value_signal(t, numeric(o + ": 00h (minimum or off) .. 3Fh (100 %)"));
            return;
        case value_kind::colour: {
            auto s = numeric(o + ": backlight colour 01h..09h");
            use_table<backlight_colour>(s, "backlight_colour");
            add_value_signal(t, std::move(s));
            return;
        }
        case value_kind::baud: {
            auto s = numeric(o + ": CAN bit rate code (01h and 05h reserved: 125 kbit/s)");
            use_table<baud_rate>(s, "baud_rate");
            add_value_signal(t, std::move(s));
            return;
        }
        case value_kind::show: {
            auto s = numeric(o + ": LED show at power-up");
            use_table<startup_show>(s, "startup_show");
            add_value_signal(t, std::move(s));
            return;
        }
        case value_kind::node: add_value_signal(t, numeric(o + ": node id 01h..7Fh")); return;
        case value_kind::period: {
            auto s = numeric(o + ": period in ms, 0 off, else " + hex_h(r.min, 4) + ".." +
                             hex_h(std::min<std::uint64_t>(r.max, 0xFFFF), 4));
            s.minimum = 0;
            s.unit = "ms";
            s.values = {{0, "off"}};
            add_value_signal(t, std::move(s));
            return;
        }
        case value_kind::consumer_heartbeat: {
            auto period = number(object_signal(o, "period_ms"), 32, 16, 0, 65535, t.receiver,
                                 with_source("Expected heartbeat period in ms, 0 off, else " +
                                                 hex_h(r.min, 4) + ".." + hex_h(r.max, 4),
                                             place));
            period.unit = "ms";
            period.values = {{0, "off"}};
            add_value_signal(t, std::move(period));
            add_value_signal(t, number(object_signal(o, "producer"), 48, 8, 1, 127, t.receiver,
                                       with_source("Node id of the heartbeat producer", place)));
            return;
        }
        case value_kind::cob_id:
            add_value_signal(t, number(object_signal(o, "can_id"), 32, 11, 0, 2047, t.receiver,
                                       with_source("The PDO's CAN identifier", place)));
            add_value_signal(t, flag(object_signal(o, "no_rtr"), 62, t.receiver,
                                     with_source("1: no remote frames (CiA 301 bit 30)", place)));
            add_value_signal(t, flag(object_signal(o, "invalid"), 63, t.receiver,
                                     with_source("1: the PDO is off (CiA 301 bit 31)", place)));
            return;
        case value_kind::pdo_mapping:
            add_value_signal(t, number(object_signal(o, "bits"), 32, 8, 0, 255, t.receiver,
                                       with_source("Length of the mapped object in bits", place)));
            add_value_signal(t, number(object_signal(o, "subindex"), 40, 8, 0, 255, t.receiver,
                                       with_source("Sub-index of the mapped object", place)));
            add_value_signal(t, number(object_signal(o, "index"), 48, 16, 0, 65535, t.receiver,
                                       with_source("Index of the mapped object", place)));
            return;
        case value_kind::device_type: {
            add_value_signal(t,
                             number(object_signal(o, "profile"), 32, 16, 0, 65535, t.receiver,
                                    with_source("Device profile number (0191h: CiA 401)", place)));
            constexpr std::string_view io[] = {"digital_input", "digital_output", "analogue_input",
                                               "analogue_output"};
            for (unsigned i = 0; i < 4; ++i)
                add_value_signal(
                    t, flag(object_signal(o, io[i]), 48 + i, t.receiver,
                            with_source("1: the device has " + std::string(io[i]) + "s (CiA 401)",
                                        place)));
            return;
        }
        case value_kind::direction_counter: {
            add_value_signal(t,
                             number(object_signal(o, "ticks"), 32, 7, 0, 127, t.receiver,
                                    with_source("Ticks since the encoder's last message", place)));
            auto d = flag(object_signal(o, "counterclockwise"), 39, t.receiver,
                          with_source("Direction: 0 clockwise, 1 counterclockwise", place));
            use_direction_table(d);
            add_value_signal(t, std::move(d));
            return;
        }
        case value_kind::keys:
        case value_kind::led_plane:
        case value_kind::led_map:
        case value_kind::led_part:
        case value_kind::ring: break;
        case value_kind::string:
        case value_kind::none:
        case value_kind::commands: return;  // no value signals (add_sdo says why)
    }
    // The set kinds: the value with one key or LED, encoded as a read reply (or a write, for an
    // object that cannot be read), against the empty value.
    const auto probe = [&r](const object_value& v) -> keypad_message {
        if (r.readable()) return sdo_read_reply{r.id, v};
        return sdo_write{r.id, v};
    };
    const keypad_message none = probe(object_value{});
    const auto add_bit = [&](std::string member, const object_value& v, std::string what) {
        const auto bit = one_bit(bits_added(c, probe(v), none));
        if (!bit || *bit < 32) return;
        add_value_signal(t, flag(object_signal(o, member), *bit, t.receiver,
                                 with_source(std::move(what), place)));
    };
    if (kind == value_kind::keys || kind == value_kind::ring) {
        const bool keys = kind == value_kind::keys;
        for (unsigned k = 1; k <= (keys ? 16u : 32u); ++k)
            add_bit((keys ? "key" : "led") + std::to_string(k), object_value{1u << (k - 1), {}, 0},
                    o + (keys ? ": key " : ": ring LED ") + std::to_string(k) +
                        (keys ? ", 1 pressed" : ", 1 set"));
        return;
    }
    for (const auto p : enum_values<plane>()) {
        const std::string colour(to_string(p));
        for (unsigned k = 1; k <= 32; ++k) {
            leds l;
            l.of(p).insert(k);
            add_bit(colour + std::to_string(k), leds_value(l),
                    o + ": " + colour + " LED " + std::to_string(k) + ", 1 set");
        }
    }
}

void add_command(const context& c, sdo_target& t, const object_row& r) {
    const std::string o(to_string(r.id));
    const auto place = object_place(c, r);
    auto code = number(object_signal(o, "command"), 32, 8, 0, 255, t.receiver,
                       with_source("Command byte (value table); its parameters follow", place));
    use_table<command_code>(code, "command_code");
    range_of_table(code);
    add_value_signal(t, std::move(code));
    for (unsigned i = 1; i <= 2; ++i)
        add_value_signal(
            t, number(object_signal(o, "parameter" + std::to_string(i)), 32 + 8 * i, 8, 0, 255,
                      t.receiver,
                      with_source("Parameter " + std::to_string(i) +
                                      " of the command: key, LED state, level, colour, flag, "
                                      "bit rate, period, node id or show, as the command says",
                                  place)));
}

void add_sdo(const context& c, database& db) {
    const auto sections = c.manual + ", the sections on each object";
    auto request = new_message(
        cob(function::sdo_rx, c.node), "sdo_request", 8, controller_node,
        with_source("SDO requests, 600h + node, controller to keypad: reads (40h) and expedited "
                    "writes of the objects of the keypad's dictionary; the multiplexor names each",
                    sections));
    auto response = new_message(
        cob(function::sdo_tx, c.node), "sdo_response", 8, keypad_node,
        with_source("SDO replies, 580h + node, keypad to controller: read replies and write "
                    "acknowledgements; segments and aborts are not described",
                    sections));
    auto mux = [](std::string name, std::string_view receiver, std::string comment) {
        auto s = number(std::move(name), 0, 32, 0, 0xFFFF'FFFFll, receiver, std::move(comment));
        s.multiplexor = true;
        return s;
    };
    request.signals.push_back(
        mux("request", keypad_node,
            "Bytes 0..3 as one number: command specifier | index << 8 | sub-index << 24 (value "
            "table: the request and the object)"));
    response.signals.push_back(
        mux("response", controller_node,
            "Bytes 0..3 as one number: command specifier | index << 8 | sub-index << 24 (value "
            "table: the reply and the object)"));
    std::vector<object_row> rows;
    for (const auto& r : rows_of(c.info.dictionary)) rows.push_back(r);
    std::sort(rows.begin(), rows.end(), [](const object_row& a, const object_row& b) {
        return std::pair(a.address.index, a.address.subindex) <
               std::pair(b.address.index, b.address.subindex);
    });
    auto name = [](message& m, std::uint64_t value, std::string text) {
        m.signals.front().values.push_back({value, std::move(text)});
    };
    for (const auto& r : rows) {
        const auto kind = info(r.id).kind;
        const std::string o(to_string(r.id));
        if (r.readable()) {
            name(request,
                 header_of(canopen::encode(c.node, canopen::sdo_upload_request{r.address})),
                 name_of<sdo_read>() + " " + o);
            if (kind == value_kind::string) {
                // A string comes back in segments (or expedited, 1..4 bytes): only the segmented
                // reply's size is described.
                const auto h = header_of(canopen::encode(
                    c.node, canopen::sdo_upload_initiate_response{r.address, true, 0}));
                name(response, h, name_of<canopen::sdo_upload_initiate_response>() + " " + o);
                sdo_target t{response, h, controller_node};
                auto size =
                    number(object_signal(o, "size"), 32, 32, 0, 0xFFFF'FFFFll, controller_node,
                           with_source("Length of the string in bytes; the segments "
                                       "that follow are not described",
                                       object_place(c, r)));
                size.unit = "bytes";
                add_value_signal(t, std::move(size));
            } else if (kind != value_kind::none) {
                const canopen::expedited_data d{
                    canopen::expedited_size::make(value_bytes(c, r)).value(), {}};
                const auto h =
                    header_of(canopen::encode(c.node, canopen::sdo_upload_response{r.address, d}));
                name(response, h, name_of<sdo_read_reply>() + " " + o);
                sdo_target t{response, h, controller_node};
                add_value(c, t, r);
            }
        }
        if (r.writable()) {
            const canopen::expedited_data d{
                canopen::expedited_size::make(value_bytes(c, r)).value(), {}};
            const auto h =
                header_of(canopen::encode(c.node, canopen::sdo_download_request{r.address, d}));
            sdo_target t{request, h, keypad_node};
            if (kind == value_kind::commands) {
                name(request, h, name_of<command>());
                add_command(c, t, r);
            } else {
                name(request, h, name_of<sdo_write>() + " " + o);
                add_value(c, t, r);
            }
            name(response,
                 header_of(canopen::encode(c.node, canopen::sdo_download_response{r.address})),
                 name_of<sdo_write_reply>() + " " + o);
        }
    }
    db.messages.push_back(std::move(request));
    db.messages.push_back(std::move(response));
}

// --- J1939 (docs/j1939.md) ----------------------------------------------------------------------
// Two messages on PGN EF00h (proprietary A), one per direction, each multiplexed on the command
// byte: what the keypad sends (the key contact state 01h, the heartbeat F9h) and what it is sent
// (the LED command 01h, the configuration commands, the switch to CANopen 80h). Which command a
// model has is its J1939 row's word (keypad/j1939_models.hpp: documented or inferred); where each
// field sits, its range and its value names are found by asking the library's J1939 codec: each
// data byte is set to every value in turn, decoded, and the field that changed is the signal.

// 04h 1Bh | command | data: the header and the command byte of every proprietary-A keypad frame
// (docs/j1939.md, The data); byte 3 on is each command's data.
constexpr unsigned j1939_command_byte = 2;
constexpr unsigned j1939_first_data_byte = 3;

// The section of the PKP1600SI and PKP2600SI J1939 manuals of each j1939::feature, in its order.
constexpr std::string_view j1939_sections[] = {"6",  "7a", "7b", "8",  "9",  "10", "11", "12", "13",
                                               "14", "15", "16", "17", "18", "19", "19", "20", "20",
                                               "21", "21", "22", "23", "24", "25", "26", "27"};
static_assert(std::size(j1939_sections) == j1939::feature_count);

// "J1939 manuals section 6 (PKP1600SI, PKP2600SI); inferred for the pkp2400 (docs/j1939.md)".
std::string j1939_cite(const context& c, const j1939::model_row& row, j1939::feature f) {
    std::string s = "PKP1600SI and PKP2600SI J1939 manuals section ";
    s.append(j1939_sections[static_cast<std::size_t>(f)]);
    s.append("; ").append(to_string(row.frames.of(f))).append(" for the ").append(c.manual_name);
    return s + " (docs/j1939.md)";
}

// One field of a decoded J1939 message: its name, its value as describe() prints it, and the
// value's name when the field is a named enum.
struct field_text {
    std::string name, text, value_name;
};

std::vector<field_text> fields_of(const j1939::message& m) {
    std::vector<field_text> out;
    for_each_field(m, [&out](std::string_view name, const auto& v) {
        std::array<char, description_capacity> buf{};
        text_writer w(buf);
        describe_value(w, name, v);
        field_text f{std::string(name), std::string(w.view()), {}};
        if constexpr (named_enum<std::decay_t<decltype(v)>>) f.value_name = to_string(v);
        out.push_back(std::move(f));
    });
    return out;
}

std::optional<j1939::message> j1939_decode(const context& c, const can::frame& f) {
    const auto r = j1939::decode(f, c.id);
    if (!r) return std::nullopt;
    return *r;
}

can::frame with_byte(const can::frame& f, unsigned i, std::uint8_t v) {
    auto bytes = f.bytes();
    bytes[i] = v;
    return can::frame::make(*f.ext_id(), std::span(bytes.data(), f.size())).value();
}

// The signals of the message that `base` decodes to, under multiplexor value `mux`: each data
// byte whose values change one field of the decoded message (the same kind) is that field's
// signal, named prefix + field, its range the values the codec takes, its value names the enum's.
// A field spread over several bytes (a key set) is left to the caller: `skip` names it.
void add_j1939_fields(const context& c, message& m, const can::frame& base, std::uint64_t mux,
                      const std::string& prefix, std::string_view receiver,
                      const std::string& source, std::string_view skip = {}) {
    const auto decoded = j1939_decode(c, base);
    if (!decoded) return;
    const auto before = fields_of(*decoded);
    for (unsigned i = j1939_first_data_byte; i < base.size(); ++i) {
        std::string field;
        bool one_field = true;
        std::vector<std::uint64_t> taken;
        std::vector<value_name> names;
        for (unsigned v = 0; v < 256; ++v) {
            const auto r = j1939_decode(c, with_byte(base, i, static_cast<std::uint8_t>(v)));
            if (!r || r->index() != decoded->index()) continue;
            const auto after = fields_of(*r);
            taken.push_back(v);
            for (std::size_t k = 0; k < after.size() && k < before.size(); ++k) {
                if (after[k].text == before[k].text) continue;
                if (!field.empty() && field != after[k].name) one_field = false;
                field = after[k].name;
            }
            for (const auto& a : after)
                if (a.name == field && !a.value_name.empty()) names.push_back({v, a.value_name});
        }
        // The base value's own name (the loop above names only values that changed the field).
        if (!field.empty())
            for (const auto& b : before)
                if (b.name == field && !b.value_name.empty() &&
                    std::none_of(names.begin(), names.end(),
                                 [&](const value_name& n) { return n.value == base[i]; }))
                    names.push_back({base[i], b.value_name});
        if (field.empty() && taken.size() == 1 && taken.front() != 0xFF) {
            // A byte the codec takes one value in, not "not used" (the switch's 00h): said, so
            // that a tool that sends the message builds the frame the keypad takes.
            auto s = number(
                prefix + "byte" + std::to_string(i), 8 * i, 8,
                static_cast<std::int64_t>(taken.front()), static_cast<std::int64_t>(taken.front()),
                receiver,
                with_source("Byte " + std::to_string(i) + ": always " + hex_h(taken.front(), 2),
                            source));
            s.mux = mux;
            m.signals.push_back(std::move(s));
            continue;
        }
        if (field.empty() || !one_field || field == skip) continue;
        std::sort(names.begin(), names.end(),
                  [](const value_name& a, const value_name& b) { return a.value < b.value; });
        // The keypads' periods count 10 ms: the signal is in ms.
        const bool tens = field.ends_with("_10ms");
        const std::string stem = tens ? field.substr(0, field.size() - 5) : field;
        // A command's one field named as the command ("baud_rate", not "baud_rate_baud_rate").
        std::string name =
            !prefix.empty() && (prefix.ends_with("_" + stem + "_") || prefix == stem + "_")
                ? prefix.substr(0, prefix.size() - 1)
                : prefix + stem;
        const unsigned factor = tens ? 10 : 1;
        const std::string unit = tens ? "ms" : "";
        if (tens) name += "_ms";
        const auto [lo, hi] = std::minmax_element(taken.begin(), taken.end());
        auto s = number(name, 8 * i, 8, static_cast<std::int64_t>(*lo * factor),
                        static_cast<std::int64_t>(*hi * factor), receiver,
                        with_source("The field " + field + " (byte " + std::to_string(i) +
                                        "): " + std::to_string(taken.size()) + " values decode, " +
                                        hex_h(*lo, 2) + ".." + hex_h(*hi, 2),
                                    source));
        s.factor = factor;
        s.unit = unit;
        s.mux = mux;
        s.values = std::move(names);
        m.signals.push_back(std::move(s));
    }
}

message new_j1939_message(const context& c, std::uint8_t destination, std::uint8_t source,
                          std::string name, std::string_view from, std::string comment) {
    const j1939::identifier id{6, j1939::proprietary_a_pgn, destination, source};
    auto m = new_message(j1939::make_id(id).value().value(), std::move(name), 8, from,
                         std::move(comment));
    m.extended = true;
    auto command = number("command", 8 * j1939_command_byte, 8, 0, 255,
                          from == keypad_node ? controller_node : keypad_node,
                          "Command byte of the proprietary-A frame (after 04h 1Bh): the "
                          "multiplexor; named are the commands the " +
                              c.manual_name + " has, documented or inferred (docs/j1939.md)");
    command.multiplexor = true;
    m.signals.push_back(std::move(command));
    return m;
}

// One multiplexor value: its name in the command's value table, then its signals.
void add_j1939_mux(const context& c, message& m, const can::frame& f, std::string name,
                   const std::string& prefix, const std::string& source,
                   std::string_view skip = {}) {
    const std::uint64_t mux = f[j1939_command_byte];
    m.signals.front().values.push_back({mux, std::move(name)});
    add_j1939_fields(c, m, f, mux, prefix,
                     m.transmitter == keypad_node ? controller_node : keypad_node, source, skip);
}

void add_j1939(const context& c, database& db) {
    const auto row = j1939::row(c.id).value();
    using j1939::feature;
    const auto keypad_address = c.j1939_address;
    const auto sender = j1939::set_led{}.source;  // the manuals' controller address, 00h
    auto from = new_j1939_message(
        c, j1939::global_address, keypad_address, "j1939_from_keypad", keypad_node,
        "J1939 PGN EF00h (proprietary A), keypad at " + hex_h(keypad_address, 2) +
            " to the global address FFh: the key contact state and the heartbeat, on the "
            "command byte (docs/j1939.md)");
    if (row.frames.has(feature::key_contact)) {
        const auto f = j1939::encode(c.id, j1939::key_contact{});
        if (f)
            add_j1939_mux(c, from, *f, name_of<j1939::key_contact>(), "",
                          j1939_cite(c, row, feature::key_contact));
    }
    if (row.frames.has(feature::heartbeat)) {
        const j1939::heartbeat none{};
        const auto f = j1939::encode(c.id, none);
        if (f) {
            const auto source = j1939_cite(c, row, feature::heartbeat);
            add_j1939_mux(c, from, *f, name_of<j1939::heartbeat>(), "heartbeat_", source, "keys");
            for (unsigned k = 1; k <= 16; ++k) {
                j1939::heartbeat one = none;
                one.keys = key_set{k};
                const auto g = j1939::encode(c.id, one);
                if (!g) continue;  // no key k on this model
                const auto bit = one_bit(g->data_le() & ~f->data_le());
                if (!bit) continue;
                auto s = flag("heartbeat_key" + std::to_string(k), *bit, controller_node,
                              with_source("Key " + std::to_string(k) + ": 1 pressed", source));
                s.mux = (*f)[j1939_command_byte];
                from.signals.push_back(std::move(s));
            }
        }
    }
    auto to = new_j1939_message(
        c, keypad_address, sender, "j1939_to_keypad", controller_node,
        "J1939 PGN EF00h (proprietary A), controller at " + hex_h(sender, 2) +
            " to the keypad at " + hex_h(keypad_address, 2) +
            ": the single-LED command, the configuration commands and the switch to CANopen, on "
            "the command byte (docs/j1939.md)");
    if (row.frames.has(feature::led_command)) {
        const auto first = static_cast<std::uint8_t>(std::countr_zero(row.leds) + 1);
        const auto source = j1939_cite(c, row, feature::led_command);
        if (const auto f = j1939::encode(c.id, j1939::set_led{.key = first}))
            add_j1939_mux(c, to, *f, name_of<j1939::set_led>(), "led_", source);
        else if (const auto g = j1939::encode(c.id, j1939::set_led_code{.key = first}))
            add_j1939_mux(c, to, *g, name_of<j1939::set_led_code>(), "led_", source);
    }
    for (unsigned code = 0; code < 0x80; ++code) {
        const auto* command_row = j1939::find_command(static_cast<std::uint8_t>(code));
        if (command_row == nullptr || !row.frames.has(command_row->what)) continue;
        // A frame of the command that decodes: its data bytes swept until one does.
        const bool two = command_row->p2 != j1939::command_param::none;
        const bool one = command_row->p1 != j1939::command_param::none;
        std::optional<can::frame> found;
        for (unsigned b3 = one ? 0 : 0xFF; b3 < 256 && !found; ++b3)
            for (unsigned b4 = two ? 0 : 0xFF; b4 < 256 && !found; ++b4) {
                const std::array<std::uint8_t, 8> data{j1939::header_0,
                                                       j1939::header_1,
                                                       static_cast<std::uint8_t>(code),
                                                       static_cast<std::uint8_t>(b3),
                                                       static_cast<std::uint8_t>(b4),
                                                       0xFF,
                                                       0xFF,
                                                       0xFF};
                const can::frame f(can::extended_id::make(to.id).value(), data);
                if (const auto r = j1939_decode(c, f);
                    r && std::holds_alternative<j1939::command>(*r))
                    found = f;
            }
        if (!found) continue;
        std::string name(to_string(command_row->code));
        std::string prefix = name.starts_with("set_") ? name.substr(4) : name;
        add_j1939_mux(c, to, *found, name, prefix + "_", j1939_cite(c, row, command_row->what));
    }
    if (row.frames.has(feature::switch_to_canopen)) {
        if (const auto f = j1939::encode(c.id, j1939::switch_to_canopen{}))
            add_j1939_mux(c, to, *f, name_of<j1939::switch_to_canopen>(), "switch_to_canopen_",
                          j1939_cite(c, row, feature::switch_to_canopen));
    }
    for (auto* m : {&from, &to}) {
        auto& command = m->signals.front();
        if (command.values.empty()) continue;
        std::sort(command.values.begin(), command.values.end(),
                  [](const value_name& a, const value_name& b) { return a.value < b.value; });
        db.messages.push_back(std::move(*m));
        db.keypad_address = keypad_address;
        db.controller_address = sender;
    }
}

}  // namespace

database describe(model m, node_id node, std::uint8_t j1939_address) {
    const context c = context_of(m, node, j1939_address);
    database db;
    db.name = c.name + "_" + hex_h(node.value(), 2);
    db.keypad_comment = "Blink Marine " + c.manual_name + " (powerkey model " + c.name +
                        ") at node id " + hex_h(node.value(), 2) + "; frames as the " + c.manual +
                        " describes them, written by powerkey export dbc from its model table "
                        "(docs/dbc.md)";
    // The frames every keypad has, then those its row of the model table gives it, then its
    // J1939 frames (its row of the J1939 model table).
    add_nmt(c, db);
    add_sync(c, db);
    add_heartbeat(c, db);
    add_key_state(c, db);
    add_led_map(c, db, false);
    add_led_map(c, db, true);
    if (c.info.brightness_pdo) add_brightness(c, db);
    if (c.info.encoder_leds_pdo) add_encoder_leds(c, db);
    if (c.info.backlight_pdo) add_backlight(c, db);
    if (c.info.encoders) {
        add_encoder_state(c, db, 1);
        add_encoder_state(c, db, 2);
        add_analog_inputs(c, db);
    }
    add_sdo(c, db);
    add_j1939(c, db);
    std::stable_sort(db.messages.begin(), db.messages.end(),
                     [](const message& a, const message& b) { return a.id < b.id; });
    return db;
}

// --- the DBC text --------------------------------------------------------------------------------

namespace {

// Comments and names are our own text; a double quote would end the string early.
std::string quoted(std::string_view s) {
    std::string out = "\"";
    for (const char ch : s) out += ch == '"' ? '\'' : ch;
    return out + "\"";
}

std::uint64_t dbc_id(const message& m) {
    return m.extended ? (std::uint64_t{m.id} | 0x8000'0000u) : m.id;
}

void append_values(std::string& out, const std::vector<value_name>& values) {
    for (const auto& v : values) {
        out += ' ';
        append_decimal(out, v.value);
        out.append(" ").append(quoted(v.name));
    }
}

void append_number(std::string& out, std::int64_t v) {
    if (v < 0) {
        out += '-';
        append_decimal(out, static_cast<std::uint64_t>(-v));
    } else {
        append_decimal(out, static_cast<std::uint64_t>(v));
    }
}

}  // namespace

std::string text(const database& db) {
    // The new-symbols list as CANdb++ writes it (some readers expect the whole list).
    std::string out = "VERSION \"\"\n\n\nNS_ :\n";
    for (const std::string_view symbol : {"NS_DESC_",     "CM_",
                                          "BA_DEF_",      "BA_",
                                          "VAL_",         "CAT_DEF_",
                                          "CAT_",         "FILTER",
                                          "BA_DEF_DEF_",  "EV_DATA_",
                                          "ENVVAR_DATA_", "SGTYPE_",
                                          "SGTYPE_VAL_",  "BA_DEF_SGTYPE_",
                                          "BA_SGTYPE_",   "SIG_TYPE_REF_",
                                          "VAL_TABLE_",   "SIG_GROUP_",
                                          "SIG_VALTYPE_", "SIGTYPE_VALTYPE_",
                                          "BO_TX_BU_",    "BA_DEF_REL_",
                                          "BA_REL_",      "BA_DEF_DEF_REL_",
                                          "BU_SG_REL_",   "BU_EV_REL_",
                                          "BU_BO_REL_",   "SG_MUL_VAL_"})
        out.append("\t").append(symbol).append("\n");
    out.append("\nBS_:\n\n");
    out.append("BU_: ").append(keypad_node).append(" ").append(controller_node).append("\n\n");
    // The named value tables, each once, in the order of first use.
    std::vector<std::string> tables;
    for (const auto& m : db.messages)
        for (const auto& s : m.signals) {
            if (s.table.empty() || std::find(tables.begin(), tables.end(), s.table) != tables.end())
                continue;
            tables.push_back(s.table);
            out.append("VAL_TABLE_ ").append(s.table);
            append_values(out, s.values);
            out.append(" ;\n");
        }
    out += '\n';
    for (const auto& m : db.messages) {
        out.append("\nBO_ ");
        append_decimal(out, dbc_id(m));
        out.append(" ").append(m.name).append(": ");
        append_decimal(out, m.dlc);
        out.append(" ").append(m.transmitter).append("\n");
        for (const auto& s : m.signals) {
            out.append(" SG_ ").append(s.name);
            if (s.multiplexor) out.append(" M");
            if (s.mux) {
                out.append(" m");
                append_decimal(out, *s.mux);
            }
            out.append(" : ");
            append_decimal(out, s.start);
            out += '|';
            append_decimal(out, s.size);
            out.append("@1+ (");
            append_decimal(out, s.factor);
            out.append(",0) [");
            append_number(out, s.minimum);
            out += '|';
            append_number(out, s.maximum);
            out.append("] ").append(quoted(s.unit)).append(" ").append(s.receiver).append("\n");
        }
    }
    out.append("\n\n");
    out.append("CM_ BU_ ").append(keypad_node).append(" ").append(quoted(db.keypad_comment));
    out.append(";\nCM_ BU_ ").append(controller_node).append(" ");
    out.append(quoted("The CANopen manager that drives the keypad (NMT master, SDO client)"));
    out.append(";\n");
    for (const auto& m : db.messages) {
        if (!m.comment.empty()) {
            out.append("CM_ BO_ ");
            append_decimal(out, dbc_id(m));
            out.append(" ").append(quoted(m.comment)).append(";\n");
        }
        for (const auto& s : m.signals) {
            if (s.comment.empty()) continue;
            out.append("CM_ SG_ ");
            append_decimal(out, dbc_id(m));
            out.append(" ").append(s.name).append(" ").append(quoted(s.comment)).append(";\n");
        }
    }
    // J1939: the attributes Vector's J1939 databases carry and canmatrix writes for them: the
    // protocol, each J1939 message's frame format J1939PG (its identifier read as priority, PGN
    // and addresses), and each node's J1939 address.
    const bool j1939 = std::any_of(db.messages.begin(), db.messages.end(),
                                   [](const message& m) { return m.extended; });
    out.append("BA_DEF_  \"BusType\" STRING ;\n");
    out.append("BA_DEF_  \"DBName\" STRING ;\n");
    if (j1939) {
        out.append("BA_DEF_  \"ProtocolType\" STRING ;\n");
        out.append(
            "BA_DEF_ BO_  \"VFrameFormat\" ENUM  "
            "\"StandardCAN\",\"ExtendedCAN\",\"reserved\",\"J1939PG\";\n");
        out.append("BA_DEF_ BU_  \"NmStationAddress\" INT 0 255;\n");
    }
    out.append("BA_DEF_DEF_  \"BusType\" \"CAN\";\n");
    out.append("BA_DEF_DEF_  \"DBName\" \"\";\n");
    if (j1939) {
        out.append("BA_DEF_DEF_  \"ProtocolType\" \"\";\n");
        out.append("BA_DEF_DEF_  \"VFrameFormat\" \"StandardCAN\";\n");
        out.append("BA_DEF_DEF_  \"NmStationAddress\" 254;\n");
    }
    out.append("BA_ \"BusType\" \"CAN\";\n");
    out.append("BA_ \"DBName\" ").append(quoted(db.name)).append(";\n");
    if (j1939) {
        out.append("BA_ \"ProtocolType\" \"J1939\";\n");
        for (const auto& [node, address] : {std::pair(keypad_node, db.keypad_address),
                                            std::pair(controller_node, db.controller_address)}) {
            out.append("BA_ \"NmStationAddress\" BU_ ").append(node).append(" ");
            append_decimal(out, address);
            out.append(";\n");
        }
        for (const auto& m : db.messages) {
            if (!m.extended) continue;
            out.append("BA_ \"VFrameFormat\" BO_ ");
            append_decimal(out, dbc_id(m));
            out.append(" 3;\n");
        }
    }
    for (const auto& m : db.messages)
        for (const auto& s : m.signals) {
            if (s.values.empty()) continue;
            out.append("VAL_ ");
            append_decimal(out, dbc_id(m));
            out.append(" ").append(s.name);
            append_values(out, s.values);
            out.append(" ;\n");
        }
    return out;
}

}  // namespace tool::dbc
