#pragma once

#include "program_generator.hpp"
#include "value_cache.hpp"

#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace eposp::compiler::codegen {

/// A value in memory: where it is and its type.
struct Value {
    vm::Operand operand{};
    const sema::Type* type = nullptr;
    /// Set when a small integer is held wider than its IEC type (computed in DINT).
    const sema::Type* iec = nullptr;
};

/// Where a result should preferably go: evaluating straight into a variable saves a move.
struct Destination {
    vm::Operand operand{};
    const sema::Type* type = nullptr;
};

/// Whether `argument` is EN or ENO, which every call takes besides its parameters
/// (pou_enable.cpp).
bool is_enable_argument(const ast::Argument& argument);

/// The arguments of a standard function call as written, without EN and ENO.
using Arguments = std::vector<const ast::Argument*>;

/// Generates the body of one POU (IEC 61131-3 ed. 3, 7.3: ST expressions and
/// statements). Expressions are evaluated memory to memory: a variable is its own operand,
/// intermediate results go to temporaries on the frame, released after each statement.
class PouGenerator {
public:
    PouGenerator(ProgramGenerator& program, const sema::SemanticModel& model, const ast::Pou& pou,
                 std::uint32_t index);
    /// Emits the body; returns the bytes it needs on the task stack (frame and out area).
    std::uint32_t generate();
    /// Emits, instead, the body around the program `instance` of this POU that copies its
    /// connections (6.8.2) in, calls the program's own body `program`, and copies them out;
    /// returns the bytes it needs on the task stack (pou_connections.cpp).
    std::uint32_t generate_connections(const ast::ProgramInstance& instance, std::uint32_t program);

private:
    struct Loop {
        vm::Label exit;
        vm::Label next;
    };
    struct Local {
        Place place;
        ast::VarSectionKind section;
    };

    // --- pou_connections.cpp -----------------------------------------------------------------
    /// The input or output of this program that `argument` connects; null after an error.
    const sema::Field* connected_field(const ast::Argument& argument);
    /// `in := source`, before the program runs.
    void connect_input(const sema::Field& field, const ast::Expression& source);
    /// `out => sink`, after it.
    void connect_output(const sema::Field& field, const ast::Expression& sink);

    // --- pou_generator.cpp: variables, temporaries, moves ----------------------------------
    void declare_locals();
    /// The body of a native block: its native called with the instance's address; the
    /// signature lists the instance's fields (native_block.cpp).
    void call_native_block();
    void initialise_frame();
    vm::Operand temp(const sema::Type& type);
    std::uint32_t out_slot(std::uint32_t end);
    /// Where a host function called now finds its argument block and leaves its result: after
    /// the arguments already placed for the function call being prepared (out_pending_).
    vm::Operand native_block() const;
    /// Whether `operand` is a temporary of the current statement (not a variable).
    bool is_temporary(vm::Operand operand) const;
    /// Ends the temporaries allocated since `mark` and forgets what was computed in them.
    void release(std::uint32_t mark);
    /// Emits an instruction and forgets the cached values it changes.
    void emit(vm::Opcode op, vm::Operand a = {}, vm::Operand b = {}, vm::Operand c = {},
              std::uint16_t aux = 0);
    /// Binds a label: control flow joins there, so nothing cached holds any more.
    void bind(vm::Label label);
    /// An array descriptor, remembering the bytes it covers.
    std::uint16_t array_descriptor(const vm::ArrayDescriptor& array);
    std::optional<Place> variable(const sema::Symbol& symbol);
    vm::Opcode op(std::string_view family, const sema::Type& type) const;
    vm::Opcode op_width(std::string_view family, const sema::Type& type) const;
    /// `dst := src` of the same type (strings of other capacities are truncated).
    void move(vm::Operand dst, const sema::Type& dst_type, const Value& src);
    void load_immediate(vm::Operand dst, const sema::Type& type, std::int64_t value);
    /// `dst := ` the zero of `type` (an empty string).
    void clear(vm::Operand dst, const sema::Type& type);
    Value load(const Place& place, const Destination* dest = nullptr);
    void store(const Place& place, const Value& value);
    /// The place `delta` bytes into `place`, of type `type`.
    Place member(const Place& place, std::uint32_t delta, const sema::Type& type);
    /// The address `place` lives at, as a pointer operand (a temporary when computed).
    vm::Operand address_of(const Place& place);
    /// `place` (an array element) reached through its address instead, for block moves.
    Place through_pointer(const Place& place);

    // --- pou_expressions.cpp -----------------------------------------------------------------
    std::optional<Place> place(const ast::Expression& expression);
    std::optional<Place> index(const ast::IndexExpression& node);
    /// How one array dimension is indexed: the index operand and the descriptor's lower bound
    /// and index size.
    struct ElementIndex {
        vm::Operand operand;
        std::int32_t lower = 0;
        std::uint8_t size = 4;
    };
    std::optional<ElementIndex> element_index(const ast::Expression& index, std::int64_t lower,
                                              std::uint32_t count);
    /// `j + 1` or `j - 1` on a DINT variable: j itself, with the constant moved into the bound.
    std::optional<ElementIndex> displaced_index(const ast::Expression& index, std::int64_t lower);
    /// `value` as a DINT: itself, or a conversion (remembered in the value cache).
    vm::Operand dint_operand(const Value& value);
    /// An array index of any integer type, checked to be one.
    std::optional<Value> integer_index(const ast::Expression& expression);
    /// An array index as DINT (converted once per statement), checked to be an integer; a wide
    /// one (wide_index()) through dint_index() with the LINT bounds that `bounds` emits.
    std::optional<Value>
    index_value(const ast::Expression& expression, bool negative_lower,
                const std::function<std::pair<vm::Operand, vm::Operand>()>& bounds);
    // pou_wide_integers.cpp: 64-bit integers (and UDINT) where the VM takes a DINT.
    /// Whether an index of `type` needs dint_index(): a DINT would not hold every value, and
    /// cut to 32 bits one outside the dimension could name an element.
    bool wide_index(const sema::Type& type, bool negative_lower) const;
    /// `index` as the DINT that names the same element of the dimension of LINT `lower` and
    /// `count`, or one outside it where the index is outside.
    vm::Operand dint_index(const Value& index, vm::Operand lower, vm::Operand count);
    /// An integer as LINT, a ULINT above `high` made `high`.
    vm::Operand as_lint_clamped(const Value& value, std::int64_t high);
    /// A LINT, ULINT or UDINT as DINT, beyond DINT's range made its nearest limit.
    Value saturated_dint(const Value& value);
    /// The value of `expression` of the type the typing stage gave it; an untyped literal takes
    /// `hint`.
    std::optional<Value> eval(const ast::Expression& expression, const sema::Type* hint,
                              const Destination* dest = nullptr);
    std::optional<Value> evaluate(const ast::Expression& expression, const sema::Type* hint,
                                  const Destination* dest);
    /// What a value of `type` is held as: a subrange's base type, a renamed type's type.
    const sema::Type* value_type(const sema::Type& type);
    /// `called` if it is a value (a function's), else an error: an FB call has none.
    std::optional<Value> function_value(const std::optional<Value>& called);
    /// The value of `expression` as `want` (implicitly widened, else an error).
    std::optional<Value> value_as(const ast::Expression& expression, const sema::Type& want,
                                  const Destination* dest = nullptr);
    /// `value`, already computed, as `want`.
    std::optional<Value> value_as(const Value& value, const sema::Type& want,
                                  const Destination* dest = nullptr);
    std::optional<Value> convert(const Value& value, const sema::Type& want,
                                 const Destination* dest);
    /// The word a bit access `w.3` reads, checked to have that bit.
    std::optional<Value> bit_word(const ast::BitAccessExpression& node);
    /// The constant `1 << bit` (or its complement) of `type`.
    vm::Operand bit_mask(const sema::Type& type, std::uint32_t bit, bool inverted);
    /// A literal as a constant of the type the typing stage gave it.
    std::optional<Value> literal(const ast::Expression& expression);
    /// A unary operator; a negation computed in DINT (operands_of) is held so, as binary().
    std::optional<Value> unary(const ast::Expression& expression, const ast::UnaryExpression& node,
                               const sema::Type* hint, const Destination* dest);
    /// A binary operator computed in the type the typing stage gives its operands
    /// (types::TypedProgram::operands_of); an arithmetic result computed wider than its type
    /// is held so while it is an operand (Value::iec).
    std::optional<Value> binary(const ast::Expression& expression,
                                const ast::BinaryExpression& node, const sema::Type* hint,
                                const Destination* dest);
    /// An operand of an operator: like eval, but a nested operation may stay wide.
    std::optional<Value> operand_value(const ast::Expression& expression, const sema::Type* hint,
                                       const Destination* dest = nullptr);
    /// `value` as a constant of the integer (or bit string, enumeration) type `type`.
    vm::Operand integer_constant(const sema::Type& type, std::int64_t value);
    /// The bounds IdxDim checks one index against: lower (DINT) then count (UDINT).
    vm::Operand dimension_constant(std::int64_t lower, std::uint32_t count);
    /// Both operands of a binary operator brought to `type`, which the typing stage chose. An
    /// untyped literal is evaluated after the other side.
    std::optional<std::pair<Value, Value>>
    operands(const ast::Expression& left, const ast::Expression& right, const sema::Type& type);
    /// An operand of an operator brought to `type`.
    std::optional<Value> operand_as(const ast::Expression& expression, const sema::Type& type);
    /// The immediate of an untyped integer literal that fits 32 bits signed.
    std::optional<std::int32_t> small_literal(const ast::Expression& expression);
    /// A binary operator on operands already of their common type, a number or bit string
    /// (time arithmetic is time_arithmetic's).
    std::optional<Value> apply(ast::BinaryOperator op, const Value& left, const Value& right,
                               const Destination* dest);
    std::optional<Value> compare(ast::BinaryOperator op, const Value& left, const Value& right,
                                 const Destination* dest);
    vm::Operand result_operand(const sema::Type& type, const Destination* dest);
    /// `pointer + bytes`, `pointer - bytes`: CODESYS pointer arithmetic, in bytes.
    std::optional<Value> pointer_offset(bool add, const Value& pointer,
                                        const ast::Expression& bytes, const Destination* dest);
    static bool contains_call(const ast::Expression& expression);
    /// Whether evaluating `expression` may write variables: it calls a user function or
    /// anything but a standard function (whose inputs are values).
    bool may_write_variables(const ast::Expression& expression) const;
    /// Evaluates `evaluate` with every variable it loads copied into a temporary where
    /// `later` (an operand evaluated after it) may write variables: operands are evaluated from
    /// left to right (IEC 61131-3 7.3.2), so `x + F(x)` adds the x before F changes it.
    template <typename Evaluate>
    auto before(const ast::Expression& later, Evaluate evaluate) {
        const HeldLoads held(*this, may_write_variables(later));
        return evaluate();
    }
    /// Loads are held (`before`) while it lives, where `hold` says so.
    class HeldLoads {
    public:
        HeldLoads(PouGenerator& generator, bool hold)
            : flag_(generator.hold_loads_), saved_(std::exchange(flag_, flag_ || hold)) {}
        HeldLoads(const HeldLoads&) = delete;
        HeldLoads& operator=(const HeldLoads&) = delete;
        ~HeldLoads() { flag_ = saved_; }

    private:
        bool& flag_;
        bool saved_;
    };
    /// `P` of `P.x`: a PROGRAM named as its single instance (CODESYS).
    bool names_program(const ast::Expression& expression) const;

    // --- pou_conformant_arrays.cpp ------------------------------------------------------------
    /// What VAR_IN_OUT `field` is passed for `target`: its address, for an ARRAY[*] with the
    /// bounds; an error if `target` does not fit.
    std::optional<Value> in_out_argument(const Place& target, const sema::Field& field);
    /// The element of the ARRAY[*] `array` at `node`'s indices, checked against its bounds.
    std::optional<Place> conformant_element(const Place& array, const ast::IndexExpression& node);
    /// LOWER_BOUND(array, dim) and UPPER_BOUND(array, dim), as DINT.
    std::optional<Value> array_bound(const std::string& name, const ast::CallExpression& node,
                                     const Destination* dest);

    // --- pou_subranges.cpp -------------------------------------------------------------------
    /// The value of `expression` as the subrange `want`: checked when compiling if constant,
    /// else when running unless it is a variable of a subrange inside `want`.
    std::optional<Value> subrange_value(const ast::Expression& expression, const sema::Type& want);
    /// The subrange type of a variable or of a function's result that `expression` names
    /// (its value is in range: it was checked when stored); null for anything else.
    const sema::Type* declared_subrange(const ast::Expression& expression);
    /// `value` (of a type that converts implicitly to `want`'s base) as the subrange `want`,
    /// with a Range check unless its own subrange lies inside `want`.
    Value checked(const Value& value, const sema::Type& want);
    /// After a FOR loop over a subrange variable: undoes the last step if it left the range.
    void step_back_into_range(vm::Operand control, const sema::Type& type, vm::Operand step);

    // --- pou_conditions.cpp ------------------------------------------------------------------
    /// Jumps to `target` when `condition` has the value `when`, with compare-and-branch
    /// instructions where the condition is a comparison.
    void branch(const ast::Expression& condition, bool when, vm::Label target);
    /// `(x AND m) = 0` or `<> 0`: the AND's operands as a bit test takes them (integers too),
    /// and whether the condition holds for set bits. `matched` says whether `condition` has
    /// that form; nullopt then means an error was reported.
    struct BitTest {
        Value x;
        Value y;
        bool set = false;
    };
    std::optional<BitTest> bit_test(const ast::Expression& condition, bool& matched);
    /// The bit test `condition` as one bit-test-and-branch (JTst / JNTst); false when it has
    /// another form.
    bool branch_on_bits(const ast::Expression& condition, bool when, vm::Label target);
    /// A condition as a BOOL value, accepting what branch() accepts.
    std::optional<Value> condition_value(const ast::Expression& condition);

    // --- pou_statements.cpp ------------------------------------------------------------------
    void statements(const ast::StatementList& list);
    void statement(const ast::Statement& statement);
    void assignment(const ast::AssignmentStatement& node);
    void bit_assignment(const ast::BitAccessExpression& target, const ast::Expression& value);
    void if_statement(const ast::IfStatement& node);
    /// The control variable of an enclosing FOR loop, which its body may not assign.
    bool is_for_variable(const Place& place) const;
    /// The IF as a conditional move (lower/if_conversion.hpp); false where it is not one.
    bool select_statement(const ast::IfStatement& node);
    void case_statement(const ast::CaseStatement& node);
    /// One CASE label (`3:` or `1..5:`) and the branch it selects.
    struct CaseRange {
        std::int64_t low = 0;
        std::int64_t high = 0;
        vm::Operand low_operand;
        vm::Operand high_operand;
        vm::Label body;
        bool single = true;
    };
    /// The labels compared with the selector one after the other, falling through if none
    /// matches.
    void compare_chain(vm::Operand selector, const sema::Type& type,
                       const std::vector<CaseRange>& ranges);
    /// One jump through a table when the labels are dense enough; false if they are not.
    bool jump_table(vm::Operand selector, const sema::Type& type,
                    const std::vector<CaseRange>& ranges, vm::Label otherwise);
    void for_statement(const ast::ForStatement& node, const SourceRange& range);
    void while_statement(const ast::WhileStatement& node);
    void repeat_statement(const ast::RepeatStatement& node);
    /// WHILE and REPEAT: the body, then a branch back to it while `condition` is
    /// `repeat_when`; `test_first` enters at the condition (WHILE).
    void conditional_loop(const ast::StatementList& body_statements,
                          const ast::Expression& condition, bool repeat_when, bool test_first);

    // --- pou_enable.cpp ----------------------------------------------------------------------
    /// The EN and ENO arguments of a call, where written.
    struct Enable {
        const ast::Argument* en = nullptr;
        const ast::Argument* eno = nullptr;
    };
    /// EN and ENO of `node`; nothing (after an error) when EN is not an input or ENO not an
    /// output.
    std::optional<Enable> enable_of(const ast::CallExpression& node);
    /// Emits `body` so that it runs only when EN is TRUE (or absent), `skipped` otherwise, and
    /// sets ENO to whether it ran; false after an error in EN or ENO.
    bool with_enable(const Enable& enable, const std::function<void()>& body,
                     const std::function<void()>& skipped = {});
    /// A call as an expression or statement, with its EN and ENO.
    std::optional<Value> call(const ast::Expression& expression, const sema::Type* hint,
                              const Destination* dest);

    // --- pou_calls.cpp -----------------------------------------------------------------------
    /// The call without EN/ENO.
    std::optional<Value> call_enabled(const ast::Expression& expression, const sema::Type* hint,
                                      const Destination* dest);
    std::optional<Value> call_function(const ast::Pou& function, const ast::CallExpression& node,
                                       const Destination* dest);
    std::optional<Value> call_host(const ast::Pou& function, const sema::Type& frame,
                                   const ast::CallExpression& node, const Destination* dest);
    void call_instance(const Place& instance, const ast::CallExpression& node);
    // native_function.cpp
    /// A call of a native function: one CallNative here, with its arguments in its block.
    std::optional<Value> call_native_function(const ast::Pou& function,
                                              const ast::CallExpression& node,
                                              const Destination* dest);
    /// The value given to an ANY input: elementary or a string, of its own type.
    std::optional<Value> any_argument(const ast::Expression& expression);
    /// The U32 constant describing a value of `type` (vm::native_descriptor).
    Value native_descriptor(const sema::Type& type);
    /// Calls native `name`; `arguments` already evaluated, strings passed by address.
    void call_native(const std::string& name, const vm::NativeSignature& signature,
                     const std::vector<Value>& arguments);
    std::optional<Value> native_result(const vm::NativeSignature& signature, const sema::Type& type,
                                       const Destination* dest);

    // --- standard_functions.cpp --------------------------------------------------------------
    /// A call of the standard function `target` (the typing stage's CallTarget).
    /// `call`: the CallExpression.
    std::optional<Value> standard_function(const types::CallTarget& target,
                                           const ast::Expression& call, const sema::Type* hint,
                                           const Destination* dest);
    /// `<T>_TO_<U>` and `TO_<U>`: from the typing stage's operand type to its result type.
    std::optional<Value> conversion(const types::CallTarget& target, const Arguments& arguments,
                                    const Destination* dest);
    std::optional<Value> string_function(const types::CallTarget& target,
                                         const Arguments& arguments, const Destination* dest);
    /// ADR(x): the address of x as POINTER TO its type; SIZEOF(x or T): its size in bytes.
    std::optional<Value> address_or_size(const types::CallTarget& target,
                                         const ast::Expression& call, const Arguments& arguments);
    /// The value of an integer expression as DINT (positions and lengths of the natives).
    std::optional<Value> as_dint(const ast::Expression& expression);
    /// A conversion `X_TO_Y` between two types that convert explicitly (table 22: the typing
    /// stage refuses the others, E0310, types/call_typing.cpp), or an internal one between
    /// numbers and times.
    std::optional<Value> explicit_convert(const Value& value, const sema::Type& want,
                                          const Destination* dest);
    /// The arithmetic, comparison, logic, shift, ABS, TRUNC and real functions of `target`.
    std::optional<Value> numeric_function(const types::CallTarget& target,
                                          const Arguments& arguments, const sema::Type* hint,
                                          const Destination* dest);

    // --- time_functions.cpp ------------------------------------------------------------------
    /// ADD_TIME, SUB_DT_DT, CONCAT_DATE_TOD, ...: the row's operand types, the typing stage's
    /// result.
    std::optional<Value> time_function(const types::CallTarget& target, const Arguments& arguments,
                                       const Destination* dest);
    /// `+` or `-` on durations and points in time (table 30) giving `result`, the typing
    /// stage's type of the operation.
    std::optional<Value> time_arithmetic(ast::BinaryOperator op, const Value& left,
                                         const Value& right, const sema::Type& result,
                                         const Destination* dest);
    /// TIME * number, TIME / number giving `result`, the typing stage's type.
    std::optional<Value> scale_time(bool multiply, const Value& time, const ast::Expression& factor,
                                    const sema::Type& result, const Destination* dest);

    // --- selection_functions.cpp -------------------------------------------------------------
    /// MOVE, SEL, MAX, MIN, LIMIT, MUX.
    std::optional<Value> selection(const types::CallTarget& target, const Arguments& arguments,
                                   const sema::Type* hint, const Destination* dest);
    /// Jumps to `target` when a <= b (a and b of one elementary type or both strings).
    void jump_if_at_most(const Value& a, const Value& b, vm::Label target);

    ProgramGenerator& program_;
    const sema::SemanticModel& model_;
    const ast::Pou& pou_;
    std::uint32_t index_;
    vm::Builder& builder_;
    sema::TypeTable& types_;
    std::unordered_map<std::string, Local> locals_; // by folded name
    std::uint32_t locals_end_ = 0; // the frame's variables end here, temporaries follow
    std::uint32_t frame_top_ = 0;
    std::uint32_t frame_max_ = 0;
    std::uint32_t out_max_ = 0;
    /// The bytes at the start of the out area that hold the arguments placed so far for the
    /// function call being prepared; nothing may write there until that call is made.
    std::uint32_t out_pending_ = 0;
    std::vector<Loop> loops_;
    std::vector<std::uint32_t> for_variables_; // operands of the enclosing FOR loops
    ValueCache cache_;
    /// Loads copy a variable's value into a temporary (`before`).
    bool hold_loads_ = false;
    std::unordered_map<std::uint16_t, std::uint32_t> array_bytes_; // per descriptor
    vm::Label end_;
};

} // namespace eposp::compiler::codegen
