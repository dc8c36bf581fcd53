#pragma once

#include <cstddef>
#include <memory>
#include <memory_resource>
#include <type_traits>
#include <utility>

namespace eposp::compiler::ast {

/// Ends a node made in a `NodeArena`: runs its destructor (its strings and vectors own heap
/// memory) and leaves its bytes to the arena, which frees them all at once.
template <typename Node>
struct NodeDeleter {
    void operator()(Node* node) const { node->~Node(); }
};

/// An owning pointer to a node made in a `NodeArena`; as `std::unique_ptr` to readers.
template <typename Node>
using NodePtr = std::unique_ptr<Node, NodeDeleter<Node>>;

/// The memory of one file's nodes (expressions, nested type specifications, initial values):
/// bump-allocated, where a heap block a node cost a malloc and a free, and kept together. The
/// `CompilationUnit` owns it and outlives every node made in it.
class NodeArena {
public:
    NodeArena() = default;
    NodeArena(const NodeArena&) = delete;
    NodeArena& operator=(const NodeArena&) = delete;

    template <typename Node, typename... Args>
    NodePtr<Node> make(Args&&... args) {
        void* place = memory_.allocate(sizeof(Node), alignof(Node));
        if constexpr (std::is_aggregate_v<Node>) {
            // Braces: clang 14 has no parenthesised aggregate initialisation (P0960).
            return NodePtr<Node>(new (place) Node{std::forward<Args>(args)...});
        } else {
            return NodePtr<Node>(new (place) Node(std::forward<Args>(args)...));
        }
    }

private:
    // The first block holds the nodes of a small file; later ones grow geometrically.
    static constexpr std::size_t kFirstBlock = 16 * 1024;
    std::pmr::monotonic_buffer_resource memory_{kFirstBlock};
};

} // namespace eposp::compiler::ast
