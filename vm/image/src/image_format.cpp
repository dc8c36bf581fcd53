#include "eposp/vm/image_format.hpp"

#include "byte_stream.hpp"

#include <array>
#include <boost/crc.hpp>
#include <string>
#include <string_view>

namespace eposp::vm {
namespace {

using detail::ByteReader;
using detail::ByteWriter;

constexpr std::array<std::uint8_t, 4> kMagic{'E', 'P', 'X', 'I'};

std::uint32_t crc32(std::span<const std::uint8_t> bytes) {
    boost::crc_32_type crc;
    crc.process_bytes(bytes.data(), bytes.size());
    return crc.checksum();
}

// The layout is described once, by the `describe_*` functions below, against either of these
// two adapters: one writes each field, the other reads it back into the same place.
class Encoder {
public:
    explicit Encoder(ByteWriter& out) : out_(out) {}
    void u8(const std::uint8_t& v) { out_.u8(v); }
    void u16(const std::uint16_t& v) { out_.u16(v); }
    void u32(const std::uint32_t& v) { out_.u32(v); }
    void u64(const std::uint64_t& v) { out_.u64(v); }
    void i32(const std::int32_t& v) { out_.i32(v); }
    void i64(const std::int64_t& v) { out_.u64(static_cast<std::uint64_t>(v)); }
    void boolean(const bool& v) { out_.u8(v ? 1 : 0); }
    void opcode(const Opcode& op) { out_.u16(static_cast<std::uint16_t>(op)); }
    void string(const std::string& s) { out_.string(s); }
    void bytes(const std::vector<std::uint8_t>& v) {
        out_.u32(static_cast<std::uint32_t>(v.size()));
        out_.raw(v);
    }
    template <typename Enum>
    void enumerator(const Enum& e, Enum /*last*/, std::string_view /*what*/) {
        out_.u8(static_cast<std::uint8_t>(e));
    }
    template <typename T, typename Fn>
    void list(const std::vector<T>& items, std::size_t /*min_size*/, Fn&& each) {
        out_.u32(static_cast<std::uint32_t>(items.size()));
        for (const auto& item : items) {
            each(const_cast<T&>(item)); // the describe functions only read through an Encoder
        }
    }

private:
    ByteWriter& out_;
};

class Decoder {
public:
    explicit Decoder(ByteReader& in) : in_(in) {}
    void u8(std::uint8_t& v) { v = in_.u8(); }
    void u16(std::uint16_t& v) { v = in_.u16(); }
    void u32(std::uint32_t& v) { v = in_.u32(); }
    void u64(std::uint64_t& v) { v = in_.u64(); }
    void i32(std::int32_t& v) { v = in_.i32(); }
    void i64(std::int64_t& v) { v = static_cast<std::int64_t>(in_.u64()); }
    // Only 0 or 1, so that every image read is exactly what write_image makes of it (fuzzed).
    void boolean(bool& v) {
        const auto byte = in_.u8();
        if (byte > 1) {
            in_.fail("invalid boolean " + std::to_string(byte));
        }
        v = byte == 1;
    }
    // Any value: the verifier refuses unknown opcodes with their instruction's position.
    void opcode(Opcode& op) { op = static_cast<Opcode>(in_.u16()); }
    void string(std::string& s) { s = in_.string(); }
    void bytes(std::vector<std::uint8_t>& v) {
        const auto data = in_.raw(in_.count(1));
        v.assign(data.begin(), data.end());
    }
    template <typename Enum>
    void enumerator(Enum& e, Enum last, std::string_view what) {
        e = in_.enumerator(last, what);
    }
    template <typename T, typename Fn>
    void list(std::vector<T>& items, std::size_t min_size, Fn&& each) {
        items.resize(in_.count(min_size));
        for (auto& item : items) {
            each(item);
            if (in_.failed()) {
                return;
            }
        }
    }

private:
    ByteReader& in_;
};

template <typename Io>
void describe_code(Io& io, std::vector<Instruction>& code) {
    io.list(code, kInstructionSize, [&](Instruction& ins) {
        io.opcode(ins.opcode);
        io.u16(ins.aux);
        io.u32(ins.a);
        io.u32(ins.b);
        io.u32(ins.c);
    });
}

template <typename Io>
void describe_arrays(Io& io, std::vector<ArrayDescriptor>& arrays) {
    io.list(arrays, 17, [&](ArrayDescriptor& d) {
        io.i32(d.lower);
        io.u32(d.count);
        io.u32(d.element_size);
        io.u8(d.index_size);
        io.u32(d.offset);
    });
}

template <typename Io>
void describe_jump_tables(Io& io, std::vector<JumpTable>& tables) {
    io.list(tables, 8, [&](JumpTable& t) {
        io.i32(t.low);
        io.list(t.targets, 4, [&](std::uint32_t& target) { io.u32(target); });
    });
}

template <typename Io>
void describe_static(Io& io, Image& image) {
    io.u32(image.static_size);
    io.bytes(image.static_init);
}

template <typename Io>
void describe_retain(Io& io, std::vector<RetainRange>& retain) {
    io.list(retain, 8, [&](RetainRange& r) {
        io.u32(r.offset);
        io.u32(r.size);
    });
}

template <typename Io>
void describe_tasks(Io& io, std::vector<Task>& tasks) {
    io.list(tasks, 25, [&](Task& t) {
        io.string(t.name);
        io.enumerator(t.kind, TaskKind::Event, "task kind");
        io.u64(t.interval_ns);
        bool single = t.event_offset.has_value();
        std::uint32_t offset = t.event_offset.value_or(0);
        io.boolean(single);
        io.u32(offset);
        t.event_offset = single ? std::optional(offset) : std::nullopt;
        io.string(t.event);
        io.u32(t.priority);
        io.u32(t.stack_size);
        io.list(t.entries, 8, [&](TaskEntry& e) {
            io.u32(e.pou);
            io.u32(e.instance);
        });
    });
}

template <typename Io>
void describe_pous(Io& io, std::vector<Pou>& pous) {
    io.list(pous, 33, [&](Pou& p) {
        io.string(p.name);
        io.enumerator(p.kind, PouKind::Program, "POU kind");
        io.u32(p.code_begin);
        io.u32(p.code_end);
        io.u32(p.frame_size);
        io.u32(p.out_size);
        io.u32(p.instance_size);
        io.list(p.lines, 8, [&](LineEntry& l) {
            io.u32(l.instruction);
            io.u32(l.line);
        });
        io.list(p.inlined, 12, [&](InlinedCall& c) {
            io.u32(c.begin);
            io.u32(c.end);
            io.u32(c.callee);
        });
    });
}

template <typename Io>
void describe_types(Io& io, std::vector<TypeDescriptor>& types) {
    io.list(types, 47, [&](TypeDescriptor& t) {
        io.string(t.name);
        io.enumerator(t.kind, TypeKind::Struct, "type kind");
        io.enumerator(t.scalar, Scalar::Ptr, "scalar type");
        io.u32(t.size);
        io.u32(t.element);
        io.i32(t.lower);
        io.u32(t.count);
        io.list(t.fields, 13, [&](TypeField& f) {
            io.string(f.name);
            io.u32(f.type);
            io.u32(f.offset);
            io.boolean(f.read_only);
        });
        io.boolean(t.subrange);
        io.i64(t.lowest);
        io.i64(t.highest);
        io.list(t.enumerators, 12, [&](Enumerator& e) {
            io.string(e.name);
            io.i64(e.value);
        });
    });
}

template <typename Io>
void describe_symbols(Io& io, std::vector<Symbol>& symbols) {
    io.list(symbols, 13, [&](Symbol& s) {
        io.string(s.path);
        io.u32(s.type);
        io.u32(s.offset);
        io.boolean(s.read_only);
    });
}

template <typename Io>
void describe_bindings(Io& io, std::vector<IoBinding>& bindings) {
    io.list(bindings, 11, [&](IoBinding& b) {
        io.enumerator(b.area, IoArea::Memory, "I/O area");
        io.enumerator(b.type, Scalar::Ptr, "scalar type");
        io.u32(b.byte_address);
        io.u8(b.bit);
        io.u32(b.offset);
    });
}

template <typename Io>
void describe_imports(Io& io, std::vector<NativeImport>& imports) {
    io.list(imports, 10, [&](NativeImport& i) {
        io.string(i.name);
        io.boolean(i.signature.has_result);
        io.enumerator(i.signature.result, Scalar::Ptr, "scalar type");
        io.list(i.signature.parameters, 1,
                [&](Scalar& s) { io.enumerator(s, Scalar::Ptr, "scalar type"); });
        io.list(i.signature.instance, 1,
                [&](Scalar& s) { io.enumerator(s, Scalar::Ptr, "scalar type"); });
    });
}

// Calls `fn(id, name, describe)` for each section in file order.
template <typename Io, typename Fn>
void for_each_section(Image& image, Fn&& fn) {
    fn(1, "code", [&](Io& io) { describe_code(io, image.code); });
    fn(2, "arrays", [&](Io& io) { describe_arrays(io, image.arrays); });
    fn(3, "jump tables", [&](Io& io) { describe_jump_tables(io, image.jump_tables); });
    fn(4, "static data", [&](Io& io) { describe_static(io, image); });
    fn(5, "retain", [&](Io& io) { describe_retain(io, image.retain); });
    fn(6, "tasks", [&](Io& io) { describe_tasks(io, image.tasks); });
    fn(7, "POUs", [&](Io& io) { describe_pous(io, image.pous); });
    fn(8, "types", [&](Io& io) { describe_types(io, image.types); });
    fn(9, "symbols", [&](Io& io) { describe_symbols(io, image.symbols); });
    fn(10, "bindings", [&](Io& io) { describe_bindings(io, image.bindings); });
    fn(11, "imports", [&](Io& io) { describe_imports(io, image.imports); });
}

} // namespace

std::vector<std::uint8_t> write_image(const Image& image) {
    ByteWriter out;
    out.raw(kMagic);
    out.u16(kImageVersion);
    out.u16(0);
    out.u32(0); // payload size, patched below
    out.u32(0); // CRC, patched below
    Encoder encoder(out);
    // The Encoder only reads, so the const_cast never leads to a write.
    for_each_section<Encoder>(
        const_cast<Image&>(image), [&](std::uint32_t id, std::string_view, auto&& describe) {
            out.u32(id);
            const auto length_at = out.size();
            out.u32(0);
            describe(encoder);
            out.patch_u32(length_at, static_cast<std::uint32_t>(out.size() - length_at - 4));
        });
    auto& bytes = out.bytes();
    const auto payload = std::span(bytes).subspan(kImageHeaderSize);
    out.patch_u32(8, static_cast<std::uint32_t>(payload.size()));
    out.patch_u32(12, crc32(payload));
    return std::move(bytes);
}

core::Result<Image> read_image(std::span<const std::uint8_t> bytes) {
    ByteReader header(bytes);
    const auto magic = header.raw(kMagic.size());
    if (header.failed() || !std::equal(magic.begin(), magic.end(), kMagic.begin())) {
        return core::Error{"not a program image (bad magic)"};
    }
    const auto version = header.u16();
    const auto reserved = header.u16();
    const auto payload_size = header.u32();
    const auto crc = header.u32();
    if (header.failed()) {
        return core::Error{"truncated image header"};
    }
    if (version != kImageVersion) {
        return core::Error{"image version " + std::to_string(version) +
                           " is not supported (expected " + std::to_string(kImageVersion) + ")"};
    }
    // Reserved for later versions: an image of this version has 0 there, so every accepted
    // file is exactly what write_image makes of its image.
    if (reserved != 0) {
        return core::Error{"reserved header bytes are not zero"};
    }
    if (payload_size != header.remaining()) {
        return core::Error{"image size mismatch: header says " + std::to_string(payload_size) +
                           " payload bytes, file has " + std::to_string(header.remaining())};
    }
    const auto payload = bytes.subspan(kImageHeaderSize);
    if (crc32(payload) != crc) {
        return core::Error{"image checksum mismatch (corrupt file)"};
    }

    Image image;
    ByteReader in(payload);
    std::string error;
    for_each_section<Decoder>(image, [&](std::uint32_t id, std::string_view name, auto&& describe) {
        if (!error.empty()) {
            return;
        }
        const auto found = in.u32();
        const auto length = in.u32();
        const auto body = in.raw(length);
        if (in.failed() || found != id) {
            error = "section " + std::string(name) + " missing or truncated";
            return;
        }
        ByteReader section(body);
        Decoder decoder(section);
        describe(decoder);
        if (!section.failed() && section.remaining() != 0) {
            section.fail(std::to_string(section.remaining()) + " trailing bytes");
        }
        if (section.failed()) {
            error = "section " + std::string(name) + ": " + section.error();
        }
    });
    if (!error.empty()) {
        return core::Error{error};
    }
    if (in.remaining() != 0) {
        return core::Error{"unexpected data after the last section"};
    }
    return image;
}

} // namespace eposp::vm
