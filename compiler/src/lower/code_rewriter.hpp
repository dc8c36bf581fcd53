#pragma once

#include "eposp/vm/image.hpp"
#include "eposp/vm/opcodes.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace eposp::compiler::lower {

/// Where the replacement of one instruction goes while a pass rebuilds the code.
class CodeSink {
public:
    /// The index the next instruction appended gets.
    std::uint32_t here() const { return static_cast<std::uint32_t>(code_.size()); }
    /// Appends an instruction whose jump targets are old indices of the same POU (mapped to
    /// wherever those instructions end up).
    void keep(const vm::Instruction& ins);
    /// Appends an instruction whose jump targets are already new indices.
    void place(const vm::Instruction& ins) { code_.push_back(ins); }

private:
    friend class CodeRewrite;
    std::vector<vm::Instruction> code_;
    std::vector<std::size_t> old_targets_; // instructions whose targets are still old indices
};

/// The code and the POUs as they were before a pass (only these change while it rebuilds).
struct CodeBefore {
    std::vector<vm::Instruction> code;
    std::vector<vm::Pou> pous;
};

/// What replaces instruction `instruction` (an index into `before.code`) of `pou`.
using Expand = std::function<void(const CodeBefore& before, vm::Pou& pou, std::uint32_t instruction,
                                  CodeSink& sink)>;

/// Rebuilds the code: calls `expand` for every instruction of every POU, in code order, with the
/// code as it was before the pass; expand appends what replaces the instruction (itself,
/// nothing or several). Jump targets, line tables and code ranges follow. Leaves the image as
/// it is if its POU bodies do not tile the code.
void rewrite_code(vm::Image& image, const Expand& expand);

/// Applies `to` to every jump target field of `ins`. A template, not a std::function: every
/// pass runs it on every instruction.
template <typename To>
void retarget(vm::Instruction& ins, const To& to) {
    const vm::OpcodeInfo& info = vm::opcode_info(ins.opcode);
    if (info.a.field == vm::Field::Target) {
        ins.a = to(ins.a);
    }
    if (info.b.field == vm::Field::Target) {
        ins.b = to(ins.b);
    }
    if (info.c.field == vm::Field::Target) {
        ins.c = to(ins.c);
    }
}

/// Whether `opcode` is a JTab, whose jump table (field B) holds targets too.
inline bool jumps_through_table(vm::Opcode opcode) {
    return vm::opcode_info(opcode).b.field == vm::Field::JumpTable;
}

/// The same, and to every target of the jump table of a JTab (`tables`: the image's).
template <typename To>
void retarget(vm::Instruction& ins, std::vector<vm::JumpTable>& tables, const To& to) {
    retarget(ins, to);
    // Each table belongs to one JTab: it moves with its instruction.
    if (jumps_through_table(ins.opcode)) {
        for (std::uint32_t& target : tables[ins.b].targets) {
            target = to(target);
        }
    }
}

} // namespace eposp::compiler::lower
