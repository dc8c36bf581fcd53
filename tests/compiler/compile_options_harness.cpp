#include "compile_options_harness.hpp"

#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"
#include "eposp/vm/symbol_lookup.hpp"

#include <cstring>
#include <gtest/gtest.h>

namespace eposp::compiler::test {

OptionsCompilation::OptionsCompilation() {
    vm::stdlib::register_standard_library(natives_);
    vm::stdlib::register_clock(natives_, [this] { return now_ns_; });
}

FileId OptionsCompilation::add(const std::string& path, const std::string& text) {
    return files_.emplace_back(sources_.add(path, text));
}

FileId OptionsCompilation::add_library(const std::string& path, const std::string& text) {
    return libraries_.emplace_back(sources_.add(path, text));
}

bool OptionsCompilation::compile(const CompileOptions& options) {
    Diagnostics diagnostics;
    image_ = compiler::compile(sources_, files_, diagnostics, libraries_, options);
    errors_ = render(diagnostics, sources_);
    return image_.has_value();
}

std::vector<std::string> OptionsCompilation::symbols() const {
    std::vector<std::string> paths;
    for (const vm::Symbol& symbol : image_->symbols) {
        paths.push_back(symbol.path);
    }
    return paths;
}

std::vector<std::string> OptionsCompilation::pous() const {
    std::vector<std::string> names;
    for (const vm::Pou& pou : image_->pous) {
        names.push_back(pou.name);
    }
    return names;
}

std::vector<std::string> OptionsCompilation::imports() const {
    std::vector<std::string> names;
    for (const vm::NativeImport& native : image_->imports) {
        names.push_back(native.name);
    }
    return names;
}

bool OptionsCompilation::run(int n) {
    auto linked = vm::link(*image_, natives_);
    if (!linked) {
        errors_ = linked.error();
        return false;
    }
    program_.emplace(std::move(*linked));
    machine_.emplace(*program_);
    for (int i = 0; i < n; ++i) {
        if (machine_->run_cycle(0) != vm::RunState::Finished) {
            errors_ = machine_->describe_fault(0);
            return false;
        }
        now_ns_ += 1'000'000;
    }
    return true;
}

std::int64_t OptionsCompilation::get(const std::string& path) const {
    const auto location = vm::lookup_variable(program_->image(), path);
    if (!location) {
        ADD_FAILURE() << location.error();
        return -1;
    }
    const std::uint32_t size = program_->image().types[location->type].size;
    const std::uint8_t* at = machine_->memory().data() + location->offset;
    switch (size) {
    case 1:
        return *at;
    case 2: {
        std::int16_t value = 0;
        std::memcpy(&value, at, sizeof value);
        return value;
    }
    case 4: {
        std::int32_t value = 0;
        std::memcpy(&value, at, sizeof value);
        return value;
    }
    default:
        ADD_FAILURE() << path << " has " << size << " bytes";
        return -1;
    }
}

} // namespace eposp::compiler::test
