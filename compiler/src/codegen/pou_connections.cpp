// Program connections (IEC 61131-3 ed. 3, 6.8.2): `PROGRAM inst WITH t : P (in := source,
// out => sink)`. A small body around the program's own copies every source into its input
// before each run and every output into its sink after it. Sources and sinks are expressions of
// the configuration (globals and their parts, constants, direct addresses, other programs'
// outputs), so they are typed and generated like any other expression.

#include "../checks/program_connections.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "pou_generator.hpp"

#include <fmt/format.h>

namespace eposp::compiler::codegen {

using vm::Opcode;
using vm::Operand;

std::uint32_t PouGenerator::generate_connections(const ast::ProgramInstance& instance,
                                                 std::uint32_t program) {
    builder_.begin_body(index_);
    builder_.line(instance.range.begin.line);
    std::vector<std::pair<const sema::Field*, const ast::Expression*>> outputs;
    for (const ast::Argument& argument : instance.connections) {
        const bool output = argument.kind == ast::Argument::Kind::Output;
        const sema::Field* field = connected_field(argument);
        // The checks refused the connections to what cannot be connected.
        if (field == nullptr || !checks::is_connectable(model_, types_, *argument.value, output)) {
            continue;
        }
        if (output) {
            outputs.emplace_back(field, argument.value.get());
        } else {
            connect_input(*field, *argument.value);
        }
    }
    emit(Opcode::CallFb, Operand::self(0), Operand::imm(program));
    for (const auto& [field, sink] : outputs) {
        connect_output(*field, *sink);
    }
    emit(Opcode::Ret);
    const std::uint32_t frame = sema::align_up(frame_max_, 8);
    const std::uint32_t out = sema::align_up(out_max_, 8);
    builder_.end_body(frame, out);
    return frame + out;
}

const sema::Field* PouGenerator::connected_field(const ast::Argument& argument) {
    const sema::Type& type = *types_.instance(pou_);
    const bool output = argument.kind == ast::Argument::Kind::Output;
    const sema::Field* field = argument.name ? type.field(argument.name->name) : nullptr;
    if (field == nullptr ||
        field->section != (output ? ast::VarSectionKind::Output : ast::VarSectionKind::Input)) {
        program_.refused_by_checks(DiagnosticCode::E0210); // types/configuration_typing.cpp
        return nullptr;
    }
    return field;
}

void PouGenerator::connect_input(const sema::Field& field, const ast::Expression& source) {
    builder_.line(source.range.begin.line); // a run-time error names the connection's line
    const std::uint32_t mark = frame_top_;
    const Place input = Place::direct(*field.type, Operand::self(field.offset));
    const Destination dest{input.operand, input.type};
    if (const auto value = value_as(source, *field.type, &dest)) {
        store(input, *value);
    }
    release(mark);
}

void PouGenerator::connect_output(const sema::Field& field, const ast::Expression& sink) {
    builder_.line(sink.range.begin.line);
    const std::uint32_t mark = frame_top_;
    const auto target = place(sink);
    if (target && !target->writable) {
        program_.refused_by_checks(DiagnosticCode::E0401); // checks/program_connections.cpp
    } else if (target) {
        const Value output{Operand::self(field.offset), field.type};
        if (const auto value = value_as(output, *target->type)) {
            store(*target, *value);
        }
    }
    release(mark);
}

} // namespace eposp::compiler::codegen
