// The files the commands write, as a user meets them: an input is never overwritten, an existing
// file of another kind only with --force, and a directory where a file belongs is an error.
#include "../../device/cli/src/last_resort.hpp"
#include "eposp_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <ostream>
#include <stdexcept>

namespace eposp::device {
namespace {

using testing::HasSubstr;

const std::string kSourceDir = EPOSP_SOURCE_DIR;

// A counter kept in a RETAIN variable: a run saves a retain store at its end.
constexpr const char* kRetainCounter = "PROGRAM Main\n"
                                       "  VAR RETAIN count : DINT; END_VAR\n"
                                       "  count := count + 1;\n"
                                       "END_PROGRAM\n"
                                       "CONFIGURATION Config0\n"
                                       "  TASK Fast(INTERVAL := T#1ms, PRIORITY := 0);\n"
                                       "  PROGRAM Inst0 WITH Fast : Main;\n"
                                       "END_CONFIGURATION\n";

constexpr const char* kNotes = "notes that took a day to write\n";

/// `text` with every `{dir}` replaced by the test's own directory.
std::string in_scratch(std::string text) {
    const std::string dir = scratch("").parent_path().string();
    for (auto at = text.find("{dir}"); at != std::string::npos; at = text.find("{dir}")) {
        text.replace(at, 5, dir);
    }
    return text;
}

TEST(OutputFiles, BuildIntoItsOwnSourceIsRefusedAndTheSourceKept) {
    const std::string source = write_source("counter.st", kRetainCounter);
    // Another name for the same file: the check compares files, not names.
    const auto alias = scratch("alias.st");
    std::filesystem::remove(alias);
    std::filesystem::create_symlink(source, alias);
    for (const std::string& output : {source, alias.string()}) {
        const auto result = eposp("build " + source + " -o " + output + " --force");
        EXPECT_EQ(result.exit_code, 1) << result.output;
        EXPECT_THAT(result.output, HasSubstr("would overwrite the input " + source));
        EXPECT_EQ(read_file(source), kRetainCounter);
    }
}

TEST(OutputFiles, RetainStoreNamingTheProgramIsRefusedAndTheProgramKept) {
    const std::string source = write_source("counter.st", kRetainCounter);
    const auto result = eposp("run " + source + " --retain " + source + " --for 10ms");
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_THAT(result.output, HasSubstr("--retain " + source + " would overwrite the input"));
    EXPECT_EQ(read_file(source), kRetainCounter);
}

struct OverwriteCase {
    const char* name;
    const char* arguments; ///< writes {dir}/notes.txt; {dir} is the test's directory
    const char* kind;      ///< what the message says the command writes

    friend void PrintTo(const OverwriteCase& row, std::ostream* out) {
        *out << "eposp " << row.arguments;
    }
};

class ExistingFileOfAnotherKind : public testing::TestWithParam<OverwriteCase> {};

// A typo in an output name must not destroy a file the command did not write.
TEST_P(ExistingFileOfAnotherKind, IsKeptWithoutForce) {
    write_source("counter.st", kRetainCounter);
    const auto notes = write_source("notes.txt", kNotes);
    const auto result = eposp(in_scratch(GetParam().arguments));
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_THAT(result.output, HasSubstr(notes + ": the existing file is not " + GetParam().kind +
                                         "; --force replaces it"));
    EXPECT_EQ(read_file(notes), kNotes);
}

TEST_P(ExistingFileOfAnotherKind, IsReplacedWithForce) {
    write_source("counter.st", kRetainCounter);
    const auto notes = write_source("notes.txt", kNotes);
    const auto result = eposp(in_scratch(GetParam().arguments) + " --force");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(read_file(notes), kNotes);
}

INSTANTIATE_TEST_SUITE_P(
    OutputFiles, ExistingFileOfAnotherKind,
    testing::Values(
        OverwriteCase{"BuildImage", "build {dir}/counter.st -o {dir}/notes.txt", "a program image"},
        OverwriteCase{"RunRetainStore", "run {dir}/counter.st --for 10ms --retain {dir}/notes.txt",
                      "a retain store"},
        OverwriteCase{"RunAxisTrace", "run {dir}/counter.st --for 10ms --trace {dir}/notes.txt",
                      "an axis trace"},
        OverwriteCase{"RunCanLog", "run {dir}/counter.st --for 10ms --can-log {dir}/notes.txt",
                      "a candump log"},
        OverwriteCase{"RunPcap", "run {dir}/counter.st --for 10ms --pcap {dir}/notes.txt",
                      "a pcap file"},
        OverwriteCase{"BusLog", "bus --virtual --for 10ms --log {dir}/notes.txt", "a candump log"},
        OverwriteCase{"BusPcap", "bus --virtual --for 10ms --pcap {dir}/notes.txt", "a pcap file"},
        OverwriteCase{"EdsExport", "eds epos2 -o {dir}/notes.txt", "an EDS or DCF file"}),
    [](const testing::TestParamInfo<OverwriteCase>& row) { return row.param.name; });

TEST(OutputFiles, AnExistingFileOfTheKindWrittenIsReplaced) {
    const std::string source = write_source("counter.st", kRetainCounter);
    const auto image = scratch("counter.epx").string();
    ASSERT_EQ(eposp("build " + source + " -o " + image).exit_code, 0);
    const auto again = eposp("build " + source + " -o " + image);
    EXPECT_EQ(again.exit_code, 0) << again.output;
}

// `eposp dcf` writes several files: none is written when one of them may not be replaced.
TEST(OutputFiles, DcfExportKeepsAFileOfAnotherKindUnderItsNameAndWritesNone) {
    const auto notes = write_source("epos-p.dcf", kNotes);
    const auto directory = scratch("").parent_path().string();
    const std::string command =
        "dcf --network " + kSourceDir + "/examples/two-axis/network.yaml -o " + directory;
    std::filesystem::remove(scratch("can-node2.cdcf"));
    const auto refused = eposp(command);
    EXPECT_EQ(refused.exit_code, 1) << refused.output;
    EXPECT_THAT(refused.output, HasSubstr("the existing file is not an EDS or DCF file"));
    EXPECT_EQ(read_file(notes), kNotes);
    EXPECT_FALSE(std::filesystem::exists(scratch("can-node2.cdcf")));
    const auto forced = eposp(command + " --force");
    EXPECT_EQ(forced.exit_code, 0) << forced.output;
    EXPECT_THAT(read_file(notes), HasSubstr("[DeviceInfo]"));
}

TEST(OutputFiles, NodeParameterFileOfAnotherKindIsKept) {
    const auto notes = write_source("notes.txt", kNotes);
    const auto result = eposp("node --eds " + kSourceDir + "/device/epos-p.eds --node-id 3 " +
                              "--virtual --for 10ms --parameter-file " + notes);
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_THAT(result.output, HasSubstr("the existing file is not a parameter file"));
    EXPECT_EQ(read_file(notes), kNotes);
}

struct DirectoryCase {
    const char* name;
    const char* arguments; ///< {dir}/D, D.yaml, D.eds and D.epx are directories
    const char* message;

    friend void PrintTo(const DirectoryCase& row, std::ostream* out) {
        *out << "eposp " << row.arguments;
    }
};

class DirectoryWhereAFileBelongs : public testing::TestWithParam<DirectoryCase> {};

// Neither an empty file read nor an abort: a user error that says what the path is.
TEST_P(DirectoryWhereAFileBelongs, IsAUserError) {
    write_source("counter.st", kRetainCounter);
    for (const char* directory : {"D", "D.yaml", "D.eds", "D.epx"}) {
        std::filesystem::create_directories(scratch(directory));
    }
    const auto result = eposp(in_scratch(GetParam().arguments));
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_THAT(result.output, HasSubstr(in_scratch(GetParam().message)));
    EXPECT_TRUE(std::filesystem::is_directory(scratch("D.epx"))); // `build D` writes no D.epx
}

INSTANTIATE_TEST_SUITE_P(
    OutputFiles, DirectoryWhereAFileBelongs,
    testing::Values(
        DirectoryCase{"CheckSource", "check {dir}/D",
                      "{dir}/D is a directory, not a Structured Text source"},
        DirectoryCase{"BuildSource", "build {dir}/D",
                      "{dir}/D is a directory, not a Structured Text source"},
        DirectoryCase{"RunImage", "run {dir}/D.epx",
                      "{dir}/D.epx is a directory, not a program image"},
        DirectoryCase{"RunNetwork", "run {dir}/counter.st --network {dir}/D.yaml",
                      "--network {dir}/D.yaml is a directory"},
        DirectoryCase{"RunRetainWarm", "run {dir}/counter.st --retain {dir}/D --start warm",
                      "--retain {dir}/D is a directory, not a retain store"},
        DirectoryCase{"RunRetainCold", "run {dir}/counter.st --retain {dir}/D --for 10ms",
                      "--retain {dir}/D is a directory, not a retain store"},
        DirectoryCase{"NodeEds", "node --eds {dir}/D.eds --node-id 3 --virtual --for 10ms",
                      "--eds {dir}/D.eds is a directory, not an EDS file"},
        DirectoryCase{"DriveConfig", "drive epos2 --config {dir}/D.yaml --virtual --for 1ms",
                      "--config {dir}/D.yaml is a directory"},
        DirectoryCase{"EdsExport", "eds epos2 -o {dir}/D", "-o {dir}/D is a directory"}),
    [](const testing::TestParamInfo<DirectoryCase>& row) { return row.param.name; });

TEST(OutputFiles, NodeParameterFileThatIsADirectoryIsAUserError) {
    const auto directory = scratch("D");
    std::filesystem::create_directories(directory);
    const auto result = eposp("node --eds " + kSourceDir + "/device/epos-p.eds --node-id 3 " +
                              "--virtual --for 10ms --parameter-file " + directory.string());
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_THAT(result.output, HasSubstr("--parameter-file " + directory.string() +
                                         " is a directory, not a parameter file"));
}

TEST(LastResortHandler, AnEscapedExceptionIsAnInternalErrorWithExitTwo) {
    testing::internal::CaptureStderr();
    const int exit_code = cli::with_last_resort_handler([]() -> int {
        throw std::runtime_error("basic_filebuf::underflow error reading the file");
    });
    EXPECT_EQ(exit_code, 2);
    EXPECT_THAT(testing::internal::GetCapturedStderr(),
                HasSubstr("eposp: internal error: basic_filebuf::underflow"));
}

} // namespace
} // namespace eposp::device
