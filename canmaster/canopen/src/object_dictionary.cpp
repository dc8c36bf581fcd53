#include "eposp/canopen/object_dictionary.hpp"

#include "numeric_value.hpp"

#include <algorithm>
#include <cstring>
#include <fmt/format.h>
#include <stdexcept>
#include <utility>

namespace eposp::canopen {
namespace {

void require_fits(DataType type, std::size_t size, std::uint16_t index, std::uint8_t sub_index) {
    const auto expected = fixed_size(type);
    if (expected && *expected != size) {
        throw std::invalid_argument(fmt::format("object {:04X}sub{:X}: {} takes {} bytes, not {}",
                                                index, sub_index, to_string(type), *expected,
                                                size));
    }
}

// CiA 301 7.2.4.3.17: a value longer than the type is "too high", shorter "too low".
AbortCode check_length(const SubObject& sub, std::size_t size) {
    const auto expected = fixed_size(sub.type);
    const std::size_t max = expected ? *expected : sub.max_length;
    if (size > max) {
        return AbortCode::LengthTooHigh;
    }
    if (expected && size < *expected) {
        return AbortCode::LengthTooLow;
    }
    return AbortCode::None;
}

NumericValue decode_limit(const SubObject& sub, const Bytes& limit) {
    const auto value = decode_numeric(sub.type, limit);
    if (!value) {
        throw std::logic_error(fmt::format("sub-object '{}': a limit that is not a {}", sub.name,
                                           to_string(sub.type)));
    }
    return *value;
}

AbortCode check_range(const SubObject& sub, std::span<const std::uint8_t> data) {
    if (!is_numeric(sub.type) || (!sub.low_limit && !sub.high_limit)) {
        return AbortCode::None;
    }
    const NumericValue value = *decode_numeric(sub.type, data);
    if (sub.high_limit) {
        const auto order = compare(value, decode_limit(sub, *sub.high_limit));
        if (order == std::partial_ordering::unordered) {
            return AbortCode::InvalidValue; // a NaN is in no range
        }
        if (order == std::partial_ordering::greater) {
            return AbortCode::ValueTooHigh;
        }
    }
    if (sub.low_limit) {
        const auto order = compare(value, decode_limit(sub, *sub.low_limit));
        if (order == std::partial_ordering::unordered) {
            return AbortCode::InvalidValue;
        }
        if (order == std::partial_ordering::less) {
            return AbortCode::ValueTooLow;
        }
    }
    return AbortCode::None;
}

// CiA 301 7.2.4.3.17: a missing index and a missing sub-index of an existing index have
// different codes.
AbortCode locate(const ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index,
                 const SubObject*& sub) {
    sub = od.find(index, sub_index);
    if (sub != nullptr) {
        return AbortCode::None;
    }
    return od.find(index) == nullptr ? AbortCode::ObjectDoesNotExist
                                     : AbortCode::SubIndexDoesNotExist;
}

SubObject make_sub(std::uint8_t sub_index, std::string name, DataType type, Access access,
                   Bytes default_value) {
    SubObject sub;
    sub.sub_index = sub_index;
    sub.name = std::move(name);
    sub.type = type;
    sub.access = access;
    sub.value = default_value;
    sub.default_value = std::move(default_value);
    return sub;
}

// The lengths of the basic types as copies of a known size, without a call to memmove: a drive
// stores its actual values every millisecond.
void copy_value(std::span<const std::uint8_t> value, std::uint8_t* to) {
    switch (value.size()) {
    case 1:
        *to = value[0];
        break;
    case 2:
        std::memcpy(to, value.data(), 2);
        break;
    case 4:
        std::memcpy(to, value.data(), 4);
        break;
    default:
        std::copy(value.begin(), value.end(), to);
        break;
    }
}

} // namespace

bool readable(Access access) {
    return access != Access::WriteOnly;
}

bool writable(Access access) {
    return access != Access::Const && access != Access::ReadOnly;
}

std::string_view to_string(Access access) {
    switch (access) {
    case Access::Const:
        return "const";
    case Access::ReadOnly:
        return "ro";
    case Access::WriteOnly:
        return "wo";
    case Access::ReadWrite:
        return "rw";
    case Access::ReadWriteInput:
        return "rwr";
    case Access::ReadWriteOutput:
        return "rww";
    }
    return "unknown";
}

SubObject& ObjectDictionary::add_variable(std::uint16_t index, std::string name, DataType type,
                                          Access access, Bytes default_value) {
    if (objects_.contains(index)) {
        throw std::invalid_argument(fmt::format("object {:04X} added twice", index));
    }
    require_fits(type, default_value.size(), index, 0);
    Object object;
    object.index = index;
    object.name = name;
    object.code = ObjectCode::Var;
    object.subs.emplace(0, make_sub(0, std::move(name), type, access, std::move(default_value)));
    return insert(std::move(object)).subs.at(0);
}

Object& ObjectDictionary::add_object(std::uint16_t index, std::string name, ObjectCode code) {
    if (code != ObjectCode::Array && code != ObjectCode::Record) {
        throw std::invalid_argument(
            fmt::format("object {:04X}: add_object() makes ARRAY and RECORD objects", index));
    }
    if (objects_.contains(index)) {
        throw std::invalid_argument(fmt::format("object {:04X} added twice", index));
    }
    Object object;
    object.index = index;
    object.name = std::move(name);
    object.code = code;
    // CiA 301 7.4.3: sub-index 0 of an ARRAY or RECORD holds the highest sub-index supported.
    object.subs.emplace(0, make_sub(0, "Highest sub-index supported", DataType::Unsigned8,
                                    Access::ReadOnly, encode(std::uint8_t{0})));
    return insert(std::move(object));
}

SubObject& ObjectDictionary::add_sub(std::uint16_t index, std::uint8_t sub_index, std::string name,
                                     DataType type, Access access, Bytes default_value) {
    Object* object = find(index);
    if (object == nullptr ||
        (object->code != ObjectCode::Array && object->code != ObjectCode::Record)) {
        throw std::invalid_argument(
            fmt::format("object {:04X}: add_sub() needs an ARRAY or RECORD added before", index));
    }
    if (object->subs.contains(sub_index)) {
        throw std::invalid_argument(
            fmt::format("object {:04X}sub{:X} added twice", index, sub_index));
    }
    require_fits(type, default_value.size(), index, sub_index);
    auto& sub = object->subs
                    .emplace(sub_index, make_sub(sub_index, std::move(name), type, access,
                                                 std::move(default_value)))
                    .first->second;
    SubObject& highest = object->subs.at(0);
    highest.default_value = encode(object->subs.rbegin()->first);
    highest.value = highest.default_value;
    return sub;
}

ObjectDictionary::ObjectDictionary(const ObjectDictionary& other)
    : objects_(other.objects_), listeners_(other.listeners_), watched_(other.watched_),
      next_listener_(other.next_listener_) {
    index_objects();
}

ObjectDictionary& ObjectDictionary::operator=(const ObjectDictionary& other) {
    if (this != &other) {
        objects_ = other.objects_;
        listeners_ = other.listeners_;
        watched_ = other.watched_;
        next_listener_ = other.next_listener_;
        index_objects();
    }
    return *this;
}

Object& ObjectDictionary::insert(Object object) {
    const std::uint16_t index = object.index;
    Object& inserted = objects_.emplace(index, std::move(object)).first->second;
    index_object(inserted);
    return inserted;
}

void ObjectDictionary::index_object(Object& object) {
    std::unique_ptr<Page>& page = pages_[object.index >> 8];
    if (!page) {
        page = std::make_unique<Page>();
        page->fill(nullptr);
    }
    (*page)[object.index & 0xFF] = &object;
}

void ObjectDictionary::index_objects() {
    for (auto& page : pages_) {
        page.reset();
    }
    for (auto& [index, object] : objects_) {
        index_object(object);
    }
}

const Object* ObjectDictionary::find(std::uint16_t index) const {
    const Page* page = pages_[index >> 8].get();
    return page == nullptr ? nullptr : (*page)[index & 0xFF];
}

Object* ObjectDictionary::find(std::uint16_t index) {
    return const_cast<Object*>(std::as_const(*this).find(index));
}

const SubObject* ObjectDictionary::find(std::uint16_t index, std::uint8_t sub_index) const {
    const Object* object = find(index);
    if (object == nullptr) {
        return nullptr;
    }
    const auto it = object->subs.find(sub_index);
    return it == object->subs.end() ? nullptr : &it->second;
}

SubObject* ObjectDictionary::find(std::uint16_t index, std::uint8_t sub_index) {
    return const_cast<SubObject*>(std::as_const(*this).find(index, sub_index));
}

AbortCode ObjectDictionary::read(std::uint16_t index, std::uint8_t sub_index, Bytes& out) const {
    const SubObject* sub = nullptr;
    if (const AbortCode missing = locate(*this, index, sub_index, sub);
        missing != AbortCode::None) {
        return missing;
    }
    if (!readable(sub->access)) {
        return AbortCode::WriteOnly;
    }
    out = sub->on_read ? sub->on_read() : sub->value;
    return AbortCode::None;
}

AbortCode ObjectDictionary::check_write_size(std::uint16_t index, std::uint8_t sub_index,
                                             std::size_t size) const {
    const SubObject* sub = nullptr;
    if (const AbortCode missing = locate(*this, index, sub_index, sub);
        missing != AbortCode::None) {
        return missing;
    }
    if (!writable(sub->access)) {
        return AbortCode::ReadOnly;
    }
    return check_length(*sub, size);
}

AbortCode ObjectDictionary::write(std::uint16_t index, std::uint8_t sub_index,
                                  std::span<const std::uint8_t> data) {
    if (const AbortCode refused = check_write_size(index, sub_index, data.size());
        refused != AbortCode::None) {
        return refused;
    }
    SubObject& sub = *find(index, sub_index);
    if (const AbortCode out_of_range = check_range(sub, data); out_of_range != AbortCode::None) {
        return out_of_range;
    }
    if (sub.on_write) {
        if (const AbortCode refused = sub.on_write(data); refused != AbortCode::None) {
            return refused;
        }
    }
    sub.value.assign(data.begin(), data.end());
    notify(index, sub_index);
    return AbortCode::None;
}

const SubObject& ObjectDictionary::existing(std::uint16_t index, std::uint8_t sub_index) const {
    const SubObject* sub = find(index, sub_index);
    if (sub == nullptr) {
        throw std::out_of_range(
            fmt::format("object {:04X}sub{:X} does not exist", index, sub_index));
    }
    return *sub;
}

void ObjectDictionary::write_aborted(std::uint16_t index, std::uint8_t sub_index,
                                     AbortCode reason) const {
    const SubObject* entry = find(index, sub_index);
    if (entry && entry->on_write_aborted) {
        entry->on_write_aborted(reason);
    }
}

Bytes ObjectDictionary::get(std::uint16_t index, std::uint8_t sub_index) const {
    const SubObject& sub = existing(index, sub_index);
    return sub.on_read ? sub.on_read() : sub.value;
}

void ObjectDictionary::set(std::uint16_t index, std::uint8_t sub_index,
                           std::span<const std::uint8_t> value) {
    set(value_ref(index, sub_index), value);
}

ValueRef ObjectDictionary::value_ref(std::uint16_t index, std::uint8_t sub_index) {
    return {index, &const_cast<SubObject&>(existing(index, sub_index))};
}

void ObjectDictionary::set(ValueRef ref, std::span<const std::uint8_t> value) {
    SubObject& sub = *ref.sub;
    // A stored value has its type's length: only another length needs the check (a drive
    // stores its actual values every millisecond).
    if (value.size() != sub.value.size()) {
        require_fits(sub.type, value.size(), ref.index, sub.sub_index);
        sub.value.assign(value.begin(), value.end());
    } else {
        copy_value(value, sub.value.data());
    }
    notify(ref.index, sub.sub_index);
}

ObjectDictionary::ListenerId ObjectDictionary::on_change(std::uint16_t index,
                                                         ChangeListener listener) {
    const ListenerId id = next_listener_++;
    listeners_.emplace(index, std::pair{id, std::move(listener)});
    watched_.set(index);
    return id;
}

void ObjectDictionary::remove_listener(ListenerId id) {
    for (auto it = listeners_.begin(); it != listeners_.end(); ++it) {
        if (it->second.first == id) {
            const std::uint16_t index = it->first;
            listeners_.erase(it);
            watched_.set(index, listeners_.contains(index));
            return;
        }
    }
}

void ObjectDictionary::reset_to_defaults() {
    for (auto& [index, object] : objects_) {
        for (auto& [sub_index, sub] : object.subs) {
            sub.value = sub.default_value;
        }
    }
}

void ObjectDictionary::notify_listeners(std::uint16_t index, std::uint8_t sub_index) const {
    // A listener may add or remove listeners: call copies, and skip one removed meanwhile.
    std::vector<std::pair<ListenerId, ChangeListener>> to_call;
    const auto [first, last] = listeners_.equal_range(index);
    for (auto it = first; it != last; ++it) {
        to_call.push_back(it->second);
    }
    for (const auto& [id, listener] : to_call) {
        const auto [from, to] = listeners_.equal_range(index);
        for (auto it = from; it != to; ++it) {
            if (it->second.first == id) {
                listener(index, sub_index);
                break;
            }
        }
    }
}

bool add_write_rule(SubObject* sub, DataType type, SubObject::WriteHook rule) {
    if (sub == nullptr || sub->on_write || sub->type != type) {
        return false;
    }
    sub->on_write = std::move(rule);
    return true;
}

} // namespace eposp::canopen
