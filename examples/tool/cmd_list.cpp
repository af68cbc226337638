// powerkey list: every message kind of a model, with its fields and their defaults, as encode
// takes them: `pkp_led_on red=- green=- blue=-`. A value with a space is quoted for the shell.
#include "common.hpp"

#include <powerkey/decoder.hpp>

#include <cstdio>
#include <string>

namespace tool {

namespace {

template <class PM>
void list_kinds(const options& o) {
    std::string out;
    powerkey::for_each_alternative<PM>([&]<class S>(std::type_identity<S>) {
        out += S::kind;
        S s{};
        apply_defaults(s, o);
        std::string_view context;
        S::fields(s, [&](std::string_view name, const auto& v) {
            using T = std::decay_t<decltype(v)>;
            std::string value;
            write_text_value(value, name, context, v);
            if constexpr (std::is_enum_v<T>) context = powerkey::enum_name(v);
            out.append(" ").append(name).append("=");
            if (value.find(' ') != std::string::npos)
                out.append("'").append(value).append("'");
            else
                out.append(value);
        });
        out += '\n';
        return false;
    });
    std::fwrite(out.data(), 1, out.size(), stdout);
}

}  // namespace

int run_list(const options& o) {
    if (powerkey::pkp_model(o.keypad))
        list_kinds<powerkey::pkp::message>(o);
    else
        list_kinds<powerkey::pk1000::message>(o);
    return 0;
}

}  // namespace tool
