// E0421, E0424: the TASKs of a configuration (IEC 61131-3 ed. 3, 6.8.2) as the controller can
// run them: PRIORITY a constant from 0 upwards, SINGLE a global BOOL, INTERVAL a TIME literal of
// at least one tick; and the `{attribute 'event' := '…'}` that releases a task on an event of the
// host instead (docs/st-language.md, "Tasks").

#include "../types/constant_folder.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "eposp/vm/image_limits.hpp"
#include "pou_checks.hpp"

#include <cstdint>
#include <fmt/format.h>

namespace eposp::compiler::checks {
namespace {

void check_priority(const ast::Expression& priority, types::TypedProgram& program,
                    Diagnostics& diagnostics) {
    const auto value = program.constants().fold_integer(priority);
    if (!value || *value < 0 || *value > UINT32_MAX) {
        diagnostics.error(DiagnosticCode::E0421, priority.range,
                          "PRIORITY must be a constant from 0 upwards");
    }
}

// Whether the task is released by its event attribute: the first one that names an event the
// host accepts on a task without INTERVAL; every other is refused.
bool check_events(const ast::TaskDeclaration& task, const CompileOptions& options,
                  Diagnostics& diagnostics) {
    bool released = false;
    for (const ast::Attribute& attribute : task.attributes) {
        if (sema::fold_case(attribute.name) != "EVENT") {
            continue; // an attribute of another tool
        }
        if (released) {
            diagnostics.error(DiagnosticCode::E0424, attribute.range,
                              "task '" + task.name.name + "' is already released by an event");
        } else if (task.interval) {
            diagnostics.error(DiagnosticCode::E0424, attribute.range,
                              "task '" + task.name.name +
                                  "' has an INTERVAL: a task released by an "
                                  "event is not cyclic");
        } else if (attribute.value.empty()) {
            diagnostics.error(DiagnosticCode::E0424, attribute.range,
                              "the attribute names the event: {attribute 'event' := 'sync'}");
        } else if (const auto refusal = options.task_event_check
                                            ? options.task_event_check(attribute.value)
                                            : std::nullopt) {
            diagnostics.error(DiagnosticCode::E0424, attribute.range,
                              "event '" + attribute.value + "': " + *refusal);
        } else {
            released = true;
        }
    }
    return released;
}

void check_single(const ast::Expression& single, types::TypedProgram& program,
                  Diagnostics& diagnostics) {
    const auto* name = std::get_if<ast::NameExpression>(&single.node);
    const sema::Symbol* symbol = name != nullptr ? program.model().resolved(name->name) : nullptr;
    const sema::Type* type = symbol != nullptr && symbol->kind == sema::SymbolKind::Variable &&
                                     symbol->variable != nullptr
                                 ? program.types().resolve(symbol->variable->type)
                                 : nullptr;
    if (type == nullptr || !sema::is_bool(*type)) {
        diagnostics.error(DiagnosticCode::E0421, single.range,
                          "SINGLE must name a global BOOL variable");
    }
}

void check_interval(const ast::Expression& interval, Diagnostics& diagnostics) {
    const auto* literal = std::get_if<ast::LiteralExpression>(&interval.node);
    const auto* duration =
        literal != nullptr ? std::get_if<ast::DurationLiteral>(&literal->value) : nullptr;
    if (duration == nullptr || duration->nanoseconds <= 0) {
        diagnostics.error(DiagnosticCode::E0421, interval.range,
                          "INTERVAL must be a positive TIME literal");
    } else if (static_cast<std::uint64_t>(duration->nanoseconds) < vm::kMinTaskIntervalNs) {
        diagnostics.error(DiagnosticCode::E0421, interval.range,
                          fmt::format("INTERVAL must be at least {} ms: the controller runs "
                                      "cyclic tasks on a {} ms tick",
                                      vm::kMinTaskIntervalNs / 1'000'000,
                                      vm::kMinTaskIntervalNs / 1'000'000));
    }
}

} // namespace

void check_tasks(types::TypedProgram& program, std::span<const ast::CompilationUnit> units,
                 const CompileOptions& options, Diagnostics& diagnostics) {
    for (const ast::CompilationUnit& unit : units) {
        for (const ast::Configuration& configuration : unit.configurations) {
            for (const ast::Resource& resource : configuration.resources) {
                for (const ast::TaskDeclaration& task : resource.tasks) {
                    if (task.priority) {
                        check_priority(*task.priority, program, diagnostics);
                    }
                    const bool released = check_events(task, options, diagnostics);
                    if (task.single) {
                        check_single(*task.single, program, diagnostics);
                    } else if (!released && task.interval) {
                        check_interval(*task.interval, diagnostics);
                    }
                }
            }
        }
    }
}

} // namespace eposp::compiler::checks
