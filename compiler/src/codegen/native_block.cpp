// The body of a native function block (compile()'s linked libraries): one call of the host
// function of the block's name with the address of the instance. The import's signature lists
// the scalar of every field of the instance in declaration order, so linking refuses a C++ body
// written for another layout of the block (vm/native.hpp, NativeBlock).

#include "eposp/compiler/sema/type.hpp"
#include "pou_generator.hpp"

namespace eposp::compiler::codegen {

using vm::Operand;

void PouGenerator::call_native_block() {
    const sema::Type& instance = *types_.instance(pou_);
    vm::NativeSignature signature{.parameters = {vm::Scalar::Ptr}};
    for (const sema::Field& field : instance.fields) {
        const bool by_reference = field.section == ast::VarSectionKind::InOut;
        if (!checks::is_native_block_variable(field)) {
            program_.refused_by_checks(DiagnosticCode::E0419); // checks/native_interfaces.cpp
            return;
        }
        signature.instance.push_back(by_reference ? vm::Scalar::Ptr : sema::scalar_of(*field.type));
    }
    const Place self = Place::direct(instance, Operand::self(0), false);
    call_native(pou_.name.name, signature, {Value{address_of(self), &types_.reference(&instance)}});
}

} // namespace eposp::compiler::codegen
