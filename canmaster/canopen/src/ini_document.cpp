#include "ini_document.hpp"

#include <cctype>
#include <fmt/format.h>

namespace eposp::canopen {
namespace {

bool printable_line(std::string_view line) {
    for (const char c : line) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 && c != '\t') {
            return false;
        }
    }
    return true;
}

} // namespace

std::string_view trim(std::string_view text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) {
        return {};
    }
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::string to_lower(std::string_view text) {
    std::string lower(text);
    for (char& c : lower) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return lower;
}

const IniDocument::Entry* IniDocument::Section::find(std::string_view key) const {
    const auto it = by_key_.find(to_lower(key));
    return it == by_key_.end() ? nullptr : &entries[it->second];
}

const IniDocument::Section* IniDocument::find(std::string_view section_name) const {
    const auto it = by_name_.find(to_lower(section_name));
    return it == by_name_.end() ? nullptr : &sections_[it->second];
}

std::string IniDocument::error_at(std::size_t line, std::string_view message) const {
    return fmt::format("{}:{}: error: {}", source_name_, line, message);
}

core::Result<IniDocument> IniDocument::parse(std::string_view text, std::string_view source_name) {
    IniDocument document;
    document.source_name_ = source_name;
    if (text.starts_with("\xEF\xBB\xBF")) {
        text.remove_prefix(3); // a UTF-8 byte order mark, as Windows editors write it
    }
    std::size_t line_number = 0;
    while (!text.empty()) {
        ++line_number;
        const auto end = text.find('\n');
        std::string_view line = text.substr(0, end);
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
        if (line.ends_with('\r')) {
            line.remove_suffix(1);
        }
        if (!printable_line(line)) {
            return core::Error{document.error_at(line_number, "control character in the line")};
        }
        line = trim(line);
        if (line.empty() || line.starts_with(';')) {
            continue;
        }
        if (line.starts_with('[')) {
            if (!line.ends_with(']')) {
                return core::Error{document.error_at(line_number, "section header without ']'")};
            }
            const std::string name(trim(line.substr(1, line.size() - 2)));
            if (name.empty()) {
                return core::Error{document.error_at(line_number, "section without a name")};
            }
            const auto [it, inserted] =
                document.by_name_.emplace(to_lower(name), document.sections_.size());
            if (!inserted) {
                return core::Error{document.error_at(
                    line_number, fmt::format("section [{}] repeats the one of line {}", name,
                                             document.sections_[it->second].line))};
            }
            Section& section = document.sections_.emplace_back();
            section.name = name;
            section.line = line_number;
            continue;
        }
        const auto equals = line.find('=');
        if (equals == std::string_view::npos) {
            return core::Error{document.error_at(
                line_number, fmt::format("'{}' is neither [section] nor key=value", line))};
        }
        if (document.sections_.empty()) {
            return core::Error{document.error_at(line_number, "key=value before any [section]")};
        }
        const std::string key(trim(line.substr(0, equals)));
        if (key.empty()) {
            return core::Error{document.error_at(line_number, "key=value without a key")};
        }
        Section& section = document.sections_.back();
        const auto [it, inserted] = section.by_key_.emplace(to_lower(key), section.entries.size());
        if (!inserted) {
            return core::Error{document.error_at(
                line_number, fmt::format("{} repeats the one of line {} in [{}]", key,
                                         section.entries[it->second].line, section.name))};
        }
        section.entries.push_back(
            Entry{key, std::string(trim(line.substr(equals + 1))), line_number});
    }
    return document;
}

} // namespace eposp::canopen
