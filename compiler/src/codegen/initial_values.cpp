// Initial values of variables (IEC 61131-3 ed. 3, 6.5.1.3 and 6.4.2): the type's default
// (zero, an empty STRING with its capacity in the header), the declared defaults of structure
// members and FB variables, then the initializer written at the declaration.

#include "eposp/compiler/sema/symbol.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"
#include "program_generator.hpp"

#include <algorithm>

namespace eposp::compiler::codegen {

std::optional<std::vector<std::uint8_t>>
ProgramGenerator::constant_value(const ast::Expression& expression, const sema::Type& type) {
    auto bytes = types::constant_bytes(expression, type, typed_);
    if (auto* refusal = std::get_if<types::ConstantRefusal>(&bytes)) {
        refused_by_checks(refusal->code); // types/initializers.cpp, types/expression_typer.cpp
        return std::nullopt;
    }
    return std::move(std::get<std::vector<std::uint8_t>>(bytes));
}

void ProgramGenerator::initial_value(const sema::Type& type, const ast::Initializer* initializer,
                                     std::span<std::uint8_t> bytes) {
    const std::vector<std::uint8_t>& defaults = default_value(type);
    std::copy(defaults.begin(), defaults.end(), bytes.begin());
    if (initializer != nullptr) {
        apply_initializer(type, *initializer, bytes);
    }
}

// Computed once per type, so that an error in a member's initializer is reported once, not
// once per array element or variable of the type.
const std::vector<std::uint8_t>& ProgramGenerator::default_value(const sema::Type& type) {
    if (const auto it = default_values_.find(&type); it != default_values_.end()) {
        return it->second;
    }
    std::vector<std::uint8_t> bytes(type.size);
    switch (type.kind) {
    case sema::TypeKind::String: {
        const auto empty = vm::stdlib::string_image(type.capacity, "");
        std::copy(empty.begin(), empty.begin() + vm::stdlib::kStringHeaderSize, bytes.begin());
        break;
    }
    case sema::TypeKind::Array: {
        const std::vector<std::uint8_t>& element = default_value(*type.element);
        for (auto at = bytes.begin(); !element.empty() && at != bytes.end(); at += element.size()) {
            std::copy(element.begin(), element.end(), at);
        }
        break;
    }
    case sema::TypeKind::Struct:
    case sema::TypeKind::Instance:
        for (const sema::Type* part = &type; part != nullptr; part = part->base) {
            for (const sema::Field& field : part->fields) {
                if (field.section == ast::VarSectionKind::InOut) {
                    continue; // a reference, bound at each call
                }
                initial_value(*field.type,
                              field.declaration != nullptr ? field.declaration->initial_value.get()
                                                           : nullptr,
                              std::span(bytes).subspan(field.offset, field.type->size));
            }
        }
        break;
    case sema::TypeKind::Enum:
        // 6.4.4.2: an enumerated type starts at its first value, whatever number that has.
        if (!type.enumerators.empty()) {
            const auto first = integer_bytes(type.enumerators.front().second, type.size);
            std::copy(first.begin(), first.end(), bytes.begin());
        }
        break;
    default:
        if (type.range) {
            // 6.4.4.4: a subrange starts at its lower bound, not at 0.
            const auto lower = integer_bytes(type.range->lower, type.size);
            std::copy(lower.begin(), lower.end(), bytes.begin());
        }
        break;
    }
    // 6.4.2: the default a type declaration gives (`TYPE Speed : INT := 100;`).
    if (type.initial_value != nullptr) {
        apply_initializer(type, *type.initial_value, bytes);
    }
    return default_values_[&type] = std::move(bytes);
}

// 6.4.4.2: a variable of an enumerated type holds one of the type's values: one of its names,
// or a constant (or number, as CODESYS allows) equal to one of them.
bool ProgramGenerator::is_enumerator_of(const ast::Expression& expression,
                                        const sema::Type& enumeration) {
    if (const sema::Symbol* value = program_.model.enum_value(expression)) {
        const sema::Type* owner = types_.enumeration_of(*value);
        return owner != nullptr && sema::same_type(*owner, enumeration);
    }
    const auto number = typed_.constants().fold_integer(expression);
    return number && std::ranges::any_of(enumeration.enumerators, [&](const auto& enumerator) {
               return enumerator.second == *number;
           });
}

void ProgramGenerator::apply_initializer(const sema::Type& type,
                                         const ast::Initializer& initializer,
                                         std::span<std::uint8_t> bytes) {
    if (const auto* expression = std::get_if<ast::ExpressionPtr>(&initializer.value)) {
        if (type.kind == sema::TypeKind::Enum && !is_enumerator_of(**expression, type)) {
            refused_by_checks(DiagnosticCode::E0301); // types/initializers.cpp
            return;
        }
        if (const auto value = constant_value(**expression, type)) {
            std::copy(value->begin(), value->end(), bytes.begin());
        }
        return;
    }
    if (const auto* elements =
            std::get_if<std::vector<ast::ArrayInitElement>>(&initializer.value)) {
        if (type.kind != sema::TypeKind::Array) {
            refused_by_checks(DiagnosticCode::E0301); // types/initializers.cpp
            return;
        }
        const std::uint32_t size = type.element->size;
        const std::uint32_t count = type.size / std::max<std::uint32_t>(size, 1);
        std::uint32_t next = 0;
        for (const ast::ArrayInitElement& element : *elements) {
            std::int64_t repeat = 1;
            if (element.repeat_count) {
                repeat = typed_.constants().fold_integer(*element.repeat_count).value_or(-1);
                if (repeat < 0) {
                    refused_by_checks(DiagnosticCode::E0313); // types/initializers.cpp
                    return;
                }
            }
            for (std::int64_t i = 0; i < repeat; ++i, ++next) {
                if (next >= count) {
                    refused_by_checks(DiagnosticCode::E0411); // checks/initial_value_counts.cpp
                    return;
                }
                if (element.value) {
                    initial_value(*type.element, element.value.get(),
                                  bytes.subspan(next * size, size));
                }
            }
        }
        return;
    }
    const auto& members = std::get<std::vector<ast::StructInitElement>>(initializer.value);
    for (const ast::StructInitElement& member : members) {
        const sema::Field* field = type.field(member.member.name);
        if (field == nullptr ||
            (type.kind != sema::TypeKind::Struct && type.kind != sema::TypeKind::Instance)) {
            refused_by_checks(DiagnosticCode::E0206); // types/initializers.cpp
            continue;
        }
        initial_value(*field->type, member.value.get(),
                      bytes.subspan(field->offset, field->type->size));
    }
}

} // namespace eposp::compiler::codegen
