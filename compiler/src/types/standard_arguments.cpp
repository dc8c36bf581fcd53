// The inputs of a standard function call in the order of its signature, by the formal input
// names of the manifest (vm/stdlib/manifest.hpp).

#include "eposp/compiler/sema/symbol.hpp"
#include "eposp/compiler/types/typed_program.hpp"
#include "eposp/vm/stdlib/manifest.hpp"

namespace eposp::compiler::types {

std::vector<const ast::Argument*> standard_arguments(std::string_view name,
                                                     const ast::CallExpression& call) {
    const vm::stdlib::StandardFunction* function = vm::stdlib::find_standard_function(name);
    std::vector<const ast::Argument*> result;
    for (const ast::Argument& argument : call.arguments) {
        if (!argument.name) {
            result.push_back(&argument);
            continue;
        }
        const std::string input = sema::fold_case(argument.name->name);
        if (input == "EN" || input == "ENO") {
            continue;
        }
        const auto at = vm::stdlib::input_position(function, input);
        if (!at) {
            result.push_back(nullptr);
            continue;
        }
        if (result.size() <= *at) {
            result.resize(*at + 1, nullptr);
        }
        result[*at] = &argument;
    }
    return result;
}

} // namespace eposp::compiler::types
