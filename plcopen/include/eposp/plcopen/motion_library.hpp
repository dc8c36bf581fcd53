#pragma once

#include "eposp/plcopen/axis_driver.hpp"
#include "eposp/plcopen/axis_link.hpp"
#include "eposp/plcopen/sdo_requests.hpp"
#include "eposp/vm/native.hpp"

#include <array>
#include <memory>
#include <string>

namespace eposp::plcopen {

/// The PLCopen motion blocks (MC_*) and maxon's MU_* and CAN_* blocks of the EPOS P over one
/// axis link: the ST declarations a
/// program is compiled with, the C++ bodies registered with the VM, and an AxisDriver per axis
/// of the axis table. docs/function-blocks.md documents every block.
class MotionLibrary {
public:
    explicit MotionLibrary(AxisLink& link);
    ~MotionLibrary();
    MotionLibrary(const MotionLibrary&) = delete;
    MotionLibrary& operator=(const MotionLibrary&) = delete;

    /// AXIS_REF, MC_BUFFER_MODE, MC_DIRECTION and the block declarations: the linked library
    /// to pass to compiler::compile().
    static std::string source();
    /// Registers every block's body. The registry must not outlive this library.
    void register_blocks(vm::NativeRegistry& registry);

    AxisDriver& axis(AxisNumber axis) { return *drivers_.at(axis); }
    const AxisDriver& axis(AxisNumber axis) const { return *drivers_.at(axis); }
    AxisLink& link() { return link_; }
    /// SDO transfers the parameter blocks started, until they collect the replies.
    SdoRequests& requests() { return requests_; }
    /// Brings every axis up to date with the link: what runs goes on even while no block of
    /// its axis is called.
    void poll();

private:
    AxisLink& link_;
    SdoRequests requests_;
    std::array<std::unique_ptr<AxisDriver>, kAxisCount> drivers_;
};

} // namespace eposp::plcopen
