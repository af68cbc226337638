// The instruction counter: run under `valgrind --tool=callgrind --collect-atstart=no`, it counts
// the instructions of each operation of ops.hpp separately (a callgrind dump per operation) so
// that scripts/callgrind.sh can divide by the number of calls. Instruction counts, unlike times,
// do not depend on what else the machine is doing.
// Usage: powerkey_icount [calls] [name-prefix]; `--list` prints the operations.
#include <valgrind/callgrind.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "all_ops.hpp"

int main(int argc, char** argv) {
    std::size_t calls = 10000;
    std::string_view prefix;
    if (argc > 1 && std::string_view(argv[1]) == "--list") {
        bench::for_each_op([](const bench::op& o) {
            std::printf("%.*s\t%.*s\n", static_cast<int>(o.name.size()), o.name.data(),
                        static_cast<int>(o.per_call.size()), o.per_call.data());
        });
        return 0;
    }
    if (argc > 1) calls = std::strtoull(argv[1], nullptr, 10);
    if (argc > 2) prefix = argv[2];
    bench::for_each_op([&](const bench::op& o) {
        if (o.name.substr(0, prefix.size()) != prefix) return;
        o.run(calls);  // warm up: the first calls fault pages in and resolve symbols
        const std::string label = std::string(o.name) + " calls=" + std::to_string(calls);
        CALLGRIND_ZERO_STATS;
        CALLGRIND_TOGGLE_COLLECT;
        o.run(calls);
        CALLGRIND_TOGGLE_COLLECT;
        CALLGRIND_DUMP_STATS_AT(label.c_str());
    });
    return 0;
}
