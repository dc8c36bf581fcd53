// pcap captures of arbitrary bytes: an error or records, never a crash. Every record read
// holds a classic CAN frame (pcap_reader.hpp).

#include "eposp/can/pcap_reader.hpp"
#include "fuzz_check.hpp"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace eposp::can;
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    const auto capture = read_pcap(in);
    if (!capture) {
        return 0;
    }
    for (const PcapRecord& record : capture->records) {
        eposp::fuzz::require(record.frame.dlc <= kMaxDataLength, "a record holds a classic frame");
        eposp::fuzz::require(record.length <= capture->header.snap_length,
                             "a record fits the snap length");
    }
    return 0;
}
