#pragma once

// Calls one standard-library native the way compiled code does: a PROGRAM Main that puts the
// arguments into its out area (Addr for STRING pointers, MovN from constants for values), runs
// CallNative and copies the result back into its instance, assembled with the Builder, verified,
// linked against register_standard_library and run in the interpreter.

#include "eposp/vm/stdlib/standard_library.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"
#include "vm_harness.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace eposp::vm::test {

/// One argument of a native call: a STRING in static data (passed by address) or a value.
struct NativeArg {
    bool is_string = false;
    std::uint32_t string_offset = 0;
    std::uint64_t value_bits = 0;
};

template <typename T>
NativeArg value(T v) {
    return NativeArg{false, 0, bits(v)};
}

class StdlibCall {
public:
    StdlibCall() { stdlib::register_standard_library(harness.natives); }

    /// A STRING[capacity] in static data holding `text`; returns its offset (its address).
    std::uint32_t string(std::uint32_t capacity, std::string_view text = {}) {
        const auto bytes = stdlib::string_image(capacity, text);
        const auto offset = harness.builder.allocate(static_cast<std::uint32_t>(bytes.size()),
                                                     stdlib::kStringAlign);
        harness.builder.initialise(offset, bytes);
        return offset;
    }
    NativeArg string_arg(std::uint32_t capacity, std::string_view text) {
        return NativeArg{true, string(capacity, text), 0};
    }
    static NativeArg string_arg(std::uint32_t offset) { return NativeArg{true, offset, 0}; }

    /// Emits the call of `name` (registered by the standard library) with `args`; may be
    /// repeated before run().
    void emit_call(const std::string& name, const std::vector<NativeArg>& args) {
        const auto* entry = harness.natives.find(name);
        if (entry == nullptr) {
            ADD_FAILURE() << "no native " << name;
            return;
        }
        const auto& signature = entry->signature;
        const auto import = harness.builder.import(name, signature);
        EXPECT_EQ(args.size(), signature.parameters.size()) << name;
        for (std::size_t i = 0; i < args.size() && i < signature.parameters.size(); ++i) {
            const auto at = Operand::out(parameter_offset(signature, i));
            const auto size = scalar_size(signature.parameters[i]);
            if (args[i].is_string) {
                harness.builder.emit(Opcode::Addr, at, Operand::global(args[i].string_offset),
                                     Operand::imm(stdlib::kStringHeaderSize));
            } else {
                std::uint8_t raw[8];
                std::memcpy(raw, &args[i].value_bits, sizeof raw);
                const auto constant = harness.builder.constant(std::span(raw, size), size);
                harness.builder.emit(Opcode::MovN, at, Operand::global(constant),
                                     Operand::imm(size));
            }
        }
        harness.builder.emit(Opcode::CallNative, Operand::imm(import), Operand::out(0));
        if (signature.has_result) {
            const auto size = scalar_size(signature.result);
            harness.builder.emit(Opcode::MovN, self(0), Operand::out(0), Operand::imm(size));
        }
    }

    RunState run() {
        harness.builder.emit(Opcode::Ret);
        harness.end_main();
        return harness.run();
    }

    /// emit_call then run.
    RunState call(const std::string& name, const std::vector<NativeArg>& args) {
        emit_call(name, args);
        return run();
    }

    template <typename T>
    T result() const {
        return harness.get<T>(0);
    }
    /// The text of the STRING at `offset` after the run, or "<invalid>".
    std::string text(std::uint32_t offset) const {
        const auto text = stdlib::read_string(harness.machine->memory().subspan(offset));
        return text ? std::string(*text) : std::string("<invalid>");
    }

    Harness harness;
};

} // namespace eposp::vm::test
