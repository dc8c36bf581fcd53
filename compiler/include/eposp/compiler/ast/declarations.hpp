#pragma once

#include "eposp/compiler/ast/direct_address.hpp"
#include "eposp/compiler/ast/expressions.hpp"
#include "eposp/compiler/ast/identifier.hpp"
#include "eposp/compiler/ast/node_arena.hpp"
#include "eposp/compiler/ast/statements.hpp"
#include "eposp/compiler/ast/types.hpp"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace eposp::compiler::ast {

// Declarations of IEC 61131-3 ed. 3: variables (6.5), types (6.4), POUs (6.6), configurations
// (6.8).

struct Initializer;
using InitializerPtr = NodePtr<Initializer>;

/// `3(0)` repeats its value three times; `3()` leaves three elements at their defaults.
struct ArrayInitElement {
    ExpressionPtr repeat_count; // null: the value appears once
    InitializerPtr value;       // null only for `n()`
};

struct StructInitElement {
    Identifier member;
    InitializerPtr value;
};

struct Initializer {
    SourceRange range;
    std::variant<ExpressionPtr, std::vector<ArrayInitElement>, std::vector<StructInitElement>>
        value;
};

/// `a, b AT %IX0.0 : INT := 5;` (AT only with a single name).
struct VariableDeclaration {
    std::vector<Identifier> names;
    std::optional<DirectAddress> address;
    TypeSpec type;
    InitializerPtr initial_value; // null: the type's default
    SourceRange range;
};

enum class VarSectionKind { Var, Input, Output, InOut, Temp, Global, External };
enum class Retention { Unspecified, Retain, NonRetain };

struct VarSection {
    VarSectionKind kind = VarSectionKind::Var;
    bool constant = false;
    Retention retention = Retention::Unspecified;
    std::vector<VariableDeclaration> variables;
    SourceRange range;
};

/// `name : Res0.Inst0.speed : INT READ_WRITE;` in VAR_ACCESS.
struct AccessDeclaration {
    Identifier name;
    std::variant<std::vector<Identifier>, DirectAddress> path;
    TypeSpec type;
    bool writable = false; // READ_ONLY is the default
    SourceRange range;
};

struct AccessSection {
    std::vector<AccessDeclaration> paths;
    SourceRange range;
};

/// A section of a POU or configuration in source order.
using DeclarationSection = std::variant<VarSection, AccessSection>;

struct TypeDeclaration {
    Identifier name;
    TypeSpec type;
    InitializerPtr initial_value;
    SourceRange range;
};

enum class PouKind { Function, FunctionBlock, Program };

/// FUNCTION, FUNCTION_BLOCK or PROGRAM. The OOP part of ed. 3 adds methods, properties and
/// access specifiers as further members of this node; EXTENDS and IMPLEMENTS are parsed already.
struct Pou {
    PouKind kind = PouKind::Program;
    Identifier name;
    std::optional<TypeSpec> return_type; // functions only
    std::optional<Identifier> extends;
    std::vector<Identifier> implements;
    std::vector<DeclarationSection> sections;
    StatementList body;
    SourceRange range;
};

/// A CODESYS attribute pragma written above a declaration: `{attribute 'name' := 'value'}`, or
/// `{attribute 'name'}` with an empty value.
struct Attribute {
    std::string name;
    std::string value;
    SourceRange range;
};

struct TaskDeclaration {
    std::vector<Attribute> attributes; ///< the attribute pragmas above it, in order
    Identifier name;
    ExpressionPtr single;   // null: cyclic or without trigger
    ExpressionPtr interval; // null: event task
    ExpressionPtr priority;
    SourceRange range;
};

/// `PROGRAM inst WITH task : Type (in := x, out => y);`
struct ProgramInstance {
    Identifier name;
    Retention retention = Retention::Unspecified;
    std::optional<Identifier> task;
    Identifier type;
    std::vector<Argument> connections;
    SourceRange range;
};

struct Resource {
    Identifier name;
    std::optional<Identifier> processor; // empty for the implicit resource of a configuration
    std::vector<DeclarationSection> sections;
    std::vector<TaskDeclaration> tasks;
    std::vector<ProgramInstance> programs;
    SourceRange range;
};

struct Configuration {
    Identifier name;
    std::vector<DeclarationSection> sections;
    std::vector<Resource> resources;
    SourceRange range;
};

} // namespace eposp::compiler::ast
