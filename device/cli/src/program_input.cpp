#include "program_input.hpp"

#include "eposp/compiler/diagnostics_json.hpp"
#include "eposp/device/program_compiler.hpp"
#include "eposp/vm/image_format.hpp"
#include "eposp/vm/verifier.hpp"
#include "file_checks.hpp"
#include "terminal_text.hpp"

#include <fmt/format.h>
#include <fstream>
#include <iterator>

namespace eposp::device::cli {
namespace {

bool is_image_file(const std::string& path) {
    return path.ends_with(".epx");
}

core::Result<vm::Image> read_image_file(const std::string& path) {
    if (auto problem = input_file_problem(path, "a program image")) {
        return core::Error{*problem};
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return core::Error{"cannot open " + path};
    }
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                          std::istreambuf_iterator<char>()};
    auto image = vm::read_image(bytes);
    if (!image) {
        return core::Error{path + ": " + image.error()};
    }
    // Verified here, not only when loaded, so that no command (dump too) shows a malformed
    // image, and the error names the file.
    if (auto defect = vm::verify(*image)) {
        return core::Error{path + ": " + defect->message};
    }
    return image;
}

} // namespace

void add_error_format_option(CLI::App& command, ErrorFormat& format) {
    command
        .add_option("--error-format", format,
                    "How compiler diagnostics are printed: human (default) or json, one object a "
                    "line")
        ->transform(CLI::CheckedTransformer(
            std::map<std::string, ErrorFormat>{{"human", ErrorFormat::Human},
                                               {"json", ErrorFormat::Json}},
            CLI::ignore_case));
}

namespace {

// The files of `paths`, loaded into `sources`; the error says which cannot be compiled.
core::Result<std::vector<compiler::FileId>> load_sources(const std::vector<std::string>& paths,
                                                         compiler::SourceManager& sources) {
    std::vector<compiler::FileId> files;
    for (const std::string& path : paths) {
        if (auto problem = input_file_problem(path, "a Structured Text source")) {
            return core::Error{*problem};
        }
        // An image under another name is still no source: its magic says what it is.
        if (is_image_file(path) || is_of_kind(path, OutputKind::ProgramImage)) {
            return core::Error{path + " is a program image, not Structured Text source (eposp "
                                      "dump shows what it holds)"};
        }
        auto file = sources.load(path);
        if (!file) {
            return core::Error{file.error()};
        }
        files.push_back(*file);
    }
    return files;
}

void print_diagnostics(const compiler::Diagnostics& diagnostics,
                       const compiler::SourceManager& sources, ErrorFormat format) {
    if (format == ErrorFormat::Json) {
        // On stdout, apart from the command's own messages, for a tool to read; escaped, so no
        // terminal codes reach it.
        fmt::print("{}", compiler::render_json(diagnostics, sources));
    } else {
        fmt::print(stderr, "{}", terminal_text(compiler::render(diagnostics, sources)));
    }
}

core::Error has_errors(const std::vector<std::string>& paths) {
    return core::Error{
        fmt::format("{} has errors", paths.size() == 1 ? paths.front() : "the program")};
}

} // namespace

core::Result<vm::Image> compile_sources(const std::vector<std::string>& paths, ErrorFormat format) {
    compiler::SourceManager sources;
    compiler::Diagnostics diagnostics;
    const auto files = load_sources(paths, sources);
    if (!files) {
        return core::Error{files.error()};
    }
    auto image = compile_program(sources, *files, diagnostics);
    print_diagnostics(diagnostics, sources, format);
    if (!image) {
        return has_errors(paths);
    }
    return std::move(*image);
}

core::Result<bool> check_sources(const std::vector<std::string>& paths, ErrorFormat format) {
    compiler::SourceManager sources;
    compiler::Diagnostics diagnostics;
    const auto files = load_sources(paths, sources);
    if (!files) {
        return core::Error{files.error()};
    }
    const bool ok = check_program(sources, *files, diagnostics);
    print_diagnostics(diagnostics, sources, format);
    if (!ok) {
        return has_errors(paths);
    }
    return true;
}

core::Result<vm::Image> program_image(const std::vector<std::string>& paths, ErrorFormat format) {
    if (paths.size() == 1 && is_image_file(paths.front())) {
        return read_image_file(paths.front());
    }
    for (const std::string& path : paths) {
        if (is_image_file(path)) {
            return core::Error{"a program image (" + path + ") comes alone, not with other files"};
        }
    }
    return compile_sources(paths, format);
}

} // namespace eposp::device::cli
