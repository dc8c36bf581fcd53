#include "eposp/can/candump_log_reader.hpp"

#include "trace_file.hpp"

#include <fmt/format.h>
#include <string>

namespace eposp::can {

core::Result<std::vector<CandumpRecord>> read_candump_log(std::istream& in,
                                                          std::string_view source_name) {
    std::vector<CandumpRecord> records;
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
        if (!line.starts_with('(')) {
            continue;
        }
        auto record = parse_candump_line(line);
        if (!record) {
            return core::Error{fmt::format("{}:{}: {}", source_name, number, record.error())};
        }
        records.push_back(std::move(record).value());
    }
    if (in.bad()) {
        return core::Error{fmt::format("{}: read error", source_name)};
    }
    return records;
}

core::Result<std::vector<CandumpRecord>> read_candump_log_file(const std::filesystem::path& path) {
    auto file = open_trace_file(path);
    if (!file) {
        return core::Error{file.error()};
    }
    return read_candump_log(*file, path.string());
}

} // namespace eposp::can
