// `candump -L` logs, lines and frames of arbitrary text: an error or records, never a crash.
// A record read must print as a line that reads back to the same record.

#include "eposp/can/candump_format.hpp"
#include "eposp/can/candump_log_reader.hpp"
#include "fuzz_check.hpp"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>

namespace {

using namespace eposp::can;

void check_round_trip(const CandumpRecord& record) {
    const auto again = parse_candump_line(format_candump_line(record));
    eposp::fuzz::require(again.ok() && *again == record,
                         "a record read prints as a line that reads back to it");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);

    std::istringstream log(text);
    if (const auto records = read_candump_log(log, "fuzz.log")) {
        for (const CandumpRecord& record : *records) {
            check_round_trip(record);
        }
    }
    // The whole input as one line and as one frame, as `eposp` reads them from a command line.
    if (const auto record = parse_candump_line(text)) {
        check_round_trip(*record);
    }
    if (const auto frame = parse_candump_frame(text)) {
        const auto again = parse_candump_frame(format_candump_frame(*frame));
        eposp::fuzz::require(again.ok() && *again == *frame,
                             "a frame read prints in a form that reads back to it");
    }
    return 0;
}
