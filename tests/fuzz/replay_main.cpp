// Runs a fuzz target over files, as libFuzzer does when given files instead of a corpus to
// grow: the normal (g++) build has no libFuzzer, and this keeps every seed and every input
// that once crashed exercised by ctest. A failure is a crash, an abort or a sanitizer report.

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

namespace fs = std::filesystem;

/// The files named, those in a named folder in name order (so a failure is reproducible).
std::vector<fs::path> inputs(int argc, char** argv) {
    std::vector<fs::path> files;
    for (int i = 1; i < argc; ++i) {
        const fs::path path = argv[i];
        if (!fs::is_directory(path)) {
            files.push_back(path);
            continue;
        }
        std::vector<fs::path> in_folder;
        for (const auto& entry : fs::directory_iterator(path)) {
            if (entry.is_regular_file()) {
                in_folder.push_back(entry.path());
            }
        }
        std::sort(in_folder.begin(), in_folder.end());
        files.insert(files.end(), in_folder.begin(), in_folder.end());
    }
    return files;
}

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

int main(int argc, char** argv) {
    const std::vector<fs::path> files = inputs(argc, argv);
    if (files.empty()) {
        std::fprintf(stderr, "usage: %s FILE_OR_FOLDER... (an empty corpus tests nothing)\n",
                     argv[0]);
        return 2;
    }
    for (const fs::path& file : files) {
        if (!fs::exists(file)) {
            std::fprintf(stderr, "%s: no such file\n", file.c_str());
            return 2;
        }
        // Printed first, so that the input which crashes is the last one named.
        std::printf("%s\n", file.c_str());
        std::fflush(stdout);
        const std::vector<std::uint8_t> bytes = read_bytes(file);
        LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
    }
    std::printf("replayed %zu inputs\n", files.size());
    return 0;
}
