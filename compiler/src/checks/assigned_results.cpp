// W0402, W0403: what a POU hands back (a function's result, the outputs of a function or FB)
// is assigned, and a function's on every path (definite_assignment.hpp).

#include "case_labels.hpp"
#include "definite_assignment.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "pou_checks.hpp"
#include "written_variables.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <unordered_set>

namespace eposp::compiler::checks {
namespace {

/// Whether an assignment of the body writes the function's result or a part of it (`F.x := 1`).
bool assigns_result(const PouUnderCheck& check) {
    for (const ast::Statement* statement : check.body.assignments()) {
        const ast::NameExpression* name =
            root_variable(*std::get<ast::AssignmentStatement>(statement->node).target);
        const sema::Symbol* symbol =
            name != nullptr ? check.program.model().resolved(name->name) : nullptr;
        if (symbol != nullptr && symbol->pou == &check.pou) {
            return true;
        }
    }
    return false;
}

/// Whether `call` may write the variable given as its argument `index` as it is: a VAR_IN_OUT
/// of a function or an instance, or a parameter that cannot be told.
bool may_write_argument(types::TypedProgram& program, const ast::CallExpression& call,
                        std::size_t index) {
    const auto* name = std::get_if<ast::NameExpression>(&call.callee->node);
    const sema::Symbol* callee = name != nullptr ? program.model().resolved(name->name) : nullptr;
    const ast::Pou* function = nullptr;
    if (callee != nullptr && callee->kind == sema::SymbolKind::Pou) {
        function = callee->pou;
    } else if (callee != nullptr && callee->kind == sema::SymbolKind::StandardFunction) {
        function = program.library_pou(callee->name);
        if (function == nullptr) {
            return false; // the built-in standard functions take values (ADR aside)
        }
    }
    if (function != nullptr) {
        const sema::Type& frame = *program.types().frame(*function);
        std::size_t positional = 0;
        for (std::size_t i = 0; i < index; ++i) {
            if (!call.arguments[i].name) {
                sema::formal_parameter(frame, call.arguments[i], positional);
            }
        }
        const sema::Field* field = sema::formal_parameter(frame, call.arguments[index], positional);
        return field != nullptr && field->section == ast::VarSectionKind::InOut;
    }
    // An instance: its formal names resolve to its variables.
    const ast::Argument& argument = call.arguments[index];
    const sema::Symbol* formal = argument.name ? program.model().resolved(*argument.name) : nullptr;
    if (formal != nullptr && formal->kind == sema::SymbolKind::Variable) {
        return formal->section == ast::VarSectionKind::InOut;
    }
    return true;
}

/// Whether a CASE selector of an enumeration, or a variable or function result declared as a
/// subrange, has every value among the labels: then no path skips all the branches
/// (7.3.3.3.3). A subrange value otherwise loaded counts as its base type.
bool covers_every_value(types::TypedProgram& program, const ast::CaseStatement& node) {
    const sema::Type* type = program.type_of(*node.selector);
    if (type == nullptr) {
        return false;
    }
    if (type->kind != sema::TypeKind::Enum) {
        const ast::Expression* named = node.selector.get();
        const auto* call = std::get_if<ast::CallExpression>(&named->node);
        if (call != nullptr) {
            named = call->callee.get();
        }
        const auto* name = std::get_if<ast::NameExpression>(&named->node);
        const sema::Symbol* symbol =
            name != nullptr ? program.model().resolved(name->name) : nullptr;
        const bool declared = symbol != nullptr &&
                              (call == nullptr ? symbol->kind == sema::SymbolKind::Variable
                                               : symbol->kind == sema::SymbolKind::Pou &&
                                                     symbol->pou->kind == ast::PouKind::Function);
        if (!declared || !type->range) {
            return false;
        }
    }
    const CaseLabels labels = case_labels(program, node, *type);
    std::vector<std::pair<std::int64_t, std::int64_t>> ranges;
    for (const CaseLabelRange& label : labels.ranges) {
        // A subrange's bounds are signed 64-bit: an unsigned label above them covers none of its
        // values, a range reaching above them all up to its upper bound.
        if (!labels.unsigned64 || label.low >= 0) {
            ranges.emplace_back(label.low,
                                labels.unsigned64 && label.high < 0 ? INT64_MAX : label.high);
        }
    }
    const auto covered = [&](std::int64_t value) {
        return std::any_of(ranges.begin(), ranges.end(),
                           [&](const auto& r) { return r.first <= value && value <= r.second; });
    };
    if (type->kind == sema::TypeKind::Enum) {
        return !type->enumerators.empty() &&
               std::all_of(type->enumerators.begin(), type->enumerators.end(),
                           [&](const auto& enumerator) { return covered(enumerator.second); });
    }
    std::sort(ranges.begin(), ranges.end());
    std::int64_t next = type->range->lower; // the lowest value not yet covered
    for (const auto& [low, high] : ranges) {
        if (low > next) {
            return false;
        }
        if (high >= type->range->upper) {
            return true;
        }
        next = std::max(next, high + 1);
    }
    return false;
}

// A function's result and outputs start from their initial values at each call (6.5.1.3): a
// path that assigns none returns those, likely an oversight unless the declaration gives one.
// An FB's outputs keep their values from the last call, so a path that leaves one is normal
// PLC practice and is not reported. What is never assigned at all is reported before.
void check_paths(const PouUnderCheck& check, const WrittenNames& written, bool result_assigned) {
    const ast::Pou& pou = check.pou;
    std::vector<std::string> names;
    std::vector<const ast::Identifier*> declared;
    if (pou.return_type && result_assigned) {
        names.push_back(sema::fold_case(pou.name.name));
        declared.push_back(&pou.name);
    }
    for (const ast::DeclarationSection& section : pou.sections) {
        const auto* variables = std::get_if<ast::VarSection>(&section);
        if (variables == nullptr || variables->kind != ast::VarSectionKind::Output) {
            continue;
        }
        for (const ast::VariableDeclaration& declaration : variables->variables) {
            for (const ast::Identifier& name : declaration.names) {
                if (declaration.initial_value == nullptr && written.contains(name.name)) {
                    names.push_back(sema::fold_case(name.name));
                    declared.push_back(&name);
                }
            }
        }
    }
    if (names.empty()) {
        return;
    }
    std::unordered_set<const ast::CaseStatement*> exhaustive;
    for (const ast::Statement* statement : check.body.statements()) {
        const auto* node = std::get_if<ast::CaseStatement>(&statement->node);
        if (node != nullptr && covers_every_value(check.program, *node)) {
            exhaustive.insert(node);
        }
    }
    const AssignmentFacts facts{[&](const ast::CallExpression& node, std::size_t index) {
                                    return may_write_argument(check.program, node, index);
                                },
                                [&](const ast::CaseStatement& node) {
                                    return exhaustive.contains(&node);
                                }};
    // The POU ends with END_FUNCTION: underline it.
    constexpr std::uint32_t kEndLength = 12; // END_FUNCTION
    SourceRange end{pou.range.file, pou.range.end, pou.range.end};
    if (end.end.column >= kEndLength) {
        end.begin.column = end.end.column - kEndLength + 1;
    }
    for (const UnassignedPaths& paths : unassigned_paths(pou.body, names, facts)) {
        const auto at = std::find(names.begin(), names.end(), paths.name) - names.begin();
        const ast::Identifier& name = *declared[static_cast<std::size_t>(at)];
        Diagnostic diagnostic{
            &name == &pou.name ? DiagnosticCode::W0403 : DiagnosticCode::W0402, name.range,
            &name == &pou.name
                ? fmt::format("function '{}' may return without assigning its result (not "
                              "assigned on every path)",
                              name.name)
                : fmt::format("output '{}' may be left unassigned (not assigned on every path)",
                              name.name)};
        for (const SourceRange& range : paths.returns) {
            diagnostic.notes.push_back({range, "this RETURN is reached without assigning it"});
        }
        if (paths.at_end) {
            diagnostic.notes.push_back(
                {end, "the end of the function is reached without assigning it"});
        }
        check.diagnostics.report(std::move(diagnostic));
    }
}

} // namespace

void check_assigned_results(const PouUnderCheck& check) {
    const ast::Pou& pou = check.pou;
    const bool result_assigned = assigns_result(check);
    if (pou.kind == ast::PouKind::Function && pou.return_type && !result_assigned) {
        check.diagnostics.warning(
            DiagnosticCode::W0403, pou.name.range,
            fmt::format("function '{}' never assigns its result", pou.name.name));
    }
    // A program's outputs may be written from outside (connections, online): only a
    // function's or FB's are reported.
    if (pou.kind == ast::PouKind::Program) {
        return;
    }
    const auto written = written_variables(pou.body);
    for (const ast::DeclarationSection& section : pou.sections) {
        const auto* variables = std::get_if<ast::VarSection>(&section);
        if (variables == nullptr || variables->kind != ast::VarSectionKind::Output) {
            continue;
        }
        for (const ast::VariableDeclaration& declaration : variables->variables) {
            for (const ast::Identifier& name : declaration.names) {
                if (!written.contains(name.name)) {
                    check.diagnostics.warning(
                        DiagnosticCode::W0402, name.range,
                        fmt::format("output '{}' is never assigned", name.name));
                }
            }
        }
    }
    if (pou.kind == ast::PouKind::Function) {
        check_paths(check, written, result_assigned);
    }
}

} // namespace eposp::compiler::checks
