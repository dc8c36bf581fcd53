#pragma once

#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/sema/integer_constants.hpp"
#include "eposp/compiler/sema/semantic_model.hpp"
#include "eposp/compiler/sema/type.hpp"

#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <unordered_map>
#include <unordered_set>

namespace eposp::compiler::sema {

/// Owns every type of a program and gives each declaration its type and layout (IEC 61131-3
/// ed. 3, 6.4): elementary, STRING[n] and REF_TO types are interned, so two of them are the
/// same type exactly when they are the same object. Constant expressions in types (array
/// bounds, string lengths, enumeration values) are the typing stage's constant folder's
/// (types/constant_folder.hpp), which the table is handed as `constants`.
class TypeTable {
public:
    /// `library` finds the POU implementing a standard FB (`TON`) in the built-in library;
    /// `is_constant` tells whether a declaration is in a CONSTANT section (only those fold);
    /// `constants` evaluates constant integer expressions (it may ask this table back).
    TypeTable(const SemanticModel& model, Diagnostics& diagnostics,
              std::function<const ast::Pou*(std::string_view)> library,
              std::function<bool(const ast::VariableDeclaration&)> is_constant,
              const IntegerConstants& constants);

    const Type& elementary(ast::ElementaryType type);
    const Type& string(std::uint32_t capacity, bool wide);
    const Type& reference(const Type* target);
    /// What a VAR_IN_OUT of the ARRAY[*] `array` is passed by (kConformantBoundsOffset).
    const Type& conformant_reference(const Type& array);
    const Type& null();
    /// ANY (Type::generic): a pointer and a descriptor, 16 bytes.
    const Type& any();
    /// The type without its subrange: a subrange's base type, else `type` itself.
    const Type& unranged(const Type& type);

    /// The type a declaration spells; null after reporting an error.
    const Type* resolve(const ast::TypeSpec& spec);
    /// The type a type name, FB or standard FB symbol denotes; null if it has none.
    const Type* named(const Symbol& symbol);
    /// The instance layout of an FB or PROGRAM.
    const Type* instance(const ast::Pou& pou);
    /// What a POU keeps on the task stack (ed. 3, 6.6.2.2): for a FUNCTION its result (named
    /// after it, at offset 0), parameters in declaration order, VAR and VAR_TEMP; for an FB or
    /// PROGRAM its VAR_TEMP.
    const Type* frame(const ast::Pou& pou);
    /// The enumeration an enumerated value belongs to, and the value's number.
    const Type* enumeration_of(const Symbol& value);
    std::optional<std::int64_t> enumerator(const Symbol& value);

    const SemanticModel& model() const { return model_; }
    /// Whether a declaration is in a CONSTANT section.
    bool is_constant(const ast::VariableDeclaration& declaration) const {
        return is_constant_(declaration);
    }

private:
    Type& add(Type type);
    const Type* resolve_uncached(const ast::TypeSpec& spec);
    const Type* array(const ast::ArrayType& spec, const SourceRange& range);
    const Type* conformant_array(const ast::ArrayType& spec, const Type& element,
                                 const SourceRange& range);
    const Type* structure(const ast::StructType& spec);
    const Type* enumeration(const ast::EnumType& spec, std::string name);
    const Type* subrange(const ast::SubrangeType& spec);
    /// The type a type declaration spells, without the declaration's own default.
    const Type* declared(const Symbol& symbol);
    const Type& with_default(const Type& type, const ast::TypeDeclaration& declaration);
    void lay_out(Type& type, const std::vector<const ast::VariableDeclaration*>& declarations,
                 const std::vector<ast::VarSectionKind>& sections, std::uint32_t start);

    const SemanticModel& model_;
    Diagnostics& diagnostics_;
    std::function<const ast::Pou*(std::string_view)> library_;
    std::function<bool(const ast::VariableDeclaration&)> is_constant_;
    const IntegerConstants& constants_;
    std::deque<Type> types_;
    std::map<ast::ElementaryType, const Type*> elementary_;
    std::map<std::pair<std::uint32_t, bool>, const Type*> strings_;
    std::map<const Type*, const Type*> references_;
    std::map<const Type*, const Type*> conformant_references_;
    const Type* null_ = nullptr;
    const Type* any_ = nullptr;
    std::unordered_map<const ast::TypeSpec*, const Type*> specs_;
    std::unordered_map<const ast::Pou*, const Type*> instances_;
    std::unordered_map<const ast::TypeDeclaration*, const Type*> renamed_with_default_;
    std::unordered_map<const ast::Pou*, const Type*> frames_;
    std::unordered_map<const ast::TypeSpec*, bool> in_progress_;
    /// STRUCTs being laid out, for references to them from inside (a linked list's `next`).
    std::unordered_map<const ast::StructType*, const Type*> partial_structures_;
    std::unordered_set<const ast::Pou*> instances_in_progress_;
    /// Whether the type being resolved is the target of a reference, which needs no size.
    bool through_reference_ = false;
    std::unordered_map<const ast::EnumValue*, std::pair<const Type*, std::int64_t>> enum_values_;
};

/// Rounds `offset` up to a multiple of `align`.
constexpr std::uint32_t align_up(std::uint32_t offset, std::uint32_t align) {
    return (offset + align - 1) / align * align;
}

} // namespace eposp::compiler::sema
