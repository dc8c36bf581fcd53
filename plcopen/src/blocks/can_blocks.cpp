// maxon's CANopen blocks (CAN_*): SDO transfers with any object of any node on either port, and
// NMT commands, for nodes the axis table does not name. Addressed as CiA 405 does, by port and
// node-ID; port 0, node 0 is the EPOS P itself. Non-blocking: a transfer runs over the next
// cycles, and the abort code comes with the error.

#include "execute_block.hpp"

namespace eposp::plcopen::blocks {

namespace {

/// Port : USINT, NodeId : USINT (fields 1 and 2, after Execute).
std::optional<NodeAddress> node_of(vm::NativeBlock& block) {
    const NodeAddress node{block.get<std::uint8_t>(1), block.get<std::uint8_t>(2)};
    const bool own = node.port == 0 && node.node == 0;
    const bool on_bus = (node.port == 1 || node.port == 2) && node.node >= 1 && node.node <= 127;
    return own || on_bus ? std::optional(node) : std::nullopt;
}

BlockInterface sdo_interface(std::string_view name, std::vector<BlockVariable> inputs,
                             std::vector<BlockVariable> results) {
    std::vector<BlockVariable> variables{input("Execute", "BOOL"), input("Port", "USINT"),
                                         input("NodeId", "USINT"), input("Index", "UINT"),
                                         input("SubIndex", "USINT")};
    variables.insert(variables.end(), inputs.begin(), inputs.end());
    const auto outputs = execute_outputs("Done", false);
    variables.insert(variables.end(), outputs.begin(), outputs.end());
    variables.insert(variables.end(), results.begin(), results.end());
    variables.push_back(output("AbortCode", "UDINT"));
    return {name, std::move(variables)};
}

/// CAN_SdoRead and CAN_SdoWrite: start on Execute, finish when the reply comes.
BlockDefinition sdo_block(BlockInterface declared, bool write) {
    const ExecuteOutputs out(declared);
    const std::size_t abort_code = field(declared, "AbortCode");
    const std::size_t data = field(declared, "Data");
    const std::size_t length = field(declared, "DataLength");
    return {std::move(declared), [=](vm::NativeBlock& block, MotionLibrary& library) {
                SdoRequests& requests = library.requests();
                if (out.begin(block)) {
                    block.set<std::uint32_t>(abort_code, 0);
                    const auto node = node_of(block);
                    const auto size = block.get<std::uint8_t>(length);
                    if (!node || (write && (size < 1 || size > 4))) {
                        out.failed(block, ErrorId::InvalidInput);
                        return;
                    }
                    const auto index = block.get<std::uint16_t>(3);
                    const auto sub_index = block.get<std::uint8_t>(4);
                    block.set<std::uint32_t>(
                        out.work, write ? requests.write(*node, index, sub_index,
                                                         block.get<std::uint32_t>(data), size)
                                        : requests.read(*node, index, sub_index));
                    set_flag(block, out.busy, true);
                }
                const auto reply = followed_reply(block, out, requests);
                if (!reply) {
                    return;
                }
                block.set<std::uint32_t>(abort_code, reply->abort_code);
                if (reply->abort_code != 0) {
                    out.failed(block, ErrorId::SdoAbort);
                    return;
                }
                if (!write) {
                    block.set<std::uint32_t>(data, reply->value);
                    block.set<std::uint8_t>(length, reply->size);
                }
                out.done(block);
            }};
}

BlockDefinition nmt_block() {
    BlockInterface declared{"CAN_Nmt",
                            {input("Execute", "BOOL"), input("Port", "USINT"),
                             input("NodeId", "USINT"), input("Command", "USINT")}};
    const auto outputs = execute_outputs("Done", false);
    declared.variables.insert(declared.variables.end(), outputs.begin(), outputs.end());
    const ExecuteOutputs out(declared);
    return {std::move(declared), [=](vm::NativeBlock& block, MotionLibrary& library) {
                if (!out.begin(block)) {
                    return;
                }
                const auto port = block.get<std::uint8_t>(1);
                const auto node = block.get<std::uint8_t>(2);
                if (node > 127 ||
                    !library.link().send_nmt(port, node, block.get<std::uint8_t>(3))) {
                    out.failed(block, ErrorId::InvalidInput);
                    return;
                }
                out.done(block); // NMT has no answer: done once sent
            }};
}

} // namespace

std::vector<BlockDefinition> can_blocks() {
    return {sdo_block(sdo_interface("CAN_SdoRead", {},
                                    {output("Data", "UDINT"), output("DataLength", "USINT")}),
                      false),
            sdo_block(sdo_interface("CAN_SdoWrite",
                                    {input("Data", "UDINT"), input("DataLength", "USINT")}, {}),
                      true),
            nmt_block()};
}

} // namespace eposp::plcopen::blocks
