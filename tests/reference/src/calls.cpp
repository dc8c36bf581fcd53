// Calls of user FUNCTIONs and FUNCTION_BLOCKs (IEC 61131-3 ed. 3, 6.6.1.4): every argument is
// evaluated before the call, in the order written, and passed by value (VAR_IN_OUT by
// reference); outputs are copied out after it.

#include "eposp/compiler/sema/symbol.hpp"
#include "evaluator.hpp"

namespace eposp::reference {

using compiler::sema::fold_case;

namespace {

/// The EN or ENO argument of a call (6.6.1.2.2); null if it has none.
const ast::Argument* enable(const ast::CallExpression& node, const char* name) {
    for (const ast::Argument& argument : node.arguments) {
        if (argument.name && fold_case(argument.name->name) == name) {
            return &argument;
        }
    }
    return nullptr;
}

} // namespace

void Evaluator::locals(const ast::Pou& pou, Frame& frame, bool temporaries_only) {
    for (const ast::DeclarationSection& section : pou.sections) {
        const auto* variables = std::get_if<ast::VarSection>(&section);
        if (variables == nullptr || variables->kind == ast::VarSectionKind::InOut ||
            variables->kind == ast::VarSectionKind::External ||
            (temporaries_only && variables->kind != ast::VarSectionKind::Temp)) {
            continue;
        }
        for (const ast::VariableDeclaration& declaration : variables->variables) {
            for (const ast::Identifier& name : declaration.names) {
                frame.locals[fold_case(name.name)] = make(
                    *program_.types().resolve(declaration.type), declaration.initial_value.get());
            }
        }
    }
    if (!temporaries_only && pou.return_type) {
        frame.locals[fold_case(pou.name.name)] =
            make(*program_.types().resolve(*pou.return_type), nullptr);
    }
}

Value Evaluator::call(const ast::Expression& expression, const ast::CallExpression& node) {
    const types::CallTarget* target = program_.call_target(expression);
    if (target == nullptr) {
        throw Unsupported("a call the typing stage did not resolve");
    }
    // 6.6.1.2.2, as docs/st-language.md says: with EN FALSE the call is not executed, ENO is
    // FALSE and the call gives 0 (an empty string); an assignment of it keeps its target.
    const ast::Argument* en = enable(node, "EN");
    const ast::Argument* eno = enable(node, "ENO");
    const bool enabled = en == nullptr || eval(*en->value).bits != 0;
    Value result;
    if (enabled) {
        result = execute(target, node);
    } else {
        skipped_ = &expression;
        if (target->result != nullptr) {
            result = make(*target->result, nullptr);
        }
    }
    if (eno != nullptr) {
        Value& flag = place(*eno->value);
        flag = store(integer(elementary(ast::ElementaryType::Bool), enabled ? 1 : 0), *flag.type);
    }
    return result;
}

Value Evaluator::execute(const types::CallTarget* target, const ast::CallExpression& node) {
    switch (target->kind) {
    case types::CallKind::Function:
        return pou_call(node, *target->pou, nullptr);
    case types::CallKind::FunctionBlock:
        return pou_call(node, *target->pou, &place(*node.callee));
    case types::CallKind::StandardFunctionBlock:
        return pou_call(node, *target->pou, &place(*node.callee), target->name);
    case types::CallKind::StandardFunction:
        return standard_function(*target, node);
    case types::CallKind::Conversion:
        return conversion(*target, store(eval(*types::standard_arguments("TO", node).at(0)->value),
                                         *target->operand));
    }
    throw Unsupported("this call");
}

Value Evaluator::pou_call(const ast::CallExpression& node, const ast::Pou& pou, Value* instance,
                          const std::string& standard) {
    // The inputs and in-outs in declaration order, for positional arguments.
    std::vector<std::pair<std::string, ast::VarSectionKind>> formals;
    std::unordered_map<std::string, ast::VarSectionKind> sections;
    for (const ast::DeclarationSection& section : pou.sections) {
        const auto* variables = std::get_if<ast::VarSection>(&section);
        if (variables == nullptr) {
            continue;
        }
        for (const ast::VariableDeclaration& declaration : variables->variables) {
            for (const ast::Identifier& name : declaration.names) {
                sections[fold_case(name.name)] = variables->kind;
                if (variables->kind == ast::VarSectionKind::Input ||
                    variables->kind == ast::VarSectionKind::InOut) {
                    formals.emplace_back(fold_case(name.name), variables->kind);
                }
            }
        }
    }
    Frame frame{.pou = &pou, .instance = instance};
    locals(pou, frame, instance != nullptr);
    std::vector<std::pair<std::string, Value>> inputs;
    std::vector<const ast::Argument*> outputs;
    std::size_t next = 0;
    for (const ast::Argument& argument : node.arguments) {
        if (argument.name &&
            (fold_case(argument.name->name) == "EN" || fold_case(argument.name->name) == "ENO")) {
            continue; // handled by call()
        }
        if (argument.kind == ast::Argument::Kind::Output) {
            outputs.push_back(&argument);
            continue;
        }
        std::string name;
        if (argument.name) {
            name = fold_case(argument.name->name);
        } else if (next < formals.size()) {
            name = formals[next++].first;
        } else {
            throw Unsupported("a call with more arguments than inputs");
        }
        if (sections[name] == ast::VarSectionKind::InOut) {
            frame.references[name] = &place(*argument.value);
        } else {
            inputs.emplace_back(name, eval(*argument.value));
        }
    }
    for (auto& [name, value] : inputs) {
        Value* slot = instance != nullptr ? instance->member(name) : &frame.locals[name];
        if (slot == nullptr) {
            throw Unsupported("the input " + name);
        }
        *slot = store(value, *slot->type);
    }
    Frame* caller = frame_;
    const int line = line_;
    frame_ = &frame;
    if (standard.empty()) {
        statements(pou.body);
    } else {
        standard_function_block(standard, *instance);
    }
    frame_ = caller;
    line_ = line;
    for (const ast::Argument* argument : outputs) {
        const std::string name = fold_case(argument->name->name);
        const Value* value = instance != nullptr ? instance->member(name) : &frame.locals[name];
        if (value == nullptr || value->type == nullptr) {
            throw Unsupported("the output " + name);
        }
        Value result = *value;
        if (argument->negated) {
            result.bits = result.bits == 0 ? 1 : 0;
        }
        Value& target = place(*argument->value);
        target = store(result, *target.type);
    }
    if (instance != nullptr || !pou.return_type) {
        return Value{};
    }
    return frame.locals[fold_case(pou.name.name)];
}

} // namespace eposp::reference
