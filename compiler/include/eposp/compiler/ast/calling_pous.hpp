#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace eposp::compiler::ast {

/// A FUNCTION_BLOCK or PROGRAM found by pous_calling().
struct CallingPou {
    std::string name; ///< as declared
    PouKind kind = PouKind::Program;
    FileId file = 0;   ///< the file that declares it
    SourceRange range; ///< the whole declaration; `range.begin.line` is its first line
};

/// The FUNCTION_BLOCKs and PROGRAMs of `unit`, in source order, whose body calls the function
/// `function` anywhere: in a statement, a nested statement, an expression or another call's
/// argument. IEC names compare case-insensitively. `eposp test` finds its suites this way: the
/// POUs that call `TEST(...)`.
std::vector<CallingPou> pous_calling(const CompilationUnit& unit, std::string_view function);

} // namespace eposp::compiler::ast
