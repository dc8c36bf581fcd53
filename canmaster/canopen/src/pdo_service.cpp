#include "eposp/canopen/pdo_service.hpp"

#include "eposp/canopen/pdo_objects.hpp"

#include <fmt/format.h>
#include <stdexcept>

namespace eposp::canopen {

PdoService::PdoService(core::EventLoop& loop, can::Port& port, ObjectDictionary& od,
                       EmergencyCallback emergency)
    : od_(od) {
    const auto stale = [this](std::uint16_t, std::uint8_t) {
        identifiers_stale_ = true;
    };
    for (std::size_t n = 1; n <= count_pdos(od, PdoDirection::Receive); ++n) {
        rpdos_.push_back(std::make_unique<Rpdo>(loop, od, n, emergency));
        od_listeners_.push_back(
            od.on_change(pdo_communication_index(PdoDirection::Receive, n), stale));
    }
    for (std::size_t n = 1; n <= count_pdos(od, PdoDirection::Transmit); ++n) {
        tpdos_.push_back(std::make_unique<Tpdo>(loop, port, od, n, emergency));
        od_listeners_.push_back(
            od.on_change(pdo_communication_index(PdoDirection::Transmit, n), stale));
    }
}

PdoService::~PdoService() {
    for (const auto id : od_listeners_) {
        od_.remove_listener(id);
    }
}

void PdoService::index_identifiers() {
    standard_ids_.reset();
    const auto add = [this](PdoCobId cob_id) {
        if (!cob_id.extended()) {
            standard_ids_.set(cob_id.can_id() & can::kMaxStandardId);
        }
    };
    for (const auto& rpdo : rpdos_) {
        add(rpdo->cob_id());
    }
    for (const auto& tpdo : tpdos_) {
        add(tpdo->cob_id());
    }
    identifiers_stale_ = false;
}

void PdoService::on_frame(const can::Frame& frame) {
    if (!frame.extended) {
        if (identifiers_stale_) {
            index_identifiers();
        }
        if (frame.id > can::kMaxStandardId || !standard_ids_.test(frame.id)) {
            return;
        }
    }
    for (auto& rpdo : rpdos_) {
        rpdo->on_frame(frame);
    }
    for (auto& tpdo : tpdos_) {
        tpdo->on_frame(frame);
    }
}

void PdoService::on_sync(std::uint8_t counter) {
    for (auto& tpdo : tpdos_) {
        tpdo->on_sync(counter);
    }
    for (auto& rpdo : rpdos_) {
        rpdo->on_sync(counter);
    }
}

void PdoService::on_window_closed() {
    for (auto& tpdo : tpdos_) {
        tpdo->on_window_closed();
    }
    for (auto& rpdo : rpdos_) {
        rpdo->on_window_closed();
    }
}

void PdoService::set_nmt_state(NmtState state) {
    for (auto& rpdo : rpdos_) {
        rpdo->set_nmt_state(state);
    }
    for (auto& tpdo : tpdos_) {
        tpdo->set_nmt_state(state);
    }
}

void PdoService::reload() {
    identifiers_stale_ = true;
    for (auto& rpdo : rpdos_) {
        rpdo->reload();
    }
    for (auto& tpdo : tpdos_) {
        tpdo->reload();
    }
}

Rpdo& PdoService::rpdo(std::size_t number) {
    if (number == 0 || number > rpdos_.size()) {
        throw std::out_of_range(fmt::format("no RPDO {}", number));
    }
    return *rpdos_[number - 1];
}

Tpdo& PdoService::tpdo(std::size_t number) {
    if (number == 0 || number > tpdos_.size()) {
        throw std::out_of_range(fmt::format("no TPDO {}", number));
    }
    return *tpdos_[number - 1];
}

} // namespace eposp::canopen
