// Integers of 64 bits (and UDINT) where the VM takes a DINT: array indices, string positions
// and lengths, the MUX selector. Cut to 32 bits, 4294967298 would be 2 and name another
// element or character; so an index keeps its whole value against its dimension, and a
// position or length beyond DINT's range becomes DINT's limit, which is as far past any string.

#include "pou_generator.hpp"

#include <limits>

namespace eposp::compiler::codegen {

using vm::Opcode;
using vm::Operand;
using E = ast::ElementaryType;

bool PouGenerator::wide_index(const sema::Type& type, bool negative_lower) const {
    switch (sema::scalar_of(type)) {
    case vm::Scalar::I64:
    case vm::Scalar::U64:
        return true;
    case vm::Scalar::U32:
        // A UDINT above DINT's range has the bits of a negative DINT: of an element only where
        // the dimension has negative indices.
        return negative_lower;
    default:
        return false;
    }
}

Operand PouGenerator::as_lint_clamped(const Value& value, std::int64_t high) {
    const sema::Type& lint = types_.elementary(E::Lint);
    if (sema::scalar_of(*value.type) != vm::Scalar::U64) {
        return convert(value, lint, nullptr)->operand;
    }
    const Operand top = integer_constant(lint, high);
    const Operand above = temp(types_.elementary(E::Bool));
    const Operand clamped = temp(lint);
    emit(Opcode::LtU64, above, top, value.operand);
    emit(Opcode::Mov64, clamped, value.operand);
    emit(Opcode::CMov64, clamped, above, top);
    return clamped;
}

Operand PouGenerator::dint_index(const Value& index, Operand lower, Operand count) {
    // lower + min(index - lower, count), the difference unsigned: the index itself inside the
    // dimension, lower + count (outside it, also modulo 2^32) anywhere else. A ULINT above
    // LINT's range is outside every dimension, and kept so by the clamp.
    const sema::Type& lint = types_.elementary(E::Lint);
    const Operand value = as_lint_clamped(index, std::numeric_limits<std::int64_t>::max());
    const Operand offset = temp(lint);
    const Operand past = temp(types_.elementary(E::Bool));
    emit(Opcode::Sub64, offset, value, lower);
    emit(Opcode::LtU64, past, count, offset);
    emit(Opcode::CMov64, offset, past, count);
    emit(Opcode::Add64, offset, offset, lower);
    const Operand result = temp(types_.elementary(E::Dint));
    emit(Opcode::CvtI64I32, result, offset);
    return result;
}

Value PouGenerator::saturated_dint(const Value& value) {
    const sema::Type& lint = types_.elementary(E::Lint);
    const sema::Type& dint = types_.elementary(E::Dint);
    const Operand high = integer_constant(lint, std::numeric_limits<std::int32_t>::max());
    const Operand clamped = temp(lint); // clamped in place: not the variable itself
    const Operand beyond = temp(types_.elementary(E::Bool));
    emit(Opcode::Mov64, clamped, as_lint_clamped(value, std::numeric_limits<std::int32_t>::max()));
    if (sema::is_signed(*value.type)) {
        const Operand low = integer_constant(lint, std::numeric_limits<std::int32_t>::min());
        emit(Opcode::LtI64, beyond, clamped, low);
        emit(Opcode::CMov64, clamped, beyond, low);
    }
    emit(Opcode::LtI64, beyond, high, clamped);
    emit(Opcode::CMov64, clamped, beyond, high);
    const Operand result = temp(dint);
    emit(Opcode::CvtI64I32, result, clamped);
    return Value{result, &dint};
}

} // namespace eposp::compiler::codegen
