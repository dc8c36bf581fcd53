#include "name_resolver.hpp"

#include "eposp/compiler/sema/standard_library.hpp"

#include <fmt/format.h>

namespace eposp::compiler::sema {
namespace {

/// What member access and indexing need to know about the value an expression denotes: enough
/// to resolve `a.b[i].c`, not a type system (that is the type checker's job).
struct ValueShape {
    bool known = false;
    std::string_view type_name{};        // for messages: a symbol's name or a fixed text
    const ast::TypeSpec* spec = nullptr; // arrays and references: indexing and `^`
    const Scope* members = nullptr;      // structs and FB instances
};

// Aliases of aliases are followed this deep; a longer chain is a cycle.
constexpr int kMaxAliasDepth = 32;

class NameResolver {
public:
    explicit NameResolver(ResolverState& state)
        : state_(state), model_(state.model), global_(state.model.global_scope()) {}

    void resolve(const ast::CompilationUnit& unit) {
        for (const ast::TypeDeclaration& declaration : unit.types) {
            resolve_type(declaration.type, global_);
            resolve_initializer(declaration.initial_value.get(), declaration.type, global_);
        }
        for (const ast::Pou& pou : unit.pous) {
            resolve_pou(pou);
        }
        for (const ast::Configuration& configuration : unit.configurations) {
            resolve_configuration(configuration);
        }
        resolve_sections(unit.global_variable_lists, global_);
    }

private:
    void error(DiagnosticCode code, const SourceRange& range, std::string message) {
        state_.diagnostics.error(code, range, std::move(message));
    }

    // --- Types -----------------------------------------------------------------------------

    /// Expressions in a type (array bounds, string lengths, enum values) see `scope`: the
    /// constants of the POU that declares the variable, or the global ones.
    void resolve_type(const ast::TypeSpec& spec, const Scope& scope) {
        std::visit([this, &scope](const auto& node) { resolve_type_node(node, scope); }, spec.node);
    }

    void resolve_type_node(const ast::ElementaryTypeRef&, const Scope&) {}
    void resolve_type_node(const ast::StringTypeRef& node, const Scope& scope) {
        resolve_optional(node.length, scope);
    }
    void resolve_type_node(const ast::NamedTypeRef& node, const Scope&) {
        const Symbol* symbol = global_.find_member(node.name.name);
        if (symbol == nullptr && fold_case(node.name.name) == "ANY") {
            return; // the generic type of native functions' inputs (TypeTable::any)
        }
        if (symbol == nullptr) {
            error(DiagnosticCode::E0203, node.name.range,
                  fmt::format("unknown type '{}'", node.name.name));
            return;
        }
        if (!names_a_type(*symbol)) {
            error(DiagnosticCode::E0204, node.name.range,
                  fmt::format("'{}' is not a type", node.name.name));
            return;
        }
        model_.bind(node.name, *symbol);
    }
    void resolve_type_node(const ast::ArrayType& node, const Scope& scope) {
        for (const ast::ArrayDimension& dimension : node.dimensions) {
            if (dimension.bounds) {
                resolve_subrange(*dimension.bounds, scope);
            }
        }
        resolve_type(*node.element, scope);
    }
    void resolve_type_node(const ast::SubrangeType& node, const Scope& scope) {
        resolve_type(*node.base, scope);
        resolve_subrange(node.range, scope);
    }
    void resolve_type_node(const ast::EnumType& node, const Scope& scope) {
        if (node.base) {
            resolve_type(*node.base, scope);
        }
        for (const ast::EnumValue& value : node.values) {
            resolve_optional(value.value, scope);
        }
    }
    void resolve_type_node(const ast::StructType& node, const Scope& scope) {
        for (const ast::VariableDeclaration& member : node.members) {
            resolve_variable(member, scope);
        }
    }
    void resolve_type_node(const ast::ReferenceType& node, const Scope& scope) {
        resolve_type(*node.target, scope);
    }

    void resolve_subrange(const ast::Subrange& range, const Scope& scope) {
        resolve_expression(*range.low, scope);
        resolve_expression(*range.high, scope);
    }

    static bool names_a_type(const Symbol& symbol) {
        return symbol.kind == SymbolKind::Type ||
               symbol.kind == SymbolKind::StandardFunctionBlock ||
               (symbol.kind == SymbolKind::Pou && symbol.pou->kind == ast::PouKind::FunctionBlock);
    }

    // --- Shapes of values ------------------------------------------------------------------

    ValueShape shape_of(const ast::TypeSpec& spec, int depth = 0) const {
        if (const auto* elementary = std::get_if<ast::ElementaryTypeRef>(&spec.node)) {
            return {.known = true, .type_name = ast::name_of(elementary->type)};
        }
        if (const auto* string = std::get_if<ast::StringTypeRef>(&spec.node)) {
            return {.known = true, .type_name = ast::name_of(string->type)};
        }
        if (const auto* named = std::get_if<ast::NamedTypeRef>(&spec.node)) {
            // Looked up rather than taken from the model: the declaration naming this type
            // may be in a file not resolved yet.
            const Symbol* symbol = global_.find_member(named->name.name);
            return symbol == nullptr || !names_a_type(*symbol)
                       ? ValueShape{}
                       : shape_of_type_symbol(*symbol, depth);
        }
        if (const auto* subrange = std::get_if<ast::SubrangeType>(&spec.node)) {
            return shape_of(*subrange->base, depth);
        }
        if (std::holds_alternative<ast::StructType>(spec.node)) {
            return {.known = true, .type_name = "STRUCT", .members = model_.struct_members(spec)};
        }
        if (std::holds_alternative<ast::ArrayType>(spec.node)) {
            return {.known = true, .type_name = "ARRAY", .spec = &spec};
        }
        if (std::holds_alternative<ast::ReferenceType>(spec.node)) {
            return {.known = true, .type_name = "REF_TO", .spec = &spec};
        }
        return {.known = true, .type_name = "enumeration"};
    }

    ValueShape shape_of_type_symbol(const Symbol& symbol, int depth) const {
        if (symbol.kind != SymbolKind::Type) {
            return {.known = true, .type_name = symbol.name, .members = symbol.members};
        }
        if (depth > kMaxAliasDepth) {
            return {};
        }
        ValueShape shape = shape_of(symbol.type->type, depth + 1);
        shape.type_name = symbol.name;
        return shape;
    }

    ValueShape shape_of_symbol(const Symbol& symbol) const {
        switch (symbol.kind) {
        case SymbolKind::Variable:
            if (symbol.variable != nullptr) {
                return shape_of(symbol.variable->type);
            }
            return {.known = true, .type_name = symbol.standard_type};
        case SymbolKind::EnumValue:
            return {.known = symbol.owner != nullptr,
                    .type_name =
                        symbol.owner != nullptr ? std::string_view(symbol.owner->name) : ""};
        case SymbolKind::ProgramInstance: {
            // `Inst1.out` in a program connection: the members of its program type.
            const Symbol* program = global_.find_member(symbol.program_instance->type.name);
            if (program == nullptr || program->kind != SymbolKind::Pou) {
                return {};
            }
            return {.known = true, .type_name = program->name, .members = program->members};
        }
        case SymbolKind::Pou:
            // A function's name in its own body is its result variable.
            if (symbol.pou->return_type) {
                return shape_of(*symbol.pou->return_type);
            }
            // `P.Step`: a PROGRAM's name stands for its single instance (CODESYS).
            if (symbol.pou->kind == ast::PouKind::Program) {
                return {.known = true, .type_name = symbol.name, .members = symbol.members};
            }
            return {};
        default:
            return {};
        }
    }

    // --- Expressions -----------------------------------------------------------------------

    void resolve_optional(const ast::ExpressionPtr& expression, const Scope& scope) {
        if (expression) {
            resolve_expression(*expression, scope);
        }
    }

    ValueShape resolve_expression(const ast::Expression& expression, const Scope& scope) {
        return std::visit([&](const auto& node) { return resolve_node(node, scope); },
                          expression.node);
    }

    ValueShape resolve_node(const ast::LiteralExpression& node, const Scope&) {
        if (const auto* value = std::get_if<ast::EnumValueLiteral>(&node.value)) {
            return resolve_qualified_enum_value(*value);
        }
        return {};
    }

    /// `Color#Red` (ed. 3, 6.4.4.2).
    ValueShape resolve_qualified_enum_value(const ast::EnumValueLiteral& literal) {
        const Symbol* type = global_.find_member(literal.type_name.name);
        if (type == nullptr) {
            error(DiagnosticCode::E0203, literal.type_name.range,
                  fmt::format("unknown type '{}'", literal.type_name.name));
            return {};
        }
        if (!is_enumerated_type(*type)) {
            error(DiagnosticCode::E0204, literal.type_name.range,
                  fmt::format("'{}' is not an enumerated type", literal.type_name.name));
            return {};
        }
        return resolve_enum_value(literal.type_name, *type, literal.value);
    }

    /// The value `value` of the enumerated type `type`, named `type_name` where it is used.
    ValueShape resolve_enum_value(const ast::Identifier& type_name, const Symbol& type,
                                  const ast::Identifier& value) {
        model_.bind(type_name, type);
        const Symbol* symbol = type.members->find_member(value.name);
        if (symbol == nullptr) {
            error(DiagnosticCode::E0205, value.range,
                  fmt::format("enumerated type '{}' has no value '{}'", type.name, value.name));
            return {};
        }
        model_.bind(value, *symbol);
        return shape_of_symbol(*symbol);
    }

    static bool is_enumerated_type(const Symbol& symbol) {
        return symbol.kind == SymbolKind::Type &&
               std::holds_alternative<ast::EnumType>(symbol.type->type.node);
    }

    ValueShape resolve_node(const ast::NameExpression& node, const Scope& scope) {
        const Symbol* symbol = find_name(node.name, scope);
        // A standard function or FB is never a value, so where one is named as a value an
        // enumerator of that name is meant (`CASE step OF Move:` with `Step : (Load, Move)`).
        if (symbol != nullptr && (symbol->kind == SymbolKind::StandardFunction ||
                                  symbol->kind == SymbolKind::StandardFunctionBlock)) {
            const auto it = state_.enum_values.find(fold_case(node.name.name));
            if (it != state_.enum_values.end()) {
                symbol = unique_enum_value(node.name, it->second);
            }
        }
        return bound(node.name, symbol);
    }

    /// A callee is looked up as a name, never as an enumerator (`MOVE(x)`).
    ValueShape resolve_callee(const ast::Expression& callee, const Scope& scope) {
        if (const auto* name = std::get_if<ast::NameExpression>(&callee.node)) {
            return bound(name->name, find_name(name->name, scope));
        }
        return resolve_expression(callee, scope);
    }

    ValueShape bound(const ast::Identifier& name, const Symbol* symbol) {
        if (symbol == nullptr) {
            return {};
        }
        model_.bind(name, *symbol);
        return shape_of_symbol(*symbol);
    }

    /// Declared names first, then unqualified enumeration values, then the conversion
    /// functions; reports the name when none of them has it.
    const Symbol* find_name(const ast::Identifier& name, const Scope& scope) {
        if (const Symbol* symbol = scope.find(name.name)) {
            return symbol;
        }
        const std::string key = fold_case(name.name);
        if (const auto it = state_.enum_values.find(key); it != state_.enum_values.end()) {
            return unique_enum_value(name, it->second);
        }
        if (is_conversion_function(name.name)) {
            auto [it, inserted] = conversions_.emplace(key, nullptr);
            if (inserted) {
                it->second = &model_.add({.kind = SymbolKind::StandardFunction, .name = key});
            }
            return it->second;
        }
        error(DiagnosticCode::E0201, name.range,
              fmt::format("undeclared identifier '{}'", name.name));
        return nullptr;
    }

    const Symbol* unique_enum_value(const ast::Identifier& name,
                                    const std::vector<const Symbol*>& candidates) {
        if (candidates.size() == 1) {
            return candidates.front();
        }
        const Symbol* first = candidates.front();
        Diagnostic diagnostic(
            DiagnosticCode::E0207, name.range,
            fmt::format("'{}' is ambiguous: qualify it with its type, as in {}#{}", name.name,
                        first->owner != nullptr ? first->owner->name : "T", name.name));
        for (const Symbol* candidate : candidates) {
            diagnostic.notes.push_back(
                {candidate->declared,
                 fmt::format("'{}' is a value of '{}'", candidate->name,
                             candidate->owner != nullptr ? candidate->owner->name : "?")});
        }
        state_.diagnostics.report(std::move(diagnostic));
        return nullptr;
    }

    ValueShape resolve_node(const ast::DirectAddressExpression&, const Scope&) { return {}; }

    ValueShape resolve_node(const ast::MemberExpression& node, const Scope& scope) {
        // `Color.Red`, CODESYS's spelling of Color#Red, unless a variable hides the type.
        if (const auto* name = std::get_if<ast::NameExpression>(&node.object->node)) {
            const Symbol* symbol = scope.find(name->name.name);
            if (symbol != nullptr && is_enumerated_type(*symbol)) {
                return resolve_enum_value(name->name, *symbol, node.member);
            }
        }
        const ValueShape object = resolve_expression(*node.object, scope);
        if (!object.known) {
            return {}; // already reported, or not knowable here
        }
        const Symbol* member =
            object.members != nullptr ? object.members->find_member(node.member.name) : nullptr;
        if (member == nullptr) {
            error(DiagnosticCode::E0206, node.member.range,
                  fmt::format("'{}' has no member '{}'", object.type_name, node.member.name));
            return {};
        }
        model_.bind(node.member, *member);
        return shape_of_symbol(*member);
    }

    ValueShape resolve_node(const ast::BitAccessExpression& node, const Scope& scope) {
        resolve_expression(*node.object, scope);
        return {.known = true, .type_name = "BOOL"};
    }

    ValueShape resolve_node(const ast::IndexExpression& node, const Scope& scope) {
        const ValueShape array = resolve_expression(*node.array, scope);
        for (const ast::ExpressionPtr& index : node.indices) {
            resolve_expression(*index, scope);
        }
        if (array.spec != nullptr) {
            if (const auto* type = std::get_if<ast::ArrayType>(&array.spec->node)) {
                return shape_of(*type->element);
            }
        }
        return {};
    }

    ValueShape resolve_node(const ast::DereferenceExpression& node, const Scope& scope) {
        const ValueShape reference = resolve_expression(*node.reference, scope);
        if (reference.spec != nullptr) {
            if (const auto* type = std::get_if<ast::ReferenceType>(&reference.spec->node)) {
                return shape_of(*type->target);
            }
        }
        return {};
    }

    ValueShape resolve_node(const ast::ReferenceExpression& node, const Scope& scope) {
        resolve_expression(*node.target, scope);
        return {};
    }

    ValueShape resolve_node(const ast::CallExpression& node, const Scope& scope) {
        const ValueShape callee = resolve_callee(*node.callee, scope);
        if (sizes_elementary_type(node, scope)) {
            return {}; // SIZEOF(INT): the typing stage sizes the type it names
        }
        const Symbol* pou = called_pou(*node.callee);
        // Formal names belong to the called POU, or to the FB type of the called instance.
        const Scope* parameters = pou != nullptr ? pou->members : callee.members;
        resolve_arguments(node.arguments, parameters, callee_name(pou, callee), scope);
        return pou != nullptr ? callee : ValueShape{};
    }

    /// Whether `node` is SIZEOF of an elementary type's name (`SIZEOF(LREAL)`), which is no
    /// name in scope; SIZEOF of a declared type's name resolves as a name.
    bool sizes_elementary_type(const ast::CallExpression& node, const Scope& scope) const {
        if (node.arguments.size() != 1 || node.arguments.front().name) {
            return false;
        }
        const auto* name = std::get_if<ast::NameExpression>(&node.arguments.front().value->node);
        const auto* callee = std::get_if<ast::NameExpression>(&node.callee->node);
        const Symbol* function =
            name != nullptr && callee != nullptr ? model_.resolved(callee->name) : nullptr;
        return function != nullptr && function->kind == SymbolKind::StandardFunction &&
               function->name == "SIZEOF" &&
               ast::elementary_type_from_name(name->name.name).has_value() &&
               scope.find(name->name.name) == nullptr;
    }

    const Symbol* called_pou(const ast::Expression& callee) const {
        const auto* name = std::get_if<ast::NameExpression>(&callee.node);
        const Symbol* symbol = name != nullptr ? model_.resolved(name->name) : nullptr;
        return symbol != nullptr && symbol->kind == SymbolKind::Pou ? symbol : nullptr;
    }

    static std::string_view callee_name(const Symbol* pou, const ValueShape& callee) {
        return pou != nullptr ? std::string_view(pou->name) : callee.type_name;
    }

    /// Formal names are checked where the callee's parameters are known; standard functions
    /// (IN1, IN2… of extensible functions) are left to the type checker.
    void resolve_arguments(const std::vector<ast::Argument>& arguments, const Scope* parameters,
                           std::string_view callee, const Scope& scope) {
        for (const ast::Argument& argument : arguments) {
            if (argument.name && parameters != nullptr) {
                if (const Symbol* formal = parameters->find_member(argument.name->name)) {
                    model_.bind(*argument.name, *formal);
                } else if (!is_enable_parameter(argument.name->name)) {
                    error(DiagnosticCode::E0210, argument.name->range,
                          fmt::format("'{}' has no parameter '{}'", callee, argument.name->name));
                }
            }
            resolve_expression(*argument.value, scope);
        }
    }

    /// EN and ENO, which every function and FB call has (ed. 3, 6.6.1.8).
    static bool is_enable_parameter(std::string_view name) {
        return equal_ignoring_case(name, "EN") || equal_ignoring_case(name, "ENO");
    }

    ValueShape resolve_node(const ast::UnaryExpression& node, const Scope& scope) {
        resolve_expression(*node.operand, scope);
        return {};
    }

    ValueShape resolve_node(const ast::BinaryExpression& node, const Scope& scope) {
        resolve_expression(*node.left, scope);
        resolve_expression(*node.right, scope);
        return {};
    }

    // --- Initial values --------------------------------------------------------------------

    void resolve_initializer(const ast::Initializer* initializer, const ast::TypeSpec& type,
                             const Scope& scope) {
        if (initializer == nullptr) {
            return;
        }
        if (const auto* expression = std::get_if<ast::ExpressionPtr>(&initializer->value)) {
            resolve_expression(**expression, scope);
        } else if (const auto* elements =
                       std::get_if<std::vector<ast::ArrayInitElement>>(&initializer->value)) {
            resolve_array_initializer(*elements, type, scope);
        } else {
            resolve_struct_initializer(
                std::get<std::vector<ast::StructInitElement>>(initializer->value), type, scope);
        }
    }

    void resolve_array_initializer(const std::vector<ast::ArrayInitElement>& elements,
                                   const ast::TypeSpec& type, const Scope& scope) {
        const ValueShape array = shape_of(type);
        const auto* array_type =
            array.spec != nullptr ? std::get_if<ast::ArrayType>(&array.spec->node) : nullptr;
        for (const ast::ArrayInitElement& element : elements) {
            if (element.repeat_count) {
                resolve_expression(*element.repeat_count, scope);
            }
            if (element.value) {
                resolve_initializer(element.value.get(),
                                    array_type != nullptr ? *array_type->element : type, scope);
            }
        }
    }

    void resolve_struct_initializer(const std::vector<ast::StructInitElement>& elements,
                                    const ast::TypeSpec& type, const Scope& scope) {
        const ValueShape structure = shape_of(type);
        for (const ast::StructInitElement& element : elements) {
            const Symbol* member = structure.members != nullptr
                                       ? structure.members->find_member(element.member.name)
                                       : nullptr;
            if (member == nullptr && structure.known) {
                error(DiagnosticCode::E0206, element.member.range,
                      fmt::format("'{}' has no member '{}'", structure.type_name,
                                  element.member.name));
            }
            if (member != nullptr) {
                model_.bind(element.member, *member);
            }
            // An unknown member's value is still searched for undeclared names; its nested
            // aggregates, of unknown type, are not checked against any members.
            const ast::TypeSpec& member_type =
                member != nullptr && member->variable != nullptr ? member->variable->type : type;
            resolve_initializer(element.value.get(), member_type, scope);
        }
    }

    // --- Declarations ----------------------------------------------------------------------

    void resolve_variable(const ast::VariableDeclaration& declaration, const Scope& scope) {
        resolve_type(declaration.type, scope);
        resolve_initializer(declaration.initial_value.get(), declaration.type, scope);
    }

    void resolve_sections(const std::vector<ast::DeclarationSection>& sections,
                          const Scope& scope) {
        for (const ast::DeclarationSection& section : sections) {
            if (const auto* access = std::get_if<ast::AccessSection>(&section)) {
                // The path itself is resolved against the instances when laying them out.
                for (const ast::AccessDeclaration& declaration : access->paths) {
                    resolve_type(declaration.type, scope);
                }
                continue;
            }
            const auto* variables = std::get_if<ast::VarSection>(&section);
            if (variables == nullptr) {
                continue;
            }
            for (const ast::VariableDeclaration& declaration : variables->variables) {
                resolve_variable(declaration, scope);
                if (variables->kind == ast::VarSectionKind::External) {
                    bind_external(declaration);
                }
            }
        }
    }

    /// Ed. 3, 6.5.2.2: a VAR_EXTERNAL names a VAR_GLOBAL of the configuration; its name in
    /// the declaration is bound to that global.
    void bind_external(const ast::VariableDeclaration& declaration) {
        for (const ast::Identifier& name : declaration.names) {
            const Symbol* global = global_.find_member(name.name);
            if (global == nullptr || global->kind != SymbolKind::Variable ||
                global->section != ast::VarSectionKind::Global) {
                error(DiagnosticCode::E0208, name.range,
                      fmt::format("VAR_EXTERNAL '{}' has no matching VAR_GLOBAL", name.name));
                continue;
            }
            model_.bind(name, *global);
        }
    }

    void resolve_pou(const ast::Pou& pou) {
        Scope& scope = *state_.pou_scopes.at(&pou);
        if (pou.return_type) {
            resolve_type(*pou.return_type, scope);
        }
        resolve_base(pou, scope);
        for (const ast::Identifier& interface : pou.implements) {
            error(DiagnosticCode::E0203, interface.range,
                  fmt::format("unknown interface '{}'", interface.name));
        }
        resolve_sections(pou.sections, scope);
        resolve_statements(pou.body, scope);
    }

    /// `FUNCTION_BLOCK B EXTENDS A`: B's members are looked up in A after B (ed. 3, 6.6.5.6).
    void resolve_base(const ast::Pou& pou, Scope& scope) {
        if (!pou.extends) {
            return;
        }
        const ast::Identifier& name = *pou.extends;
        const Symbol* base = global_.find_member(name.name);
        if (base == nullptr) {
            error(DiagnosticCode::E0203, name.range,
                  fmt::format("unknown function block '{}'", name.name));
            return;
        }
        if (base->kind != SymbolKind::Pou || base->pou->kind != ast::PouKind::FunctionBlock) {
            error(DiagnosticCode::E0204, name.range,
                  fmt::format("'{}' is not a function block", name.name));
            return;
        }
        for (const Scope* ancestor = base->members; ancestor != nullptr;
             ancestor = ancestor->base()) {
            if (ancestor == &scope) {
                error(DiagnosticCode::E0211, name.range,
                      fmt::format("'{}' extends itself through '{}'", pou.name.name, name.name));
                return;
            }
        }
        model_.bind(name, *base);
        scope.set_base(base->members);
    }

    // --- Statements ------------------------------------------------------------------------

    void resolve_statements(const ast::StatementList& statements, const Scope& scope) {
        for (const ast::Statement& statement : statements) {
            std::visit([&](const auto& node) { resolve_statement(node, scope); }, statement.node);
        }
    }

    void resolve_statement(const ast::AssignmentStatement& node, const Scope& scope) {
        resolve_expression(*node.target, scope);
        resolve_expression(*node.value, scope);
    }
    void resolve_statement(const ast::CallStatement& node, const Scope& scope) {
        resolve_expression(*node.call, scope);
    }
    void resolve_statement(const ast::IfStatement& node, const Scope& scope) {
        for (const ast::ConditionalBlock& branch : node.branches) {
            resolve_expression(*branch.condition, scope);
            resolve_statements(branch.body, scope);
        }
        resolve_statements(node.else_body, scope);
    }
    void resolve_statement(const ast::CaseStatement& node, const Scope& scope) {
        resolve_expression(*node.selector, scope);
        for (const ast::CaseBranch& branch : node.branches) {
            for (const ast::CaseLabel& label : branch.labels) {
                resolve_expression(*label.low, scope);
                if (label.high) {
                    resolve_expression(*label.high, scope);
                }
            }
            resolve_statements(branch.body, scope);
        }
        resolve_statements(node.else_body, scope);
    }
    void resolve_statement(const ast::ForStatement& node, const Scope& scope) {
        if (const Symbol* variable = find_name(node.control_variable, scope)) {
            model_.bind(node.control_variable, *variable);
        }
        resolve_expression(*node.from, scope);
        resolve_expression(*node.to, scope);
        if (node.by) {
            resolve_expression(*node.by, scope);
        }
        resolve_statements(node.body, scope);
    }
    void resolve_statement(const ast::WhileStatement& node, const Scope& scope) {
        resolve_expression(*node.condition, scope);
        resolve_statements(node.body, scope);
    }
    void resolve_statement(const ast::RepeatStatement& node, const Scope& scope) {
        resolve_statements(node.body, scope);
        resolve_expression(*node.until, scope);
    }
    void resolve_statement(const ast::ExitStatement&, const Scope&) {}
    void resolve_statement(const ast::ContinueStatement&, const Scope&) {}
    void resolve_statement(const ast::ReturnStatement&, const Scope&) {}
    void resolve_statement(const ast::EmptyStatement&, const Scope&) {}

    // --- Configurations --------------------------------------------------------------------

    void resolve_configuration(const ast::Configuration& configuration) {
        resolve_sections(configuration.sections, global_);
        for (const ast::Resource& resource : configuration.resources) {
            resolve_sections(resource.sections, global_);
            for (const ast::TaskDeclaration& task : resource.tasks) {
                resolve_optional(task.single, global_);
                resolve_optional(task.interval, global_);
                resolve_optional(task.priority, global_);
            }
            const Scope& resource_scope = *state_.resource_scopes.at(&resource);
            for (const ast::ProgramInstance& instance : resource.programs) {
                resolve_program_instance(instance, resource_scope,
                                         *state_.connection_scopes.at(&configuration));
            }
        }
    }

    /// `PROGRAM inst WITH task : Type (…)` (ed. 3, 6.8.2).
    void resolve_program_instance(const ast::ProgramInstance& instance, const Scope& resource_scope,
                                  const Scope& connections) {
        check_not_a_global(instance.name);
        if (instance.task) {
            const Symbol* task = resource_scope.find_member(instance.task->name);
            if (task == nullptr || task->kind != SymbolKind::Task) {
                error(DiagnosticCode::E0209, instance.task->range,
                      fmt::format("unknown task '{}'", instance.task->name));
            } else {
                model_.bind(*instance.task, *task);
            }
        }
        const Symbol* program = global_.find_member(instance.type.name);
        if (program == nullptr || program->kind != SymbolKind::Pou ||
            program->pou->kind != ast::PouKind::Program) {
            error(program == nullptr ? DiagnosticCode::E0203 : DiagnosticCode::E0204,
                  instance.type.range,
                  program == nullptr ? fmt::format("unknown program type '{}'", instance.type.name)
                                     : fmt::format("'{}' is not a PROGRAM", instance.type.name));
            resolve_arguments(instance.connections, nullptr, instance.type.name, connections);
            return;
        }
        model_.bind(instance.type, *program);
        resolve_arguments(instance.connections, program->members, program->name, connections);
    }

    /// A program instance's variables are watched under its name (`Inst0.x`), global variable
    /// lists' under theirs (`x`): one name cannot be both.
    void check_not_a_global(const ast::Identifier& name) {
        const Symbol* global = global_.find_member(name.name);
        if (global == nullptr || global->kind != SymbolKind::Variable) {
            return;
        }
        Diagnostic diagnostic(
            DiagnosticCode::E0202, name.range,
            fmt::format("'{}' is already the name of a global variable", name.name));
        diagnostic.notes.push_back(
            {global->declared, fmt::format("'{}' was declared here", global->name)});
        state_.diagnostics.report(std::move(diagnostic));
    }

    ResolverState& state_;
    SemanticModel& model_;
    Scope& global_;
    /// One symbol per conversion function actually used, created on first use.
    std::unordered_map<std::string, const Symbol*> conversions_;
};

} // namespace

void resolve_names(std::span<const ast::CompilationUnit> units, ResolverState& state) {
    NameResolver resolver(state);
    for (const ast::CompilationUnit& unit : units) {
        resolver.resolve(unit);
    }
}

} // namespace eposp::compiler::sema
