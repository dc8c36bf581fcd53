#include "eposp/vm/plc_runtime.hpp"

#include "eposp/vm/value_format.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>

namespace eposp::vm {
namespace {

// A binding belongs to the task whose program instance holds the variable; one in a global
// (VAR_GLOBAL AT ...) to every task, which each copy it around their own cycles.
std::vector<std::vector<IoBinding>> bindings_per_task(const Image& image) {
    std::vector<std::vector<IoBinding>> per_task(image.tasks.size());
    for (const IoBinding& binding : image.bindings) {
        std::optional<std::size_t> owner;
        for (std::size_t task = 0; task < image.tasks.size() && !owner; ++task) {
            for (const TaskEntry& entry : image.tasks[task].entries) {
                if (binding.offset >= entry.instance &&
                    binding.offset < entry.instance + image.pous[entry.pou].instance_size) {
                    owner = task;
                }
            }
        }
        for (std::size_t task = 0; task < image.tasks.size(); ++task) {
            if (!owner || *owner == task) {
                per_task[task].push_back(binding);
            }
        }
    }
    return per_task;
}

// The integer `bytes` hold (little-endian, as VM memory) lies within the subrange `type`.
bool in_subrange(const TypeDescriptor& type, std::span<const std::uint8_t> bytes) {
    const std::int64_t value = integer_value(type.scalar, bytes);
    // An unsigned value above INT64_MAX is outside every subrange.
    const bool wrapped = !is_signed_integer(type.scalar) && value < 0;
    return !wrapped && value >= type.lowest && value <= type.highest;
}

} // namespace

PlcRuntime::PlcRuntime(core::EventLoop& loop, const NativeRegistry& natives, RuntimeConfig config,
                       ErrorSink errors)
    : loop_(loop), natives_(natives), config_(std::move(config)), errors_(std::move(errors)) {
    if (config_.retain_file) {
        retain_store_.emplace(*config_.retain_file, config_.retain_capacity);
    }
}

PlcRuntime::~PlcRuntime() = default;

std::optional<core::Error> PlcRuntime::load(Image image) {
    if (state() == ProgramState::Running) {
        return core::Error{"a program is running; stop it before loading another"};
    }
    if (const auto error = RetainStore(config_.retain_file.value_or(""), config_.retain_capacity)
                               .check_capacity(image)) {
        return error;
    }
    if (const auto error = ProcessImage::check_bindings(image)) {
        return error;
    }
    if (const auto error = MarkerArea::check_bindings(image)) {
        return error;
    }
    auto program =
        link(std::move(image), natives_,
             config_.coverage == Coverage::Record ? Engine::Interpreter : config_.engine);
    if (!program) {
        return core::Error{program.error()};
    }
    dispatcher_.reset();
    machine_.reset();
    program_ = std::make_unique<Program>(std::move(*program));
    machine_ = std::make_unique<Machine>(*program_, config_.coverage);
    dispatcher_ = std::make_unique<TaskDispatcher>(loop_, *machine_, hooks(), config_.cost);
    for (std::size_t task = 0; task < program_->image().tasks.size(); ++task) {
        dispatcher_->set_watchdog(task, config_.watchdog_instructions);
    }
    task_bindings_ = bindings_per_task(program_->image());
    forced_.release_all();
    retain_saved_.reset();
    return std::nullopt;
}

std::optional<core::Error> PlcRuntime::start(StartMode mode) {
    if (state() == ProgramState::NotLoaded) {
        return core::Error{"no program is loaded"};
    }
    if (state() == ProgramState::Running) {
        return core::Error{"the program is already running; stop it first"};
    }
    markers_.clear();
    machine_->cold_start();
    retain_saved_.reset(); // a cold start's values replace the store at the next save
    if (mode != StartMode::Cold) {
        restore_retain();
    }
    running_mode_ = mode;
    if (retain_store_ && !image().retain.empty() &&
        config_.retain_save_interval > core::Duration::zero()) {
        retain_timer_ = core::ScopedTimer(
            loop_, loop_.every(config_.retain_save_interval, [this] { save_retain_if_changed(); }));
    }
    dispatcher_->start();
    return std::nullopt;
}

void PlcRuntime::stop() {
    if (state() != ProgramState::Running) {
        return;
    }
    dispatcher_->stop();
    retain_timer_.cancel();
    running_mode_.reset();
    save_retain_if_changed();
    if (config_.safe_state == SafeState::Zero) {
        process_image_.clear_outputs();
    }
}

void PlcRuntime::unload() {
    stop();
    dispatcher_.reset();
    machine_.reset();
    program_.reset();
    task_bindings_.clear();
    forced_.release_all();
    retain_saved_.reset();
}

ProgramState PlcRuntime::state() const {
    if (!program_) {
        return ProgramState::NotLoaded;
    }
    return running_mode_ ? ProgramState::Running : ProgramState::Stopped;
}

CoverageReport PlcRuntime::coverage() const {
    return machine_ ? machine_->coverage() : CoverageReport{};
}

std::uint16_t PlcRuntime::program_control() const {
    return running_mode_ ? static_cast<std::uint16_t>(*running_mode_) : 0;
}

std::optional<std::size_t> PlcRuntime::task_index(std::string_view name) const {
    const auto& tasks = image().tasks;
    // IEC identifiers compare case-insensitively.
    const auto same = [name](const Task& task) {
        return std::equal(task.name.begin(), task.name.end(), name.begin(), name.end(),
                          [](char a, char b) {
                              return std::tolower(static_cast<unsigned char>(a)) ==
                                     std::tolower(static_cast<unsigned char>(b));
                          });
    };
    const auto it = std::find_if(tasks.begin(), tasks.end(), same);
    return it == tasks.end()
               ? std::nullopt
               : std::optional<std::size_t>(static_cast<std::size_t>(it - tasks.begin()));
}

void PlcRuntime::raise_event(std::size_t task) {
    if (state() == ProgramState::Running) {
        dispatcher_->raise_event(task);
    }
}

void PlcRuntime::align_cycles(core::TimePoint anchor, core::Duration period) {
    if (state() == ProgramState::Running) {
        dispatcher_->align(anchor, period);
    }
}

void PlcRuntime::set_watchdog(std::size_t task, std::uint64_t instructions) {
    dispatcher_->set_watchdog(task, instructions);
}

const TaskStatistics& PlcRuntime::statistics(std::size_t task) const {
    return dispatcher_->statistics(task);
}

bool PlcRuntime::task_faulted(std::size_t task) const {
    return dispatcher_->faulted(task);
}

// IEC 61131-3 6.5.5 and DS-405: a task works on one snapshot of its inputs, taken before its
// cycle, and its outputs appear together after it.
void PlcRuntime::before_cycle(std::size_t task) {
    const auto memory = machine_->memory();
    process_image_.read_inputs(task_bindings_[task], memory);
    markers_.read_into(task_bindings_[task], memory);
    forced_.apply(memory);
}

void PlcRuntime::after_cycle(std::size_t task) {
    const auto memory = machine_->memory();
    forced_.apply(memory);
    process_image_.write_outputs(task_bindings_[task], memory);
    markers_.write_from(task_bindings_[task], memory);
}

void PlcRuntime::on_fault(std::size_t task) {
    const Trap trap = machine_->task(task).fault.trap;
    report(error_code_of(trap),
           fmt::format("task {} stopped: {}", image().tasks[task].name, fault_text(task)), task);
    if (config_.safe_state == SafeState::Zero) {
        process_image_.clear_outputs(task_bindings_[task]);
    }
}

void PlcRuntime::on_overrun(std::size_t task, std::uint16_t code) {
    const std::string& name = image().tasks[task].name;
    markers_.record_overrun(task);
    report(
        code,
        code == error_code::kTimerTask
            ? fmt::format("task {} still running when its next cycle was due; cycle skipped", name)
            : fmt::format("task {} triggered again while running; event lost", name),
        task);
}

void PlcRuntime::report(std::uint16_t code, std::string text, std::optional<std::size_t> task) {
    markers_.record_error(code, task);
    if (errors_) {
        errors_(code, std::move(text));
    }
}

core::Result<std::string> PlcRuntime::read(std::string_view path) const {
    if (!program_) {
        return core::Error{"no program is loaded"};
    }
    const auto location = lookup_variable(image(), path);
    if (!location) {
        return core::Error{location.error()};
    }
    return format_value(image(), machine_->memory(), *location);
}

core::Result<VariableLocation> PlcRuntime::writable(std::string_view path,
                                                    std::span<const std::uint8_t> bytes) const {
    if (!program_) {
        return core::Error{"no program is loaded"};
    }
    const auto location = lookup_variable(image(), path);
    if (!location) {
        return location;
    }
    if (location->read_only) {
        return core::Error{
            fmt::format("{} is read-only (a constant or a READ_ONLY access path)", path)};
    }
    const TypeDescriptor& type = image().types[location->type];
    const std::uint32_t size = type.size;
    if (bytes.size() != size) {
        return core::Error{fmt::format("{} is {} bytes, not {}", path, size, bytes.size())};
    }
    if (type.subrange && !in_subrange(type, bytes)) {
        return core::Error{
            fmt::format("{} takes values from {} to {} only", path, type.lowest, type.highest)};
    }
    return location;
}

std::optional<core::Error> PlcRuntime::write(std::string_view path,
                                             std::span<const std::uint8_t> bytes) {
    const auto location = writable(path, bytes);
    if (!location) {
        return core::Error{location.error()};
    }
    std::copy(bytes.begin(), bytes.end(), machine_->memory().begin() + location->offset);
    forced_.apply(machine_->memory()); // a forced variable keeps its forced value
    if (state() == ProgramState::Running) {
        dispatcher_->check_event_inputs();
    }
    return std::nullopt;
}

std::optional<core::Error> PlcRuntime::force(std::string_view path,
                                             std::span<const std::uint8_t> bytes) {
    const auto location = writable(path, bytes);
    if (!location) {
        return core::Error{location.error()};
    }
    forced_.force(std::string(path), location->offset,
                  std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
    forced_.apply(machine_->memory());
    if (state() == ProgramState::Running) {
        dispatcher_->check_event_inputs();
    }
    return std::nullopt;
}

std::optional<core::Error> PlcRuntime::unforce(std::string_view path) {
    if (!program_) {
        return core::Error{"no program is loaded"};
    }
    const auto location = lookup_variable(image(), path);
    if (!location) {
        return core::Error{location.error()};
    }
    if (!forced_.release(location->offset)) {
        return core::Error{fmt::format("{} is not forced", path)};
    }
    return std::nullopt;
}

// EPOS P firmware specification 10.37: a warm start keeps the RETAIN variables; a store that is
// damaged or of another program is Retain Variable Error 0x6310 and leaves the cold values.
void PlcRuntime::restore_retain() {
    if (!retain_store_ || image().retain.empty()) {
        return;
    }
    const RetainRestore restored = retain_store_->restore(image(), machine_->memory());
    switch (restored.outcome) {
    case RetainOutcome::Restored:
        retain_saved_ = retained_bytes();
        return;
    case RetainOutcome::NoStore:
        return;
    case RetainOutcome::Corrupt:
    case RetainOutcome::OtherProgram:
        report(
            error_code::kRetainVariable,
            fmt::format("retain variables not restored ({}); cold start values", restored.reason),
            std::nullopt);
        return;
    }
}

void PlcRuntime::save_retain_if_changed() {
    if (!retain_store_ || image().retain.empty()) {
        return;
    }
    auto bytes = retained_bytes();
    if (retain_saved_ == bytes) {
        return;
    }
    if (const auto error = retain_store_->save(image(), machine_->memory())) {
        report(error_code::kRetainVariable,
               fmt::format("retain variables not saved: {}", error->message), std::nullopt);
        return;
    }
    retain_saved_ = std::move(bytes);
}

std::vector<std::uint8_t> PlcRuntime::retained_bytes() const {
    std::vector<std::uint8_t> bytes;
    const auto memory = machine_->memory();
    for (const RetainRange& range : image().retain) {
        const auto part = memory.subspan(range.offset, range.size);
        bytes.insert(bytes.end(), part.begin(), part.end());
    }
    return bytes;
}

} // namespace eposp::vm
