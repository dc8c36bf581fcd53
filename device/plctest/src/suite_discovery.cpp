#include "eposp/compiler/ast/calling_pous.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/parser.hpp"
#include "eposp/plctest/suites.hpp"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <vector>

namespace eposp::plctest {
namespace {

constexpr std::string_view kMockAttribute = "{attribute 'mock' := '";
constexpr std::string_view kNetworkAttribute = "{attribute 'network' := '";

std::string_view trimmed(std::string_view text) {
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) {
        return {};
    }
    return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string_view> lines_of(std::string_view text) {
    std::vector<std::string_view> lines;
    for (std::size_t begin = 0; begin <= text.size();) {
        const std::size_t end = std::min(text.find('\n', begin), text.size());
        lines.push_back(text.substr(begin, end - begin));
        begin = end + 1;
    }
    return lines;
}

bool is_identifier(std::string_view name) {
    return !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
           std::ranges::all_of(name, [](char c) {
               return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
           });
}

std::string upper_case(std::string_view name) {
    std::string upper(name);
    std::ranges::transform(upper, upper.begin(),
                           [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return upper;
}

} // namespace

core::Result<SuiteAttributes> suite_attributes(std::string_view text, std::uint32_t line) {
    const std::vector<std::string_view> lines = lines_of(text);
    SuiteAttributes attributes;
    for (std::uint32_t number = line - 1; number >= 1 && number <= lines.size(); --number) {
        const std::string_view content = trimmed(lines[number - 1]);
        if (content.empty() || content.starts_with("//") ||
            (content.starts_with("(*") && content.ends_with("*)"))) {
            continue;
        }
        if (!content.starts_with("{")) {
            break; // the end of what precedes the declaration
        }
        const bool mock = content.starts_with(kMockAttribute);
        const bool network = content.starts_with(kNetworkAttribute);
        if (!mock && !network) {
            continue; // another pragma
        }
        const std::string_view value =
            content.substr(mock ? kMockAttribute.size() : kNetworkAttribute.size());
        const auto end = value.find("'}");
        if (network) {
            if (end == std::string_view::npos || end == 0) {
                return core::Error{fmt::format("{}: error: a network attribute reads {{attribute "
                                               "'network' := 'machine.yaml'}}",
                                               number)};
            }
            attributes.network = std::string(value.substr(0, end));
            continue;
        }
        const auto arrow = value.find("=>");
        const std::string_view original = trimmed(value.substr(0, std::min(arrow, end)));
        const std::string_view replacement =
            arrow < end ? trimmed(value.substr(arrow + 2, end - arrow - 2)) : std::string_view();
        if (end == std::string_view::npos || !is_identifier(original) ||
            !is_identifier(replacement)) {
            return core::Error{
                fmt::format("{}: error: a mock attribute reads {{attribute 'mock' := 'FB_Name => "
                            "FB_Double'}}",
                            number)};
        }
        attributes.mocks.emplace(original, replacement);
    }
    return attributes;
}

std::string TestSources::file_of(std::string_view pou) const {
    const auto found = pou_files.find(upper_case(pou));
    return found == pou_files.end() ? std::string() : found->second;
}

core::Result<TestSources> discover_suites(const std::vector<std::string>& paths,
                                          const DiagnosticsObserver& observe) {
    compiler::SourceManager sources;
    compiler::Diagnostics diagnostics;
    TestSources found{.paths = paths, .suites = {}, .pou_files = {}};
    std::vector<Suite>& suites = found.suites;
    for (const std::string& path : paths) {
        auto file = sources.load(path);
        if (!file) {
            return core::Error{file.error()};
        }
        const compiler::ast::CompilationUnit unit = compiler::parse(sources, *file, diagnostics);
        for (const compiler::ast::Pou& pou : unit.pous) {
            found.pou_files.emplace(upper_case(pou.name.name), path);
        }
        for (const compiler::ast::CallingPou& pou : compiler::ast::pous_calling(unit, "TEST")) {
            const std::uint32_t line = pou.range.begin.line;
            auto attributes = suite_attributes(sources.text(*file), line);
            if (!attributes) {
                return core::Error{path + ":" + attributes.error()};
            }
            std::optional<std::string> network;
            if (attributes->network) {
                network = (std::filesystem::path(path).parent_path() / *attributes->network)
                              .lexically_normal()
                              .string();
            }
            suites.push_back(
                {pou.name, pou.kind, {path, line}, std::move(attributes->mocks), network});
        }
    }
    if (observe) {
        observe(diagnostics, sources);
    }
    if (diagnostics.has_errors()) {
        return core::Error{compiler::render(diagnostics, sources)};
    }
    return found;
}

} // namespace eposp::plctest
