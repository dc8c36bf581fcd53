#include "value_list.hpp"

namespace eposp::drives::epos2 {

canopen::Entry value_list(canopen::Entry entry, std::initializer_list<std::int64_t> values) {
    entry.one_of(values);
    entry.sub().low_limit.reset();
    entry.sub().high_limit.reset();
    return entry;
}

} // namespace eposp::drives::epos2
