#include "eposp/vm/disassembler.hpp"

#include <fmt/format.h>

namespace eposp::vm {
namespace {

std::string operand(Operand op) {
    static constexpr const char* kBase[] = {"s", "f", "i", "o"};
    return fmt::format("{}+{}", kBase[static_cast<int>(op.base())], op.offset());
}

template <typename Table>
std::string name_or_index(const Table& table, std::uint32_t index) {
    return index < table.size() ? table[index].name : fmt::format("<bad {}>", index);
}

std::string field(const Image& image, FieldSpec spec, std::uint32_t value) {
    switch (spec.field) {
    case Field::None:
        return {};
    case Field::Imm:
        return fmt::format("#{}", static_cast<std::int32_t>(value));
    case Field::Size:
        return fmt::format("#{}", value);
    case Field::Target:
        return fmt::format("->{}", value);
    case Field::Pou:
        return name_or_index(image.pous, value);
    case Field::Import:
        return name_or_index(image.imports, value);
    case Field::JumpTable: {
        if (value >= image.jump_tables.size()) {
            return fmt::format("<bad table {}>", value);
        }
        const JumpTable& table = image.jump_tables[value];
        std::string text = fmt::format("{{from {}:", table.low);
        for (const std::uint32_t target : table.targets) {
            text += fmt::format(" ->{}", target);
        }
        return text + "}";
    }
    default:
        return operand(Operand{value});
    }
}

std::string signature(const NativeSignature& signature) {
    std::string text = "(";
    for (std::size_t i = 0; i < signature.parameters.size(); ++i) {
        text += fmt::format("{}{}", i == 0 ? "" : ", ", scalar_name(signature.parameters[i]));
    }
    text += ")";
    if (signature.has_result) {
        text += fmt::format(" : {}", scalar_name(signature.result));
    }
    if (!signature.instance.empty()) {
        text += " instance {";
        for (std::size_t i = 0; i < signature.instance.size(); ++i) {
            text += fmt::format("{}{}", i == 0 ? "" : ", ", scalar_name(signature.instance[i]));
        }
        text += "}";
    }
    return text;
}

constexpr const char* kPouKind[] = {"FUNCTION", "FUNCTION_BLOCK", "PROGRAM"};
constexpr const char* kIoArea[] = {"I", "Q", "M"};

void tables(const Image& image, std::string& out) {
    out += fmt::format("image v{}: {} instructions, {} bytes of static data\n", kImageVersion,
                       image.code.size(), image.static_size);
    out += "tasks:\n";
    for (const auto& task : image.tasks) {
        out += fmt::format("  {}", task.name);
        if (task.kind == TaskKind::Cyclic) {
            out += fmt::format(" INTERVAL {} ns", task.interval_ns);
        }
        if (task.event_offset) {
            out += fmt::format(" SINGLE s+{}", *task.event_offset);
        }
        if (!task.event.empty()) {
            out += fmt::format(" EVENT '{}'", task.event);
        }
        out += fmt::format(" PRIORITY {} stack {}:", task.priority, task.stack_size);
        for (const auto& entry : task.entries) {
            out += fmt::format(" {}@s+{}", name_or_index(image.pous, entry.pou), entry.instance);
        }
        out += "\n";
    }
    out += "POUs:\n";
    for (const auto& pou : image.pous) {
        out += fmt::format("  {} {} code [{}, {}) frame {} out {} instance {}\n",
                           kPouKind[static_cast<int>(pou.kind) % 3], pou.name, pou.code_begin,
                           pou.code_end, pou.frame_size, pou.out_size, pou.instance_size);
    }
    out += "symbols:\n";
    for (const auto& symbol : image.symbols) {
        out += fmt::format("  {} : {} @ s+{}{}\n", symbol.path,
                           name_or_index(image.types, symbol.type), symbol.offset,
                           symbol.read_only ? " READ_ONLY" : "");
    }
    out += "bindings:\n";
    for (const auto& b : image.bindings) {
        out += fmt::format("  %{}{}.{} : {} @ s+{}\n", kIoArea[static_cast<int>(b.area) % 3],
                           b.byte_address, b.bit, scalar_name(b.type), b.offset);
    }
    out += "retain:\n";
    for (const auto& range : image.retain) {
        out += fmt::format("  s+{} .. {} bytes\n", range.offset, range.size);
    }
    out += "imports:\n";
    for (const auto& import : image.imports) {
        out += fmt::format("  {}{}\n", import.name, signature(import.signature));
    }
}

} // namespace

std::string disassemble(const Image& image, const Instruction& ins) {
    if (static_cast<std::uint16_t>(ins.opcode) >= kOpcodeCount) {
        return fmt::format("<unknown opcode {}>", static_cast<std::uint16_t>(ins.opcode));
    }
    const auto& info = opcode_info(ins.opcode);
    std::string text(info.name);
    const char* separator = " ";
    for (const auto& [spec, value] : {std::pair{info.a, ins.a}, {info.b, ins.b}, {info.c, ins.c}}) {
        if (spec.field != Field::None) {
            text += separator + field(image, spec, value);
            separator = ", ";
        }
    }
    if (info.aux == Aux::Step) {
        text += fmt::format(" step {}", static_cast<std::int16_t>(ins.aux));
    } else if (info.aux == Aux::Array) {
        if (ins.aux < image.arrays.size()) {
            const auto& array = image.arrays[ins.aux];
            text += fmt::format(" [{} +{} x{}{}{}]", array.lower, array.count, array.element_size,
                                array.offset != 0 ? fmt::format(" .{}", array.offset) : "",
                                array.index_size == 2 ? " INT" : "");
        } else {
            text += fmt::format(" [<bad {}>]", ins.aux);
        }
    }
    return text;
}

std::string disassemble(const Image& image) {
    std::string out;
    tables(image, out);
    for (const auto& pou : image.pous) {
        out += fmt::format("\n{} {}:\n", kPouKind[static_cast<int>(pou.kind) % 3], pou.name);
        auto line = pou.lines.begin();
        auto inlined = pou.inlined.begin();
        for (auto i = pou.code_begin; i < pou.code_end && i < image.code.size(); ++i) {
            if (inlined != pou.inlined.end() && inlined->begin == i) {
                out += fmt::format("         ({} inlined up to {})\n",
                                   name_or_index(image.pous, inlined->callee), inlined->end);
                ++inlined;
            }
            std::string where = "     ";
            if (line != pou.lines.end() && line->instruction == i) {
                where = fmt::format("L{:<4}", line->line);
                ++line;
            }
            out += fmt::format("  {} {:5}  {}\n", where, i, disassemble(image, image.code[i]));
        }
    }
    return out;
}

} // namespace eposp::vm
