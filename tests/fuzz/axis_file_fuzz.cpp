// The machine file of `eposp drive epos2 --config` (YAML) from arbitrary text: an axis the
// plant can run, or an error that names the file, never a crash.

#include "eposp/drives/plant/axis_file.hpp"
#include "fuzz_check.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace eposp::drives::plant;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto axis = parse_axis_file(text, "fuzz.yaml");
    if (!axis) {
        eposp::fuzz::require(axis.error().starts_with("fuzz.yaml:"),
                             "an error names the file and its place");
        return 0;
    }
    eposp::fuzz::require(validate(axis->plant).ok(), "a parsed machine is one the model runs");
    eposp::fuzz::require(axis->encoder_pulses >= 16, "the encoder has at least 16 pulses");
    const auto current = to_parameter_set(axis->gains.current);
    eposp::fuzz::require(current.p_gain >= 0 && current.i_gain >= 0,
                         "the current gains are in 0x60F6's range");
    const SwitchLayout& switches = axis->switches;
    eposp::fuzz::require(!switches.negative_limit || !switches.positive_limit ||
                             *switches.negative_limit < *switches.positive_limit,
                         "the limit switches leave travel between them");
    return 0;
}
