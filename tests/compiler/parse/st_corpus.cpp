#include "st_corpus.hpp"

#include "utf8.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>

namespace eposp::compiler::corpus {

std::vector<std::filesystem::path> st_files() {
    std::vector<std::filesystem::path> files;
    const std::filesystem::path roots[] = {std::filesystem::path(EPOSP_SOURCE_DIR) / "tests",
                                           std::filesystem::path(EPOSP_SOURCE_DIR) / "examples",
                                           EPOSP_BENCH_ST_DIR};
    for (const auto& root : roots) {
        if (!std::filesystem::is_directory(root)) {
            continue; // the benchmarks' folder lies outside the repository
        }
        for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
            if (entry.is_regular_file() && entry.path().extension() == ".st") {
                files.push_back(entry.path());
            }
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string as_text(const std::string& bytes) {
    for (std::size_t i = 0; i < bytes.size();) {
        if (!utf8::decode(bytes, i)) {
            return utf8::from_windows_1252(bytes);
        }
    }
    return bytes;
}

std::string random_string(std::mt19937& random, std::string_view alphabet, std::size_t length) {
    std::string text;
    std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
    for (std::size_t i = 0; i < length; ++i) {
        text.push_back(alphabet[pick(random)]);
    }
    return text;
}

std::string mixed_case(std::mt19937& random, std::string word) {
    for (char& c : word) {
        if (random() % 2 == 0) {
            c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        }
    }
    return word;
}

void for_each_variant(const std::string& text, const std::string& name, std::mt19937& random,
                      std::string_view alphabet,
                      const std::function<void(const std::string&, const std::string&)>& visit) {
    if (text.empty()) {
        return;
    }
    std::uniform_int_distribution<std::size_t> position(0, text.size() - 1);
    for (int i = 0; i < 6; ++i) {
        const std::size_t cut = position(random);
        visit(text.substr(0, cut), name + " cut at " + std::to_string(cut));
    }
    for (int i = 0; i < 6; ++i) {
        std::string mutated = text;
        for (int change = 0; change < 4; ++change) {
            const std::size_t at = position(random) % mutated.size();
            const std::string piece = random_string(random, alphabet, 1 + random() % 3);
            switch (random() % 3) {
            case 0:
                mutated.replace(at, piece.size(), piece);
                break;
            case 1:
                mutated.insert(at, piece);
                break;
            default:
                mutated.erase(at, piece.size());
                break;
            }
        }
        visit(mutated, name + " mutation " + std::to_string(i));
    }
}

} // namespace eposp::compiler::corpus
