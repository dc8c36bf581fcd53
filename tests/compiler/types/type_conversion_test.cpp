// The implicit conversions of IEC 61131-3 ed. 3, figure 11: widening only.
#include "eposp/compiler/sema/type_table.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::sema {
namespace {

using E = ast::ElementaryType;

struct Conversion {
    E from;
    E to;
    bool implicit;
};

class ImplicitConversion : public testing::TestWithParam<Conversion> {};

/// Elementary types only: no constant expression to evaluate.
class NoConstants final : public IntegerConstants {
public:
    std::optional<std::int64_t> fold_integer(const ast::Expression&) const override {
        return std::nullopt;
    }
};

TEST_P(ImplicitConversion, FollowsFigure11) {
    SemanticModel model;
    Diagnostics diagnostics;
    const NoConstants constants;
    TypeTable types(
        model, diagnostics, [](std::string_view) { return nullptr; },
        [](const ast::VariableDeclaration&) { return false; }, constants);
    const Conversion& c = GetParam();
    EXPECT_EQ(converts_implicitly(types.elementary(c.from), types.elementary(c.to)), c.implicit)
        << ast::name_of(c.from) << " -> " << ast::name_of(c.to);
}

INSTANTIATE_TEST_SUITE_P(
    Figure11, ImplicitConversion,
    testing::Values(Conversion{E::Sint, E::Int, true}, Conversion{E::Int, E::Dint, true},
                    Conversion{E::Dint, E::Lint, true}, Conversion{E::Int, E::Sint, false},
                    Conversion{E::Lint, E::Dint, false}, Conversion{E::Usint, E::Uint, true},
                    Conversion{E::Usint, E::Int, true}, Conversion{E::Uint, E::Int, false},
                    Conversion{E::Udint, E::Lint, true}, Conversion{E::Dint, E::Udint, false},
                    Conversion{E::Int, E::Real, true}, Conversion{E::Dint, E::Lreal, true},
                    Conversion{E::Dint, E::Real, false}, Conversion{E::Real, E::Lreal, true},
                    Conversion{E::Lreal, E::Real, false}, Conversion{E::Real, E::Dint, false},
                    Conversion{E::Byte, E::Word, true}, Conversion{E::Word, E::Byte, false},
                    Conversion{E::Byte, E::Int, false}, Conversion{E::Int, E::Word, false},
                    Conversion{E::Bool, E::Byte, true}, Conversion{E::Bool, E::Int, false},
                    Conversion{E::Time, E::Ltime, true}, Conversion{E::Ltime, E::Time, false},
                    Conversion{E::Time, E::Dint, false}));

} // namespace
} // namespace eposp::compiler::sema
