#include "pty_symlink.hpp"

#include <fmt/format.h>
#include <system_error>

namespace eposp::service {
namespace fs = std::filesystem;

namespace {

bool is_stale_pty_link(const fs::path& link) {
    std::error_code error;
    const fs::path target = fs::read_symlink(link, error);
    return !error && target.string().starts_with("/dev/pts/") && !fs::exists(target, error) &&
           !error;
}

} // namespace

core::Result<bool> make_pty_symlink(const fs::path& link, const fs::path& slave) {
    std::error_code error;
    const fs::file_status status = fs::symlink_status(link, error);
    if (fs::exists(status)) {
        if (!fs::is_symlink(status)) {
            return core::Error{
                fmt::format("{} exists and is not a symlink; not replaced", link.string())};
        }
        if (!is_stale_pty_link(link)) {
            return core::Error{
                fmt::format("{} is a symlink to {}, not one left to a pseudo-terminal that is "
                            "gone; not replaced (remove it yourself if it is stale)",
                            link.string(), fs::read_symlink(link, error).string())};
        }
        // A leftover of a run that did not close: put the new link in its place at once.
        const fs::path temporary = fs::path(link).concat(".new");
        fs::remove(temporary, error);
        fs::create_symlink(slave, temporary, error);
        if (!error) {
            fs::rename(temporary, link, error);
        }
        if (error) {
            const std::string reason = error.message();
            fs::remove(temporary, error);
            return core::Error{
                fmt::format("cannot replace the stale symlink {}: {}", link.string(), reason)};
        }
        return true;
    }
    fs::create_symlink(slave, link, error);
    if (error) {
        return core::Error{
            fmt::format("cannot create the symlink {}: {}", link.string(), error.message())};
    }
    return true;
}

void remove_pty_symlink(const fs::path& link, const fs::path& slave) {
    std::error_code error;
    if (fs::read_symlink(link, error) == slave && !error) {
        fs::remove(link, error); // gone meanwhile: nothing left to clean up
    }
}

} // namespace eposp::service
