#include "eposp/device/network_file.hpp"

#include "eposp/canopen/device_info.hpp"
#include "eposp/canopen/heartbeat_consumer.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/axis_process_data.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/drives/epos2/epos2_dictionary.hpp"
#include "eposp/manager/concise_dcf.hpp"
#include "eposp/manager/network_list.hpp"
#include "eposp/vm/process_image.hpp"
#include "eposp/yaml/reader.hpp"
#include "network_escon2.hpp"
#include "yaml_values.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <utility>

namespace eposp::device {
namespace {

using yaml::Reader;

constexpr std::uint8_t kMaxNodeId = 127;

void read_expected(Reader& in, const YAML::Node& node, NetworkSlave& slave) {
    const auto u32 = [&in](std::uint32_t& field, std::string_view what) {
        return [&in, &field, what](const YAML::Node& value) {
            field = in_range<std::uint32_t>(in, value, what, 0, 0xFFFF'FFFF);
        };
    };
    in.each_key(
        node, "expect",
        {{"device_type", u32(slave.device_type, "expect.device_type")},
         {"vendor_id", u32(slave.identity.vendor_id, "expect.vendor_id")},
         {"product_code", u32(slave.identity.product_code, "expect.product_code")},
         {"revision_number", u32(slave.identity.revision_number, "expect.revision_number")},
         {"serial_number", u32(slave.identity.serial_number, "expect.serial_number")},
         {"configuration_date", u32(slave.configuration_date, "expect.configuration_date")},
         {"configuration_time", u32(slave.configuration_time, "expect.configuration_time")}});
}

// A concise DCF named relative to the network file; its writes replace the axis set-up.
std::vector<manager::ConfigurationWrite> read_concise_dcf(Reader& in, const YAML::Node& value,
                                                          const std::filesystem::path& base) {
    const auto name = in.scalar<std::string>(value, "dcf");
    const std::filesystem::path path = base / name;
    const auto bytes = yaml::read_text(path);
    if (!bytes) {
        in.fail(value, fmt::format("dcf {}: cannot read the file", path.string()));
    }
    auto writes = manager::decode_concise_dcf(
        {reinterpret_cast<const std::uint8_t*>(bytes->data()), bytes->size()});
    if (!writes) {
        in.fail(value, fmt::format("dcf {}: {}", path.string(), writes.error()));
    }
    return std::move(*writes);
}

NetworkSlave read_slave(Reader& in, const YAML::Node& node, const std::filesystem::path& base) {
    NetworkSlave slave;
    bool has_node = false;
    in.each_key(node, "slaves",
                {{"node",
                  [&](const YAML::Node& value) {
                      slave.node_id = in_range<canopen::NodeId>(in, value, "node", 1, kMaxNodeId);
                      has_node = true;
                  }},
                 {"port",
                  [&](const YAML::Node& value) {
                      const auto port = in.scalar<std::string>(value, "port");
                      if (port != "internal" && port != "can") {
                          in.fail(value, "port must be 'internal' (the internal EPOS2) or 'can'");
                      }
                      slave.port = port == "internal" ? kInternalPort : kExternalPort;
                  }},
                 {"kind",
                  [&](const YAML::Node& value) {
                      const auto kind = in.scalar<std::string>(value, "kind");
                      if (kind != "epos2" && kind != "external") {
                          in.fail(value, "kind must be 'epos2' (simulated here) or 'external'");
                      }
                      slave.kind = kind == "epos2" ? NetworkSlave::Kind::Epos2
                                                   : NetworkSlave::Kind::External;
                  }},
                 {"mandatory",
                  [&](const YAML::Node& value) {
                      slave.mandatory = in.scalar<bool>(value, "mandatory");
                  }},
                 {"axis",
                  [&](const YAML::Node& value) {
                      slave.axis = in_range<std::uint8_t>(in, value, "axis", 0, kAxisCount - 1);
                  }},
                 {"heartbeat",
                  [&](const YAML::Node& value) {
                      const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                          duration(in, value, "heartbeat"));
                      if (ms.count() < 0 || ms.count() > 0xFFFF) {
                          in.fail(value, "heartbeat must be 0..65535ms");
                      }
                      slave.heartbeat_ms = static_cast<std::uint16_t>(ms.count());
                  }},
                 {"dcf",
                  [&](const YAML::Node& value) {
                      slave.concise_dcf = read_concise_dcf(in, value, base);
                  }},
                 {"plant",
                  [&](const YAML::Node& value) {
                      slave.plant = read_plant(in, value, base);
                  }},
                 {"expect", [&](const YAML::Node& value) {
                      read_expected(in, value, slave);
                  }}});
    if (!has_node) {
        in.fail(node, "a slave needs its 'node'");
    }
    if (slave.port == kInternalPort &&
        (slave.node_id != 1 || slave.kind != NetworkSlave::Kind::Epos2)) {
        in.fail(node, "the internal slave is the EPOS2 with node 1");
    }
    if (slave.plant && (slave.port == kInternalPort || slave.kind != NetworkSlave::Kind::Epos2)) {
        in.fail(node, "'plant' is for EPOS2s simulated on the CAN bus (the internal EPOS2's axis "
                      "is the device's own)");
    }
    return slave;
}

// "%IX4.2": byte 4, bit 2 of the process input image.
void read_input_bit(Reader& in, const YAML::Node& value, EventBinding& event) {
    const auto bit = parse_input_bit(in.scalar<std::string>(value, "input"));
    if (!bit) {
        in.fail(value, fmt::format("input must be a process input bit %IX0.0 .. %IX{}.7",
                                   vm::kProcessImageSize - 1));
    }
    event.input_byte = bit->first;
    event.input_bit = bit->second;
}

EventBinding read_event(Reader& in, const YAML::Node& node) {
    EventBinding event;
    bool has_source = false;
    std::optional<YAML::Node> rpdo_node;
    in.each_key(node, "events",
                {{"task",
                  [&](const YAML::Node& value) {
                      event.task = in.scalar<std::string>(value, "task");
                  }},
                 {"on",
                  [&](const YAML::Node& value) {
                      static const std::map<std::string, EventBinding::Source> sources = {
                          {"sync", EventBinding::Source::Sync},
                          {"emcy", EventBinding::Source::Emcy},
                          {"rpdo", EventBinding::Source::Rpdo},
                          {"input", EventBinding::Source::Input}};
                      const auto found = sources.find(in.scalar<std::string>(value, "on"));
                      if (found == sources.end()) {
                          in.fail(value, "on must be 'sync', 'emcy', 'rpdo' or 'input'");
                      }
                      event.source = found->second;
                      has_source = true;
                  }},
                 {"port",
                  [&](const YAML::Node& value) {
                      const auto port = in.scalar<std::string>(value, "port");
                      if (port != "internal" && port != "can") {
                          in.fail(value, "port must be 'internal' or 'can'");
                      }
                      event.port = port == "internal" ? kInternalPort : kExternalPort;
                  }},
                 {"node",
                  [&](const YAML::Node& value) {
                      event.node = in_range<canopen::NodeId>(in, value, "node", 1, kMaxNodeId);
                  }},
                 {"rpdo",
                  [&](const YAML::Node& value) {
                      event.rpdo = in_range<std::size_t>(in, value, "rpdo", 1, 32);
                      rpdo_node = value;
                  }},
                 {"input", [&](const YAML::Node& value) {
                      read_input_bit(in, value, event);
                  }}});
    if (event.task.empty() || !has_source) {
        in.fail(node, "an event needs its 'task' and what it is 'on'");
    }
    if (event.source == EventBinding::Source::Rpdo &&
        (event.rpdo == 0 || event.rpdo > last_rpdo(event.port))) {
        in.fail(rpdo_node.value_or(node),
                "an rpdo event needs 'rpdo': 1..32 on the CAN port, 1..4 on the internal one");
    }
    return event;
}

SignalEnd read_signal_end(Reader& in, const YAML::Node& value, std::string_view what) {
    auto end = parse_signal_end(in.scalar<std::string>(value, what));
    if (!end) {
        in.fail(value, fmt::format("{}: {}", what, end.error()));
    }
    return *end;
}

SignalWire read_wire(Reader& in, const YAML::Node& node) {
    std::optional<SignalEnd> from;
    std::optional<SignalEnd> to;
    in.each_key(node, "wires",
                {{"from",
                  [&](const YAML::Node& value) {
                      from = read_signal_end(in, value, "from");
                  }},
                 {"to", [&](const YAML::Node& value) {
                      to = read_signal_end(in, value, "to");
                  }}});
    if (!from || !to) {
        in.fail(node, "a wire needs its 'from' (an output) and its 'to' (an input)");
    }
    const SignalWire wire{*from, *to};
    if (auto problem = wire_problem(wire)) {
        in.fail(node, *problem);
    }
    return wire;
}

// Each drive a wire names is simulated here, and no input has two wires.
void check_wires(Reader& in, const NetworkFile& network,
                 const std::vector<YAML::Node>& wire_nodes) {
    const auto problem = [&network](const SignalEnd& end) -> std::optional<std::string> {
        if (end.device == SignalEnd::Device::Escon2) {
            if (std::ranges::none_of(network.escon2s, [&end](const NetworkEscon2& escon2) {
                    return escon2.name == end.name;
                })) {
                return fmt::format("no ESCON2 is named '{}' (escon2)", end.name);
            }
        } else if (end.device == SignalEnd::Device::Epos2 && end.port == kExternalPort &&
                   std::ranges::none_of(network.slaves, [&end](const NetworkSlave& slave) {
                       return slave.port == kExternalPort && slave.node_id == end.node &&
                              slave.kind == NetworkSlave::Kind::Epos2;
                   })) {
            return fmt::format("node {} is no EPOS2 simulated on the CAN bus (slaves)", end.node);
        }
        return std::nullopt;
    };
    for (std::size_t i = 0; i < network.wires.size(); ++i) {
        const SignalWire& wire = network.wires[i];
        for (const SignalEnd* end : {&wire.from, &wire.to}) {
            if (auto missing = problem(*end)) {
                in.fail(wire_nodes[i], fmt::format("'{}': {}", to_string(*end), *missing));
            }
        }
        for (std::size_t earlier = 0; earlier < i; ++earlier) {
            if (network.wires[earlier].to == wire.to) {
                in.fail(wire_nodes[i], fmt::format("'{}' is wired twice", to_string(wire.to)));
            }
        }
    }
}

NetworkFile read_network(Reader& in, const YAML::Node& root, const std::filesystem::path& base) {
    NetworkFile network;
    std::set<std::pair<std::uint8_t, canopen::NodeId>> nodes;
    std::set<std::uint8_t> axes;
    std::vector<std::pair<NetworkSlave, YAML::Node>> can_slaves;
    std::vector<YAML::Node> wire_nodes;
    in.each_key(
        root, "network",
        {{"node_id",
          [&](const YAML::Node& value) {
              network.node_id = in_range<canopen::NodeId>(in, value, "node_id", 1, 127);
          }},
         {"bit_rate",
          [&](const YAML::Node& value) {
              network.bit_rate = in_range<std::uint32_t>(in, value, "bit_rate", 1, 1'000'000);
              if (std::ranges::find(canopen::kEdsBaudRatesKbit, network.bit_rate / 1000) ==
                      canopen::kEdsBaudRatesKbit.end() ||
                  network.bit_rate % 1000 != 0) {
                  in.fail(value, "bit_rate must be a CANopen bit rate (10000 ... 1000000)");
              }
          }},
         {"boot_time",
          [&](const YAML::Node& value) {
              network.boot_time = duration(in, value, "boot_time");
              if (network.boot_time < std::chrono::milliseconds(200) ||
                  network.boot_time > std::chrono::milliseconds(30000)) {
                  in.fail(value, "boot_time must be 200ms..30s (0x1F89)");
              }
          }},
         {"sync_period",
          [&](const YAML::Node& value) {
              const core::Duration period = duration(in, value, "sync_period");
              const auto us = std::chrono::duration_cast<std::chrono::microseconds>(period);
              // 10.6: 1 ms and more, in whole microseconds.
              if (period < std::chrono::milliseconds(1) || us != period ||
                  us.count() > 0xFFFF'FFFF) {
                  in.fail(value, "sync_period must be 1ms or more, in whole microseconds (0x1006)");
              }
              network.sync_period = period;
          }},
         {"events",
          [&](const YAML::Node& list) {
              if (!list.IsSequence()) {
                  in.fail(list, "'events' must be a list");
              }
              for (const YAML::Node& node : list) {
                  network.events.push_back(read_event(in, node));
              }
          }},
         {"escon2",
          [&](const YAML::Node& list) {
              if (!list.IsSequence()) {
                  in.fail(list, "'escon2' must be a list");
              }
              for (const YAML::Node& node : list) {
                  NetworkEscon2 escon2 = read_escon2(in, node, base);
                  if (std::ranges::any_of(network.escon2s, [&escon2](const NetworkEscon2& other) {
                          return other.name == escon2.name;
                      })) {
                      in.fail(node,
                              fmt::format("an ESCON2 named '{}' is listed twice", escon2.name));
                  }
                  network.escon2s.push_back(std::move(escon2));
              }
          }},
         {"wires",
          [&](const YAML::Node& list) {
              if (!list.IsSequence()) {
                  in.fail(list, "'wires' must be a list");
              }
              for (const YAML::Node& node : list) {
                  network.wires.push_back(read_wire(in, node));
                  wire_nodes.push_back(node);
              }
          }},
         {"slaves", [&](const YAML::Node& list) {
              if (!list.IsSequence()) {
                  in.fail(list, "'slaves' must be a list");
              }
              for (const YAML::Node& node : list) {
                  NetworkSlave slave = read_slave(in, node, base);
                  if (!nodes.emplace(slave.port, slave.node_id).second) {
                      in.fail(node, fmt::format("node {} is listed twice", slave.node_id));
                  }
                  if (slave.axis && !axes.insert(*slave.axis).second) {
                      in.fail(node, fmt::format("axis {} is served twice", *slave.axis));
                  }
                  if (slave.port == kExternalPort) {
                      can_slaves.emplace_back(slave, node);
                  }
                  network.slaves.push_back(slave);
              }
          }}});
    check_wires(in, network, wire_nodes);
    for (const auto& [slave, node] : can_slaves) {
        if (slave.node_id == network.node_id) {
            in.fail(node, fmt::format("node {} is the EPOS P's own node-ID on the CAN bus "
                                      "(node_id)",
                                      slave.node_id));
        }
        // A real EPOS2 would never find this rate on the bus (table 8-81: 10 kbit/s "not
        // supported"), so a simulated one does not pretend to.
        if (slave.kind == NetworkSlave::Kind::Epos2 &&
            !drives::epos2::bit_rate_code(network.bit_rate)) {
            in.fail(node, fmt::format("node {} is an EPOS2, which cannot run at bit_rate {} "
                                      "(EPOS2 firmware specification, table 8-81)",
                                      slave.node_id, network.bit_rate));
        }
    }
    return network;
}

} // namespace

core::Result<NetworkFile> parse_network_file(std::string_view text, std::string_view source,
                                             const std::filesystem::path& base) {
    return yaml::parse<NetworkFile>(text, source, [&base](Reader& in, const YAML::Node& root) {
        return read_network(in, root, base);
    });
}

core::Result<NetworkFile> load_network_file(const std::filesystem::path& path) {
    auto text = yaml::read_text(path);
    if (!text) {
        return core::Error{text.error()};
    }
    return parse_network_file(*text, path.string(), path.parent_path());
}

void apply_network(const NetworkFile& network, canopen::ObjectDictionary& od) {
    od.set_as<std::uint32_t>(
        0x1F89, 0,
        static_cast<std::uint32_t>(
            std::chrono::duration_cast<std::chrono::milliseconds>(network.boot_time).count()));
    if (network.sync_period) {
        constexpr std::uint32_t kGenerate = 1U << 30; // 10.5, table 6
        od.set_as<std::uint32_t>(
            0x1006, 0,
            static_cast<std::uint32_t>(
                std::chrono::duration_cast<std::chrono::microseconds>(*network.sync_period)
                    .count()));
        od.set_as<std::uint32_t>(0x1005, 0, od.get_as<std::uint32_t>(0x1005, 0) | kGenerate);
    }
    std::uint8_t heartbeat_entry = 0;
    // Each port's axes take its PDOs in the order of the file (257: the first internal one).
    std::size_t next_pdo[] = {0, kFirstInternalPdo, 1};
    for (const NetworkSlave& slave : network.slaves) {
        const std::uint8_t sub =
            slave.port == kInternalPort ? kInternalSlaveSubIndex : slave.node_id;
        std::uint32_t assignment = manager::assignment::kSlave | manager::assignment::kBootSlave;
        if (slave.mandatory) {
            assignment |= manager::assignment::kMandatory;
        }
        od.set_as<std::uint32_t>(0x1F81, sub, assignment);
        od.set_as<std::uint32_t>(0x1F84, sub, slave.device_type);
        od.set_as<std::uint32_t>(0x1F85, sub, slave.identity.vendor_id);
        od.set_as<std::uint32_t>(0x1F86, sub, slave.identity.product_code);
        od.set_as<std::uint32_t>(0x1F87, sub, slave.identity.revision_number);
        od.set_as<std::uint32_t>(0x1F88, sub, slave.identity.serial_number);
        od.set_as<std::uint32_t>(0x1F26, sub, slave.configuration_date);
        od.set_as<std::uint32_t>(0x1F27, sub, slave.configuration_time);
        if (slave.heartbeat_ms != 0) {
            od.set_as<std::uint32_t>(canopen::kConsumerHeartbeatTimeIndex, ++heartbeat_entry,
                                     std::uint32_t{slave.port} << 24 |
                                         std::uint32_t{slave.node_id} << 16 | slave.heartbeat_ms);
        }
        if (slave.axis) {
            od.set_as<std::uint8_t>(static_cast<std::uint16_t>(kAxisIndex + *slave.axis), 1,
                                    slave.port == kInternalPort ? kInternalSlave : slave.node_id);
            configure_axis_pdos(od, next_pdo[slave.port]++, slave.node_id, *slave.axis);
        }
    }
}

} // namespace eposp::device
