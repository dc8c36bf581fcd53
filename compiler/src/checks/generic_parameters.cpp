// E0416: a parameter of type ANY (or another generic type) is a native function's alone: a
// FUNCTION without statements in a linked library, which the host implements in C++ with the
// argument's type descriptor (docs/runtime.md, "Native functions"). Compiled ST has no code for
// a value of unknown type.

#include "pou_checks.hpp"

#include <fmt/format.h>

namespace eposp::compiler::checks {

void check_generic_parameters(const PouUnderCheck& check) {
    if (check.pou.kind != ast::PouKind::Function) {
        return;
    }
    const sema::Type* frame = check.program.types().frame(check.pou);
    if (frame == nullptr) {
        return;
    }
    for (const sema::Field& field : frame->fields) {
        if (field.declaration != nullptr && field.type->generic) {
            check.diagnostics.error(
                DiagnosticCode::E0416, field.declaration->type.range,
                fmt::format("'{}' is ANY, which only a native function takes: a FUNCTION "
                            "without statements in a linked library",
                            field.name));
        }
    }
}

} // namespace eposp::compiler::checks
