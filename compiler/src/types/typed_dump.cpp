#include "eposp/compiler/types/typed_dump.hpp"

#include "eposp/compiler/ast/ast_printer.hpp"

#include <fmt/format.h>

namespace eposp::compiler::types {
namespace {

std::string constant_text(const Constant& value) {
    return std::visit(
        [](const auto& v) -> std::string {
            using V = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<V, bool>) {
                return v ? "TRUE" : "FALSE";
            } else if constexpr (std::is_same_v<V, std::string>) {
                return fmt::format("'{}'", v);
            } else if constexpr (std::is_same_v<V, std::u16string>) {
                // As a WSTRING literal writes it: ASCII as itself, any other unit as $hhhh.
                std::string text = "\"";
                for (const char16_t unit : v) {
                    text += unit >= 0x20 && unit < 0x7F && unit != u'"' && unit != u'$'
                                ? std::string(1, static_cast<char>(unit))
                                : fmt::format("${:04X}", static_cast<unsigned>(unit));
                }
                return text + "\"";
            } else if constexpr (std::is_same_v<V, double>) {
                return fmt::format("{}", v); // the shortest text that reads back as the same value
            } else {
                return std::to_string(v);
            }
        },
        value);
}

std::string call_text(const CallTarget& target) {
    const std::string_view callee =
        target.pou != nullptr && target.kind != CallKind::StandardFunctionBlock
            ? std::string_view(target.pou->name.name)
            : std::string_view(target.name);
    return target.operand != nullptr ? fmt::format("->{}({})", callee, target.operand->name)
                                     : fmt::format("->{}", callee);
}

} // namespace

std::string dump_typed(const TypedProgram& program, const ast::CompilationUnit& unit) {
    ast::DumpLayout layout;
    layout.note = [&program](const ast::Expression& expression) {
        std::string note;
        if (const sema::Type* type = program.type_of(expression)) {
            note = ":" + type->name;
        }
        // The type a binary operator's operands are computed in (DINT for small integers).
        if (const sema::Type* operands = program.operands_of(expression)) {
            note += "@" + operands->name;
        }
        if (const Constant* value = program.constant_of(expression)) {
            note += "=" + constant_text(*value);
        }
        if (const CallTarget* target = program.call_target(expression)) {
            note += call_text(*target);
        }
        return note;
    };
    return ast::to_sexpr(unit, layout);
}

} // namespace eposp::compiler::types
