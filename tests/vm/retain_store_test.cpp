// Retain variables across power loss: the values come back only from an intact store of the
// same variable layout, and a write cut off at any instant leaves the old or the new values.

#include "eposp/test/test_directory.hpp"
#include "eposp/vm/retain_store.hpp"

#include <csignal>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <random>
#include <sys/wait.h>
#include <unistd.h>

namespace eposp::vm {
namespace {

constexpr std::uint32_t kMemorySize = 64;

Image retain_image() {
    Image image;
    image.static_size = kMemorySize;
    image.static_init.assign(kMemorySize, 0);
    image.retain = {{8, 16}, {40, 8}};
    image.types.push_back(TypeDescriptor{.name = "DINT", .size = 4, .fields = {}});
    image.symbols = {{"Main.a", 0, 8}, {"Main.b", 0, 40}};
    return image;
}

std::filesystem::path store_path(const std::string& name) {
    return test::test_file(name);
}

std::vector<std::uint8_t> memory_filled_with(std::uint8_t value) {
    return std::vector<std::uint8_t>(kMemorySize, value);
}

TEST(RetainStore, FirstStartFindsNoStore) {
    const RetainStore store(store_path("retain.bin"), 1024);
    auto memory = memory_filled_with(0);
    EXPECT_EQ(store.restore(retain_image(), memory).outcome, RetainOutcome::NoStore);
}

TEST(RetainStore, SavedRangesComeBackAndNothingElse) {
    const RetainStore store(store_path("retain.bin"), 1024);
    const Image image = retain_image();
    ASSERT_FALSE(store.save(image, memory_filled_with(0x5A)));
    auto memory = memory_filled_with(0);
    ASSERT_EQ(store.restore(image, memory).outcome, RetainOutcome::Restored);
    for (std::uint32_t at = 0; at < kMemorySize; ++at) {
        const bool retained = (at >= 8 && at < 24) || (at >= 40 && at < 48);
        EXPECT_EQ(memory[at], retained ? 0x5A : 0) << "byte " << at;
    }
}

TEST(RetainStore, DamagedStoreIsRefusedAndMemoryLeftAlone) {
    const RetainStore store(store_path("retain.bin"), 1024);
    const Image image = retain_image();
    ASSERT_FALSE(store.save(image, memory_filled_with(0x5A)));
    {
        std::fstream file(store.file(), std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(20);
        file.put('\x00');
    }
    auto memory = memory_filled_with(7);
    const auto restored = store.restore(image, memory);
    EXPECT_EQ(restored.outcome, RetainOutcome::Corrupt);
    EXPECT_EQ(restored.reason, "retain store checksum mismatch");
    EXPECT_EQ(memory, memory_filled_with(7));
}

TEST(RetainStore, TruncatedAndForeignFilesAreCorrupt) {
    const RetainStore store(store_path("retain.bin"), 1024);
    const Image image = retain_image();
    ASSERT_FALSE(store.save(image, memory_filled_with(1)));
    std::filesystem::resize_file(store.file(), 30);
    auto memory = memory_filled_with(0);
    EXPECT_EQ(store.restore(image, memory).outcome, RetainOutcome::Corrupt);
    std::ofstream(store.file(), std::ios::binary | std::ios::trunc) << "not a store at all";
    EXPECT_EQ(store.restore(image, memory).reason, "not a retain store");
}

TEST(RetainStore, StoreOfAnotherVariableLayoutIsNotRestored) {
    const RetainStore store(store_path("retain.bin"), 1024);
    ASSERT_FALSE(store.save(retain_image(), memory_filled_with(1)));
    Image changed = retain_image();
    changed.symbols[1].offset = 44; // Main.b moved: the stored bytes would land in the wrong place
    auto memory = memory_filled_with(0);
    const auto restored = store.restore(changed, memory);
    EXPECT_EQ(restored.outcome, RetainOutcome::OtherProgram);
    EXPECT_EQ(memory, memory_filled_with(0));
}

TEST(RetainStore, ChangedCodeWithTheSameVariablesKeepsTheValues) {
    const RetainStore store(store_path("retain.bin"), 1024);
    ASSERT_FALSE(store.save(retain_image(), memory_filled_with(3)));
    Image changed = retain_image();
    changed.code.push_back(Instruction{});
    auto memory = memory_filled_with(0);
    EXPECT_EQ(store.restore(changed, memory).outcome, RetainOutcome::Restored);
}

TEST(RetainStore, ProgramWithMoreRetainDataThanTheCapacityIsRefused) {
    const RetainStore store(store_path("retain.bin"), 20);
    const auto error = store.check_capacity(retain_image());
    ASSERT_TRUE(error);
    EXPECT_EQ(error->message,
              "the program declares 24 bytes of RETAIN variables, the controller holds 20");
    EXPECT_FALSE(RetainStore(store.file(), 24).check_capacity(retain_image()));
}

// A child saves the values 1, 2, 3, ... (every retained byte the same value) and reports each
// completed save on a pipe; the parent kills it with SIGKILL right after a random number of
// saves, so the kill lands anywhere inside a later write. The restart must find the last
// completed save or the one that was cut off, all bytes alike.
TEST(RetainStore, PowerLossDuringAWriteLeavesTheOldOrTheNewValues) {
    const RetainStore store(store_path("retain.bin"), 1024);
    const Image image = retain_image();
    std::mt19937 random(20261125);
    constexpr int kTrials = 300;
    for (int trial = 0; trial < kTrials; ++trial) {
        std::filesystem::remove(store.file());
        const int saves_before_kill = std::uniform_int_distribution<int>(1, 4)(random);
        int pipe_fds[2];
        ASSERT_EQ(::pipe(pipe_fds), 0);
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            ::close(pipe_fds[0]);
            for (std::uint8_t value = 1;; ++value) {
                if (store.save(image, memory_filled_with(value))) {
                    ::_exit(2);
                }
                if (::write(pipe_fds[1], &value, 1) != 1) {
                    ::_exit(3);
                }
            }
        }
        ::close(pipe_fds[1]);
        std::uint8_t reported = 0;
        for (int save = 0; save < saves_before_kill; ++save) {
            ASSERT_EQ(::read(pipe_fds[0], &reported, 1), 1);
        }
        ::kill(child, SIGKILL);
        int status = 0;
        ::waitpid(child, &status, 0);
        // The child may have finished more saves before the kill landed: the pipe holds them.
        std::uint8_t later = 0;
        while (::read(pipe_fds[0], &later, 1) == 1) {
            reported = later;
        }
        ::close(pipe_fds[0]);

        auto memory = memory_filled_with(0);
        ASSERT_EQ(store.restore(image, memory).outcome, RetainOutcome::Restored) << trial;
        const std::uint8_t found = memory[8];
        EXPECT_TRUE(found == reported || found == static_cast<std::uint8_t>(reported + 1))
            << "trial " << trial << ": reported " << int{reported} << ", found " << int{found};
        for (const RetainRange& range : image.retain) {
            for (std::uint32_t at = range.offset; at < range.offset + range.size; ++at) {
                ASSERT_EQ(memory[at], found) << "a mix of two saves in trial " << trial;
            }
        }
    }
}

} // namespace
} // namespace eposp::vm
