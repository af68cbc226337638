// The main of every fuzz target when libFuzzer is not available (g++, or a coverage build): runs
// LLVMFuzzerTestOneInput once on each file named, or on each file of each directory named, in
// name order. A directory that does not exist counts as empty. Exit status 0 when every input ran;
// a failing property aborts the process, as it would under libFuzzer.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

std::vector<std::uint8_t> read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    std::size_t count = 0;
    for (int i = 1; i < argc; ++i) {
        const fs::path arg(argv[i]);
        std::vector<fs::path> files;
        if (fs::is_directory(arg)) {
            for (const auto& e : fs::directory_iterator(arg))
                if (e.is_regular_file()) files.push_back(e.path());
            std::sort(files.begin(), files.end());
        } else if (fs::is_regular_file(arg)) {
            files.push_back(arg);
        } else {
            std::printf("%s: no such file or directory, skipped\n", argv[i]);
        }
        for (const auto& f : files) {
            const auto bytes = read_file(f);
            // A non-null pointer even for an empty input, as libFuzzer passes.
            static const std::uint8_t empty = 0;
            (void)LLVMFuzzerTestOneInput(bytes.empty() ? &empty : bytes.data(), bytes.size());
            ++count;
        }
    }
    // Also the empty input, which libFuzzer always tries first.
    static const std::uint8_t empty = 0;
    (void)LLVMFuzzerTestOneInput(&empty, 0);
    std::printf("replayed %zu inputs\n", count);
    return 0;
}
