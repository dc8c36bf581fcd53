#pragma once

#include "eposp/vm/coverage_report.hpp"

#include <map>
#include <string>
#include <string_view>

namespace eposp::plctest {

/// `report` as an lcov tracefile (the format of geninfo(1), read by genhtml and by CI coverage
/// viewers): one record per source file with the POUs in it as functions (FN: at their first
/// line with code, FNDA: how often they were entered), their branch outcomes (BRDA:), their
/// lines (DA:) and the totals (FNF/FNH, BRF/BRH, LF/LH). `sources` gives each POU's source
/// file; POUs not in it (a linked library's) are left out. `test_name` becomes TN:, its
/// characters other than letters, digits and '_' replaced by '_', as lcov requires.
std::string lcov_tracefile(const vm::CoverageReport& report,
                           const std::map<std::string, std::string>& sources,
                           std::string_view test_name = "");

} // namespace eposp::plctest
