#include "eposp/differential/program_tree.hpp"

#include <stdexcept>
#include <utility>

namespace eposp::differential {
namespace {

void render_block(const Block& block, const std::string& indent, std::string& out);

void render_statement(const Stmt& stmt, const std::string& indent, std::string& out) {
    out += indent;
    for (const auto& segment : stmt.segments) {
        out += segment.text;
        if (!segment.expr.empty()) {
            out += render(segment.expr.front());
        }
        if (!segment.block.empty()) {
            out += '\n';
            render_block(segment.block.front(), indent + "  ", out);
            out += indent;
        }
    }
    out += '\n';
}

void render_block(const Block& block, const std::string& indent, std::string& out) {
    for (const auto& stmt : block) {
        render_statement(stmt, indent, out);
    }
}

std::size_t size_of(const Expr& expr) {
    std::size_t n = 1;
    for (const auto& operand : expr.operands) {
        n += size_of(operand);
    }
    return n;
}

} // namespace

Expr leaf(std::string text, std::string replacement) {
    return Expr{{{std::move(text), -1}}, {}, std::move(replacement)};
}

Expr pattern(const std::string& text, std::vector<Expr> operands, std::string replacement) {
    Expr expr{{}, std::move(operands), std::move(replacement)};
    std::string pending;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '$' && i + 1 < text.size() && text[i + 1] >= '0' && text[i + 1] <= '9') {
            expr.pieces.push_back({std::move(pending), -1});
            pending.clear();
            const int operand = text[++i] - '0';
            if (static_cast<std::size_t>(operand) >= expr.operands.size()) {
                throw std::logic_error("pattern names a missing operand: " + text);
            }
            expr.pieces.push_back({{}, operand});
        } else {
            pending += text[i];
        }
    }
    expr.pieces.push_back({std::move(pending), -1});
    return expr;
}

Stmt statement(const std::string& text, std::vector<Expr> exprs, std::vector<Block> blocks,
               bool droppable) {
    Stmt stmt{{}, droppable};
    std::size_t next_expr = 0;
    std::size_t next_block = 0;
    Stmt::Segment segment;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const bool hole = text[i] == '$' && i + 1 < text.size();
        if (hole && text[i + 1] == 'e') {
            segment.expr.push_back(std::move(exprs.at(next_expr++)));
        } else if (hole && text[i + 1] == 'b') {
            segment.block.push_back(std::move(blocks.at(next_block++)));
        } else {
            segment.text += text[i];
            continue;
        }
        ++i;
        stmt.segments.push_back(std::move(segment));
        segment = {};
    }
    if (next_expr != exprs.size() || next_block != blocks.size()) {
        throw std::logic_error("statement pattern does not use every part: " + text);
    }
    stmt.segments.push_back(std::move(segment));
    return stmt;
}

std::string render(const Expr& expr) {
    std::string out;
    for (const auto& piece : expr.pieces) {
        out += piece.operand < 0 ? piece.text
                                 : render(expr.operands[static_cast<std::size_t>(piece.operand)]);
    }
    return out;
}

std::string render(const Block& block) {
    std::string text;
    render_block(block, "", text);
    // A block that ends a statement leaves an indented empty line behind: drop those.
    std::string out;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        const std::string line = text.substr(start, end - start);
        if (line.find_first_not_of(' ') != std::string::npos) {
            out += line + '\n';
        }
        start = end + 1;
    }
    return out;
}

std::size_t size_of(const Block& block) {
    std::size_t n = 0;
    for (const auto& stmt : block) {
        ++n;
        for (const auto& segment : stmt.segments) {
            for (const auto& expr : segment.expr) {
                n += size_of(expr);
            }
            for (const auto& inner : segment.block) {
                n += size_of(inner);
            }
        }
    }
    return n;
}

} // namespace eposp::differential
