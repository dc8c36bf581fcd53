#include "diagnostic_example.hpp"

#include "eposp/compiler/compiler.hpp"

namespace eposp::compiler::test {

CompiledExample compile_example(std::string_view example) {
    constexpr std::string_view kLibraryMarker = "(* in a linked library: *)\n";
    const std::size_t marker = example.find(kLibraryMarker);
    SourceManager sources;
    const std::vector<FileId> files = {
        sources.add("example.st", std::string(example.substr(0, marker)))};
    std::vector<FileId> libraries;
    if (marker != std::string_view::npos) {
        libraries.push_back(
            sources.add("library.st", std::string(example.substr(marker + kLibraryMarker.size()))));
    }
    Diagnostics diagnostics;
    compile(sources, files, diagnostics, libraries);
    CompiledExample compiled;
    for (const Diagnostic& diagnostic : diagnostics.all()) {
        compiled.codes.push_back(diagnostic.code);
    }
    compiled.rendered = render(diagnostics, sources);
    return compiled;
}

} // namespace eposp::compiler::test
