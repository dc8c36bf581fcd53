#include "trace_file.hpp"

#include <cerrno>
#include <fmt/format.h>
#include <system_error>

namespace eposp::can {

core::Error file_error(std::string_view verb, const std::filesystem::path& path) {
    // The standard streams leave errno as open(2) set it on every library we build with.
    const std::string reason = std::generic_category().message(errno);
    return core::Error{fmt::format("cannot {} {}: {}", verb, path.string(), reason)};
}

core::Result<std::ifstream> open_trace_file(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        return file_error("open", path);
    }
    return file;
}

} // namespace eposp::can
