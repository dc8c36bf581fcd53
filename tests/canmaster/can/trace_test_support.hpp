#pragma once

#include "eposp/test/test_directory.hpp"

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

/// A file path for the running test, in the test's own directory.
class TempFile {
public:
    explicit TempFile(std::string_view extension)
        : path_(test::test_file("trace" + std::string(extension))) {}

    const std::filesystem::path& path() const { return path_; }

    std::string contents() const {
        std::ifstream in(path_, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }

private:
    std::filesystem::path path_;
};

} // namespace eposp::can::testing_support
