#pragma once

// A map from AST nodes to what a stage found for them (the symbol an identifier names, the type
// of an expression): one entry per node of a whole program, so it is one array probed in place
// (open addressing) instead of a hash node allocated per entry.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace eposp::compiler::sema {

/// Maps `const Node*` to `const Value*`; a node is set once or set again, never erased.
template <typename Node, typename Value>
class NodeMap {
public:
    /// What `node` was set to; null when it never was.
    const Value* find(const Node* node) const {
        if (slots_.empty()) {
            return nullptr;
        }
        for (std::size_t i = slot_of(node);; i = (i + 1) & mask()) {
            if (slots_[i].node == node) {
                return slots_[i].value;
            }
            if (slots_[i].node == nullptr) {
                return nullptr;
            }
        }
    }

    void set(const Node* node, const Value* value) {
        if ((size_ + 1) * 4 > slots_.size() * 3) { // at most 3/4 full
            grow();
        }
        std::size_t i = slot_of(node);
        while (slots_[i].node != nullptr && slots_[i].node != node) {
            i = (i + 1) & mask();
        }
        if (slots_[i].node == nullptr) {
            ++size_;
        }
        slots_[i] = {node, value};
    }

private:
    struct Slot {
        const Node* node = nullptr;
        const Value* value = nullptr;
    };

    std::size_t mask() const { return slots_.size() - 1; }

    // Fibonacci hashing: the product's high bits mix all bits of the address.
    std::size_t slot_of(const Node* node) const {
        const auto bits = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(node));
        return static_cast<std::size_t>((bits * 0x9E3779B97F4A7C15ULL) >> shift_);
    }

    void grow() {
        std::vector<Slot> old = std::move(slots_);
        const std::size_t capacity = old.empty() ? 64 : old.size() * 2;
        slots_.assign(capacity, Slot{});
        shift_ = 64 - std::countr_zero(capacity);
        size_ = 0;
        for (const Slot& slot : old) {
            if (slot.node != nullptr) {
                set(slot.node, slot.value);
            }
        }
    }

    std::vector<Slot> slots_;
    std::size_t size_ = 0;
    int shift_ = 64;
};

} // namespace eposp::compiler::sema
