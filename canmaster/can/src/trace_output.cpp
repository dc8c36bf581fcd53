#include "eposp/can/trace_output.hpp"

#include "trace_file.hpp"

namespace eposp::can {

TraceOutput::TraceOutput(std::unique_ptr<std::ofstream> file)
    : file_(std::move(file)), stream_(file_.get()) {}

core::Result<TraceOutput> TraceOutput::create(const std::filesystem::path& path) {
    auto file = std::make_unique<std::ofstream>(path, std::ios::binary | std::ios::trunc);
    if (!*file) {
        return file_error("create", path);
    }
    return TraceOutput(std::move(file));
}

void TraceOutput::write(std::string_view bytes) {
    stream_->write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    stream_->flush();
}

} // namespace eposp::can
