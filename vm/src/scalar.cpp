#include "eposp/vm/scalar.hpp"

namespace eposp::vm {

std::string_view scalar_name(Scalar s) {
    switch (s) {
    case Scalar::Bool:
        return "BOOL";
    case Scalar::I8:
        return "SINT";
    case Scalar::I16:
        return "INT";
    case Scalar::I32:
        return "DINT";
    case Scalar::I64:
        return "LINT";
    case Scalar::U8:
        return "USINT";
    case Scalar::U16:
        return "UINT";
    case Scalar::U32:
        return "UDINT";
    case Scalar::U64:
        return "ULINT";
    case Scalar::F32:
        return "REAL";
    case Scalar::F64:
        return "LREAL";
    case Scalar::Ptr:
        return "POINTER";
    }
    return "?";
}

} // namespace eposp::vm
