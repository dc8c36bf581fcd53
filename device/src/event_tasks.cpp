#include "event_tasks.hpp"

#include "eposp/device/epos_p_dictionary.hpp"
#include "network_port.hpp"

#include <fmt/format.h>

namespace eposp::device {

namespace {

bool is_event_task(const vm::Image& image, std::optional<std::size_t> task) {
    return task && image.tasks[*task].kind == vm::TaskKind::Event;
}

} // namespace

EventTasks::EventTasks(vm::PlcRuntime& runtime, canopen::ObjectDictionary& objects, PortOf port_of)
    : runtime_(runtime), objects_(objects), port_of_(std::move(port_of)) {
    for (const std::uint8_t port : {kInternalPort, kExternalPort}) {
        port_of_(port).on_emergency([this, port](const canopen::Emergency& emergency) {
            on_emergency(port, emergency.node);
        });
    }
}

std::optional<core::Error> EventTasks::bind(EventBinding binding) {
    if (!is_event_task(runtime_.image(), runtime_.task_index(binding.task))) {
        return core::Error{
            fmt::format("event task {}: the program has no such task with SINGLE (an event task)",
                        binding.task)};
    }
    listen(binding);
    network_.push_back(std::move(binding));
    return std::nullopt;
}

std::optional<core::Error> EventTasks::check(const vm::Image& image) const {
    for (const vm::Task& task : image.tasks) {
        if (task.event.empty()) {
            continue;
        }
        if (const auto event = parse_event(task.event); !event) {
            return core::Error{
                fmt::format("task {}: event '{}': {}", task.name, task.event, event.error())};
        }
    }
    return std::nullopt;
}

void EventTasks::loaded(const vm::Image& image) {
    program_.clear();
    for (const vm::Task& task : image.tasks) {
        if (task.event.empty()) {
            continue;
        }
        EventBinding binding = *parse_event(task.event); // check() accepted it
        binding.task = task.name;
        listen(binding);
        program_.push_back(std::move(binding));
    }
}

void EventTasks::listen(const EventBinding& binding) {
    switch (binding.source) {
    case EventBinding::Source::Sync:
    case EventBinding::Source::Emcy: // heard from the start
        break;
    case EventBinding::Source::Rpdo:
        if (rpdos_heard_.emplace(binding.port, binding.rpdo).second) {
            port_of_(binding.port)
                .on_rpdo(binding.rpdo, [this, port = binding.port, number = binding.rpdo] {
                    on_rpdo(port, number);
                });
        }
        break;
    case EventBinding::Source::Input: {
        const std::pair bit{binding.input_byte, binding.input_bit};
        if (!input_levels_.contains(bit)) {
            const std::uint8_t mask = static_cast<std::uint8_t>(1U << bit.second);
            input_levels_[bit] = (runtime_.process_image().inputs()[bit.first] & mask) != 0;
        }
        const std::uint16_t index = vm::object_entry_of(vm::IoArea::Input, bit.first)->index;
        if (input_objects_heard_.insert(index).second) {
            objects_.on_change(index, [this](std::uint16_t, std::uint8_t) { on_input_written(); });
        }
        break;
    }
    }
}

template <typename Matches>
void EventTasks::release_where(Matches matches) {
    if (runtime_.state() != vm::ProgramState::Running) {
        return;
    }
    for (const auto* bindings : {&network_, &program_}) {
        for (const EventBinding& binding : *bindings) {
            const auto task = runtime_.task_index(binding.task);
            if (matches(binding) && is_event_task(runtime_.image(), task)) {
                runtime_.raise_event(*task);
            }
        }
    }
}

void EventTasks::on_sync() {
    release_where(
        [](const EventBinding& binding) { return binding.source == EventBinding::Source::Sync; });
}

void EventTasks::on_emergency(std::uint8_t port, canopen::NodeId node) {
    release_where([port, node](const EventBinding& binding) {
        return binding.source == EventBinding::Source::Emcy && binding.port == port &&
               (!binding.node || *binding.node == node);
    });
}

void EventTasks::on_rpdo(std::uint8_t port, std::size_t number) {
    release_where([port, number](const EventBinding& binding) {
        return binding.source == EventBinding::Source::Rpdo && binding.port == port &&
               binding.rpdo == number;
    });
}

void EventTasks::on_input_written() {
    std::set<std::pair<std::uint32_t, std::uint8_t>> risen;
    for (auto& [bit, level] : input_levels_) {
        const std::uint8_t mask = static_cast<std::uint8_t>(1U << bit.second);
        const bool now = (runtime_.process_image().inputs()[bit.first] & mask) != 0;
        if (now && !level) {
            risen.insert(bit);
        }
        level = now;
    }
    if (!risen.empty()) {
        release_where([&risen](const EventBinding& binding) {
            return binding.source == EventBinding::Source::Input &&
                   risen.contains({binding.input_byte, binding.input_bit});
        });
    }
}

} // namespace eposp::device
