#pragma once

#include "eposp/compiler/diagnostics.hpp"

#include <DefaultErrorStrategy.h>

namespace eposp::compiler {

/// ANTLR's recovery (single-token insertion and deletion, then resynchronisation) with messages
/// in the words of a PLC programmer instead of ANTLR's token-set dumps:
/// "expected ';' after statement", "expected an expression, found 'THEN'".
class SyntaxErrorStrategy : public antlr4::DefaultErrorStrategy {
public:
    SyntaxErrorStrategy(FileId file, Diagnostics& diagnostics);

protected:
    void reportNoViableAlternative(antlr4::Parser* parser,
                                   const antlr4::NoViableAltException& error) override;
    void reportInputMismatch(antlr4::Parser* parser,
                             const antlr4::InputMismatchException& error) override;
    void reportFailedPredicate(antlr4::Parser* parser,
                               const antlr4::FailedPredicateException& error) override;
    void reportUnwantedToken(antlr4::Parser* parser) override;
    void reportMissingToken(antlr4::Parser* parser) override;
    antlr4::Token* singleTokenDeletion(antlr4::Parser* parser) override;

private:
    void report_unexpected(antlr4::Parser* parser, antlr4::Token* token,
                           const antlr4::misc::IntervalSet& expected);

    FileId file_;
    Diagnostics& diagnostics_;
};

} // namespace eposp::compiler
