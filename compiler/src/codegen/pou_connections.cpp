// Program connections (IEC 61131-3 ed. 3, 6.8.2): `PROGRAM inst WITH t : P (in := source,
// out => sink)`. A small body around the program's own copies every source into its input
// before each run and every output into its sink after it. Sources and sinks are expressions of
// the configuration (globals and their parts, constants, direct addresses, other programs'
// outputs), so they are typed and generated like any other expression.

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
        if (field == nullptr || !is_connectable(*argument.value, output)) {
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
        error(DiagnosticCode::E0210, argument.range,
              fmt::format("'{}' has no {} of that name", type.name, output ? "output" : "input"));
        return nullptr;
    }
    return field;
}

bool PouGenerator::is_connectable(const ast::Expression& expression, bool output) {
    const auto refuse = [&](const SourceRange& range) {
        error(DiagnosticCode::E0423, range,
              output ? "an output connects to a global variable (or a part of one) or a "
                       "direct output or memory address"
                     : "an input connects to a global variable (or a part of one), a "
                       "constant, a direct address or an output of another program");
        return false;
    };
    const ast::Expression* path = &expression;
    if (const auto* negated = std::get_if<ast::UnaryExpression>(&path->node)) {
        path = negated->operand.get(); // `-5`
        if (!std::holds_alternative<ast::LiteralExpression>(path->node)) {
            return refuse(expression.range);
        }
    }
    if (std::holds_alternative<ast::LiteralExpression>(path->node)) {
        return output ? refuse(expression.range) : true;
    }
    // Down a variable path to its root: `g`, `g.x`, `arr[2]`, `Inst1.out`, `%QX0.0`.
    for (;;) {
        if (const auto* member = std::get_if<ast::MemberExpression>(&path->node)) {
            const auto* object = std::get_if<ast::NameExpression>(&member->object->node);
            const sema::Symbol* symbol = object ? model_.resolved(object->name) : nullptr;
            if (symbol != nullptr && symbol->kind == sema::SymbolKind::ProgramInstance) {
                const auto instance = program_.program_instance_variable(symbol->name);
                const sema::Field* field =
                    instance ? instance->type->field(member->member.name) : nullptr;
                if (output || field == nullptr || field->section != ast::VarSectionKind::Output) {
                    return refuse(expression.range); // only read, and only its outputs
                }
            }
            path = member->object.get();
        } else if (const auto* element = std::get_if<ast::IndexExpression>(&path->node)) {
            path = element->array.get();
        } else {
            break;
        }
    }
    if (const auto* direct = std::get_if<ast::DirectAddressExpression>(&path->node)) {
        const bool input_area = direct->address.area == ast::DirectAddress::Area::Input;
        return output && input_area ? refuse(expression.range) : true;
    }
    return std::holds_alternative<ast::NameExpression>(path->node) ? true
                                                                   : refuse(expression.range);
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
        error(DiagnosticCode::E0401, sink.range,
              fmt::format("'{}' cannot be connected to a constant", field.name));
    } else if (target) {
        const Value output{Operand::self(field.offset), field.type};
        if (const auto value = value_as(output, sink.range, *target->type)) {
            store(*target, *value);
        }
    }
    release(mark);
}

} // namespace eposp::compiler::codegen
