#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/can/port.hpp"
#include "eposp/canopen/emcy_producer.hpp"
#include "eposp/canopen/error_history.hpp"
#include "eposp/canopen/frame_router.hpp"
#include "eposp/canopen/heartbeat_consumer.hpp"
#include "eposp/canopen/heartbeat_producer.hpp"
#include "eposp/canopen/lss_protocol.hpp"
#include "eposp/canopen/lss_slave.hpp"
#include "eposp/canopen/nmt_slave.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/node_guarding.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/parameter_store.hpp"
#include "eposp/canopen/pdo_objects.hpp"
#include "eposp/canopen/pdo_service.hpp"
#include "eposp/canopen/sdo_server.hpp"
#include "eposp/canopen/services_port.hpp"
#include "eposp/canopen/store_restore_objects.hpp"
#include "eposp/canopen/sync_consumer.hpp"
#include "eposp/canopen/sync_objects.hpp"
#include "eposp/canopen/sync_producer.hpp"
#include "eposp/core/event_loop.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>

namespace eposp::canopen {

inline constexpr std::uint16_t kDeviceTypeIndex = 0x1000;
inline constexpr std::uint16_t kIdentityIndex = 0x1018;

/// EPOS2 FW spec table 4-11: "Software Parameter Error", here the stored parameters that were
/// refused at a load (the node runs on its defaults).
inline constexpr std::uint16_t kEmcySoftwareParameterError = 0x6320;

/// What a node needs beyond the device's own objects. The communication objects it describes
/// are added only where the dictionary does not have them yet (e.g. one imported from an EDS).
struct NodeConfig {
    /// 1..127, or kLssUnconfiguredNodeId: the node then waits for LSS to configure one (CiA
    /// 305). A node-ID that LSS stored replaces it.
    NodeId node_id = 1;
    std::uint32_t device_type = 0;               ///< 0x1000
    LssAddress identity;                         ///< 0x1018 sub 1..4, also the node's LSS address
    std::uint8_t heartbeat_consumer_entries = 1; ///< 0x1016
    std::uint8_t error_history_capacity = kEpos2ErrorHistoryEntries; ///< 0x1003
    SyncObjectOptions sync;                                          ///< 0x1005..0x1007, 0x1019
    bool emcy_inhibit_time = true;                                   ///< 0x1015
    /// CiA 301 7.5.2.2 sets the generic bit of 0x1001 with every error; a device whose manual
    /// gives each error its own register value (EPOS2 FW spec table 4-11) keeps to its table.
    GenericErrorBit generic_error_bit = GenericErrorBit::WithEveryError;
    /// The PDOs when the dictionary has none; empty: CiA 301 defaults for 4 RPDOs and 4 TPDOs.
    std::optional<PdoObjectsConfig> pdos;
    /// The non-volatile memory behind 0x1010/0x1011; empty: the node has no stored values.
    std::optional<std::filesystem::path> parameter_file;
    /// Who may restore the defaults (0x1011), e.g. the EPOS2 only in pre-operational.
    StoreRestoreOptions store_restore;
    /// EPOS2 FW spec 8.2.9: 0x1011 sub 5 "Restore Default PDO COB-IDs" (needs a parameter file).
    bool restore_pdo_cob_ids = false;
    SdoServerConfig sdo;

    /// LSS (CiA 305). The bit rate (bit/s) of the bus the node starts on; one that LSS stored
    /// replaces it.
    std::uint32_t bit_rate = 1'000'000;
    /// The bit rates (bit/s) the device supports, e.g. its EDS's BaudRate_ entries (CiA 306
    /// 4.4): LSS configure bit timing accepts these (CiA 305). Empty: every rate of the CiA
    /// table when switch_bit_rate is set, none otherwise.
    std::set<std::uint32_t> bit_rates;
    /// Switches the node's CAN controller to another bit rate (LSS activate bit timing): the
    /// node cannot do it itself; start() calls it with the rate the node starts at. Missing:
    /// activate bit timing changes bit_rate() only.
    std::function<void(std::uint32_t bit_rate)> switch_bit_rate;
    /// EPOS2 FW spec 7.4: LSS only in NMT stopped (a node without node-ID takes it always).
    bool lss_only_when_stopped = false;
};

/// The error register bits of an emergency code the node raises (EPOS2 FW spec table 4-11: every
/// CAN error 0x81xx/0x82xx is a communication error, 0x6320 device profile specific); generic
/// otherwise.
std::uint8_t error_register_bits(std::uint16_t emcy_error_code);

/// A CANopen slave node (CiA 301), CANopenNode-style: a dictionary, a port and the services on
/// them. The node owns the port's receive handler and hands each frame to the services that take
/// its identifier (FrameRouter: the table follows every COB-ID and node-ID change), tells
/// every service the NMT state, feeds SYNCs (received or its own) to the PDOs and the services'
/// emergencies to its EMCY producer.
///
/// NMT reset communication sets the communication area (0x1000..0x1FFF) back to its stored
/// values (or defaults) and reloads the PDOs; reset node first does the same for the rest of
/// the dictionary and tells the device (on_reset_application). The dictionary must outlive the
/// node and not move. Stored values that are refused (a damaged file) leave the defaults in
/// place and raise EMCY 0x6320 once the node is pre-operational.
///
/// Errors have a lifetime: a service's error ends when its cause does (the next RPDO or SYNC of
/// the right length, the next heartbeat or guarding request), with the error reset EMCY 0x0000
/// once no other cause holds the code; an NMT reset ends every error the services raised (reset
/// node also the device's), so that 0x1001 is back at its power-on value 0, and the error reset
/// EMCY follows the boot-up.
///
/// LSS (CiA 305): the node's LSS slave, addressed by NodeConfig::identity, gets every frame. A
/// node-ID it configures becomes active at the next reset communication (right away for a
/// node that had none, when it leaves LSS configuration), and everything that depends on the
/// node-ID follows it: NMT addressing, boot-up and heartbeat, node guarding, the SDO server, and
/// the defaults of 0x1014, 0x1200 and the PDO COB-IDs of the predefined connection set (CiA 301
/// 7.3.5). Store configuration writes the pending node-ID and bit rate beside the parameter
/// file ("<parameter file>.lss"); without one it is not supported. While the LSS slave switches
/// the bit rate the node's services send nothing.
class Node {
public:
    Node(core::EventLoop& loop, can::Port& port, ObjectDictionary& dictionary, NodeConfig config);
    ~Node();
    Node(const Node&) = delete;
    Node& operator=(const Node&) = delete;

    /// Power-up: stored values, boot-up message, pre-operational (CiA 301 7.3.2.2, figure 48).
    void start();

    /// Told at power-up and at every NMT reset node, after the application area got its stored
    /// values back: the device resets its own state.
    void on_reset_application(std::function<void()> handler);
    /// Told of every change of the CAN controller's error state (ISO 11898-1 12.1.4), after the
    /// node's own services heard it: the device raises its CAN errors from it.
    void on_controller_state(std::function<void(can::ErrorState)> handler);

    NmtState nmt_state() const { return nmt_.state(); }
    NodeId node_id() const { return nmt_.node_id(); }
    /// The bit rate (bit/s) the node runs at, after LSS.
    std::uint32_t bit_rate() const { return lss_.active_bit_rate(); }
    ObjectDictionary& dictionary() { return od_; }
    /// What the last load of stored values found; NoneStored without a parameter file.
    const StoredValuesReport& stored_values() const { return stored_values_; }

    NmtSlave& nmt() { return nmt_; }
    LssSlave& lss() { return lss_; }
    EmcyProducer& emcy() { return emcy_; }
    HeartbeatConsumer& heartbeat_consumer() { return heartbeat_consumer_; }
    NodeGuarding& node_guarding() { return guarding_; }
    SyncConsumer& sync_consumer() { return sync_consumer_; }
    PdoService& pdo() { return pdo_; }

private:
    /// Each service receives the frames of its identifiers; the table follows their changes.
    void route_frames();
    void set_nmt_state(NmtState state);
    /// A service's error started or ended: the EMCY producer hears of its first cause and the
    /// end of its last.
    void raise_emergency(std::uint16_t error_code);
    void resolve_emergency(std::uint16_t error_code);
    void end_service_errors();
    /// Stored values (or defaults) back in the communication area only, or in all of it.
    void restore_stored_values(bool communication_area_only);
    void reset_application();
    void reset_communication();
    /// Moves every node-ID-dependent service and default to `node_id` (CiA 305).
    void adopt_node_id(NodeId node_id);
    LssSlaveHooks lss_hooks();

    can::Port& port_;
    /// What the services send through: closed while the LSS slave is silent.
    ServicesPort services_port_;
    /// Stored values or the stored LSS configuration were refused, and no EMCY told it yet.
    bool refused_store_to_report_ = false;
    NodeConfig config_;    ///< with the stored LSS configuration applied
    ObjectDictionary& od_; ///< with the communication objects added (see the constructor)
    std::optional<ParameterStore> store_;
    StoredValuesReport stored_values_;
    std::function<void()> application_reset_handler_;
    std::function<void(can::ErrorState)> controller_state_handler_;
    FrameRouter router_;
    std::vector<ObjectDictionary::ListenerId> cob_id_listeners_;
    std::map<std::uint16_t, unsigned> service_errors_; ///< error code -> causes still present

    NmtSlave nmt_;
    EmcyProducer emcy_;
    SdoServer sdo_;
    HeartbeatProducer heartbeat_producer_;
    HeartbeatConsumer heartbeat_consumer_;
    NodeGuarding guarding_;
    SyncProducer sync_producer_;
    SyncConsumer sync_consumer_;
    PdoService pdo_;
    LssSlave lss_;
};

} // namespace eposp::canopen
