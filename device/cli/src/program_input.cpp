#include "program_input.hpp"

#include "eposp/device/program_compiler.hpp"
#include "eposp/vm/image_format.hpp"

#include <fmt/format.h>
#include <fstream>
#include <iterator>

namespace eposp::device::cli {
namespace {

bool is_image_file(const std::string& path) {
    return path.ends_with(".epx");
}

core::Result<vm::Image> read_image_file(const std::string& path) {
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
    return image;
}

} // namespace

core::Result<vm::Image> compile_sources(const std::vector<std::string>& paths) {
    compiler::SourceManager sources;
    compiler::Diagnostics diagnostics;
    std::vector<compiler::FileId> files;
    for (const std::string& path : paths) {
        auto file = sources.load(path);
        if (!file) {
            return core::Error{file.error()};
        }
        files.push_back(*file);
    }
    auto image = compile_program(sources, files, diagnostics);
    fmt::print(stderr, "{}", compiler::render(diagnostics, sources));
    if (!image) {
        return core::Error{
            fmt::format("{} has errors", paths.size() == 1 ? paths.front() : "the program")};
    }
    return std::move(*image);
}

core::Result<vm::Image> program_image(const std::vector<std::string>& paths) {
    if (paths.size() == 1 && is_image_file(paths.front())) {
        return read_image_file(paths.front());
    }
    for (const std::string& path : paths) {
        if (is_image_file(path)) {
            return core::Error{"a program image (" + path + ") comes alone, not with other files"};
        }
    }
    return compile_sources(paths);
}

} // namespace eposp::device::cli
