#include "file_checks.hpp"

#include "eposp/manager/concise_dcf.hpp"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iterator>
#include <vector>

namespace eposp::device::cli {
namespace {

// Enough to recognise every kind by its start; a concise DCF is read whole (they are small).
constexpr std::size_t kHeadSize = 4096;
constexpr std::size_t kConciseDcfLimit = 1 << 20;

std::string read_head(const std::filesystem::path& path, std::size_t size) {
    std::ifstream in(path, std::ios::binary);
    std::string head(size, '\0');
    in.read(head.data(), static_cast<std::streamsize>(size));
    head.resize(static_cast<std::size_t>(in.gcount()));
    return head;
}

std::string_view first_line(std::string_view text) {
    return text.substr(0, text.find('\n'));
}

// CiA 306 4.1: an INI file; before the first [section] only comments and blank lines.
bool looks_like_ini(std::string_view text) {
    if (text.starts_with("\xEF\xBB\xBF")) {
        text.remove_prefix(3);
    }
    while (!text.empty()) {
        const std::string_view line = first_line(text);
        const auto start = line.find_first_not_of(" \t\r");
        if (start != std::string_view::npos && line[start] != ';') {
            return line[start] == '[';
        }
        text.remove_prefix(std::min(text.size(), line.size() + 1));
    }
    return false;
}

// candump -L: `(1436509052.249713) can0 123#DEADBEEF`.
bool looks_like_candump_log(std::string_view text) {
    const std::string_view line = first_line(text);
    return line.starts_with('(') && line.find(") ") != std::string_view::npos &&
           line.find('#') != std::string_view::npos;
}

bool looks_like_pcap(std::string_view text) {
    static constexpr std::string_view kMagics[] = {"\xD4\xC3\xB2\xA1", "\xA1\xB2\xC3\xD4",
                                                   "\x4D\x3C\xB2\xA1", "\xA1\xB2\x3C\x4D"};
    return std::ranges::any_of(kMagics,
                               [text](std::string_view magic) { return text.starts_with(magic); });
}

bool looks_like_concise_dcf(const std::filesystem::path& path) {
    const std::string text = read_head(path, kConciseDcfLimit);
    const std::vector<std::uint8_t> bytes(text.begin(), text.end());
    return static_cast<bool>(manager::decode_concise_dcf(bytes));
}

std::string_view kind_name(OutputKind kind) {
    switch (kind) {
    case OutputKind::ProgramImage:
        return "a program image";
    case OutputKind::RetainStore:
        return "a retain store";
    case OutputKind::ParameterFile:
        return "a parameter file";
    case OutputKind::AxisTrace:
        return "an axis trace";
    case OutputKind::CandumpLog:
        return "a candump log";
    case OutputKind::Pcap:
        return "a pcap file";
    case OutputKind::DeviceDescription:
        return "an EDS or DCF file";
    case OutputKind::ConciseDcf:
        return "a concise DCF";
    case OutputKind::SvgPicture:
        return "an SVG picture";
    case OutputKind::JunitReport:
        return "a JUnit report";
    case OutputKind::LcovTracefile:
        return "an lcov tracefile";
    }
    return "a file of this kind";
}

bool same_file(const std::string& a, const std::string& b) {
    std::error_code error;
    return std::filesystem::equivalent(a, b, error);
}

} // namespace

bool is_of_kind(const std::filesystem::path& path, OutputKind kind) {
    const std::string head = read_head(path, kHeadSize);
    switch (kind) {
    case OutputKind::ProgramImage:
        return head.starts_with("EPXI");
    case OutputKind::RetainStore:
        return head.starts_with("EPRT");
    case OutputKind::ParameterFile:
        return head.starts_with("EPOSPPAR");
    case OutputKind::AxisTrace:
        return head.starts_with("time_s,axis,");
    case OutputKind::CandumpLog:
        return looks_like_candump_log(head);
    case OutputKind::Pcap:
        return looks_like_pcap(head);
    case OutputKind::DeviceDescription:
        return looks_like_ini(head);
    case OutputKind::ConciseDcf:
        return looks_like_concise_dcf(path);
    case OutputKind::SvgPicture:
        return head.starts_with("<svg") || head.starts_with("<?xml");
    case OutputKind::JunitReport:
        return head.starts_with("<?xml") && head.find("<testsuites") != std::string::npos;
    case OutputKind::LcovTracefile:
        return head.starts_with("TN:") || head.starts_with("SF:");
    }
    return false;
}

std::optional<std::string> input_file_problem(const std::string& path, std::string_view what) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        return fmt::format("{} is a directory, not {}", path, what);
    }
    return std::nullopt;
}

std::optional<std::string> output_file_problem(const OutputFile& output,
                                               std::span<const std::string> inputs, bool force) {
    std::error_code error;
    const auto status = std::filesystem::status(output.path, error);
    if (std::filesystem::is_directory(status)) {
        return fmt::format("{} {} is a directory, not {}", output.option, output.path,
                           kind_name(output.kind));
    }
    for (const std::string& input : inputs) {
        if (same_file(output.path, input)) {
            return fmt::format("{} {} would overwrite the input {}", output.option, output.path,
                               input);
        }
    }
    // Devices and pipes (/dev/stdout) are written to, not replaced; an empty file holds nothing.
    if (!force && std::filesystem::is_regular_file(status) &&
        std::filesystem::file_size(output.path, error) > 0 &&
        !is_of_kind(output.path, output.kind)) {
        return fmt::format("{} {}: the existing file is not {}; --force replaces it", output.option,
                           output.path, kind_name(output.kind));
    }
    return std::nullopt;
}

std::optional<std::string> output_files_problem(std::span<const OutputFile> outputs,
                                                std::span<const std::string> inputs, bool force) {
    for (auto output = outputs.begin(); output != outputs.end(); ++output) {
        if (auto problem = output_file_problem(*output, inputs, force)) {
            return problem;
        }
        for (auto earlier = outputs.begin(); earlier != output; ++earlier) {
            if (earlier->path == output->path || same_file(earlier->path, output->path)) {
                return fmt::format("{} {}: that file is written twice", output->option,
                                   output->path);
            }
        }
    }
    return std::nullopt;
}

void add_force_option(CLI::App& command, bool& force) {
    command.add_flag("--force", force,
                     "Replace existing output files even when they are not of the kind written "
                     "(never an input of the command)");
}

} // namespace eposp::device::cli
