#include "eposp/can/candump_log_writer.hpp"

#include "eposp/can/candump_format.hpp"

namespace eposp::can {

void CandumpLogWriter::record(TraceTime time, std::string_view interface_name, const Frame& frame) {
    output_.write(format_candump_line({time, std::string(interface_name), frame}) + '\n');
}

} // namespace eposp::can
