// powerkey tool: the subcommands, in the order `powerkey help` lists them. Adding one is a file
// cmd_NAME.cpp defining add_NAME(registry&) (cli.hpp says what it does) and one line in each list
// below; the build picks up every cmd_*.cpp.
#ifndef POWERKEY_TOOL_COMMANDS_HPP
#define POWERKEY_TOOL_COMMANDS_HPP

#include "cli.hpp"

namespace tool {

void add_decode(registry& r);
void add_encode(registry& r);
void add_list(registry& r);
void add_models(registry& r);
void add_simulate(registry& r);
void add_check(registry& r);
void add_convert(registry& r);
void add_export(registry& r);

inline constexpr void (*commands[])(registry&) = {
    add_decode, add_encode, add_list, add_models, add_simulate, add_check, add_convert, add_export,
};

}  // namespace tool

#endif
