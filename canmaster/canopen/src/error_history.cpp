#include "eposp/canopen/error_history.hpp"

#include <fmt/format.h>
#include <stdexcept>

namespace eposp::canopen {
namespace {

constexpr std::uint8_t kMaxCapacity = 254;

// The entries of 0x1003 live in sub-indices 1..capacity; sub-index 0 counts the used ones.
std::uint8_t capacity_of(const ObjectDictionary& od) {
    const Object* history = od.find(kPreDefinedErrorFieldIndex);
    return history == nullptr || history->subs.empty() ? 0 : history->subs.rbegin()->first;
}

// CiA 301 7.5.2.6: writing 0 to sub-index 0 empties the history; no other value is allowed.
void guard_error_count(ObjectDictionary& od) {
    add_write_rule(od.find(kPreDefinedErrorFieldIndex, 0), DataType::Unsigned8,
                   [&od](std::span<const std::uint8_t> data) {
                       if (decode<std::uint8_t>(data) != 0) {
                           return AbortCode::InvalidValue;
                       }
                       ErrorHistory(od).clear();
                       return AbortCode::None;
                   });
}

} // namespace

void add_error_objects(ObjectDictionary& od, std::uint8_t capacity) {
    if (capacity == 0 || capacity > kMaxCapacity) {
        throw std::invalid_argument("add_error_objects: 0x1003 holds 1..254 entries");
    }
    if (od.find(kErrorRegisterIndex) == nullptr) {
        od.add_variable(kErrorRegisterIndex, "Error Register", DataType::Unsigned8,
                        Access::ReadOnly, encode(std::uint8_t{0}));
    }
    if (od.find(kPreDefinedErrorFieldIndex) == nullptr) {
        Object& history =
            od.add_object(kPreDefinedErrorFieldIndex, "Pre-defined Error Field", ObjectCode::Array);
        for (unsigned sub = 1; sub <= capacity; ++sub) {
            od.add_sub(kPreDefinedErrorFieldIndex, static_cast<std::uint8_t>(sub),
                       fmt::format("Standard Error Field {}", sub), DataType::Unsigned32,
                       Access::ReadOnly, encode(std::uint32_t{0}));
        }
        // Sub-index 0 is the number of errors here, not the highest sub-index (CiA 301 7.5.2,
        // 1003h).
        SubObject& count = history.subs.at(0);
        count.name = "Number of Errors";
        count.access = Access::ReadWrite;
        count.default_value = encode(std::uint8_t{0});
        count.value = count.default_value;
    }
    guard_error_count(od);
}

void ErrorHistory::record(std::uint32_t entry) {
    const std::uint8_t capacity = capacity_of(od_);
    if (capacity == 0) {
        return; // a 0x1003 without entries (an EDS's) records nothing
    }
    const auto count = od_.get_as<std::uint8_t>(kPreDefinedErrorFieldIndex, 0);
    const auto kept = static_cast<std::uint8_t>(count < capacity ? count : capacity - 1);
    for (std::uint8_t sub = kept; sub >= 1; --sub) {
        od_.set(kPreDefinedErrorFieldIndex, static_cast<std::uint8_t>(sub + 1),
                od_.get(kPreDefinedErrorFieldIndex, sub));
    }
    od_.set_as(kPreDefinedErrorFieldIndex, 1, entry);
    od_.set_as(kPreDefinedErrorFieldIndex, 0, static_cast<std::uint8_t>(kept + 1));
}

void ErrorHistory::clear() {
    const std::uint8_t capacity = capacity_of(od_);
    for (unsigned sub = 1; sub <= capacity; ++sub) {
        od_.set_as(kPreDefinedErrorFieldIndex, static_cast<std::uint8_t>(sub), std::uint32_t{0});
    }
    od_.set_as(kPreDefinedErrorFieldIndex, 0, std::uint8_t{0});
}

std::vector<std::uint32_t> ErrorHistory::entries() const {
    const auto count = od_.get_as<std::uint8_t>(kPreDefinedErrorFieldIndex, 0);
    std::vector<std::uint32_t> out;
    for (unsigned sub = 1; sub <= count; ++sub) {
        out.push_back(
            od_.get_as<std::uint32_t>(kPreDefinedErrorFieldIndex, static_cast<std::uint8_t>(sub)));
    }
    return out;
}

std::uint8_t ErrorHistory::error_register() const {
    return od_.get_as<std::uint8_t>(kErrorRegisterIndex, 0);
}

void ErrorHistory::set_error_register(std::uint8_t bits) {
    if (bits != 0 && generic_bit_ == GenericErrorBit::WithEveryError) {
        bits = static_cast<std::uint8_t>(bits | error_register::kGeneric);
    }
    od_.set_as(kErrorRegisterIndex, 0, bits);
}

} // namespace eposp::canopen
