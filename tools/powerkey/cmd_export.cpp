// powerkey export dbc --model M [--node N] [--address A]: the DBC of one keypad at one node id
// and J1939 address on standard output (dbc.hpp, docs/dbc.md). `export` names what it writes, so
// that another form can join as another word beside `dbc`.
#include "cli.hpp"
#include "commands.hpp"
#include "dbc.hpp"

#include <cstdio>
#include <string>

namespace tool {

void add_export(registry& r) {
    static const CLI::App* dbc_command = nullptr;
    auto& sub = r.add(
        {"export",
         "dbc --model M [--node N] [--address A]",
         "the keypad's frames as a DBC file for CAN tools (docs/dbc.md)",
         {},
         model_use::required,
         "the keypad's J1939 address in the DBC's J1939 messages, 01h..FDh "
         "(default 21h)"},
        [&r] {
            if (!*dbc_command) return usage_error("export: say what to export (dbc)");
            const auto& o = r.common();
            const std::string text = dbc::text(dbc::describe(
                o.keypad, o.node, o.address.value_or(powerkey::j1939::keypad_default_address)));
            std::fwrite(text.data(), 1, text.size(), stdout);
            return status_ok;
        });
    auto* d = sub.add_subcommand("dbc", "a DBC file for one keypad at one node id");
    d->fallthrough();  // --model and --node may come after `dbc` too
    dbc_command = d;
}

}  // namespace tool
