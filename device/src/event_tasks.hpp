#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/device/event_binding.hpp"
#include "eposp/device/plc.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace eposp::device {

class NetworkPort;

/// Releases the program's event tasks on the device's events (docs/network.md, "Events"): the
/// bindings of the network file, which stay for every program, and those the loaded program's
/// TASKs name (`{attribute 'event' := 'sync'}`), replaced at each load.
///
/// A task is found by its name at each event: a program loaded later gets the network file's
/// event if it has an event task of that name, and ignores it otherwise.
class EventTasks final : public Plc::LoadObserver {
public:
    using PortOf = std::function<NetworkPort&(std::uint8_t port)>;
    EventTasks(vm::PlcRuntime& runtime, canopen::ObjectDictionary& objects, PortOf port_of);

    /// A binding of the network file; the loaded program must have the event task it names.
    std::optional<core::Error> bind(EventBinding binding);
    /// The EPOS P sent a SYNC.
    void on_sync();

    /// A program whose TASK names an event the device does not have is refused.
    std::optional<core::Error> check(const vm::Image& image) const override;
    void loaded(const vm::Image& image) override;

private:
    /// Makes sure the device tells this object of the binding's kind of event.
    void listen(const EventBinding& binding);
    void on_emergency(std::uint8_t port, canopen::NodeId node);
    void on_rpdo(std::uint8_t port, std::size_t number);
    void on_input_written();
    /// Releases the task of every binding, the network file's and the program's, that `matches`.
    template <typename Matches>
    void release_where(Matches matches);

    vm::PlcRuntime& runtime_;
    canopen::ObjectDictionary& objects_;
    PortOf port_of_;
    std::vector<EventBinding> network_;
    std::vector<EventBinding> program_;
    std::set<std::pair<std::uint8_t, std::size_t>> rpdos_heard_; ///< (port, RPDO number)
    std::set<std::uint16_t> input_objects_heard_;                ///< 0xA000.. entries
    /// The level after the last write of each input bit that a binding names: an edge is 0 -> 1.
    std::map<std::pair<std::uint32_t, std::uint8_t>, bool> input_levels_;
};

} // namespace eposp::device
