#pragma once

// Compiles ST source with compile(), links it with the standard library and a virtual clock,
// and runs its first task scan by scan: the shape of every end-to-end code generation test.

#include "eposp/compiler/compiler.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/native.hpp"
#include "eposp/vm/program.hpp"

#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace eposp::compiler::test {

class StProgram {
public:
    /// Compiles and links `source`; errors() says what went wrong if it did not.
    explicit StProgram(const std::string& source);
    /// The same for a program of several (path, text) files.
    explicit StProgram(const std::vector<std::pair<std::string, std::string>>& files);

    bool ok() const { return machine_.has_value(); }
    /// The rendered diagnostics (errors and warnings) of the compilation, or the link error.
    const std::string& errors() const { return errors_; }

    /// Runs `n` scans of task 0, the clock advancing `step_ns` after each; false on a fault.
    bool scans(int n, std::int64_t step_ns = 1'000'000);
    /// The fault text of task 0 ("division by zero in Main at line 3").
    std::string fault() const;
    /// The compiled image (only when ok()).
    const vm::Image& image() const { return program_->image(); }

    /// A variable by its path (`Main.x`, `Config0.result`, `Inst0.s.checksum`).
    template <typename T>
    T get(const std::string& path) const;
    std::string get_string(const std::string& path) const;
    std::u16string get_wstring(const std::string& path) const;
    /// Sets a variable between scans.
    template <typename T>
    void set(const std::string& path, T value) {
        if (const std::uint8_t* at = address(path, sizeof(T))) {
            std::memcpy(const_cast<std::uint8_t*>(at), &value, sizeof(T));
        }
    }

private:
    const std::uint8_t* address(const std::string& path, std::size_t size) const;

    std::int64_t now_ns_ = 0;
    vm::NativeRegistry natives_;
    std::optional<vm::Program> program_;
    std::optional<vm::Machine> machine_;
    std::string errors_;
};

/// The diagnostics of compiling `source`, rendered; empty when it compiles cleanly.
std::string diagnostics_of(const std::string& source);

} // namespace eposp::compiler::test
