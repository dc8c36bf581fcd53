#include "eposp/differential/reference_executor.hpp"

#include "eposp/differential/st_generator.hpp"
#include "eposp/reference/reference_program.hpp"

#include <string_view>

namespace eposp::differential {
namespace {

constexpr std::string_view kRefusal = "not supported by the reference evaluator";

} // namespace

Execution ReferenceExecutor::run(const std::string& source, int scans) {
    Execution execution;
    reference::ReferenceProgram program(source);
    if (!program.ok()) {
        execution.errors = program.errors();
        return execution;
    }
    execution.loaded = true;
    for (int scan = 0; scan < scans; ++scan) {
        if (!program.scans(1)) {
            // What the evaluator meets only while running and does not model is a refusal too.
            if (program.fault().starts_with(kRefusal)) {
                return Execution{false, program.fault(), {}, {}, {}};
            }
            execution.fault_scan = scan;
            execution.fault = program.fault();
            break;
        }
        execution.checksums.push_back(program.bits(kChecksumPath).value_or(0));
    }
    return execution;
}

} // namespace eposp::differential
