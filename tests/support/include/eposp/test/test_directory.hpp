#pragma once

#include <filesystem>
#include <string_view>

namespace eposp::test {

/// A directory of the running test's own, created empty at the first call in the test. Its name
/// holds the test's name and a unique suffix (mkdtemp), so tests never share files: not when
/// ctest runs them in parallel or in random order, and not when two copies of the suite run at
/// once. It is removed when the test passes and kept for inspection when it fails.
std::filesystem::path test_directory();

/// `test_directory() / name`.
std::filesystem::path test_file(std::string_view name);

} // namespace eposp::test
