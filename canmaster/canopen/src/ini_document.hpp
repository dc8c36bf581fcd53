#pragma once

#include "eposp/core/result.hpp"

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::canopen {

/// An INI file as CiA 306 (4.2) uses it for EDS and DCF files: [sections] of key=value lines,
/// names compared without regard to case, ';' comment lines, blank lines, LF or CR LF.
///
/// Our own reader rather than Boost.PropertyTree's INI parser: that one reports errors by
/// exception, compares keys with case, and forgets line numbers once parsed, while an EDS import
/// must name the line of a bad value found long after parsing, and must never throw on input
/// that a fuzzer or a user made up.
class IniDocument {
public:
    struct Entry {
        std::string key; ///< as written
        std::string value;
        std::size_t line = 0;
    };
    struct Section {
        std::string name; ///< as written, without the brackets
        std::size_t line = 0;
        std::vector<Entry> entries;

        const Entry* find(std::string_view key) const;

    private:
        friend class IniDocument;
        std::map<std::string, std::size_t> by_key_; // lower-case key -> index in entries
    };

    /// Errors name the line: "`source_name`:12: error: ...". A repeated section or key is an
    /// error: it would leave the file's meaning to the reader.
    static core::Result<IniDocument> parse(std::string_view text, std::string_view source_name);

    const Section* find(std::string_view section_name) const;
    const std::vector<Section>& sections() const { return sections_; }
    const std::string& source_name() const { return source_name_; }

    /// "`source_name`:`line`: error: `message`", the form every import error takes.
    std::string error_at(std::size_t line, std::string_view message) const;

private:
    std::string source_name_;
    std::vector<Section> sections_;
    std::map<std::string, std::size_t> by_name_; // lower-case name -> index in sections_
};

/// `text` in lower case (ASCII), for comparing names the way INI files do.
std::string to_lower(std::string_view text);
/// `text` without the blanks and tabs around it.
std::string_view trim(std::string_view text);

} // namespace eposp::canopen
