#pragma once

#include "eposp/compiler/source_location.hpp"
#include "eposp/core/result.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace eposp::compiler {

/// Owns the text of every source file of a compilation, so that diagnostics can quote any line
/// of any file long after parsing.
class SourceManager {
public:
    /// Adds text under a display path (used in diagnostics) and returns its id.
    FileId add(std::string path, std::string text);
    /// Reads a file from disk; the error names the path and the reason.
    core::Result<FileId> load(const std::string& path);

    const std::string& path(FileId file) const;
    const std::string& text(FileId file) const;
    /// The text of a 1-based line without its line terminator; empty past the end.
    std::string_view line(FileId file, std::uint32_t line_number) const;
    std::size_t file_count() const { return files_.size(); }

private:
    struct File {
        std::string path;
        std::string text;
        std::vector<std::size_t> line_starts;
    };
    std::vector<File> files_;
};

} // namespace eposp::compiler
