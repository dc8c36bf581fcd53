// The standard functions of IEC 61131-3 ed. 3, 6.6.2.5 (tables 22-36) that are opcodes or
// natives: type conversions, numeric, bit shift, comparison and string functions (selection in
// selection_functions.cpp).

#include "../types/expression_typer.hpp"
#include "eposp/compiler/sema/standard_library.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "eposp/vm/stdlib/manifest.hpp"
#include "pou_generator.hpp"

#include <algorithm>

namespace eposp::compiler::codegen {

using E = ast::ElementaryType;
using vm::Opcode;
using vm::Operand;
using S = vm::Scalar;
using vm::stdlib::Family;
using vm::stdlib::Operation;

std::optional<Value> PouGenerator::standard_function(const types::CallTarget& target,
                                                     const ast::Expression& call,
                                                     const sema::Type* hint,
                                                     const Destination* dest) {
    const std::string& name = target.name;
    const auto& node = std::get<ast::CallExpression>(call.node);
    // EN and ENO are handled around the call (pou_enable.cpp); the function sees its inputs, in
    // the order of its signature, as the typing stage took them.
    for (const ast::Argument& argument : node.arguments) {
        if (!is_enable_argument(argument) && argument.kind == ast::Argument::Kind::Output) {
            program_.refused_by_checks(DiagnosticCode::E0210); // the typing stage's
            return std::nullopt;
        }
    }
    const Arguments arguments = types::standard_arguments(name, node);
    if (std::find(arguments.begin(), arguments.end(), nullptr) != arguments.end()) {
        program_.refused_by_checks(DiagnosticCode::E0210); // types/standard_function_typing.cpp
        return std::nullopt;
    }
    if (sema::is_conversion_function(name)) {
        return conversion(target, arguments, dest);
    }
    // An input is what it is before a later input's call may change it (left to right).
    const HeldLoads held(*this, arguments.size() > 1 &&
                                    std::any_of(std::next(arguments.begin()), arguments.end(),
                                                [this](const ast::Argument* argument) {
                                                    return may_write_variables(*argument->value);
                                                }));
    const vm::stdlib::StandardFunction* function = vm::stdlib::find_standard_function(name);
    // ADD and MUL on times are extensible, each a row of table 30 (time_functions.cpp).
    const bool extended_time =
        function != nullptr && function->family == Family::Time && function->time.overloaded &&
        (function->operation == Operation::Add || function->operation == Operation::Multiply);
    if (function == nullptr || arguments.size() < function->min_inputs ||
        (arguments.size() > function->max_inputs && !extended_time)) {
        program_.refused_by_checks(DiagnosticCode::E0306); // the typing stage's
        return std::nullopt;
    }
    switch (function->family) {
    case Family::Text:
        return string_function(target, arguments, dest);
    case Family::Bound:
        return array_bound(name, node, dest);
    case Family::Address:
    case Family::Size:
        return address_or_size(target, call, arguments);
    case Family::Time:
        return time_function(target, arguments, dest);
    case Family::Select:
    case Family::Extreme:
    case Family::Limit:
    case Family::Multiplex:
    case Family::Move:
        return selection(target, arguments, hint, dest);
    default:
        return numeric_function(target, arguments, hint, dest);
    }
}

std::optional<Value> PouGenerator::address_or_size(const types::CallTarget& target,
                                                   const ast::Expression& call,
                                                   const Arguments& arguments) {
    if (vm::stdlib::find_standard_function(target.name)->family == Family::Address) {
        // As in CODESYS, an address goes into a POINTER TO of any type (the VM checks every
        // access through it); REF() is the typed, IEC way.
        const auto object = place(*arguments.front()->value);
        return object ? std::optional(Value{address_of(*object), target.result}) : std::nullopt;
    }
    // SIZEOF: the typing stage's constant, of the type it chose for it.
    const types::Constant* size = program_.typed().constant_of(call);
    if (size == nullptr || target.result == nullptr) {
        program_.refused_by_checks(DiagnosticCode::E0417); // checks/conformant_sizes.cpp
        return std::nullopt;
    }
    return Value{
        integer_constant(*target.result, static_cast<std::int64_t>(std::get<std::uint64_t>(*size))),
        target.result};
}

std::optional<Value> PouGenerator::as_dint(const ast::Expression& expression) {
    const sema::Type& dint = types_.elementary(E::Dint);
    const auto value = eval(expression, &dint);
    if (!value) {
        return std::nullopt;
    }
    if (!sema::is_integer(*value->type)) {
        program_.refused_by_checks(DiagnosticCode::E0305); // the typing stage's
        return std::nullopt;
    }
    if (wide_index(*value->type, true)) {
        return saturated_dint(*value);
    }
    return explicit_convert(*value, dint, nullptr);
}

std::optional<Value> PouGenerator::explicit_convert(const Value& value, const sema::Type& want,
                                                    const Destination* dest) {
    const sema::Type& from = *value.type;
    if (&from == &want) {
        return value;
    }
    const bool from_string = from.kind == sema::TypeKind::String;
    const bool to_string = want.kind == sema::TypeKind::String;
    if (to_string) {
        // Made straight in a text destination only where that holds no more than the typed
        // result: `s200 := TO_STRING(s100)` is the STRING[80] it is typed, cut at 80 characters.
        const bool in_destination = dest != nullptr && dest->type->kind == sema::TypeKind::String &&
                                    dest->type->wide == want.wide &&
                                    dest->type->capacity <= want.capacity;
        const Operand result = in_destination ? dest->operand : temp(want);
        const sema::Type& target = in_destination ? *dest->type : want;
        // Table 22 (types/call_typing.cpp): a text of the same width is assigned (TO_STRING of a
        // STRING[10]), one of the other width converted character by character; a WSTRING
        // comes from WCHAR only, a STRING from every other elementary type.
        const auto native =
            !from_string
                ? vm::stdlib::to_text_binding(sema::native_type(from), sema::char_width(want))
            : from.wide == want.wide ? vm::stdlib::text_assignment_binding(sema::char_width(want))
                                     : vm::stdlib::text_width_binding(sema::char_width(want));
        call_native(native.name, native.signature, {Value{result, &target}, value});
        return Value{result, &target};
    }
    if (from_string) {
        const auto native =
            vm::stdlib::from_text_binding(sema::native_type(want), sema::char_width(from));
        call_native(native.name, native.signature, {value});
        return native_result(native.signature, want, dest);
    }
    const bool from_time = sema::is_time_like(from);
    const bool to_time = sema::is_time_like(want);
    if (from_time && to_time) {
        const sema::TimePart part = sema::time_part(from, want);
        if (part == sema::TimePart::All) {
            return Value{value.operand, &want}; // the same nanoseconds
        }
        const auto native = vm::stdlib::date_time_part_binding(
            part == sema::TimePart::Day ? vm::NativeType::Date : vm::NativeType::TimeOfDay);
        call_native(native.name, native.signature, {value});
        return native_result(native.signature, want, dest);
    }
    Value source = value;
    if (from_time && sema::number_unit(from.elementary) != 1) {
        // Durations and times count in nanoseconds; as numbers they count in their unit.
        const sema::Type& lint = types_.elementary(E::Lint);
        const Operand scaled = temp(lint);
        emit(Opcode::DivI64, scaled, value.operand,
             integer_constant(lint, sema::number_unit(from.elementary)));
        source = Value{scaled, &lint};
    }
    if (to_time) {
        const sema::Type& lint = types_.elementary(E::Lint);
        const auto as_lint = explicit_convert(source, lint, nullptr);
        const Operand result = result_operand(want, dest);
        emit(Opcode::Mul64, result, as_lint->operand,
             integer_constant(lint, sema::number_unit(want.elementary)));
        return Value{result, &want};
    }
    const S a = sema::scalar_of(*source.type);
    const S b = sema::scalar_of(want);
    if (a == b) {
        return Value{source.operand, &want};
    }
    const Operand result = result_operand(want, dest);
    emit(program_.opcodes().get("Cvt", std::string(type_suffix(a)) + std::string(type_suffix(b))),
         result, source.operand);
    return Value{result, &want};
}

std::optional<Value> PouGenerator::conversion(const types::CallTarget& target,
                                              const Arguments& arguments, const Destination* dest) {
    if (arguments.size() != 1 || target.operand == nullptr || target.result == nullptr) {
        program_.refused_by_checks(DiagnosticCode::E0306); // types/call_typing.cpp
        return std::nullopt;
    }
    // The input as the conversion's source type (`INT_TO_REAL(b)` of a BYTE b widens it first),
    // then converted explicitly.
    const sema::Type& source = *target.operand;
    auto value = eval(*arguments.front()->value, &source);
    if (value && value->type != &source &&
        !(value->type->kind == sema::TypeKind::String && source.kind == sema::TypeKind::String &&
          value->type->wide == source.wide)) {
        if (!sema::converts_implicitly(*value->type, source)) {
            program_.refused_by_checks(DiagnosticCode::E0305); // types/call_typing.cpp
            return std::nullopt;
        }
        value = convert(*value, source, nullptr);
    }
    return value ? explicit_convert(*value, *target.result, dest) : std::nullopt;
}

std::optional<Value> PouGenerator::string_function(const types::CallTarget& target,
                                                   const Arguments& arguments,
                                                   const Destination* dest) {
    // Text arguments, then positions and lengths, in the order of the native's parameters.
    const vm::stdlib::StandardFunction& function = *vm::stdlib::find_standard_function(target.name);
    const bool folded = function.max_inputs == vm::stdlib::kExtensible; // CONCAT
    const std::size_t texts = folded ? arguments.size() : function.texts;
    // IEC 61131-3 table 43 on STRING and on WSTRING alike: the first text says which, the
    // others must agree; the WSTRING natives carry a suffix (LEFT_WSTRING).
    std::vector<Value> values;
    bool wide = false;
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const ast::Expression& expression = *arguments[i]->value;
        auto value = i < texts ? eval(expression, nullptr) : as_dint(expression);
        if (!value) {
            return std::nullopt;
        }
        if (i < texts) {
            const bool is_string = value->type->kind == sema::TypeKind::String;
            if (i == 0 && is_string) {
                wide = value->type->wide;
            }
            if (!is_string || value->type->wide != wide) {
                program_.refused_by_checks(DiagnosticCode::E0305); // the typing stage's
                return std::nullopt;
            }
        }
        values.push_back(*value);
    }
    const auto native = vm::stdlib::native_binding(function, wide ? vm::stdlib::Variant::Wide
                                                                  : vm::stdlib::Variant::Base);
    if (function.text_result == vm::stdlib::TextResult::Count) {
        call_native(native.name, native.signature, values);
        // LEN and FIND are INT, as in CODESYS; the natives count in DINT.
        return native_result(native.signature, *target.result, dest);
    }
    // The string that holds whatever the inputs make: the typing stage's (text_capacity).
    const sema::Type& natural = *target.result;
    const bool into_dest =
        dest != nullptr && dest->type->kind == sema::TypeKind::String && dest->type->wide == wide;
    Value result{into_dest ? dest->operand : temp(natural), into_dest ? dest->type : &natural};
    if (folded) {
        // CONCAT is binary in the VM: folded left to right into the result (vm/README).
        for (std::size_t i = 2; into_dest && i < values.size(); ++i) {
            if (values[i].operand.raw == result.operand.raw) {
                result = Value{temp(natural), &natural};
            }
        }
        call_native(native.name, native.signature, {result, values[0], values[1]});
        for (std::size_t i = 2; i < values.size(); ++i) {
            call_native(native.name, native.signature, {result, result, values[i]});
        }
        return result;
    }
    std::vector<Value> all{result};
    all.insert(all.end(), values.begin(), values.end());
    call_native(native.name, native.signature, all);
    return result;
}

std::optional<Value> PouGenerator::numeric_function(const types::CallTarget& target,
                                                    const Arguments& arguments,
                                                    const sema::Type* hint,
                                                    const Destination* dest) {
    const vm::stdlib::StandardFunction& function = *vm::stdlib::find_standard_function(target.name);
    using Op = ast::BinaryOperator;
    const Family family = function.family;
    if (family == Family::Arithmetic || family == Family::Comparison ||
        (family == Family::Logic && function.operation != Operation::Not)) {
        const auto operation = types::operator_of(function.operation);
        if (!operation) {
            program_.refused_by_checks(DiagnosticCode::E0305); // the typing stage's
            return std::nullopt;
        }
        const Op op = *operation;
        const bool comparison = op >= Op::Less && op <= Op::NotEqual;
        // The inputs brought to the overload the typing stage chose; an input stores its
        // argument, so a small integer computed in DINT is cut to its type first.
        // Extensible comparisons hold for each neighbouring pair (table 28): GT(a, b, c) is
        // a > b AND b > c; the other extensible functions fold left to right.
        if (target.operand == nullptr) {
            program_.refused_by_checks(DiagnosticCode::E0305); // the typing stage's
            return std::nullopt;
        }
        const sema::Type& type = *target.operand;
        const auto first = value_as(*arguments[0]->value, type);
        const auto second = first ? value_as(*arguments[1]->value, type) : std::nullopt;
        if (!second) {
            return std::nullopt;
        }
        auto result = apply(op, *first, *second, arguments.size() == 2 ? dest : nullptr);
        Value previous = *second;
        for (std::size_t i = 2; result && i < arguments.size(); ++i) {
            auto next = value_as(*arguments[i]->value, type);
            if (!next) {
                return std::nullopt;
            }
            if (comparison) {
                const auto step = apply(op, previous, *next, nullptr);
                if (!step) {
                    return std::nullopt;
                }
                emit(Opcode::And8, result->operand, result->operand, step->operand);
                previous = *next;
            } else {
                result = apply(op, *result, *next, nullptr);
            }
        }
        return result;
    }
    if (family == Family::Logic) { // NOT
        const auto value = eval(*arguments[0]->value, hint);
        if (!value) {
            return std::nullopt;
        }
        const Operand result = result_operand(*value->type, dest);
        if (sema::is_bool(*value->type)) {
            emit(Opcode::NotB, result, value->operand);
        } else if (sema::is_bit_string(*value->type) || sema::is_integer(*value->type)) {
            emit(op_width("Not", *value->type), result, value->operand);
        } else {
            program_.refused_by_checks(DiagnosticCode::E0304); // the typing stage's
            return std::nullopt;
        }
        return Value{result, value->type};
    }
    if (family == Family::Shift) {
        const auto value = eval(*arguments[0]->value, hint);
        const sema::Type& udint = types_.elementary(E::Udint);
        // An untyped literal count is a UDINT where it fits one (the typing stage's).
        auto count = value ? eval(*arguments[1]->value, nullptr) : std::nullopt;
        if (!count) {
            return std::nullopt;
        }
        if ((!sema::is_bit_string(*value->type) && !sema::is_integer(*value->type)) ||
            !sema::is_integer(*count->type)) {
            program_.refused_by_checks(DiagnosticCode::E0305); // the typing stage's
            return std::nullopt;
        }
        // A count is taken as unsigned (a negative one as its two's complement): SHL and SHR
        // by one of at least the width give 0, ROL and ROR rotate by it modulo the width. The
        // VM's count is a UDINT: cut to 32 bits, a 64-bit count keeps its remainder modulo
        // every width (a divisor of 2^32), but a shift needs one beyond 32 bits kept beyond.
        const bool shift = function.operation == Operation::ShiftLeft ||
                           function.operation == Operation::ShiftRight;
        const vm::Scalar wide = sema::scalar_of(*count->type);
        if (shift && (wide == vm::Scalar::I64 || wide == vm::Scalar::U64)) {
            // Beyond UDINT's range, UDINT's maximum: as far beyond every width.
            const Operand top = integer_constant(udint, 0xFFFF'FFFF);
            const Operand beyond = temp(types_.elementary(E::Bool));
            const Operand cut = temp(udint);
            emit(Opcode::LtU64, beyond, integer_constant(types_.elementary(E::Ulint), 0xFFFF'FFFF),
                 count->operand);
            emit(Opcode::CvtI64I32, cut, count->operand);
            emit(Opcode::CMov32, cut, beyond, top);
            count = Value{cut, &udint};
        } else {
            count = explicit_convert(*count, udint, nullptr);
        }
        const char* opcode = function.operation == Operation::ShiftLeft    ? "Shl"
                             : function.operation == Operation::ShiftRight ? "Shr"
                             : function.operation == Operation::RotateLeft ? "Rol"
                                                                           : "Ror";
        const Operand result = result_operand(*value->type, dest);
        emit(op_width(opcode, *value->type), result, value->operand, count->operand);
        return Value{result, value->type};
    }
    if (family == Family::Truncate) {
        const auto value = eval(*arguments[0]->value, &types_.elementary(E::Lreal));
        if (!value || !sema::is_real(*value->type)) {
            if (value) {
                program_.refused_by_checks(DiagnosticCode::E0305); // the typing stage's
            }
            return std::nullopt;
        }
        const sema::Type& lint = types_.elementary(E::Lint);
        const Operand wide = temp(lint);
        emit(op("Trunc", *value->type), wide, value->operand);
        // Into DINT it saturates as the *_TO_* conversions do: through LREAL, which holds every
        // DINT exactly and keeps a larger value out of DINT's range.
        const auto real =
            explicit_convert(Value{wide, &lint}, types_.elementary(E::Lreal), nullptr);
        return real ? explicit_convert(*real, types_.elementary(E::Dint), dest) : real;
    }
    if (family == Family::Absolute) {
        const auto value = eval(*arguments[0]->value, hint);
        if (!value || !sema::is_numeric(*value->type)) {
            if (value) {
                program_.refused_by_checks(DiagnosticCode::E0305); // the typing stage's
            }
            return std::nullopt;
        }
        const Operand result = result_operand(*value->type, dest);
        if (sema::is_signed(*value->type)) {
            emit(op("Abs", *value->type), result, value->operand);
        } else {
            move(result, *value->type, *value);
        }
        return Value{result, value->type};
    }
    // The real functions: the inputs converted to the real type the typing stage chose first.
    const bool two = function.max_inputs == 2;
    if (target.operand == nullptr || !sema::is_real(*target.operand)) {
        program_.refused_by_checks(DiagnosticCode::E0305); // types/standard_function_typing.cpp
        return std::nullopt;
    }
    const sema::Type& real = *target.operand;
    auto first = eval(*arguments[0]->value, &real);
    if (!first || !sema::is_numeric(*first->type)) {
        if (first) {
            program_.refused_by_checks(DiagnosticCode::E0305); // the typing stage's
        }
        return std::nullopt;
    }
    first = explicit_convert(*first, real, nullptr);
    std::vector<Value> values{*first};
    if (two) {
        auto second = eval(*arguments[1]->value, &real);
        if (!second || !sema::is_numeric(*second->type)) {
            if (second) {
                program_.refused_by_checks(DiagnosticCode::E0305); // the typing stage's
            }
            return std::nullopt;
        }
        values.push_back(*explicit_convert(*second, real, nullptr));
    }
    if (vm::stdlib::implementation(function) == vm::stdlib::Implementation::Inline) { // SQRT
        const Operand result = result_operand(real, dest);
        emit(op("Sqrt", real), result, values[0].operand);
        return Value{result, &real};
    }
    const auto native = vm::stdlib::native_binding(function, sema::scalar_of(real) == S::F32
                                                                 ? vm::stdlib::Variant::Base
                                                                 : vm::stdlib::Variant::Wide);
    call_native(native.name, native.signature, values);
    return native_result(native.signature, real, dest);
}

} // namespace eposp::compiler::codegen
