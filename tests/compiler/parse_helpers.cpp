#include "parse_helpers.hpp"

#include "eposp/compiler/ast/ast_printer.hpp"
#include "eposp/compiler/parser.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {

std::string Parsed::first_message() const {
    return diagnostics.all().empty() ? "" : diagnostics.all().front().message;
}

Parsed parse_text(const std::string& text, const std::string& path) {
    Parsed parsed;
    const FileId file = parsed.sources.add(path, text);
    parsed.unit = parse(parsed.sources, file, parsed.diagnostics);
    return parsed;
}

std::string statements_sexpr(const std::string& body) {
    const Parsed parsed = parse_text("PROGRAM P\n" + body + "\nEND_PROGRAM\n");
    EXPECT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    if (parsed.unit.pous.empty()) {
        return "<no program>";
    }
    std::string out;
    for (const ast::Statement& statement : parsed.unit.pous.front().body) {
        out += (out.empty() ? "" : " ") + ast::to_sexpr(statement);
    }
    return out;
}

std::string expression_sexpr(const std::string& text) {
    const Parsed parsed = parse_text("PROGRAM P\nx := " + text + ";\nEND_PROGRAM\n");
    EXPECT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    if (parsed.unit.pous.empty() || parsed.unit.pous.front().body.empty()) {
        return "<no statement>";
    }
    const auto& assignment =
        std::get<ast::AssignmentStatement>(parsed.unit.pous.front().body.front().node);
    return ast::to_sexpr(*assignment.value);
}

std::string statement_error(const std::string& body) {
    return parse_text("PROGRAM P\n" + body + "\nEND_PROGRAM\n").first_message();
}

} // namespace eposp::compiler::test
