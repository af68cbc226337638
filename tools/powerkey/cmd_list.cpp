// powerkey list: every message kind of a model, with its fields and their defaults, as encode
// takes them: `led_on red=- green=- blue=-`. A value with a space is quoted for the shell.
#include "cli.hpp"
#include "commands.hpp"
#include "refusal.hpp"

#include <powerkey/keypad/codec.hpp>

#include <cstdio>
#include <string>

namespace tool {

namespace {

// Listed for a model: every kind the model has (refusal.hpp speaks: its default message
// encodes, or does with a field set to a number, such as a key), so the PKP-3500-MT's encoder
// messages only for it, J1939 only for the keypads that have it.
void list_kinds(const options& o) {
    std::string out;
    powerkey::for_each_alternative<powerkey::message>([&]<class S>(std::type_identity<S>) {
        S s{};
        apply_defaults(s, o.node, false, o.address);
        const powerkey::message m{s};
        if (!speaks(s, o.keypad, o.node, o.address)) return false;
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

void add_list(registry& r) {
    r.add({"list",
           "[--model M] [--node N] [--address A]",
           "every message of a model, with its fields as encode fills them",
           {},
           model_use::optional,
           "the J1939 messages of the keypad at A (its frames' source, its commands' "
           "destination)"},
          [&r] {
              list_kinds(r.common());
              return status_ok;
          });
}

}  // namespace tool
