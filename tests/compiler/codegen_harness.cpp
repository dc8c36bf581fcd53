#include "codegen_harness.hpp"

#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"
#include "eposp/vm/symbol_lookup.hpp"

#include <cstring>
#include <gtest/gtest.h>

namespace eposp::compiler::test {

StProgram::StProgram(const std::string& source)
    : StProgram(std::vector<std::pair<std::string, std::string>>{{"test.st", source}}) {}

StProgram::StProgram(const std::vector<std::pair<std::string, std::string>>& files) {
    vm::stdlib::register_standard_library(natives_);
    vm::stdlib::register_clock(natives_, [this] { return now_ns_; });
    SourceManager sources;
    std::vector<FileId> ids;
    for (const auto& [path, text] : files) {
        ids.push_back(sources.add(path, text));
    }
    Diagnostics diagnostics;
    auto image = compile(sources, ids, diagnostics);
    errors_ = render(diagnostics, sources);
    if (!image) {
        return;
    }
    auto linked = vm::link(std::move(*image), natives_);
    if (!linked) {
        errors_ += linked.error();
        return;
    }
    program_.emplace(std::move(*linked));
    machine_.emplace(*program_);
}

bool StProgram::scans(int n, std::int64_t step_ns) {
    for (int i = 0; i < n; ++i) {
        if (machine_->run_cycle(0) != vm::RunState::Finished) {
            return false;
        }
        now_ns_ += step_ns;
    }
    return true;
}

std::string StProgram::fault() const {
    // The machine keeps the last fault record (or a default one) after the task runs again.
    if (!ok() || machine_->task(0).state != vm::RunState::Faulted) {
        return "";
    }
    return machine_->describe_fault(0);
}

const std::uint8_t* StProgram::address(const std::string& path, std::size_t size) const {
    const auto location = vm::lookup_variable(program_->image(), path);
    if (!location) {
        ADD_FAILURE() << location.error();
        return nullptr;
    }
    if (program_->image().types[location->type].size != size &&
        program_->image().types[location->type].kind != vm::TypeKind::String) {
        ADD_FAILURE() << path << " is a " << program_->image().types[location->type].name;
        return nullptr;
    }
    return machine_->memory().data() + location->offset;
}

template <typename T>
T StProgram::get(const std::string& path) const {
    T value{};
    if (const std::uint8_t* at = address(path, sizeof(T))) {
        std::memcpy(&value, at, sizeof(T));
    }
    return value;
}

template bool StProgram::get<bool>(const std::string&) const;
template std::int8_t StProgram::get<std::int8_t>(const std::string&) const;
template std::int16_t StProgram::get<std::int16_t>(const std::string&) const;
template std::int32_t StProgram::get<std::int32_t>(const std::string&) const;
template std::int64_t StProgram::get<std::int64_t>(const std::string&) const;
template std::uint8_t StProgram::get<std::uint8_t>(const std::string&) const;
template std::uint16_t StProgram::get<std::uint16_t>(const std::string&) const;
template std::uint32_t StProgram::get<std::uint32_t>(const std::string&) const;
template std::uint64_t StProgram::get<std::uint64_t>(const std::string&) const;
template float StProgram::get<float>(const std::string&) const;
template double StProgram::get<double>(const std::string&) const;

std::string StProgram::get_string(const std::string& path) const {
    const std::uint8_t* at = address(path, 0);
    if (at == nullptr) {
        return {};
    }
    const auto text = vm::stdlib::read_string(
        {at, machine_->memory().size() - static_cast<std::size_t>(at - machine_->memory().data())});
    return text ? std::string(*text) : std::string("<bad string>");
}

std::u16string StProgram::get_wstring(const std::string& path) const {
    const std::uint8_t* at = address(path, vm::stdlib::kStringHeaderSize);
    if (at == nullptr) {
        return {};
    }
    const std::span<const std::uint8_t> bytes{
        at, machine_->memory().size() - static_cast<std::size_t>(at - machine_->memory().data())};
    if (!vm::stdlib::string_capacity(bytes, vm::stdlib::CharWidth::Wide)) {
        return u"<bad wstring>";
    }
    std::u16string units;
    for (std::size_t i = 0; i < vm::stdlib::string_length(bytes); ++i) {
        units.push_back(vm::stdlib::wstring_unit(bytes, i));
    }
    return units;
}

std::string diagnostics_of(const std::string& source) {
    SourceManager sources;
    const FileId file = sources.add("test.st", source);
    Diagnostics diagnostics;
    compile(sources, {&file, 1}, diagnostics);
    return render(diagnostics, sources);
}

} // namespace eposp::compiler::test
