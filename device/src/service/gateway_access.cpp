#include "gateway_access.hpp"

#include "../network_port.hpp"

#include <utility>

namespace eposp::device {

GatewayAccess::~GatewayAccess() {
    cancel();
}

void GatewayAccess::cancel() {
    if (!request_) {
        return;
    }
    const auto request = std::exchange(request_, {});
    // Its callback runs and is told to do nothing more.
    const auto alive = std::exchange(alive_, std::make_shared<bool>(true));
    *alive = false;
    port_.sdo().cancel(request);
}

void GatewayAccess::upload(std::uint16_t index, std::uint8_t sub_index, Uploaded done) {
    request_ = port_.sdo().upload(node_, index, sub_index,
                                  [this, alive = alive_, done = std::move(done)](
                                      canopen::AbortCode abort, canopen::Bytes value) {
                                      if (*alive) {
                                          request_ = {};
                                          done(static_cast<std::uint32_t>(abort), std::move(value));
                                      }
                                  });
}

void GatewayAccess::download(std::uint16_t index, std::uint8_t sub_index, canopen::Bytes value,
                             bool sized, Downloaded done) {
    request_ = port_.sdo().download(
        node_, index, sub_index, std::move(value),
        [this, alive = alive_, done = std::move(done)](canopen::AbortCode abort) {
            if (*alive) {
                request_ = {};
                done(static_cast<std::uint32_t>(abort));
            }
        },
        {.size_indicated = sized});
}

canopen::AbortCode GatewayAccess::check_write_size(std::uint16_t, std::uint8_t,
                                                   std::uint32_t length) const {
    // The node's answer comes with the last segment; only the buffer's size is checked here.
    return length > kMaxValue ? canopen::AbortCode::OutOfMemory : canopen::AbortCode::None;
}

} // namespace eposp::device
