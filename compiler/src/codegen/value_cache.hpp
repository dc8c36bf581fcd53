#pragma once

#include "eposp/vm/instruction.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace eposp::compiler::codegen {

/// Values a POU body has already computed into temporaries, reused while nothing they were
/// computed from changes: `items[i].pos := items[i].pos + 1` computes the address of
/// `items[i]` once; the swap of a bubble sort reuses the elements its comparison loaded. An
/// entry dies when an instruction writes memory it depends on, at every label (a join of
/// control flow), at every call and write through a pointer, and when its temporary is
/// released.
class ValueCache {
public:
    enum class Kind : std::uint8_t { Convert, AddImmediate, Address, Load };
    struct Key {
        Kind kind = Kind::Convert;
        std::uint32_t a = 0;
        std::uint32_t b = 0;
        std::uint32_t c = 0;
        bool operator==(const Key&) const = default;
    };
    /// Memory a value depends on.
    struct Range {
        vm::Operand start{};
        std::uint32_t size = 0;
    };

    std::optional<vm::Operand> find(const Key& key) const;
    /// `result` (`size` bytes) holds the value of `key`, computed from `sources`.
    void add(const Key& key, vm::Operand result, std::uint32_t size, std::vector<Range> sources);
    /// After emitting `op`: forgets every entry the instruction may have changed.
    /// `array_bytes` gives the size of the array an indexed store writes.
    void written(vm::Opcode op, vm::Operand a, vm::Operand b, vm::Operand c, std::uint16_t aux,
                 const std::function<std::uint32_t(std::uint16_t)>& array_bytes);
    /// Forgets the entries that use frame bytes at or above `mark` (released temporaries).
    void release(std::uint32_t mark);
    void clear() { entries_.clear(); }

private:
    struct Entry {
        Key key;
        vm::Operand result;
        std::vector<Range> depends; // the sources and the result itself
    };
    void forget(const Range& range);

    std::vector<Entry> entries_;
};

} // namespace eposp::compiler::codegen
