#include "eposp/compiler/source_manager.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace eposp::compiler {

FileId SourceManager::add(std::string path, std::string text) {
    File file{std::move(path), std::move(text), {0}};
    for (std::size_t i = 0; i < file.text.size(); ++i) {
        if (file.text[i] == '\n') {
            file.line_starts.push_back(i + 1);
        }
    }
    files_.push_back(std::move(file));
    return static_cast<FileId>(files_.size() - 1);
}

core::Result<FileId> SourceManager::load(const std::string& path) {
    std::ifstream stream(path, std::ios::binary);
    if (!stream) {
        return core::Error{"cannot open '" + path + "': " + std::strerror(errno)};
    }
    std::ostringstream text;
    text << stream.rdbuf();
    if (stream.bad()) {
        return core::Error{"cannot read '" + path + "'"};
    }
    return add(path, std::move(text).str());
}

const std::string& SourceManager::path(FileId file) const {
    return files_.at(file).path;
}

const std::string& SourceManager::text(FileId file) const {
    return files_.at(file).text;
}

std::string_view SourceManager::line(FileId file, std::uint32_t line_number) const {
    const File& source = files_.at(file);
    if (line_number == 0 || line_number > source.line_starts.size()) {
        return {};
    }
    const std::size_t begin = source.line_starts[line_number - 1];
    std::size_t end = line_number < source.line_starts.size() ? source.line_starts[line_number] - 1
                                                              : source.text.size();
    if (end > begin && source.text[end - 1] == '\r') {
        --end;
    }
    return std::string_view(source.text).substr(begin, end - begin);
}

} // namespace eposp::compiler
