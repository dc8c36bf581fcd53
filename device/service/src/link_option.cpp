#include "eposp/service/link_option.hpp"

#include "eposp/core/tcp_address.hpp"

#include <cerrno>
#include <fmt/format.h>
#include <sys/stat.h>
#include <system_error>

namespace eposp::service {
namespace {

constexpr std::string_view kTcpPrefix = "tcp:";
constexpr std::string_view kExpected = "pty, a serial device path or tcp:ADDR";

} // namespace

core::Result<LinkOption> parse_link_option(std::string_view text) {
    if (text.empty()) {
        return core::Error{fmt::format("no link given: expected {}", kExpected)};
    }
    if (text == "pty") {
        return LinkOption{LinkOption::Kind::Pty, {}};
    }
    if (text.starts_with(kTcpPrefix)) {
        const std::string_view address = text.substr(kTcpPrefix.size());
        if (const auto parsed = core::parse_tcp_address(address); !parsed) {
            return core::Error{fmt::format("{}: {}", text, parsed.error())};
        }
        return LinkOption{LinkOption::Kind::Tcp, std::string(address)};
    }
    const std::string path(text);
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) {
        const int error = errno;
        return core::Error{
            error == ENOENT || error == ENOTDIR
                ? fmt::format("{} does not exist (expected {})", path, kExpected)
                : fmt::format("cannot use {}: {}", path,
                              std::error_code(error, std::generic_category()).message())};
    }
    if (S_ISDIR(status.st_mode)) {
        return core::Error{fmt::format("{} is a directory, not a serial device", path)};
    }
    if (!S_ISCHR(status.st_mode)) {
        return core::Error{fmt::format("{} is not a serial device (expected {})", path, kExpected)};
    }
    return LinkOption{LinkOption::Kind::DevicePath, path};
}

} // namespace eposp::service
