#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/device/signal_wire.hpp"

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace eposp::vm {
class ProcessImage;
}
namespace eposp::drives::epos2 {
class Epos2Drive;
}
namespace eposp::drives::escon2 {
class Escon2Drive;
}

namespace eposp::device {

/// The network file's wires at work (docs/network.md, "Wires"): every millisecond, on the
/// machine's clock, each input takes the level its wire's output puts out: a digital level, or
/// an analog voltage in mV (a process image word holds it as an INT). Sampling at the EPOS2's
/// control period is all its inputs can see. The process input image is written through its
/// DS-405 objects, as an RPDO writes it: an SDO reads what the wire put there and an input
/// event sees its edge.
class SignalWires {
public:
    /// The simulated drives a wire may name; the network file names only those there are.
    struct Drives {
        std::function<drives::epos2::Epos2Drive&(std::uint8_t port, canopen::NodeId node)> epos2;
        std::function<drives::escon2::Escon2Drive&(const std::string& name)> escon2;
    };

    SignalWires(core::EventLoop& loop, canopen::ObjectDictionary& objects, vm::ProcessImage& image,
                Drives drives);

    /// Wires `wires` (checked by the network file's reader) and, with the first, starts the
    /// sampling.
    void add(const std::vector<SignalWire>& wires);

private:
    struct Connection {
        std::function<std::int32_t()> source;
        std::function<void(std::int32_t)> sink;
    };

    std::function<std::int32_t()> source(const SignalEnd& end);
    std::function<void(std::int32_t)> sink(const SignalEnd& end);
    void sample();
    /// Puts `bytes` at byte `first` of the input image through the objects that hold them,
    /// writing only the entries that change.
    void write_inputs(std::uint32_t first, std::span<const std::uint8_t> bytes);

    core::EventLoop& loop_;
    canopen::ObjectDictionary& objects_;
    vm::ProcessImage& image_;
    Drives drives_;
    std::vector<Connection> connections_;
    core::ScopedTimer timer_;
};

} // namespace eposp::device
