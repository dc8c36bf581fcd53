#pragma once

#include "eposp/canopen/lss_master.hpp"
#include "eposp/canopen/lss_protocol.hpp"
#include "eposp/core/result.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace eposp::canopen {

struct LssFastscanConfig {
    /// Parts of the address every slave is known to have (all EPOS2 have maxon's vendor-ID):
    /// fastscan confirms a known part with one request instead of scanning its 32 bits.
    std::optional<std::uint32_t> vendor_id;
    std::optional<std::uint32_t> product_code;
    std::optional<std::uint32_t> revision_number;
    /// Also store each new node-ID in the slave (store configuration, EPOS2 FW spec 7.4.2.6).
    bool store_configuration = false;
};

/// A slave and the node-ID it was given.
struct LssAssignment {
    LssAddress address;
    NodeId node_id = kLssUnconfiguredNodeId;
    friend bool operator==(const LssAssignment&, const LssAssignment&) = default;
};

/// What a node-ID assignment did: the slaves that got their node-ID, in order, and why it
/// stopped early if it did.
struct LssAssignmentReport {
    std::vector<LssAssignment> assigned;
    std::optional<core::Error> failure;
    bool complete() const { return !failure; }
};

/// Picks the node-ID for a slave found by fastscan: 1..127.
using NodeIdAllocator = std::function<NodeId(const LssAddress& address)>;

/// Node-ID assignment over LSS (CiA 305): fastscan finds the non-configured slaves one after
/// another and gives each a node-ID; when the addresses are known, switch state selective
/// reaches each slave directly. Both run on an LssMaster, which must outlive them; destroying
/// this object abandons a running assignment without calling its callback.
class LssFastscan {
public:
    using Done = std::function<void(const LssAssignmentReport&)>;

    explicit LssFastscan(LssMaster& master, LssFastscanConfig config = {});

    /// CiA 305 fastscan, round after round: a confirm request asks whether a non-configured
    /// slave is left; then each part of the address is found bit by bit, from bit 31 down (a
    /// slave answers when its bits above and at the checked one match, and silence means the
    /// bit is 1), and confirmed, which moves the matching slaves on to the next part. After the
    /// serial number exactly one slave is in configuration: it gets `allocate`'s node-ID and is
    /// switched back to waiting. `done` runs when no non-configured slave answers any more.
    /// Starting while an assignment runs is a programming error (std::logic_error).
    void scan(NodeIdAllocator allocate, Done done);

    /// The alternative when the addresses are known: switch state selective to each, configure
    /// its node-ID, back to waiting. A slave that had a node-ID uses the new one after its next
    /// reset communication.
    void assign(std::vector<LssAssignment> targets, Done done);

    bool running() const { return running_; }

private:
    void start(Done done);
    void next_round();
    void scan_part(LssPart part);
    void scan_bit(LssPart part, std::uint8_t bit);
    void confirm_part(LssPart part);
    void assign_next();
    void configure_found(NodeId id);
    /// Switch state global to waiting, then `then`.
    void all_to_waiting(std::function<void()> then);
    void finish(std::optional<core::Error> failure);
    std::optional<std::uint32_t> known(LssPart part) const;
    /// Wraps a master callback so that it does nothing once this object is gone.
    template <typename T>
    LssMaster::Callback<T> guarded(std::function<void(const LssResult<T>&)> fn);

    LssMaster& master_;
    LssFastscanConfig config_;
    NodeIdAllocator allocate_;
    std::vector<LssAssignment> targets_; ///< assign(): the slaves not yet done
    LssAddress found_;                   ///< the address being scanned or assigned
    LssAssignmentReport report_;
    Done done_;
    bool running_ = false;
    std::shared_ptr<const bool> alive_ = std::make_shared<const bool>(true);
};

} // namespace eposp::canopen
