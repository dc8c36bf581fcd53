#include "eposp/vm/verifier.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace eposp::vm {
namespace {

using Defect = std::optional<core::Error>;

Defect defect(std::string message) {
    return core::Error{std::move(message)};
}

bool fits(std::uint64_t offset, std::uint64_t size, std::uint64_t area) {
    return offset + size <= area;
}

std::string_view base_name(Base base) {
    switch (base) {
    case Base::Static:
        return "static";
    case Base::Frame:
        return "frame";
    case Base::Self:
        return "instance";
    case Base::Out:
        return "out";
    }
    return "?";
}

class CodeVerifier {
public:
    CodeVerifier(const Image& image, const Pou& pou) : image_(image), pou_(pou) {}

    Defect check_instruction(std::uint32_t index) {
        const auto& ins = image_.code[index];
        where_ = "POU " + pou_.name + ", instruction " + std::to_string(index);
        if (static_cast<std::uint16_t>(ins.opcode) >= kOpcodeCount) {
            return defect(where_ + ": unknown opcode " +
                          std::to_string(static_cast<std::uint16_t>(ins.opcode)));
        }
        const auto& info = opcode_info(ins.opcode);
        where_ += " (" + std::string(info.name) + ")";
        if ((info.aux == Aux::Array && ins.aux >= image_.arrays.size()) ||
            (info.aux == Aux::None && ins.aux != 0)) {
            return defect(where_ + ": invalid array descriptor " + std::to_string(ins.aux));
        }
        const FieldSpec specs[] = {info.a, info.b, info.c};
        const std::uint32_t values[] = {ins.a, ins.b, ins.c};
        for (int f = 0; f < 3; ++f) {
            if (auto d = check_field(ins, specs[f], values[f], "ABC"[f])) {
                return d;
            }
        }
        return {};
    }

private:
    Defect check_field(const Instruction& ins, FieldSpec spec, std::uint32_t value, char name) {
        const auto fail = [&](const std::string& why) {
            return defect(where_ + ", field " + name + ": " + why);
        };
        switch (spec.field) {
        case Field::None:
            return value == 0 ? Defect{} : fail("unused field is not 0");
        case Field::Imm:
        case Field::Size:
            return {};
        case Field::Read:
        case Field::Write:
            return check_operand(Operand{value}, spec.size, fail);
        case Field::ReadN:
        case Field::WriteN:
            return check_operand(Operand{value}, ins.c, fail);
        case Field::Target:
            return value >= pou_.code_begin && value < pou_.code_end
                       ? Defect{}
                       : fail("jump target " + std::to_string(value) + " outside the POU");
        case Field::Pou:
            return check_callee(ins.opcode, value, fail);
        case Field::Import:
            return value < image_.imports.size()
                       ? Defect{}
                       : fail("import " + std::to_string(value) + " does not exist");
        case Field::NativeArguments:
            // Field A (the import) is checked first.
            return check_operand(Operand{value},
                                 argument_block_size(image_.imports[ins.a].signature), fail);
        case Field::Instance:
            // Field B (the POU) is checked on its own; here only its instance size matters.
            return ins.b < image_.pous.size()
                       ? check_operand(Operand{value}, image_.pous[ins.b].instance_size, fail)
                       : fail("instance of a POU that does not exist");
        case Field::JumpTable: {
            if (value >= image_.jump_tables.size() || image_.jump_tables[value].targets.empty()) {
                return fail("jump table " + std::to_string(value) + " does not exist or is empty");
            }
            const auto& targets = image_.jump_tables[value].targets;
            const bool inside = std::all_of(targets.begin(), targets.end(), [&](std::uint32_t t) {
                return t >= pou_.code_begin && t < pou_.code_end;
            });
            return inside ? Defect{} : fail("a jump table target is outside the POU");
        }
        case Field::ArrayIndex:
            return check_operand(Operand{value}, image_.arrays[ins.aux].index_size, fail);
        case Field::ArrayRead:
        case Field::ArrayWrite: {
            const auto& array = image_.arrays[ins.aux];
            if (std::uint64_t{array.offset} + spec.size > array.element_size) {
                return fail("an access of " + std::to_string(spec.size) + " bytes at " +
                            std::to_string(array.offset) + " is past the element size " +
                            std::to_string(array.element_size));
            }
            return check_operand(Operand{value}, std::uint64_t{array.count} * array.element_size,
                                 fail);
        }
        }
        return fail("unknown field kind");
    }

    template <typename Fail>
    Defect check_operand(Operand op, std::uint64_t size, const Fail& fail) const {
        std::uint64_t area = 0;
        switch (op.base()) {
        case Base::Static:
            area = image_.static_size;
            break;
        case Base::Frame:
            area = pou_.frame_size;
            break;
        case Base::Self:
            area = pou_.kind == PouKind::Function ? 0 : pou_.instance_size;
            break;
        case Base::Out:
            area = pou_.out_size;
            break;
        }
        if (fits(op.offset(), size, area)) {
            return {};
        }
        return fail(std::string(base_name(op.base())) + " offset " + std::to_string(op.offset()) +
                    " + " + std::to_string(size) + " exceeds its area of " + std::to_string(area) +
                    " bytes");
    }

    template <typename Fail>
    Defect check_callee(Opcode op, std::uint32_t index, const Fail& fail) const {
        if (index >= image_.pous.size()) {
            return fail("POU " + std::to_string(index) + " does not exist");
        }
        const bool wants_function = op == Opcode::Call;
        const bool is_function = image_.pous[index].kind == PouKind::Function;
        if (wants_function != is_function) {
            return fail("calls " + image_.pous[index].name +
                        (wants_function ? ", which is not a function" : ", which has no instance"));
        }
        return {};
    }

    const Image& image_;
    const Pou& pou_;
    std::string where_;
};

bool ends_control_flow(Opcode op) {
    return op == Opcode::Ret || op == Opcode::Jmp;
}

// POU code ranges must be non-empty, inside the code and pairwise disjoint, so that each
// instruction is checked against the one POU it can run in.
Defect verify_code_ranges(const Image& image) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;
    for (const auto& pou : image.pous) {
        if (pou.code_begin >= pou.code_end || pou.code_end > image.code.size()) {
            return defect("POU " + pou.name + ": code range [" + std::to_string(pou.code_begin) +
                          ", " + std::to_string(pou.code_end) + ") is empty or outside the code");
        }
        ranges.emplace_back(pou.code_begin, pou.code_end);
    }
    std::sort(ranges.begin(), ranges.end());
    for (std::size_t i = 1; i < ranges.size(); ++i) {
        if (ranges[i].first < ranges[i - 1].second) {
            return defect("POU code ranges overlap at instruction " +
                          std::to_string(ranges[i].first));
        }
    }
    return {};
}

Defect verify_pous(const Image& image) {
    if (auto d = verify_code_ranges(image)) {
        return d;
    }
    for (const auto& pou : image.pous) {
        const auto where = "POU " + pou.name;
        if (std::uint64_t{pou.frame_size} + pou.out_size > kMaxAreaSize ||
            pou.instance_size > kMaxAreaSize) {
            return defect(where + ": frame or instance too large");
        }
        if (pou.kind == PouKind::Function && pou.instance_size != 0) {
            return defect(where + ": a function has no instance");
        }
        std::uint32_t last = pou.code_begin;
        for (const auto& entry : pou.lines) {
            if (entry.instruction < last || entry.instruction >= pou.code_end) {
                return defect(where + ": line table out of order or outside the POU");
            }
            last = entry.instruction;
        }
        last = pou.code_begin;
        for (const auto& call : pou.inlined) {
            if (call.begin < last || call.begin >= call.end || call.end > pou.code_end ||
                call.callee >= image.pous.size() ||
                call.end - call.begin >
                    image.pous[call.callee].code_end - image.pous[call.callee].code_begin) {
                return defect(where + ": inlined call out of order, outside the POU or longer "
                                      "than its callee");
            }
            last = call.end;
        }
        CodeVerifier verifier(image, pou);
        for (auto i = pou.code_begin; i < pou.code_end; ++i) {
            if (auto d = verifier.check_instruction(i)) {
                return d;
            }
        }
        if (!ends_control_flow(image.code[pou.code_end - 1].opcode)) {
            return defect(where + ": the last instruction must be Ret or Jmp");
        }
    }
    return {};
}

Defect verify_static(const Image& image) {
    if (image.static_size < kNullGuardSize || image.static_size > kMaxAreaSize) {
        return defect("static data size " + std::to_string(image.static_size) + " out of range");
    }
    if (image.static_init.size() != image.static_size) {
        return defect("static data initial values do not match its size");
    }
    for (const auto& array : image.arrays) {
        if (array.element_size == 0 ||
            std::uint64_t{array.count} * array.element_size > kMaxAreaSize) {
            return defect("array descriptor with an empty element or too large");
        }
        if (array.index_size != 2 && array.index_size != 4) {
            return defect("array descriptor with an index of " + std::to_string(array.index_size) +
                          " bytes");
        }
    }
    for (const auto& range : image.retain) {
        if (!fits(range.offset, range.size, image.static_size)) {
            return defect("retain range at " + std::to_string(range.offset) +
                          " outside static data");
        }
    }
    return {};
}

Defect verify_tasks(const Image& image) {
    std::uint64_t stacks = 0;
    for (const auto& task : image.tasks) {
        const auto where = "task " + task.name;
        if (task.kind == TaskKind::Cyclic && task.interval_ns == 0) {
            return defect(where + ": cyclic task without an interval");
        }
        if (task.kind == TaskKind::Cyclic && (task.event_offset || !task.event.empty())) {
            return defect(where + ": cyclic task with an event");
        }
        if (task.event_offset && !fits(*task.event_offset, 1, image.static_size)) {
            return defect(where + ": event variable outside static data");
        }
        stacks += task.stack_size;
        if (task.stack_size > kMaxAreaSize || stacks > kMaxAreaSize) {
            return defect(where + ": stack too large");
        }
        for (const auto& entry : task.entries) {
            if (entry.pou >= image.pous.size() || image.pous[entry.pou].kind != PouKind::Program) {
                return defect(where + ": entry " + std::to_string(entry.pou) + " is not a program");
            }
            const auto& pou = image.pous[entry.pou];
            if (!fits(entry.instance, pou.instance_size, image.static_size)) {
                return defect(where + ": instance of " + pou.name + " outside static data");
            }
            if (std::uint64_t{pou.frame_size} + pou.out_size > task.stack_size) {
                return defect(where + ": frame of " + pou.name + " exceeds the task stack of " +
                              std::to_string(task.stack_size) + " bytes");
            }
        }
    }
    return {};
}

Defect verify_types_and_symbols(const Image& image) {
    const auto& types = image.types;
    for (std::uint32_t i = 0; i < types.size(); ++i) {
        const auto& t = types[i];
        const auto where = "type " + t.name;
        switch (t.kind) {
        case TypeKind::Elementary:
            if (t.size != scalar_size(t.scalar)) {
                return defect(where + ": size does not match its scalar type");
            }
            if (t.subrange && (!is_integer(t.scalar) || t.lowest > t.highest)) {
                return defect(where + ": bad subrange");
            }
            if (!t.enumerators.empty() && !is_integer(t.scalar)) {
                return defect(where + ": enumerators on a type that is not an integer");
            }
            break;
        case TypeKind::String:
            if (t.size == 0) {
                return defect(where + ": empty string type");
            }
            break;
        case TypeKind::Array:
            if (t.element >= i || std::uint64_t{t.count} * types[t.element].size != t.size) {
                return defect(where + ": bad element type or size");
            }
            break;
        case TypeKind::Struct:
            for (const auto& field : t.fields) {
                if (field.type >= i || !fits(field.offset, types[field.type].size, t.size)) {
                    return defect(where + ": field " + field.name + " has a bad type or offset");
                }
            }
            break;
        }
    }
    for (const auto& symbol : image.symbols) {
        if (symbol.type >= types.size() ||
            !fits(symbol.offset, types[symbol.type].size, image.static_size)) {
            return defect("symbol " + symbol.path + ": bad type or outside static data");
        }
    }
    for (const auto& binding : image.bindings) {
        if (binding.bit > 7 || (binding.bit != 0 && binding.type != Scalar::Bool) ||
            !fits(binding.offset, scalar_size(binding.type), image.static_size)) {
            return defect("binding of address " + std::to_string(binding.byte_address) +
                          ": bad bit, type or offset");
        }
    }
    return {};
}

// Names reach terminals (dump, run summaries, watch): printable ASCII only, so that an image
// cannot carry escape sequences. The defect does not quote the name, for the same reason.
bool printable(const std::string& name) {
    return std::ranges::all_of(name, [](char c) { return c >= 0x20 && c <= 0x7E; });
}

Defect verify_names(const Image& image) {
    for (std::size_t i = 0; i < image.pous.size(); ++i) {
        if (!printable(image.pous[i].name)) {
            return defect("POU " + std::to_string(i) + ": name is not printable ASCII");
        }
    }
    for (std::size_t i = 0; i < image.tasks.size(); ++i) {
        if (!printable(image.tasks[i].name)) {
            return defect("task " + std::to_string(i) + ": name is not printable ASCII");
        }
    }
    for (std::size_t i = 0; i < image.types.size(); ++i) {
        const TypeDescriptor& type = image.types[i];
        const bool fields = std::ranges::all_of(
            type.fields, [](const TypeField& field) { return printable(field.name); });
        const bool enumerators = std::ranges::all_of(
            type.enumerators, [](const Enumerator& value) { return printable(value.name); });
        if (!printable(type.name) || !fields || !enumerators) {
            return defect("type " + std::to_string(i) +
                          ": a name (type, field or enumerator) is not printable ASCII");
        }
    }
    for (std::size_t i = 0; i < image.symbols.size(); ++i) {
        if (!printable(image.symbols[i].path)) {
            return defect("symbol " + std::to_string(i) + ": path is not printable ASCII");
        }
    }
    for (std::size_t i = 0; i < image.imports.size(); ++i) {
        if (!printable(image.imports[i].name)) {
            return defect("native import " + std::to_string(i) + ": name is not printable ASCII");
        }
    }
    return {};
}

} // namespace

std::optional<core::Error> verify(const Image& image) {
    for (auto* step :
         {verify_names, verify_static, verify_pous, verify_tasks, verify_types_and_symbols}) {
        if (auto d = step(image)) {
            return d;
        }
    }
    return {};
}

} // namespace eposp::vm
