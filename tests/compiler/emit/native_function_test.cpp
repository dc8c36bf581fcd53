// Native FUNCTIONs (docs/runtime.md "Native functions"): declared without statements in a linked
// library, called at the call site with one CallNative, their bodies in C++; on both engines.

#include "eposp/compiler/compiler.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/native.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"
#include "eposp/vm/symbol_lookup.hpp"

#include <algorithm>
#include <cstring>
#include <gtest/gtest.h>
#include <optional>
#include <string>
#include <vector>

namespace eposp::compiler::test {
namespace {

using vm::Scalar;

constexpr std::string_view kLibrary = R"ST(
TYPE Color : (Red, Green := 5, Blue); END_TYPE

FUNCTION N_ADD : DINT
VAR_INPUT a : DINT; b : DINT := 10; END_VAR
END_FUNCTION

FUNCTION N_MIX : LREAL
VAR_INPUT x : REAL; k : LREAL := 2.0; t : TIME; flag : BOOL; c : Color; w : WORD; END_VAR
END_FUNCTION

FUNCTION N_LOG
VAR_INPUT message : STRING; wide : WSTRING; tag : STRING(10) := 'tag'; END_VAR
END_FUNCTION

FUNCTION N_EQUALS : BOOL
VAR_INPUT Expected, Actual : ANY; Message : STRING; END_VAR
END_FUNCTION

FUNCTION N_SUM : LREAL
VAR_IN_OUT values : ARRAY[*] OF INT; END_VAR
END_FUNCTION

FUNCTION N_JOIN
VAR_IN_OUT texts : ARRAY[*] OF STRING(20); END_VAR
END_FUNCTION

FUNCTION N_WHERE
VAR_INPUT tag : STRING; END_VAR
END_FUNCTION

FUNCTION_BLOCK N_BLOCK
VAR_INPUT tag : INT; END_VAR
END_FUNCTION_BLOCK

FUNCTION N_UNUSED : BOOL
VAR_INPUT x : BOOL; END_VAR
END_FUNCTION
)ST";

struct Compiled {
    std::optional<vm::Image> image;
    std::string diagnostics;
};

Compiled compile_with_library(std::string_view program, std::string_view library = kLibrary) {
    SourceManager sources;
    const FileId file = sources.add("main.st", std::string(program));
    const FileId linked = sources.add("library.st", std::string(library));
    Diagnostics diagnostics;
    Compiled compiled;
    compiled.image = compile(sources, {&file, 1}, diagnostics, {&linked, 1});
    compiled.diagnostics = render(diagnostics, sources);
    return compiled;
}

/// The library's C++ bodies, each call written to `log`.
class NativeFunctions : public testing::TestWithParam<vm::Engine> {
protected:
    NativeFunctions() {
        vm::stdlib::register_standard_library(natives_);
        natives_.add("N_ADD", {true, Scalar::I32, {Scalar::I32, Scalar::I32}},
                     [](vm::NativeArgs& args) {
                         args.set_result(args.get<std::int32_t>(0) + args.get<std::int32_t>(1));
                     });
        natives_.add(
            "N_MIX",
            {true,
             Scalar::F64,
             {Scalar::F32, Scalar::F64, Scalar::I64, Scalar::Bool, Scalar::I16, Scalar::U16}},
            [this](vm::NativeArgs& args) {
                log_.push_back(std::to_string(args.get<std::int64_t>(2)) + " " +
                               std::to_string(args.get<std::uint8_t>(3)) + " " +
                               std::to_string(args.get<std::int16_t>(4)) + " " +
                               std::to_string(args.get<std::uint16_t>(5)));
                args.set_result(args.get<float>(0) * args.get<double>(1));
            });
        natives_.add("N_LOG", {false, Scalar::Bool, {Scalar::Ptr, Scalar::Ptr, Scalar::Ptr}},
                     [this](vm::NativeArgs& args) {
                         log_.push_back(args.text(0) + "|" + args.wide_text(1) + "|" +
                                        args.text(2));
                     });
        natives_.add(
            "N_EQUALS",
            {true, Scalar::Bool, {Scalar::Ptr, Scalar::U32, Scalar::Ptr, Scalar::U32, Scalar::Ptr}},
            [this](vm::NativeArgs& args) {
                const vm::NativeValue expected = args.any(0);
                const vm::NativeValue actual = args.any(2);
                log_.push_back(std::string(vm::native_type_name(expected.type)) + ":" +
                               std::to_string(expected.bytes.size()) + " " +
                               std::string(vm::native_type_name(actual.type)) + ":" +
                               std::to_string(actual.bytes.size()) + " " + args.text(4));
                const bool equal =
                    expected.type == actual.type &&
                    (expected.is_string() ? expected.text() == actual.text()
                                          : std::equal(expected.bytes.begin(), expected.bytes.end(),
                                                       actual.bytes.begin(), actual.bytes.end()));
                args.set_result<std::uint8_t>(equal ? 1 : 0);
            });
        natives_.add("N_SUM", {true, Scalar::F64, {Scalar::Ptr, Scalar::U32}},
                     [this](vm::NativeArgs& args) {
                         const vm::NativeArray values = args.array(0);
                         double sum = 0;
                         for (std::uint32_t i = 0; i < values.count; ++i) {
                             sum += values.at(i).as<std::int16_t>();
                         }
                         log_.push_back(std::string(vm::native_type_name(values.element)) + ":" +
                                        std::to_string(values.element_size) + " " +
                                        std::to_string(values.lower) + ".." +
                                        std::to_string(values.upper()));
                         args.set_result(sum);
                     });
        natives_.add("N_JOIN", {false, Scalar::Bool, {Scalar::Ptr, Scalar::U32}},
                     [this](vm::NativeArgs& args) {
                         const vm::NativeArray texts = args.array(0);
                         std::string joined;
                         for (std::uint32_t i = 0; i < texts.count; ++i) {
                             joined += texts.at(i).text() + ";";
                         }
                         log_.push_back(joined);
                     });
        natives_.add("N_WHERE", {false, Scalar::Bool, {Scalar::Ptr}}, [this](vm::NativeArgs& args) {
            const vm::NativeCallSite site = args.call_site();
            std::string text = args.text(0) + " at " + site.pou + ":" + std::to_string(site.line);
            for (const vm::NativeCallSite& caller : args.callers()) {
                text += " < " + caller.pou + ":" + std::to_string(caller.line);
            }
            log_.push_back(text);
            if (args.text(0) == "fail") {
                args.fail("told to fail");
            }
        });
        natives_.add_block("N_BLOCK", {Scalar::I16}, [this](vm::NativeBlock& block) {
            const vm::NativeCallSite site = block.args().call_site();
            log_.push_back("block " + std::to_string(block.get<std::int16_t>(0)) + " at " +
                           site.pou + ":" + std::to_string(site.line));
        });
    }

    /// Compiles `program` with the library and runs one scan; false (with a failure) if that
    /// did not work.
    bool run(std::string_view program) {
        Compiled compiled = compile_with_library(program);
        if (!compiled.image) {
            ADD_FAILURE() << compiled.diagnostics;
            return false;
        }
        image_ = *compiled.image;
        auto linked = vm::link(std::move(*compiled.image), natives_, GetParam());
        if (!linked) {
            ADD_FAILURE() << linked.error();
            return false;
        }
        program_.emplace(std::move(*linked));
        machine_.emplace(*program_);
        return machine_->run_cycle(0) == vm::RunState::Finished;
    }

    template <typename T>
    T get(const std::string& path) const {
        const auto location = vm::lookup_variable(program_->image(), path);
        T value{};
        if (!location) {
            ADD_FAILURE() << location.error();
            return value;
        }
        std::memcpy(&value, machine_->memory().data() + location->offset, sizeof(T));
        return value;
    }

    /// How many CallNative instructions of import `name` the image has.
    std::size_t native_calls(const std::string& name) const {
        const auto& imports = image_.imports;
        const auto it = std::find_if(imports.begin(), imports.end(),
                                     [&](const vm::NativeImport& i) { return i.name == name; });
        if (it == imports.end()) {
            return 0;
        }
        const auto index = static_cast<std::uint32_t>(it - imports.begin());
        return static_cast<std::size_t>(
            std::count_if(image_.code.begin(), image_.code.end(), [&](const vm::Instruction& ins) {
                return ins.opcode == vm::Opcode::CallNative && ins.a == index;
            }));
    }

    vm::NativeRegistry natives_;
    vm::Image image_;
    std::optional<vm::Program> program_;
    std::optional<vm::Machine> machine_;
    std::vector<std::string> log_;
};

TEST_P(NativeFunctions, ElementaryInputsArePassedByValuePositionallyNamedAndByDefault) {
    ASSERT_TRUE(run(R"ST(
PROGRAM Main
VAR r1, r2, r3 : DINT; m : LREAL; END_VAR
r1 := N_ADD(1, 2);
r2 := N_ADD(a := 5);
r3 := N_ADD(b := 1, a := N_ADD(2, 3)) * 2;
m := N_MIX(x := 1.5, t := T#2ms, flag := TRUE, c := Blue, w := 16#FFFF);
END_PROGRAM
)ST"));
    EXPECT_EQ(get<std::int32_t>("Main.r1"), 3);
    EXPECT_EQ(get<std::int32_t>("Main.r2"), 15);
    EXPECT_EQ(get<std::int32_t>("Main.r3"), 12);
    EXPECT_EQ(get<double>("Main.m"), 3.0);
    EXPECT_EQ(log_, (std::vector<std::string>{"2000000 1 6 65535"}));
    // At the call site: no body of the function in the image.
    EXPECT_EQ(native_calls("N_ADD"), 4U);
    EXPECT_TRUE(std::none_of(image_.pous.begin(), image_.pous.end(),
                             [](const vm::Pou& pou) { return pou.name == "N_ADD"; }));
    const auto& imports = image_.imports;
    const auto add = std::find_if(imports.begin(), imports.end(),
                                  [](const vm::NativeImport& i) { return i.name == "N_ADD"; });
    ASSERT_NE(add, imports.end());
    EXPECT_EQ(add->signature, (vm::NativeSignature{true, Scalar::I32, {Scalar::I32, Scalar::I32}}));
    // A native function never called is not imported.
    EXPECT_EQ(native_calls("N_UNUSED"), 0U);
}

TEST_P(NativeFunctions, StringsArePassedByAddressAndOmittedOnesTakeTheirInitialValue) {
    const std::string long_text(102, 'x');
    ASSERT_TRUE(run("PROGRAM Main\nVAR long : STRING(200) := '" + long_text + R"ST(';
  w : WSTRING := "w$00E4$20AC"; END_VAR
N_LOG('hi', w);
N_LOG(message := CONCAT('a', 'b'), wide := "", tag := 'T');
N_LOG(long, "x");
END_PROGRAM
)ST"));
    ASSERT_EQ(log_.size(), 3U);
    EXPECT_EQ(log_[0], "hi|w\xC3\xA4\xE2\x82\xAC|tag");
    EXPECT_EQ(log_[1], "ab||T");
    EXPECT_EQ(log_[2], long_text + "|x|tag"); // not cut to the input's 80 characters
}

TEST_P(NativeFunctions, AnyInputsTakeTheValueAndItsTypeAndSize) {
    ASSERT_TRUE(run(R"ST(
PROGRAM Main
VAR i : INT := 7; j : INT := 3; s : STRING := 'abc'; c : Color := Green; d : LREAL := 0.5;
    t : TIME := T#1s; w : WSTRING := "w"; e1, e2, e3, e4, e5, e6 : BOOL; END_VAR
e1 := N_EQUALS(i, j + 4, 'ints');
e2 := N_EQUALS(Expected := 'abc', Actual := s, Message := 'strings');
e3 := N_EQUALS(c, Green, 'enums');
e4 := N_EQUALS(d, 0.25, 'reals');
e5 := N_EQUALS(T#1s, t, 'times');
e6 := N_EQUALS("w", w, 'wide');
e1 := e1 AND N_EQUALS(5, TRUE, 'literals');
END_PROGRAM
)ST"));
    EXPECT_FALSE(get<bool>("Main.e1"));
    EXPECT_TRUE(get<bool>("Main.e2"));
    EXPECT_TRUE(get<bool>("Main.e3"));
    EXPECT_FALSE(get<bool>("Main.e4"));
    EXPECT_TRUE(get<bool>("Main.e5"));
    EXPECT_TRUE(get<bool>("Main.e6"));
    ASSERT_EQ(log_.size(), 7U);
    EXPECT_EQ(log_[0], "INT:2 INT:2 ints");
    EXPECT_EQ(log_[1], "STRING:8 STRING:85 strings");
    EXPECT_EQ(log_[2], "INT:2 INT:2 enums");
    EXPECT_EQ(log_[3], "LREAL:8 LREAL:8 reals");
    EXPECT_EQ(log_[4], "TIME:8 TIME:8 times");
    EXPECT_EQ(log_[5], "WSTRING:8 WSTRING:166 wide");
    EXPECT_EQ(log_[6], "DINT:4 BOOL:1 literals");
}

TEST_P(NativeFunctions, ConformantArraysArriveWithElementTypeAndBounds) {
    ASSERT_TRUE(run(R"ST(
PROGRAM Main
VAR a : ARRAY[-1..2] OF INT := [1, 2, 3, 4]; t : ARRAY[1..2] OF STRING(20) := ['x', 'yz'];
    sum : LREAL; END_VAR
sum := N_SUM(a);
N_JOIN(texts := t);
sum := sum + Forward(a);
END_PROGRAM

FUNCTION Forward : LREAL
VAR_IN_OUT v : ARRAY[*] OF INT; END_VAR
Forward := N_SUM(v);
END_FUNCTION
)ST"));
    EXPECT_EQ(get<double>("Main.sum"), 20.0);
    EXPECT_EQ(log_, (std::vector<std::string>{"INT:2 -1..2", "x;yz;", "INT:2 -1..2"}));
}

TEST_P(NativeFunctions, CallSiteNamesThePouAndLineAndTheCallers) {
    ASSERT_TRUE(run(R"ST(
PROGRAM Main
VAR small : Small; big : Big; END_VAR
N_WHERE('main');
small();
big();
END_PROGRAM

FUNCTION_BLOCK Small
N_WHERE('small');
END_FUNCTION_BLOCK

FUNCTION_BLOCK Big
VAR inner : Small; END_VAR
inner();
N_WHERE('big');
END_FUNCTION_BLOCK
)ST"));
    EXPECT_EQ(log_, (std::vector<std::string>{"main at Main:4", "small at Small:10 < Main:5",
                                              "small at Small:10 < Big:15 < Main:6",
                                              "big at Big:16 < Main:6"}));
    // Small's body is copied into Main and Big, Big's is called: both ways are covered.
    const auto main = std::find_if(image_.pous.begin(), image_.pous.end(),
                                   [](const vm::Pou& pou) { return pou.name == "Main"; });
    ASSERT_NE(main, image_.pous.end());
    EXPECT_EQ(main->inlined.size(), 1U);
}

TEST_P(NativeFunctions, ANativeBlocksCallSiteIsItsCallInTheCaller) {
    ASSERT_TRUE(run(R"ST(
PROGRAM Main
VAR b : N_BLOCK; END_VAR
b(tag := 1);
END_PROGRAM
)ST"));
    EXPECT_EQ(log_, (std::vector<std::string>{"block 1 at Main:4"}));
}

TEST_P(NativeFunctions, EnSkipsTheCall) {
    ASSERT_TRUE(run(R"ST(
PROGRAM Main
VAR r1, r2 : DINT := -1; go : BOOL; END_VAR
r1 := N_ADD(EN := go, a := 1);
go := TRUE;
r2 := N_ADD(EN := go, a := 1);
END_PROGRAM
)ST"));
    EXPECT_EQ(get<std::int32_t>("Main.r2"), 11);
    EXPECT_NE(get<std::int32_t>("Main.r1"), 11);
}

TEST_P(NativeFunctions, AFailureStopsTheTaskAtTheCall) {
    EXPECT_FALSE(run(R"ST(
PROGRAM Main
N_WHERE('fail');
END_PROGRAM
)ST"));
    EXPECT_EQ(machine_->describe_fault(0),
              "native function failed: told to fail in Main at line 3");
}

INSTANTIATE_TEST_SUITE_P(BothEngines, NativeFunctions,
                         testing::Values(vm::Engine::Interpreter, vm::Engine::Compiled),
                         [](const testing::TestParamInfo<vm::Engine>& engine) {
                             return engine.param == vm::Engine::Interpreter ? "Interpreter"
                                                                            : "Compiled";
                         });

std::string errors_of(std::string_view program, std::string_view library = kLibrary) {
    return compile_with_library(program, library).diagnostics;
}

constexpr std::string_view kEmptyMain = "PROGRAM Main\nEND_PROGRAM\n";

TEST(NativeFunctionDeclarations, AnUnsupportedParameterIsAnErrorAtTheDeclaration) {
    const std::string errors = errors_of(kEmptyMain, R"ST(
TYPE Pair : STRUCT a, b : INT; END_STRUCT END_TYPE
FUNCTION N_BAD : BOOL
VAR_INPUT p : Pair; END_VAR
VAR_OUTPUT o : INT; END_VAR
VAR_IN_OUT fixed : ARRAY[1..3] OF INT; pairs : ARRAY[*] OF Pair; END_VAR
END_FUNCTION
FUNCTION N_TEXT : STRING
END_FUNCTION
)ST");
    EXPECT_NE(errors.find("library.st:4:11: error: 'p' of the native function 'N_BAD' is a Pair"),
              std::string::npos)
        << errors;
    EXPECT_NE(errors.find("library.st:5:12: error: 'o' of the native function 'N_BAD' is not a "
                          "VAR_INPUT"),
              std::string::npos)
        << errors;
    EXPECT_NE(errors.find("'fixed' of the native function 'N_BAD' is a VAR_IN_OUT"),
              std::string::npos)
        << errors;
    EXPECT_NE(
        errors.find("'pairs' of the native function 'N_BAD' is a VAR_IN_OUT of ARRAY[*] OF Pair"),
        std::string::npos)
        << errors;
    EXPECT_NE(errors.find("the native function 'N_TEXT' returns a STRING[80]"), std::string::npos)
        << errors;
}

TEST(NativeFunctionDeclarations, AnyIsOnlyForTheInputsOfNativeFunctions) {
    const std::string errors = errors_of(R"ST(
PROGRAM Main
VAR x : ANY; END_VAR
END_PROGRAM
FUNCTION NotLinked : BOOL
VAR_INPUT v : ANY; END_VAR
END_FUNCTION
)ST");
    EXPECT_NE(errors.find("main.st:3:9: error: ANY is only allowed for a VAR_INPUT of a native "
                          "function"),
              std::string::npos)
        << errors;
    EXPECT_NE(errors.find("main.st:6:15: error: 'v' is ANY, which only a native function takes"),
              std::string::npos)
        << errors;
}

TEST(NativeFunctionCalls, AnyTakesAnElementaryValueOrAString) {
    const std::string errors = errors_of(R"ST(
PROGRAM Main
VAR a : ARRAY[1..2] OF INT; f : Helper; ok : BOOL; END_VAR
ok := N_EQUALS(a, a, 'arrays');
ok := N_EQUALS(f, f, 'instances');
ok := N_EQUALS(Actual := 1, Message := 'no expected');
END_PROGRAM
FUNCTION_BLOCK Helper
END_FUNCTION_BLOCK
)ST");
    EXPECT_NE(errors.find("main.st:4:16: error: ANY takes an elementary value or a string"),
              std::string::npos)
        << errors;
    EXPECT_NE(errors.find("main.st:5:16: error: ANY takes an elementary value or a string"),
              std::string::npos)
        << errors;
    EXPECT_NE(errors.find("the ANY input 'Expected' of 'N_EQUALS' must be given"),
              std::string::npos)
        << errors;
}

TEST(NativeFunctionCalls, WrongArgumentsAreErrors) {
    const std::vector<std::pair<std::string_view, std::string_view>> cases = {
        {"r := N_ADD(1, 2, 3);", "main.st:3:18: error: too many arguments for 'N_ADD'"},
        {"r := N_ADD(c := 1);", "main.st:3:12: error: 'N_ADD' has no parameter 'c'"},
        {"r := N_ADD(a := 1, a := 2);", "main.st:3:20: error: 'a' is given twice"},
        {"r := N_ADD(a := 'text');", "main.st:3:17: error: "},
        {"x := N_SUM(b);",
         "main.st:3:12: error: VAR_IN_OUT 'values' needs an array of 1 dimension(s) of INT"},
        {"x := N_SUM();", "the VAR_IN_OUT 'values' of 'N_SUM' must be given"},
    };
    for (const auto& [statement, expected] : cases) {
        const std::string errors =
            errors_of("PROGRAM Main\nVAR r : DINT; b : ARRAY[1..2] OF DINT; x : LREAL; END_VAR\n" +
                      std::string(statement) + "\nEND_PROGRAM\n");
        EXPECT_NE(errors.find(expected), std::string::npos) << expected << "\n" << errors;
    }
}

} // namespace
} // namespace eposp::compiler::test
