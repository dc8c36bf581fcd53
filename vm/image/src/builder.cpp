#include "eposp/vm/builder.hpp"

#include <stdexcept>

namespace eposp::vm {
namespace {

std::uint32_t align_up(std::uint32_t value, std::uint32_t align) {
    return align <= 1 ? value : (value + align - 1) / align * align;
}

std::uint32_t& field_of(Instruction& ins, int field) {
    return field == 0 ? ins.a : field == 1 ? ins.b : ins.c;
}

} // namespace

std::uint32_t Builder::allocate(std::uint32_t size, std::uint32_t align) {
    const auto offset = align_up(image_.static_size, align);
    image_.static_size = offset + size;
    image_.static_init.resize(image_.static_size, 0);
    return offset;
}

void Builder::initialise(std::uint32_t offset, std::span<const std::uint8_t> bytes) {
    if (offset + bytes.size() > image_.static_init.size()) {
        throw std::logic_error("Builder::initialise outside allocated data");
    }
    std::copy(bytes.begin(), bytes.end(), image_.static_init.begin() + offset);
}

std::uint32_t Builder::constant(std::span<const std::uint8_t> bytes, std::uint32_t align) {
    const auto offset = allocate(static_cast<std::uint32_t>(bytes.size()), align);
    initialise(offset, bytes);
    return offset;
}

std::uint16_t Builder::array(const ArrayDescriptor& descriptor) {
    for (std::size_t i = 0; i < image_.arrays.size(); ++i) {
        if (image_.arrays[i] == descriptor) {
            return static_cast<std::uint16_t>(i);
        }
    }
    image_.arrays.push_back(descriptor);
    return static_cast<std::uint16_t>(image_.arrays.size() - 1);
}

std::uint32_t Builder::declare_pou(std::string name, PouKind kind, std::uint32_t instance_size) {
    Pou pou;
    pou.name = std::move(name);
    pou.kind = kind;
    pou.instance_size = instance_size;
    image_.pous.push_back(std::move(pou));
    has_body_.push_back(false);
    return static_cast<std::uint32_t>(image_.pous.size() - 1);
}

void Builder::begin_body(std::uint32_t pou) {
    if (current_pou_ || pou >= image_.pous.size() || has_body_[pou]) {
        throw std::logic_error("Builder::begin_body: another body is open or already emitted");
    }
    current_pou_ = pou;
    has_body_[pou] = true;
    image_.pous[pou].code_begin = static_cast<std::uint32_t>(image_.code.size());
}

void Builder::end_body(std::uint32_t frame_size, std::uint32_t out_size) {
    if (!current_pou_) {
        throw std::logic_error("Builder::end_body without begin_body");
    }
    auto& pou = image_.pous[*current_pou_];
    pou.code_end = static_cast<std::uint32_t>(image_.code.size());
    pou.frame_size = frame_size;
    pou.out_size = out_size;
    current_pou_.reset();
}

void Builder::line(std::uint32_t line) {
    if (!current_pou_) {
        throw std::logic_error("Builder::line outside a body");
    }
    auto& lines = image_.pous[*current_pou_].lines;
    const auto here = static_cast<std::uint32_t>(image_.code.size());
    if (!lines.empty() && lines.back().instruction == here) {
        lines.back().line = line;
    } else if (lines.empty() || lines.back().line != line) {
        lines.push_back({here, line});
    }
}

Label Builder::label() {
    labels_.emplace_back();
    return Label{static_cast<std::uint32_t>(labels_.size() - 1)};
}

void Builder::bind(Label label) {
    labels_.at(label.id) = static_cast<std::uint32_t>(image_.code.size());
}

void Builder::emit(Opcode op, Operand a, Operand b, Operand c, std::uint16_t aux) {
    if (!current_pou_) {
        throw std::logic_error("Builder::emit outside a body");
    }
    image_.code.push_back(Instruction{op, aux, a.raw, b.raw, c.raw});
}

void Builder::jump(Opcode op, Label target, Operand a, Operand b, std::uint16_t aux) {
    const auto& info = opcode_info(op);
    const FieldSpec specs[] = {info.a, info.b, info.c};
    const Operand given[] = {a, b};
    Instruction ins{op, 0, 0, 0, 0};
    int next_given = 0;
    int target_field = -1;
    for (int field = 0; field < 3; ++field) {
        if (specs[field].field == Field::Target) {
            target_field = field;
        } else if (next_given < 2) {
            field_of(ins, field) = given[next_given++].raw;
        }
    }
    if (target_field < 0) {
        throw std::logic_error("Builder::jump with an opcode that has no target");
    }
    emit(op, Operand{ins.a}, Operand{ins.b}, Operand{ins.c}, aux);
    fixups_.push_back(
        {static_cast<std::uint32_t>(image_.code.size() - 1), target_field, target.id});
}

void Builder::for_loop(Opcode op, Label body, Operand variable, Operand limit, std::int16_t step) {
    jump(op, body, variable, limit, static_cast<std::uint16_t>(step));
}

std::uint32_t Builder::jump_table(std::int32_t low, const std::vector<Label>& targets) {
    image_.jump_tables.push_back({low, {}});
    const auto table = static_cast<std::uint32_t>(image_.jump_tables.size() - 1);
    table_fixups_.push_back({table, targets});
    return table;
}

std::uint32_t Builder::import(std::string name, NativeSignature signature) {
    image_.imports.push_back({std::move(name), std::move(signature)});
    return static_cast<std::uint32_t>(image_.imports.size() - 1);
}

std::uint32_t Builder::type(TypeDescriptor type) {
    image_.types.push_back(std::move(type));
    return static_cast<std::uint32_t>(image_.types.size() - 1);
}

void Builder::symbol(std::string path, std::uint32_t type, std::uint32_t offset, bool read_only) {
    image_.symbols.push_back({std::move(path), type, offset, read_only});
}

void Builder::binding(const IoBinding& binding) {
    image_.bindings.push_back(binding);
}

void Builder::retain(std::uint32_t offset, std::uint32_t size) {
    image_.retain.push_back({offset, size});
}

void Builder::task(Task task) {
    image_.tasks.push_back(std::move(task));
}

core::Result<Image> Builder::finish() {
    if (current_pou_) {
        return core::Error{"POU " + image_.pous[*current_pou_].name + " has no end_body"};
    }
    for (std::size_t i = 0; i < image_.pous.size(); ++i) {
        if (!has_body_[i]) {
            return core::Error{"POU " + image_.pous[i].name + " declared but has no body"};
        }
    }
    for (const auto& fixup : fixups_) {
        const auto& bound = labels_.at(fixup.label);
        if (!bound) {
            return core::Error{"label " + std::to_string(fixup.label) + " used but never bound"};
        }
        field_of(image_.code[fixup.instruction], fixup.field) = *bound;
    }
    for (const auto& fixup : table_fixups_) {
        auto& targets = image_.jump_tables[fixup.table].targets;
        for (const Label target : fixup.targets) {
            const auto& bound = labels_.at(target.id);
            if (!bound) {
                return core::Error{"label " + std::to_string(target.id) + " used but never bound"};
            }
            targets.push_back(*bound);
        }
    }
    return image_;
}

} // namespace eposp::vm
