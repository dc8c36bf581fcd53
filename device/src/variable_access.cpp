#include "variable_access.hpp"

#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/vm/symbol_lookup.hpp"
#include "value_literal.hpp"

#include <algorithm>
#include <string>
#include <variant>

namespace eposp::device {
namespace {

using canopen::AbortCode;

enum Sub : std::uint8_t { kPath = 1, kValue = 2, kForce = 3, kUnforce = 4 };

std::string text_of(std::span<const std::uint8_t> bytes) {
    std::string text(bytes.begin(), bytes.end());
    text.erase(std::find(text.begin(), text.end(), '\0'), text.end()); // a C string's padding
    return text;
}

bool has_program(const Plc& plc) {
    return plc.runtime().state() != vm::ProgramState::NotLoaded;
}

struct Target {
    std::string path;
    vm::VariableLocation location;
};

// The variable sub 1 names, or the code that refuses an access to it.
std::variant<Target, AbortCode> target(const canopen::ObjectDictionary& od, const Plc& plc) {
    if (!has_program(plc)) {
        return AbortCode::DeviceState;
    }
    std::string path = text_of(od.find(kVariableAccessIndex, kPath)->value);
    const auto location = vm::lookup_variable(plc.image(), path);
    if (!location) {
        return AbortCode::TransferOrStore;
    }
    return Target{std::move(path), *location};
}

using Access = std::optional<core::Error> (vm::PlcRuntime::*)(std::string_view,
                                                              std::span<const std::uint8_t>);

// Sub 2 and sub 3: the literal becomes the variable's bytes, set once or forced.
AbortCode put(const canopen::ObjectDictionary& od, Plc& plc, std::span<const std::uint8_t> literal,
              Access access) {
    const auto found = target(od, plc);
    if (const auto* refused = std::get_if<AbortCode>(&found)) {
        return *refused;
    }
    const Target& variable = std::get<Target>(found);
    if (variable.location.read_only) {
        return AbortCode::ReadOnly;
    }
    const auto bytes = parse_value(plc.image().types.at(variable.location.type), text_of(literal));
    if (!bytes) {
        return AbortCode::InvalidValue;
    }
    return (plc.runtime().*access)(variable.path, *bytes) ? AbortCode::InvalidValue
                                                          : AbortCode::None;
}

bool is_forced(const Plc& plc, const vm::VariableLocation& location) {
    return std::ranges::any_of(plc.runtime().forced().forced(), [&](const auto& forced) {
        return forced.offset == location.offset;
    });
}

// The value of the variable sub 1 names, if `only_forced` then only while it is forced.
canopen::Bytes value_of(const canopen::ObjectDictionary& od, const Plc& plc, bool only_forced) {
    const auto found = target(od, plc);
    const auto* variable = std::get_if<Target>(&found);
    if (variable == nullptr || (only_forced && !is_forced(plc, variable->location))) {
        return {};
    }
    const auto value = plc.value_of(variable->path);
    return value ? canopen::encode_string(*value) : canopen::Bytes{};
}

} // namespace

void bind_variable_access(canopen::ObjectDictionary& od, Plc& plc) {
    od.find(kVariableAccessIndex, kPath)->on_write = [&plc](std::span<const std::uint8_t> path) {
        if (!has_program(plc)) {
            return AbortCode::DeviceState;
        }
        return vm::lookup_variable(plc.image(), text_of(path)) ? AbortCode::None
                                                               : AbortCode::InvalidValue;
    };
    canopen::SubObject& value = *od.find(kVariableAccessIndex, kValue);
    value.on_read = [&od, &plc] {
        return value_of(od, plc, false);
    };
    value.on_write = [&od, &plc](std::span<const std::uint8_t> literal) {
        return put(od, plc, literal, &vm::PlcRuntime::write);
    };
    canopen::SubObject& force = *od.find(kVariableAccessIndex, kForce);
    force.on_read = [&od, &plc] {
        return value_of(od, plc, true);
    };
    force.on_write = [&od, &plc](std::span<const std::uint8_t> literal) {
        return put(od, plc, literal, &vm::PlcRuntime::force);
    };
    od.find(kVariableAccessIndex, kUnforce)->on_write = [&od, &plc](std::span<const std::uint8_t>) {
        const auto found = target(od, plc);
        if (const auto* refused = std::get_if<AbortCode>(&found)) {
            return *refused;
        }
        const Target& variable = std::get<Target>(found);
        if (is_forced(plc, variable.location)) {
            plc.runtime().unforce(variable.path);
        }
        return AbortCode::None;
    };
}

} // namespace eposp::device
