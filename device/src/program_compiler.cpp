#include "eposp/device/program_compiler.hpp"

#include "eposp/device/event_binding.hpp"
#include "eposp/plcopen/motion_library.hpp"

namespace eposp::device {

namespace {

compiler::CompileOptions device_options() {
    compiler::CompileOptions options;
    // The TASKs' {attribute 'event' := '…'} name the EPOS P's events (docs/network.md, "Events").
    options.task_event_check = [](std::string_view text) -> std::optional<std::string> {
        const auto event = parse_event(text);
        return event ? std::nullopt : std::optional(event.error());
    };
    return options;
}

compiler::FileId motion_library(compiler::SourceManager& sources) {
    return sources.add("<motion library>", plcopen::MotionLibrary::source());
}

} // namespace

std::optional<vm::Image> compile_program(compiler::SourceManager& sources,
                                         std::span<const compiler::FileId> files,
                                         compiler::Diagnostics& diagnostics) {
    const compiler::FileId motion = motion_library(sources);
    return compiler::compile(sources, files, diagnostics, std::span(&motion, 1), device_options());
}

bool check_program(compiler::SourceManager& sources, std::span<const compiler::FileId> files,
                   compiler::Diagnostics& diagnostics) {
    const compiler::FileId motion = motion_library(sources);
    return compiler::check(sources, files, diagnostics, std::span(&motion, 1), device_options());
}

} // namespace eposp::device
