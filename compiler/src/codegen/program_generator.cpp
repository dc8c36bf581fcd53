#include "program_generator.hpp"

#include "../checks/located_variables.hpp"
#include "constant_declarations.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "eposp/vm/image_limits.hpp"
#include "pou_generator.hpp"

#include <fmt/format.h>

namespace eposp::compiler::codegen {

namespace {

// IEC 61131-3 leaves the task of a program without a configuration to the implementer; this
// is CODESYS's default cycle.
constexpr std::uint64_t kDefaultIntervalNs = 10'000'000;
constexpr std::uint32_t kStackMargin = 256;

vm::PouKind vm_kind(ast::PouKind kind) {
    switch (kind) {
    case ast::PouKind::Function:
        return vm::PouKind::Function;
    case ast::PouKind::FunctionBlock:
        return vm::PouKind::FunctionBlock;
    case ast::PouKind::Program:
        return vm::PouKind::Program;
    }
    return vm::PouKind::Function;
}

} // namespace

ProgramGenerator::ProgramGenerator(PouSource program, PouSource library, types::TypedProgram& typed,
                                   Diagnostics& diagnostics, const CompileOptions& options)
    : program_(program), library_(library), typed_(typed), diagnostics_(diagnostics),
      options_(options), types_(typed.types()) {
    for (const ast::CompilationUnit& unit : library_.units) {
        for (const ast::Pou& pou : unit.pous) {
            pou_models_[&pou] = &library_.model;
        }
    }
    for (const ast::CompilationUnit& unit : program_.units) {
        for (const ast::Pou& pou : unit.pous) {
            pou_models_[&pou] = &program_.model;
        }
    }
    for (const ast::CompilationUnit& unit : program_.units.last(program_.linked)) {
        for (const ast::Pou& pou : unit.pous) {
            linked_pous_.insert(&pou);
        }
    }
}

const ast::Pou* ProgramGenerator::library_pou(std::string_view name) const {
    const std::string key = sema::fold_case(name);
    for (const ast::CompilationUnit& unit : library_.units) {
        for (const ast::Pou& pou : unit.pous) {
            if (sema::fold_case(pou.name.name) == key) {
                return &pou;
            }
        }
    }
    return nullptr;
}

std::optional<Place> ProgramGenerator::global(std::string_view name) const {
    const auto it = globals_.find(sema::fold_case(name));
    return it == globals_.end() ? std::nullopt : std::optional(it->second);
}

std::optional<Place> ProgramGenerator::program_instance_variable(std::string_view name) const {
    const auto it = instances_.find(sema::fold_case(name));
    return it == instances_.end() ? std::nullopt : std::optional(it->second);
}

std::uint32_t ProgramGenerator::pou_index(const ast::Pou& pou) {
    if (const auto it = pou_indices_.find(&pou); it != pou_indices_.end()) {
        return it->second;
    }
    const sema::Type* instance =
        pou.kind == ast::PouKind::Function ? nullptr : types_.instance(pou);
    const std::uint32_t index = builder_.declare_pou(pou.name.name, vm_kind(pou.kind),
                                                     instance != nullptr ? instance->size : 0);
    pou_indices_[&pou] = index;
    queue_.push_back({&pou, pou_models_.at(&pou), index});
    return index;
}

bool ProgramGenerator::is_host_function(const ast::Pou& pou) const {
    const auto it = pou_models_.find(&pou);
    return it != pou_models_.end() && it->second == &library_.model &&
           pou.kind == ast::PouKind::Function && pou.body.empty();
}

bool ProgramGenerator::is_native_block(const ast::Pou& pou) const {
    return linked_pous_.contains(&pou) && pou.kind == ast::PouKind::FunctionBlock &&
           pou.body.empty();
}

std::uint32_t ProgramGenerator::import(const std::string& name,
                                       const vm::NativeSignature& signature) {
    if (const auto it = imports_.find(name); it != imports_.end()) {
        return it->second;
    }
    const std::uint32_t index = builder_.import(name, signature);
    imports_[name] = index;
    return index;
}

vm::Operand ProgramGenerator::constant(const std::vector<std::uint8_t>& bytes,
                                       std::uint32_t align) {
    auto [it, inserted] = constants_.emplace(std::pair(bytes, align), 0);
    if (inserted) {
        it->second = builder_.constant(bytes, align);
    }
    return vm::Operand::global(it->second);
}

std::optional<vm::Image> ProgramGenerator::generate() {
    builder_.allocate(0, 1); // the NULL guard has its initial value even in an empty image
    check_type_defaults();
    // Global variable lists are watched by the bare variable name (`count`), configuration
    // globals with the configuration's (`Cell.count`).
    for (const ast::CompilationUnit& unit : program_.units) {
        lay_out_global_section("", unit.global_variable_lists);
    }
    bool has_configuration = false;
    for (const ast::CompilationUnit& unit : program_.units) {
        for (const ast::Configuration& configuration : unit.configurations) {
            has_configuration = true;
            lay_out_globals(configuration);
        }
    }
    // Every user POU is generated, called or not, so that all its errors are reported; a
    // linked library's only when called.
    for (const ast::CompilationUnit& unit :
         program_.units.first(program_.units.size() - program_.linked)) {
        for (const ast::Pou& pou : unit.pous) {
            pou_index(pou);
        }
    }
    // A native function's declaration is checked whether it is called or not: a library's
    // author learns that the C++ side cannot be written for it.
    for (const ast::CompilationUnit& unit : program_.units.last(program_.linked)) {
        for (const ast::Pou& pou : unit.pous) {
            if (is_native_function(pou)) {
                native_function(pou);
            }
        }
    }
    if (has_configuration) {
        for (const ast::CompilationUnit& unit : program_.units) {
            for (const ast::Configuration& configuration : unit.configurations) {
                lay_out_programs(configuration);
                publish_access_paths(configuration);
            }
        }
    } else {
        default_program_instances();
    }
    generate_bodies();
    connect_programs();
    // Recursion (the checks stage) is an error already: the limits below assume none.
    if (diagnostics_.has_errors()) {
        return std::nullopt;
    }
    check_limits();
    if (diagnostics_.has_errors()) {
        return std::nullopt;
    }
    // No task at all (no PROGRAM) is the checks' warning W0407 (checks/runnable_programs.cpp).
    for (vm::Task& task : tasks_) {
        task.stack_size = static_cast<std::uint32_t>(stack_size()); // checked above
        builder_.task(std::move(task));
    }
    auto image = builder_.finish();
    if (!image) {
        diagnostics_.error(DiagnosticCode::E0001, {}, "internal error: " + image.error());
        return std::nullopt;
    }
    return std::move(*image);
}

void ProgramGenerator::generate_bodies() {
    while (!queue_.empty()) {
        const QueuedPou next = queue_.front();
        queue_.pop_front();
        PouGenerator generator(*this, *next.model, *next.pou, next.index);
        pou_frames_total_ += generator.generate();
    }
}

void ProgramGenerator::check_type_defaults() {
    for (const ast::CompilationUnit& unit : program_.units) {
        for (const ast::TypeDeclaration& declaration : unit.types) {
            const sema::Symbol* symbol = program_.model.global().find_member(declaration.name.name);
            if (declaration.initial_value && symbol != nullptr && symbol->type == &declaration) {
                if (const sema::Type* type = types_.named(*symbol)) {
                    default_value(*type);
                }
            }
        }
    }
}

std::uint64_t ProgramGenerator::stack_size() const {
    // Without recursion (6.6.1.1) a chain of calls holds each POU's frame at most once, so the
    // sum of all frames bounds the stack any task needs.
    return pou_frames_total_ + kStackMargin;
}

void ProgramGenerator::lay_out_globals(const ast::Configuration& configuration) {
    const std::string path_prefix = configuration.name.name + ".";
    lay_out_global_section(path_prefix, configuration.sections);
    for (const ast::Resource& resource : configuration.resources) {
        lay_out_global_section(path_prefix, resource.sections);
    }
}

void ProgramGenerator::lay_out_global_section(
    const std::string& path_prefix, const std::vector<ast::DeclarationSection>& sections) {
    for (const ast::DeclarationSection& section : sections) {
        const auto* variables = std::get_if<ast::VarSection>(&section);
        if (variables == nullptr) {
            continue;
        }
        for (const ast::VariableDeclaration& declaration : variables->variables) {
            const sema::Type* type = types_.resolve(declaration.type);
            if (type == nullptr) {
                continue;
            }
            for (const ast::Identifier& name : declaration.names) {
                const std::uint32_t offset = builder_.allocate(type->size, type->align);
                std::vector<std::uint8_t> bytes(type->size);
                initial_value(*type, declaration.initial_value.get(), bytes);
                builder_.initialise(offset, bytes);
                globals_[sema::fold_case(name.name)] =
                    Place::direct(*type, vm::Operand::global(offset), !variables->constant);
                add_symbol(path_prefix + name.name, *type, offset, variables->constant);
                if (variables->retention == ast::Retention::Retain) {
                    builder_.retain(offset, type->size);
                }
                if (declaration.address) {
                    add_io_binding(*declaration.address, *type, offset);
                }
            }
        }
    }
}

std::optional<Place> ProgramGenerator::instance_of_program(const ast::Pou& program) {
    const auto it = instance_paths_.find(&program);
    if (it == instance_paths_.end()) {
        // Not instantiated by the configuration (or the configuration is ignored, as under
        // `eposp test`): one instance for the calls, watched by the program's name.
        if (instances_.contains(sema::fold_case(program.name.name))) {
            refused_by_checks(DiagnosticCode::E0422); // checks/program_instances.cpp
            return std::nullopt;
        }
        program_instance(program, program.name.name, false);
        return instances_.at(sema::fold_case(program.name.name));
    }
    if (it->second.size() > 1) {
        refused_by_checks(DiagnosticCode::E0422);
        return std::nullopt;
    }
    return instances_.at(sema::fold_case(it->second.front()));
}

std::uint32_t ProgramGenerator::program_instance(const ast::Pou& program, const std::string& path,
                                                 bool retain) {
    const sema::Type* type = types_.instance(program);
    const std::uint32_t offset = builder_.allocate(type->size, type->align);
    std::vector<std::uint8_t> bytes(type->size);
    initial_value(*type, nullptr, bytes);
    builder_.initialise(offset, bytes);
    add_symbol(path, *type, offset);
    instances_[sema::fold_case(path)] = Place::direct(*type, vm::Operand::global(offset));
    instance_paths_[&program].push_back(path);
    // RETAIN variables of the program (6.5.6), or all of it for a RETAIN instance.
    if (retain) {
        builder_.retain(offset, type->size);
    }
    for (const ast::DeclarationSection& section : program.sections) {
        const auto* variables = std::get_if<ast::VarSection>(&section);
        if (variables == nullptr) {
            continue;
        }
        for (const ast::VariableDeclaration& declaration : variables->variables) {
            for (const ast::Identifier& name : declaration.names) {
                const sema::Field* field = type->field(name.name);
                if (field == nullptr) {
                    continue;
                }
                if (!retain && variables->retention == ast::Retention::Retain) {
                    builder_.retain(offset + field->offset, field->type->size);
                }
                if (declaration.address) {
                    add_io_binding(*declaration.address, *field->type, offset + field->offset);
                }
            }
        }
    }
    return offset;
}

void ProgramGenerator::lay_out_programs(const ast::Configuration& configuration) {
    for (const ast::Resource& resource : configuration.resources) {
        std::vector<std::size_t> task_of; // index into tasks_ per TASK of this resource
        for (const ast::TaskDeclaration& declaration : resource.tasks) {
            vm::Task task;
            task.name = declaration.name.name;
            // The checks refused the properties the controller cannot run (checks/tasks.cpp).
            if (declaration.priority) {
                const auto priority = typed_.constants().fold_integer(*declaration.priority);
                if (priority && *priority >= 0 && *priority <= UINT32_MAX) {
                    task.priority = static_cast<std::uint32_t>(*priority);
                }
            }
            bind_task_event(declaration, task);
            if (declaration.single) {
                task.kind = vm::TaskKind::Event;
                const auto* name = std::get_if<ast::NameExpression>(&declaration.single->node);
                if (const auto place = name != nullptr ? global(name->name.name) : std::nullopt) {
                    task.event_offset = place->operand.offset();
                }
            } else if (task.event.empty()) {
                task.interval_ns = task_interval(declaration);
            }
            task_of.push_back(tasks_.size());
            tasks_.push_back(std::move(task));
        }
        for (const ast::ProgramInstance& instance : resource.programs) {
            const sema::Symbol* symbol = program_.model.resolved(instance.type);
            if (symbol == nullptr || symbol->kind != sema::SymbolKind::Pou) {
                continue; // reported by the resolver
            }
            const std::uint32_t offset = program_instance(
                *symbol->pou, instance.name.name, instance.retention == ast::Retention::Retain);
            const vm::TaskEntry entry{pou_index(*symbol->pou), offset};
            std::size_t task = tasks_.size();
            if (instance.task) {
                for (std::size_t i = 0; i < resource.tasks.size(); ++i) {
                    if (sema::fold_case(resource.tasks[i].name.name) ==
                        sema::fold_case(instance.task->name)) {
                        task = task_of[i];
                    }
                }
            }
            if (task == tasks_.size()) {
                // 6.8.2: a program without a task runs in the background at the lowest priority.
                vm::Task background;
                background.name = instance.name.name + "Task";
                background.interval_ns = kDefaultIntervalNs;
                background.priority = UINT32_MAX;
                tasks_.push_back(std::move(background));
            }
            if (!instance.connections.empty()) {
                connected_.push_back({&instance, symbol->pou, task, tasks_[task].entries.size()});
            }
            tasks_[task].entries.push_back(entry);
        }
    }
}

void ProgramGenerator::connect_programs() {
    for (const Connected& connected : connected_) {
        vm::TaskEntry& entry = tasks_[connected.task].entries[connected.entry];
        const sema::Type& type = *types_.instance(*connected.program);
        const std::uint32_t wrapper = builder_.declare_pou(
            connected.instance->name.name + ".connections", vm::PouKind::Program, type.size);
        PouGenerator generator(*this, program_.model, *connected.program, wrapper);
        pou_frames_total_ += generator.generate_connections(*connected.instance, entry.pou);
        entry.pou = wrapper;
    }
}

void ProgramGenerator::bind_task_event(const ast::TaskDeclaration& declaration, vm::Task& task) {
    // The checks refused every event attribute but one the host accepts (checks/tasks.cpp).
    for (const ast::Attribute& attribute : declaration.attributes) {
        if (sema::fold_case(attribute.name) == sema::fold_case("event")) {
            task.kind = vm::TaskKind::Event;
            task.event = attribute.value;
            return;
        }
    }
}

std::uint64_t ProgramGenerator::task_interval(const ast::TaskDeclaration& task) {
    const auto* literal =
        task.interval ? std::get_if<ast::LiteralExpression>(&task.interval->node) : nullptr;
    const auto* duration =
        literal != nullptr ? std::get_if<ast::DurationLiteral>(&literal->value) : nullptr;
    // A missing INTERVAL takes the default; the checks refused one below a tick.
    return duration != nullptr && duration->nanoseconds > 0
               ? static_cast<std::uint64_t>(duration->nanoseconds)
               : kDefaultIntervalNs;
}

void ProgramGenerator::default_program_instances() {
    for (const ast::CompilationUnit& unit : program_.units) {
        for (const ast::Pou& pou : unit.pous) {
            if (pou.kind != ast::PouKind::Program) {
                continue;
            }
            const std::uint32_t offset = program_instance(pou, pou.name.name, false);
            vm::Task task;
            task.name = pou.name.name + "Task";
            task.interval_ns = kDefaultIntervalNs;
            task.entries.push_back({pou_index(pou), offset});
            tasks_.push_back(std::move(task));
        }
    }
}

void ProgramGenerator::add_symbol(const std::string& path, const sema::Type& type,
                                  std::uint32_t offset, bool constant) {
    // A constant is refused online writes and forces like a READ_ONLY access path.
    builder_.symbol(path, type_descriptor(type), offset, constant);
}

std::uint32_t ProgramGenerator::type_descriptor(const sema::Type& type) {
    if (const auto it = descriptors_.find(&type); it != descriptors_.end()) {
        return it->second;
    }
    vm::TypeDescriptor descriptor;
    descriptor.name = type.name;
    descriptor.size = type.size;
    switch (type.kind) {
    case sema::TypeKind::String:
        descriptor.kind = vm::TypeKind::String;
        break;
    case sema::TypeKind::Array: {
        // A multi-dimensional array is an array of arrays (as symbol_lookup walks it).
        std::uint32_t element = type_descriptor(*type.element);
        std::uint32_t size = type.element->size;
        for (std::size_t d = type.dimensions.size(); d-- > 1;) {
            size *= type.dimensions[d].count;
            vm::TypeDescriptor row;
            row.name = type.name;
            row.kind = vm::TypeKind::Array;
            row.size = size;
            row.element = element;
            row.lower = static_cast<std::int32_t>(type.dimensions[d].lower);
            row.count = type.dimensions[d].count;
            element = builder_.type(std::move(row));
        }
        descriptor.kind = vm::TypeKind::Array;
        descriptor.element = element;
        descriptor.lower = static_cast<std::int32_t>(type.dimensions.front().lower);
        descriptor.count = type.dimensions.front().count;
        break;
    }
    case sema::TypeKind::Struct:
    case sema::TypeKind::Instance:
        descriptor.kind = vm::TypeKind::Struct;
        for (const sema::Type* part = &type; part != nullptr; part = part->base) {
            for (const sema::Field& field : part->fields) {
                const bool constant =
                    part->pou != nullptr && is_constant(*part->pou, field.declaration);
                descriptor.fields.push_back(
                    {field.name, type_descriptor(*field.type), field.offset, constant});
            }
        }
        break;
    default:
        descriptor.kind = vm::TypeKind::Elementary;
        descriptor.scalar = sema::scalar_of(type);
        descriptor.size = vm::scalar_size(descriptor.scalar);
        if (type.range) {
            descriptor.subrange = true;
            descriptor.lowest = type.range->lower;
            descriptor.highest = type.range->upper;
        }
        for (const auto& [name, value] : type.enumerators) {
            descriptor.enumerators.push_back({name, value});
        }
        break;
    }
    const std::uint32_t index = builder_.type(std::move(descriptor));
    descriptors_[&type] = index;
    return index;
}

std::optional<Place> ProgramGenerator::direct_variable(const ast::DirectAddress& address) {
    const auto key =
        std::tuple(static_cast<int>(address.area), static_cast<int>(address.size), address.path);
    if (const auto it = direct_variables_.find(key); it != direct_variables_.end()) {
        return it->second;
    }
    const sema::Type& variable = types_.elementary(checks::direct_address_type(address.size));
    if (address.path.empty() || checks::location_mismatch(address, variable)) {
        refused_by_checks(DiagnosticCode::E0420); // checks/located_variables.cpp
        return std::nullopt;
    }
    const std::uint32_t offset = builder_.allocate(variable.size, variable.align);
    add_io_binding(address, variable, offset);
    // Inputs are read-only in code: the process image writes them.
    const Place place = Place::direct(variable, vm::Operand::global(offset),
                                      address.area != ast::DirectAddress::Area::Input);
    direct_variables_.emplace(key, place);
    return place;
}

void ProgramGenerator::refused_by_checks(DiagnosticCode code) {
    diagnostics_.error(DiagnosticCode::E0001, {},
                       fmt::format("internal error: code generation met what an earlier stage "
                                   "refuses ({}), and it did not report it",
                                   describe(code).name));
}

void ProgramGenerator::disagrees_with_typing(const SourceRange& range,
                                             const sema::Type& computed,
                                             const sema::Type* typed) {
    diagnostics_.error(DiagnosticCode::E0001, range,
                       fmt::format("internal error: code generation computed a {} where the "
                                   "typing stage gave {}",
                                   computed.name, typed != nullptr ? typed->name : "no type"));
}

void ProgramGenerator::add_io_binding(const ast::DirectAddress& address, const sema::Type& type,
                                      std::uint32_t offset) {
    if (address.path.empty()) {
        return; // `%I*`: bound in the configuration (not supported yet)
    }
    if (checks::location_mismatch(address, type)) {
        refused_by_checks(DiagnosticCode::E0420); // checks/located_variables.cpp
        return;
    }
    vm::IoBinding binding{.type = sema::scalar_of(type), .offset = offset};
    switch (address.area) {
    case ast::DirectAddress::Area::Input:
        binding.area = vm::IoArea::Input;
        break;
    case ast::DirectAddress::Area::Output:
        binding.area = vm::IoArea::Output;
        break;
    case ast::DirectAddress::Area::Memory:
        binding.area = vm::IoArea::Memory;
        break;
    }
    // Byte addressing as CODESYS: %IW4 is the word at byte 8, %IX1.3 bit 3 of byte 1.
    if (address.size == ast::DirectAddress::Size::None ||
        address.size == ast::DirectAddress::Size::Bit) {
        binding.bit = static_cast<std::uint8_t>(address.path[1]);
    }
    binding.byte_address = address.path[0] * checks::direct_address_unit(address.size);
    builder_.binding(binding);
}

} // namespace eposp::compiler::codegen
