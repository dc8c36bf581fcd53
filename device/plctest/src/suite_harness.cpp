// A suite's program: the test files, the libraries and a harness that runs the suite.

#include "eposp/compiler/compile_options.hpp"
#include "eposp/compiler/compiler.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/plcopen/motion_library.hpp"
#include "eposp/plctest/suite_runner.hpp"
#include "eposp/plctest/test_library.hpp"

#include <fmt/format.h>

namespace eposp::plctest {

device::NetworkFile default_network() {
    device::NetworkFile network;
    network.sync_period = std::chrono::milliseconds(1);
    device::NetworkSlave internal;
    internal.port = device::kInternalPort;
    internal.node_id = 1;
    internal.axis = 0;
    network.slaves.push_back(internal);
    return network;
}

core::Duration test_cycle(const device::NetworkFile& network) {
    return network.sync_period.value_or(std::chrono::milliseconds(1));
}

std::string harness_source(const Suite& suite, core::Duration cycle) {
    std::string text;
    std::string program = suite.name;
    if (suite.kind == compiler::ast::PouKind::FunctionBlock) {
        program = "EPOSP_TEST_SUITE";
        text += fmt::format("PROGRAM EPOSP_TEST_SUITE\nVAR\n    Suite : {};\nEND_VAR\n"
                            "    Suite();\nEND_PROGRAM\n\n",
                            suite.name);
    }
    text += fmt::format("PROGRAM EPOSP_TEST_CYCLE\n    {}();\nEND_PROGRAM\n\n", kCycleEndFunction);
    text += fmt::format("CONFIGURATION EPOSP_TEST\n"
                        "    RESOURCE EposP ON EPOS_P\n"
                        "        TASK EPOSP_TEST_TASK (INTERVAL := T#{}, PRIORITY := 1);\n"
                        "        PROGRAM Suite WITH EPOSP_TEST_TASK : {};\n"
                        "        PROGRAM CycleEnd WITH EPOSP_TEST_TASK : EPOSP_TEST_CYCLE;\n"
                        "    END_RESOURCE\n"
                        "END_CONFIGURATION\n",
                        core::format_duration(cycle), program);
    return text;
}

core::Result<vm::Image> build_suite(const TestSources& sources, const Suite& suite,
                                    core::Duration cycle, bool coverage,
                                    const DiagnosticsObserver& observe) {
    compiler::SourceManager files;
    compiler::CompileOptions options;
    std::vector<compiler::FileId> program;
    for (const std::string& path : sources.paths) {
        auto file = files.load(path);
        if (!file) {
            return core::Error{file.error()};
        }
        program.push_back(*file);
        options.ignored_configurations.push_back(*file);
    }
    program.push_back(
        files.add("<test harness of " + suite.name + ">", harness_source(suite, cycle)));
    const compiler::FileId libraries[] = {
        files.add("<motion library>", std::string(plcopen::MotionLibrary::source())),
        files.add("<test library>", std::string(TestLibrary::source()))};
    options.substitutions.insert(suite.mocks.begin(), suite.mocks.end());
    options.if_conversion = !coverage;
    compiler::Diagnostics diagnostics;
    auto image = compiler::compile(files, program, diagnostics, libraries, options);
    if (observe) {
        observe(diagnostics, files);
    }
    if (!image) {
        return core::Error{"does not compile:\n" + compiler::render(diagnostics, files)};
    }
    return std::move(*image);
}

} // namespace eposp::plctest
