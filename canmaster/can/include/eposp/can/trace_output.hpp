#pragma once

#include "eposp/core/result.hpp"

#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <string_view>

namespace eposp::can {

/// Where a trace writer's bytes go: a stream the caller owns (std::cout, a string stream) or a
/// file this output owns. Every write is flushed, so the file is complete on disk while the bus
/// still runs and a run cut short by a signal loses nothing.
class TraceOutput {
public:
    explicit TraceOutput(std::ostream& stream) : stream_(&stream) {}

    /// Creates or truncates `path`, in binary mode.
    static core::Result<TraceOutput> create(const std::filesystem::path& path);

    void write(std::string_view bytes);
    /// False once a write failed (disk full, closed pipe, ...).
    bool good() const { return stream_->good(); }

private:
    explicit TraceOutput(std::unique_ptr<std::ofstream> file);

    std::unique_ptr<std::ofstream> file_;
    std::ostream* stream_;
};

} // namespace eposp::can
