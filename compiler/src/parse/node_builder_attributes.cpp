// CODESYS attribute pragmas: `{attribute 'name'}` and `{attribute 'name' := 'value'}` above a
// declaration. Other pragmas ({info ...}, {warning ...}) mean nothing here and are passed over.

#include "node_builder.hpp"
#include "token_range.hpp"

#include <cctype>
#include <optional>
#include <string_view>

namespace eposp::compiler {

namespace {

class PragmaReader {
public:
    explicit PragmaReader(std::string_view text) : rest_(text) {}

    void skip_spaces() {
        while (!rest_.empty() && std::isspace(static_cast<unsigned char>(rest_.front())) != 0) {
            rest_.remove_prefix(1);
        }
    }
    /// The word at the front, case-insensitively.
    bool take_word(std::string_view word) {
        skip_spaces();
        if (rest_.size() < word.size()) {
            return false;
        }
        for (std::size_t i = 0; i < word.size(); ++i) {
            if (std::tolower(static_cast<unsigned char>(rest_[i])) != word[i]) {
                return false;
            }
        }
        rest_.remove_prefix(word.size());
        return true;
    }
    /// A text in single quotes ('' inside stands for one quote, as in ST strings).
    std::optional<std::string> take_quoted() {
        skip_spaces();
        if (rest_.empty() || rest_.front() != '\'') {
            return std::nullopt;
        }
        std::string text;
        for (std::size_t i = 1; i < rest_.size(); ++i) {
            if (rest_[i] != '\'') {
                text += rest_[i];
            } else if (i + 1 < rest_.size() && rest_[i + 1] == '\'') {
                text += '\'';
                ++i;
            } else {
                rest_.remove_prefix(i + 1);
                return text;
            }
        }
        return std::nullopt;
    }
    bool at_end() {
        skip_spaces();
        return rest_.empty();
    }

private:
    std::string_view rest_;
};

enum class PragmaKind { NotAnAttribute, Attribute, Malformed };

PragmaKind read_attribute(std::string_view pragma, ast::Attribute& attribute) {
    pragma.remove_prefix(1); // '{'
    pragma.remove_suffix(1); // '}'
    PragmaReader reader(pragma);
    if (!reader.take_word("attribute")) {
        return PragmaKind::NotAnAttribute;
    }
    auto name = reader.take_quoted();
    if (!name || name->empty()) {
        return PragmaKind::Malformed;
    }
    attribute.name = std::move(*name);
    if (reader.take_word(":=")) {
        auto value = reader.take_quoted();
        if (!value) {
            return PragmaKind::Malformed;
        }
        attribute.value = std::move(*value);
    }
    return reader.at_end() ? PragmaKind::Attribute : PragmaKind::Malformed;
}

} // namespace

std::vector<ast::Attribute>
NodeBuilder::attributes_before(const std::vector<antlr4::Token*>& tokens, std::size_t index) {
    // The hidden tokens back to the previous token on the default channel, as
    // BufferedTokenStream::getHiddenTokensToLeft finds them.
    std::size_t first = index;
    while (first > 0 && tokens[first - 1]->getChannel() != antlr4::Token::DEFAULT_CHANNEL) {
        --first;
    }
    std::vector<ast::Attribute> attributes;
    for (std::size_t i = first; i < index; ++i) {
        const antlr4::Token* pragma = tokens[i];
        ast::Attribute attribute;
        attribute.range = token_range(file_, *pragma);
        switch (read_attribute(pragma->getText(), attribute)) {
        case PragmaKind::Attribute:
            attributes.push_back(std::move(attribute));
            break;
        case PragmaKind::Malformed:
            warning(DiagnosticCode::W0105, attribute.range,
                    "this attribute is ignored: an attribute reads {attribute "
                    "'name'} or {attribute 'name' := 'value'}");
            break;
        case PragmaKind::NotAnAttribute:
            break;
        }
    }
    return attributes;
}

} // namespace eposp::compiler
