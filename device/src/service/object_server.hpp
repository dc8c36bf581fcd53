#pragma once

#include "eposp/service/commands.hpp"
#include "object_access.hpp"

#include <functional>
#include <memory>

namespace eposp::device {

/// The object commands of one service link (maxon EPOS2 communication guide): ReadObject and
/// WriteObject of up to 4 bytes, and segmented transfers of any size in segments of up to 63
/// bytes, with the CANopen abort codes, on whatever dictionary the request's address reaches
/// (an ObjectAccess: the device's own objects, a node behind a gateway). Any device with a
/// `canopen::ObjectDictionary` serves its host with it: the EPOS P on its RS-232 and USB ports,
/// the ESCON2 on its USB port.
///
/// A link runs one segmented transfer at a time; a new initiate ends the one before. A
/// segmented read fetches the whole value at its initiate; a segmented write hands the value on
/// once its last segment is in.
///
/// Every command completes by its callback exactly once, possibly at once; a request in flight
/// when the link is abandoned, or the object dies, never completes.
class ObjectServer {
public:
    using Done = std::function<void(service::Answer answer)>;
    /// The access to a request's object, or the error code that refuses its address.
    struct Resolved {
        std::shared_ptr<ObjectAccess> access;
        std::uint32_t error = service::error::kNone;
    };
    using Resolve = std::function<Resolved(const service::ObjectAddress& address)>;

    /// `segmented_expected`: what a ReadObject of a value longer than 4 bytes answers (the
    /// EPOS P 0x06070012, the ESCON2 0x0F00FFC1).
    ObjectServer(Resolve resolve, std::uint32_t segmented_expected);
    ~ObjectServer();
    ObjectServer(const ObjectServer&) = delete;
    ObjectServer& operator=(const ObjectServer&) = delete;

    void read(const service::ReadObject& request, Done done);
    void write(const service::WriteObject& request, Done done);
    void initiate_read(const service::InitiateSegmentedRead& request, Done done);
    void initiate_write(const service::InitiateSegmentedWrite& request, Done done);
    void read_segment(const service::SegmentRead& request, Done done);
    void write_segment(const service::SegmentWrite& request, Done done);
    /// The host went away: the segmented transfer ends, a request in flight is cancelled.
    void abandon();

private:
    struct Segmented;

    /// Resolves `address` and keeps its access as the one in flight; null with the error answered.
    ObjectAccess* start(const service::ObjectAddress& address, Done& done);
    /// Ends the segmented transfer; an unfinished write tells its object why.
    void end_segmented(canopen::AbortCode reason);

    Resolve resolve_;
    std::uint32_t segmented_expected_;
    std::unique_ptr<Segmented> segmented_;
    /// The access of the last request, cancelled when the link goes.
    std::shared_ptr<ObjectAccess> in_flight_;
};

} // namespace eposp::device
