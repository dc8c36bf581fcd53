// E0422: a PROGRAM called or reached by its name (`P()`, `P.x`, as CODESYS allows;
// docs/st-language.md, "Calling a PROGRAM") runs its one instance: the configuration declares
// at most one instance of it, and when it declares none, the instance created for the calls
// takes the program's name, which no instance of another type may have.

#include "eposp/compiler/sema/symbol.hpp"
#include "pou_checks.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unordered_map>
#include <vector>

namespace eposp::compiler::checks {
namespace {

struct Instances {
    // The configurations' program instances of each PROGRAM, and every instance by its name.
    std::unordered_map<const ast::Pou*, std::vector<const ast::ProgramInstance*>> of_program;
    std::unordered_map<std::string, const ast::ProgramInstance*> by_name;
};

Instances configured_instances(const types::TypedProgram& program,
                               std::span<const ast::CompilationUnit> units) {
    Instances instances;
    for (const ast::CompilationUnit& unit : units) {
        for (const ast::Configuration& configuration : unit.configurations) {
            for (const ast::Resource& resource : configuration.resources) {
                for (const ast::ProgramInstance& instance : resource.programs) {
                    const sema::Symbol* type = program.model().resolved(instance.type);
                    if (type != nullptr && type->kind == sema::SymbolKind::Pou) {
                        instances.of_program[type->pou].push_back(&instance);
                        instances.by_name.emplace(sema::fold_case(instance.name.name), &instance);
                    }
                }
            }
        }
    }
    return instances;
}

void check_use(const ast::Pou& called, const SourceRange& range, const Instances& instances,
               Diagnostics& diagnostics) {
    const auto configured = instances.of_program.find(&called);
    if (configured == instances.of_program.end()) {
        const auto other = instances.by_name.find(sema::fold_case(called.name.name));
        if (other != instances.by_name.end()) {
            Diagnostic diagnostic{DiagnosticCode::E0422, range,
                                  fmt::format("'{}' cannot have an instance of its own name: the "
                                              "configuration has a program instance '{}' of "
                                              "another type",
                                              called.name.name, called.name.name)};
            diagnostic.notes.push_back({other->second->range, "that instance is declared here"});
            diagnostics.report(std::move(diagnostic));
        }
        return;
    }
    if (configured->second.size() > 1) {
        std::vector<std::string> names;
        for (const ast::ProgramInstance* instance : configured->second) {
            names.push_back(instance->name.name);
        }
        Diagnostic diagnostic{DiagnosticCode::E0422, range,
                              fmt::format("'{}' has several instances in the configuration ({}): "
                                          "a call by the program's name needs exactly one",
                                          called.name.name, fmt::join(names, ", "))};
        for (const ast::ProgramInstance* instance : configured->second) {
            diagnostic.notes.push_back(
                {instance->range,
                 fmt::format("instance '{}' is declared here", instance->name.name)});
        }
        diagnostics.report(std::move(diagnostic));
    }
}

} // namespace

void check_program_instances(const ProgramUnderCheck& check,
                             std::span<const ast::CompilationUnit> units) {
    const Instances instances = configured_instances(check.program, units);
    if (instances.by_name.empty()) {
        return; // without a configuration every PROGRAM has one instance of its own name
    }
    for (const ast::Pou* pou : check.calls.pous()) {
        for (const ast::Expression* expression : check.calls.body(*pou).names()) {
            const auto& name = std::get<ast::NameExpression>(expression->node);
            const sema::Symbol* symbol = check.program.model().resolved(name.name);
            if (symbol != nullptr && symbol->kind == sema::SymbolKind::Pou &&
                symbol->pou->kind == ast::PouKind::Program) {
                check_use(*symbol->pou, expression->range, instances, check.diagnostics);
            }
        }
    }
}

} // namespace eposp::compiler::checks
