// IEC 61131-3 (3rd ed.) table 36 and 37: time and date arithmetic. TIME, LTIME, DATE, TOD and DT
// are all 64-bit nanosecond counts in the VM (DATE and DT since 1970-01-01, TOD since midnight),
// so ADD_TIME, SUB_TIME, ADD_DT_TIME, SUB_DT_TIME, SUB_DATE_DATE, SUB_TOD_TOD, SUB_DT_DT and
// CONCAT_DATE_TOD are the Add64/Sub64 opcodes; only what needs more than one add is here, each
// computed by vm/stdlib/time_arithmetic.hpp, which the compiler folds constants with.

#include "eposp/vm/stdlib/time_arithmetic.hpp"
#include "library_parts.hpp"

namespace eposp::vm::stdlib {

void register_time_functions(NativeRegistry& registry) {
    add_standard(registry, native_binding("ADD_TOD_TIME"), [](NativeArgs& args) {
        args.set_result(add_tod_time(args.get<std::int64_t>(0), args.get<std::int64_t>(1)));
    });
    add_standard(registry, native_binding("SUB_TOD_TIME"), [](NativeArgs& args) {
        args.set_result(sub_tod_time(args.get<std::int64_t>(0), args.get<std::int64_t>(1)));
    });
    add_standard(registry, date_time_part_binding(NativeType::Date), [](NativeArgs& args) {
        args.set_result(floor_to_day(args.get<std::int64_t>(0)));
    });
    add_standard(registry, date_time_part_binding(NativeType::TimeOfDay),
                 [](NativeArgs& args) { args.set_result(wrap_to_day(args.get<std::int64_t>(0))); });
    add_standard(registry, native_binding("MUL_TIME"), [](NativeArgs& args) {
        args.set_result(mul_time(args.get<std::int64_t>(0), args.get<std::int64_t>(1)));
    });
    add_standard(registry, native_binding("MUL_TIME", Variant::Wide), [](NativeArgs& args) {
        args.set_result(mul_time(args.get<std::int64_t>(0), args.get<double>(1)));
    });
    add_standard(registry, native_binding("DIV_TIME"), [](NativeArgs& args) {
        const auto quotient = div_time(args.get<std::int64_t>(0), args.get<std::int64_t>(1));
        if (!quotient) {
            args.fail("division by zero in DIV_TIME");
            return;
        }
        args.set_result(*quotient);
    });
    add_standard(registry, native_binding("DIV_TIME", Variant::Wide), [](NativeArgs& args) {
        const auto quotient = div_time(args.get<std::int64_t>(0), args.get<double>(1));
        if (!quotient) {
            args.fail("division by zero in DIV_TIME");
            return;
        }
        args.set_result(*quotient);
    });
}

} // namespace eposp::vm::stdlib
