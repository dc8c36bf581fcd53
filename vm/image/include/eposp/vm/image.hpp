#pragma once

#include "eposp/vm/instruction.hpp"
#include "eposp/vm/scalar.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace eposp::vm {

/// Bumped whenever the binary layout or the meaning of an opcode changes; the loader refuses
/// other versions.
inline constexpr std::uint16_t kImageVersion = 5;

/// Memory addresses (pointer values, static offsets) below this are never valid data: a
/// pointer of 0 is NULL and dereferencing anything in the guard traps.
inline constexpr std::uint32_t kNullGuardSize = 8;

/// How an indexed instruction turns its index operand into an element: index - lower, taken
/// modulo 2^32, must be below count. The modular difference is what lets the compiler fold a
/// constant into the descriptor (`a[j + 1]` indexes with j against lower - 1) and still check
/// exactly what `a[j + 1]` with a wrapping DINT addition would.
struct ArrayDescriptor {
    std::int32_t lower = 0;
    std::uint32_t count = 0;
    std::uint32_t element_size = 0;
    std::uint8_t index_size = 4; ///< the signed index operand: 2 (INT) or 4 (DINT) bytes
    std::uint32_t offset = 0;    ///< bytes into the element: `items[i].pos` in one access
    bool operator==(const ArrayDescriptor&) const = default;
};

enum class PouKind : std::uint8_t { Function, FunctionBlock, Program };

/// A source line starting at an instruction; entries sorted by instruction.
struct LineEntry {
    std::uint32_t instruction = 0;
    std::uint32_t line = 0;
    bool operator==(const LineEntry&) const = default;
};

/// Where a JTab instruction goes for each selector value from `low` on (a dense CASE).
struct JumpTable {
    std::int32_t low = 0;
    std::vector<std::uint32_t> targets;
    bool operator==(const JumpTable&) const = default;
};

/// Instructions [begin, end) of a POU are a copy of the body of `callee` put in place of a call
/// (the last Ret dropped): run-time errors there name the callee and its line.
struct InlinedCall {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    std::uint32_t callee = 0;
    bool operator==(const InlinedCall&) const = default;
};

/// A program organisation unit: a range of code and the memory its activations need.
struct Pou {
    std::string name;
    PouKind kind = PouKind::Function;
    std::uint32_t code_begin = 0;    ///< first instruction
    std::uint32_t code_end = 0;      ///< one past the last
    std::uint32_t frame_size = 0;    ///< parameters, locals and temporaries on the task stack
    std::uint32_t out_size = 0;      ///< argument area for the calls this POU makes
    std::uint32_t instance_size = 0; ///< for FBs and programs: the instance `self` points to
    std::vector<LineEntry> lines;
    std::vector<InlinedCall> inlined; ///< sorted by begin, not overlapping
    bool operator==(const Pou&) const = default;
};

/// A byte range of static data that survives a warm start.
struct RetainRange {
    std::uint32_t offset = 0;
    std::uint32_t size = 0;
    bool operator==(const RetainRange&) const = default;
};

enum class TaskKind : std::uint8_t { Cyclic, Event };

/// A program instance run by a task: the body of `pou` with `self` at `instance`.
struct TaskEntry {
    std::uint32_t pou = 0;
    std::uint32_t instance = 0;
    bool operator==(const TaskEntry&) const = default;
};

/// IEC 61131-3 TASK: cyclic (INTERVAL), or an event task released on the rising edge of a BOOL
/// (SINGLE), by an event of the host, or both.
struct Task {
    std::string name;
    TaskKind kind = TaskKind::Cyclic;
    std::uint64_t interval_ns = 0; ///< cyclic tasks
    /// Event tasks: the static BOOL whose rising edge releases it (SINGLE); none without SINGLE.
    std::optional<std::uint32_t> event_offset{};
    /// Event tasks: the host's event that releases it, as the program names it (`{attribute
    /// 'event' := 'sync'}` on the TASK); the host judges the text. Empty: none.
    std::string event{};
    std::uint32_t priority = 0;   ///< 0 is the highest
    std::uint32_t stack_size = 0; ///< bytes of function frames
    std::vector<TaskEntry> entries;
    bool operator==(const Task&) const = default;
};

enum class TypeKind : std::uint8_t { Elementary, String, Array, Struct };

/// A named value of an enumeration: what a debugger shows instead of the number.
struct Enumerator {
    std::string name;
    std::int64_t value = 0;
    bool operator==(const Enumerator&) const = default;
};

struct TypeField {
    std::string name;
    std::uint32_t type = 0;
    std::uint32_t offset = 0;
    bool read_only = false; ///< a VAR CONSTANT of an FB or program: online writes are refused
    bool operator==(const TypeField&) const = default;
};

/// A type as the debugger sees it. A type only refers to types with smaller indices, so the
/// graph is acyclic by construction (the verifier checks it).
struct TypeDescriptor {
    std::string name; ///< e.g. DINT, STRING[80], Axis
    TypeKind kind = TypeKind::Elementary;
    Scalar scalar = Scalar::Bool; ///< Elementary
    std::uint32_t size = 0;
    std::uint32_t element = 0;     ///< Array: element type
    std::int32_t lower = 0;        ///< Array: first index
    std::uint32_t count = 0;       ///< Array: element count
    std::vector<TypeField> fields; ///< Struct (also FB instances)
    /// Elementary integer subrange (`INT(0..100)`): online writes outside lowest..highest are
    /// refused, as the program's own stores are.
    bool subrange = false;
    std::int64_t lowest = 0;
    std::int64_t highest = 0;
    std::vector<Enumerator> enumerators{}; ///< Elementary integer: an enumeration's values
    bool operator==(const TypeDescriptor&) const = default;
};

/// A variable in static data by its full path (`Main.counter`, `Config0.result`).
struct Symbol {
    std::string path;
    std::uint32_t type = 0;
    std::uint32_t offset = 0;
    /// A READ_ONLY access path (VAR_ACCESS) or a constant: online writes and forces are refused.
    bool read_only = false;
    bool operator==(const Symbol&) const = default;
};

enum class IoArea : std::uint8_t { Input, Output, Memory };

/// A located variable (`AT %IW4`): its IEC address and the static data it lives in.
struct IoBinding {
    IoArea area = IoArea::Input;
    Scalar type = Scalar::Bool; ///< Bool for %X bit access
    std::uint32_t byte_address = 0;
    std::uint8_t bit = 0; ///< %X only
    std::uint32_t offset = 0;
    bool operator==(const IoBinding&) const = default;
};

/// A host function the program calls. Its arguments live in the caller's out area: the result
/// (if any) at offset 0, then each parameter at the next offset aligned to its size.
struct NativeSignature {
    bool has_result = false;
    Scalar result = Scalar::Bool;
    std::vector<Scalar> parameters;
    /// A native function block's instance (its one parameter is the instance's address): the
    /// scalar of each field in declaration order, VAR_IN_OUT as Ptr, each field aligned to its
    /// size (vm::NativeBlock). Empty for a native function.
    std::vector<Scalar> instance{};

    bool operator==(const NativeSignature&) const = default;
};

struct NativeImport {
    std::string name;
    NativeSignature signature;
    bool operator==(const NativeImport&) const = default;
};

/// A program image: everything the VM needs to run a compiled application, and everything a
/// debugger needs to show it by name. Built with Builder, stored with write_image, loaded with
/// read_image and checked with verify before anything runs.
struct Image {
    std::vector<Instruction> code;
    std::vector<ArrayDescriptor> arrays;
    std::vector<JumpTable> jump_tables; ///< each used by one JTab instruction
    std::uint32_t static_size = kNullGuardSize;
    std::vector<std::uint8_t> static_init; ///< initial values of static data, static_size bytes
    std::vector<RetainRange> retain;
    std::vector<Task> tasks;
    std::vector<Pou> pous;
    std::vector<TypeDescriptor> types;
    std::vector<Symbol> symbols;
    std::vector<IoBinding> bindings;
    std::vector<NativeImport> imports;

    bool operator==(const Image&) const = default;
};

/// Bytes of the argument block of a native call with this signature.
std::uint32_t argument_block_size(const NativeSignature& signature);
/// Offset of parameter `index` in that block.
std::uint32_t parameter_offset(const NativeSignature& signature, std::size_t index);

} // namespace eposp::vm
