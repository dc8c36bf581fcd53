#pragma once

// What a call expression calls, as the call checks see it (call_forms.cpp, in_out_connections.cpp,
// repeated_parameters.cpp): the callee's name as the program resolves it and the instance type an
// FB call's callee has, so that a call the typing stage could not type is still checked.

#include "eposp/compiler/ast/expressions.hpp"
#include "eposp/compiler/types/typed_program.hpp"

#include <string>

namespace eposp::compiler::checks {

struct Callee {
    enum class Kind {
        Function,         ///< a user or library FUNCTION: `frame` holds its parameters
        Instance,         ///< an FB instance or a PROGRAM called by name: `frame` is its instance
        StandardFunction, ///< a standard function or conversion compiled inline: `name` upper case
        Unknown,          ///< not a call the program can make (the names' or types' error)
    };
    Kind kind = Kind::Unknown;
    const ast::Pou* pou = nullptr;
    const sema::Type* frame = nullptr;
    std::string name{};
};

Callee callee_of(types::TypedProgram& program, const ast::CallExpression& call);

/// `EN := c` or `ENO => v` (6.6.1.2.2), whichever form it is written in.
bool is_enable_argument(const ast::Argument& argument);

} // namespace eposp::compiler::checks
