#include "eposp/plcopen/block_interface.hpp"

#include <fmt/format.h>

namespace eposp::plcopen {

namespace {

std::string_view keyword(Section section) {
    switch (section) {
    case Section::InOut:
        return "VAR_IN_OUT";
    case Section::Input:
        return "VAR_INPUT";
    case Section::Output:
        return "VAR_OUTPUT";
    case Section::Var:
        break;
    }
    return "VAR";
}

} // namespace

std::string BlockInterface::declaration() const {
    std::string text = fmt::format("FUNCTION_BLOCK {}\n", name);
    // The variables stay in order: a new section opens whenever the section changes.
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const BlockVariable& variable = variables[i];
        if (i == 0 || variables[i - 1].section != variable.section) {
            text += fmt::format("  {}\n", keyword(variable.section));
        }
        text += fmt::format("    {} : {};\n", variable.name, variable.type);
        if (i + 1 == variables.size() || variables[i + 1].section != variable.section) {
            text += "  END_VAR\n";
        }
    }
    return text + "END_FUNCTION_BLOCK\n";
}

std::vector<vm::Scalar> BlockInterface::fields() const {
    std::vector<vm::Scalar> scalars;
    for (const BlockVariable& variable : variables) {
        scalars.push_back(variable.scalar);
    }
    return scalars;
}

} // namespace eposp::plcopen
