#include "evaluator.hpp"

#include "eposp/compiler/sema/symbol.hpp"

#include <charconv>
#include <sstream>
#include <unordered_map>

namespace eposp::reference {

using compiler::sema::fold_case;

namespace {

const ast::Pou* find_pou(const types::FrontEnd& front_end, const std::string& name) {
    for (const ast::CompilationUnit& unit : front_end.units) {
        for (const ast::Pou& pou : unit.pous) {
            if (fold_case(pou.name.name) == fold_case(name)) {
                return &pou;
            }
        }
    }
    return nullptr;
}

} // namespace

Evaluator::Evaluator(std::unique_ptr<types::FrontEnd> front_end)
    : front_end_(std::move(front_end)), program_(*front_end_->program) {
    // Globals first: program instances' initial values may name them.
    const ast::Configuration* configuration = nullptr;
    for (const ast::CompilationUnit& unit : front_end_->units) {
        for (const ast::DeclarationSection& section : unit.global_variable_lists) {
            if (const auto* variables = std::get_if<ast::VarSection>(&section)) {
                for (const ast::VariableDeclaration& declaration : variables->variables) {
                    const sema::Type* type = program_.types().resolve(declaration.type);
                    for (const ast::Identifier& name : declaration.names) {
                        Value& global = globals_[fold_case(name.name)] =
                            make(*type, declaration.initial_value.get());
                        roots_[fold_case(name.name)] = &global;
                    }
                }
            }
        }
        for (const ast::Configuration& each : unit.configurations) {
            if (configuration != nullptr) {
                throw Unsupported("more than one CONFIGURATION");
            }
            configuration = &each;
        }
    }
    if (configuration == nullptr) {
        // Without a configuration every PROGRAM runs in a task of its own, in file order, and
        // is named after its type (docs/st-language.md, "A program").
        for (const ast::CompilationUnit& unit : front_end_->units) {
            for (const ast::Pou& pou : unit.pous) {
                if (pou.kind != ast::PouKind::Program) {
                    continue;
                }
                Value& instance = instances_[fold_case(pou.name.name)] =
                    make(*program_.types().instance(pou), nullptr);
                roots_[fold_case(pou.name.name)] = &instance;
                instances_of_[&pou].push_back(&instance);
                if (task_.empty()) {
                    task_.emplace_back(&pou, &instance);
                }
            }
        }
        return;
    }
    std::vector<const ast::DeclarationSection*> sections;
    for (const ast::DeclarationSection& section : configuration->sections) {
        sections.push_back(&section);
    }
    for (const ast::Resource& resource : configuration->resources) {
        for (const ast::DeclarationSection& section : resource.sections) {
            sections.push_back(&section);
        }
    }
    for (const ast::DeclarationSection* section : sections) {
        const auto* variables = std::get_if<ast::VarSection>(section);
        if (variables == nullptr) {
            throw Unsupported("VAR_ACCESS");
        }
        for (const ast::VariableDeclaration& declaration : variables->variables) {
            const sema::Type* type = program_.types().resolve(declaration.type);
            for (const ast::Identifier& name : declaration.names) {
                Value& global = globals_[fold_case(name.name)] =
                    make(*type, declaration.initial_value.get());
                roots_[fold_case(configuration->name.name + "." + name.name)] = &global;
            }
        }
    }
    // Tasks numbered as the image numbers them: each resource's TASKs in order, and a
    // background task for a program instance without one where it is declared (6.8.2).
    std::vector<std::vector<std::pair<const ast::Pou*, Value*>>> tasks;
    for (const ast::Resource& resource : configuration->resources) {
        std::unordered_map<std::string, std::size_t> task_of;
        for (const ast::TaskDeclaration& task : resource.tasks) {
            task_of[fold_case(task.name.name)] = tasks.size();
            tasks.emplace_back();
        }
        for (const ast::ProgramInstance& declared : resource.programs) {
            if (!declared.connections.empty()) {
                throw Unsupported("program connections");
            }
            const ast::Pou* pou = find_pou(*front_end_, declared.type.name);
            Value& instance = instances_[fold_case(declared.name.name)] =
                make(*program_.types().instance(*pou), nullptr);
            roots_[fold_case(declared.name.name)] = &instance;
            instances_of_[pou].push_back(&instance);
            const auto task =
                declared.task ? task_of.find(fold_case(declared.task->name)) : task_of.end();
            if (task != task_of.end()) {
                tasks[task->second].emplace_back(pou, &instance);
            } else {
                tasks.push_back({{pou, &instance}});
            }
        }
    }
    if (!tasks.empty()) {
        task_ = tasks.front();
    }
}

Value& Evaluator::instance_of(const ast::Pou& program) {
    std::vector<Value*>& found = instances_of_[&program];
    if (found.size() > 1) {
        throw Unsupported("a call of a PROGRAM with several instances");
    }
    if (found.empty()) {
        const std::string key = fold_case(program.name.name);
        if (instances_.contains(key)) {
            throw Unsupported("a PROGRAM named like another program's instance");
        }
        Value& instance = instances_[key] = make(*program_.types().instance(program), nullptr);
        roots_[key] = &instance;
        found.push_back(&instance);
    }
    return *found.front();
}

bool Evaluator::is_library(const ast::Pou* pou) const {
    for (const ast::CompilationUnit& unit : front_end_->library_units) {
        for (const ast::Pou& each : unit.pous) {
            if (&each == pou) {
                return true;
            }
        }
    }
    return false;
}

Value Evaluator::make(const sema::Type& type, const ast::Initializer* initializer) {
    Value value;
    value.type = &type;
    switch (shape_of(type)) {
    case Shape::Integer:
        if (type.range) {
            value.bits = static_cast<std::uint64_t>(type.range->lower);
        } else if (type.kind == sema::TypeKind::Enum && !type.enumerators.empty()) {
            value.bits = static_cast<std::uint64_t>(type.enumerators.front().second);
        }
        break;
    case Shape::Real:
    case Shape::Lreal:
    case Shape::String:
        break;
    case Shape::Array: {
        std::size_t count = 1;
        for (const sema::ArrayDimension& dimension : type.dimensions) {
            count *= dimension.count;
        }
        const Value element = make(*type.element, nullptr);
        value.elements.assign(count, element);
        break;
    }
    case Shape::Record: {
        // An instance's initial values may name its constants declared before them.
        Frame building{.instance = &value};
        Frame* const outer = frame_;
        if (type.kind == sema::TypeKind::Instance) {
            frame_ = &building;
        }
        for (const sema::Field& field : type.fields) {
            if (field.section == ast::VarSectionKind::InOut ||
                field.section == ast::VarSectionKind::Temp ||
                field.section == ast::VarSectionKind::External) {
                continue;
            }
            // A standard FB is its interface; its state is the evaluator's own.
            if (is_library(type.pou) && field.section == ast::VarSectionKind::Var) {
                continue;
            }
            value.names.push_back(fold_case(field.name));
            value.elements.push_back(make(*field.type, field.declaration != nullptr
                                                           ? field.declaration->initial_value.get()
                                                           : nullptr));
        }
        frame_ = outer;
        break;
    }
    case Shape::Unsupported:
        throw Unsupported("the type " + type.name);
    }
    if (initializer == nullptr) {
        initializer = type.initial_value;
    }
    if (initializer != nullptr) {
        initialise(value, *initializer);
    }
    return value;
}

void Evaluator::initialise(Value& value, const ast::Initializer& initializer) {
    if (const auto* expression = std::get_if<ast::ExpressionPtr>(&initializer.value)) {
        value = store(eval(**expression), *value.type);
    } else if (const auto* elements =
                   std::get_if<std::vector<ast::ArrayInitElement>>(&initializer.value)) {
        std::size_t next = 0;
        for (const ast::ArrayInitElement& element : *elements) {
            std::int64_t repeat = 1;
            if (element.repeat_count) {
                repeat = eval(*element.repeat_count).as_signed();
            }
            for (std::int64_t i = 0; i < repeat && next < value.elements.size(); ++i, ++next) {
                if (element.value) {
                    initialise(value.elements[next], *element.value);
                }
            }
        }
    } else {
        for (const ast::StructInitElement& element :
             std::get<std::vector<ast::StructInitElement>>(initializer.value)) {
            if (Value* member = value.member(fold_case(element.member.name));
                member && element.value) {
                initialise(*member, *element.value);
            }
        }
    }
}

void Evaluator::scan(std::int64_t now_ns) {
    now_ns_ = now_ns;
    steps_ = 0;
    for (const auto& [pou, instance] : task_) {
        Frame frame{.pou = pou, .instance = instance};
        frame_ = &frame;
        locals(*pou, frame, true);
        statements(pou->body);
        frame_ = nullptr;
    }
}

const Value* Evaluator::find(const std::string& path) const {
    const std::string folded = fold_case(path);
    // The longest known root that prefixes the path, then members and indices.
    std::size_t end = folded.size();
    while (true) {
        const auto root = roots_.find(folded.substr(0, end));
        if (root != roots_.end()) {
            const Value* value = root->second;
            std::size_t at = end;
            while (value != nullptr && at < folded.size()) {
                if (folded[at] == '.') {
                    const std::size_t next = folded.find_first_of(".[", at + 1);
                    value = value->member(folded.substr(at + 1, next - at - 1));
                    at = next == std::string::npos ? folded.size() : next;
                } else if (folded[at] == '[') {
                    // `a[1, 2]` and `a[1][2]` both name an element of ARRAY[.., ..].
                    if (value->type->kind != sema::TypeKind::Array) {
                        return nullptr;
                    }
                    const sema::Type& array = *value->type;
                    std::size_t flat = 0;
                    std::size_t dimension = 0;
                    while (dimension < array.dimensions.size()) {
                        if (at >= folded.size() || folded[at] != '[') {
                            return nullptr;
                        }
                        const std::size_t close = folded.find(']', at);
                        if (close == std::string::npos) {
                            return nullptr;
                        }
                        std::istringstream indices(folded.substr(at + 1, close - at - 1));
                        std::string index;
                        while (std::getline(indices, index, ',')) {
                            if (dimension >= array.dimensions.size()) {
                                return nullptr;
                            }
                            const sema::ArrayDimension& bounds = array.dimensions[dimension++];
                            if (index.find_first_not_of(' ') == std::string::npos) {
                                return nullptr;
                            }
                            std::int64_t i = 0;
                            const auto [end_of_number, error] =
                                std::from_chars(index.data() + index.find_first_not_of(' '),
                                                index.data() + index.size(), i);
                            if (error != std::errc{} ||
                                index.find_first_not_of(
                                    ' ', static_cast<std::size_t>(end_of_number - index.data())) !=
                                    std::string::npos) {
                                return nullptr; // not a number
                            }
                            i -= bounds.lower;
                            if (i < 0 || i >= bounds.count) {
                                return nullptr;
                            }
                            flat = flat * bounds.count + static_cast<std::size_t>(i);
                        }
                        at = close + 1;
                    }
                    value = &value->elements.at(flat);
                } else {
                    return nullptr;
                }
            }
            return value;
        }
        const std::size_t dot = folded.find_last_of(".[", end - 1);
        if (dot == std::string::npos || dot == 0) {
            return nullptr;
        }
        end = dot;
    }
}

} // namespace eposp::reference
