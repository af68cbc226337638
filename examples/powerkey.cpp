// powerkey: read any frame of a PowerKey keypad, or build one.
//   powerkey decode [--model M|auto] [--node N] [--json | --show] [FILE...]
//   powerkey encode [--model M] [--node N] [--broadcast] MESSAGE [FIELD=VALUE...]
//   powerkey encode --json [--model M] [--node N] [FILE...]
//   powerkey list [--model M] [--node N]
//   powerkey simulate --model M [--node N] [--press T:K] [--release T:K] [--until T] [FILE...]
//   powerkey check --model M [--node N] [--json] [--sdo-timeout MS] [FILE...]
//   powerkey export dbc --model M [--node N]
// The options are read by CLI11; each subcommand is one file of tool/ (cmd_decode.cpp,
// cmd_encode.cpp, cmd_list.cpp, cmd_export.cpp, and cmd_simulate.cpp, cmd_check.cpp, which read
// their own options). docs/cli.md describes the options, the output and the exit status.
#include "tool/common.hpp"

#include <CLI/CLI.hpp>
#include <powerkey/version.hpp>

#include <cstdio>
#include <cstring>
#include <string>

// The behaviour layer's subcommands (docs/behaviour.md, docs/controller.md): they take the
// arguments after their name.
int run_simulate(int argc, char** argv);
int run_check(int argc, char** argv);

namespace {

constexpr std::string_view usage_text =
    "usage: powerkey decode [--model M|auto] [--node N] [--json | --show] [FILE...]\n"
    "       powerkey encode [--model M] [--node N] [--broadcast] MESSAGE [FIELD=VALUE...]\n"
    "       powerkey encode --json [--model M] [--node N] [FILE...]\n"
    "       powerkey list [--model M] [--node N]\n"
    "       powerkey simulate --model M [--node N] [--press T:K] [--release T:K] [--until T]\n"
    "                         [FILE...]\n"
    "       powerkey check --model M [--node N] [--json] [--sdo-timeout MS] [FILE...]\n"
    "       powerkey export dbc --model M [--node N]\n"
    "       powerkey help | version\n"
    "\n"
    "  --model M    pk1000 (default), pkp2200, pkp2400, pkp2600, pkp2600si, pkp3500mt,\n"
    "               pkp3500si, pkp2500si, pkp1500li, pkp2200si, pkp2300si, pkp2400si, in any\n"
    "               case and as the manuals write them (PKP-2400-LI, PKP-3500-MT) or the keypad\n"
    "               reports them (PKU2400); decode also takes auto\n"
    "  --node N     the keypad's node id 1..127: 0x15 (default), 15h or 21\n"
    "  --json       decode: JSON lines; encode: read decode --json lines (with --node N the\n"
    "               frames are re-targeted to node N)\n"
    "  --show       decode: draw the keypad after each frame that changes it (not with --json)\n"
    "  --broadcast  encode: an NMT command for every node (target 0) instead of --node\n"
    "  simulate     a virtual keypad answering a controller's frames (docs/behaviour.md)\n"
    "  check        a bus log checked against the keypad's rules (docs/controller.md)\n"
    "  export dbc   the keypad's frames as a DBC file for CAN tools (docs/dbc.md)\n"
    "\n"
    "Input (told apart by content; FILE - or none reads standard input, as it arrives):\n"
    "  candump -l, -L     (1700000000.000000) can0 195#0900000012   (a trailing R or T too)\n"
    "  cansend            195#0900000012   195#09.00.00.00.12\n"
    "  candump's screen   can0  195   [5]  09 00 00 00 12   (also -t, -x, -a)\n"
    "  Vector ASC, PEAK TRC 1.x and 2.x, python-can CSV, Vector BLF\n"
    "  Remote, CAN FD and error frames are counted and skipped, not decoded.\n"
    "\n"
    "Exit status: 0 all input read (frames of other nodes are output, not failures);\n"
    "  1 bad input: a line or file that is not a frame, a JSON line that does not rebuild its\n"
    "    frame, a field value encode refuses, a file that cannot be read;\n"
    "  2 usage: unknown command, option, model, message or field, a node id outside 1..127.\n"
    "See docs/cli.md.\n";

int usage_error(const std::string& what) {
    tool::report("", what + " (powerkey help shows the usage)");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc >= 2 && std::strcmp(argv[1], "simulate") == 0) return run_simulate(argc - 2, argv + 2);
    if (argc >= 2 && std::strcmp(argv[1], "check") == 0) return run_check(argc - 2, argv + 2);
    tool::options o;
    CLI::App app{"powerkey"};
    app.set_help_flag();
    bool help = false, version = false;
    std::string model_text, node_text;
    app.add_flag("-h,--help", help);
    app.add_flag("--version", version);
    app.add_option("--model", model_text);
    app.add_option("--node", node_text);
    app.add_flag("--json", o.json);
    app.add_flag("--show", o.show);
    app.add_flag("--broadcast", o.broadcast);
    app.add_flag("--parse-only", o.parse_only);
    app.add_flag("--quiet", o.quiet);
    app.add_flag("--nlohmann-writer", o.nlohmann_writer);
    auto* decode = app.add_subcommand("decode");
    decode->add_option("FILE", o.args);
    auto* encode = app.add_subcommand("encode");
    encode->add_option("ARG", o.args);
    auto* list = app.add_subcommand("list");
    auto* export_command = app.add_subcommand("export");
    auto* dbc = export_command->add_subcommand("dbc");
    auto* help_command = app.add_subcommand("help");
    auto* version_command = app.add_subcommand("version");
    for (auto* sub : {decode, encode, list, export_command, dbc, help_command, version_command}) {
        sub->fallthrough();  // the options above may come before or after the subcommand
        sub->set_help_flag();
    }
    app.require_subcommand(0, 1);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        std::string what = e.what();
        if (!what.empty() && what.back() == '\n') what.pop_back();
        return usage_error(tool::escape(what, 120));
    }
    if (help || *help_command) {
        std::fwrite(usage_text.data(), 1, usage_text.size(), stdout);
        return 0;
    }
    if (version || *version_command) {
        std::printf("powerkey %.*s\n", static_cast<int>(powerkey::version.size()),
                    powerkey::version.data());
        return 0;
    }
    if (app.get_subcommands().empty()) {
        std::fwrite(usage_text.data(), 1, usage_text.size(), stderr);
        return 2;
    }
    if (!model_text.empty()) {
        if (*decode && (model_text == "auto" || model_text == "AUTO")) {
            o.model_auto = true;
        } else if (const auto m = tool::model_from_name(model_text)) {
            o.keypad = *m;
            o.model_given = true;
        } else {
            return usage_error("--model: unknown model '" + tool::escape(model_text, 32) + "' (" +
                               tool::model_names() + (*decode ? ", auto)" : ")"));
        }
    }
    if (!node_text.empty()) {
        std::uint64_t n = 0;
        const bool number = tool::parse_number(node_text, n);
        const auto id = powerkey::canopen::node_id::make(number ? n : 0);
        if (!number || !id)
            return usage_error("--node: expected a node id 1..127 (0x15, 15h or 21), got '" +
                               tool::escape(node_text, 32) + "'");
        o.node = *id;
        o.node_given = true;
    }
    if (o.json && o.show)
        return usage_error(
            "--show draws pictures for people and --json writes lines for programs: use one");
    if (o.show && !*decode) return usage_error("--show is an option of decode");
    if (o.broadcast && !*encode) return usage_error("--broadcast is an option of encode");
    if (o.nlohmann_writer && !(*decode && o.json))
        return usage_error("--nlohmann-writer is an option of decode --json");
    if ((o.parse_only || o.quiet) && !*decode)
        return usage_error("--parse-only and --quiet are options of decode");
    if (*decode) return tool::run_decode(o);
    if (*encode) return o.json ? tool::run_encode_json(o) : tool::run_encode(o);
    if (*export_command && !*dbc) return usage_error("export: say what to export (dbc)");
    if (*dbc) {
        if (!o.model_given)
            return usage_error("export dbc: --model is required (" + tool::model_names() + ")");
        if (o.json) return usage_error("export dbc has no --json");
        return tool::run_export_dbc(o);
    }
    if (*list) {
        if (o.json) return usage_error("list has no --json");
        return tool::run_list(o);
    }
    return 2;
}
