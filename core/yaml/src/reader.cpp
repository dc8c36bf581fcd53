#include "eposp/yaml/reader.hpp"

#include <fstream>
#include <set>
#include <sstream>
#include <vector>
#include <yaml-cpp/eventhandler.h>

namespace eposp::yaml {

namespace {

/// Where each document of a stream starts; the rest of the events are not needed.
class DocumentStarts : public YAML::EventHandler {
public:
    std::vector<YAML::Mark> marks;

    void OnDocumentStart(const YAML::Mark& mark) override { marks.push_back(mark); }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  const std::string&) override {}
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                         YAML::EmitterStyle::value) override {}
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                    YAML::EmitterStyle::value) override {}
    void OnMapEnd() override {}
};

} // namespace

void Reader::fail(const YAML::Node& node, const std::string& message) const {
    fail(node.Mark(), message);
}

void Reader::fail(const YAML::Mark& mark, const std::string& message) const {
    throw FileError{
        fmt::format("{}:{}:{}: error: {}", source_, mark.line + 1, mark.column + 1, message)};
}

YAML::Node load_one_document(const Reader& in, std::string_view text) {
    std::istringstream stream{std::string(text)};
    YAML::Parser parser(stream);
    DocumentStarts documents;
    // Two documents at most: yaml-cpp's LoadAll never ends on some malformed input (a fuzz
    // finding), where each further "document" consumes nothing.
    if (parser.HandleNextDocument(documents) && parser.HandleNextDocument(documents)) {
        in.fail(documents.marks.size() > 1 ? documents.marks[1] : YAML::Mark{},
                "a second YAML document: a file holds one");
    }
    return YAML::Load(std::string(text));
}

void Reader::each_key(
    const YAML::Node& node, std::string_view section,
    const std::map<std::string, std::function<void(const YAML::Node&)>>& readers) {
    if (!node.IsMap()) {
        fail(node, fmt::format("'{}' must be a mapping", section));
    }
    std::set<std::string> seen;
    for (const auto& entry : node) {
        const auto key = entry.first.as<std::string>();
        if (!seen.insert(key).second) {
            fail(entry.first, fmt::format("duplicate key '{}' in '{}'", key, section));
        }
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
