#pragma once

#include <optional>
#include <string>
#include <utility>

namespace eposp::core {

/// Why something the user asked for could not be done, in words for that user: it names the
/// file and line, the address, the interface or the object where that applies.
struct Error {
    std::string message;
};

/// A value, or the Error that explains its absence. Failures that the user can fix (a file that
/// will not parse, an address in use, a missing interface) are returned as values; exceptions
/// are kept for programming errors.
template <typename T>
class Result {
public:
    Result(T value) : value_(std::move(value)) {}
    Result(Error error) : error_(std::move(error)) {}

    bool ok() const { return value_.has_value(); }
    explicit operator bool() const { return ok(); }

    /// The value; asking a failed result for it is a programming error (bad_optional_access).
    T& value() & { return value_.value(); }
    const T& value() const& { return value_.value(); }
    T&& value() && { return std::move(value_).value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }
    T&& operator*() && { return std::move(*this).value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }

    /// Empty when ok().
    const std::string& error() const { return error_.message; }

private:
    std::optional<T> value_;
    Error error_;
};

} // namespace eposp::core
