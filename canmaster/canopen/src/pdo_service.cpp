#include "eposp/canopen/pdo_service.hpp"

#include "eposp/canopen/pdo_objects.hpp"

#include <fmt/format.h>
#include <stdexcept>

namespace eposp::canopen {

PdoService::PdoService(core::EventLoop& loop, can::Port& port, ObjectDictionary& od,
                       EmergencyCallback emergency, std::size_t first_number)
    : od_(od) {
    const std::size_t rpdos = count_pdos(od, PdoDirection::Receive, first_number);
    for (std::size_t n = first_number; n < first_number + rpdos; ++n) {
        rpdos_.push_back(std::make_unique<Rpdo>(loop, od, n, emergency));
    }
    const std::size_t tpdos = count_pdos(od, PdoDirection::Transmit, first_number);
    for (std::size_t n = first_number; n < first_number + tpdos; ++n) {
        tpdos_.push_back(std::make_unique<Tpdo>(loop, port, od, n, emergency));
    }
    // Each PDO's own listener, added before, has read the new parameters when this one runs.
    const auto relist = [this](std::uint16_t, std::uint8_t) {
        list_synchronous();
    };
    for (const auto& rpdo : rpdos_) {
        listeners_.push_back(
            od_.on_change(pdo_communication_index(PdoDirection::Receive, rpdo->number()), relist));
    }
    for (const auto& tpdo : tpdos_) {
        listeners_.push_back(
            od_.on_change(pdo_communication_index(PdoDirection::Transmit, tpdo->number()), relist));
    }
    list_synchronous();
}

PdoService::~PdoService() {
    for (const auto id : listeners_) {
        od_.remove_listener(id);
    }
}

void PdoService::list_synchronous() {
    synchronous_tpdos_.clear();
    for (const auto& tpdo : tpdos_) {
        if (tpdo->synchronous()) {
            synchronous_tpdos_.push_back(tpdo.get());
        }
    }
    synchronous_rpdos_.clear();
    for (const auto& rpdo : rpdos_) {
        if (rpdo->synchronous()) {
            rpdo->set_window_closed(window_closed_);
            synchronous_rpdos_.push_back(rpdo.get());
        }
    }
}

void PdoService::receive_keys(ReceiveKeys& keys) const {
    // A TPDO takes its remote requests, and its own identifier sent by another node (a collision).
    for (const auto& rpdo : rpdos_) {
        if (rpdo->cob_id().valid()) {
            keys.push_back(receive_key(rpdo->cob_id().raw));
        }
    }
    for (const auto& tpdo : tpdos_) {
        if (tpdo->cob_id().valid()) {
            keys.push_back(receive_key(tpdo->cob_id().raw));
        }
    }
}

void PdoService::on_frame(const can::Frame& frame) {
    for (auto& rpdo : rpdos_) {
        rpdo->on_frame(frame);
    }
    for (auto& tpdo : tpdos_) {
        tpdo->on_frame(frame);
    }
}

// The other PDOs have nothing to do at a SYNC or the end of its window. By index: what an RPDO
// stores may change parameters, and so the lists.
void PdoService::on_sync(std::uint8_t counter) {
    window_closed_ = false;
    for (std::size_t i = 0; i < synchronous_tpdos_.size(); ++i) {
        synchronous_tpdos_[i]->on_sync(counter);
    }
    for (std::size_t i = 0; i < synchronous_rpdos_.size(); ++i) {
        synchronous_rpdos_[i]->on_sync(counter);
    }
}

void PdoService::on_window_closed() {
    window_closed_ = true;
    for (std::size_t i = 0; i < synchronous_tpdos_.size(); ++i) {
        synchronous_tpdos_[i]->on_window_closed();
    }
    for (std::size_t i = 0; i < synchronous_rpdos_.size(); ++i) {
        synchronous_rpdos_[i]->on_window_closed();
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
    for (auto& rpdo : rpdos_) {
        rpdo->reload();
    }
    for (auto& tpdo : tpdos_) {
        tpdo->reload();
    }
    list_synchronous();
}

void PdoService::on_error_resolved(const ErrorResolvedCallback& resolved) {
    for (auto& rpdo : rpdos_) {
        rpdo->on_error_resolved(resolved);
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
