#pragma once

#include "eposp/device/program_compiler.hpp"
#include "eposp/vm/image.hpp"

#include <gtest/gtest.h>
#include <span>
#include <string>

namespace eposp::device {

/// The image of an ST program of one file (with the motion library), for a test that loads it
/// into an EposP; a program that does not compile fails the test.
inline vm::Image compile_program(const std::string& source) {
    compiler::SourceManager sources;
    const compiler::FileId file = sources.add("main.st", source);
    compiler::Diagnostics diagnostics;
    auto image = compile_program(sources, std::span(&file, 1), diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << compiler::render(diagnostics, sources);
    EXPECT_TRUE(image.has_value());
    return image ? std::move(*image) : vm::Image{};
}

} // namespace eposp::device
