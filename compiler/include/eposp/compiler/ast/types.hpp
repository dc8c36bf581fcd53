#pragma once

#include "eposp/compiler/ast/elementary_type.hpp"
#include "eposp/compiler/ast/expressions.hpp"
#include "eposp/compiler/ast/identifier.hpp"
#include "eposp/compiler/ast/node_arena.hpp"

#include <variant>
#include <vector>

namespace eposp::compiler::ast {

// Type specifications (IEC 61131-3 ed. 3, 6.4), as written in a TYPE block or a declaration.

struct TypeSpec;
using TypeSpecPtr = NodePtr<TypeSpec>;
struct VariableDeclaration; // declarations.hpp: structure members are declared like variables

struct ElementaryTypeRef {
    ElementaryType type = ElementaryType::Int;
};

/// `STRING[80]`, `WSTRING(20)`, or `STRING` with the default length (no length expression).
struct StringTypeRef {
    ElementaryType type = ElementaryType::String;
    ExpressionPtr length;
};

/// A derived type, FB type or (later) interface, by name.
struct NamedTypeRef {
    Identifier name;
};

struct Subrange {
    ExpressionPtr low;
    ExpressionPtr high;
};

/// One dimension of an array; no bounds for the `*` of a variable-length array (ed. 3, 6.5.3).
struct ArrayDimension {
    std::optional<Subrange> bounds;
};

struct ArrayType {
    std::vector<ArrayDimension> dimensions;
    TypeSpecPtr element;
};

/// `INT(0..100)`.
struct SubrangeType {
    TypeSpecPtr base;
    Subrange range;
};

struct EnumValue {
    Identifier name;
    ExpressionPtr value; // null when implicit
};

/// `(Red, Green)`, or typed with explicit values: `DWORD (Red := 16#FF0000, Green := 16#FF00)`.
struct EnumType {
    TypeSpecPtr base; // null for an untyped enumeration
    std::vector<EnumValue> values;
};

struct StructType {
    std::vector<VariableDeclaration> members;
};

/// `REF_TO T` (IEC) or `POINTER TO T` (CODESYS).
struct ReferenceType {
    enum class Kind { Reference, Pointer };
    Kind kind = Kind::Reference;
    TypeSpecPtr target;
};

struct TypeSpec {
    SourceRange range;
    std::variant<ElementaryTypeRef, StringTypeRef, NamedTypeRef, ArrayType, SubrangeType, EnumType,
                 StructType, ReferenceType>
        node;
};

} // namespace eposp::compiler::ast
