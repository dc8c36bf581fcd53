#include "value_cache.hpp"

#include <algorithm>

namespace eposp::compiler::codegen {

namespace {

bool overlaps(const ValueCache::Range& x, const ValueCache::Range& y) {
    return x.start.base() == y.start.base() &&
           std::uint64_t{x.start.offset()} < std::uint64_t{y.start.offset()} + y.size &&
           std::uint64_t{y.start.offset()} < std::uint64_t{x.start.offset()} + x.size;
}

} // namespace

std::optional<vm::Operand> ValueCache::find(const Key& key) const {
    for (const Entry& entry : entries_) {
        if (entry.key == key) {
            return entry.result;
        }
    }
    return std::nullopt;
}

void ValueCache::add(const Key& key, vm::Operand result, std::uint32_t size,
                     std::vector<Range> sources) {
    sources.push_back({result, size});
    entries_.push_back({key, result, std::move(sources)});
}

void ValueCache::forget(const Range& range) {
    std::erase_if(entries_, [&](const Entry& entry) {
        return std::any_of(entry.depends.begin(), entry.depends.end(),
                           [&](const Range& source) { return overlaps(source, range); });
    });
}

void ValueCache::written(vm::Opcode op, vm::Operand a, vm::Operand b, vm::Operand c,
                         std::uint16_t aux,
                         const std::function<std::uint32_t(std::uint16_t)>& array_bytes) {
    if (entries_.empty()) {
        return;
    }
    const vm::OpcodeInfo& info = vm::opcode_info(op);
    // Calls and stores through pointers may write anything.
    if (info.name.starts_with("Call") || info.name.starts_with("Stp")) {
        clear();
        return;
    }
    const vm::Operand operands[3] = {a, b, c};
    const vm::FieldSpec* fields[3] = {&info.a, &info.b, &info.c};
    for (int i = 0; i < 3; ++i) {
        switch (fields[i]->field) {
        case vm::Field::Write:
            forget({operands[i], fields[i]->size});
            break;
        case vm::Field::WriteN:
            forget({operands[i], c.raw});
            break;
        case vm::Field::ArrayWrite:
            forget({operands[i], array_bytes(aux)});
            break;
        default:
            break;
        }
    }
}

void ValueCache::release(std::uint32_t mark) {
    forget({vm::Operand::local(mark), vm::kOffsetMask - mark});
}

} // namespace eposp::compiler::codegen
