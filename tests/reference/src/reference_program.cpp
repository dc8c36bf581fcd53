#include "eposp/reference/reference_program.hpp"

namespace eposp::reference {

// The evaluator proper; defined once the typing stage it walks exists.
class Evaluator {};

ReferenceProgram::ReferenceProgram(const std::string& source)
    : ReferenceProgram(std::vector<std::pair<std::string, std::string>>{{"main.st", source}}) {}

ReferenceProgram::ReferenceProgram(const std::vector<std::pair<std::string, std::string>>&)
    : errors_("not supported by the reference evaluator: anything yet") {}

ReferenceProgram::~ReferenceProgram() = default;

bool ReferenceProgram::ok() const {
    return evaluator_ != nullptr;
}
const std::string& ReferenceProgram::errors() const {
    return errors_;
}
bool ReferenceProgram::scans(int, std::int64_t) {
    return false;
}
std::string ReferenceProgram::fault() const {
    return {};
}
std::optional<std::uint64_t> ReferenceProgram::bits(const std::string&) const {
    return {};
}
std::optional<std::string> ReferenceProgram::string(const std::string&) const {
    return {};
}

} // namespace eposp::reference
