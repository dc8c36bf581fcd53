// The constants of the string functions of table 29: only LEN of a STRING literal, whose
// characters are the literal's bytes as the image holds them. The other functions, and texts
// that are CONSTANTs (cut to their declared length when stored), are left to run time.

#include "constant_evaluator.hpp"

#include <limits>

namespace eposp::compiler::types {

std::optional<Constant> ConstantEvaluator::text_function(const std::string& name,
                                                         const ast::CallExpression& node) const {
    const auto arguments = standard_arguments(name, node);
    if (name != "LEN" || arguments.size() != 1 || arguments[0] == nullptr) {
        return std::nullopt;
    }
    const auto* literal = std::get_if<ast::LiteralExpression>(&arguments[0]->value->node);
    const auto* text =
        literal != nullptr ? std::get_if<ast::StringLiteral>(&literal->value) : nullptr;
    const auto* bytes = text != nullptr && text->type == ast::ElementaryType::String
                            ? std::get_if<std::string>(&text->value)
                            : nullptr;
    // LEN is an INT (codegen: the native's DINT count cut to INT); no literal is that long.
    if (bytes == nullptr || bytes->size() > std::numeric_limits<std::int16_t>::max()) {
        return std::nullopt;
    }
    return static_cast<std::int64_t>(bytes->size());
}

} // namespace eposp::compiler::types
