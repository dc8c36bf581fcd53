#include "expression_typer.hpp"

#include "eposp/compiler/sema/standard_library.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "initial_constant.hpp"

#include <fmt/format.h>

namespace eposp::compiler::types {

namespace {

bool fits(const ast::IntegerLiteral& literal, ast::ElementaryType type) {
    const auto range = ast::integer_range(type);
    if (!range) {
        return ast::is_real(type);
    }
    if (literal.negative) {
        return literal.magnitude == 0 ||
               (range->min < 0 &&
                literal.magnitude - 1 <= static_cast<std::uint64_t>(-(range->min + 1)));
    }
    return literal.magnitude <= range->max;
}

/// The integer literal without a type prefix that `expression` is (negated or not); null if
/// it is none.
const ast::IntegerLiteral* integer_literal(const ast::Expression& expression) {
    const ast::Expression* inner = &expression;
    bool negative = false;
    while (const auto* unary = std::get_if<ast::UnaryExpression>(&inner->node)) {
        if (unary->op == ast::UnaryOperator::Not) {
            return nullptr;
        }
        negative = negative != (unary->op == ast::UnaryOperator::Negate);
        inner = unary->operand.get();
    }
    const auto* literal = std::get_if<ast::LiteralExpression>(&inner->node);
    const auto* integer =
        literal != nullptr ? std::get_if<ast::IntegerLiteral>(&literal->value) : nullptr;
    return integer != nullptr && !integer->type && !negative ? integer : nullptr;
}

/// Why a value of `actual` cannot be stored where `target` is expected (`what`).
std::string mismatch(const char* what, const sema::Type& actual, const sema::Type& target) {
    if (std::string_view(what) == "a CASE label") {
        return fmt::format("a CASE label must be a value of {}", target.name);
    }
    if (std::string_view(what) == "an initial value") {
        return fmt::format("the initial value must be a {} {}",
                           target.kind == sema::TypeKind::Enum ? "value of" : "constant",
                           target.name);
    }
    return fmt::format("a {} value cannot be used as {}{}", actual.name, target.name,
                       actual.kind == sema::TypeKind::Elementary &&
                               target.kind == sema::TypeKind::Elementary
                           ? fmt::format(" (convert it with {}_TO_{})", actual.name, target.name)
                           : "");
}

std::string in_out_mismatch(const sema::Field& field, const sema::Type& formal) {
    if (field.type->conformant) {
        return fmt::format("VAR_IN_OUT '{}' needs an array of {} dimension(s) of {}", field.name,
                           formal.dimensions.size(), formal.element->name);
    }
    return fmt::format("VAR_IN_OUT '{}' needs a {} variable", field.name, formal.name);
}

/// Table 22: a WSTRING converts to and from WCHAR only, a STRING to and from every other
/// elementary type; the others between scalars that are no references.
bool converts_explicitly(const sema::Type& from, const sema::Type& to) {
    const bool from_string = from.kind == sema::TypeKind::String;
    const bool to_string = to.kind == sema::TypeKind::String;
    if (from_string && to_string) {
        return true;
    }
    if (from_string || to_string) {
        const sema::Type& other = to_string ? from : to;
        const bool wchar = other.kind == sema::TypeKind::Elementary &&
                           other.elementary == ast::ElementaryType::Wchar;
        return sema::is_scalar(other) && other.kind == sema::TypeKind::Elementary &&
               (to_string ? to.wide : from.wide) == wchar;
    }
    return sema::is_scalar(from) && sema::is_scalar(to) && from.kind != sema::TypeKind::Reference &&
           to.kind != sema::TypeKind::Reference;
}

bool numeric_context(const sema::Type* type) {
    return type != nullptr && type->kind == sema::TypeKind::Elementary &&
           (sema::is_numeric(*type) || sema::is_bit_string(*type));
}

} // namespace

bool is_untyped_literal(const ast::Expression& expression) {
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        return unary->op != ast::UnaryOperator::Not && is_untyped_literal(*unary->operand);
    }
    const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node);
    if (literal == nullptr) {
        return false;
    }
    if (const auto* integer = std::get_if<ast::IntegerLiteral>(&literal->value)) {
        return !integer->type;
    }
    const auto* real = std::get_if<ast::RealLiteral>(&literal->value);
    return real != nullptr && !real->type;
}

ExpressionTyper::ExpressionTyper(TypedProgram& program, Diagnostics& diagnostics)
    : program_(program), diagnostics_(diagnostics) {}

const sema::Type* ExpressionTyper::fail(DiagnosticCode code, const SourceRange& range,
                                        std::string message) {
    diagnostics_.error(code, range, std::move(message));
    return nullptr;
}

bool ExpressionTyper::is_variable(const ast::Expression& expression) const {
    if (const auto* name = std::get_if<ast::NameExpression>(&expression.node)) {
        const sema::Symbol* symbol = program_.model().resolved(name->name);
        return symbol == nullptr || symbol->kind == sema::SymbolKind::Variable ||
               (symbol->kind == sema::SymbolKind::Pou && symbol->pou == current_);
    }
    return std::holds_alternative<ast::MemberExpression>(expression.node) ||
           std::holds_alternative<ast::IndexExpression>(expression.node) ||
           std::holds_alternative<ast::DereferenceExpression>(expression.node) ||
           std::holds_alternative<ast::DirectAddressExpression>(expression.node);
}

bool ExpressionTyper::names_program(const ast::Expression& expression) const {
    const auto* name = std::get_if<ast::NameExpression>(&expression.node);
    const sema::Symbol* symbol = name != nullptr ? program_.model().resolved(name->name) : nullptr;
    return symbol != nullptr &&
           ((symbol->kind == sema::SymbolKind::Pou && symbol->pou->kind == ast::PouKind::Program) ||
            symbol->kind == sema::SymbolKind::ProgramInstance);
}

void ExpressionTyper::pou(const ast::Pou& pou) {
    current_ = &pou;
    // Its instance or frame first: a declaration that refers to the POU itself (`next :
    // REF_TO Link`) is then laid out inside it.
    if (pou.kind == ast::PouKind::Function) {
        program_.types().frame(pou);
    } else {
        program_.types().instance(pou);
    }
    sections(pou.sections);
    statements(pou.body);
    current_ = nullptr;
}

void ExpressionTyper::sections(const std::vector<ast::DeclarationSection>& sections) {
    for (const ast::DeclarationSection& section : sections) {
        const auto* variables = std::get_if<ast::VarSection>(&section);
        if (variables == nullptr) {
            continue;
        }
        for (const ast::VariableDeclaration& declaration : variables->variables) {
            type_spec(declaration.type);
            if (declaration.initial_value) {
                initializer(*declaration.initial_value, program_.types().resolve(declaration.type));
            }
        }
    }
}

void ExpressionTyper::type_declaration(const ast::TypeDeclaration& declaration) {
    type_spec(declaration.type);
    // By its name (`Pct`), which its diagnostics say; laid out even when nothing uses it, so
    // that its errors are reported.
    const sema::Symbol* symbol = program_.model().global().find_member(declaration.name.name);
    const sema::Type* type = symbol != nullptr && symbol->type == &declaration
                                 ? program_.types().named(*symbol)
                                 : program_.types().resolve(declaration.type);
    if (declaration.initial_value) {
        initializer(*declaration.initial_value, type);
    }
}

void ExpressionTyper::type_spec(const ast::TypeSpec& spec) {
    // Members of a STRUCT, inline or declared, have initial values of their own.
    if (const auto* structure = std::get_if<ast::StructType>(&spec.node)) {
        for (const ast::VariableDeclaration& member : structure->members) {
            type_spec(member.type);
            if (member.initial_value) {
                initializer(*member.initial_value, program_.types().resolve(member.type));
            }
        }
    } else if (const auto* array = std::get_if<ast::ArrayType>(&spec.node)) {
        type_spec(*array->element);
    }
}

const sema::Type& ExpressionTyper::address_type(const ast::DirectAddress& address) {
    // 6.5.5: the size prefix is the type (X or none BOOL, B BYTE, W WORD, ...).
    static constexpr E kBySize[] = {E::Bool, E::Bool, E::Byte, E::Word, E::Dword, E::Lword};
    return elementary(kBySize[static_cast<int>(address.size)]);
}

void ExpressionTyper::configuration(const ast::Configuration& configuration) {
    access_paths(configuration);
    sections(configuration.sections);
    for (const ast::Resource& resource : configuration.resources) {
        sections(resource.sections);
        for (const ast::ProgramInstance& instance : resource.programs) {
            connections(instance);
        }
    }
}

const sema::Type* ExpressionTyper::program_instance(const ast::ProgramInstance& instance) {
    const sema::Symbol* program = program_.model().resolved(instance.type);
    return program != nullptr && program->kind == sema::SymbolKind::Pou
               ? program_.types().instance(*program->pou)
               : nullptr;
}

void ExpressionTyper::connections(const ast::ProgramInstance& instance) {
    // 6.8.2: a source is stored into the program's input, an output into its sink; what they
    // may name is the checking stage's (checks/program_connections.cpp).
    const sema::Type* type = program_instance(instance);
    for (const ast::Argument& connection : instance.connections) {
        const bool output = connection.kind == ast::Argument::Kind::Output;
        const sema::Field* field =
            type != nullptr && connection.name ? type->field(connection.name->name) : nullptr;
        if (field == nullptr ||
            field->section != (output ? ast::VarSectionKind::Output : ast::VarSectionKind::Input)) {
            if (type != nullptr) {
                diagnostics_.error(DiagnosticCode::E0210, connection.range,
                                   fmt::format("'{}' has no {} of that name", type->name,
                                               output ? "output" : "input"));
            }
            this->type(*connection.value, nullptr);
            continue;
        }
        if (!output) {
            expect(*connection.value, *field->type, "a value");
            continue;
        }
        const sema::Type* sink = this->type(*connection.value, nullptr);
        if (sink != nullptr && !sema::converts_implicitly(*field->type, *sink)) {
            diagnostics_.error(DiagnosticCode::E0301, connection.value->range,
                               mismatch("a value", *field->type, *sink));
        }
    }
}

void ExpressionTyper::initializer(const ast::Initializer& initializer, const sema::Type* target) {
    if (target == nullptr) {
        return;
    }
    if (const auto* expression = std::get_if<ast::ExpressionPtr>(&initializer.value)) {
        const std::size_t errors = diagnostics_.error_count();
        store(**expression, *target, "an initial value");
        // The image holds the value folded (a constant defined through itself has none): what
        // code generation writes (codegen/initial_values.cpp).
        if (errors == diagnostics_.error_count()) {
            const auto bytes = constant_bytes(**expression, *target, program_.types());
            if (const auto* refusal = std::get_if<ConstantRefusal>(&bytes)) {
                diagnostics_.error(refusal->code, (*expression)->range, refusal->message);
            }
        }
    } else if (const auto* elements =
                   std::get_if<std::vector<ast::ArrayInitElement>>(&initializer.value)) {
        if (target->kind != sema::TypeKind::Array) {
            diagnostics_.error(DiagnosticCode::E0301, initializer.range,
                               fmt::format("{} is not an array", target->name));
            return;
        }
        for (const ast::ArrayInitElement& element : *elements) {
            if (element.repeat_count) {
                const std::size_t errors = diagnostics_.error_count();
                type(*element.repeat_count, &elementary(E::Dint));
                if (errors == diagnostics_.error_count() &&
                    program_.types().fold_integer(*element.repeat_count).value_or(-1) < 0) {
                    diagnostics_.error(DiagnosticCode::E0313, element.repeat_count->range,
                                       "a repetition count must be a constant >= 0");
                }
            }
            if (element.value) {
                this->initializer(*element.value, target->element);
            }
        }
    } else {
        for (const ast::StructInitElement& element :
             std::get<std::vector<ast::StructInitElement>>(initializer.value)) {
            const sema::Field* field = target->field(element.member.name);
            if (element.value) {
                this->initializer(*element.value, field != nullptr ? field->type : nullptr);
            }
        }
    }
}

void ExpressionTyper::statements(const ast::StatementList& list) {
    for (const ast::Statement& statement : list) {
        this->statement(statement);
    }
}

void ExpressionTyper::case_label_constant(const ast::CaseLabel& label, const sema::Type& selector) {
    // As code generation folds them: a ULINT or LWORD selector's labels as unsigned numbers.
    sema::TypeTable& types = program_.types();
    const bool unsigned64 = sema::scalar_of(selector) == vm::Scalar::U64;
    const auto folds = [&](const ast::ExpressionPtr& bound, bool as_unsigned) {
        return !bound || (as_unsigned ? types.fold_unsigned(*bound).has_value()
                                      : types.fold_integer(*bound).has_value());
    };
    if (folds(label.low, unsigned64) && folds(label.high, unsigned64)) {
        return;
    }
    const bool constant = folds(label.low, true) && folds(label.high, true);
    diagnostics_.error(constant ? DiagnosticCode::E0301 : DiagnosticCode::E0313, label.range,
                       constant ? fmt::format("a CASE label must be a value of {}", selector.name)
                                : "a CASE label must be a constant");
}

void ExpressionTyper::condition(const ast::Expression& expression) {
    expect(expression, elementary(E::Bool), "a condition");
}

void ExpressionTyper::expect(const ast::Expression& expression, const sema::Type& target,
                             const char* what) {
    const sema::Type* actual = type(expression, &target);
    if (actual == nullptr) {
        return;
    }
    const sema::Type& to = program_.types().unranged(target);
    const sema::Type& from = program_.types().unranged(*actual);
    if (sema::converts_implicitly(from, to) || sema::conforms(*actual, target)) {
        return;
    }
    if (const auto* integer = integer_literal(expression);
        integer != nullptr && sema::is_integer(to) && std::string_view(what) != "a CASE label") {
        diagnostics_.error(DiagnosticCode::E0311, expression.range,
                           fmt::format("the value {}{} does not fit in {}",
                                       integer->negative ? "-" : "", integer->magnitude, to.name));
        return;
    }
    // An initial value is a constant of the variable's type (an enumeration value is its
    // number where an integer is expected).
    if (std::string_view(what) == "an initial value" && actual->kind == sema::TypeKind::Enum &&
        sema::is_integer(to)) {
        return;
    }
    diagnostics_.error(std::string_view(what) == "an initial value" &&
                               target.kind != sema::TypeKind::Enum
                           ? DiagnosticCode::E0313
                           : DiagnosticCode::E0301,
                       expression.range, mismatch(what, *actual, target));
}

void ExpressionTyper::store(const ast::Expression& expression, const sema::Type& target,
                            const char* what) {
    expect(expression, target, what);
    program_.add_store({&expression, &target, current_});
}

void ExpressionTyper::statement(const ast::Statement& statement) {
    std::visit(
        [&](const auto& node) {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::AssignmentStatement>) {
                const auto* member = std::get_if<ast::MemberExpression>(&node.target->node);
                if (member != nullptr && program_.model().enum_value(*node.target) != nullptr) {
                    const auto* object = std::get_if<ast::NameExpression>(&member->object->node);
                    diagnostics_.error(DiagnosticCode::E0204, member->object->range,
                                       fmt::format("'{}' is not a variable",
                                                   object != nullptr ? object->name.name : "?"));
                    type(*node.value, nullptr);
                    return;
                }
                if (!is_variable(*node.target) &&
                    !std::holds_alternative<ast::BitAccessExpression>(node.target->node) &&
                    !std::holds_alternative<ast::NameExpression>(node.target->node)) {
                    diagnostics_.error(DiagnosticCode::E0315, node.target->range,
                                       "this expression is not a variable");
                    type(*node.value, nullptr);
                    return;
                }
                if (const sema::Type* target = type(*node.target, nullptr)) {
                    store(*node.value, *target, "a value");
                }
            } else if constexpr (std::is_same_v<T, ast::CallStatement>) {
                statement_call_ = node.call.get();
                type(*node.call, nullptr);
            } else if constexpr (std::is_same_v<T, ast::IfStatement>) {
                for (const ast::ConditionalBlock& branch : node.branches) {
                    condition(*branch.condition);
                    statements(branch.body);
                }
                statements(node.else_body);
            } else if constexpr (std::is_same_v<T, ast::CaseStatement>) {
                const sema::Type* selector = type(*node.selector, nullptr);
                if (selector != nullptr && selector->kind != sema::TypeKind::Enum &&
                    !sema::is_integer(program_.types().unranged(*selector)) &&
                    !sema::is_bit_string(*selector)) {
                    diagnostics_.error(
                        DiagnosticCode::E0304, node.selector->range,
                        fmt::format("a CASE selector must be an integer or enumeration, not {}",
                                    selector->name));
                    selector = nullptr;
                }
                for (const ast::CaseBranch& branch : node.branches) {
                    for (const ast::CaseLabel& label : branch.labels) {
                        const std::size_t errors = diagnostics_.error_count();
                        for (const ast::ExpressionPtr* bound : {&label.low, &label.high}) {
                            if (*bound && selector != nullptr) {
                                expect(**bound, *selector, "a CASE label");
                            }
                        }
                        if (selector != nullptr && errors == diagnostics_.error_count()) {
                            case_label_constant(label, *selector);
                        }
                    }
                    statements(branch.body);
                }
                statements(node.else_body);
            } else if constexpr (std::is_same_v<T, ast::ForStatement>) {
                const sema::Symbol* symbol = program_.model().resolved(node.control_variable);
                const sema::Type* control = symbol != nullptr ? variable_type(*symbol) : nullptr;
                if (control != nullptr) {
                    expect(*node.from, *control, "a FOR bound");
                    expect(*node.to, *control, "a FOR bound");
                    if (node.by) {
                        expect(*node.by, *control, "a FOR step");
                    }
                }
                statements(node.body);
            } else if constexpr (std::is_same_v<T, ast::WhileStatement>) {
                condition(*node.condition);
                statements(node.body);
            } else if constexpr (std::is_same_v<T, ast::RepeatStatement>) {
                statements(node.body);
                condition(*node.until);
            }
        },
        statement.node);
}

const sema::Type* ExpressionTyper::variable_type(const sema::Symbol& symbol) {
    if (symbol.variable != nullptr) {
        return program_.types().resolve(symbol.variable->type);
    }
    if (!symbol.standard_type.empty()) {
        if (const auto e = ast::elementary_type_from_name(symbol.standard_type)) {
            return &elementary(*e);
        }
    }
    return nullptr;
}

const sema::Type* ExpressionTyper::type(const ast::Expression& expression,
                                        const sema::Type* expected) {
    const sema::Type* result = std::visit(
        [&](const auto& node) -> const sema::Type* {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::LiteralExpression>) {
                return literal(expression, node.value, expected);
            } else if constexpr (std::is_same_v<T, ast::NameExpression>) {
                return name(expression, node);
            } else if constexpr (std::is_same_v<T, ast::MemberExpression>) {
                return member(expression, node);
            } else if constexpr (std::is_same_v<T, ast::BitAccessExpression>) {
                const sema::Type* word = type(*node.object, nullptr);
                if (word != nullptr && !sema::is_bit_string(*word) && !sema::is_integer(*word)) {
                    return fail(DiagnosticCode::E0304, expression.range,
                                fmt::format("bit access needs a bit string, not {}", word->name));
                }
                if (word != nullptr && node.bit >= word->size * 8) {
                    return fail(DiagnosticCode::E0105, expression.range,
                                fmt::format("{} has no bit {}", word->name, node.bit));
                }
                return &elementary(E::Bool);
            } else if constexpr (std::is_same_v<T, ast::IndexExpression>) {
                return index(expression, node);
            } else if constexpr (std::is_same_v<T, ast::DereferenceExpression>) {
                const sema::Type* reference = type(*node.reference, nullptr);
                if (reference != nullptr && (reference->kind != sema::TypeKind::Reference ||
                                             reference->element == nullptr)) {
                    return fail(DiagnosticCode::E0304, expression.range,
                                fmt::format("'^' needs a reference, not {}", reference->name));
                }
                return reference != nullptr ? reference->element : nullptr;
            } else if constexpr (std::is_same_v<T, ast::ReferenceExpression>) {
                const sema::Type* target = type(*node.target, nullptr);
                return target != nullptr ? &program_.types().reference(target) : nullptr;
            } else if constexpr (std::is_same_v<T, ast::CallExpression>) {
                const bool statement = statement_call_ == &expression;
                statement_call_ = nullptr;
                const sema::Type* value = call(expression, node, expected);
                if (value == nullptr && !statement && program_.call_target(expression) != nullptr) {
                    return fail(DiagnosticCode::E0309, expression.range, "this call has no value");
                }
                return value;
            } else if constexpr (std::is_same_v<T, ast::UnaryExpression>) {
                return unary(expression, node, expected);
            } else if constexpr (std::is_same_v<T, ast::BinaryExpression>) {
                return binary(expression, node, expected);
            } else {
                return &address_type(node.address);
            }
        },
        expression.node);
    if (result != nullptr) {
        program_.set_type(expression, *result);
        fold(expression, *result);
    }
    return result;
}

const sema::Type* ExpressionTyper::literal(const ast::Expression& expression,
                                           const ast::Literal& literal,
                                           const sema::Type* expected) {
    if (const auto* integer = std::get_if<ast::IntegerLiteral>(&literal)) {
        if (integer->type) {
            if (!fits(*integer, *integer->type)) {
                return fail(
                    DiagnosticCode::E0311, expression.range,
                    fmt::format("the literal does not fit {}", ast::name_of(*integer->type)));
            }
            return &elementary(*integer->type);
        }
        if (numeric_context(expected) && fits(*integer, expected->elementary)) {
            return &program_.types().unranged(*expected);
        }
        for (const E e : {E::Dint, E::Lint, E::Ulint}) {
            if (fits(*integer, e)) {
                return &elementary(e);
            }
        }
        return fail(DiagnosticCode::E0311, expression.range, "the literal fits no integer type");
    }
    if (const auto* real = std::get_if<ast::RealLiteral>(&literal)) {
        if (real->type) {
            return &elementary(*real->type);
        }
        return expected != nullptr && sema::is_real(*expected) ? expected : &elementary(E::Lreal);
    }
    if (std::holds_alternative<ast::BoolLiteral>(literal)) {
        return &elementary(E::Bool);
    }
    if (const auto* duration = std::get_if<ast::DurationLiteral>(&literal)) {
        return &elementary(duration->type);
    }
    if (const auto* date = std::get_if<ast::DateTimeLiteral>(&literal)) {
        return &elementary(date->type);
    }
    if (const auto* text = std::get_if<ast::StringLiteral>(&literal)) {
        if (text->type == E::Char || text->type == E::Wchar) {
            return &elementary(text->type);
        }
        const std::size_t length =
            std::visit([](const auto& value) { return value.size(); }, text->value);
        return &program_.types().string(static_cast<std::uint32_t>(length),
                                        text->type == E::Wstring);
    }
    if (std::holds_alternative<ast::EnumValueLiteral>(literal)) {
        const sema::Symbol* value = program_.model().enum_value(expression);
        return value != nullptr ? program_.types().enumeration_of(*value) : nullptr;
    }
    return &program_.types().null();
}

const sema::Type* ExpressionTyper::name(const ast::Expression& expression,
                                        const ast::NameExpression& node) {
    if (const sema::Symbol* value = program_.model().enum_value(expression)) {
        return program_.types().enumeration_of(*value);
    }
    const sema::Symbol* symbol = program_.model().resolved(node.name);
    if (symbol == nullptr) {
        return nullptr; // reported by name resolution
    }
    if (symbol->kind == sema::SymbolKind::Variable) {
        return variable_type(*symbol);
    }
    // Inside a FUNCTION its name is its result variable (6.6.2.2).
    if (symbol->kind == sema::SymbolKind::Pou && symbol->pou == current_ &&
        symbol->pou->kind == ast::PouKind::Function && symbol->pou->return_type) {
        return program_.types().resolve(*symbol->pou->return_type);
    }
    // A PROGRAM's name stands for its single instance: `P()`, `P.x` (CODESYS).
    if (symbol->kind == sema::SymbolKind::Pou && symbol->pou->kind == ast::PouKind::Program) {
        return program_.types().instance(*symbol->pou);
    }
    // A configuration's program instance (in a program connection, `P1.out`).
    if (symbol->kind == sema::SymbolKind::ProgramInstance) {
        return program_instance(*symbol->program_instance);
    }
    return fail(DiagnosticCode::E0204, expression.range,
                fmt::format("'{}' is not a variable", symbol->name));
}

const sema::Type* ExpressionTyper::member(const ast::Expression& expression,
                                          const ast::MemberExpression& node) {
    if (const sema::Symbol* value = program_.model().enum_value(expression)) {
        return program_.types().enumeration_of(*value);
    }
    const sema::Type* object = type(*node.object, nullptr);
    if (object == nullptr) {
        return nullptr;
    }
    const sema::Field* field =
        object->kind == sema::TypeKind::Struct || object->kind == sema::TypeKind::Instance
            ? object->field(node.member.name)
            : nullptr;
    if (field == nullptr) {
        return fail(DiagnosticCode::E0206, node.member.range,
                    fmt::format("'{}' has no member '{}'", object->name, node.member.name));
    }
    // 6.5.2.2: only inputs and outputs of an instance are visible outside it; a PROGRAM
    // reached by its name shows all its variables but its in-outs and temporaries (CODESYS).
    const bool program = names_program(*node.object);
    const bool internal = program ? field->section == ast::VarSectionKind::InOut ||
                                        field->section == ast::VarSectionKind::Temp ||
                                        field->declaration == nullptr
                                  : object->kind == sema::TypeKind::Instance &&
                                        (field->section == ast::VarSectionKind::Var ||
                                         field->section == ast::VarSectionKind::InOut);
    if (internal) {
        return fail(DiagnosticCode::E0212, node.member.range,
                    fmt::format("'{}' is internal to '{}'", field->name, object->name));
    }
    return field->type;
}

const sema::Type* ExpressionTyper::index(const ast::Expression& expression,
                                         const ast::IndexExpression& node) {
    const sema::Type* array = type(*node.array, nullptr);
    for (const ast::ExpressionPtr& index : node.indices) {
        const sema::Type* type = this->type(*index, nullptr);
        if (type != nullptr && !sema::is_integer(program_.types().unranged(*type)) &&
            type->kind != sema::TypeKind::Enum) {
            diagnostics_.error(
                DiagnosticCode::E0307, index->range,
                fmt::format("an array index must be an integer, not {}", type->name));
        }
    }
    if (array == nullptr) {
        return nullptr;
    }
    if (array->kind != sema::TypeKind::Array) {
        return fail(DiagnosticCode::E0308, expression.range,
                    fmt::format("{} is not an array", array->name));
    }
    if (node.indices.size() != array->dimensions.size()) {
        return fail(DiagnosticCode::E0308, expression.range,
                    fmt::format("{} needs {} indices", array->name, array->dimensions.size()));
    }
    return array->element;
}

const sema::Type* ExpressionTyper::unary(const ast::Expression& expression,
                                         const ast::UnaryExpression& node,
                                         const sema::Type* expected) {
    const sema::Type* operand = type(*node.operand, expected);
    if (operand == nullptr) {
        return nullptr;
    }
    const sema::Type& plain = program_.types().unranged(*operand);
    if (node.op == ast::UnaryOperator::Not) {
        if (!sema::is_bool(plain) && !sema::is_bit_string(plain) && !sema::is_integer(plain)) {
            return fail(DiagnosticCode::E0304, expression.range,
                        fmt::format("NOT needs a BOOL or bit string, not {}", plain.name));
        }
        return &plain;
    }
    if (!sema::is_numeric(plain) && plain.elementary != E::Time && plain.elementary != E::Ltime) {
        return fail(DiagnosticCode::E0304, expression.range,
                    fmt::format("'-' needs a number, not {}", plain.name));
    }
    return &plain;
}

const sema::Type* ExpressionTyper::common(const sema::Type& a, const sema::Type& b) {
    const sema::Type& x = program_.types().unranged(a);
    const sema::Type& y = program_.types().unranged(b);
    if (sema::converts_implicitly(x, y)) {
        return &y;
    }
    if (sema::converts_implicitly(y, x)) {
        return &x;
    }
    return nullptr;
}

const sema::Type* ExpressionTyper::time_arithmetic(ast::BinaryOperator op, const sema::Type& left,
                                                   const sema::Type& right,
                                                   const SourceRange& range) {
    // 6.6.2.5.5 table 30: durations add and subtract, a point in time moves by a duration (a
    // TIME_OF_DAY wraps around midnight), two points of one type subtract to a duration.
    using Op = ast::BinaryOperator;
    const auto duration = [](const sema::Type& type) {
        return type.kind == sema::TypeKind::Elementary &&
               (type.elementary == E::Time || type.elementary == E::Ltime);
    };
    const bool add_or_subtract = op == Op::Add || op == Op::Subtract;
    if (add_or_subtract && duration(right) && left.elementary != E::Date) {
        return &left;
    }
    if (op == Op::Subtract && left.kind == right.kind && left.elementary == right.elementary) {
        return &elementary(left.elementary == E::Ltime || left.elementary == E::Ldt ? E::Ltime
                                                                                    : E::Time);
    }
    return fail(DiagnosticCode::E0303, range,
                fmt::format("this operation is not defined on {} and {} (use the functions of "
                            "IEC 61131-3 table 30)",
                            left.name, right.name));
}

const sema::Type* ExpressionTyper::unify(const std::vector<const ast::Expression*>& operands,
                                         const sema::Type* expected, const SourceRange& range,
                                         const sema::Type* first) {
    // Typed operands first; the untyped literals then take their common type.
    const sema::Type* result = nullptr;
    bool failed = false;
    for (const bool literals : {false, true}) {
        for (const ast::Expression* operand : operands) {
            if (is_untyped_literal(*operand) != literals) {
                continue;
            }
            const sema::Type* context = result != nullptr ? result : expected;
            if (literals && result != nullptr && !numeric_context(result)) {
                context = nullptr;
            }
            const sema::Type* type = first != nullptr && operand == operands.front()
                                         ? first
                                         : this->type(*operand, context);
            if (type == nullptr) {
                failed = true;
                continue;
            }
            if (result == nullptr) {
                result = &program_.types().unranged(*type);
            } else if (result->kind == sema::TypeKind::String && type->kind == result->kind &&
                       type->wide == result->wide) {
                // Strings of any lengths meet in the longest, which holds each of them.
                result = type->capacity > result->capacity ? type : result;
            } else if (const sema::Type* both = common(*result, *type)) {
                result = both;
            } else {
                diagnostics_.error(DiagnosticCode::E0303, range,
                                   fmt::format("operands of types {} and {} do not match",
                                               result->name, type->name));
                failed = true;
            }
        }
    }
    if (failed) {
        return nullptr;
    }
    // A literal typed before a wider one (`5 > 3000000000`) takes the common type after all;
    // literals have no side effects, so typing one again changes nothing else.
    for (const ast::Expression* operand : operands) {
        if (is_untyped_literal(*operand) && numeric_context(result) &&
            program_.type_of(*operand) != result) {
            type(*operand, result);
        }
    }
    return result;
}

const sema::Type* ExpressionTyper::binary(const ast::Expression& expression,
                                          const ast::BinaryExpression& node,
                                          const sema::Type* expected) {
    using Op = ast::BinaryOperator;
    const SourceRange& range = expression.range;
    switch (node.op) {
    case Op::Power: {
        // EXPT (table 24): IN1 ANY_REAL, IN2 ANY_NUM; the result has IN1's type.
        const sema::Type* base =
            type(*node.left, expected != nullptr && sema::is_real(*expected) ? expected : nullptr);
        type(*node.right, nullptr);
        if (base == nullptr) {
            return nullptr;
        }
        return sema::is_real(*base) ? base : &elementary(E::Lreal);
    }
    case Op::Less:
    case Op::Greater:
    case Op::LessEqual:
    case Op::GreaterEqual:
    case Op::Equal:
    case Op::NotEqual: {
        const sema::Type* operands = unify({node.left.get(), node.right.get()}, nullptr, range);
        if (operands != nullptr && operands->kind != sema::TypeKind::String &&
            !sema::is_scalar(*operands)) {
            return fail(DiagnosticCode::E0304, range,
                        fmt::format("values of type {} cannot be compared", operands->name));
        }
        return operands != nullptr ? &elementary(E::Bool) : nullptr;
    }
    case Op::And:
    case Op::Or:
    case Op::Xor: {
        const sema::Type* operands = unify({node.left.get(), node.right.get()}, expected, range);
        if (operands != nullptr && !sema::is_bool(*operands) && !sema::is_bit_string(*operands) &&
            !sema::is_integer(*operands)) {
            return fail(
                DiagnosticCode::E0304, range,
                fmt::format("AND, OR and XOR need BOOL or bit strings, not {}", operands->name));
        }
        return operands;
    }
    default:
        break;
    }
    // The left operand decides first whether this is a TIME scaled by a number (table 30) or
    // a pointer moved by a number of bytes.
    const sema::Type* left = nullptr;
    if (node.op != Op::Modulo && !is_untyped_literal(*node.left)) {
        const bool scale = node.op == Op::Multiply || node.op == Op::Divide;
        // A product's left operand is typed without a TIME context, which would make a TIME of
        // its literals; a numeric context still types them (`x := 2 * 3 * 5` with x an INT).
        left = type(*node.left, !scale || numeric_context(expected) ? expected : nullptr);
        if (left == nullptr) {
            type(*node.right, nullptr);
            return nullptr;
        }
        if (scale && (left->elementary == E::Time || left->elementary == E::Ltime) &&
            left->kind == sema::TypeKind::Elementary) {
            const sema::Type* factor = type(*node.right, &elementary(E::Lint));
            if (factor != nullptr && !sema::is_numeric(*factor)) {
                return fail(DiagnosticCode::E0304, node.right->range,
                            fmt::format("a TIME is multiplied or divided by a number, not {}",
                                        factor->name));
            }
            return factor != nullptr ? left : nullptr;
        }
        if (!scale && left->kind == sema::TypeKind::Reference) {
            const sema::Type* bytes = type(*node.right, &elementary(E::Lint));
            if (bytes != nullptr && !sema::is_integer(program_.types().unranged(*bytes))) {
                return fail(DiagnosticCode::E0304, node.right->range,
                            fmt::format("a pointer moves by a whole number of bytes, not by a {}",
                                        bytes->name));
            }
            return bytes != nullptr ? left : nullptr;
        }
        if (!scale && sema::is_time_like(*left)) {
            const sema::Type* right = type(*node.right, nullptr);
            return right != nullptr ? time_arithmetic(node.op, *left, *right, range) : nullptr;
        }
    }
    const sema::Type* operands = unify({node.left.get(), node.right.get()}, expected, range, left);
    if (operands == nullptr) {
        return nullptr;
    }
    if (node.op == Op::Modulo && !sema::is_integer(*operands) && !sema::is_bit_string(*operands)) {
        return fail(DiagnosticCode::E0304, range,
                    fmt::format("MOD needs integers, not {}", operands->name));
    }
    if (sema::is_numeric(*operands) || sema::is_bit_string(*operands)) {
        return operands;
    }
    return fail(DiagnosticCode::E0304, range,
                fmt::format("arithmetic needs numbers, not {}", operands->name));
}

std::vector<const ast::Argument*> ExpressionTyper::inputs(const ast::CallExpression& node) {
    std::vector<const ast::Argument*> result;
    for (const ast::Argument& argument : node.arguments) {
        if (argument.name && (sema::fold_case(argument.name->name) == "EN" ||
                              sema::fold_case(argument.name->name) == "ENO")) {
            if (argument.kind == ast::Argument::Kind::Input) {
                condition(*argument.value);
            } else if (const sema::Type* eno = type(*argument.value, nullptr);
                       eno != nullptr && !sema::is_bool(*eno)) {
                diagnostics_.error(DiagnosticCode::E0301, argument.value->range,
                                   fmt::format("ENO needs a BOOL variable, not {}", eno->name));
            }
            continue;
        }
        result.push_back(&argument);
    }
    return result;
}

const sema::Type* ExpressionTyper::call(const ast::Expression& expression,
                                        const ast::CallExpression& node,
                                        const sema::Type* expected) {
    if (const auto* callee = std::get_if<ast::NameExpression>(&node.callee->node)) {
        const sema::Symbol* symbol = program_.model().resolved(callee->name);
        if (symbol != nullptr && symbol->kind == sema::SymbolKind::Pou &&
            symbol->pou->kind == ast::PouKind::Function) {
            return pou_call(expression, node, *symbol->pou, nullptr);
        }
        const std::string upper = sema::fold_case(callee->name.name);
        if ((symbol == nullptr || symbol->kind == sema::SymbolKind::StandardFunction) &&
            (sema::is_conversion_function(upper) || upper == "TRUNC")) {
            return conversion(expression, node, upper);
        }
        if (symbol != nullptr && symbol->kind == sema::SymbolKind::StandardFunction) {
            return standard_call(expression, node, upper, expected);
        }
    }
    if (const auto* callee = std::get_if<ast::NameExpression>(&node.callee->node)) {
        const sema::Symbol* symbol = program_.model().resolved(callee->name);
        if (symbol != nullptr && (symbol->kind == sema::SymbolKind::StandardFunctionBlock ||
                                  (symbol->kind == sema::SymbolKind::Pou &&
                                   symbol->pou->kind == ast::PouKind::FunctionBlock))) {
            inputs(node);
            return fail(DiagnosticCode::E0204, expression.range,
                        fmt::format("'{}' is a {} type: call an instance of it", symbol->name,
                                    symbol->kind == sema::SymbolKind::Pou ? "FUNCTION_BLOCK"
                                                                          : "function block"));
        }
    }
    const sema::Type* instance = type(*node.callee, nullptr);
    if (instance == nullptr) {
        return nullptr;
    }
    if (instance->kind != sema::TypeKind::Instance || instance->pou == nullptr) {
        return fail(DiagnosticCode::E0204, node.callee->range,
                    fmt::format("a {} cannot be called: it is not a function block instance",
                                instance->name));
    }
    return pou_call(expression, node, *instance->pou, instance);
}

const sema::Type* ExpressionTyper::pou_call(const ast::Expression& expression,
                                            const ast::CallExpression& node, const ast::Pou& pou,
                                            const sema::Type* instance) {
    // Positional arguments take the inputs and in-outs in declaration order (6.6.1.4.2).
    const sema::Type* frame = instance != nullptr ? instance : program_.types().frame(pou);
    std::vector<const sema::Field*> positional;
    if (frame != nullptr) {
        for (const sema::Field& field : frame->fields) {
            if (field.section == ast::VarSectionKind::Input ||
                field.section == ast::VarSectionKind::InOut) {
                positional.push_back(&field);
            }
        }
    }
    std::size_t next = 0;
    const std::string& callee = instance != nullptr ? instance->name : pou.name.name;
    for (const ast::Argument* argument : inputs(node)) {
        const sema::Field* field = nullptr;
        if (argument->name) {
            field = frame != nullptr ? frame->field(argument->name->name) : nullptr;
        } else if (next < positional.size()) {
            field = positional[next++];
        }
        const bool output = argument->kind == ast::Argument::Kind::Output;
        if (field == nullptr) {
            type(*argument->value, nullptr);
            // An FB's positional arguments are the checking stage's (E0415).
            if (argument->name || instance == nullptr) {
                diagnostics_.error(
                    argument->name ? DiagnosticCode::E0210 : DiagnosticCode::E0306, argument->range,
                    argument->name ? fmt::format("'{}' has no {} '{}'", callee,
                                                 output ? "output" : "input", argument->name->name)
                                   : fmt::format("too many arguments for '{}'", callee));
            }
            continue;
        }
        if (output != (field->section == ast::VarSectionKind::Output) ||
            (field->section != ast::VarSectionKind::Input &&
             field->section != ast::VarSectionKind::InOut &&
             field->section != ast::VarSectionKind::Output)) {
            type(*argument->value, nullptr);
            diagnostics_.error(DiagnosticCode::E0210, argument->range,
                               fmt::format("'{}' is not an {} of '{}'", field->name,
                                           output ? "output" : "input", callee));
            continue;
        }
        if ((output || field->section == ast::VarSectionKind::InOut) &&
            !is_variable(*argument->value)) {
            type(*argument->value, nullptr);
            diagnostics_.error(DiagnosticCode::E0315, argument->value->range,
                               "this expression is not a variable");
            continue;
        }
        if (field->type->generic) {
            // ANY (a native function's): an elementary value or a string, with its own type.
            const sema::Type* actual = type(*argument->value, nullptr);
            if (actual != nullptr && actual->kind != sema::TypeKind::Elementary &&
                actual->kind != sema::TypeKind::Enum && actual->kind != sema::TypeKind::String) {
                diagnostics_.error(
                    DiagnosticCode::E0305, argument->value->range,
                    fmt::format("ANY takes an elementary value or a string, not a {}",
                                actual->name));
            }
            continue;
        }
        if (output) {
            const sema::Type* target = type(*argument->value, nullptr);
            if (target != nullptr && !sema::converts_implicitly(*field->type, *target)) {
                diagnostics_.error(DiagnosticCode::E0301, argument->range,
                                   fmt::format("output {} of type {} goes into {}", field->name,
                                               field->type->name, target->name));
            }
        } else if (field->section == ast::VarSectionKind::InOut) {
            // A VAR_IN_OUT is held as a reference to the variable passed (6.6.1.2.2).
            const bool by_reference =
                field->type->kind == sema::TypeKind::Reference ||
                (field->type->kind == sema::TypeKind::Struct && field->type->conformant);
            const sema::Type& formal = by_reference && field->type->element != nullptr
                                           ? *field->type->element
                                           : *field->type;
            const sema::Type* actual = type(*argument->value, &formal);
            if (actual != nullptr && !sema::same_type(*actual, formal) &&
                !sema::conforms(*actual, formal) &&
                !(actual->kind == sema::TypeKind::String && formal.kind == actual->kind)) {
                diagnostics_.error(DiagnosticCode::E0302, argument->range,
                                   in_out_mismatch(*field, formal));
            }
        } else {
            store(*argument->value, *field->type, "an input");
        }
    }
    CallTarget target;
    target.pou = &pou;
    if (instance != nullptr) {
        const ast::Pou* library = nullptr;
        target.kind = CallKind::FunctionBlock;
        if (const sema::Symbol* symbol = program_.model().global().find(pou.name.name);
            symbol != nullptr && symbol->kind == sema::SymbolKind::StandardFunctionBlock) {
            library = &pou;
        }
        if (library != nullptr) {
            target.kind = CallKind::StandardFunctionBlock;
            target.name = sema::fold_case(pou.name.name);
        }
        program_.set_call(expression, target);
        return nullptr;
    }
    target.kind = CallKind::Function;
    target.result = pou.return_type ? program_.types().resolve(*pou.return_type) : nullptr;
    program_.set_call(expression, target);
    return target.result;
}

const sema::Type* ExpressionTyper::conversion(const ast::Expression& expression,
                                              const ast::CallExpression& node,
                                              const std::string& name) {
    inputs(node); // EN and ENO
    const auto arguments = standard_arguments("TO", node);
    if (arguments.size() != 1 || arguments[0] == nullptr) {
        return fail(DiagnosticCode::E0306, expression.range,
                    fmt::format("{} takes one input", name));
    }
    CallTarget target{.kind = CallKind::Conversion, .name = name};
    const sema::Type* source = nullptr;
    const sema::Type* result = nullptr;
    if (name == "TRUNC") {
        // Table 22: TRUNC of an ANY_REAL; the project truncates to DINT.
        source = type(*arguments[0]->value, nullptr);
        if (source != nullptr && !sema::is_real(*source)) {
            return fail(DiagnosticCode::E0305, expression.range,
                        fmt::format("TRUNC needs a REAL, not {}", source->name));
        }
        result = &elementary(E::Dint);
    } else {
        const auto separator = name.find("_TO_");
        const std::string to =
            name.starts_with("TO_") ? name.substr(3) : name.substr(separator + 4);
        const auto to_type = ast::elementary_type_from_name(to);
        result = *to_type == E::String || *to_type == E::Wstring
                     ? &program_.types().string(80, *to_type == E::Wstring)
                     : &elementary(*to_type);
        if (name.starts_with("TO_")) {
            source = type(*arguments[0]->value, nullptr);
        } else {
            const auto from = *ast::elementary_type_from_name(name.substr(0, separator));
            const sema::Type& from_type = from == E::String || from == E::Wstring
                                              ? program_.types().string(80, from == E::Wstring)
                                              : elementary(from);
            expect(*arguments[0]->value, from_type, "a conversion's input");
            source = &from_type;
        }
    }
    if (source == nullptr) {
        return nullptr;
    }
    if (!converts_explicitly(program_.types().unranged(*source), *result)) {
        return fail(DiagnosticCode::E0310, expression.range,
                    fmt::format("{} cannot be converted to {}", source->name, result->name));
    }
    target.operand = &program_.types().unranged(*source);
    target.result = result;
    program_.set_call(expression, target);
    return result;
}

} // namespace eposp::compiler::types
