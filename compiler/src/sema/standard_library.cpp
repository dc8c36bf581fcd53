#include "eposp/compiler/sema/standard_library.hpp"

#include "eposp/compiler/ast/elementary_type.hpp"

#include <array>
#include <string>

namespace eposp::compiler::sema {
namespace {

// Ed. 3, tables 22-36: numeric, bit-shift, selection, comparison, character string functions.
constexpr std::array kStandardFunctions = {
    "ABS",
    "SQRT",
    "LN",
    "LOG",
    "EXP",
    "SIN",
    "COS",
    "TAN",
    "ASIN",
    "ACOS",
    "ATAN",
    "ATAN2",
    "ADD",
    "MUL",
    "SUB",
    "DIV",
    "MOD",
    "EXPT",
    "MOVE",
    "SHL",
    "SHR",
    "ROL",
    "ROR",
    "AND",
    "OR",
    "XOR",
    "NOT",
    "SEL",
    "MAX",
    "MIN",
    "LIMIT",
    "MUX",
    "GT",
    "GE",
    "EQ",
    "LE",
    "LT",
    "NE",
    "LEN",
    "LEFT",
    "RIGHT",
    "MID",
    "CONCAT",
    "INSERT",
    "DELETE",
    "REPLACE",
    "FIND",
    "TRUNC",
    "ADR",
    "SIZEOF", // CODESYS extensions of the pointer kind
              // (POINTER TO is parsed)
    "LOWER_BOUND",
    "UPPER_BOUND", // 6.5.3: the bounds of an ARRAY[*] (or any array)
    // Table 30: time and date functions.
    "ADD_TIME",
    "ADD_TOD_TIME",
    "ADD_DT_TIME",
    "SUB_TIME",
    "SUB_DATE_DATE",
    "SUB_TOD_TIME",
    "SUB_TOD_TOD",
    "SUB_DT_TIME",
    "SUB_DT_DT",
    "MUL_TIME",
    "DIV_TIME",
    "CONCAT_DATE_TOD",
};

struct Parameter {
    std::string_view name;
    ast::VarSectionKind section;
    std::string_view type;
};

struct StandardFunctionBlock {
    std::string name;
    std::vector<Parameter> parameters;
};

constexpr auto In = ast::VarSectionKind::Input;
constexpr auto Out = ast::VarSectionKind::Output;

// Ed. 3, tables 43-46: bistables, edge detection, counters, timers.
std::vector<StandardFunctionBlock> standard_function_blocks() {
    std::vector<StandardFunctionBlock> blocks{
        {"SR", {{"S1", In, "BOOL"}, {"R", In, "BOOL"}, {"Q1", Out, "BOOL"}}},
        {"RS", {{"S", In, "BOOL"}, {"R1", In, "BOOL"}, {"Q1", Out, "BOOL"}}},
        {"R_TRIG", {{"CLK", In, "BOOL"}, {"Q", Out, "BOOL"}}},
        {"F_TRIG", {{"CLK", In, "BOOL"}, {"Q", Out, "BOOL"}}},
        {"CTU",
         {{"CU", In, "BOOL"},
          {"R", In, "BOOL"},
          {"PV", In, "INT"},
          {"Q", Out, "BOOL"},
          {"CV", Out, "INT"}}},
        {"CTD",
         {{"CD", In, "BOOL"},
          {"LD", In, "BOOL"},
          {"PV", In, "INT"},
          {"Q", Out, "BOOL"},
          {"CV", Out, "INT"}}},
        {"CTUD",
         {{"CU", In, "BOOL"},
          {"CD", In, "BOOL"},
          {"R", In, "BOOL"},
          {"LD", In, "BOOL"},
          {"PV", In, "INT"},
          {"QU", Out, "BOOL"},
          {"QD", Out, "BOOL"},
          {"CV", Out, "INT"}}},
        {"RTC", {{"IN", In, "BOOL"}, {"PDT", In, "DT"}, {"Q", Out, "BOOL"}, {"CDT", Out, "DT"}}},
        {"TP", {{"IN", In, "BOOL"}, {"PT", In, "TIME"}, {"Q", Out, "BOOL"}, {"ET", Out, "TIME"}}},
        {"TON", {{"IN", In, "BOOL"}, {"PT", In, "TIME"}, {"Q", Out, "BOOL"}, {"ET", Out, "TIME"}}},
        {"TOF", {{"IN", In, "BOOL"}, {"PT", In, "TIME"}, {"Q", Out, "BOOL"}, {"ET", Out, "TIME"}}},
    };
    // The typed counters of table 45 (CTU_DINT…), with the parameters of CTU, CTD and CTUD.
    for (const std::string_view suffix : {"_DINT", "_LINT", "_UDINT", "_ULINT"}) {
        for (std::size_t i = 4; i < 7; ++i) {
            StandardFunctionBlock typed = blocks[i];
            typed.name += suffix;
            for (Parameter& parameter : typed.parameters) {
                if (parameter.type == "INT") {
                    parameter.type = suffix.substr(1);
                }
            }
            blocks.push_back(std::move(typed));
        }
    }
    return blocks;
}

bool is_elementary_name(std::string_view name) {
    return ast::elementary_type_from_name(name).has_value();
}

} // namespace

void declare_standard_library(SemanticModel& model, bool function_blocks) {
    for (const char* name : kStandardFunctions) {
        model.global_scope().declare(
            model.add(Symbol{.kind = SymbolKind::StandardFunction, .name = name}));
    }
    for (const StandardFunctionBlock& block :
         function_blocks ? standard_function_blocks() : std::vector<StandardFunctionBlock>{}) {
        Scope& members = model.add_scope(nullptr);
        for (const Parameter& parameter : block.parameters) {
            members.declare(model.add(Symbol{.kind = SymbolKind::Variable,
                                             .name = std::string(parameter.name),
                                             .section = parameter.section,
                                             .standard_type = parameter.type}));
        }
        model.global_scope().declare(model.add(Symbol{.kind = SymbolKind::StandardFunctionBlock,
                                                      .name = std::string(block.name),
                                                      .members = &members}));
    }
}

bool is_conversion_function(std::string_view name) {
    const std::string folded = fold_case(name);
    const std::string_view view = folded;
    if (view.starts_with("TO_")) {
        return is_elementary_name(view.substr(3));
    }
    const auto separator = view.find("_TO_");
    return separator != std::string_view::npos && is_elementary_name(view.substr(0, separator)) &&
           is_elementary_name(view.substr(separator + 4));
}

} // namespace eposp::compiler::sema
