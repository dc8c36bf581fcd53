// E0410: a constant stored into a subrange variable or parameter lies inside its bounds
// (IEC 61131-3 ed. 3, 6.4.4.4); other values are checked at run time by code generation.

#include "../types/constant_folder.hpp"
#include "pou_checks.hpp"

#include <fmt/format.h>

namespace eposp::compiler::checks {

void check_constant_subranges(const ProgramUnderCheck& check) {
    for (const types::Store& store : check.program.stores()) {
        if (!check.includes(store.pou) || !store.into->range) {
            continue;
        }
        const auto value = check.program.constants().fold_integer(*store.value);
        if (value && !store.into->range->contains(*value)) {
            check.diagnostics.error(DiagnosticCode::E0410, store.value->range,
                                    fmt::format("the value {} is outside {} ({}..{})", *value,
                                                store.into->name, store.into->range->lower,
                                                store.into->range->upper));
        }
    }
}

} // namespace eposp::compiler::checks
