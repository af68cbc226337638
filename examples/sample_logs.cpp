// Writes the sample bus logs of examples/logs/ from the manual rows of the test suite
// (tests/pk1000_rows.hpp, tests/pkp_rows.hpp; for the SI family tests/si_rows.hpp, generated from
// tests/data/si_rows.txt, and tests/si_reference_rows.hpp for the sizes without a complete
// manual), one log per model, in the manuals' order:
//   sample_logs pk1000 > examples/logs/pk1000.log
// Each frame is a candump -l line with a made-up timestamp, 10 ms apart. The manuals show some
// frames for another node id (after a node-id change); where the next row is for another node
// than the keypad has at that point, the log moves the keypad there with the model's own node-id
// change, marked "not in the manual", so that the log reads as one session.
// Two more kinds of log, from the J1939 rows (tests/j1939_rows.hpp):
//   sample_logs j1939-pkp1600si    every example frame of the model's J1939 manual, in order
//   sample_logs switch-pkp2600si   a PKP-2600-SI crossing the switch both ways: CANopen, the write
//                                  of 20FFh, J1939 traffic with an address change, 80h, CANopen
#include "../tests/j1939_rows.hpp"
#include "../tests/pk1000_rows.hpp"
#include "../tests/pkp_rows.hpp"
#include "../tests/si_reference_rows.hpp"
#include "../tests/si_rows.hpp"

#include <powerkey/can/candump.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/names.hpp>
#include <powerkey/session.hpp>

#include <cstdio>
#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace {
using namespace powerkey;

struct writer {
    model keypad;
    session<256> s;
    long tick = 0;
    std::string_view last_section;

    void frame(const can::frame& f) {
        (void)s.step(f);
        const auto t = can::format_candump(f);
        std::printf("(%ld.%06ld) can0 %.*s\n", 1700000000L + tick / 100, (tick % 100) * 10000L,
                    static_cast<int>(t.view().size()), t.view().data());
        ++tick;
    }
    void text(std::string_view candump) { frame(can::parse_candump(candump).value()); }

    // Moves the keypad to `target` the way its model does it: a write of node_id (2013h) answered
    // from the new id (PK1000 section 23), or command 70h answered from the old id, then the
    // boot-up from the new one (PKP section 13 h).
    void move_to(canopen::node_id target) {
        const auto from = s.node();
        std::printf("# (not in the manual) node id %02Xh -> %02Xh\n", from.value(), target.value());
        if (info(keypad)->replies_from_new_id) {
            frame(*encode(from, keypad, sdo_write{object::node_id, node_value(target)}));
            frame(*encode(target, keypad, sdo_write_reply{object::node_id}));
        } else {
            command c;
            c.code = command_code::set_node_id;
            c.node_id = target;
            frame(*encode(from, keypad, c));
            frame(*encode(from, keypad, sdo_write_reply{object::command_module}));
            frame(*encode(target, keypad, canopen::heartbeat_message{}));
        }
    }

    // Moves the keypad's J1939 address (and identifier) to `target` with command 70h sent to
    // its address (section 16), as a controller at 00h does.
    void move_j1939_to(std::uint8_t target) {
        const std::uint8_t from = s.j1939_address();
        std::printf("# (not in the manual) J1939 address %02Xh -> %02Xh\n", from, target);
        j1939::command c;
        c.code = j1939::command_code::set_source_address;
        c.destination = from;
        c.address = target;
        c.identifier = target;
        frame(*j1939::encode(keypad, c, from));
    }

    void row(std::string_view section, std::uint8_t node, std::string_view candump) {
        if (section != last_section) {
            std::printf("# %.*s\n", static_cast<int>(section.size()), section.data());
            last_section = section;
        }
        const auto n = canopen::node_id::make(node).value();
        if (n != s.node()) move_to(n);
        text(candump);
    }
};

// A J1939 session of a model with a complete J1939 manual: its rows in the manual's order. The
// manuals print every frame for the default address 21h: after their example of 70h the log
// moves the keypad back, marked "not in the manual", so that the log reads as one session; and
// the multiple-LED command (section 7b) comes before the 37h 02h that lets it in (section 13),
// so the log sends that first (`powerkey check` passes the log).
int j1939_log(model m) {
    const auto rows = m == model::pkp1600si
                          ? std::span<const j1939_rows::row>(j1939_rows::pkp1600si_rows)
                          : std::span<const j1939_rows::row>(j1939_rows::pkp2600si_rows);
    writer w{m, session<256>(m, canopen::default_node_id), 0, {}};
    std::printf(
        "# powerkey sample log: %s in J1939, every example frame of its J1939 manual in order\n"
        "# from %s (tests/j1939_rows.hpp)\n",
        std::string(to_string(m)).c_str(),
        m == model::pkp1600si ? "PKP1600SI_J1939_UM_rev1.0" : "PKP2600SI_J1939_UM_rev1.5");
    bool managed = false;  // 37h 02h sent
    for (const auto& r : rows) {
        const auto f = can::parse_candump(r.frame).value();
        const auto msg = j1939::decode(f, m);
        if (!managed && msg && std::holds_alternative<j1939::multiple_leds>(*msg)) {
            std::printf("# (not in the manual) LED management 37h 02h (section 13) first\n");
            w.text("18EF2100#041B3702FFFFFFFF");
            w.last_section = {};
            managed = true;
        }
        if (const auto* c = msg ? std::get_if<j1939::command>(&*msg) : nullptr)
            managed =
                managed || (c->code == j1939::command_code::set_led_management && c->multiple_leds);
        if (r.section != w.last_section) {
            std::printf("# %.*s\n", static_cast<int>(r.section.size()), r.section.data());
            w.last_section = r.section;
        }
        w.frame(f);
        if (w.s.j1939_address() != j1939::keypad_default_address)
            w.move_j1939_to(j1939::keypad_default_address);
    }
    return 0;
}

// A PKP-2600-SI that crosses the switch both ways. Every frame is a manual's (the PKP2600SI
// CANopen and J1939 manuals, sections named) but the two after the address change, which the
// manuals print for the default address only.
int switch_log() {
    const model m = model::pkp2600si;
    writer w{m, session<256>(m, canopen::default_node_id), 0, {}};
    const auto say = [](const char* t) { std::printf("# %s\n", t); };
    std::printf(
        "# powerkey sample log: pkp2600si crossing the protocol switch both ways, node 15h\n"
        "# and J1939 address 21h (PKP2600SI CANopen and J1939 manuals)\n");
    say("CANopen: boot-up (8), start (4), key 4 pressed and released (11)");
    for (const auto* t : {"715#00", "000#0115", "195#080000002A", "195#000000002A"}) w.text(t);
    say("CANopen 47 (E-SI-7 corrected): the switch to J1939");
    w.text("615#2BFF200101000000");
    say("J1939 20: the address claim; 6: key 1 pressed and released; 7a: LED 1 red");
    for (const auto* t : {"18EEFF21#3F426F1A00823CC0", "18EFFF21#041B01010121FFFF",
                          "18EFFF21#041B01010021FFFF", "18EF2100#041B0101010100FF"})
        w.text(t);
    say("J1939 21: a heartbeat (key 8 down); 16: source address 02h, identifier 01h");
    for (const auto* t : {"18EFFF21#041BF9038000FF21", "18EF2100#041B700201FFFFFF"}) w.text(t);
    say("(not in the manual) key 3 pressed at the new address, and 80h (27) sent there");
    for (const auto* t : {"18EFFF02#041B01030101FFFF", "18EF0200#041B8000FFFFFFFF"}) w.text(t);
    say("CANopen again: boot-up (8), key 8 pressed (11)");
    for (const auto* t : {"715#00", "000#0115", "195#800000002A"}) w.text(t);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 2 && std::string_view(argv[1]).starts_with("j1939-")) {
        const auto m = parse_model(std::string_view(argv[1]).substr(6));
        if (m && (*m == model::pkp1600si || *m == model::pkp2600si)) return j1939_log(*m);
    }
    if (argc == 2 && std::string_view(argv[1]) == "switch-pkp2600si") return switch_log();
    if (argc != 2 || !parse_model(argv[1])) {
        std::fputs(
            "usage: sample_logs MODEL (pk1000, pkp2600, pkp2600si, pkp3500mt, ...)\n"
            "       sample_logs j1939-pkp1600si | j1939-pkp2600si | switch-pkp2600si\n",
            stderr);
        return 2;
    }
    const model m = *parse_model(argv[1]);
    writer w{m, session<256>(m, canopen::default_node_id), 0, {}};
    const bool reference = info(m)->dictionary == dictionary::si_per_colour;
    std::printf(
        "# powerkey sample log: %s, node 15h, %s in order\n", argv[1],
        reference ? "the frames of its reference rows" : "every example frame of the manual");
    if (m == model::pk1000) {
        std::printf("# from PK1000_CANopen_UM_rev1.13 (tests/pk1000_rows.hpp)\n");
        for (const auto& r : pk1000_rows::rows) w.row(r.section, r.node, r.frame);
    } else if (m == model::pkp2600si || m == model::pkp3500mt) {
        std::printf("# from the %s CANopen UM (tests/data/si_rows.txt, tests/si_rows.hpp)\n",
                    m == model::pkp2600si ? "PKP-2600-SI rev 1.5" : "PKP-3500-MT rev 1.3");
        for (const auto& r : si_rows::rows)
            if (r.models.contains(m)) w.row(r.section, r.node, r.frame);
    } else if (reference) {
        std::printf(
            "# from docs/si-family.md, \"The other sizes\": the manual pages available and the\n"
            "# inferred layouts, marked so (tests/si_reference_rows.hpp)\n");
        for (const auto& r : si_reference_rows::rows)
            if (r.models.contains(m)) w.row(r.section, r.node, r.frame);
    } else {
        std::printf(
            "# from PKP-2200-2400-LI_CANopen_UM_rev1.1 and docs/pkp.md (tests/pkp_rows.hpp)\n");
        for (const auto& r : pkp_rows::rows)
            if (r.models.contains(m)) w.row(r.section, r.node, r.frame);
    }
    if (w.s.node() != canopen::default_node_id) w.move_to(canopen::default_node_id);
}
