// E0420: a located variable (`x AT %IW4 : INT`, IEC 61131-3 ed. 3, 6.5.5) and a direct address
// used in code fit their address: an elementary variable, BOOL on a bit (%IX<byte>.<bit>), one
// byte on %IB, two on %IW, four on %ID, eight on %IL; an address in code is complete (not %I*).
// The variables bound to the process image are those of globals and of PROGRAMs.

#include "located_variables.hpp"

#include "eposp/vm/scalar.hpp"
#include "pou_checks.hpp"

#include <fmt/format.h>

namespace eposp::compiler::checks {
namespace {

void check_address_in_code(const ast::DirectAddress& address, types::TypedProgram& program,
                           Diagnostics& diagnostics) {
    if (address.path.empty()) {
        diagnostics.error(DiagnosticCode::E0420, address.range,
                          "an address used in code must be complete (not %I*)");
    } else if (auto mismatch = location_mismatch(
                   address, program.types().elementary(direct_address_type(address.size)))) {
        diagnostics.error(DiagnosticCode::E0420, address.range, std::move(*mismatch));
    }
}

// Located variables, and direct addresses an access path names.
void check_declarations(const std::vector<ast::DeclarationSection>& sections,
                        types::TypedProgram& program, Diagnostics& diagnostics) {
    for (const ast::DeclarationSection& section : sections) {
        if (const auto* access = std::get_if<ast::AccessSection>(&section)) {
            for (const ast::AccessDeclaration& path : access->paths) {
                if (const auto* address = std::get_if<ast::DirectAddress>(&path.path)) {
                    check_address_in_code(*address, program, diagnostics);
                }
            }
            continue;
        }
        for (const ast::VariableDeclaration& declaration :
             std::get<ast::VarSection>(section).variables) {
            const sema::Type* type =
                declaration.address ? program.types().resolve(declaration.type) : nullptr;
            if (type == nullptr) {
                continue;
            }
            if (auto mismatch = location_mismatch(*declaration.address, *type)) {
                diagnostics.error(DiagnosticCode::E0420, declaration.address->range,
                                  std::move(*mismatch));
            }
        }
    }
}

} // namespace

std::optional<std::string> location_mismatch(const ast::DirectAddress& address,
                                             const sema::Type& type) {
    if (address.path.empty()) {
        return std::nullopt; // `%I*`: bound in the configuration (not supported yet)
    }
    if (!sema::is_scalar(type)) {
        return "only elementary variables can be located";
    }
    if (address.size == ast::DirectAddress::Size::None ||
        address.size == ast::DirectAddress::Size::Bit) {
        if (address.path.size() != 2 || address.path[1] > 7 || !sema::is_bool(type)) {
            return "a bit address is %IX<byte>.<bit> on a BOOL";
        }
        return std::nullopt;
    }
    const std::uint32_t unit = direct_address_unit(address.size);
    if (vm::scalar_size(sema::scalar_of(type)) != unit) {
        return fmt::format("a {}-byte address cannot hold a {}", unit, type.name);
    }
    return std::nullopt;
}

ast::ElementaryType direct_address_type(ast::DirectAddress::Size size) {
    using Size = ast::DirectAddress::Size;
    switch (size) {
    case Size::Byte:
        return ast::ElementaryType::Byte;
    case Size::Word:
        return ast::ElementaryType::Word;
    case Size::DoubleWord:
        return ast::ElementaryType::Dword;
    case Size::LongWord:
        return ast::ElementaryType::Lword;
    default:
        return ast::ElementaryType::Bool;
    }
}

std::uint32_t direct_address_unit(ast::DirectAddress::Size size) {
    using Size = ast::DirectAddress::Size;
    switch (size) {
    case Size::Word:
        return 2;
    case Size::DoubleWord:
        return 4;
    case Size::LongWord:
        return 8;
    default:
        return 1;
    }
}

void check_located_variables(const ProgramUnderCheck& check,
                             std::span<const ast::CompilationUnit> units) {
    for (const ast::CompilationUnit& unit : units) {
        check_declarations(unit.global_variable_lists, check.program, check.diagnostics);
        for (const ast::Configuration& configuration : unit.configurations) {
            check_declarations(configuration.sections, check.program, check.diagnostics);
            for (const ast::Resource& resource : configuration.resources) {
                check_declarations(resource.sections, check.program, check.diagnostics);
                for (const ast::ProgramInstance& instance : resource.programs) {
                    for (const ast::Argument& connection : instance.connections) {
                        if (const auto* direct = std::get_if<ast::DirectAddressExpression>(
                                &connection.value->node)) {
                            check_address_in_code(direct->address, check.program,
                                                  check.diagnostics);
                        }
                    }
                }
            }
        }
        for (const ast::Pou& pou : unit.pous) {
            if (pou.kind == ast::PouKind::Program && check.includes(&pou)) {
                check_declarations(pou.sections, check.program, check.diagnostics);
            }
        }
    }
    for (const ast::Pou* pou : check.calls.pous()) {
        for (const ast::Expression* expression : check.calls.body(*pou).expressions()) {
            if (const auto* direct = std::get_if<ast::DirectAddressExpression>(&expression->node)) {
                check_address_in_code(direct->address, check.program, check.diagnostics);
            }
        }
    }
}

} // namespace eposp::compiler::checks
