// powerkey tool: how a subcommand joins the program. Each subcommand is one file, cmd_NAME.cpp,
// with one function add_NAME(registry&) that describes it, adds its own options to the CLI11
// subcommand it gets back, and says what runs when it is chosen; commands.hpp lists the
// functions, main.cpp calls them. The options every subcommand shares (--model, --node), the
// usage text, -h/--help, usage errors and the exit status are the registry's and main.cpp's, so
// they are the same everywhere.
#ifndef POWERKEY_TOOL_CLI_HPP
#define POWERKEY_TOOL_CLI_HPP

#include "common.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace tool {

// What a subcommand makes of --model.
enum class model_use : std::uint8_t {
    optional,  // default pk1000
    or_auto,   // optional, or `auto`
    required,  // a model must be given
    none,      // no --model and no --node (the subcommand knows nothing of keypads)
};

struct command_spec {
    std::string_view name;
    std::string_view synopsis;  // what follows `powerkey NAME` in the usage, wrapped with \n
    std::string_view summary;   // one line: what it does
    std::string_view help;      // its own options, one per line ("  --json  ..."), may be empty
    model_use model = model_use::optional;
    // What --address means to it, when not the common narrowing to one keypad's J1939 frames:
    // the rest of its usage line after "--address A  " (simulate: where its keypad starts).
    std::string_view address = {};
    // model_use::none: why it takes no --model, --node or --address, as its usage error says it.
    std::string_view no_model_why = "it reads logs of any bus";
};

class registry {
public:
    registry(CLI::App& app, options& common) : app_(app), common_(common) {}

    // Adds subcommand `spec.name`. Its own options go on the returned CLI11 subcommand (store
    // them where `run` finds them); `run` returns the exit status (status_ok, status_input,
    // status_usage: common.hpp).
    CLI::App& add(const command_spec& spec, std::function<int()> run) {
        CLI::App* sub = app_.add_subcommand(std::string(spec.name), std::string(spec.summary));
        sub->fallthrough();  // --model and --node may come before or after the subcommand
        sub->set_help_flag();
        sub->add_flag("-h,--help", help_);
        entries_.push_back({spec, sub, std::move(run)});
        return *sub;
    }

    // The options every subcommand shares, as parsed (valid once main.cpp checked them).
    [[nodiscard]] const options& common() const noexcept { return common_; }

    struct entry {
        command_spec spec;
        CLI::App* app;
        std::function<int()> run;
    };
    [[nodiscard]] const std::vector<entry>& entries() const noexcept { return entries_; }
    [[nodiscard]] bool help_asked() const noexcept { return help_; }

private:
    CLI::App& app_;
    options& common_;
    bool help_ = false;
    std::vector<entry> entries_;
};

}  // namespace tool

#endif
