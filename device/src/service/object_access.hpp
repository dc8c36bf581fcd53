#pragma once

#include "eposp/canopen/abort_code.hpp"
#include "eposp/canopen/value_codec.hpp"

#include <cstdint>
#include <functional>

namespace eposp::device {

/// Where the value of a service link's object command lives: a device's own dictionary
/// (DictionaryAccess) or, through the EPOS P's gateway, an object of a node on its CAN bus
/// (GatewayAccess). The object server (ObjectServer) runs the protocol on top of it, the same for
/// both.
class ObjectAccess {
public:
    /// The answer's error code (0, an abort code, a communication error) and the value.
    using Uploaded = std::function<void(std::uint32_t error, canopen::Bytes value)>;
    using Downloaded = std::function<void(std::uint32_t error)>;

    virtual ~ObjectAccess() = default;

    /// Reads the whole value; `done` runs exactly once, possibly at once, unless cancel() comes
    /// first.
    virtual void upload(std::uint16_t index, std::uint8_t sub_index, Uploaded done) = 0;
    /// Writes `value`. `sized`: the value is exactly this long (a segmented write); otherwise it
    /// is a WriteObject's 4 bytes, of which the object takes as many as its type has.
    virtual void download(std::uint16_t index, std::uint8_t sub_index, canopen::Bytes value,
                          bool sized, Downloaded done) = 0;
    /// What an initiated write of `length` bytes is refused with at once (None: it may go on).
    virtual canopen::AbortCode check_write_size(std::uint16_t index, std::uint8_t sub_index,
                                                std::uint32_t length) const = 0;
    /// A segmented write to the object ended before its last byte, for `reason`.
    virtual void write_aborted(std::uint16_t index, std::uint8_t sub_index,
                               canopen::AbortCode reason) = 0;
    /// The request in flight ends without calling back.
    virtual void cancel() = 0;
};

} // namespace eposp::device
