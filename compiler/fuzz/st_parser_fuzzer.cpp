// libFuzzer entry point for the ST front end: any byte string must parse (or fail with
// diagnostics) without crashing, hanging or leaking, and its diagnostics must render.
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/parser.hpp"
#include "eposp/compiler/source_manager.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    eposp::compiler::SourceManager sources;
    const eposp::compiler::FileId file =
        sources.add("fuzz.st", std::string(reinterpret_cast<const char*>(data), size));
    eposp::compiler::Diagnostics diagnostics;
    eposp::compiler::parse(sources, file, diagnostics);
    eposp::compiler::render(diagnostics, sources);
    return 0;
}
