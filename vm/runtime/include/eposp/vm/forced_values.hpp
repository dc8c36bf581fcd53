#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace eposp::vm {

/// Variables held at a value by the operator (online access "force"): the runtime writes them
/// before and after every task cycle, so the program sees the forced value and so do the outputs
/// it publishes, whatever it assigns in between.
class ForcedValues {
public:
    struct Forced {
        std::string path;
        std::uint32_t offset = 0;
        std::vector<std::uint8_t> bytes;
    };

    /// Forces the bytes at `offset` (a later force of the same variable replaces the value).
    void force(std::string path, std::uint32_t offset, std::vector<std::uint8_t> bytes);
    /// False when the variable at `offset` was not forced.
    bool release(std::uint32_t offset);
    void release_all() { forced_.clear(); }

    void apply(std::span<std::uint8_t> memory) const;
    const std::vector<Forced>& forced() const { return forced_; }

private:
    std::vector<Forced> forced_;
};

} // namespace eposp::vm
