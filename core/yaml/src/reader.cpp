#include "eposp/yaml/reader.hpp"

#include <fstream>
#include <sstream>

namespace eposp::yaml {

void Reader::fail(const YAML::Node& node, const std::string& message) const {
    const YAML::Mark mark = node.Mark();
    throw FileError{
        fmt::format("{}:{}:{}: error: {}", source_, mark.line + 1, mark.column + 1, message)};
}

void Reader::each_key(
    const YAML::Node& node, std::string_view section,
    const std::map<std::string, std::function<void(const YAML::Node&)>>& readers) {
    if (!node.IsMap()) {
        fail(node, fmt::format("'{}' must be a mapping", section));
    }
    for (const auto& entry : node) {
        const auto key = entry.first.as<std::string>();
        const auto reader = readers.find(key);
        if (reader == readers.end()) {
            fail(entry.first, fmt::format("unknown key '{}' in '{}'", key, section));
        }
        reader->second(entry.second);
    }
}

core::Result<std::string> read_text(const std::filesystem::path& path) {
    std::error_code error;
    std::ifstream file(path);
    if (!file || std::filesystem::is_directory(path, error)) {
        return core::Error{fmt::format("{}: error: cannot read the file", path.string())};
    }
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

} // namespace eposp::yaml
