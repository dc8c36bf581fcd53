// {attribute 'event' := '…'} on a TASK: the host's event that releases it, carried into the
// image for the host to bind (docs/st-language.md, "Tasks released by device events").
#include "compile_options_harness.hpp"
#include "parse_helpers.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

using testing::HasSubstr;

std::string configuration(const std::string& tasks) {
    return R"(
VAR_GLOBAL trigger : BOOL; END_VAR
PROGRAM Count VAR n : DINT; END_VAR n := n + 1; END_PROGRAM
CONFIGURATION C RESOURCE R ON EPOS_P
)" + tasks +
           R"(
    PROGRAM P WITH T : Count;
END_RESOURCE END_CONFIGURATION
)";
}

TEST(TaskEventAttribute, AttributesAboveATaskReachTheAst) {
    const Parsed parsed = parse_text(configuration(R"(
    {attribute 'event' := 'rpdo internal 1'} (* a comment between *)
    {info 'not an attribute'}
    {ATTRIBUTE 'hide'}
    TASK T (SINGLE := trigger, PRIORITY := 1);)"));
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    const auto& attributes = parsed.unit.configurations[0].resources[0].tasks[0].attributes;
    ASSERT_EQ(attributes.size(), 2u);
    EXPECT_EQ(attributes[0].name, "event");
    EXPECT_EQ(attributes[0].value, "rpdo internal 1");
    EXPECT_EQ(attributes[0].range.begin.line, 6u);
    EXPECT_EQ(attributes[1].name, "hide");
    EXPECT_EQ(attributes[1].value, "");
}

TEST(TaskEventAttribute, AMalformedAttributeIsIgnoredWithAWarning) {
    const Parsed parsed = parse_text(configuration(R"(
    {attribute event := 'sync'}
    TASK T (SINGLE := trigger, PRIORITY := 1);)"));
    EXPECT_FALSE(parsed.diagnostics.has_errors());
    EXPECT_THAT(parsed.rendered(), HasSubstr("test.st:6:5: warning: this attribute is ignored"));
    EXPECT_TRUE(parsed.unit.configurations[0].resources[0].tasks[0].attributes.empty());
}

TEST(TaskEventAttribute, ATaskWithOnlyAnEventIsAnEventTaskWithoutSingle) {
    OptionsCompilation compilation;
    compilation.add("main.st", configuration(R"(
    {attribute 'event' := 'sync'}
    TASK T (PRIORITY := 0);)"));
    ASSERT_TRUE(compilation.compile()) << compilation.errors();
    const vm::Task& task = compilation.image().tasks[0];
    EXPECT_EQ(task.kind, vm::TaskKind::Event);
    EXPECT_EQ(task.event, "sync");
    EXPECT_FALSE(task.event_offset);
    EXPECT_EQ(task.interval_ns, 0u);
}

TEST(TaskEventAttribute, SingleAndAnEventBothReleaseTheTask) {
    OptionsCompilation compilation;
    compilation.add("main.st", configuration(R"(
    {attribute 'event' := 'emcy 5'}
    TASK T (SINGLE := trigger, PRIORITY := 0);)"));
    ASSERT_TRUE(compilation.compile()) << compilation.errors();
    const vm::Task& task = compilation.image().tasks[0];
    EXPECT_EQ(task.kind, vm::TaskKind::Event);
    EXPECT_EQ(task.event, "emcy 5");
    EXPECT_TRUE(task.event_offset);
}

TEST(TaskEventAttribute, TheHostJudgesTheEventAtTheAttribute) {
    OptionsCompilation compilation;
    compilation.add("main.st", configuration(R"(
    {attribute 'event' := 'rpdo 99'}
    TASK T (PRIORITY := 0);)"));
    CompileOptions options;
    options.task_event_check = [](std::string_view text) -> std::optional<std::string> {
        return text == "sync" ? std::nullopt : std::optional<std::string>("only sync here");
    };
    EXPECT_FALSE(compilation.compile(options));
    EXPECT_THAT(compilation.errors(),
                HasSubstr("main.st:6:5: error: event 'rpdo 99': only sync here"));
}

TEST(TaskEventAttribute, AnEventTaskIsNotCyclicAndNamesOneEvent) {
    for (const auto& [tasks, message] : std::vector<std::pair<std::string, std::string>>{
             {"{attribute 'event' := 'sync'} TASK T (INTERVAL := T#1ms, PRIORITY := 0);",
              "task 'T' has an INTERVAL: a task released by an event is not cyclic"},
             {"{attribute 'event'} TASK T (PRIORITY := 0);",
              "the attribute names the event: {attribute 'event' := 'sync'}"},
             {"{attribute 'event' := 'sync'} {attribute 'event' := 'emcy'} TASK T (PRIORITY := 0);",
              "task 'T' is already released by an event"}}) {
        OptionsCompilation compilation;
        compilation.add("main.st", configuration(tasks));
        EXPECT_FALSE(compilation.compile()) << tasks;
        EXPECT_THAT(compilation.errors(), HasSubstr(message)) << tasks;
    }
}

TEST(TaskEventAttribute, AttributesOfOtherToolsAreLeftAlone) {
    OptionsCompilation compilation;
    compilation.add("main.st", configuration(R"(
    {attribute 'hide'}
    TASK T (INTERVAL := T#5ms, PRIORITY := 0);)"));
    ASSERT_TRUE(compilation.compile()) << compilation.errors();
    EXPECT_EQ(compilation.image().tasks[0].kind, vm::TaskKind::Cyclic);
    EXPECT_EQ(compilation.image().tasks[0].event, "");
}

} // namespace
} // namespace eposp::compiler::test
