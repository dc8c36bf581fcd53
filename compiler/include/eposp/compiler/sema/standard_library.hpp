#pragma once

#include "eposp/compiler/sema/semantic_model.hpp"

#include <string_view>

namespace eposp::compiler::sema {

/// Declares the standard functions and function blocks of IEC 61131-3 ed. 3 (6.6.2.5, 6.6.3.5)
/// in the global scope: names, and for FBs their parameters, which `ton.Q` and `ton(PT := t)`
/// resolve against. Without `function_blocks` only the functions: for the built-in library
/// that implements the FBs in ST (stdlib/standard_library_source.cpp).
void declare_standard_library(SemanticModel& model, bool function_blocks = true);

/// True for the type conversion functions `INT_TO_REAL`, `TO_DINT`… (ed. 3, 6.6.2.5.3), of
/// which there are too many to declare one by one.
bool is_conversion_function(std::string_view name);

} // namespace eposp::compiler::sema
