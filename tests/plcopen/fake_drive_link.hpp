#pragma once

// An axis link to CiA 402 drives reduced to what the motion blocks see: device control, the
// profile position, profile velocity and homing handshakes, and SDO access to a map of objects.
// Positions move by a fixed step per SYNC, so every test can count cycles exactly. SDO replies
// and new process data arrive only at sync(), never inside a call of the link.

#include "eposp/plcopen/axis_link.hpp"

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace eposp::plcopen::test {

struct FakeDrive {
    AxisPresence presence = AxisPresence::Unassigned;
    std::uint16_t statusword = 0x0040; ///< Switch on disabled
    std::uint16_t controlword = 0;
    std::int32_t position = 0;
    std::int32_t target = 0;       ///< set by the link, taken on a new set-point
    std::int32_t taken_target = 0; ///< the set-point the drive moves to
    std::int32_t step = 0;         ///< its quadcounts per SYNC: 0x6081 when it was taken
    /// A set-point taken with "change set immediately" clear during a move (target, step): the
    /// drive's one-deep buffer, started when the move ends.
    std::optional<std::pair<std::int32_t, std::int32_t>> buffered;
    std::uint16_t error_code = 0; ///< 0x1003 sub 1; non-zero: Fault
    int homing_cycles = -1;       ///< cycles left of a running homing
    std::int32_t velocity = 0;    ///< profile velocity mode: quadcounts per SYNC now
    std::int32_t ramp = 0;        ///< its change per SYNC toward 0x60FF; 0: at once
    std::map<std::pair<std::uint16_t, std::uint8_t>, std::uint32_t> objects;
    /// What an upload reports as the object's size; 4 bytes unless set here.
    std::map<std::pair<std::uint16_t, std::uint8_t>, std::uint8_t> sizes;
    bool refuse_mode = false; ///< 0x6061 never follows 0x6060

    std::uint32_t object(std::uint16_t index, std::uint8_t sub = 0) const {
        const auto it = objects.find({index, sub});
        return it == objects.end() ? 0 : it->second;
    }
};

class FakeDriveLink : public AxisLink {
public:
    std::array<FakeDrive, kAxisCount> drives{};
    std::uint32_t sdo_transfers = 0;
    /// An SDO download acts only after the process data of the SYNC that follows its answer,
    /// as a controlword does (AxisLink::samples): that SYNC's statusword still predates it.
    bool downloads_act_late = false;
    std::uint8_t last_write_size = 0;

    /// One SYNC: SDO replies arrive, each drive takes its controlword and answers, then the
    /// downloads answered at the SYNC before act if they act late.
    void sync() {
        auto replies = std::move(replies_);
        replies_.clear();
        auto late = std::move(late_downloads_);
        late_downloads_.clear();
        for (auto& reply : replies) {
            reply();
        }
        for (FakeDrive& drive : drives) {
            step(drive);
        }
        for (auto& download : late) {
            download();
        }
        ++samples_;
    }

    AxisPresence presence(AxisNumber axis) const override { return drives[axis].presence; }
    std::uint16_t statusword(AxisNumber axis) const override { return drives[axis].statusword; }
    std::int32_t actual_position(AxisNumber axis) const override { return drives[axis].position; }
    std::uint32_t samples(AxisNumber) const override { return samples_; }
    void set_controlword(AxisNumber axis, std::uint16_t controlword) override {
        drives[axis].controlword = controlword;
    }
    void set_target_position(AxisNumber axis, std::int32_t position) override {
        drives[axis].target = position;
    }
    void read(AxisNumber axis, std::uint16_t index, std::uint8_t sub_index, SdoDone done) override {
        ++sdo_transfers;
        replies_.push_back([this, axis, index, sub_index, done = std::move(done)] {
            FakeDrive& drive = drives[axis];
            std::uint32_t value = drive.object(index, sub_index);
            if (index == 0x6061) {
                value = drive.refuse_mode ? 0 : drive.object(0x6060);
            } else if (index == 0x1003 && sub_index == 1 && drive.error_code != 0) {
                value = drive.error_code;
            }
            const auto size = drive.sizes.find({index, sub_index});
            done({.value = value,
                  .size = size == drive.sizes.end() ? std::uint8_t{4} : size->second});
        });
    }
    void write(AxisNumber axis, std::uint16_t index, std::uint8_t sub_index, std::uint32_t value,
               std::uint8_t size, SdoDone done) override {
        ++sdo_transfers;
        replies_.push_back([this, axis, index, sub_index, value, size, done = std::move(done)] {
            last_write_size = size;
            if (index == 0x2FFF) { // an object the fake drive does not have
                done({.abort_code = 0x06020000});
                return;
            }
            auto download = [this, axis, index, sub_index, value] {
                drives[axis].objects[{index, sub_index}] = value;
            };
            if (downloads_act_late) {
                late_downloads_.push_back(std::move(download));
            } else {
                download();
            }
            done({});
        });
    }

    /// Objects of other nodes, by (port, node): absent ones abort with 0x06020000.
    std::map<std::pair<std::uint8_t, std::uint8_t>,
             std::map<std::pair<std::uint16_t, std::uint8_t>, std::uint32_t>>
        nodes;
    struct Nmt {
        std::uint8_t port, node, command;
    };
    std::vector<Nmt> nmt_sent;

    void read(NodeAddress node, std::uint16_t index, std::uint8_t sub_index,
              SdoDone done) override {
        replies_.push_back([this, node, index, sub_index, done = std::move(done)] {
            const auto& objects = nodes[{node.port, node.node}];
            const auto it = objects.find({index, sub_index});
            done(it == objects.end() ? SdoReply{.abort_code = 0x06020000}
                                     : SdoReply{.value = it->second, .size = 4});
        });
    }
    void write(NodeAddress node, std::uint16_t index, std::uint8_t sub_index, std::uint32_t value,
               std::uint8_t size, SdoDone done) override {
        replies_.push_back([this, node, index, sub_index, value, size, done = std::move(done)] {
            auto& objects = nodes[{node.port, node.node}];
            if (!objects.contains({index, sub_index})) {
                done({.abort_code = 0x06020000});
                return;
            }
            last_write_size = size;
            objects[{index, sub_index}] = value;
            done({});
        });
    }
    bool send_nmt(std::uint8_t port, std::uint8_t node, std::uint8_t command) override {
        if (port < 1 || port > 2) {
            return false;
        }
        nmt_sent.push_back({port, node, command});
        return true;
    }

private:
    static void step(FakeDrive& drive) {
        const std::uint16_t before = drive.statusword;
        const std::uint16_t cw = drive.controlword;
        const bool rising_new_setpoint = (cw & 0x10) != 0 && (drive.object(0xFFFF) & 0x10) == 0;
        const bool rising_fault_reset = (cw & 0x80) != 0 && (drive.object(0xFFFF) & 0x80) == 0;
        drive.objects[{0xFFFF, 0}] = cw; // the controlword the last step saw
        if (drive.error_code != 0) {
            if (rising_fault_reset) {
                drive.error_code = 0;
                drive.statusword = 0x0040;
            } else {
                drive.statusword = 0x0008;
            }
            return;
        }
        const std::uint16_t state = before & 0x6F;
        const bool enabled = state == 0x27;
        if ((cw & 0x8F) == 0x0F && (state == 0x21 || state == 0x23 || enabled)) {
            if (!enabled) {
                drive.taken_target = drive.position; // enabled, it holds where it is
                drive.buffered.reset();
            }
            drive.statusword = 0x0027;
        } else if ((cw & 0x87) == 0x06) {
            drive.statusword = 0x0021;
        } else if ((cw & 0x86) == 0x02 || (cw & 0x82) == 0) {
            drive.statusword = 0x0040;
        }
        if ((drive.statusword & 0x6F) != 0x27) {
            return;
        }
        move(drive, rising_new_setpoint);
    }

    static void move(FakeDrive& drive, bool rising_new_setpoint) {
        const std::uint16_t cw = drive.controlword;
        const auto mode = static_cast<std::int8_t>(drive.object(0x6060));
        const bool halt = (cw & 0x100) != 0;
        std::uint16_t bits = 0;
        if (mode == 1) {
            if (rising_new_setpoint) {
                const std::pair next{drive.target, static_cast<std::int32_t>(drive.object(0x6081))};
                const bool at_rest = drive.position == drive.taken_target;
                if ((cw & 0x20) != 0 || at_rest) { // change set immediately, or nothing to finish
                    std::tie(drive.taken_target, drive.step) = next;
                    drive.buffered.reset();
                } else {
                    drive.buffered = next;
                }
            }
            if ((cw & 0x10) != 0 || drive.buffered) {
                bits |= 0x1000; // acknowledged while the bit is high, or while the buffer is full
            }
            if (!halt && drive.position != drive.taken_target) {
                const std::int32_t rest = drive.taken_target - drive.position;
                drive.position +=
                    rest > 0 ? std::min(rest, drive.step) : std::max(rest, -drive.step);
            }
            if (!halt && drive.position == drive.taken_target && drive.buffered) {
                std::tie(drive.taken_target, drive.step) = *drive.buffered; // on at once
                drive.buffered.reset();
            } else if (halt || drive.position == drive.taken_target) {
                bits |= 0x0400;
            }
        } else if (mode == 3) {
            const std::int32_t goal = halt ? 0 : static_cast<std::int32_t>(drive.object(0x60FF));
            const std::int32_t rest = goal - drive.velocity;
            drive.velocity = drive.ramp == 0 ? goal
                             : rest > 0      ? drive.velocity + std::min(rest, drive.ramp)
                                             : drive.velocity + std::max(rest, -drive.ramp);
            drive.position += drive.velocity;
            if (drive.velocity == goal) {
                bits |= 0x0400; // target velocity reached (FW spec table 5-54)
            }
        } else if (mode == 6) {
            if (rising_new_setpoint) {
                drive.homing_cycles = 3;
            }
            if (drive.homing_cycles > 0 && --drive.homing_cycles == 0) {
                drive.position = static_cast<std::int32_t>(drive.object(0x2081));
            }
            if (drive.homing_cycles == 0) {
                bits |= 0x1400;
            }
        }
        drive.statusword = 0x0027 | bits;
    }

    std::uint32_t samples_ = 0;
    std::deque<std::function<void()>> replies_;
    std::vector<std::function<void()>> late_downloads_;
};

} // namespace eposp::plcopen::test
