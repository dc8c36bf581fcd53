// `eposp plot`: an axis trace drawn as an SVG picture, and the inputs it refuses.

#include "eposp/device/axis_plot.hpp"
#include "eposp_command.hpp"

#include <gtest/gtest.h>
#include <sstream>

namespace eposp::device {
namespace {

constexpr std::string_view kTrace =
    "time_s,axis,statusword,mode,target_position,position_demand,actual_position,"
    "velocity_demand,actual_velocity,current_mA,plcopen_state\n"
    "0.000000000,0,1335,1,0,0,0,0,0,0,Standstill\n"
    "0.000000000,1,1335,1,0,0,5,0,0,0,Disabled\n"
    "0.001000000,0,311,1,100,10,9,50,48,120,DiscreteMotion\n"
    "0.001000000,1,1335,1,0,0,5,0,0,0,Disabled\n"
    "0.002000000,0,1335,1,100,100,100,0,0,3,Standstill\n"
    "0.002000000,1,1335,1,0,0,5,0,0,0,ErrorStop\n";

TEST(AxisPlot, ReadsEachAxisOfATrace) {
    std::istringstream in{std::string(kTrace)};
    const auto axes = read_axis_trace(in, "axes.csv");
    ASSERT_TRUE(axes) << axes.error();
    ASSERT_EQ(axes->size(), 2U);
    EXPECT_EQ((*axes)[0].axis, 0);
    EXPECT_EQ((*axes)[0].position, (std::vector<double>{0, 9, 100}));
    EXPECT_EQ((*axes)[0].state[1], "DiscreteMotion");
    EXPECT_EQ((*axes)[1].time_s.size(), 3U);
}

TEST(AxisPlot, DrawsEveryAxisWithItsStates) {
    std::istringstream in{std::string(kTrace)};
    const std::string svg = plot_svg(*read_axis_trace(in, "axes.csv"));
    EXPECT_TRUE(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
    EXPECT_NE(svg.find("axis 1 actual velocity (rpm)"), std::string::npos);
    EXPECT_NE(svg.find("<title>DiscreteMotion</title>"), std::string::npos);
    EXPECT_NE(svg.find("<title>ErrorStop</title>"), std::string::npos);
    EXPECT_EQ(svg.find("nan"), std::string::npos);
    EXPECT_TRUE(svg.ends_with("</svg>\n"));
}

TEST(AxisPlot, ARowThatIsNotATraceRowIsNamedByItsLine) {
    std::istringstream in{std::string(kTrace) + "0.003,0,1335,1,0,0,x,0,0,0,Standstill\n"};
    const auto axes = read_axis_trace(in, "axes.csv");
    ASSERT_FALSE(axes);
    EXPECT_EQ(axes.error(), "axes.csv:8: not a row of the axis trace");
    std::istringstream other{"a,b,c\n1,2,3\n"};
    EXPECT_NE(read_axis_trace(other, "x.csv").error().find("x.csv:1: not an axis trace"),
              std::string::npos);
}

TEST(PlotCommand, DrawsTheTraceOfARun) {
    const auto trace = scratch("axes.csv");
    const auto picture = scratch("axes.svg");
    const std::string example = std::string(EPOSP_SOURCE_DIR) + "/examples/";
    ASSERT_EQ(eposp("run " + example + "pick-and-place/pick-and-place.st --network " + example +
                    "two-axis/network.yaml --for 2s --trace " + trace.string())
                  .exit_code,
              0);
    const auto result = eposp("plot " + trace.string() + " -o " + picture.string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(result.output, picture.string() + ": 2 axes\n");
    const std::string svg = read_file(picture);
    EXPECT_NE(svg.find("<title>DiscreteMotion</title>"), std::string::npos);
    EXPECT_NE(svg.find("<title>Homing</title>"), std::string::npos);
}

TEST(PlotCommand, RefusesWhatItCannotDrawOrMustNotOverwrite) {
    const std::string trace = write_source("axes.csv", std::string(kTrace));
    auto result = eposp("plot " + trace + " -o " + scratch("axes.png").string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.output.find("name it .svg"), std::string::npos) << result.output;

    const std::string renamed = write_source("axes.svg", std::string(kTrace));
    result = eposp("plot " + renamed + " -o " + renamed);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.output.find("would overwrite the input"), std::string::npos) << result.output;
    EXPECT_EQ(read_file(renamed), kTrace);

    result = eposp("plot " + scratch("").string() + " -o " + scratch("d.svg").string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.output.find("is a directory"), std::string::npos) << result.output;

    const std::string garbage = write_source("garbage.csv", "\x01\x02,\xff\n");
    result = eposp("plot " + garbage + " -o " + scratch("g.svg").string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.output.find("not an axis trace"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(scratch("g.svg")));
}

} // namespace
} // namespace eposp::device
