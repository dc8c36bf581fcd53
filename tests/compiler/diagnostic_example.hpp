// Compiles a piece of ST as `eposp explain` shows it (diagnostic_catalogue.def): the part after a
// line `(* in a linked library: *)` is a linked library, as the host's declarations are.
#pragma once

#include "eposp/compiler/diagnostics.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace eposp::compiler::test {

struct CompiledExample {
    std::vector<DiagnosticCode> codes; // of every diagnostic, in order
    std::string rendered;
};

CompiledExample compile_example(std::string_view example);

} // namespace eposp::compiler::test
