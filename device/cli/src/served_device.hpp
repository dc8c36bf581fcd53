#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "service_connection.hpp"

#include <memory>

namespace eposp::device {
class EposPDictionary;
}
namespace eposp::drives::escon2 {
class Escon2Dictionary;
}

namespace eposp::device::cli {

/// The devices whose own objects a service link reaches (NodeId 0).
enum class ServedDevice { EposP, Escon2 };

/// Asks the device at the other end of the link what it is: an ESCON2 says so by its device type
/// (0x1000 = 0x00020192, ESCON2 FW spec 6.2.1); any other answer, or a refusal, is the EPOS P.
/// The error is the link's.
service::ClientResult<ServedDevice> identify_device(ServiceConnection& connection);

/// A dictionary of `device` with its defaults: the types and names of its objects.
class ServedDictionary {
public:
    explicit ServedDictionary(ServedDevice device);
    ~ServedDictionary();
    ServedDictionary(const ServedDictionary&) = delete;
    ServedDictionary& operator=(const ServedDictionary&) = delete;

    const canopen::ObjectDictionary& objects() const;

private:
    std::unique_ptr<EposPDictionary> epos_p_;
    std::unique_ptr<drives::escon2::Escon2Dictionary> escon2_;
};

} // namespace eposp::device::cli
