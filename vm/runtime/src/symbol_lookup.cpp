#include "eposp/vm/symbol_lookup.hpp"

#include <charconv>
#include <string>

namespace eposp::vm {
namespace {

bool same_name(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) {
        return false;
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(a[i])) !=
            std::tolower(static_cast<unsigned char>(b[i]))) {
            return false;
        }
    }
    return true;
}

bool ends_a_name(std::string_view path, std::size_t at) {
    return at == path.size() || path[at] == '.' || path[at] == '[';
}

// The symbol whose path is the longest prefix of `path` ending at a name boundary.
const Symbol* longest_symbol(const Image& image, std::string_view path) {
    const Symbol* best = nullptr;
    for (const auto& symbol : image.symbols) {
        const auto n = symbol.path.size();
        if (n <= path.size() && ends_a_name(path, n) && same_name(path.substr(0, n), symbol.path) &&
            (best == nullptr || n > best->path.size())) {
            best = &symbol;
        }
    }
    return best;
}

// Walks fields and indices from a symbol; what is inside a read-only symbol is read-only too.
class PathWalker {
public:
    PathWalker(const Image& image, std::string_view path, std::size_t at, VariableLocation start)
        : image_(image), path_(path), at_(at), location_(start) {}

    core::Result<VariableLocation> walk() {
        while (at_ < path_.size()) {
            const auto error = path_[at_] == '.' ? field() : path_[at_] == '[' ? indices() : bad();
            if (!error.empty()) {
                return core::Error{error};
            }
        }
        return location_;
    }

private:
    std::string field() {
        const auto begin = ++at_;
        while (at_ < path_.size() && !ends_a_name(path_, at_)) {
            ++at_;
        }
        const auto name = path_.substr(begin, at_ - begin);
        const auto& type = image_.types[location_.type];
        for (const auto& f : type.fields) {
            if (same_name(f.name, name)) {
                location_.offset += f.offset;
                location_.type = f.type;
                location_.read_only = location_.read_only || f.read_only;
                return {};
            }
        }
        return std::string(path_.substr(0, begin - 1)) + " has no field " + std::string(name);
    }

    // `[i]`, `[i, j]` (a multi-dimensional array is an array of arrays) or `[i][j]`.
    std::string indices() {
        const auto array_end = at_;
        do {
            ++at_;
            while (at_ < path_.size() && path_[at_] == ' ') {
                ++at_;
            }
            std::int64_t index = 0;
            const auto [end, ec] =
                std::from_chars(path_.data() + at_, path_.data() + path_.size(), index);
            if (ec != std::errc{}) {
                return "expected an index at position " + std::to_string(at_) + " of " +
                       std::string(path_);
            }
            at_ = static_cast<std::size_t>(end - path_.data());
            const auto& type = image_.types[location_.type];
            if (type.kind != TypeKind::Array) {
                return std::string(path_.substr(0, array_end)) + " is not an array";
            }
            const auto element = index - type.lower;
            if (element < 0 || element >= type.count) {
                return "index " + std::to_string(index) + " outside " + type.name;
            }
            const auto element_size = image_.types[type.element].size;
            location_.offset += static_cast<std::uint32_t>(element) * element_size;
            location_.type = type.element;
            while (at_ < path_.size() && path_[at_] == ' ') {
                ++at_;
            }
        } while (at_ < path_.size() && path_[at_] == ',');
        if (at_ >= path_.size() || path_[at_] != ']') {
            return "missing ] in " + std::string(path_);
        }
        ++at_;
        return {};
    }

    std::string bad() {
        return "unexpected character at position " + std::to_string(at_) + " of " +
               std::string(path_);
    }

    const Image& image_;
    std::string_view path_;
    std::size_t at_;
    VariableLocation location_;
};

} // namespace

core::Result<VariableLocation> lookup_variable(const Image& image, std::string_view path) {
    const auto* symbol = longest_symbol(image, path);
    if (symbol == nullptr) {
        return core::Error{"no variable " + std::string(path)};
    }
    return PathWalker(image, path, symbol->path.size(),
                      {symbol->offset, symbol->type, symbol->read_only})
        .walk();
}

} // namespace eposp::vm
