#include "function_interface.hpp"

#include <fmt/format.h>

namespace eposp::plctest {
namespace {

bool by_reference(const FunctionParameter& parameter) {
    return parameter.passed == Passed::Array;
}

std::size_t places(const FunctionParameter& parameter) {
    return parameter.passed == Passed::Any || parameter.passed == Passed::Array ? 2 : 1;
}

} // namespace

std::string FunctionInterface::declaration() const {
    std::string text = fmt::format("FUNCTION {} : BOOL\n", name);
    // Consecutive parameters of one section share it, so that the declaration order (which
    // positional calls follow) is the parameters' order.
    for (std::size_t i = 0; i < parameters.size();) {
        const bool in_out = by_reference(parameters[i]);
        text += in_out ? "VAR_IN_OUT\n" : "VAR_INPUT\n";
        for (; i < parameters.size() && by_reference(parameters[i]) == in_out; ++i) {
            text += fmt::format("    {} : {};\n", parameters[i].name, parameters[i].type);
        }
        text += "END_VAR\n";
    }
    return text + "END_FUNCTION\n";
}

vm::NativeSignature FunctionInterface::signature() const {
    vm::NativeSignature signature{.has_result = true, .result = vm::Scalar::Bool, .parameters = {}};
    for (const FunctionParameter& parameter : parameters) {
        switch (parameter.passed) {
        case Passed::Value:
            signature.parameters.push_back(parameter.scalar);
            break;
        case Passed::String:
            signature.parameters.push_back(vm::Scalar::Ptr);
            break;
        case Passed::Any:
        case Passed::Array:
            signature.parameters.push_back(vm::Scalar::Ptr);
            signature.parameters.push_back(vm::Scalar::U32);
            break;
        }
    }
    return signature;
}

std::size_t FunctionInterface::position(std::size_t parameter) const {
    std::size_t position = 0;
    for (std::size_t i = 0; i < parameter; ++i) {
        position += places(parameters[i]);
    }
    return position;
}

} // namespace eposp::plctest
