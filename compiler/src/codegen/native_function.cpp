// Native functions (docs/runtime.md "Native functions"): a FUNCTION without statements in a
// linked library has no body in the image; every call of it is one CallNative of the host
// function of its name, its arguments in the call's argument block. Elementary inputs go by
// value, strings by address, ANY as the value's address and a descriptor of its type, and a
// VAR_IN_OUT ARRAY[*] as the address of its reference (address and bounds) and a descriptor of
// its element type (vm/native_type.hpp).

#include "eposp/compiler/sema/type.hpp"
#include "eposp/vm/native_type.hpp"
#include "pou_generator.hpp"

#include <algorithm>

namespace eposp::compiler::codegen {

using vm::Operand;

bool ProgramGenerator::is_native_function(const ast::Pou& pou) const {
    return linked_pous_.contains(&pou) && pou.kind == ast::PouKind::Function && pou.body.empty();
}

const NativeFunctionInterface* ProgramGenerator::native_function(const ast::Pou& pou) {
    if (const auto it = native_functions_.find(&pou); it != native_functions_.end()) {
        return it->second ? &*it->second : nullptr;
    }
    auto& entry = native_functions_[&pou];
    NativeFunctionInterface native;
    const sema::Type& frame = *types_.frame(pou);
    for (const sema::Field& field : frame.fields) {
        if (field.declaration == nullptr) { // the result
            if (!checks::is_native_result(*field.type)) {
                refused_by_checks(DiagnosticCode::E0419); // checks/native_interfaces.cpp
                return nullptr;
            }
            native.result = field.type;
            native.signature.has_result = true;
            native.signature.result = sema::scalar_of(*field.type);
            continue;
        }
        const auto kind = checks::native_parameter_kind(field);
        if (!kind) {
            refused_by_checks(DiagnosticCode::E0419);
            return nullptr;
        }
        native.parameters.push_back({&field, *kind, native.signature.parameters.size()});
        if (*kind == NativeParameter::Kind::Value) {
            native.signature.parameters.push_back(sema::scalar_of(*field.type));
        } else {
            native.signature.parameters.push_back(vm::Scalar::Ptr);
            if (*kind != NativeParameter::Kind::String) { // and the type's descriptor
                native.signature.parameters.push_back(vm::Scalar::U32);
            }
        }
    }
    entry = std::move(native);
    return &*entry;
}

std::optional<Value> PouGenerator::call_native_function(const ast::Pou& function,
                                                        const ast::CallExpression& node,
                                                        const Destination* dest) {
    const NativeFunctionInterface* native = program_.native_function(function);
    if (native == nullptr) {
        return std::nullopt; // reported at its declaration
    }
    const sema::Type& frame = *types_.frame(function);
    const auto& parameters = native->parameters;
    std::vector<const ast::Argument*> given(parameters.size(), nullptr);
    std::size_t positional = 0;
    bool ok = true;
    for (const ast::Argument& argument : node.arguments) {
        if (is_enable_argument(argument)) {
            continue;
        }
        const sema::Field* field = sema::formal_parameter(frame, argument, positional);
        const auto it = std::find_if(parameters.begin(), parameters.end(),
                                     [&](const NativeParameter& p) { return p.field == field; });
        if (field == nullptr || it == parameters.end() ||
            argument.kind == ast::Argument::Kind::Output) {
            program_.refused_by_checks(argument.name
                                           ? DiagnosticCode::E0210
                                           : DiagnosticCode::E0306); // types/call_typing.cpp
            ok = false;
            continue;
        }
        const auto& slot = given[static_cast<std::size_t>(it - parameters.begin())];
        if (slot != nullptr) {
            program_.refused_by_checks(DiagnosticCode::E0414); // checks/repeated_parameters.cpp
            ok = false;
            continue;
        }
        given[static_cast<std::size_t>(it - parameters.begin())] = &argument;
    }
    if (!ok) {
        return std::nullopt;
    }
    // Every argument is evaluated before any is placed: evaluating one may call.
    std::vector<Value> arguments(native->signature.parameters.size());
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        const NativeParameter& parameter = parameters[i];
        const sema::Type& type = *parameter.field->type;
        const ast::Argument* argument = given[i];
        if (argument == nullptr && (parameter.kind == NativeParameter::Kind::Value ||
                                    parameter.kind == NativeParameter::Kind::String)) {
            // 6.6.1.7: an input left out takes its initial value.
            std::vector<std::uint8_t> bytes(type.size);
            program_.initial_value(type, parameter.field->declaration->initial_value.get(), bytes);
            arguments[parameter.slot] = Value{program_.constant(bytes, 8), &type};
            continue;
        }
        if (argument == nullptr) {
            program_.refused_by_checks(DiagnosticCode::E0413); // checks/in_out_connections.cpp
            return std::nullopt;
        }
        std::optional<Value> value;
        switch (parameter.kind) {
        case NativeParameter::Kind::Value:
            value = value_as(*argument->value, type);
            break;
        case NativeParameter::Kind::String:
            // Any STRING goes by its own address, whatever its capacity: nothing is cut.
            value = eval(*argument->value, &type);
            if (value &&
                !(value->type->kind == sema::TypeKind::String && value->type->wide == type.wide)) {
                value = value_as(*value, type);
            }
            break;
        case NativeParameter::Kind::Any:
            value = any_argument(*argument->value);
            if (value) {
                arguments[parameter.slot + 1] = native_descriptor(*value->type);
            }
            break;
        case NativeParameter::Kind::Array: {
            const auto target = place(*argument->value);
            value = target ? in_out_argument(*target, *parameter.field) : std::nullopt;
            arguments[parameter.slot + 1] = native_descriptor(*type.element->element);
            break;
        }
        }
        if (!value) {
            return std::nullopt;
        }
        arguments[parameter.slot] = *value;
    }
    call_native(function.name.name, native->signature, arguments);
    return native->result != nullptr ? native_result(native->signature, *native->result, dest)
                                     : std::optional(Value{});
}

std::optional<Value> PouGenerator::any_argument(const ast::Expression& expression) {
    auto value = eval(expression, nullptr);
    if (value && value->iec != nullptr) {
        value = value_as(*value, *value->iec);
    }
    if (value && !checks::is_native_any_value(*value->type)) {
        program_.refused_by_checks(DiagnosticCode::E0305); // types/call_typing.cpp
        return std::nullopt;
    }
    return value;
}

Value PouGenerator::native_descriptor(const sema::Type& type) {
    const std::uint32_t descriptor = vm::native_descriptor(sema::native_type(type), type.size);
    return Value{program_.constant(integer_bytes(descriptor, 4), 4),
                 &types_.elementary(ast::ElementaryType::Udint)};
}

} // namespace eposp::compiler::codegen
