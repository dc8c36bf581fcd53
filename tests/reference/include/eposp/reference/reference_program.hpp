#pragma once

// The reference evaluator (issue 16): a deliberately simple tree-walking interpreter of the typed
// program (after name resolution and the typing stage, before any lowering), written from the
// rules of IEC 61131-3 ed. 3 and the project's documented choices. It shares nothing with code
// generation or the VM, so it is the oracle of the differential tests; speed does not matter.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace eposp::reference {

class Evaluator;

class ReferenceProgram {
public:
    /// Parses, resolves and types the files with the compiler's front end (parse → names →
    /// types); errors() says why when that fails or when the program uses something the
    /// evaluator does not support (it then refuses rather than guessing).
    explicit ReferenceProgram(const std::vector<std::pair<std::string, std::string>>& files);
    explicit ReferenceProgram(const std::string& source); // one file, "main.st"
    ~ReferenceProgram();
    ReferenceProgram(const ReferenceProgram&) = delete;
    ReferenceProgram& operator=(const ReferenceProgram&) = delete;
    ReferenceProgram(ReferenceProgram&&) noexcept;
    ReferenceProgram& operator=(ReferenceProgram&&) noexcept;

    bool ok() const;
    const std::string& errors() const;
    /// Runs n scans of the first task exactly as tests/compiler/codegen_harness.hpp's StProgram
    /// does (same task choice, same clock: the clock advances step_ns after each scan);
    /// false on a run-time fault (division by zero, index out of range, ...).
    bool scans(int n, std::int64_t step_ns = 1'000'000);
    std::string fault() const;
    /// An elementary variable by the same paths StProgram takes (`Main.x`, `Inst0.s.a`,
    /// `Config0.g`): its value's bytes as the VM stores them (little-endian, its size),
    /// zero-extended to 64 bits (BOOL 0/1, REAL the float's bits, LREAL the double's, TIME ns).
    std::optional<std::uint64_t> bits(const std::string& path) const;
    /// A STRING variable's characters.
    std::optional<std::string> string(const std::string& path) const;

private:
    std::unique_ptr<Evaluator> evaluator_;
    std::string errors_;
    std::string fault_;
    std::int64_t now_ns_ = 0;
};

} // namespace eposp::reference
