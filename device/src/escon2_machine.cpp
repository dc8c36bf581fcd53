#include "eposp/device/escon2_machine.hpp"

#include "eposp/yaml/reader.hpp"
#include "network_escon2.hpp"

#include <fmt/format.h>

namespace eposp::device {

core::Result<Escon2Machine> parse_escon2_machine(std::string_view text, std::string_view source,
                                                 const std::filesystem::path& base) {
    return yaml::parse<Escon2Machine>(text, source,
                                      [&base](yaml::Reader& in, const YAML::Node& root) {
                                          return read_escon2_machine(in, root, "escon2", base);
                                      });
}

core::Result<Escon2Machine> load_escon2_machine(const std::filesystem::path& path) {
    auto text = yaml::read_text(path);
    if (!text) {
        return core::Error{text.error()};
    }
    return parse_escon2_machine(*text, path.string(), path.parent_path());
}

core::Result<std::unique_ptr<drives::escon2::Escon2Drive>>
start_escon2(core::EventLoop& loop, const Escon2Machine& machine,
             drives::escon2::Escon2DictionaryConfig dictionary) {
    drives::escon2::Escon2DriveConfig config;
    config.dictionary = std::move(dictionary);
    config.dictionary.hardware = machine.hardware;
    if (machine.plant) {
        config.axis = *machine.plant;
    }
    auto drive = std::make_unique<drives::escon2::Escon2Drive>(loop, std::move(config));
    drive->start();
    for (const Escon2Machine::Parameter& parameter : machine.parameters) {
        if (const canopen::AbortCode refused =
                drive->objects().write(parameter.index, parameter.sub_index, parameter.value);
            refused != canopen::AbortCode::None) {
            return core::Error{fmt::format(
                "0x{:04X} sub {}: the ESCON2 refuses the machine's value after its stored "
                "parameters: {}",
                parameter.index, parameter.sub_index, canopen::describe(refused))};
        }
    }
    return drive;
}

} // namespace eposp::device
