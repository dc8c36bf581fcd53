#include "eposp/core/durable_file.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <fstream>
#include <iterator>
#include <unistd.h>

namespace eposp::core {
namespace {

Error system_error(std::string_view what, const std::filesystem::path& path) {
    return Error{fmt::format("{} {}: {}", what, path.string(), std::strerror(errno))};
}

// Closes the descriptor on every path out of a function.
class FileDescriptor {
public:
    explicit FileDescriptor(int fd) : fd_(fd) {}
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor() {
        if (fd_ >= 0) {
            ::close(fd_);
        }
    }
    int get() const { return fd_; }
    /// Closes now, so that a failing close (a deferred write error) can be reported.
    bool close() {
        const int fd = fd_;
        fd_ = -1;
        return ::close(fd) == 0;
    }

private:
    int fd_;
};

std::filesystem::path directory_of(const std::filesystem::path& path) {
    return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

std::optional<Error> sync_directory(const std::filesystem::path& path) {
    const std::filesystem::path directory = directory_of(path);
    FileDescriptor fd(::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (fd.get() < 0 || ::fsync(fd.get()) != 0) {
        return system_error("cannot sync the directory", directory);
    }
    return std::nullopt;
}

} // namespace

std::optional<Error> write_file_durably(const std::filesystem::path& path,
                                              std::span<const std::uint8_t> content) {
    std::filesystem::path temporary = path;
    temporary += ".tmp";
    FileDescriptor fd(::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
    if (fd.get() < 0) {
        return system_error("cannot create", temporary);
    }
    std::size_t written = 0;
    while (written < content.size()) {
        const ssize_t n = ::write(fd.get(), content.data() + written, content.size() - written);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            const auto error = system_error("cannot write", temporary);
            ::unlink(temporary.c_str());
            return error;
        }
        written += static_cast<std::size_t>(n);
    }
    if (::fsync(fd.get()) != 0 || !fd.close()) {
        const auto error = system_error("cannot sync", temporary);
        ::unlink(temporary.c_str());
        return error;
    }
    if (::rename(temporary.c_str(), path.c_str()) != 0) {
        const auto error = system_error("cannot replace", path);
        ::unlink(temporary.c_str());
        return error;
    }
    return sync_directory(path);
}

std::optional<Error> remove_file_durably(const std::filesystem::path& path) {
    if (::unlink(path.c_str()) != 0) {
        if (errno == ENOENT) {
            return std::nullopt;
        }
        return system_error("cannot remove", path);
    }
    return sync_directory(path);
}

Result<std::optional<std::vector<std::uint8_t>>> read_whole_file(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        if (ec) {
            return Error{fmt::format("cannot read {}: {}", path.string(), ec.message())};
        }
        return std::optional<std::vector<std::uint8_t>>{};
    }
    std::ifstream in(path, std::ios::binary);
    std::vector<std::uint8_t> content{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad() || !in.is_open()) {
        return Error{fmt::format("cannot read {}", path.string())};
    }
    return std::optional<std::vector<std::uint8_t>>{std::move(content)};
}

} // namespace eposp::core
