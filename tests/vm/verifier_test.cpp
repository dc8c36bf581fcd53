// The verifier refuses each kind of malformed image with its reason (one row per check), and
// whatever it accepts runs without touching memory outside the VM.

#include "eposp/vm/machine.hpp"
#include "eposp/vm/verifier.hpp"
#include "sample_image.hpp"

#include <gtest/gtest.h>
#include <random>

namespace eposp::vm::test {
namespace {

TEST(Verifier, AcceptsTheSampleImage) {
    const auto defect = verify(sample_image());
    EXPECT_FALSE(defect) << defect->message;
}

struct Malformation {
    const char* name;
    void (*break_image)(Image&);
    const char* reason; ///< a part of the message that says why
};

void PrintTo(const Malformation& m, std::ostream* os) {
    *os << m.name;
}

class VerifierRefuses : public ::testing::TestWithParam<Malformation> {};

TEST_P(VerifierRefuses, WithTheReason) {
    auto image = sample_image();
    GetParam().break_image(image);
    const auto defect = verify(image);
    ASSERT_TRUE(defect);
    EXPECT_NE(defect->message.find(GetParam().reason), std::string::npos) << defect->message;
}

// Sample image layout: Main is instructions 0..9, Twice 10..11; Main's instance is 32 bytes.
INSTANTIATE_TEST_SUITE_P(
    Code, VerifierRefuses,
    ::testing::Values(
        Malformation{"UnknownOpcode",
                     [](Image& i) { i.code[0].opcode = static_cast<Opcode>(kOpcodeCount); },
                     "unknown opcode"},
        Malformation{"StaticOperandPastStaticData",
                     [](Image& i) { i.code[1].b = Operand::global(i.static_size - 2).raw; },
                     "static offset"},
        Malformation{"InstanceOperandPastInstance",
                     [](Image& i) { i.code[0].a = Operand::self(30).raw; },
                     "instance offset 30 + 4 exceeds its area of 32 bytes"},
        Malformation{"FrameOperandPastFrame",
                     [](Image& i) { i.code[10].a = Operand::local(6).raw; },
                     "frame offset 6 + 4 exceeds its area of 8 bytes"},
        Malformation{"SelfOperandInAFunction",
                     [](Image& i) { i.code[10].b = Operand::self(0).raw; },
                     "instance offset 0 + 4 exceeds its area of 0 bytes"},
        Malformation{"OutOperandPastOutArea", [](Image& i) { i.code[1].a = Operand::out(14).raw; },
                     "out offset"},
        Malformation{"JumpOutOfThePou", [](Image& i) { i.code[7].c = 10; },
                     "jump target 10 outside the POU"},
        Malformation{"JumpTableMissing", [](Image& i) { i.code[8].b = 1; },
                     "jump table 1 does not exist or is empty"},
        Malformation{"JumpTableEmpty", [](Image& i) { i.jump_tables[0].targets.clear(); },
                     "jump table 0 does not exist or is empty"},
        Malformation{"JumpTableTargetOutsideThePou",
                     [](Image& i) { i.jump_tables[0].targets[1] = 10; },
                     "a jump table target is outside the POU"},
        Malformation{"JumpPastTheCode", [](Image& i) { i.code[7].c = 1000; },
                     "jump target 1000 outside the POU"},
        Malformation{"FallsOffTheEnd", [](Image& i) { i.code[9].opcode = Opcode::Nop; },
                     "the last instruction must be Ret or Jmp"},
        Malformation{"CallOfAMissingPou", [](Image& i) { i.code[2].a = 7; },
                     "POU 7 does not exist"},
        Malformation{"CallOfAProgramAsFunction", [](Image& i) { i.code[2].a = 0; },
                     "which is not a function"},
        Malformation{"FbCallOfAFunction",
                     [](Image& i) {
                         i.code[2] = Instruction{Opcode::CallFb, 0, Operand::self(0).raw, 1, 0};
                     },
                     "which has no instance"},
        Malformation{"MissingImport", [](Image& i) { i.code[5].a = 3; }, "import 3 does not exist"},
        Malformation{"ImportArgumentsPastOutArea",
                     [](Image& i) { i.imports[0].signature.parameters.push_back(Scalar::F64); },
                     "field B: out offset 0 + 24 exceeds its area"},
        Malformation{"MissingArrayDescriptor", [](Image& i) { i.code[3].aux = 5; },
                     "invalid array descriptor 5"},
        Malformation{"ArrayPastInstance", [](Image& i) { i.arrays[0].count = 8; },
                     "instance offset 4 + 32 exceeds"},
        Malformation{"ElementNarrowerThanAccess", [](Image& i) { i.arrays[0].element_size = 2; },
                     "an access of 4 bytes at 0 is past the element size 2"},
        Malformation{"FieldPastTheElement", [](Image& i) { i.arrays[0].offset = 2; },
                     "an access of 4 bytes at 2 is past the element size 4"},
        Malformation{"IndexNeitherIntNorDint", [](Image& i) { i.arrays[0].index_size = 3; },
                     "an index of 3 bytes"},
        Malformation{"GarbageInUnusedField", [](Image& i) { i.code[9].b = 1; },
                     "unused field is not 0"},
        Malformation{"AuxOnANonIndexedInstruction", [](Image& i) { i.code[0].aux = 1; },
                     "invalid array descriptor 1"}));

INSTANTIATE_TEST_SUITE_P(
    Tables, VerifierRefuses,
    ::testing::Values(
        Malformation{"OverlappingPous", [](Image& i) { i.pous[1].code_begin = 9; },
                     "code ranges overlap"},
        Malformation{"EmptyPou", [](Image& i) { i.pous[1].code_end = i.pous[1].code_begin; },
                     "is empty or outside the code"},
        Malformation{"PouPastTheCode", [](Image& i) { i.pous[1].code_end = 99; },
                     "is empty or outside the code"},
        Malformation{"InlinedCallPastThePou",
                     [](Image& i) {
                         i.pous[0].inlined.push_back({7, 10, 1});
                     },
                     "inlined call out of order, outside the POU"},
        Malformation{"InlinedCallLongerThanItsCallee",
                     [](Image& i) {
                         i.pous[0].inlined.push_back({2, 5, 1});
                     },
                     "longer than its callee"},
        Malformation{"LineTableOutsideThePou", [](Image& i) { i.pous[1].lines[0].instruction = 2; },
                     "line table"},
        Malformation{"FunctionWithAnInstance", [](Image& i) { i.pous[1].instance_size = 4; },
                     "a function has no instance"},
        Malformation{"StaticInitialValuesOfWrongSize", [](Image& i) { i.static_init.pop_back(); },
                     "initial values"},
        Malformation{"StaticSmallerThanNullGuard",
                     [](Image& i) {
                         i.static_size = 4;
                         i.static_init.resize(4);
                     },
                     "static data size 4 out of range"},
        Malformation{"RetainOutsideStaticData", [](Image& i) { i.retain[0].size = 1u << 20; },
                     "retain range"},
        Malformation{"TaskEntryNotAProgram", [](Image& i) { i.tasks[0].entries[0].pou = 1; },
                     "is not a program"},
        Malformation{"TaskInstanceOutsideStaticData",
                     [](Image& i) { i.tasks[0].entries[0].instance = i.static_size; },
                     "outside static data"},
        Malformation{"TaskStackSmallerThanFrame", [](Image& i) { i.tasks[0].stack_size = 8; },
                     "exceeds the task stack of 8 bytes"},
        Malformation{"CyclicTaskWithoutInterval", [](Image& i) { i.tasks[0].interval_ns = 0; },
                     "without an interval"},
        Malformation{"EventVariableOutsideStaticData",
                     [](Image& i) {
                         i.tasks[0].kind = TaskKind::Event;
                         i.tasks[0].event_offset = i.static_size;
                     },
                     "event variable outside static data"},
        Malformation{"CyclicTaskWithAnEvent", [](Image& i) { i.tasks[0].event = "sync"; },
                     "cyclic task with an event"},
        Malformation{"CyclicTaskWithASingleVariable", [](Image& i) { i.tasks[0].event_offset = 0; },
                     "cyclic task with an event"},
        Malformation{"TypeReferringForward", [](Image& i) { i.types[2].element = 3; },
                     "bad element type or size"},
        Malformation{"ArrayTypeOfWrongSize", [](Image& i) { i.types[2].size = 12; },
                     "bad element type or size"},
        Malformation{"EnumeratorsOnAReal",
                     [](Image& i) {
                         i.types[1].enumerators = {{"x", 0}};
                     },
                     "enumerators on a type that is not an integer"},
        Malformation{"StructFieldPastTheStruct", [](Image& i) { i.types[3].fields[2].offset = 28; },
                     "field r has a bad type or offset"},
        Malformation{"ElementaryTypeOfWrongSize", [](Image& i) { i.types[0].size = 2; },
                     "size does not match"},
        Malformation{"EmptySubrange",
                     [](Image& i) {
                         i.types[0].subrange = true;
                         i.types[0].lowest = 5;
                         i.types[0].highest = 4;
                     },
                     "bad subrange"},
        Malformation{"SymbolPastStaticData",
                     [](Image& i) { i.symbols[0].offset = i.static_size - 4; }, "symbol Inst0"},
        Malformation{"SymbolWithMissingType", [](Image& i) { i.symbols[1].type = 40; },
                     "symbol Inst0.counter"},
        Malformation{"BindingBitPastByte", [](Image& i) { i.bindings[0].bit = 8; },
                     "binding of address 4"},
        Malformation{"BindingPastStaticData",
                     [](Image& i) { i.bindings[0].offset = i.static_size; },
                     "binding of address 4"}));

// Whatever survives random damage to its code and the verifier runs to an end without
// touching memory outside the VM: the verifier's guarantees are what makes that safe.
TEST(Verifier, WhatItAcceptsRunsSafelyAfterRandomDamage) {
    NativeRegistry natives;
    natives.add("SQRT", NativeSignature{true, Scalar::F64, {Scalar::F64}},
                [](NativeArgs& args) { args.set_result(args.get<double>(0)); });
    std::mt19937 random(11);
    // A small offset in any base: often valid, often just past an area's end.
    const auto random_operand = [&] {
        return static_cast<std::uint32_t>(random() % 64 | (random() % 4) << kBaseShift);
    };
    int accepted = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        auto image = sample_image();
        auto& ins = image.code[random() % image.code.size()];
        switch (random() % 4) {
        case 0:
            ins.opcode = static_cast<Opcode>(random() % kOpcodeCount);
            break;
        case 1:
            ins.a = random_operand();
            break;
        case 2:
            ins.b = random_operand();
            break;
        default:
            ins.c = static_cast<std::uint32_t>(random() % 64);
            break;
        }
        auto program = link(std::move(image), natives);
        if (!program) {
            continue;
        }
        ++accepted;
        Machine machine(*program);
        machine.set_budget(0, 100'000);
        const auto state = machine.run_cycle(0);
        EXPECT_TRUE(state == RunState::Finished || state == RunState::Faulted);
    }
    EXPECT_GT(accepted, 100);
}

} // namespace
} // namespace eposp::vm::test
