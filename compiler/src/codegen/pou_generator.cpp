#include "pou_generator.hpp"

#include "constant_declarations.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "eposp/vm/stdlib/manifest.hpp"

#include <algorithm>

namespace eposp::compiler::codegen {

using vm::Opcode;
using vm::Operand;

PouGenerator::PouGenerator(ProgramGenerator& program, const sema::SemanticModel& model,
                           const ast::Pou& pou, std::uint32_t index)
    : program_(program), model_(model), pou_(pou), index_(index), builder_(program.builder()),
      types_(program.types()) {}

std::uint32_t PouGenerator::generate() {
    builder_.begin_body(index_);
    const bool native = program_.is_native_block(pou_);
    if (!native) { // a native body has no source: its errors are at its call (vm run_end.cpp)
        builder_.line(pou_.range.begin.line);
    }
    declare_locals(); // an ANY parameter is refused by the checks (checks/generic_parameters.cpp)
    end_ = builder_.label();
    initialise_frame();
    if (native) {
        call_native_block();
    } else {
        statements(pou_.body);
    }
    bind(end_);
    emit(Opcode::Ret);
    const std::uint32_t frame = sema::align_up(frame_max_, 8);
    const std::uint32_t out = sema::align_up(out_max_, 8);
    builder_.end_body(frame, out);
    return frame + out;
}

void PouGenerator::declare_locals() {
    const bool function = pou_.kind == ast::PouKind::Function;
    auto declare = [&](const sema::Field& field, Operand operand) {
        // Constants are read-only. Inputs are too in IEC 61131-3, but libraries written for
        // CODESYS (OSCAT) use them as scratch variables: writing one is a warning.
        const bool writable = !is_constant(pou_, field.declaration);
        Place place = Place::direct(*field.type, operand, writable);
        if (field.section == ast::VarSectionKind::InOut) {
            place = {.kind = Place::Kind::Indirect,
                     .type = field.type->element,
                     .operand = operand,
                     .writable = true};
        }
        locals_[sema::fold_case(field.name)] = {place, field.section};
    };
    const sema::Type* frame = types_.frame(pou_);
    if (!function) {
        for (const sema::Type* part = types_.instance(pou_); part != nullptr; part = part->base) {
            for (const sema::Field& field : part->fields) {
                if (!locals_.contains(sema::fold_case(field.name))) {
                    declare(field, Operand::self(field.offset));
                }
            }
        }
    }
    for (const sema::Field& field : frame->fields) {
        declare(field, Operand::local(field.offset));
    }
    locals_end_ = frame_top_ = frame_max_ = frame->size;
}

void PouGenerator::initialise_frame() {
    // 6.5.1.3: a function's variables and every VAR_TEMP start from their initial values at
    // each call. Runs of consecutive non-parameter fields are copied from one template each.
    const sema::Type& frame = *types_.frame(pou_);
    std::vector<std::uint8_t> bytes(frame.size);
    program_.initial_value(frame, nullptr, bytes);
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    auto flush = [&] {
        if (end > begin) {
            const std::vector<std::uint8_t> part(bytes.begin() + begin, bytes.begin() + end);
            emit(Opcode::MovN, Operand::local(begin), program_.constant(part, 8),
                 Operand::imm(end - begin));
        }
    };
    for (const sema::Field& field : frame.fields) {
        const bool parameter = field.section == ast::VarSectionKind::Input ||
                               field.section == ast::VarSectionKind::InOut;
        if (parameter) {
            flush();
            begin = end = field.offset + field.type->size;
        } else {
            if (end == begin) {
                begin = field.offset;
            }
            end = field.offset + field.type->size;
        }
    }
    flush();
}

Operand PouGenerator::temp(const sema::Type& type) {
    frame_top_ = sema::align_up(frame_top_, std::max<std::uint32_t>(type.align, 1));
    const Operand operand = Operand::local(frame_top_);
    frame_top_ += type.size;
    frame_max_ = std::max(frame_max_, frame_top_);
    if (type.kind == sema::TypeKind::String) {
        // The header: capacity, length 0.
        emit(Opcode::Ldi32, operand, Operand::imm(type.capacity));
    }
    return operand;
}

void PouGenerator::release(std::uint32_t mark) {
    frame_top_ = mark;
    cache_.release(mark);
}

void PouGenerator::emit(Opcode op, Operand a, Operand b, Operand c, std::uint16_t aux) {
    builder_.emit(op, a, b, c, aux);
    cache_.written(op, a, b, c, aux, [this](std::uint16_t descriptor) {
        const auto it = array_bytes_.find(descriptor);
        return it == array_bytes_.end() ? vm::kOffsetMask : it->second;
    });
}

void PouGenerator::bind(vm::Label label) {
    builder_.bind(label);
    cache_.clear();
}

std::uint16_t PouGenerator::array_descriptor(const vm::ArrayDescriptor& array) {
    const std::uint16_t descriptor = builder_.array(array);
    array_bytes_[descriptor] = array.count * array.element_size;
    return descriptor;
}

bool PouGenerator::is_temporary(Operand operand) const {
    return operand.base() == vm::Base::Frame && operand.offset() >= locals_end_;
}

std::uint32_t PouGenerator::out_slot(std::uint32_t end) {
    out_max_ = std::max(out_max_, end);
    return end;
}

Operand PouGenerator::native_block() const {
    return Operand::out(sema::align_up(out_pending_, 8));
}

std::optional<Place> PouGenerator::variable(const sema::Symbol& symbol) {
    // A PROGRAM's own VAR_GLOBAL lives in its instance; other globals in the configuration.
    const auto local = locals_.find(sema::fold_case(symbol.name));
    if (symbol.kind == sema::SymbolKind::Variable &&
        (symbol.section == ast::VarSectionKind::External ||
         (symbol.section == ast::VarSectionKind::Global && local == locals_.end()))) {
        auto global = program_.global(symbol.name);
        if (!global) {
            program_.refused_by_checks(DiagnosticCode::E0208); // sema/name_resolver.cpp
            return std::nullopt;
        }
        if (symbol.section == ast::VarSectionKind::External && symbol.variable != nullptr &&
            is_constant(pou_, symbol.variable)) {
            global->writable = false;
        }
        return global;
    }
    if (symbol.kind == sema::SymbolKind::ProgramInstance) {
        return program_.program_instance_variable(symbol.name); // a program connection's source
    }
    if (symbol.kind == sema::SymbolKind::Pou && symbol.pou->kind == ast::PouKind::Program) {
        return program_.instance_of_program(*symbol.pou); // `P.x`, `P()` (CODESYS)
    }
    if (symbol.kind == sema::SymbolKind::Variable ||
        (symbol.kind == sema::SymbolKind::Pou && symbol.pou == &pou_)) {
        if (local != locals_.end()) {
            return local->second.place;
        }
    }
    // A variable missing from the frame is one whose declaration failed, already reported.
    if (symbol.kind != sema::SymbolKind::Variable || !program_.diagnostics().has_errors()) {
        program_.refused_by_checks(DiagnosticCode::E0204); // types/operand_typing.cpp
    }
    return std::nullopt;
}

Opcode PouGenerator::op(std::string_view family, const sema::Type& type) const {
    return program_.opcodes().get(family, type_suffix(sema::scalar_of(type)));
}

Opcode PouGenerator::op_width(std::string_view family, const sema::Type& type) const {
    const vm::Scalar scalar = sema::scalar_of(type);
    const bool real = scalar == vm::Scalar::F32 || scalar == vm::Scalar::F64;
    return program_.opcodes().get(family, real ? type_suffix(scalar) : width_suffix(scalar));
}

void PouGenerator::load_immediate(Operand dst, const sema::Type& type, std::int64_t value) {
    const auto raw = static_cast<std::uint64_t>(value);
    emit(program_.opcodes().get("Ldi", width_suffix(sema::scalar_of(type))), dst,
         Operand::imm(static_cast<std::uint32_t>(raw)),
         Operand::imm(static_cast<std::uint32_t>(raw >> 32)));
}

void PouGenerator::clear(Operand dst, const sema::Type& type) {
    if (type.kind == sema::TypeKind::String) {
        emit(Opcode::Ldi32, dst, Operand::imm(type.capacity)); // capacity, length 0
    } else if (sema::is_scalar(type)) {
        load_immediate(dst, type, 0);
    } else {
        emit(Opcode::MovN, dst,
             program_.constant(std::vector<std::uint8_t>(type.size, 0), std::max(type.align, 1U)),
             Operand::imm(type.size));
    }
}

void PouGenerator::move(Operand dst, const sema::Type& dst_type, const Value& src) {
    if (dst.raw == src.operand.raw) {
        return;
    }
    if (sema::is_scalar(dst_type)) {
        emit(program_.opcodes().get("Mov", width_suffix(sema::scalar_of(dst_type))), dst,
             src.operand);
        return;
    }
    if (dst_type.kind == sema::TypeKind::String && src.type != &dst_type) {
        const auto assign = vm::stdlib::text_assignment_binding(sema::char_width(dst_type));
        call_native(assign.name, assign.signature, {Value{dst, &dst_type}, src});
        return;
    }
    emit(Opcode::MovN, dst, src.operand, Operand::imm(dst_type.size));
}

Value PouGenerator::load(const Place& place, const Destination* dest) {
    // A subrange variable's value computes as its base type (pou_subranges.cpp).
    const sema::Type& type = types_.unranged(*place.type);
    if (place.kind == Place::Kind::Direct && hold_loads_ && !is_temporary(place.operand)) {
        const Operand copy = temp(type);
        move(copy, type, Value{place.operand, &type});
        return {copy, &type};
    }
    if (place.kind == Place::Kind::Direct) {
        return {place.operand, &type};
    }
    if (place.kind == Place::Kind::Element && !sema::is_scalar(type)) {
        return load(through_pointer(place), dest);
    }
    if (place.kind == Place::Kind::Element) {
        // An element loaded before, while neither the array nor the index changed.
        const ValueCache::Key key{ValueCache::Kind::Load, place.operand.raw, place.index.raw,
                                  place.array};
        const bool into_dest = dest != nullptr && dest->type == &type;
        if (const auto hit = into_dest ? std::nullopt : cache_.find(key)) {
            return {*hit, &type};
        }
        const Operand result = result_operand(type, dest);
        emit(program_.opcodes().get("Ldx", width_suffix(sema::scalar_of(type))), result,
             place.operand, place.index, place.array);
        if (!into_dest) {
            cache_.add(key, result, type.size,
                       {{place.index, 4}, {place.operand, array_bytes_.at(place.array)}});
        }
        return {result, &type};
    }
    const Operand result = result_operand(type, dest);
    if (sema::is_scalar(type)) {
        emit(program_.opcodes().get("Ldp", width_suffix(sema::scalar_of(type))), result,
             place.operand, Operand::imm(place.offset));
    } else {
        emit(Opcode::LdpN, result, address_of(place), Operand::imm(type.size));
    }
    return {result, &type};
}

void PouGenerator::store(const Place& place, const Value& value) {
    const sema::Type& type = *place.type;
    if (place.kind == Place::Kind::Direct) {
        move(place.operand, type, value);
    } else if (place.kind == Place::Kind::Element && !sema::is_scalar(type)) {
        store(through_pointer(place), value);
    } else if (place.kind == Place::Kind::Element) {
        emit(program_.opcodes().get("Stx", width_suffix(sema::scalar_of(type))), place.operand,
             place.index, value.operand, place.array);
    } else if (sema::is_scalar(type)) {
        emit(program_.opcodes().get("Stp", width_suffix(sema::scalar_of(type))), place.operand,
             value.operand, Operand::imm(place.offset));
    } else if (type.kind == sema::TypeKind::String && value.type != &type) {
        const auto assign = vm::stdlib::text_assignment_binding(sema::char_width(type));
        call_native(assign.name, assign.signature,
                    {Value{address_of(place), &types_.reference(&type)}, value});
    } else {
        emit(Opcode::StpN, address_of(place), value.operand, Operand::imm(type.size));
    }
}

Place PouGenerator::member(const Place& place, std::uint32_t delta, const sema::Type& type) {
    switch (place.kind) {
    case Place::Kind::Direct:
        return Place::direct(type, shifted(place.operand, delta), place.writable);
    case Place::Kind::Element: {
        // A part of an element is an element too, further into it: one access at run time.
        vm::ArrayDescriptor part = builder_.array_at(place.array);
        part.offset += delta;
        Place result = place;
        result.type = &type;
        result.array = array_descriptor(part);
        return result;
    }
    case Place::Kind::Indirect:
        break;
    }
    Place result = place;
    result.type = &type;
    result.offset += delta;
    return result;
}

Place PouGenerator::through_pointer(const Place& place) {
    return {.kind = Place::Kind::Indirect,
            .type = place.type,
            .operand = address_of(place),
            .writable = place.writable};
}

Operand PouGenerator::address_of(const Place& place) {
    const sema::Type& pointer = types_.reference(place.type);
    if (place.kind == Place::Kind::Indirect && place.offset == 0) {
        return place.operand;
    }
    // The address of an element, remembered while neither the array nor the index changes.
    const ValueCache::Key key{ValueCache::Kind::Address, place.operand.raw, place.index.raw,
                              place.array};
    if (place.kind == Place::Kind::Element) {
        if (const auto hit = cache_.find(key)) {
            return *hit;
        }
    }
    const Operand result = temp(pointer);
    switch (place.kind) {
    case Place::Kind::Direct:
        emit(Opcode::Addr, result, place.operand, Operand::imm(place.type->size));
        break;
    case Place::Kind::Element:
        emit(Opcode::IdxA, result, place.operand, place.index, place.array);
        cache_.add(key, result, 8, {{place.index, 4}});
        break;
    case Place::Kind::Indirect:
        emit(Opcode::AddI64, result, place.operand, Operand::imm(place.offset));
        break;
    }
    return result;
}

} // namespace eposp::compiler::codegen
