#pragma once

#include "eposp/core/result.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <yaml-cpp/yaml.h>

// Reading the YAML files users write (an axis, a network) so that every mistake is reported as
// "file:line:col: error: message", as every eposp diagnostic.
namespace eposp::yaml {

/// A mistake at a node of the file; Reader throws it, parse() turns it into the Error.
struct FileError {
    std::string message;
};

class Reader {
public:
    explicit Reader(std::string_view source) : source_(source) {}

    [[noreturn]] void fail(const YAML::Node& node, const std::string& message) const;
    [[noreturn]] void fail(const YAML::Mark& mark, const std::string& message) const;

    /// Calls `read` for each key of the mapping `node`; a key without a reader is an error, and
    /// so is a key given twice (YAML 1.2 3.2.1.1: keys are unique; yaml-cpp keeps both, and the
    /// second would silently win).
    void each_key(const YAML::Node& node, std::string_view section,
                  const std::map<std::string, std::function<void(const YAML::Node&)>>& readers);

    template <typename T>
    T scalar(const YAML::Node& node, std::string_view what) const {
        if (!node.IsScalar()) {
            fail(node, fmt::format("{} must be {}", what, kind_of<T>()));
        }
        try {
            return node.as<T>();
        } catch (const YAML::BadConversion&) {
            fail(node, fmt::format("{} must be {}", what, kind_of<T>()));
        }
    }

private:
    template <typename T>
    static std::string_view kind_of() {
        if constexpr (std::is_same_v<T, bool>) {
            return "true or false";
        } else if constexpr (std::is_integral_v<T>) {
            return "an integer in range";
        } else if constexpr (std::is_floating_point_v<T>) {
            return "a number";
        } else {
            return "a text";
        }
    }

    std::string_view source_;
};

/// The one document of `text`; a second one is an error (a file describes one thing, and
/// YAML::Load would silently ignore the rest).
YAML::Node load_one_document(const Reader& in, std::string_view text);

/// Parses `text` (named `source` in messages) and reads its root with `read`; a YAML syntax
/// error or a mistake `read` reports is the Error.
template <typename T>
core::Result<T> parse(std::string_view text, std::string_view source,
                      const std::function<T(Reader& in, const YAML::Node& root)>& read) {
    Reader in(source);
    try {
        return read(in, load_one_document(in, text));
    } catch (const FileError& error) {
        return core::Error{error.message};
    } catch (const YAML::Exception& error) {
        return core::Error{fmt::format("{}:{}:{}: error: {}", source, error.mark.line + 1,
                                       error.mark.column + 1, error.msg)};
    }
}

/// The whole text of `path`, or "path: error: cannot read the file" (also for a directory).
core::Result<std::string> read_text(const std::filesystem::path& path);

} // namespace eposp::yaml
