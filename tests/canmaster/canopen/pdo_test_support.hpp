#pragma once

#include "service_bench.hpp"
#include "eposp/can/candump_format.hpp"
#include "eposp/can/frame_timing.hpp"
#include "eposp/canopen/pdo_objects.hpp"
#include "eposp/canopen/pdo_service.hpp"

#include <cstdint>
#include <fmt/format.h>
#include <memory>
#include <string>
#include <vector>

// What the PDO tests share: a dictionary with mappable application objects, configuration
// through remote writes in CiA 301's order, and a node on a virtual bus whose SYNC consumer is
// stood in for by the port's receive handler.

namespace eposp::canopen::testing {

inline constexpr NodeId kNode = 5;

inline SubObject& add_application_object(ObjectDictionary& od, std::uint16_t index, DataType type,
                                         Access access, Bytes value, bool mappable = true) {
    SubObject& sub = od.add_variable(index, "Object", type, access, std::move(value));
    sub.pdo_mappable = mappable;
    return sub;
}

/// CiA 402 objects as the EPOS2 maps them, and objects of every kind the mapping rules treat
/// differently.
inline void add_application_objects(ObjectDictionary& od) {
    const auto rww = Access::ReadWriteOutput;
    const auto ro = Access::ReadOnly;
    const auto rw = Access::ReadWrite;
    add_application_object(od, 0x6040, DataType::Unsigned16, rww, encode(std::uint16_t{0}));
    add_application_object(od, 0x6041, DataType::Unsigned16, ro, encode(std::uint16_t{0}));
    add_application_object(od, 0x6060, DataType::Integer8, rww, encode(std::int8_t{0}));
    add_application_object(od, 0x6061, DataType::Integer8, ro, encode(std::int8_t{0}));
    add_application_object(od, 0x6064, DataType::Integer32, ro, encode(std::int32_t{0}));
    add_application_object(od, 0x606C, DataType::Integer32, ro, encode(std::int32_t{0}));
    add_application_object(od, 0x607A, DataType::Integer32, rww, encode(std::int32_t{0}));
    add_application_object(od, 0x60FF, DataType::Integer32, rww, encode(std::int32_t{0}));
    add_application_object(od, 0x2001, DataType::Boolean, rw, encode(false));
    add_application_object(od, 0x2002, DataType::Unsigned8, rw, encode(std::uint8_t{0}));
    add_application_object(od, 0x2003, DataType::Unsigned16, rw, encode(std::uint16_t{0}));
    add_application_object(od, 0x2004, DataType::Integer32, rw, encode(std::int32_t{0}));
    add_application_object(od, 0x2005, DataType::Unsigned64, rw, encode(std::uint64_t{0}));
    add_application_object(od, 0x2006, DataType::Real32, rw, encode(0.0F));
    add_application_object(od, 0x2007, DataType::Integer8, rw, encode(std::int8_t{0}));
    add_application_object(od, 0x2020, DataType::Unsigned32, rw, encode(std::uint32_t{0}), false);
    add_application_object(od, 0x2021, DataType::VisibleString, rw, encode_string("abc"));
    add_application_object(od, 0x2022, DataType::Unsigned32, Access::WriteOnly,
                           encode(std::uint32_t{0}));
}

/// One PDO's parameters for configure_pdo().
struct PdoSetup {
    PdoSetup(std::uint32_t cob_id_, std::uint8_t transmission_type_,
             std::vector<std::uint32_t> mapping_)
        : cob_id(cob_id_), transmission_type(transmission_type_), mapping(std::move(mapping_)) {}

    std::uint32_t cob_id = 0;
    std::uint8_t transmission_type = kEventDrivenProfile;
    std::vector<std::uint32_t> mapping;
    std::uint16_t inhibit_time = 0;
    std::uint16_t event_timer = 0;
    std::uint8_t sync_start = 0;
};

/// Configures a PDO with remote writes in the order of CiA 301 7.5.2.36: invalidate, clear the
/// mapping, write the entries and their number, then the parameters, then the COB-ID. Returns
/// the first refusal, or None.
inline AbortCode configure_pdo(ObjectDictionary& od, PdoDirection direction, std::size_t number,
                               const PdoSetup& setup) {
    const auto comm = pdo_communication_index(direction, number);
    const auto map = pdo_mapping_index(direction, number);
    const auto old_cob_id = od.get_as<std::uint32_t>(comm, kPdoCobIdSub);
    std::vector<AbortCode> codes;
    codes.push_back(write_as(od, comm, kPdoCobIdSub, old_cob_id | PdoCobId::kInvalid));
    codes.push_back(write_as(od, map, 0, std::uint8_t{0}));
    for (std::size_t i = 0; i < setup.mapping.size(); ++i) {
        codes.push_back(write_as(od, map, static_cast<std::uint8_t>(i + 1), setup.mapping[i]));
    }
    codes.push_back(write_as(od, map, 0, static_cast<std::uint8_t>(setup.mapping.size())));
    codes.push_back(write_as(od, comm, kPdoTransmissionTypeSub, setup.transmission_type));
    if (direction == PdoDirection::Transmit) {
        codes.push_back(write_as(od, comm, kPdoInhibitTimeSub, setup.inhibit_time));
        codes.push_back(write_as(od, comm, kPdoEventTimerSub, setup.event_timer));
        codes.push_back(write_as(od, comm, kPdoSyncStartSub, setup.sync_start));
    }
    codes.push_back(write_as(od, comm, kPdoCobIdSub, setup.cob_id));
    for (const AbortCode code : codes) {
        if (code != AbortCode::None) {
            return code;
        }
    }
    return AbortCode::None;
}

/// When the next frame can start after `sent` (its end of frame plus the intermission), at
/// the bench's 1 Mbit/s, 1 us a bit.
inline core::TimePoint next_start_after(const Sent& sent) {
    const auto frame = can::parse_candump_frame(sent.frame);
    return sent.at + std::chrono::microseconds(can::frame_length(*frame).total());
}

/// When receivers take `sent`: at the end of its EOF.
inline core::TimePoint end_of_frame(const Sent& sent) {
    const auto frame = can::parse_candump_frame(sent.frame);
    return sent.at + std::chrono::microseconds(can::frame_length(*frame).to_end_of_frame());
}

/// A device with PDOs on a ServiceBench. The device port's receive handler stands in for the
/// node: SYNC frames (0x080) go to on_sync() with their counter, every frame to on_frame().
struct PdoNode : ServiceBench {
    ObjectDictionary od;
    std::vector<std::uint16_t> emcy;
    std::unique_ptr<PdoService> pdo;

    explicit PdoNode(const PdoObjectsConfig& config = cia301_pdo_defaults(kNode, 4, 4)) {
        add_application_objects(od);
        add_pdo_objects(od, config);
        pdo = std::make_unique<PdoService>(loop, *device, od,
                                           [this](std::uint16_t code) { emcy.push_back(code); });
        device->on_receive([this](const can::Frame& frame) {
            if (frame.id == 0x080 && !frame.extended && !frame.remote) {
                pdo->on_sync(frame.dlc > 0 ? frame.data[0] : 0);
            }
            pdo->on_frame(frame);
        });
    }

    void operational() { pdo->set_nmt_state(NmtState::Operational); }
    /// The tester sends a SYNC, with a counter unless it is 0.
    void sync(std::uint8_t counter = 0) {
        send(counter == 0 ? std::string("080#") : fmt::format("080#{:02X}", counter));
    }
    /// The frames the tester sent, in order.
    std::vector<Sent> tester_frames() const { return sent_by("tester"); }
};

} // namespace eposp::canopen::testing
