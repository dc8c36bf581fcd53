#pragma once

#include "eposp/core/result.hpp"
#include "eposp/vm/image.hpp"

#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace eposp::vm {

/// A jump target not necessarily emitted yet.
struct Label {
    std::uint32_t id = 0;
};

/// Assembles an Image: static data allocation, POUs with labels and forward jumps, line
/// tables, and the descriptive tables. Code generation and the tests produce images only
/// through this; what it produces still goes through verify like any other image.
class Builder {
public:
    // --- static data -------------------------------------------------------------------------
    /// Reserves `size` zero-initialised bytes aligned to `align`; returns their offset.
    std::uint32_t allocate(std::uint32_t size, std::uint32_t align);
    std::uint32_t static_size() const { return image_.static_size; }
    /// Sets the initial value of bytes already allocated.
    void initialise(std::uint32_t offset, std::span<const std::uint8_t> bytes);
    /// Allocates and initialises a constant: a value, a string, a template for a frame.
    std::uint32_t constant(std::span<const std::uint8_t> bytes, std::uint32_t align);
    template <typename T>
    std::uint32_t constant(T value) {
        std::uint8_t bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        return constant(bytes, sizeof(T));
    }
    /// An array descriptor for the indexed instructions' aux field.
    std::uint16_t array(const ArrayDescriptor& descriptor);
    const ArrayDescriptor& array_at(std::uint16_t index) const { return image_.arrays.at(index); }

    // --- code --------------------------------------------------------------------------------
    /// A POU whose body comes later (so calls can precede it); returns its index.
    std::uint32_t declare_pou(std::string name, PouKind kind, std::uint32_t instance_size = 0);
    /// Starts emitting the body of a declared POU.
    void begin_body(std::uint32_t pou);
    /// Ends the body, with the sizes of its frame and of its argument area for calls.
    void end_body(std::uint32_t frame_size, std::uint32_t out_size = 0);
    /// Source line of the instructions emitted from now on.
    void line(std::uint32_t line);

    Label label();
    void bind(Label label);

    void emit(Opcode op, Operand a = {}, Operand b = {}, Operand c = {}, std::uint16_t aux = 0);
    /// Emits a jump or compare-and-branch: `target` goes into the opcode's target field, `a`
    /// and `b` into its other fields in order.
    void jump(Opcode op, Label target, Operand a = {}, Operand b = {}, std::uint16_t aux = 0);
    /// The back-edge of a FOR loop: `variable` += `step`, then on to `body` while it has not
    /// passed `limit`.
    void for_loop(Opcode op, Label body, Operand variable, Operand limit, std::int16_t step);
    /// A jump table for a JTab instruction: `targets[v - low]` for selector value v.
    std::uint32_t jump_table(std::int32_t low, const std::vector<Label>& targets);

    // --- tables ------------------------------------------------------------------------------
    std::uint32_t import(std::string name, NativeSignature signature);
    std::uint32_t type(TypeDescriptor type);
    void symbol(std::string path, std::uint32_t type, std::uint32_t offset, bool read_only = false);
    void binding(const IoBinding& binding);
    void retain(std::uint32_t offset, std::uint32_t size);
    void task(Task task);

    /// The image; fails if a label is unbound or a declared POU has no body. Not verified.
    core::Result<Image> finish();

private:
    struct Fixup {
        std::uint32_t instruction;
        int field;
        std::uint32_t label;
    };
    struct TableFixup {
        std::uint32_t table;
        std::vector<Label> targets;
    };

    Image image_;
    std::vector<std::optional<std::uint32_t>> labels_;
    std::vector<Fixup> fixups_;
    std::vector<TableFixup> table_fixups_;
    std::optional<std::uint32_t> current_pou_;
    std::vector<bool> has_body_;
};

} // namespace eposp::vm
