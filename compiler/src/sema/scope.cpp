#include "eposp/compiler/sema/symbol.hpp"

namespace eposp::compiler::sema {

std::string fold_case(std::string_view name) {
    std::string folded(name);
    for (char& c : folded) {
        c = upper_ascii(c);
    }
    return folded;
}

const Symbol* Scope::declare(const Symbol& symbol) {
    const auto [it, inserted] = symbols_.emplace(symbol.name, &symbol);
    return inserted ? nullptr : it->second;
}

const Symbol* Scope::find_member(std::string_view name) const {
    // A depth bound keeps a (diagnosed) EXTENDS cycle from looping.
    int depth = 0;
    for (const Scope* scope = this; scope != nullptr && depth < 64; scope = scope->base_, ++depth) {
        if (const auto it = scope->symbols_.find(name); it != scope->symbols_.end()) {
            return it->second;
        }
    }
    return nullptr;
}

const Symbol* Scope::find(std::string_view name) const {
    for (const Scope* scope = this; scope != nullptr; scope = scope->parent_) {
        if (const Symbol* symbol = scope->find_member(name)) {
            return symbol;
        }
    }
    return nullptr;
}

} // namespace eposp::compiler::sema
