// The process image and the marker area through a running program: every process-image type
// and IEC address form in and out, outputs published at the end of the cycle, the error
// information the markers give the program, and the safe state of a faulted task's outputs.

#include "runtime_harness.hpp"

namespace eposp::vm::test {
namespace {

using namespace std::chrono_literals;

// Every object of the input image to the output object of the same type, plus one: the first
// and the last entry of each, and a bit.
constexpr const char* kLoopBack = R"(
PROGRAM Main
  VAR
    i8 AT %IB0 : SINT;      o8 AT %QB0 : SINT;
    i8last AT %IB15 : SINT; o8last AT %QB15 : SINT;
    u8 AT %IB16 : BYTE;     ou8 AT %QB16 : BYTE;
    i16 AT %IW16 : INT;     o16 AT %QW16 : INT;
    u16 AT %IW47 : UINT;    ou16 AT %QW47 : UINT;
    i32 AT %ID24 : DINT;    o32 AT %QD24 : DINT;
    u32 AT %ID55 : UDINT;   ou32 AT %QD55 : UDINT;
    bit AT %IX1.3 : BOOL;   obit AT %QX1.3 : BOOL;
  END_VAR
  o8 := i8 + 1;
  o8last := i8last + 1;
  ou8 := u8 + 1;
  o16 := i16 + 1;
  ou16 := u16 + 1;
  o32 := i32 + 1;
  ou32 := u32 + 1;
  obit := NOT bit;
END_PROGRAM
)";

struct EntryCase {
    std::uint16_t input;
    std::uint8_t input_sub;
    std::uint16_t output;
    std::uint8_t output_sub;
    std::int64_t value; ///< written to the input; the output must hold value + 1
};

class ProcessImageMapping : public ::testing::TestWithParam<EntryCase> {};

std::int64_t read_entry(std::span<const std::uint8_t> bytes) {
    std::int64_t value = 0;
    std::memcpy(&value, bytes.data(), bytes.size());
    // Sign-extend from the entry's width.
    const int shift = 64 - 8 * static_cast<int>(bytes.size());
    return shift == 0 ? value : (value << shift) >> shift;
}

TEST_P(ProcessImageMapping, InputEntryReachesTheProgramAndItsResultTheOutputEntry) {
    const EntryCase& c = GetParam();
    RuntimeHarness h;
    ASSERT_EQ(h.load(kLoopBack), "");
    auto input = h.runtime->process_image().entry(c.input, c.input_sub);
    ASSERT_TRUE(input) << input.error();
    std::memcpy(input->data(), &c.value, input->size());
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    auto output = h.runtime->process_image().entry(c.output, c.output_sub);
    ASSERT_TRUE(output) << output.error();
    const std::int64_t expected = read_entry(*input) + 1;
    EXPECT_EQ(read_entry(*output),
              read_entry(std::span<const std::uint8_t>(
                  reinterpret_cast<const std::uint8_t*>(&expected), output->size())));
}

INSTANTIATE_TEST_SUITE_P(
    EveryObject, ProcessImageMapping,
    ::testing::Values(EntryCase{0xA000, 1, 0xA400, 1, -5},                // %IB0 SINT
                      EntryCase{0xA000, 16, 0xA400, 16, 126},             // %IB15
                      EntryCase{0xA040, 1, 0xA4C0, 1, 200},               // %IB16 BYTE
                      EntryCase{0xA0C0, 1, 0xA540, 1, -30000},            // %IW16 INT
                      EntryCase{0xA100, 16, 0xA580, 16, 65000},           // %IW47 UINT
                      EntryCase{0xA1C0, 1, 0xA640, 1, -2'000'000'000},    // %ID24 DINT
                      EntryCase{0xA200, 16, 0xA680, 16, 4'000'000'000})); // %ID55 UDINT

TEST(ProcessImageBits, BitAddressesReadAndWriteOneBitOfTheirByte) {
    RuntimeHarness h;
    ASSERT_EQ(h.load(kLoopBack), "");
    // %IX1.3 is bit 3 of %IB1, entry 2 of 0xA000; %QX1.3 bit 3 of 0xA400 entry 2.
    (*h.runtime->process_image().entry(0xA000, 2))[0] = 0b0000'1000;
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    EXPECT_EQ(h.get<std::uint8_t>("Main.bit"), 1);
    EXPECT_EQ((*h.runtime->process_image().entry(0xA400, 2))[0], 0);
    h.runtime->stop();
    (*h.runtime->process_image().entry(0xA000, 2))[0] = 0b1111'0111;
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    EXPECT_EQ((*h.runtime->process_image().entry(0xA400, 2))[0], 0b0000'1000)
        << "only bit 3 is the program's";
}

TEST(ProcessImageCycle, OutputsAppearAtTheEndOfTheCycleAndInputsAreReadAtItsStart) {
    RuntimeConfig config;
    config.cost.ns_per_instruction = 1000; // the cycle takes milliseconds
    RuntimeHarness h(config);
    ASSERT_EQ(h.load(R"(
PROGRAM Main
  VAR x AT %ID24 : DINT; y AT %QD24 : DINT; k : DINT; END_VAR
  FOR k := 1 TO 1000 DO y := x; END_FOR;
END_PROGRAM
)"),
              "");
    auto input = *h.runtime->process_image().entry(0xA1C0, 1);
    auto output = *h.runtime->process_image().entry(0xA640, 1);
    input[0] = 7;
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.loop.run_for(1ms);
    input[0] = 9; // during the cycle: not seen by it
    EXPECT_EQ(output[0], 0) << "not published before the cycle ends";
    h.loop.run_for(8ms);
    EXPECT_EQ(output[0], 7);
    h.loop.run_for(10ms);
    EXPECT_EQ(output[0], 9);
}

// Busy overruns its 1 ms period (5 ms of work at 1 µs per instruction); Watcher, of higher
// priority, copies the error information and a general-purpose word Busy writes.
constexpr const char* kOverrunWatcher = R"(
PROGRAM Busy
  VAR k : DINT; n : INT; shared AT %MW0 : INT; END_VAR
  FOR k := 1 TO 2000 DO END_FOR;
  n := n + 1;
  shared := n;
END_PROGRAM
PROGRAM Watcher
  VAR
    code AT %MW384 : UINT; count AT %MW385 : UINT; error_task AT %MW386 : UINT;
    overrun_task AT %MW387 : UINT; overruns AT %MW388 : UINT; shared AT %MW0 : INT;
    seen_code : UINT; seen_overruns : UINT; seen_shared : INT;
  END_VAR
  seen_code := code;
  seen_overruns := overruns;
  seen_shared := shared;
  code := 0; (* the error part is the runtime's: this does not reach the markers *)
END_PROGRAM
CONFIGURATION Config0
  RESOURCE Res0 ON PLC
    TASK Slow(INTERVAL := T#1ms, PRIORITY := 2);
    TASK Watch(INTERVAL := T#20ms, PRIORITY := 1);
    PROGRAM BusyInst WITH Slow : Busy;
    PROGRAM WatchInst WITH Watch : Watcher;
  END_RESOURCE
END_CONFIGURATION
)";

TEST(MarkerArea, ProgramsReadTheErrorInformationAndShareGeneralPurposeMarkers) {
    RuntimeConfig config;
    config.cost.ns_per_instruction = 1000;
    RuntimeHarness h(config);
    ASSERT_EQ(h.load(kOverrunWatcher), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.loop.run_for(25ms);
    const auto slow = *h.runtime->task_index("slow");
    EXPECT_GT(h.runtime->statistics(slow).overruns, 0u);
    EXPECT_EQ(h.get<std::uint16_t>("WatchInst.seen_code"), error_code::kTimerTask);
    EXPECT_EQ(h.get<std::uint16_t>("WatchInst.overrun_task"), slow);
    EXPECT_EQ(h.get<std::uint16_t>("WatchInst.error_task"), slow);
    EXPECT_GT(h.get<std::uint16_t>("WatchInst.seen_overruns"), 0);
    EXPECT_GT(h.get<std::int16_t>("WatchInst.seen_shared"), 0);
    // The markers themselves, as the runtime keeps them.
    const auto markers = h.runtime->markers().bytes();
    EXPECT_EQ(markers[marker::kLastErrorCode] | markers[marker::kLastErrorCode + 1] << 8,
              error_code::kTimerTask);
    EXPECT_EQ(h.error_codes().size(),
              static_cast<std::size_t>(markers[marker::kErrorCount] |
                                       markers[marker::kErrorCount + 1] << 8));
}

TEST(TaskFaults, DivisionByZeroIsAnInterpreterErrorAndZeroesOnlyThatTasksOutputs) {
    RuntimeHarness h;
    ASSERT_EQ(h.load(R"(
PROGRAM Good VAR n AT %QW16 : INT; END_VAR n := n + 1; END_PROGRAM
PROGRAM Bad
  VAR n AT %QW17 : INT; zero : INT; END_VAR
  n := n + 1;
  IF n = 3 THEN n := n / zero; END_IF;
END_PROGRAM
CONFIGURATION Config0
  RESOURCE Res0 ON PLC
    TASK A(INTERVAL := T#1ms, PRIORITY := 0);
    TASK B(INTERVAL := T#1ms, PRIORITY := 1);
    PROGRAM G WITH A : Good;
    PROGRAM BadInst WITH B : Bad;
  END_RESOURCE
END_CONFIGURATION
)"),
              "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.loop.run_for(1ms);
    EXPECT_EQ((*h.runtime->process_image().entry(0xA540, 2))[0], 2);
    h.loop.run_for(4ms);
    EXPECT_TRUE(h.runtime->task_faulted(1));
    EXPECT_FALSE(h.runtime->task_faulted(0));
    ASSERT_EQ(h.error_codes(), std::vector<std::uint16_t>{error_code::kInterpreter});
    EXPECT_EQ(h.errors[0].text, "task B stopped: division by zero in Bad at line 6");
    EXPECT_EQ((*h.runtime->process_image().entry(0xA540, 2))[0], 0) << "B's output: safe state";
    EXPECT_EQ((*h.runtime->process_image().entry(0xA540, 1))[0], 6) << "A goes on";
}

TEST(TaskFaults, IndexOutOfRangeIsADataAccessErrorAndHoldKeepsTheOutputs) {
    RuntimeConfig config;
    config.safe_state = SafeState::Hold;
    RuntimeHarness h(config);
    ASSERT_EQ(h.load(R"(
PROGRAM Main
  VAR a : ARRAY[1..3] OF INT; i : INT; out AT %QW16 : INT; END_VAR
  i := i + 1;
  out := i;
  a[i] := i;
END_PROGRAM
)"),
              "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.loop.run_for(50ms);
    EXPECT_TRUE(h.runtime->task_faulted(0));
    EXPECT_EQ(h.error_codes(), std::vector<std::uint16_t>{error_code::kDataAccess});
    EXPECT_EQ((*h.runtime->process_image().entry(0xA540, 1))[0], 3) << "held at the last cycle";
}

TEST(TaskFaults, EachTrapHasItsErrorCode) {
    EXPECT_EQ(error_code_of(Trap::DivisionByZero), 0x6181);
    EXPECT_EQ(error_code_of(Trap::BudgetExceeded), 0x6181);
    EXPECT_EQ(error_code_of(Trap::StackOverflow), 0x6181);
    EXPECT_EQ(error_code_of(Trap::NativeError), 0x6181);
    EXPECT_EQ(error_code_of(Trap::SubrangeViolation), 0x6181);
    EXPECT_EQ(error_code_of(Trap::IndexOutOfRange), 0x6185);
    EXPECT_EQ(error_code_of(Trap::NullDereference), 0x6185);
    EXPECT_EQ(error_code_of(Trap::InvalidAddress), 0x6185);
}

TEST(TaskFaults, EndlessLoopIsStoppedByTheWatchdog) {
    RuntimeConfig config;
    config.watchdog_instructions = 100'000;
    RuntimeHarness h(config);
    ASSERT_EQ(h.load("PROGRAM Main VAR n : DINT; END_VAR WHILE TRUE DO n := n + 1; END_WHILE; "
                     "END_PROGRAM"),
              "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    EXPECT_TRUE(h.runtime->task_faulted(0));
    ASSERT_EQ(h.error_codes(), std::vector<std::uint16_t>{error_code::kInterpreter});
    EXPECT_NE(h.errors[0].text.find("instruction budget exceeded in Main"), std::string::npos);
}

} // namespace
} // namespace eposp::vm::test
