#include "support_check.hpp"

#include "eposp/compiler/sema/symbol.hpp"
#include "eposp/vm/stdlib/manifest.hpp"
#include "value.hpp"

#include <set>

namespace eposp::reference {

namespace ast = compiler::ast;
namespace types = compiler::types;

namespace {

const std::set<std::string> kFunctions = {"ABS",          "SQRT",
                                          "LN",           "LOG",
                                          "EXP",          "SIN",
                                          "COS",          "TAN",
                                          "ASIN",         "ACOS",
                                          "ATAN",         "ATAN2",
                                          "EXPT",         "MOVE",
                                          "ADD",          "MUL",
                                          "SUB",          "DIV",
                                          "MOD",          "SHL",
                                          "SHR",          "ROL",
                                          "ROR",          "AND",
                                          "OR",           "XOR",
                                          "NOT",          "SEL",
                                          "MAX",          "MIN",
                                          "LIMIT",        "MUX",
                                          "GT",           "GE",
                                          "EQ",           "LE",
                                          "LT",           "NE",
                                          "LEN",          "LEFT",
                                          "RIGHT",        "MID",
                                          "CONCAT",       "INSERT",
                                          "DELETE",       "REPLACE",
                                          "FIND",         "LOWER_BOUND",
                                          "UPPER_BOUND",  "ADD_TIME",
                                          "SUB_TIME",     "MUL_TIME",
                                          "DIV_TIME",     "ADD_DT_TIME",
                                          "SUB_DT_TIME",  "SUB_DATE_DATE",
                                          "SUB_DT_DT",    "CONCAT_DATE_TOD",
                                          "ADD_TOD_TIME", "SUB_TOD_TIME",
                                          "SUB_TOD_TOD"};

bool is_modelled(const sema::Type& type) {
    return shape_of(type) != Shape::Unsupported && shape_of(type) != Shape::String;
}

/// A conversion whose result the standard leaves to the implementation: the evaluator
/// refuses it.
bool real_and_time_or_bool(const types::CallTarget& target) {
    const auto other = [](const sema::Type& type) {
        return sema::is_time_like(type) || sema::is_bool(type);
    };
    return (sema::is_real(*target.operand) && other(*target.result)) ||
           (sema::is_real(*target.result) && other(*target.operand));
}

class Checker {
public:
    explicit Checker(const types::TypedProgram& program) : program_(program) {}

    void sections(const std::vector<ast::DeclarationSection>& sections) {
        for (const ast::DeclarationSection& section : sections) {
            const auto* variables = std::get_if<ast::VarSection>(&section);
            if (variables == nullptr) {
                throw Unsupported("VAR_ACCESS");
            }
            for (const ast::VariableDeclaration& declaration : variables->variables) {
                // Outputs and markers are plain memory in a simulation; inputs are the host's.
                if (declaration.address &&
                    declaration.address->area == ast::DirectAddress::Area::Input) {
                    throw Unsupported("variables located at inputs (AT %I...)");
                }
            }
        }
    }

    void statements(const ast::StatementList& list) {
        for (const ast::Statement& statement : list) {
            std::visit([&](const auto& node) { this->statement(node); }, statement.node);
        }
    }

private:
    void statement(const ast::AssignmentStatement& node) {
        expression(*node.target);
        expression(*node.value);
    }
    void statement(const ast::CallStatement& node) { expression(*node.call); }
    void statement(const ast::IfStatement& node) {
        for (const ast::ConditionalBlock& branch : node.branches) {
            expression(*branch.condition);
            statements(branch.body);
        }
        statements(node.else_body);
    }
    void statement(const ast::CaseStatement& node) {
        expression(*node.selector);
        for (const ast::CaseBranch& branch : node.branches) {
            statements(branch.body);
        }
        statements(node.else_body);
    }
    void statement(const ast::ForStatement& node) {
        expression(*node.from);
        expression(*node.to);
        if (node.by) {
            expression(*node.by);
        }
        statements(node.body);
    }
    void statement(const ast::WhileStatement& node) {
        expression(*node.condition);
        statements(node.body);
    }
    void statement(const ast::RepeatStatement& node) {
        statements(node.body);
        expression(*node.until);
    }
    template <typename T>
    void statement(const T&) {}

    void expression(const ast::Expression& expression) {
        if (const sema::Type* type = program_.type_of(expression);
            type != nullptr && shape_of(*type) == Shape::Unsupported) {
            throw Unsupported("values of type " + type->name);
        }
        std::visit([&](const auto& node) { this->node(expression, node); }, expression.node);
    }
    void node(const ast::Expression&, const ast::LiteralExpression& node) {
        if (std::holds_alternative<ast::NullLiteral>(node.value)) {
            throw Unsupported("NULL");
        }
    }
    void node(const ast::Expression&, const ast::NameExpression&) {}
    void node(const ast::Expression&, const ast::DirectAddressExpression&) {
        throw Unsupported("direct addresses (%I, %Q, %M)");
    }
    void node(const ast::Expression&, const ast::MemberExpression& node) {
        expression(*node.object);
    }
    void node(const ast::Expression&, const ast::BitAccessExpression& node) {
        expression(*node.object);
    }
    void node(const ast::Expression&, const ast::IndexExpression& node) {
        expression(*node.array);
        for (const ast::ExpressionPtr& index : node.indices) {
            expression(*index);
        }
    }
    void node(const ast::Expression&, const ast::DereferenceExpression&) {
        throw Unsupported("pointers and references (^)");
    }
    void node(const ast::Expression&, const ast::ReferenceExpression&) {
        throw Unsupported("pointers and references (REF)");
    }
    void node(const ast::Expression& expression, const ast::CallExpression& node) {
        const types::CallTarget* target = program_.call_target(expression);
        if (target == nullptr) {
            throw Unsupported("a call the typing stage did not resolve");
        }
        // Every row of table 30, short and long (standard_functions.cpp reads the row).
        const vm::stdlib::StandardFunction* row = vm::stdlib::find_standard_function(target->name);
        const bool time = row != nullptr && row->family == vm::stdlib::Family::Time;
        if (target->kind == types::CallKind::StandardFunction &&
            !kFunctions.contains(target->name) && !time) {
            throw Unsupported("the standard function " + target->name);
        }
        const bool decimal = target->kind == types::CallKind::Conversion &&
                             shape_of(*target->result) == Shape::String &&
                             is_decimal(*target->operand);
        if (target->kind == types::CallKind::Conversion && !decimal &&
            (!is_modelled(*target->operand) || !is_modelled(*target->result))) {
            throw Unsupported("the conversion " + target->name +
                              " (only integers convert to strings)");
        }
        if (target->kind == types::CallKind::Conversion && real_and_time_or_bool(*target)) {
            throw Unsupported("the conversion " + target->name +
                              " (between REAL and TIME, a date or BOOL)");
        }
        if (target->kind == types::CallKind::StandardFunctionBlock && target->name == "RTC") {
            throw Unsupported("the standard function block RTC");
        }
        for (const ast::Argument& argument : node.arguments) {
            this->expression(*argument.value);
        }
    }
    void node(const ast::Expression&, const ast::UnaryExpression& node) {
        expression(*node.operand);
    }
    void node(const ast::Expression&, const ast::BinaryExpression& node) {
        expression(*node.left);
        expression(*node.right);
    }

    const types::TypedProgram& program_;
};

} // namespace

void check_supported(const types::FrontEnd& front_end) {
    Checker checker(*front_end.program);
    for (const ast::CompilationUnit& unit : front_end.units) {
        checker.sections(unit.global_variable_lists);
        for (const ast::Pou& pou : unit.pous) {
            checker.sections(pou.sections);
            checker.statements(pou.body);
        }
        for (const ast::Configuration& configuration : unit.configurations) {
            checker.sections(configuration.sections);
            for (const ast::Resource& resource : configuration.resources) {
                checker.sections(resource.sections);
            }
        }
    }
}

} // namespace eposp::reference
