// powerkey list: every message kind of a model, with its fields and their defaults, as encode
// takes them: `led_on red=- green=- blue=-`. A value with a space is quoted for the shell.
#include "common.hpp"

#include <powerkey/keypad/codec.hpp>

#include <cstdio>
#include <string>

namespace tool {

namespace {

// Listed for a model: every kind whose default message encodes for it (so the PKP-3500-MT's
// encoder messages only for it, J1939 only for the keypads that have it), the SDO kinds always
// (their fields follow the object; object=... picks it), and the PKP command where the model's
// dictionary has the command module (6500h/1).
bool listed(const options& o, std::string_view kind, const powerkey::message& m) {
    if (powerkey::encode(o.node, o.keypad, m)) return true;
    if (kind.starts_with("sdo_")) return true;
    const auto mi = powerkey::info(o.keypad);
    return kind == "command" && mi &&
           powerkey::find_row(mi->dictionary, powerkey::object::command_module).has_value();
}

void list_kinds(const options& o) {
    std::string out;
    powerkey::for_each_alternative<powerkey::message>([&]<class S>(std::type_identity<S>) {
        S s{};
        apply_defaults(s, o);
        const powerkey::message m{s};
        if (!listed(o, S::kind, m)) return false;
        out += S::kind;
        // The values exactly as decode's text prints them (describe), quoted when they hold a
        // space.
        for (const auto& [name, value] : described_fields(m, o.node)) {
            out.append(" ").append(name).append("=");
            if (value.find(' ') != std::string::npos)
                out.append("'").append(value).append("'");
            else
                out.append(value);
        }
        out += '\n';
        return false;
    });
    std::fwrite(out.data(), 1, out.size(), stdout);
}

}  // namespace

int run_list(const options& o) {
    list_kinds(o);
    return 0;
}

}  // namespace tool
