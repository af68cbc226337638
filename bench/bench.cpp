// The Google Benchmark suite. Each benchmark runs one operation of ops.hpp `calls_per_iteration`
// times per iteration; the reporter adds two columns to every row:
//   ns/call  CPU time of one library call (one frame, or one whole transfer for the reader)
//   x_floor  that time divided by the floor's, the cost of merely reading a frame
// Usage: powerkey_bench [Google Benchmark flags]; --benchmark_min_time=0.01 for a quick run.
// The operations first: the manual rows they include call a `sync()` of their own, which
// <unistd.h>'s ::sync() would make ambiguous if it were declared before them.
#include "all_ops.hpp"

#include <benchmark/benchmark.h>

#include <unistd.h>

#include <string>
#include <vector>

namespace {

constexpr std::size_t calls_per_iteration = 256;

class floor_ratio_reporter : public benchmark::ConsoleReporter {
public:
    floor_ratio_reporter()
        : ConsoleReporter(isatty(STDOUT_FILENO) != 0 ? OO_ColorTabular : OO_Tabular) {}
    void ReportRuns(const std::vector<Run>& runs) override {
        std::vector<Run> copy = runs;
        for (Run& r : copy) {
            if (r.error_occurred) continue;
            const double ns = r.GetAdjustedCPUTime() / static_cast<double>(calls_per_iteration);
            if (r.run_name.function_name.rfind("floor/", 0) == 0 && floor_ns_ == 0) floor_ns_ = ns;
            r.counters["ns/call"] = benchmark::Counter(ns);
            if (floor_ns_ > 0) r.counters["x_floor"] = benchmark::Counter(ns / floor_ns_);
        }
        ConsoleReporter::ReportRuns(copy);
    }

private:
    double floor_ns_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
    bench::for_each_op([](const bench::op& o) {
        benchmark::RegisterBenchmark(std::string(o.name).c_str(), [&o](benchmark::State& state) {
            for (auto _ : state) o.run(calls_per_iteration);
            state.SetItemsProcessed(state.iterations() *
                                    static_cast<std::int64_t>(calls_per_iteration));
        })->Unit(benchmark::kNanosecond);
    });
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    floor_ratio_reporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}
