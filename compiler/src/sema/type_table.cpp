#include "eposp/compiler/sema/type_table.hpp"

#include "eposp/vm/image_limits.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"

#include <fmt/format.h>
#include <utility>

namespace eposp::compiler::sema {

namespace {

using E = ast::ElementaryType;

std::uint32_t elementary_size(E type) {
    switch (type) {
    case E::Bool:
    case E::Sint:
    case E::Usint:
    case E::Byte:
    case E::Char:
        return 1;
    case E::Int:
    case E::Uint:
    case E::Word:
    case E::Wchar:
        return 2;
    case E::Dint:
    case E::Udint:
    case E::Dword:
    case E::Real:
        return 4;
    default:
        return 8;
    }
}

} // namespace

TypeTable::TypeTable(const SemanticModel& model, Diagnostics& diagnostics,
                     std::function<const ast::Pou*(std::string_view)> library,
                     std::function<bool(const ast::VariableDeclaration&)> is_constant,
                     const IntegerConstants& constants)
    : model_(model), diagnostics_(diagnostics), library_(std::move(library)),
      is_constant_(std::move(is_constant)), constants_(constants) {}

Type& TypeTable::add(Type type) {
    return types_.emplace_back(std::move(type));
}

const Type& TypeTable::elementary(E type) {
    if (type == E::String || type == E::Wstring) {
        return string(vm::stdlib::kDefaultStringCapacity, type == E::Wstring);
    }
    auto& slot = elementary_[type];
    if (slot == nullptr) {
        const std::uint32_t size = elementary_size(type);
        slot = &add({.kind = TypeKind::Elementary,
                     .name = std::string(ast::name_of(type)),
                     .elementary = type,
                     .size = size,
                     .align = size});
    }
    return *slot;
}

const Type& TypeTable::string(std::uint32_t capacity, bool wide) {
    auto& slot = strings_[{capacity, wide}];
    if (slot == nullptr) {
        slot =
            &add({.kind = TypeKind::String,
                  .name = fmt::format("{}[{}]", wide ? "WSTRING" : "STRING", capacity),
                  .elementary = wide ? E::Wstring : E::String,
                  .size = vm::stdlib::string_size(capacity, wide ? vm::stdlib::CharWidth::Wide
                                                                 : vm::stdlib::CharWidth::Narrow),
                  .align = vm::stdlib::kStringAlign,
                  .capacity = capacity,
                  .wide = wide});
    }
    return *slot;
}

const Type& TypeTable::reference(const Type* target) {
    auto& slot = references_[target];
    if (slot == nullptr) {
        slot = &add({.kind = TypeKind::Reference,
                     .name = "REF_TO " + (target != nullptr ? target->name : std::string("?")),
                     .size = 8,
                     .align = 8,
                     .element = target});
    }
    return *slot;
}

const Type& TypeTable::conformant_reference(const Type& array) {
    auto& slot = conformant_references_[&array];
    if (slot == nullptr) {
        slot = &add(
            {.kind = TypeKind::Struct,
             .name = "REF_TO " + array.name,
             .size = kConformantBoundsOffset +
                     kConformantDimensionSize * static_cast<std::uint32_t>(array.dimensions.size()),
             .align = 8,
             .element = &array,
             .conformant = true});
    }
    return *slot;
}

const Type& TypeTable::null() {
    if (null_ == nullptr) {
        null_ = &add({.kind = TypeKind::Null, .name = "NULL", .size = 8, .align = 8});
    }
    return *null_;
}

const Type& TypeTable::any() {
    if (any_ == nullptr) {
        any_ = &add(
            {.kind = TypeKind::Struct, .name = "ANY", .size = 16, .align = 8, .generic = true});
    }
    return *any_;
}

const Type& TypeTable::unranged(const Type& type) {
    return type.range ? elementary(type.elementary) : type;
}

const Type* TypeTable::resolve(const ast::TypeSpec& spec) {
    if (const auto it = specs_.find(&spec); it != specs_.end()) {
        return it->second;
    }
    if (in_progress_[&spec]) {
        // A reference does not contain its target (a linked list's `next : REF_TO Node`): it
        // gets the structure still being laid out, whose address is all it needs.
        const auto* node = std::get_if<ast::StructType>(&spec.node);
        if (const auto partial =
                node != nullptr ? partial_structures_.find(node) : partial_structures_.end();
            through_reference_ && partial != partial_structures_.end()) {
            return partial->second;
        }
        diagnostics_.error(DiagnosticCode::E0418, spec.range, "this type contains itself");
        return nullptr;
    }
    in_progress_[&spec] = true;
    const Type* type = resolve_uncached(spec);
    in_progress_[&spec] = false;
    specs_[&spec] = type;
    return type;
}

const Type* TypeTable::resolve_uncached(const ast::TypeSpec& spec) {
    if (const auto* node = std::get_if<ast::ElementaryTypeRef>(&spec.node)) {
        return &elementary(node->type);
    }
    if (const auto* node = std::get_if<ast::StringTypeRef>(&spec.node)) {
        std::int64_t capacity = vm::stdlib::kDefaultStringCapacity;
        if (node->length) {
            const auto folded = constants_.fold_integer(*node->length);
            if (!folded || *folded < 1 || *folded > vm::stdlib::kMaxStringCapacity) {
                diagnostics_.error(DiagnosticCode::E0313, node->length->range,
                                   "a string length must be a constant from 1 to 32767");
                return nullptr;
            }
            capacity = *folded;
        }
        return &string(static_cast<std::uint32_t>(capacity), node->type == E::Wstring);
    }
    if (const auto* node = std::get_if<ast::NamedTypeRef>(&spec.node)) {
        const Symbol* symbol = model_.resolved(node->name);
        if (symbol == nullptr && fold_case(node->name.name) == "ANY") {
            return &any(); // the name resolver leaves it to the layout (lay_out)
        }
        return symbol != nullptr ? named(*symbol) : nullptr; // unresolved: already reported
    }
    if (const auto* node = std::get_if<ast::ArrayType>(&spec.node)) {
        return array(*node, spec.range);
    }
    if (const auto* node = std::get_if<ast::SubrangeType>(&spec.node)) {
        return subrange(*node);
    }
    if (const auto* node = std::get_if<ast::EnumType>(&spec.node)) {
        return enumeration(*node, "enumeration");
    }
    if (const auto* node = std::get_if<ast::StructType>(&spec.node)) {
        return structure(*node);
    }
    const auto& node = std::get<ast::ReferenceType>(spec.node);
    const bool outer = std::exchange(through_reference_, true);
    const Type* target = resolve(*node.target);
    through_reference_ = outer;
    if (target != nullptr && target->conformant) {
        diagnostics_.error(DiagnosticCode::E0417, spec.range,
                           "ARRAY[*] is only allowed for VAR_IN_OUT");
        return nullptr;
    }
    return target != nullptr ? &reference(target) : nullptr;
}

const Type* TypeTable::array(const ast::ArrayType& spec, const SourceRange& range) {
    const bool outer = std::exchange(through_reference_, false); // elements need their size
    const Type* element = resolve(*spec.element);
    through_reference_ = outer;
    if (element == nullptr) {
        return nullptr;
    }
    if (element->kind == TypeKind::Array && element->conformant) {
        diagnostics_.error(DiagnosticCode::E0417, range,
                           "the elements of an array need their bounds");
        return nullptr;
    }
    if (!spec.dimensions.front().bounds) {
        return conformant_array(spec, *element, range);
    }
    Type type{.kind = TypeKind::Array, .align = element->align, .element = element};
    std::uint64_t count = 1;
    std::string bounds;
    for (const ast::ArrayDimension& dimension : spec.dimensions) {
        if (!dimension.bounds) {
            diagnostics_.error(DiagnosticCode::E0417, range,
                               "an array has either bounds or '*' in every dimension");
            return nullptr;
        }
        const auto low = constants_.fold_integer(*dimension.bounds->low);
        const auto high = constants_.fold_integer(*dimension.bounds->high);
        if (!low || !high) {
            diagnostics_.error(DiagnosticCode::E0313, dimension.bounds->low->range,
                               "array bounds must be constants");
            return nullptr;
        }
        if (*high < *low || *low < INT32_MIN || *high > INT32_MAX) {
            diagnostics_.error(
                DiagnosticCode::E0314, dimension.bounds->low->range,
                fmt::format("array bounds {}..{} are empty or too large", *low, *high));
            return nullptr;
        }
        const auto n = static_cast<std::uint64_t>(*high - *low + 1);
        count *= n;
        if (count * element->size > vm::kMaxAreaSize) {
            diagnostics_.error(DiagnosticCode::E0502, range,
                               fmt::format("this array is too large: its data exceeds the "
                                           "limit of {} bytes",
                                           vm::kMaxAreaSize));
            return nullptr;
        }
        type.dimensions.push_back({*low, static_cast<std::uint32_t>(n)});
        bounds += fmt::format("{}{}..{}", bounds.empty() ? "" : ",", *low, *high);
    }
    type.size = static_cast<std::uint32_t>(count * element->size);
    type.name = fmt::format("ARRAY[{}] OF {}", bounds, element->name);
    return &add(std::move(type));
}

const Type* TypeTable::conformant_array(const ast::ArrayType& spec, const Type& element,
                                        const SourceRange& range) {
    for (const ast::ArrayDimension& dimension : spec.dimensions) {
        if (dimension.bounds) {
            diagnostics_.error(DiagnosticCode::E0417, range,
                               "an array has either bounds or '*' in every dimension");
            return nullptr;
        }
    }
    std::string stars = "*";
    for (std::size_t d = 1; d < spec.dimensions.size(); ++d) {
        stars += ", *";
    }
    return &add({.kind = TypeKind::Array,
                 .name = fmt::format("ARRAY[{}] OF {}", stars, element.name),
                 .align = element.align,
                 .element = &element,
                 .dimensions = std::vector<ArrayDimension>(spec.dimensions.size()),
                 .conformant = true});
}

void TypeTable::lay_out(Type& type,
                        const std::vector<const ast::VariableDeclaration*>& declarations,
                        const std::vector<ast::VarSectionKind>& sections, std::uint32_t start) {
    std::uint64_t offset = start;
    bool too_large = false;
    const bool outer = through_reference_;
    for (std::size_t i = 0; i < declarations.size() && !too_large; ++i) {
        const ast::VariableDeclaration& declaration = *declarations[i];
        // A member needs its target's size, a VAR_IN_OUT only its address (6.5.1.2).
        through_reference_ = sections[i] == ast::VarSectionKind::InOut;
        const Type* member = resolve(declaration.type);
        if (member == nullptr) {
            continue;
        }
        if (member->generic &&
            !(type.kind == TypeKind::Struct && type.pou != nullptr &&
              type.pou->kind == ast::PouKind::Function && type.pou->body.empty() &&
              sections[i] == ast::VarSectionKind::Input)) {
            diagnostics_.error(DiagnosticCode::E0416, declaration.type.range,
                               "ANY is only allowed for a VAR_INPUT of a native function (a "
                               "FUNCTION without statements in a linked library)");
            continue;
        }
        // VAR_IN_OUT is passed by reference (6.5.1.2), an ARRAY[*] with its bounds (6.5.3).
        if (member->kind == TypeKind::Array && member->conformant) {
            if (sections[i] != ast::VarSectionKind::InOut) {
                diagnostics_.error(DiagnosticCode::E0417, declaration.type.range,
                                   "ARRAY[*] is only allowed for VAR_IN_OUT");
                continue;
            }
            member = &conformant_reference(*member);
        } else if (sections[i] == ast::VarSectionKind::InOut) {
            member = &reference(member);
        }
        for (const ast::Identifier& name : declaration.names) {
            const std::uint64_t at = align_up(static_cast<std::uint32_t>(offset), member->align);
            if (at + member->size > vm::kMaxAreaSize) {
                // The members laid out so far stay a consistent type for what follows.
                diagnostics_.error(DiagnosticCode::E0502, declaration.range,
                                   fmt::format("this structure or instance is too large: its data "
                                               "exceeds the limit of {} bytes",
                                               vm::kMaxAreaSize));
                too_large = true;
                break;
            }
            type.add_field(
                {name.name, member, static_cast<std::uint32_t>(at), sections[i], &declaration});
            offset = at + member->size;
            type.align = std::max(type.align, member->align);
        }
    }
    through_reference_ = outer;
    type.size = align_up(static_cast<std::uint32_t>(offset), type.align);
}

const Type* TypeTable::structure(const ast::StructType& spec) {
    Type& type = add({.kind = TypeKind::Struct, .name = "STRUCT"});
    partial_structures_[&spec] = &type;
    std::vector<const ast::VariableDeclaration*> declarations;
    for (const ast::VariableDeclaration& member : spec.members) {
        declarations.push_back(&member);
    }
    lay_out(type, declarations,
            std::vector<ast::VarSectionKind>(declarations.size(), ast::VarSectionKind::Var), 0);
    partial_structures_.erase(&spec);
    return &type;
}

const Type* TypeTable::enumeration(const ast::EnumType& spec, std::string name) {
    const Type* base = spec.base ? resolve(*spec.base) : &elementary(E::Int);
    if (base == nullptr || !(is_integer(*base) || is_bit_string(*base))) {
        diagnostics_.error(DiagnosticCode::E0312,
                           spec.values.empty() ? SourceRange{} : spec.values.front().name.range,
                           "an enumeration's base type must be an integer type");
        return nullptr;
    }
    Type& type = add({.kind = TypeKind::Enum,
                      .name = std::move(name),
                      .elementary = base->elementary,
                      .size = base->size,
                      .align = base->align});
    // 6.4.4.2: implicit values count on from the previous one, starting at 0.
    std::int64_t next = 0;
    for (const ast::EnumValue& value : spec.values) {
        if (value.value) {
            if (const auto folded = constants_.fold_integer(*value.value)) {
                next = *folded;
            } else {
                diagnostics_.error(DiagnosticCode::E0313, value.value->range,
                                   "an enumeration value must be a constant");
            }
        }
        type.enumerators.emplace_back(value.name.name, next);
        enum_values_[&value] = {&type, next};
        ++next;
    }
    return &type;
}

const Type* TypeTable::subrange(const ast::SubrangeType& spec) {
    const Type* base = resolve(*spec.base);
    if (base == nullptr) {
        return nullptr;
    }
    if (!is_integer(*base)) {
        diagnostics_.error(
            DiagnosticCode::E0312, spec.base->range,
            fmt::format("a subrange needs an integer base type, not {}", base->name));
        return nullptr;
    }
    const auto lower = constants_.fold_integer(*spec.range.low);
    const auto upper = constants_.fold_integer(*spec.range.high);
    if (!lower || !upper) {
        diagnostics_.error(DiagnosticCode::E0313, spec.range.low->range,
                           "subrange bounds must be constants");
        return nullptr;
    }
    const auto limits = ast::integer_range(base->elementary);
    const auto fits = [&](std::int64_t value) {
        return !limits || (value >= limits->min &&
                           (value < 0 || static_cast<std::uint64_t>(value) <= limits->max));
    };
    if (*upper < *lower || !fits(*lower) || !fits(*upper)) {
        diagnostics_.error(DiagnosticCode::E0314, spec.range.low->range,
                           fmt::format("the subrange {}..{} is empty or does not fit in {}", *lower,
                                       *upper, base->name));
        return nullptr;
    }
    Type type = unranged(*base);
    type.name = fmt::format("{}({}..{})", type.name, *lower, *upper);
    type.range = ValueRange{*lower, *upper};
    return &add(std::move(type));
}

const Type* TypeTable::named(const Symbol& symbol) {
    if (symbol.kind == SymbolKind::StandardFunctionBlock) {
        const ast::Pou* pou = library_(symbol.name);
        return pou != nullptr ? instance(*pou) : nullptr;
    }
    if (symbol.kind == SymbolKind::Pou) {
        return symbol.pou->kind == ast::PouKind::Function ? nullptr : instance(*symbol.pou);
    }
    if (symbol.kind != SymbolKind::Type) {
        return nullptr;
    }
    const Type* type = declared(symbol);
    return type != nullptr && symbol.type->initial_value ? &with_default(*type, *symbol.type)
                                                         : type;
}

const Type* TypeTable::declared(const Symbol& symbol) {
    const ast::TypeSpec& spec = symbol.type->type;
    if (const auto* enumeration_spec = std::get_if<ast::EnumType>(&spec.node)) {
        if (const auto it = specs_.find(&spec); it != specs_.end()) {
            return it->second;
        }
        return specs_[&spec] = enumeration(*enumeration_spec, symbol.name);
    }
    const Type* type = resolve(spec);
    const bool anonymous = (std::holds_alternative<ast::StructType>(spec.node) && type != nullptr &&
                            type->name == "STRUCT") ||
                           std::holds_alternative<ast::SubrangeType>(spec.node);
    if (type != nullptr && anonymous) {
        const_cast<Type*>(type)->name = symbol.name; // named on first use, for messages
        if (const auto it = references_.find(type); it != references_.end()) {
            const_cast<Type*>(it->second)->name = "REF_TO " + symbol.name; // made from inside
        }
    }
    return type;
}

// 6.4.2: a type declaration may give its own default. A type made for this declaration
// carries it; a shared one (INT, STRING[80], another declared type) is renamed into a copy.
const Type& TypeTable::with_default(const Type& type, const ast::TypeDeclaration& declaration) {
    const auto& spec = declaration.type.node;
    if (std::holds_alternative<ast::EnumType>(spec) ||
        std::holds_alternative<ast::SubrangeType>(spec) ||
        std::holds_alternative<ast::StructType>(spec) ||
        std::holds_alternative<ast::ArrayType>(spec)) {
        const_cast<Type&>(type).initial_value = declaration.initial_value.get();
        return type;
    }
    auto& renamed = renamed_with_default_[&declaration];
    if (renamed == nullptr) {
        Type copy = type;
        copy.name = declaration.name.name;
        copy.initial_value = declaration.initial_value.get();
        copy.renames = type.renames != nullptr ? type.renames : &type;
        renamed = &add(std::move(copy));
    }
    return *renamed;
}

const Type* TypeTable::instance(const ast::Pou& pou) {
    if (const auto it = instances_.find(&pou); it != instances_.end()) {
        if (instances_in_progress_.contains(&pou) && !through_reference_) {
            diagnostics_.error(DiagnosticCode::E0418, pou.name.range,
                               fmt::format("'{}' contains an instance of itself", pou.name.name));
            return nullptr;
        }
        return it->second;
    }
    Type& type = add({.kind = TypeKind::Instance, .name = pou.name.name, .pou = &pou});
    instances_[&pou] = &type;
    instances_in_progress_.insert(&pou);
    std::uint32_t start = 0;
    if (pou.extends) {
        const Symbol* base = model_.resolved(*pou.extends);
        if (base != nullptr && base->kind == SymbolKind::Pou) {
            type.base = instance(*base->pou);
        }
        if (type.base != nullptr) {
            start = type.base->size;
            type.align = type.base->align;
        }
    }
    std::vector<const ast::VariableDeclaration*> declarations;
    std::vector<ast::VarSectionKind> sections;
    for (const ast::DeclarationSection& section : pou.sections) {
        const auto* variables = std::get_if<ast::VarSection>(&section);
        if (variables == nullptr || variables->kind == ast::VarSectionKind::Temp ||
            variables->kind == ast::VarSectionKind::External) {
            continue; // temporaries live in the frame, externals in the configuration
        }
        for (const ast::VariableDeclaration& declaration : variables->variables) {
            declarations.push_back(&declaration);
            sections.push_back(variables->kind);
        }
    }
    lay_out(type, declarations, sections, start);
    type.size = std::max<std::uint32_t>(type.size, 1);
    instances_in_progress_.erase(&pou);
    return &type;
}

const Type* TypeTable::frame(const ast::Pou& pou) {
    if (const auto it = frames_.find(&pou); it != frames_.end()) {
        return it->second;
    }
    Type& type = add({.kind = TypeKind::Struct, .name = pou.name.name, .pou = &pou});
    frames_[&pou] = &type;
    const bool function = pou.kind == ast::PouKind::Function;
    std::uint32_t start = 0;
    if (function && pou.return_type) {
        const Type* result = resolve(*pou.return_type);
        if (result != nullptr && result->conformant) {
            diagnostics_.error(DiagnosticCode::E0417, pou.return_type->range,
                               "ARRAY[*] is only allowed for VAR_IN_OUT");
            result = nullptr;
        }
        if (result != nullptr) {
            type.add_field({pou.name.name, result, 0, ast::VarSectionKind::Output, nullptr});
            start = result->size;
            type.align = result->align;
        }
    }
    std::vector<const ast::VariableDeclaration*> declarations;
    std::vector<ast::VarSectionKind> sections;
    for (const ast::DeclarationSection& section : pou.sections) {
        const auto* variables = std::get_if<ast::VarSection>(&section);
        if (variables == nullptr || variables->kind == ast::VarSectionKind::External ||
            (!function && variables->kind != ast::VarSectionKind::Temp)) {
            continue;
        }
        for (const ast::VariableDeclaration& declaration : variables->variables) {
            declarations.push_back(&declaration);
            sections.push_back(variables->kind);
        }
    }
    lay_out(type, declarations, sections, start);
    type.size = align_up(type.size, 8);
    return &type;
}

const Type* TypeTable::enumeration_of(const Symbol& value) {
    if (value.owner != nullptr) {
        named(*value.owner);
    }
    const auto it = enum_values_.find(value.enum_value);
    return it == enum_values_.end() ? nullptr : it->second.first;
}

std::optional<std::int64_t> TypeTable::enumerator(const Symbol& value) {
    if (value.owner != nullptr) {
        named(*value.owner);
    }
    const auto it = enum_values_.find(value.enum_value);
    return it == enum_values_.end() ? std::nullopt : std::optional(it->second.second);
}

} // namespace eposp::compiler::sema
