// powerkey: read any frame of a PowerKey keypad, or build one; one program whose subcommands
// (commands.hpp, one file each) share one command-line parser (CLI11), one reader of every log
// form (input.hpp), one number parser (numbers.hpp), one way of reporting problems and one exit
// status (common.hpp). docs/cli.md describes the subcommands, their output and their status.
#include "cli.hpp"
#include "commands.hpp"

#include <powerkey/behaviour/j1939_keypad.hpp>
#include <powerkey/version.hpp>

#include <cstdio>
#include <string>
#include <string_view>

namespace {

using tool::model_use;

// "pk1000 (default), pkp2200, ..., pkp1600si" wrapped to the usage text's width, from the model
// table; without "(default)" for a subcommand that needs --model.
std::string wrapped_models(std::size_t indent, std::size_t first_width, bool with_default) {
    std::string out, line;
    std::size_t width = first_width;
    bool first = true;
    for (const auto m : powerkey::enum_values<powerkey::model>()) {
        std::string word(powerkey::to_string(m));
        if (first && with_default) word += " (default)";
        first = false;
        if (!line.empty() && line.size() + 2 + word.size() > width) {
            out += line + ",\n" + std::string(indent, ' ');
            line.clear();
            width = 96 - indent;
        }
        line += (line.empty() ? "" : ", ") + word;
    }
    return out + line;
}

std::string common_options_text(model_use use, std::string_view address = {}) {
    if (use == model_use::none) return {};
    std::string s = "  --model M    " + wrapped_models(15, 81, use != model_use::required) +
                    ";\n               in any case, as the manuals write them (PKP-2400-LI, "
                    "PKP-3500-MT) or as\n               the keypad reports them (PKU2400)";
    if (use == model_use::or_auto) s += "; or auto";
    if (use == model_use::required) s += "; required";
    s += "\n  --node N     the keypad's node id 1..127: 0x15 (default), 15h or 21\n";
    s += "  --address A  " +
         (address.empty()
              ? std::string("J1939 frames of the keypad at address A only (01h..FDh; default any)")
              : std::string(address)) +
         "\n";
    return s;
}

// The usage lines of a subcommand: each line of its synopsis is one way to call it, a line that
// starts with two spaces continues the line before.
std::string synopsis(const tool::command_spec& c, bool first) {
    std::string s;
    std::string_view rest = c.synopsis;
    std::size_t pad = 0;
    do {
        const auto nl = rest.find('\n');
        auto line = rest.substr(0, nl);
        rest.remove_prefix(nl == std::string_view::npos ? rest.size() : nl + 1);
        if (line.starts_with("  ")) {
            s += std::string(pad, ' ') + std::string(line.substr(2)) + "\n";
            continue;
        }
        std::string head = (first ? "usage: powerkey " : "       powerkey ") + std::string(c.name);
        first = false;
        pad = head.size() + 1;
        s += head + (line.empty() ? "" : " ") + std::string(line) + "\n";
    } while (!rest.empty());
    return s;
}

constexpr std::string_view input_text =
    "Input (every subcommand; told apart by content; FILE - or none reads standard input, as it\n"
    "arrives):\n"
    "  candump -l, -L     (1700000000.000000) can0 195#0900000012   (a trailing R or T too)\n"
    "  cansend            195#0900000012   195#09.00.00.00.12\n"
    "  candump's screen   can0  195   [5]  09 00 00 00 12   (also -t, -x, -a)\n"
    "  Vector ASC, PEAK TRC 1.x and 2.x, python-can CSV, Vector BLF\n"
    "  Remote, CAN FD and error frames are counted, not decoded (convert writes the remote and\n"
    "  CAN FD ones).\n"
    "\n"
    "Exit status (every subcommand):\n"
    "  0 all input read, nothing wrong found;\n"
    "  1 bad input: a file that cannot be read or is no log, a line that is not a frame, a\n"
    "    JSON line that does not rebuild its frame, a value encode refuses; check: a problem\n"
    "    found in the log (its warnings do not count);\n"
    "  2 usage: unknown command, option, model, message or field, a node id outside 1..127.\n"
    "See docs/cli.md.\n";

std::string usage_text(const tool::registry& r) {
    std::string s;
    bool first = true;
    for (const auto& e : r.entries()) {
        s += synopsis(e.spec, first);
        first = false;
    }
    s += "       powerkey help [COMMAND] | version\n\n";
    for (const auto& e : r.entries())
        s += "  " + std::string(e.spec.name) + std::string(12 - e.spec.name.size(), ' ') +
             std::string(e.spec.summary) + "\n";
    s += "\n" + common_options_text(model_use::or_auto);
    for (const auto& e : r.entries()) {
        if (e.spec.help.empty()) continue;
        s += std::string(e.spec.name) + ":\n" + std::string(e.spec.help);
    }
    s += "\n";
    s += input_text;
    return s;
}

std::string command_help(const tool::command_spec& c) {
    return synopsis(c, true) + std::string(c.summary) + "\n\n" +
           common_options_text(c.model, c.address) + std::string(c.help) + "\n" +
           std::string(input_text);
}

void print(const std::string& s, std::FILE* to) { std::fwrite(s.data(), 1, s.size(), to); }

}  // namespace

int main(int argc, char** argv) {
    tool::options common;
    CLI::App app{"powerkey"};
    app.set_help_flag();
    bool help = false, version = false;
    std::string model_text, node_text, address_text;
    app.add_flag("-h,--help", help);
    app.add_flag("--version", version);
    app.add_option("--model", model_text);
    app.add_option("--node", node_text);
    app.add_option("--address", address_text);
    tool::registry r(app, common);
    for (const auto add : tool::commands) add(r);
    auto* help_command = app.add_subcommand("help");
    std::string help_topic;
    help_command->add_option("COMMAND", help_topic);
    auto* version_command = app.add_subcommand("version");
    for (auto* sub : {help_command, version_command}) sub->set_help_flag();
    app.require_subcommand(0, 1);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        std::string what = e.what();
        if (!what.empty() && what.back() == '\n') what.pop_back();
        return tool::usage_error(tool::escape(what, 120));
    }
    const tool::registry::entry* chosen = nullptr;
    for (const auto& e : r.entries())
        if (*e.app) chosen = &e;
    if (*help_command && !help_topic.empty()) {
        for (const auto& e : r.entries())
            if (e.spec.name == help_topic) chosen = &e;
        if (chosen == nullptr)
            return tool::usage_error("help: no command '" + tool::escape(help_topic, 32) + "'");
    }
    if (help || r.help_asked() || *help_command) {
        print(chosen ? command_help(chosen->spec) : usage_text(r), stdout);
        return tool::status_ok;
    }
    if (version || *version_command) {
        std::printf("powerkey %.*s\n", static_cast<int>(powerkey::version.size()),
                    powerkey::version.data());
        return tool::status_ok;
    }
    if (chosen == nullptr) {
        print(usage_text(r), stderr);
        return tool::status_usage;
    }
    // An option given an empty value (--until '', --node=) is a usage error, never its default.
    for (const CLI::App* a :
         {static_cast<const CLI::App*>(&app), static_cast<const CLI::App*>(chosen->app)})
        for (const CLI::Option* opt : a->get_options())
            if (!opt->get_positional() && opt->get_type_size_max() > 0)
                for (const auto& value : opt->results())
                    if (value.empty())
                        return tool::usage_error(opt->get_name() +
                                                 ": an empty value (give one, or leave the "
                                                 "option out for its default)");
    const auto use = chosen->spec.model;
    const std::string name(chosen->spec.name);
    // Given, even empty (--node ''): an empty value is an error, never the default.
    const bool model_given = app.get_option("--model")->count() > 0;
    const bool node_given = app.get_option("--node")->count() > 0;
    const bool address_given = app.get_option("--address")->count() > 0;
    if (use == model_use::none && (model_given || node_given || address_given))
        return tool::usage_error(name + " takes no --model or --node or --address (" +
                                 std::string(chosen->spec.no_model_why) + ")");
    if (model_given) {
        if (use == model_use::or_auto && (model_text == "auto" || model_text == "AUTO")) {
            common.model_auto = true;
        } else if (const auto m = tool::model_from_name(model_text)) {
            common.keypad = *m;
            common.model_given = true;
        } else {
            return tool::usage_error("--model: unknown model '" + tool::escape(model_text, 32) +
                                     "' (" + tool::model_names() +
                                     (use == model_use::or_auto ? ", auto)" : ")"));
        }
    } else if (use == model_use::required) {
        return tool::usage_error(name + " needs --model M (" + tool::model_names() + ")");
    }
    if (node_given) {
        std::uint64_t n = 0;
        const bool number = tool::parse_number(node_text, n);
        const auto id = powerkey::canopen::node_id::make(number ? n : 0);
        if (!number || !id)
            return tool::usage_error("--node: expected a node id 1..127 (0x15, 15h or 21), got '" +
                                     tool::escape(node_text, 32) + "'");
        common.node = *id;
        common.node_given = true;
    }
    if (address_given) {
        std::uint64_t a = 0;
        // 70h's range (behaviour::j1939_source_address): 00h is the controllers' (the manuals'
        // sender), FEh J1939's null address and FFh the global one; no keypad holds them.
        if (!tool::parse_number(address_text, a) ||
            !powerkey::behaviour::j1939_source_address::make(a))
            return tool::usage_error(
                "--address: expected a keypad's J1939 address 01h..FDh (70h's range: 0x21, 21h "
                "or 33), got '" +
                tool::escape(address_text, 32) + "'");
        common.address = static_cast<std::uint8_t>(a);
    }
    return chosen->run();
}
