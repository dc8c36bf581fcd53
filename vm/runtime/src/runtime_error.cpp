#include "eposp/vm/runtime_error.hpp"

namespace eposp::vm {

std::uint16_t error_code_of(Trap trap) {
    switch (trap) {
    case Trap::IndexOutOfRange:
    case Trap::NullDereference:
    case Trap::InvalidAddress:
        return error_code::kDataAccess;
    case Trap::DivisionByZero:
    case Trap::BudgetExceeded:
    case Trap::StackOverflow:
    case Trap::NativeError:
    case Trap::SubrangeViolation:
        return error_code::kInterpreter;
    }
    return error_code::kInterpreter;
}

} // namespace eposp::vm
