// powerkey models [NAME]: the models --model takes, one per line, from the library's model table:
// the name, the keys, the object dictionary and whether its CANopen side has the J1939 switch
// (20FFh; every model speaks J1939 in simulate --j1939). With NAME, the one name of the model
// NAME stands for (PKP-2400-LI: pkp2400), as --model reads it; scripts use that (scripts/run.sh).
#include "cli.hpp"
#include "commands.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace tool {

void add_models(registry& r) {
    static std::string name;
    auto& sub = r.add({"models",
                       "[NAME]",
                       "the models --model takes (with NAME: the model NAME stands for)",
                       {},
                       model_use::none,
                       {},
                       "the model is its argument: powerkey models NAME"},
                      [] {
                          std::string out;
                          if (!name.empty()) {
                              const auto m = model_from_name(name);
                              if (!m)
                                  return usage_error("unknown model '" + escape(name, 32) + "' (" +
                                                     model_names() + ")");
                              out = std::string(powerkey::to_string(*m)) + "\n";
                          }
                          for (const auto m : powerkey::enum_values<powerkey::model>()) {
                              if (!name.empty()) break;
                              const auto mi = powerkey::info(m).value();
                              std::string line(powerkey::to_string(m));
                              line.resize(std::max<std::size_t>(line.size() + 1, 11), ' ');
                              line += std::to_string(mi.keys) + (mi.keys < 10 ? "  keys" : " keys");
                              line += "  dictionary ";
                              line += powerkey::to_string(mi.dictionary);
                              out += line + (mi.j1939 ? ", J1939\n" : "\n");
                          }
                          std::fwrite(out.data(), 1, out.size(), stdout);
                          return status_ok;
                      });
    sub.add_option("NAME", name);
}

}  // namespace tool
