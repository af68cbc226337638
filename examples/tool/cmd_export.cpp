// powerkey export dbc: the DBC of one keypad at one node id on standard output (dbc.hpp,
// docs/dbc.md).
#include "common.hpp"
#include "dbc.hpp"

#include <cstdio>
#include <string>

namespace tool {

int run_export_dbc(const options& o) {
    const std::string text = dbc::text(dbc::describe(o.keypad, o.node));
    std::fwrite(text.data(), 1, text.size(), stdout);
    return 0;
}

}  // namespace tool
