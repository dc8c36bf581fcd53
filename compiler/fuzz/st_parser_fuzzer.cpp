// libFuzzer entry point for the ST compiler: any byte string must compile (or fail with
// diagnostics) without crashing, hanging or leaking, its diagnostics must render, and every
// image it produces must pass the VM's verifier.
#include "eposp/compiler/compiler.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/source_manager.hpp"
#include "eposp/vm/verifier.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    eposp::compiler::SourceManager sources;
    const eposp::compiler::FileId file =
        sources.add("fuzz.st", std::string(reinterpret_cast<const char*>(data), size));
    eposp::compiler::Diagnostics diagnostics;
    const auto image = eposp::compiler::compile(sources, {&file, 1}, diagnostics);
    eposp::compiler::render(diagnostics, sources);
    if (image && eposp::vm::verify(*image)) {
        std::abort(); // code generation produced an image the VM refuses
    }
    return 0;
}
