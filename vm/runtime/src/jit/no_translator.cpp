#include "compiled_code.hpp"

// This build has no translator for its processor: the interpreter runs every program.

namespace eposp::vm::jit {

CompiledCode::~CompiledCode() = default;

RunState CompiledCode::run(const Program&, std::span<std::uint8_t>, TaskState& task,
                           std::uint64_t) const {
    return task.state;
}

std::shared_ptr<const CompiledCode> compile(const Image&) {
    return nullptr;
}

} // namespace eposp::vm::jit
