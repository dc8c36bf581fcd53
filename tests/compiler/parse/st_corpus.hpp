#pragma once

// The ST inputs the front end's equivalence tests (lexer_equivalence_test.cpp,
// parser_equivalence_test.cpp) run their implementation and its oracle on.

#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::compiler::corpus {

/// Every `.st` file of tests/, examples/ and the benchmarks' folder beside the repository.
std::vector<std::filesystem::path> st_files();
std::string read_file(const std::filesystem::path& path);

/// `bytes` as the parser reads them: UTF-8 as it is, anything else as Windows-1252.
std::string as_text(const std::string& bytes);

/// The characters that make tokens differ: openers and closers of comments, pragmas and
/// strings, '$' escapes, '#' and the letters of literal prefixes, operators, line ends.
constexpr std::string_view kInteresting =
    "(*)/{}'\"$#%._-+:=<>^&[],;0123456789eEtTdDlLiIxX_ab\n\r\t ";

std::string random_string(std::mt19937& random, std::string_view alphabet, std::size_t length);
std::string mixed_case(std::mt19937& random, std::string word);

/// Six truncations of `text` and six mutations (pieces of `alphabet` replaced, inserted and
/// erased at four places), each with its name.
void for_each_variant(const std::string& text, const std::string& name, std::mt19937& random,
                      std::string_view alphabet,
                      const std::function<void(const std::string&, const std::string&)>& visit);

} // namespace eposp::compiler::corpus
