#pragma once

#include "eposp/core/result.hpp"
#include "eposp/vm/image.hpp"
#include "eposp/vm/native.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace eposp::vm {

namespace jit {
class CompiledCode;
}

/// What runs a program's tasks. Both give the same results, instruction counts, safe points and
/// run-time errors; the interpreter is the reference and runs everywhere, compiled code is
/// x86-64 machine code translated when the program is linked.
enum class Engine : std::uint8_t { Interpreter, Compiled };

/// Compiled where this build has a translator, unless the environment variable
/// EPOSP_VM_ENGINE is `interpreter`.
Engine default_engine();

/// A verified image with its imports bound to host functions: the only thing the interpreter
/// runs. Made by link or load_program, so an unverified image cannot reach the interpreter.
class Program {
public:
    const Image& image() const { return image_; }
    const NativeFunction& native(std::uint32_t import) const { return *natives_[import]; }
    /// The machine code of the image; nullptr when the interpreter runs it.
    const jit::CompiledCode* compiled() const { return compiled_.get(); }
    Engine engine() const { return compiled_ ? Engine::Compiled : Engine::Interpreter; }

private:
    friend core::Result<Program> link(Image image, const NativeRegistry& natives, Engine engine);
    Program(Image image, std::vector<const NativeFunction*> natives,
            std::shared_ptr<const jit::CompiledCode> compiled)
        : image_(std::move(image)), natives_(std::move(natives)), compiled_(std::move(compiled)) {}

    Image image_;
    std::vector<const NativeFunction*> natives_;
    std::shared_ptr<const jit::CompiledCode> compiled_;
};

/// Verifies `image` and binds each import to the registry entry of the same name and
/// signature; the registry must outlive the program. With Engine::Compiled the image is
/// translated to machine code where this build can (else the interpreter runs it).
core::Result<Program> link(Image image, const NativeRegistry& natives,
                           Engine engine = default_engine());

/// read_image, then link: from the bytes of a file to something that can run.
core::Result<Program> load_program(std::span<const std::uint8_t> bytes,
                                   const NativeRegistry& natives, Engine engine = default_engine());

} // namespace eposp::vm
