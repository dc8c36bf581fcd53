#pragma once

#include "eposp/canopen/abort_code.hpp"
#include "eposp/canopen/data_type.hpp"
#include "eposp/canopen/value_codec.hpp"

#include <array>
#include <bitset>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace eposp::canopen {

/// CiA 301 7.4.3 (table 42), as EDS files state it (ObjectType=0x7).
enum class ObjectCode : std::uint8_t {
    Null = 0x0,
    Domain = 0x2,
    DefType = 0x5,
    DefStruct = 0x6,
    Var = 0x7,
    Array = 0x8,
    Record = 0x9,
};

/// Access rights as CiA 306 names them (AccessType=rw). `ReadWriteInput` (rwr) and
/// `ReadWriteOutput` (rww) are read-write objects meant for TPDOs and RPDOs respectively.
enum class Access : std::uint8_t {
    Const,
    ReadOnly,
    WriteOnly,
    ReadWrite,
    ReadWriteInput,
    ReadWriteOutput
};
bool readable(Access access);
bool writable(Access access);
std::string_view to_string(Access access); ///< "rw", as in EDS files

/// One value of the dictionary: a VAR object (sub-index 0) or one sub-index of an ARRAY or a
/// RECORD. Plain data plus two optional hooks with which the node's services compute a value on
/// read or check and act on a write.
struct SubObject {
    /// Large enough for a program image in a DOMAIN, small enough that a remote client cannot
    /// exhaust memory with an SDO size indication.
    static constexpr std::size_t kDefaultMaxLength = std::size_t{1} << 20;

    /// Computes the value on every read (an error register, a counter); the stored value is
    /// not used then.
    using ReadHook = std::function<Bytes()>;
    /// Called for a write that passed the access, length and range checks, before the value is
    /// stored. Returning anything but AbortCode::None refuses the write with that code; this is
    /// where services enforce their rules (a PDO's COB-ID may only change while it is invalid).
    using WriteHook = std::function<AbortCode(std::span<const std::uint8_t> value)>;
    /// Told when a transfer that was writing this value in pieces (an SDO segmented or block
    /// download, a service tool's segmented write) ended without handing it over, with why: the
    /// client aborted, a piece was refused, the transfer timed out, the client went away. The
    /// value stays as it was; a device reports the interruption (CiA 302-3 0x1F57).
    using AbortHook = std::function<void(AbortCode reason)>;

    std::uint8_t sub_index = 0;
    std::string name;
    DataType type = DataType::Unsigned8;
    Access access = Access::ReadWrite;
    bool pdo_mappable = false;
    bool persistent = false; ///< saved by 0x1010 "save", reset by 0x1011 "load"
    Bytes default_value;
    std::optional<Bytes> low_limit;  ///< numeric types only, encoded as the type
    std::optional<Bytes> high_limit; ///< numeric types only, encoded as the type
    /// The longest value a remote write may store in a string or DOMAIN (LengthTooHigh beyond).
    std::size_t max_length = kDefaultMaxLength;
    Bytes value; ///< the current value
    ReadHook on_read;
    WriteHook on_write;
    AbortHook on_write_aborted;
};

/// An object: one index with its sub-objects, in sub-index order.
struct Object {
    std::uint16_t index = 0;
    std::string name;
    ObjectCode code = ObjectCode::Var;
    std::map<std::uint8_t, SubObject> subs;
};

/// A value looked up once to be stored often (a drive's actual values, every millisecond):
/// ObjectDictionary::set() through it skips the lookup. Valid as long as the dictionary it came
/// from: objects are never removed, but a copy of a dictionary has sub-objects of its own.
struct ValueRef {
    std::uint16_t index = 0;
    SubObject* sub = nullptr;
};

/// A CANopen object dictionary as plain data (CiA 301 7.4): everything a node exposes, with the
/// exact SDO abort code for every refused access. Remote access (SDO, a service tool) goes
/// through read()/write(), which check access rights, type length and value range; the device's
/// own code uses get()/set(), which check only the type. Services watch the objects they
/// depend on through on_change().
class ObjectDictionary {
public:
    using ChangeListener = std::function<void(std::uint16_t index, std::uint8_t sub_index)>;
    using ListenerId = std::uint64_t;

    ObjectDictionary() = default;
    ObjectDictionary(const ObjectDictionary& other);
    ObjectDictionary& operator=(const ObjectDictionary& other);
    ObjectDictionary(ObjectDictionary&&) = default;
    ObjectDictionary& operator=(ObjectDictionary&&) = default;

    /// Adds a VAR object; its value starts at `default_value`. Adding an index twice, or a
    /// default that does not fit the type, is a programming error (std::invalid_argument).
    SubObject& add_variable(std::uint16_t index, std::string name, DataType type, Access access,
                            Bytes default_value);
    /// Adds an ARRAY or RECORD object with sub-index 0 ("Highest sub-index supported",
    /// UNSIGNED8, read-only) kept equal to the highest sub-index added later.
    Object& add_object(std::uint16_t index, std::string name, ObjectCode code);
    /// Adds a sub-object to an ARRAY or RECORD added before.
    SubObject& add_sub(std::uint16_t index, std::uint8_t sub_index, std::string name, DataType type,
                       Access access, Bytes default_value);

    const Object* find(std::uint16_t index) const;
    Object* find(std::uint16_t index);
    const SubObject* find(std::uint16_t index, std::uint8_t sub_index) const;
    SubObject* find(std::uint16_t index, std::uint8_t sub_index);
    const std::map<std::uint16_t, Object>& objects() const { return objects_; }

    /// Remote read: ObjectDoesNotExist, SubIndexDoesNotExist, WriteOnly, or None with `out` set.
    AbortCode read(std::uint16_t index, std::uint8_t sub_index, Bytes& out) const;
    /// Remote write: ObjectDoesNotExist, SubIndexDoesNotExist, ReadOnly (also for CONST),
    /// LengthTooLow / LengthTooHigh / LengthMismatch, ValueTooLow / ValueTooHigh, the write
    /// hook's code; None when stored. Listeners are told after the value is stored.
    AbortCode write(std::uint16_t index, std::uint8_t sub_index,
                    std::span<const std::uint8_t> data);
    /// The checks write() makes before it sees the data (existence, access, length), for a
    /// value of `size` bytes: lets an SDO server refuse a download at its initiate request.
    AbortCode check_write_size(std::uint16_t index, std::uint8_t sub_index, std::size_t size) const;
    /// A transfer writing `index`:`sub_index` in pieces ended before the value was complete
    /// (SubObject::on_write_aborted); nothing for a missing entry or one without the hook.
    void write_aborted(std::uint16_t index, std::uint8_t sub_index, AbortCode reason) const;

    /// The device's own access: the value (through the read hook if any). Asking for a missing
    /// object is a programming error (std::out_of_range).
    Bytes get(std::uint16_t index, std::uint8_t sub_index) const;
    /// Stores a value without access-right, range or hook checks and tells the listeners;
    /// a wrong length for the type is a programming error (std::invalid_argument).
    void set(std::uint16_t index, std::uint8_t sub_index, std::span<const std::uint8_t> value);
    /// As above, for a value found by value_ref() (a missing one: std::out_of_range).
    ValueRef value_ref(std::uint16_t index, std::uint8_t sub_index);
    void set(ValueRef ref, std::span<const std::uint8_t> value);

    template <typename T>
    T get_as(std::uint16_t index, std::uint8_t sub_index) const {
        // Decoded in place: the device reads its objects every control period.
        const SubObject& entry = existing(index, sub_index);
        return entry.on_read ? decode<T>(entry.on_read()) : decode<T>(entry.value);
    }
    template <typename T>
    void set_as(std::uint16_t index, std::uint8_t sub_index, T value) {
        set(index, sub_index, encode_array(value));
    }
    template <typename T>
    void set_as(ValueRef ref, T value) {
        // In place and inline when the stored value has T's length, as set() would store it: a
        // drive stores its actual values through here every millisecond.
        const auto bytes = encode_array(value);
        if (ref.sub->value.size() != bytes.size()) {
            set(ref, bytes);
            return;
        }
        std::memcpy(ref.sub->value.data(), bytes.data(), bytes.size());
        notify(ref.index, ref.sub->sub_index);
    }

    /// Tells `listener` of every change of a value at `index` (any sub-index), by write() or set().
    ListenerId on_change(std::uint16_t index, ChangeListener listener);
    void remove_listener(ListenerId id);

    /// Sets every value back to its default (without telling listeners: used at reset).
    void reset_to_defaults();

private:
    /// The sub-object, or std::out_of_range.
    const SubObject& existing(std::uint16_t index, std::uint8_t sub_index) const;
    Object& insert(Object object);
    void index_object(Object& object);
    void index_objects();
    /// Inline: most stored values have no listener, and the bit is all a drive's publishing
    /// should pay for them.
    void notify(std::uint16_t index, std::uint8_t sub_index) const {
        if (watched_.test(index)) {
            notify_listeners(index, sub_index);
        }
    }
    void notify_listeners(std::uint16_t index, std::uint8_t sub_index) const;

    std::map<std::uint16_t, Object> objects_;
    /// The objects by index in pages of 256 indices, made for the pages in use: find() runs
    /// for every object a drive publishes and a PDO packs each period, two reads instead of a
    /// search. Pointers into objects_, whose nodes stay put when the dictionary moves.
    using Page = std::array<Object*, 256>;
    std::array<std::unique_ptr<Page>, 256> pages_;
    std::multimap<std::uint16_t, std::pair<ListenerId, ChangeListener>> listeners_;
    /// The indices with a listener: a drive stores its actual values every millisecond, and
    /// most of them nobody watches; the test is one bit, not a walk through listeners_.
    std::bitset<std::size_t{1} << 16> watched_;
    ListenerId next_listener_ = 1;
};

/// A service's write rule for an object a device brought itself (e.g. from an EDS): `sub` gets
/// `rule` as its write hook unless it is missing, has a hook of its own, or is not of `type`
/// (the rule decodes that type). Returns whether it did.
bool add_write_rule(SubObject* sub, DataType type, SubObject::WriteHook rule);

} // namespace eposp::canopen
