#pragma once

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <string>

namespace eposp::can::testing_support {

/// Names a table-driven test after the `name` field of its row.
template <typename Row>
std::string row_name(const testing::TestParamInfo<Row>& row) {
    return std::string(row.param.name);
}

/// A file path for the running test, in the temporary directory, removed afterwards.
class TempFile {
public:
    explicit TempFile(std::string_view extension) {
        const auto* test = testing::UnitTest::GetInstance()->current_test_info();
        path_ = std::filesystem::temp_directory_path() /
                (std::string("eposp-") + test->test_suite_name() + "-" + test->name() +
                 std::string(extension));
    }
    ~TempFile() {
        std::error_code ignored;
        std::filesystem::remove(path_, ignored);
    }
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;

    const std::filesystem::path& path() const { return path_; }

    std::string contents() const {
        std::ifstream in(path_, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }

private:
    std::filesystem::path path_;
};

} // namespace eposp::can::testing_support
