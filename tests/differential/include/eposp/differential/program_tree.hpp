#pragma once

// A generated ST program as a tree the reducer can shrink: statements that may be dropped and
// expressions that may be replaced by a literal of their type, each rendered back to ST text.
// Everything else (keywords, declarations' syntax, guards that keep the program well-defined) is
// plain text that stays.

#include <cstddef>
#include <string>
#include <vector>

namespace eposp::differential {

/// An expression: text pieces around its operands (`(`, 0, ` + `, 1, `)`); an operand may be
/// named more than once (`MIN(2, LEN(`, 0, `))`).
struct Expr {
    struct Piece {
        std::string text;
        int operand = -1; // >= 0: the operand of that index instead of text
    };
    std::vector<Piece> pieces;
    std::vector<Expr> operands;
    /// The literal this expression may be replaced by while reducing; empty for a guard, an
    /// expression whose value keeps the program well-defined (a divisor, an index).
    std::string replacement;
};

struct Stmt;
using Block = std::vector<Stmt>;

/// A statement or declaration: text, expressions and nested blocks in source order.
struct Stmt {
    struct Segment {
        std::string text;
        std::vector<Expr> expr;   // one expression, or none
        std::vector<Block> block; // one block, or none
    };
    std::vector<Segment> segments;
    /// False for what keeps the program well-defined or compiling whatever else is dropped (a
    /// loop counter's increment).
    bool droppable = true;
};

/// An expression that is one piece of text, replaceable by `replacement` (empty: not at all).
Expr leaf(std::string text, std::string replacement = {});

/// Builds an expression from a pattern where `$0`, `$1`, ... name the operands.
Expr pattern(const std::string& text, std::vector<Expr> operands, std::string replacement);

/// Builds a statement from a pattern where `$e` is the next expression and `$b` the next block.
Stmt statement(const std::string& text, std::vector<Expr> exprs = {},
               std::vector<Block> blocks = {}, bool droppable = true);

std::string render(const Expr& expr);
/// The block as ST source, one statement a line, nested blocks indented.
std::string render(const Block& block);

/// How many statements and expression nodes the block holds (the reducer's progress measure).
std::size_t size_of(const Block& block);

} // namespace eposp::differential
