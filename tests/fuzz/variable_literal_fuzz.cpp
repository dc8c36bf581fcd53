// What a service tool may write to the variable access object 0x5F60 of the EPOS P
// (docs/service-interface.md, "Variable access"): arbitrary text as the value of a variable of
// each elementary type. The write is taken or refused with a documented code and never crashes;
// a value taken reads back as a literal that is taken again and reads back the same.
//
// Input: [variable] [literal...]; the first byte picks the variable (modulo their number).

#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/program_compiler.hpp"
#include "eposp/vm/image_format.hpp"
#include "fuzz_check.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace {

using eposp::canopen::AbortCode;
using eposp::fuzz::require;

constexpr std::string_view kProgram = R"(
TYPE Mode : (Idle, Travel, Halt); END_TYPE
PROGRAM Main
VAR b : BOOL; s : SINT; us : USINT; i : INT; ui : UINT; di : DINT; udi : UDINT; l : LINT;
    ul : ULINT; w : WORD; r : REAL; lr : LREAL; m : Mode; p : INT(0..100); t : TIME; END_VAR
VAR CONSTANT k : INT := 3; END_VAR
END_PROGRAM
)";

constexpr std::array<std::string_view, 16> kPaths{
    "Main.b",  "Main.s", "Main.us", "Main.i",  "Main.ui", "Main.di", "Main.udi", "Main.l",
    "Main.ul", "Main.w", "Main.r",  "Main.lr", "Main.m",  "Main.p",  "Main.t",   "Main.k"};

eposp::device::EposP& device() {
    static const auto loaded = [] {
        auto epos_p = std::make_unique<eposp::device::EposP>();
        eposp::compiler::SourceManager sources;
        const eposp::compiler::FileId file = sources.add("main.st", std::string(kProgram));
        eposp::compiler::Diagnostics diagnostics;
        auto image = eposp::device::compile_program(sources, std::span(&file, 1), diagnostics);
        require(image.has_value(), "the fuzz program compiles");
        require(epos_p->objects().write(eposp::device::kProgramDataIndex, 1,
                                        eposp::vm::write_image(*image)) == AbortCode::None,
                "the fuzz program downloads");
        return epos_p;
    }();
    return *loaded;
}

AbortCode write(std::uint8_t sub, std::string_view text) {
    return device().objects().write(eposp::device::kVariableAccessIndex, sub,
                                    eposp::canopen::encode_string(text));
}

std::string read_value() {
    eposp::canopen::Bytes value;
    require(device().objects().read(eposp::device::kVariableAccessIndex, 2, value) ==
                AbortCode::None,
            "the value of a variable reads");
    return {value.begin(), value.end()};
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    require(write(1, kPaths[data[0] % kPaths.size()]) == AbortCode::None, "every path is known");
    const std::string_view literal(reinterpret_cast<const char*>(data + 1), size - 1);
    const AbortCode code = write(2, literal);
    require(code == AbortCode::None || code == AbortCode::InvalidValue ||
                code == AbortCode::ReadOnly || code == AbortCode::LengthTooHigh,
            "a literal is taken or refused with a documented code");
    if (code != AbortCode::None) {
        return 0;
    }
    const std::string shown = read_value();
    require(!shown.empty(), "a value taken reads back");
    require(write(2, shown) == AbortCode::None, "the value read back is taken again");
    require(read_value() == shown, "and reads back the same");
    return 0;
}
