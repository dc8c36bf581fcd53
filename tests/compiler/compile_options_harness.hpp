#pragma once

// Compiles files (and linked libraries) with CompileOptions, then links the image with the
// standard library and a virtual clock and runs its first task: what the tests of
// compile_options.hpp need beyond StProgram, which takes no options.

#include "eposp/compiler/compiler.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/native.hpp"
#include "eposp/vm/program.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace eposp::compiler::test {

class OptionsCompilation {
public:
    OptionsCompilation();

    /// Adds a program file or a linked library (compile()'s `libraries`); its id for options.
    FileId add(const std::string& path, const std::string& text);
    FileId add_library(const std::string& path, const std::string& text);

    /// Compiles what was added with `options`; false with errors() saying why.
    bool compile(const CompileOptions& options = {});
    const std::string& errors() const { return errors_; }
    /// The image of the last successful compile().
    const vm::Image& image() const { return *image_; }
    /// Paths of the image's symbols, names of its POUs and of its native imports.
    std::vector<std::string> symbols() const;
    std::vector<std::string> pous() const;
    std::vector<std::string> imports() const;

    /// Links the image and runs `n` scans of task 0; false (errors() says why) on a link error
    /// or a fault.
    bool run(int n);
    /// An integer, BOOL (0/1) or enumeration variable of 1, 2 or 4 bytes after run().
    std::int64_t get(const std::string& path) const;

    SourceManager& sources() { return sources_; }

private:
    SourceManager sources_;
    std::vector<FileId> files_;
    std::vector<FileId> libraries_;
    std::optional<vm::Image> image_;
    std::string errors_;
    std::int64_t now_ns_ = 0;
    vm::NativeRegistry natives_;
    std::optional<vm::Program> program_;
    std::optional<vm::Machine> machine_;
};

} // namespace eposp::compiler::test
