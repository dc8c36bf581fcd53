#include "typing_helpers.hpp"

#include <vector>

namespace eposp::compiler::test {

std::string Typed::errors() const {
    return render(diagnostics, sources);
}

const ast::Expression& Typed::value(std::size_t n) const {
    const ast::Pou& pou = front_end->units.back().pous.back();
    return *std::get<ast::AssignmentStatement>(pou.body.at(n).node).value;
}

std::string Typed::type_of(std::size_t n) const {
    const sema::Type* type = program().type_of(value(n));
    return type != nullptr ? type->name : "";
}

std::unique_ptr<Typed> type_source(const std::string& source) {
    auto typed = std::make_unique<Typed>();
    const FileId file = typed->sources.add("test.st", source);
    const std::vector<FileId> files{file};
    typed->front_end = types::analyse(typed->sources, files, typed->diagnostics);
    return typed;
}

std::unique_ptr<Typed> type_body(const std::string& declarations, const std::string& body) {
    return type_source("PROGRAM Main\nVAR\n" + declarations + "\nEND_VAR\n" + body +
                       "\nEND_PROGRAM\n");
}

std::vector<std::string> codes_of(const Diagnostics& diagnostics) {
    std::vector<std::string> codes;
    for (const Diagnostic& diagnostic : diagnostics.all()) {
        codes.emplace_back(describe(diagnostic.code).name);
    }
    return codes;
}

void PrintTo(const TypingCase& c, std::ostream* out) {
    *out << c.name;
}

} // namespace eposp::compiler::test
