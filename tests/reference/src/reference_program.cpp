#include "eposp/reference/reference_program.hpp"

#include "eposp/compiler/source_manager.hpp"
#include "eposp/compiler/types/front_end.hpp"
#include "evaluator.hpp"
#include "support_check.hpp"

#include <cstring>

namespace eposp::reference {

ReferenceProgram::ReferenceProgram(const std::string& source)
    : ReferenceProgram(std::vector<std::pair<std::string, std::string>>{{"main.st", source}}) {}

ReferenceProgram::ReferenceProgram(const std::vector<std::pair<std::string, std::string>>& files) {
    compiler::SourceManager sources;
    std::vector<compiler::FileId> ids;
    for (const auto& [path, text] : files) {
        ids.push_back(sources.add(path, text));
    }
    compiler::Diagnostics diagnostics;
    auto front_end = compiler::types::analyse(sources, ids, diagnostics);
    errors_ = render(diagnostics, sources);
    if (front_end->program == nullptr) {
        return;
    }
    try {
        check_supported(*front_end);
        evaluator_ = std::make_unique<Evaluator>(std::move(front_end));
    } catch (const Unsupported& unsupported) {
        errors_ += unsupported.what();
    } catch (const Fault& fault) {
        errors_ += fault.what();
    }
}

ReferenceProgram::~ReferenceProgram() = default;
ReferenceProgram::ReferenceProgram(ReferenceProgram&&) noexcept = default;
ReferenceProgram& ReferenceProgram::operator=(ReferenceProgram&&) noexcept = default;

bool ReferenceProgram::ok() const {
    return evaluator_ != nullptr;
}

const std::string& ReferenceProgram::errors() const {
    return errors_;
}

bool ReferenceProgram::scans(int n, std::int64_t step_ns) {
    if (!fault_.empty()) {
        return false;
    }
    for (int i = 0; i < n; ++i) {
        try {
            evaluator_->scan(now_ns_);
        } catch (const std::runtime_error& error) { // Fault or Unsupported
            fault_ = error.what();
            return false;
        }
        now_ns_ += step_ns;
    }
    return true;
}

std::string ReferenceProgram::fault() const {
    return fault_;
}

std::optional<std::uint64_t> ReferenceProgram::bits(const std::string& path) const {
    const Value* value = evaluator_ != nullptr ? evaluator_->find(path) : nullptr;
    if (value == nullptr || value->type == nullptr) {
        return std::nullopt;
    }
    switch (shape_of(*value->type)) {
    case Shape::Integer: {
        const unsigned width = width_of(*value->type);
        return width >= 64 ? value->bits
                           : value->bits & ((std::uint64_t{1} << std::max(width, 8U)) - 1);
    }
    case Shape::Real: {
        const float f = static_cast<float>(value->real);
        std::uint32_t raw = 0;
        std::memcpy(&raw, &f, sizeof raw);
        return raw;
    }
    case Shape::Lreal: {
        std::uint64_t raw = 0;
        std::memcpy(&raw, &value->real, sizeof raw);
        return raw;
    }
    default:
        return std::nullopt;
    }
}

std::optional<std::string> ReferenceProgram::string(const std::string& path) const {
    const Value* value = evaluator_ != nullptr ? evaluator_->find(path) : nullptr;
    if (value == nullptr || value->type == nullptr || shape_of(*value->type) != Shape::String) {
        return std::nullopt;
    }
    return value->text;
}

} // namespace eposp::reference
