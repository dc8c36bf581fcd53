#include "resolve_helpers.hpp"

#include "eposp/compiler/parser.hpp"
#include "eposp/compiler/sema/resolver.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

/// The identifier an expression ends in: `x`, the `c` of `a.b.c`, `Red` of `Color#Red`.
const ast::Identifier* last_identifier(const ast::Expression& expression) {
    if (const auto* name = std::get_if<ast::NameExpression>(&expression.node)) {
        return &name->name;
    }
    if (const auto* member = std::get_if<ast::MemberExpression>(&expression.node)) {
        return &member->member;
    }
    if (const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node)) {
        if (const auto* value = std::get_if<ast::EnumValueLiteral>(&literal->value)) {
            return &value->value;
        }
    }
    return nullptr;
}

} // namespace

std::vector<std::string> Resolved::messages() const {
    std::vector<std::string> out;
    for (const Diagnostic& diagnostic : diagnostics.all()) {
        out.push_back(diagnostic.message);
    }
    return out;
}

const sema::Symbol* Resolved::assignment_target(std::size_t index) const {
    const auto& body = units.at(0).pous.at(0).body;
    const auto& assignment = std::get<ast::AssignmentStatement>(body.at(index).node);
    const ast::Identifier* identifier = last_identifier(*assignment.target);
    return identifier != nullptr ? model.resolved(*identifier) : nullptr;
}

const sema::Symbol* Resolved::assignment_value(std::size_t index) const {
    const auto& body = units.at(0).pous.at(0).body;
    const auto& assignment = std::get<ast::AssignmentStatement>(body.at(index).node);
    const ast::Identifier* identifier = last_identifier(*assignment.value);
    return identifier != nullptr ? model.resolved(*identifier) : nullptr;
}

std::unique_ptr<Resolved>
resolve_files(const std::vector<std::pair<std::string, std::string>>& files) {
    auto resolved = std::make_unique<Resolved>();
    for (const auto& [path, text] : files) {
        const FileId file = resolved->sources.add(path, text);
        resolved->units.push_back(parse(resolved->sources, file, resolved->diagnostics));
    }
    EXPECT_FALSE(resolved->diagnostics.has_errors()) << resolved->rendered();
    resolved->model = sema::resolve(resolved->units, resolved->diagnostics);
    return resolved;
}

std::unique_ptr<Resolved> resolve_text(const std::string& text) {
    return resolve_files({{"test.st", text}});
}

} // namespace eposp::compiler::test
