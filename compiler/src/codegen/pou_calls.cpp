// Calls of functions, function block instances and host functions (IEC 61131-3 ed. 3, 6.6.1.7
// and 7.3.3.2). A function's arguments are written into the caller's out area, which becomes
// the callee's frame (host functions called meanwhile take their block after them); an FB's
// inputs are written into its instance before CallFb.

#include "eposp/compiler/sema/standard_library.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "pou_generator.hpp"

#include <fmt/format.h>
#include <stdexcept>
#include <utility>

namespace eposp::compiler::codegen {

using vm::Opcode;
using vm::Operand;

std::optional<Value> PouGenerator::call_enabled(const ast::Expression& expression,
                                                const sema::Type* hint, const Destination* dest) {
    const auto& node = std::get<ast::CallExpression>(expression.node);
    if (const auto* name = std::get_if<ast::NameExpression>(&node.callee->node)) {
        const sema::Symbol* symbol = model_.resolved(name->name);
        if (symbol == nullptr) {
            return std::nullopt;
        }
        switch (symbol->kind) {
        case sema::SymbolKind::Pou:
            if (symbol->pou->kind == ast::PouKind::Function) {
                return call_function(*symbol->pou, node, dest);
            }
            if (symbol->pou->kind == ast::PouKind::Program) {
                break; // its single instance is called, as CODESYS does
            }
            program_.refused_by_checks(DiagnosticCode::E0204); // types/call_typing.cpp
            return std::nullopt;
        case sema::SymbolKind::StandardFunction:
            if (const ast::Pou* pou = program_.library_pou(symbol->name);
                pou != nullptr && pou->kind == ast::PouKind::Function) {
                return call_function(*pou, node, dest);
            }
            if (const types::CallTarget* target = program_.typed().call_target(expression)) {
                return standard_function(*target, expression, hint, dest);
            }
            program_.refused_by_checks(DiagnosticCode::E0306); // types/call_typing.cpp
            return std::nullopt;
        case sema::SymbolKind::StandardFunctionBlock:
            program_.refused_by_checks(DiagnosticCode::E0204); // types/call_typing.cpp
            return std::nullopt;
        default:
            break;
        }
    }
    const auto instance = place(*node.callee);
    if (!instance) {
        return std::nullopt;
    }
    if (instance->type->kind != sema::TypeKind::Instance) {
        program_.refused_by_checks(DiagnosticCode::E0204); // types/call_typing.cpp
        return std::nullopt;
    }
    call_instance(*instance, node);
    return Value{};
}

namespace {

bool is_parameter(ast::VarSectionKind section) {
    return section == ast::VarSectionKind::Input || section == ast::VarSectionKind::InOut ||
           section == ast::VarSectionKind::Output;
}

} // namespace

std::optional<Value> PouGenerator::call_function(const ast::Pou& function,
                                                 const ast::CallExpression& node,
                                                 const Destination* dest) {
    const sema::Type& frame = *types_.frame(function);
    if (program_.is_host_function(function)) {
        return call_host(function, frame, node, dest);
    }
    if (program_.is_native_function(function)) {
        return call_native_function(function, node, dest);
    }
    const std::uint32_t index = program_.pou_index(function);
    program_.calls(pou_, function);
    struct Bound {
        const sema::Field* field;
        const ast::Argument* argument;
        std::optional<Value> value; // evaluated before the out area is written
    };
    std::vector<Bound> bound;
    std::size_t positional = 0;
    std::uint32_t end = 0;
    bool ok = true;
    for (const sema::Field& field : frame.fields) {
        if (field.declaration == nullptr || is_parameter(field.section)) {
            end = std::max(end, field.offset + field.type->size);
        }
    }
    for (const ast::Argument& argument : node.arguments) {
        if (is_enable_argument(argument)) {
            continue;
        }
        const sema::Field* field = sema::formal_parameter(frame, argument, positional);
        const bool output = argument.kind == ast::Argument::Kind::Output;
        if (field == nullptr || !is_parameter(field->section) ||
            output != (field->section == ast::VarSectionKind::Output)) {
            program_.refused_by_checks(argument.name
                                           ? DiagnosticCode::E0210
                                           : DiagnosticCode::E0306); // types/call_typing.cpp
            ok = false;
            continue;
        }
        bound.push_back({field, &argument, std::nullopt});
    }
    // First the arguments that call a function: the callee's frame is the out area, so they
    // run before any argument is placed there. Host functions (string comparisons and
    // functions, conversions) in the others take their block after the arguments placed. An
    // input before a later argument that may write variables is taken here too, in order:
    // arguments are evaluated from left to right.
    const auto last_writer = std::find_if(bound.rbegin(), bound.rend(), [this](const Bound& b) {
        return may_write_variables(*b.argument->value);
    });
    const auto written_later = [&](const Bound& b) {
        return &b < &*last_writer;
    };
    for (Bound& b : bound) {
        if (b.field->section == ast::VarSectionKind::InOut) {
            const auto target = place(*b.argument->value);
            b.value = target ? in_out_argument(*target, *b.field) : std::nullopt;
            ok = ok && b.value.has_value();
        } else if (b.field->section == ast::VarSectionKind::Input &&
                   (contains_call(*b.argument->value) ||
                    (last_writer != bound.rend() && written_later(b)))) {
            const Operand slot = temp(*b.field->type);
            const Destination into{slot, b.field->type};
            b.value = value_as(*b.argument->value, *b.field->type, &into);
            if (b.value) {
                move(slot, *b.field->type, *b.value);
                b.value = Value{slot, b.field->type};
            }
            ok = ok && b.value.has_value();
        }
    }
    if (!ok) {
        return std::nullopt;
    }
    const std::uint32_t pending = std::exchange(out_pending_, end);
    for (const sema::Field& field : frame.fields) {
        if (field.declaration == nullptr || field.section == ast::VarSectionKind::Output ||
            !is_parameter(field.section)) {
            continue;
        }
        const Operand slot = Operand::out(field.offset);
        const auto it = std::find_if(bound.begin(), bound.end(),
                                     [&](const Bound& b) { return b.field == &field; });
        if (it == bound.end()) {
            if (field.section == ast::VarSectionKind::InOut) {
                program_.refused_by_checks(DiagnosticCode::E0413); // checks/in_out_connections.cpp
                ok = false;
                break;
            }
            // 6.6.1.7: an input left out takes its initial value.
            std::vector<std::uint8_t> bytes(field.type->size);
            program_.initial_value(*field.type, field.declaration->initial_value.get(), bytes);
            move(slot, *field.type, Value{program_.constant(bytes, 8), field.type});
        } else if (it->value) {
            emit(sema::is_scalar(*field.type)
                     ? program_.opcodes().get("Mov", width_suffix(sema::scalar_of(*field.type)))
                     : Opcode::MovN,
                 slot, it->value->operand,
                 Operand::imm(sema::is_scalar(*field.type) ? 0 : field.type->size));
        } else {
            if (field.type->kind == sema::TypeKind::String) {
                clear(slot, *field.type); // the header a string function writes through
            }
            const Destination into{slot, field.type};
            const auto value = value_as(*it->argument->value, *field.type, &into);
            if (!value) {
                ok = false;
                break;
            }
            move(slot, *field.type, *value);
        }
    }
    out_pending_ = pending;
    if (!ok) {
        return std::nullopt;
    }
    if (out_pending_ != 0) {
        // Calls in arguments run before any argument is placed (above), so this cannot be.
        throw std::logic_error("a call while arguments are being placed in the out area");
    }
    out_slot(end);
    emit(Opcode::Call, Operand::imm(index));
    std::optional<Value> result = Value{};
    if (!frame.fields.empty() && frame.fields.front().declaration == nullptr) {
        const sema::Type& type = types_.unranged(*frame.fields.front().type);
        const Operand operand = result_operand(type, dest);
        emit(sema::is_scalar(type)
                 ? program_.opcodes().get("Mov", width_suffix(sema::scalar_of(type)))
                 : Opcode::MovN,
             operand, Operand::out(0), Operand::imm(sema::is_scalar(type) ? 0 : type.size));
        result = Value{operand, &type};
    }
    // The outputs leave the out area before the places they go to are computed, which may
    // call again.
    std::vector<std::pair<const Bound*, Operand>> outputs;
    for (const Bound& b : bound) {
        if (b.field->section == ast::VarSectionKind::Output) {
            const Operand copy = temp(*b.field->type);
            emit(Opcode::MovN, copy, Operand::out(b.field->offset),
                 Operand::imm(b.field->type->size));
            outputs.emplace_back(&b, copy);
        }
    }
    for (const auto& [b, copy] : outputs) {
        const auto target = place(*b->argument->value);
        if (target) {
            if (const auto value = value_as(Value{copy, b->field->type}, *target->type)) {
                store(*target, *value);
            }
        }
    }
    return result;
}

std::optional<Value> PouGenerator::call_host(const ast::Pou& function, const sema::Type& frame,
                                             const ast::CallExpression& node,
                                             const Destination* dest) {
    vm::NativeSignature signature;
    std::vector<Value> arguments;
    std::size_t positional = 0;
    for (const ast::Argument& argument : node.arguments) {
        const sema::Field* field = sema::formal_parameter(frame, argument, positional);
        if (field == nullptr || field->section != ast::VarSectionKind::Input) {
            program_.refused_by_checks(DiagnosticCode::E0210); // types/call_typing.cpp
            return std::nullopt;
        }
        const auto value = value_as(*argument.value, *field->type);
        if (!value) {
            return std::nullopt;
        }
        signature.parameters.push_back(sema::scalar_of(*field->type));
        arguments.push_back(*value);
    }
    const sema::Type* result = frame.fields.empty() || frame.fields.front().declaration != nullptr
                                   ? nullptr
                                   : frame.fields.front().type;
    signature.has_result = result != nullptr;
    signature.result = result != nullptr ? sema::scalar_of(*result) : vm::Scalar::Bool;
    call_native(function.name.name, signature, arguments);
    return result != nullptr ? native_result(signature, *result, dest) : std::optional(Value{});
}

void PouGenerator::call_instance(const Place& instance, const ast::CallExpression& node) {
    const sema::Type& type = *instance.type;
    const std::uint32_t index = program_.pou_index(*type.pou);
    program_.calls(pou_, *type.pou);
    std::vector<std::pair<const sema::Field*, const ast::Argument*>> outputs;
    std::vector<const sema::Field*> connected;
    for (const ast::Argument& argument : node.arguments) {
        if (is_enable_argument(argument)) {
            continue;
        }
        const sema::Field* field = argument.name ? type.field(argument.name->name) : nullptr;
        connected.push_back(field);
        if (field == nullptr) {
            if (argument.name) {
                program_.refused_by_checks(DiagnosticCode::E0210); // types/call_typing.cpp
            } else {
                program_.refused_by_checks(DiagnosticCode::E0415); // checks/call_forms.cpp
            }
            continue;
        }
        const bool output = argument.kind == ast::Argument::Kind::Output;
        if (output != (field->section == ast::VarSectionKind::Output) ||
            !is_parameter(field->section)) {
            program_.refused_by_checks(DiagnosticCode::E0210); // types/call_typing.cpp
            continue;
        }
        if (output) {
            outputs.emplace_back(field, &argument);
            continue;
        }
        const Place slot = member(instance, field->offset, *field->type);
        if (field->section == ast::VarSectionKind::InOut) {
            const auto target = place(*argument.value);
            if (const auto reference = target ? in_out_argument(*target, *field) : std::nullopt) {
                store(slot, *reference);
            }
            continue;
        }
        if (slot.kind == Place::Kind::Direct) {
            const Destination into{slot.operand, field->type};
            if (const auto value = value_as(*argument.value, *field->type, &into)) {
                move(slot.operand, *field->type, *value);
            }
        } else if (const auto value = value_as(*argument.value, *field->type)) {
            store(slot, *value);
        }
    }
    // An in-out is a reference the instance keeps only for the call: every call connects it
    // (as CODESYS requires), or the body would work through a stale or NULL reference.
    for (const sema::Field& field : type.fields) {
        if (field.section == ast::VarSectionKind::InOut &&
            std::find(connected.begin(), connected.end(), &field) == connected.end()) {
            program_.refused_by_checks(DiagnosticCode::E0413); // checks/in_out_connections.cpp
        }
    }
    if (instance.kind == Place::Kind::Direct) {
        emit(Opcode::CallFb, instance.operand, Operand::imm(index));
    } else {
        emit(Opcode::CallFbP, address_of(instance), Operand::imm(index));
    }
    for (const auto& [field, argument] : outputs) {
        const auto target = place(*argument->value);
        if (!target) {
            continue;
        }
        Value value = load(member(instance, field->offset, *field->type));
        if (argument->negated) {
            const Operand negated = temp(*field->type);
            emit(Opcode::NotB, negated, value.operand);
            value.operand = negated;
        }
        if (!sema::converts_implicitly(*field->type, *target->type)) {
            program_.refused_by_checks(DiagnosticCode::E0301); // types/call_typing.cpp
            continue;
        }
        store(*target, *value_as(value, *target->type));
    }
}

void PouGenerator::call_native(const std::string& name, const vm::NativeSignature& signature,
                               const std::vector<Value>& arguments) {
    const std::uint32_t import = program_.import(name, signature);
    const Operand block = native_block();
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const Operand slot = Operand::out(block.offset() + vm::parameter_offset(signature, i));
        const Value& argument = arguments[i];
        if (signature.parameters[i] == vm::Scalar::Ptr &&
            argument.type->kind != sema::TypeKind::Reference &&
            argument.type->kind != sema::TypeKind::Null) {
            emit(Opcode::Addr, slot, argument.operand, Operand::imm(argument.type->size));
        } else {
            emit(program_.opcodes().get("Mov", width_suffix(signature.parameters[i])), slot,
                 argument.operand);
        }
    }
    out_slot(block.offset() + vm::argument_block_size(signature));
    emit(Opcode::CallNative, Operand::imm(import), block);
}

std::optional<Value> PouGenerator::native_result(const vm::NativeSignature& signature,
                                                 const sema::Type& type, const Destination* dest) {
    const Operand result = result_operand(type, dest);
    const vm::Scalar want = sema::scalar_of(type);
    if (signature.result == want) {
        emit(program_.opcodes().get("Mov", width_suffix(want)), result, native_block());
    } else {
        emit(program_.opcodes().get("Cvt", std::string(type_suffix(signature.result)) +
                                               std::string(type_suffix(want))),
             result, native_block());
    }
    return Value{result, &type};
}

} // namespace eposp::compiler::codegen
