#include "eposp/test/test_directory.hpp"

#include <algorithm>
#include <cstdlib>
#include <gtest/gtest.h>
#include <map>
#include <stdexcept>
#include <string>

namespace eposp::test {
namespace {

std::string current_test_name() {
    const auto* test = testing::UnitTest::GetInstance()->current_test_info();
    std::string name = test == nullptr ? std::string("outside-a-test")
                                       : std::string(test->test_suite_name()) + "." + test->name();
    // Parameterised tests are named Prefix/Suite.Name/3.
    std::replace(name.begin(), name.end(), '/', '_');
    return name;
}

/// The directories made in this process, by test; a passing test's directory is removed when
/// the test ends.
class Directories : public testing::EmptyTestEventListener {
public:
    std::filesystem::path of_current_test() {
        const std::string name = current_test_name();
        if (const auto made = made_.find(name); made != made_.end()) {
            return made->second;
        }
        std::string pattern =
            (std::filesystem::temp_directory_path() / ("eposp-" + name + "-XXXXXX")).string();
        if (::mkdtemp(pattern.data()) == nullptr) {
            throw std::runtime_error("cannot create a test directory like " + pattern);
        }
        return made_.emplace(name, pattern).first->second;
    }

private:
    void OnTestEnd(const testing::TestInfo& test) override {
        const auto made = made_.find(current_test_name());
        if (made == made_.end()) {
            return;
        }
        if (test.result()->Passed()) {
            std::error_code ignored;
            std::filesystem::remove_all(made->second, ignored);
        }
        made_.erase(made);
    }

    std::map<std::string, std::filesystem::path> made_;
};

Directories& directories() {
    // GoogleTest owns its listeners: registered at the first use, it lives as long as the run.
    static Directories* const instance = [] {
        auto* directories = new Directories;
        testing::UnitTest::GetInstance()->listeners().Append(directories);
        return directories;
    }();
    return *instance;
}

} // namespace

std::filesystem::path test_directory() {
    return directories().of_current_test();
}

std::filesystem::path test_file(std::string_view name) {
    return test_directory() / name;
}

} // namespace eposp::test
