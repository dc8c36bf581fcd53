#include "translator.hpp"

// Where an operand is (its base register and offset), and which register still holds the value
// an instruction stored, so that the next one need not load it again.

namespace eposp::vm::jit {

Xbyak::RegExp Translator::address_of(std::uint32_t field, std::int64_t extra) {
    const Operand operand{field};
    std::int64_t displacement = std::int64_t{operand.offset()} + extra;
    switch (operand.base()) {
    case Base::Static:
        return r12 + displacement;
    case Base::Frame:
        return r13 + displacement;
    case Base::Self:
        return r14 + displacement;
    case Base::Out:
        return r13 + (displacement + pou_->frame_size);
    }
    return r12 + displacement;
}

const Xbyak::AddressFrame& Translator::sized(int bytes) const {
    switch (bytes) {
    case 1:
        return byte;
    case 2:
        return word;
    case 4:
        return dword;
    default:
        return qword;
    }
}

Xbyak::Address Translator::at(std::uint32_t field, int bytes, std::int64_t extra) {
    return sized(bytes)[address_of(field, extra)];
}

// Values narrower than 64 bits are worked on in the 32-bit register.
Xbyak::Reg Translator::work(const Xbyak::Reg64& r, int bytes) {
    return bytes == 8 ? Xbyak::Reg(r) : Xbyak::Reg(r.cvt32());
}

Xbyak::Reg Translator::part(const Xbyak::Reg64& r, int bytes) {
    switch (bytes) {
    case 1:
        return r.cvt8();
    case 2:
        return r.cvt16();
    case 4:
        return r.cvt32();
    default:
        return r;
    }
}

// A value an instruction stores from rax (or xmm0) is still there when the next one starts: its
// loads of that operand take the register, which spares the store-to-load forwarding latency on
// every chain of dependent instructions. Valid only from the store to the next instruction's
// first write of the register, and never across a block start. Only the stored bytes are the
// value: above them the register holds whatever the storing instruction computed (a narrowing
// conversion stores 4 bytes of a 64-bit result), so a load that needs more extends them anew.
bool Translator::holds(const std::optional<Held>& held, std::uint32_t field, int bytes) {
    return held && held->field == field && held->bytes == bytes;
}

void Translator::load(const Xbyak::Reg64& r, std::uint32_t field, int bytes, bool sign) {
    const bool hit = bytes >= 4 && holds(held_rax_, field, bytes);
    if (r.getIdx() == rax.getIdx()) {
        held_rax_.reset(); // the caller is about to change rax
        if (hit) {
            return;
        }
    } else if (hit) {
        mov(work(r, bytes), work(rax, bytes));
        return;
    }
    if (bytes < 4) {
        sign ? movsx(r.cvt32(), at(field, bytes)) : movzx(r.cvt32(), at(field, bytes));
    } else {
        mov(work(r, bytes), at(field, bytes));
    }
}

// Into rax, extended to 64 bits.
void Translator::load64(std::uint32_t field, int bytes, bool sign) {
    const bool hit = bytes >= 4 && holds(held_rax_, field, bytes);
    held_rax_.reset();
    if (hit) {
        if (bytes == 4) {
            sign ? movsxd(rax, eax) : mov(eax, eax);
        }
    } else if (bytes == 8) {
        mov(rax, at(field, 8));
    } else if (bytes == 4) {
        sign ? movsxd(rax, at(field, 4)) : mov(eax, at(field, 4));
    } else {
        sign ? movsx(rax, at(field, bytes)) : movzx(eax, at(field, bytes));
    }
}

void Translator::store(std::uint32_t field, int bytes, const Xbyak::Reg64& r) {
    mov(at(field, bytes), part(r, bytes));
    if (r.getIdx() == rax.getIdx() && bytes >= 4) {
        stored_rax_ = Held{field, bytes};
    }
}

template <typename T>
void Translator::float_load(std::uint32_t field) {
    const bool hit = holds(held_xmm0_, field, sizeof(T));
    held_xmm0_.reset();
    if (hit) {
        return;
    }
    if constexpr (sizeof(T) == 4) {
        movss(xmm0, at(field, 4));
    } else {
        movsd(xmm0, at(field, 8));
    }
}

template <typename T>
void Translator::float_store(std::uint32_t field) {
    if constexpr (sizeof(T) == 4) {
        movss(at(field, 4), xmm0);
    } else {
        movsd(at(field, 8), xmm0);
    }
    stored_xmm0_ = Held{field, sizeof(T)};
}

Xbyak::RegExp Translator::element(const Instruction& ins, std::uint32_t array_field,
                                  std::uint32_t index_field) {
    const ArrayDescriptor& descriptor = image_.arrays[ins.aux];
    held_rax_.reset();
    if (descriptor.index_size == 2) {
        movsx(eax, at(index_field, 2));
    } else {
        mov(eax, at(index_field, 4));
    }
    if (descriptor.lower != 0) {
        sub(eax, static_cast<std::uint32_t>(descriptor.lower));
    }
    cmp(eax, descriptor.count);
    jae(trap_exit(Trap::IndexOutOfRange));
    const std::uint32_t size = descriptor.element_size;
    if (size == 1 || size == 2 || size == 4 || size == 8) {
        return address_of(array_field, descriptor.offset) + rax * static_cast<int>(size);
    }
    imul(rax, rax, static_cast<int>(size));
    return address_of(array_field, descriptor.offset) + rax;
}

template void Translator::float_load<float>(std::uint32_t field);
template void Translator::float_load<double>(std::uint32_t field);
template void Translator::float_store<float>(std::uint32_t field);
template void Translator::float_store<double>(std::uint32_t field);

} // namespace eposp::vm::jit
