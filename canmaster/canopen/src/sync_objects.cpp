#include "eposp/canopen/sync_objects.hpp"

#include "eposp/canopen/cob_id.hpp"

namespace eposp::canopen {
namespace {

constexpr std::uint8_t kMaxCounterOverflow = 240;

// CiA 301 7.5.2 (1005h).
AbortCode check_cob_id_sync(const ObjectDictionary& od, bool producer, std::uint32_t value) {
    if (!cob_id_acceptable(value) || ((value & kCobIdGenerate) != 0 && !producer)) {
        return AbortCode::InvalidValue;
    }
    const auto current = od.get_as<std::uint32_t>(kCobIdSyncIndex, 0);
    const bool generating = (current & kCobIdGenerate) != 0 && (value & kCobIdGenerate) != 0;
    if (generating && (current & kCobIdIdentifierBits) != (value & kCobIdIdentifierBits)) {
        return AbortCode::InvalidValue;
    }
    return AbortCode::None;
}

// A time in µs where 0 switches the function off and other values have a device minimum.
SubObject::WriteHook minimum_unless_zero(std::uint32_t minimum) {
    return [minimum](std::span<const std::uint8_t> data) {
        const auto value = decode<std::uint32_t>(data);
        return value != 0 && value < minimum ? AbortCode::ValueTooLow : AbortCode::None;
    };
}

// CiA 301 7.5.2 (1019h).
AbortCode check_counter_overflow(const ObjectDictionary& od, std::uint8_t value) {
    const SubObject* period = od.find(kCommunicationCyclePeriodIndex, 0);
    if (period != nullptr && decode<std::uint32_t>(period->value) != 0) {
        return AbortCode::DeviceState;
    }
    return value == 1 || value > kMaxCounterOverflow ? AbortCode::InvalidValue : AbortCode::None;
}

} // namespace

void add_sync_objects(ObjectDictionary& od, const SyncObjectOptions& options) {
    od.add_variable(kCobIdSyncIndex, "COB-ID SYNC", DataType::Unsigned32, Access::ReadWrite,
                    encode(kSyncCanId))
        .persistent = true;
    if (options.producer) {
        od.add_variable(kCommunicationCyclePeriodIndex, "Communication Cycle Period",
                        DataType::Unsigned32, Access::ReadWrite, encode(std::uint32_t{0}))
            .persistent = true;
        od.add_variable(kSyncCounterOverflowIndex, "Synchronous Counter Overflow Value",
                        DataType::Unsigned8, Access::ReadWrite, encode(std::uint8_t{0}))
            .persistent = true;
    }
    if (options.window) {
        od.add_variable(kSynchronousWindowLengthIndex, "Synchronous Window Length",
                        DataType::Unsigned32, Access::ReadWrite, encode(std::uint32_t{0}))
            .persistent = true;
    }
    enforce_sync_rules(od, options);
}

void enforce_sync_rules(ObjectDictionary& od, const SyncObjectOptions& options) {
    add_write_rule(od.find(kCobIdSyncIndex, 0), DataType::Unsigned32,
                   [&od, producer = options.producer](std::span<const std::uint8_t> data) {
                       return check_cob_id_sync(od, producer, decode<std::uint32_t>(data));
                   });
    add_write_rule(od.find(kCommunicationCyclePeriodIndex, 0), DataType::Unsigned32,
                   minimum_unless_zero(options.min_cycle_period_us));
    add_write_rule(od.find(kSyncCounterOverflowIndex, 0), DataType::Unsigned8,
                   [&od](std::span<const std::uint8_t> data) {
                       return check_counter_overflow(od, decode<std::uint8_t>(data));
                   });
    add_write_rule(od.find(kSynchronousWindowLengthIndex, 0), DataType::Unsigned32,
                   minimum_unless_zero(options.min_window_length_us));
}

} // namespace eposp::canopen
