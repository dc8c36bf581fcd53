#include "served_device.hpp"

#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/drives/escon2/escon2_dictionary.hpp"

namespace eposp::device::cli {

service::ClientResult<ServedDevice> identify_device(ServiceConnection& connection) {
    const auto device_type =
        connection.read_object(service::ObjectAddress{std::nullopt, 0, 0x1000, 0});
    if (!device_type) {
        if (device_type.error().kind != service::ClientError::Kind::Refused) {
            return device_type.error();
        }
        return ServedDevice::EposP;
    }
    return canopen::decode<std::uint32_t>(*device_type) == drives::escon2::kDeviceType
               ? ServedDevice::Escon2
               : ServedDevice::EposP;
}

ServedDictionary::ServedDictionary(ServedDevice device) {
    if (device == ServedDevice::Escon2) {
        escon2_ = std::make_unique<drives::escon2::Escon2Dictionary>(
            drives::escon2::Escon2DictionaryConfig{});
    } else {
        epos_p_ = std::make_unique<EposPDictionary>(EposPDictionaryConfig{});
    }
}

ServedDictionary::~ServedDictionary() = default;

const canopen::ObjectDictionary& ServedDictionary::objects() const {
    return escon2_ ? escon2_->objects() : epos_p_->objects();
}

} // namespace eposp::device::cli
