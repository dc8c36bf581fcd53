#include "eposp/manager/boot_error.hpp"

namespace eposp::manager {

std::string_view describe(BootError error) {
    switch (error) {
    case BootError::DeviceType:
        return "Device Type Error";
    case BootError::VendorId:
        return "Vendor-Id Error";
    case BootError::ProductCode:
        return "Product Code Error";
    case BootError::RevisionNumber:
        return "Revision Number Error";
    case BootError::SerialNumber:
        return "Serial Number Error";
    case BootError::ConfigurationDateTime:
        return "Configuration Time and Date Error";
    case BootError::ErrorControl:
        return "Error Control Error";
    case BootError::NotSlave:
        return "Node is not Slave Error";
    case BootError::NoAnswer:
        return "CAN No Answer Error";
    }
    return "unknown boot error";
}

} // namespace eposp::manager
