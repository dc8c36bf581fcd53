// IEC 61131-3 (3rd ed.) table 36 and 37: time and date arithmetic. TIME, LTIME, DATE, TOD and DT
// are all 64-bit nanosecond counts in the VM (DATE and DT since 1970-01-01, TOD since midnight),
// so ADD_TIME, SUB_TIME, ADD_DT_TIME, SUB_DT_TIME, SUB_DATE_DATE, SUB_TOD_TOD, SUB_DT_DT and
// CONCAT_DATE_TOD are the Add64/Sub64 opcodes; only what needs more than one add is here.

#include "eposp/vm/value_semantics.hpp"
#include "library_parts.hpp"
#include "time_units.hpp"

#include <limits>

namespace eposp::vm::stdlib {
namespace {

using S = Scalar;

/// TOD arithmetic wraps around midnight, as CODESYS does.
std::int64_t wrap_to_day(std::int64_t ns) {
    const auto r = ns % kNsPerDay;
    return r < 0 ? r + kNsPerDay : r;
}

std::int64_t floor_to_day(std::int64_t ns) {
    return ns - wrap_to_day(ns);
}

/// LREAL to a nanosecond count exactly as CvtF64I64 (REAL_TO_TIME) does: to nearest, ties to
/// even (IEC 60559), saturating, NaN gives 0.
std::int64_t round_to_ns(double ns) {
    return detail::convert<std::int64_t>(ns);
}

std::int64_t wrapping_mul(std::int64_t a, std::int64_t b) {
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) * static_cast<std::uint64_t>(b));
}

} // namespace

void register_time_functions(NativeRegistry& registry) {
    // Both operands are reduced to one day first, so that no sum overflows whatever they hold.
    add_standard(registry, native_binding("ADD_TOD_TIME"), [](NativeArgs& args) {
        args.set_result(wrap_to_day(wrap_to_day(args.get<std::int64_t>(0)) +
                                    wrap_to_day(args.get<std::int64_t>(1))));
    });
    add_standard(registry, native_binding("SUB_TOD_TIME"), [](NativeArgs& args) {
        args.set_result(wrap_to_day(wrap_to_day(args.get<std::int64_t>(0)) -
                                    wrap_to_day(args.get<std::int64_t>(1))));
    });
    add_standard(registry, date_time_part_binding(NativeType::Date), [](NativeArgs& args) {
        args.set_result(floor_to_day(args.get<std::int64_t>(0)));
    });
    add_standard(registry, date_time_part_binding(NativeType::TimeOfDay),
                 [](NativeArgs& args) { args.set_result(wrap_to_day(args.get<std::int64_t>(0))); });
    // MUL_TIME / DIV_TIME (IN1: TIME, IN2: ANY_NUM): integer factors wrap like LINT arithmetic,
    // real ones round to the nanosecond.
    add_standard(registry, native_binding("MUL_TIME"), [](NativeArgs& args) {
        args.set_result(wrapping_mul(args.get<std::int64_t>(0), args.get<std::int64_t>(1)));
    });
    add_standard(registry, native_binding("MUL_TIME", Variant::Wide), [](NativeArgs& args) {
        args.set_result(
            round_to_ns(static_cast<double>(args.get<std::int64_t>(0)) * args.get<double>(1)));
    });
    add_standard(registry, native_binding("DIV_TIME"), [](NativeArgs& args) {
        const auto divisor = args.get<std::int64_t>(1);
        if (divisor == 0) {
            args.fail("division by zero in DIV_TIME");
            return;
        }
        const auto time = args.get<std::int64_t>(0);
        args.set_result(divisor == -1 ? wrapping_mul(time, -1) : time / divisor);
    });
    add_standard(registry, native_binding("DIV_TIME", Variant::Wide), [](NativeArgs& args) {
        const auto divisor = args.get<double>(1);
        if (divisor == 0.0) {
            args.fail("division by zero in DIV_TIME");
            return;
        }
        args.set_result(round_to_ns(static_cast<double>(args.get<std::int64_t>(0)) / divisor));
    });
}

} // namespace eposp::vm::stdlib
