#include "source_location.hpp"

namespace eposp::vm::detail {

std::uint32_t line_at(const Pou& pou, std::uint32_t instruction) {
    std::uint32_t line = 0;
    for (const auto& entry : pou.lines) {
        if (entry.instruction > instruction) {
            break;
        }
        line = entry.line;
    }
    return line;
}

std::optional<std::uint32_t> locate(const Image& image, std::uint32_t& pou,
                                    std::uint32_t& instruction) {
    for (const InlinedCall& call : image.pous[pou].inlined) {
        if (instruction >= call.begin && instruction < call.end) {
            if (image.pous[call.callee].lines.empty()) {
                return call.callee;
            }
            instruction = image.pous[call.callee].code_begin + (instruction - call.begin);
            pou = call.callee;
            break;
        }
    }
    return std::nullopt;
}

std::uint32_t pou_at(const Image& image, std::uint32_t instruction) {
    for (std::uint32_t pou = 0; pou < image.pous.size(); ++pou) {
        if (instruction >= image.pous[pou].code_begin && instruction < image.pous[pou].code_end) {
            return pou;
        }
    }
    return 0;
}

} // namespace eposp::vm::detail
