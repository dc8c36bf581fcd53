#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace eposp::device::cli {

/// The kinds of file the commands write. An existing file is replaced only when its first bytes
/// say it is of the kind being written (or under --force): a typo must not destroy a source, a
/// network file or a picture.
enum class OutputKind {
    ProgramImage,      ///< `eposp build` (magic "EPXI")
    RetainStore,       ///< --retain (magic "EPRT")
    ParameterFile,     ///< --parameter-file (magic "EPOSPPAR")
    AxisTrace,         ///< --trace (its CSV header)
    CandumpLog,        ///< --log / --can-log (`(time) interface id#data` lines)
    Pcap,              ///< --pcap (a pcap magic number)
    DeviceDescription, ///< EDS or DCF (CiA 306: an INI file)
    ConciseDcf,        ///< CiA 302-3 concise DCF (a well-formed entry list)
    SvgPicture,        ///< `eposp plot`
    JunitReport,       ///< `eposp test --junit` (XML with <testsuites>)
    LcovTracefile,     ///< `eposp test --coverage` (lcov records: `TN:` / `SF:` lines)
};

/// A file a command is about to write, and the option that named it.
struct OutputFile {
    std::string option; ///< e.g. "--retain", "-o"
    std::string path;
    OutputKind kind;
};

/// Whether the content of the file at `path` says it is of `kind` (its magic, its header line).
bool is_of_kind(const std::filesystem::path& path, OutputKind kind);

/// Why `path` cannot be read as a file (`what` says what it should be: "an EDS file"), or
/// nullopt: a directory is refused here rather than read as an empty file.
std::optional<std::string> input_file_problem(const std::string& path, std::string_view what);

/// Why the command must not write `output`, or nullopt: it is a directory, or the same file as
/// one of `inputs` (never allowed: the run reads them), or an existing file whose contents are
/// not of `output.kind`, unless `force`.
std::optional<std::string> output_file_problem(const OutputFile& output,
                                               std::span<const std::string> inputs, bool force);

/// The same for several outputs, which must also be different files.
std::optional<std::string> output_files_problem(std::span<const OutputFile> outputs,
                                                std::span<const std::string> inputs, bool force);

/// Adds `--force`: replace existing files of another kind.
void add_force_option(CLI::App& command, bool& force);

} // namespace eposp::device::cli
