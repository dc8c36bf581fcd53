#include "eposp/compiler/ast/ast_printer.hpp"

#include <sstream>

namespace eposp::compiler::ast {

namespace {

template <typename... Fs>
struct Overloaded : Fs... {
    using Fs::operator()...;
};
template <typename... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

std::string_view operator_name(BinaryOperator op) {
    static constexpr std::string_view kNames[] = {"**", "*",  "/", "MOD", "+",   "-",   "<", ">",
                                                  "<=", ">=", "=", "<>",  "AND", "XOR", "OR"};
    return kNames[static_cast<std::size_t>(op)];
}

std::string_view operator_name(UnaryOperator op) {
    static constexpr std::string_view kNames[] = {"neg", "plus", "NOT"};
    return kNames[static_cast<std::size_t>(op)];
}

/// Writes one tree as nested parentheses; every node kind prints its own tag.
class Printer {
public:
    Printer() = default;
    /// Laid out for reading: statements on lines of their own, expressions with their notes.
    explicit Printer(const DumpLayout& layout) : layout_(&layout) {}

    std::string text() const { return out_.str(); }

    void literal(const Literal& value) {
        std::visit(
            Overloaded{
                [&](const IntegerLiteral& v) {
                    out_ << "(int " << (v.negative ? "-" : "") << v.magnitude;
                    type_suffix(v.type);
                },
                [&](const RealLiteral& v) {
                    out_ << "(real " << v.value;
                    type_suffix(v.type);
                },
                [&](const BoolLiteral& v) { out_ << "(bool " << (v.value ? "TRUE" : "FALSE"); },
                [&](const DurationLiteral& v) {
                    out_ << "(" << name_of(v.type) << " " << v.nanoseconds << "ns";
                },
                [&](const DateTimeLiteral& v) {
                    out_ << "(" << name_of(v.type) << " " << v.nanoseconds << "ns";
                },
                [&](const StringLiteral& v) {
                    out_ << "(" << name_of(v.type) << " ";
                    if (const auto* narrow = std::get_if<std::string>(&v.value)) {
                        out_ << '"' << *narrow << '"';
                    } else {
                        out_ << std::get<std::u16string>(v.value).size() << " units";
                    }
                },
                [&](const EnumValueLiteral& v) {
                    out_ << "(enum " << v.type_name.name << " " << v.value.name;
                },
                [&](const NullLiteral&) { out_ << "(null"; },
            },
            value);
        out_ << ")";
    }

    void expression(const Expression& e) {
        std::visit(Overloaded{
                       [&](const LiteralExpression& v) { literal(v.value); },
                       [&](const NameExpression& v) { out_ << "(name " << v.name.name << ")"; },
                       [&](const DirectAddressExpression& v) { address(v.address); },
                       [&](const MemberExpression& v) {
                           open("member");
                           child(*v.object);
                           out_ << " " << v.member.name << ")";
                       },
                       [&](const BitAccessExpression& v) {
                           open("bit");
                           child(*v.object);
                           out_ << " " << v.bit << ")";
                       },
                       [&](const IndexExpression& v) {
                           open("index");
                           child(*v.array);
                           for (const auto& index : v.indices) {
                               child(*index);
                           }
                           out_ << ")";
                       },
                       [&](const DereferenceExpression& v) { unary("deref", *v.reference); },
                       [&](const ReferenceExpression& v) { unary("ref", *v.target); },
                       [&](const CallExpression& v) { call(v); },
                       [&](const UnaryExpression& v) { unary(operator_name(v.op), *v.operand); },
                       [&](const BinaryExpression& v) {
                           open(operator_name(v.op));
                           child(*v.left);
                           child(*v.right);
                           out_ << ")";
                       },
                   },
                   e.node);
        if (layout_ != nullptr && layout_->note) {
            out_ << layout_->note(e);
        }
    }

    void statement(const Statement& s) {
        std::visit(Overloaded{
                       [&](const AssignmentStatement& v) {
                           open("assign");
                           child(*v.target);
                           child(*v.value);
                           out_ << ")";
                       },
                       [&](const CallStatement& v) { expression(*v.call); },
                       [&](const IfStatement& v) {
                           open("if");
                           for (const ConditionalBlock& branch : v.branches) {
                               child(*branch.condition);
                               block("then", branch.body);
                           }
                           if (!v.else_body.empty()) {
                               block("else", v.else_body);
                           }
                           out_ << ")";
                       },
                       [&](const CaseStatement& v) {
                           open("case");
                           child(*v.selector);
                           for (const CaseBranch& branch : v.branches) {
                               out_ << " (";
                               for (std::size_t i = 0; i < branch.labels.size(); ++i) {
                                   out_ << (i > 0 ? " " : "");
                                   expression(*branch.labels[i].low);
                                   if (branch.labels[i].high) {
                                       out_ << "..";
                                       expression(*branch.labels[i].high);
                                   }
                               }
                               block(":", branch.body);
                               out_ << ")";
                           }
                           if (!v.else_body.empty()) {
                               block("else", v.else_body);
                           }
                           out_ << ")";
                       },
                       [&](const ForStatement& v) {
                           out_ << "(for " << v.control_variable.name;
                           child(*v.from);
                           child(*v.to);
                           if (v.by) {
                               child(*v.by);
                           }
                           block("do", v.body);
                           out_ << ")";
                       },
                       [&](const WhileStatement& v) {
                           open("while");
                           child(*v.condition);
                           block("do", v.body);
                           out_ << ")";
                       },
                       [&](const RepeatStatement& v) {
                           open("repeat");
                           block("do", v.body);
                           child(*v.until);
                           out_ << ")";
                       },
                       [&](const ExitStatement&) { out_ << "(exit)"; },
                       [&](const ContinueStatement&) { out_ << "(continue)"; },
                       [&](const ReturnStatement&) { out_ << "(return)"; },
                       [&](const EmptyStatement&) { out_ << "(empty)"; },
                   },
                   s.node);
    }

    void type(const TypeSpec& t) {
        std::visit(Overloaded{
                       [&](const ElementaryTypeRef& v) { out_ << name_of(v.type); },
                       [&](const StringTypeRef& v) {
                           out_ << "(" << name_of(v.type);
                           if (v.length) {
                               child(*v.length);
                           }
                           out_ << ")";
                       },
                       [&](const NamedTypeRef& v) { out_ << v.name.name; },
                       [&](const ArrayType& v) {
                           open("array");
                           for (const ArrayDimension& dimension : v.dimensions) {
                               out_ << " ";
                               if (dimension.bounds) {
                                   expression(*dimension.bounds->low);
                                   out_ << "..";
                                   expression(*dimension.bounds->high);
                               } else {
                                   out_ << "*";
                               }
                           }
                           out_ << " ";
                           type(*v.element);
                           out_ << ")";
                       },
                       [&](const SubrangeType& v) {
                           open("subrange");
                           out_ << " ";
                           type(*v.base);
                           child(*v.range.low);
                           child(*v.range.high);
                           out_ << ")";
                       },
                       [&](const EnumType& v) {
                           open("enum");
                           if (v.base) {
                               out_ << " ";
                               type(*v.base);
                           }
                           for (const EnumValue& value : v.values) {
                               out_ << " " << value.name.name;
                               if (value.value) {
                                   out_ << "=";
                                   expression(*value.value);
                               }
                           }
                           out_ << ")";
                       },
                       [&](const StructType& v) {
                           open("struct");
                           for (const VariableDeclaration& member : v.members) {
                               out_ << " ";
                               variable(member);
                           }
                           out_ << ")";
                       },
                       [&](const ReferenceType& v) {
                           open(v.kind == ReferenceType::Kind::Reference ? "ref_to" : "pointer_to");
                           out_ << " ";
                           type(*v.target);
                           out_ << ")";
                       },
                   },
                   t.node);
    }

    void variable(const VariableDeclaration& v) {
        out_ << "(var";
        for (const Identifier& name : v.names) {
            out_ << " " << name.name;
        }
        if (v.address) {
            out_ << " ";
            address(*v.address);
        }
        out_ << " ";
        type(v.type);
        if (v.initial_value) {
            out_ << " ";
            initializer(*v.initial_value);
        }
        out_ << ")";
    }

    void initializer(const Initializer& init) {
        std::visit(Overloaded{
                       [&](const ExpressionPtr& e) { expression(*e); },
                       [&](const std::vector<ArrayInitElement>& elements) {
                           out_ << "[";
                           for (const ArrayInitElement& element : elements) {
                               out_ << " ";
                               if (element.repeat_count) {
                                   expression(*element.repeat_count);
                                   out_ << "*";
                               }
                               if (element.value) {
                                   initializer(*element.value);
                               } else {
                                   out_ << "()";
                               }
                           }
                           out_ << " ]";
                       },
                       [&](const std::vector<StructInitElement>& elements) {
                           out_ << "(";
                           for (const StructInitElement& element : elements) {
                               out_ << " " << element.member.name << "=";
                               initializer(*element.value);
                           }
                           out_ << " )";
                       },
                   },
                   init.value);
    }

    void unit(const CompilationUnit& u) {
        for (const TypeDeclaration& declaration : u.types) {
            out_ << "(type " << declaration.name.name << " ";
            type(declaration.type);
            out_ << ")\n";
        }
        for (const Pou& pou : u.pous) {
            static constexpr std::string_view kKinds[] = {"function", "function_block", "program"};
            out_ << "(" << kKinds[static_cast<std::size_t>(pou.kind)] << " " << pou.name.name;
            for (const DeclarationSection& section : pou.sections) {
                if (const auto* variables = std::get_if<VarSection>(&section)) {
                    for (const VariableDeclaration& declaration : variables->variables) {
                        ++depth_;
                        separate();
                        --depth_;
                        variable(declaration);
                    }
                }
            }
            block("body", pou.body);
            out_ << ")\n";
        }
        for (const Configuration& configuration : u.configurations) {
            out_ << "(configuration " << configuration.name.name;
            for (const Resource& resource : configuration.resources) {
                out_ << " (resource " << resource.name.name;
                for (const TaskDeclaration& task : resource.tasks) {
                    out_ << " (task " << task.name.name << ")";
                }
                for (const ProgramInstance& program : resource.programs) {
                    out_ << " (program " << program.name.name << " "
                         << (program.task ? program.task->name : "-") << " " << program.type.name
                         << ")";
                }
                out_ << ")";
            }
            out_ << ")\n";
        }
    }

private:
    void open(std::string_view tag) { out_ << "(" << tag; }
    void child(const Expression& e) {
        out_ << " ";
        expression(e);
    }
    void unary(std::string_view tag, const Expression& operand) {
        open(tag);
        child(operand);
        out_ << ")";
    }
    void call(const CallExpression& v) {
        open("call");
        child(*v.callee);
        for (const Argument& argument : v.arguments) {
            out_ << " ";
            if (argument.name) {
                out_ << (argument.negated ? "NOT " : "") << argument.name->name
                     << (argument.kind == Argument::Kind::Output ? "=>" : ":=");
            }
            expression(*argument.value);
        }
        out_ << ")";
    }
    /// A space between the parts of a line; in a laid-out dump, a new line at the depth.
    void separate() {
        if (layout_ != nullptr) {
            out_ << "\n" << std::string(2 * depth_, ' ');
        } else {
            out_ << " ";
        }
    }
    void block(std::string_view tag, const StatementList& body) {
        out_ << " (" << tag;
        ++depth_;
        for (const Statement& s : body) {
            separate();
            statement(s);
        }
        --depth_;
        out_ << ")";
    }
    void address(const DirectAddress& a) {
        static constexpr std::string_view kAreas = "IQM";
        static constexpr std::string_view kSizes[] = {"", "X", "B", "W", "D", "L"};
        out_ << "(at %" << kAreas[static_cast<std::size_t>(a.area)]
             << kSizes[static_cast<std::size_t>(a.size)];
        for (std::size_t i = 0; i < a.path.size(); ++i) {
            out_ << (i > 0 ? "." : "") << a.path[i];
        }
        out_ << (a.path.empty() ? "*)" : ")");
    }
    void type_suffix(const std::optional<ElementaryType>& type) {
        if (type) {
            out_ << " " << name_of(*type);
        }
    }

    const DumpLayout* layout_ = nullptr;
    int depth_ = 0;
    std::ostringstream out_;
};

} // namespace

std::string to_sexpr(const Expression& expression) {
    Printer printer;
    printer.expression(expression);
    return printer.text();
}

std::string to_sexpr(const Statement& statement) {
    Printer printer;
    printer.statement(statement);
    return printer.text();
}

std::string to_sexpr(const TypeSpec& type) {
    Printer printer;
    printer.type(type);
    return printer.text();
}

std::string to_sexpr(const CompilationUnit& unit) {
    Printer printer;
    printer.unit(unit);
    return printer.text();
}

std::string to_sexpr(const CompilationUnit& unit, const DumpLayout& layout) {
    Printer printer(layout);
    printer.unit(unit);
    return printer.text();
}

} // namespace eposp::compiler::ast
