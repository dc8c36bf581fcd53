// The constants of the real functions of table 23-24 (SQRT, LN, LOG, EXP, SIN ... ATAN2, EXPT
// and `**`), computed by the VM's own functions (vm/stdlib/real_functions.hpp) in the real type
// the call computes in, so that REAL's single-precision result is REAL's. A NaN (a domain
// error: SQRT(-1.0), LN(-1.0)) is no constant: it is left to run time, which gives it as the
// VM's libm does; infinities are constants.

#include "constant_folder.hpp"
#include "eposp/vm/stdlib/real_functions.hpp"

#include <cmath>

namespace eposp::compiler::types {

namespace {

template <typename F>
std::optional<Constant> apply(std::string_view name, const std::vector<Constant>& inputs) {
    const vm::stdlib::RealFunction<F>* function = vm::stdlib::find_real_function<F>(name);
    const std::size_t arity = function == nullptr ? 0 : function->unary != nullptr ? 1 : 2;
    if (arity == 0 || inputs.size() != arity) {
        return std::nullopt;
    }
    F x[2]{};
    for (std::size_t i = 0; i < arity; ++i) {
        const auto* value = std::get_if<double>(&inputs[i]);
        if (value == nullptr) {
            return std::nullopt;
        }
        x[i] = static_cast<F>(*value); // exact: the input is already a value of F
    }
    const F result = arity == 1 ? function->unary(x[0]) : function->binary(x[0], x[1]);
    if (std::isnan(result)) {
        return std::nullopt;
    }
    return static_cast<double>(result);
}

} // namespace

std::optional<Constant> ConstantFolder::real_function(std::string_view name,
                                                      const std::vector<Constant>& inputs,
                                                      const sema::Type& real) const {
    switch (sema::scalar_of(real)) {
    case vm::Scalar::F32:
        return apply<float>(name, inputs);
    case vm::Scalar::F64:
        return apply<double>(name, inputs);
    default:
        return std::nullopt;
    }
}

std::optional<Constant> ConstantFolder::power_value(const ast::BinaryExpression& node,
                                                    const sema::Type& type) const {
    // As code generation computes `**`: both operands converted to the result's real type,
    // then EXPT of that type.
    std::vector<Constant> inputs;
    for (const ast::Expression* operand : {node.left.get(), node.right.get()}) {
        const Constant* value = program_.constant_of(*operand);
        const sema::Type* from = program_.type_of(*operand);
        auto input = value != nullptr && from != nullptr
                         ? convert(*value, types_.unranged(*from), type)
                         : std::nullopt;
        if (!input) {
            return std::nullopt;
        }
        inputs.push_back(std::move(*input));
    }
    return real_function("EXPT", inputs, type);
}

} // namespace eposp::compiler::types
