// A formal call of a standard function (`LIMIT(MN := 0, IN := v, MX := 10)`) may name its inputs
// in any order; code generation takes them in the order of the signature, by the input names of
// the manifest (vm/stdlib/manifest.hpp), as the typing stage does (types::standard_arguments).

#include "eposp/compiler/sema/symbol.hpp"
#include "eposp/vm/stdlib/manifest.hpp"
#include "pou_generator.hpp"

namespace eposp::compiler::codegen {

std::optional<Arguments> PouGenerator::in_parameter_order(const std::string& name,
                                                          const Arguments& arguments) {
    const bool formal = std::any_of(arguments.begin(), arguments.end(),
                                    [](const ast::Argument* a) { return a->name.has_value(); });
    if (!formal) {
        return arguments;
    }
    const vm::stdlib::StandardFunction* function = vm::stdlib::find_standard_function(name);
    Arguments ordered(arguments.size(), nullptr);
    for (const ast::Argument* argument : arguments) {
        if (!argument->name) {
            program_.refused_by_checks(DiagnosticCode::E0415); // checks/call_forms.cpp
            return std::nullopt;
        }
        const auto position =
            vm::stdlib::input_position(function, sema::fold_case(argument->name->name));
        if (!position || *position >= ordered.size()) {
            program_.refused_by_checks(DiagnosticCode::E0210); // types::standard_arguments
            return std::nullopt;
        }
        if (ordered[*position] != nullptr) {
            program_.refused_by_checks(DiagnosticCode::E0414); // checks/repeated_parameters.cpp
            return std::nullopt;
        }
        ordered[*position] = argument;
    }
    return ordered;
}

} // namespace eposp::compiler::codegen
