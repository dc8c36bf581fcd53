#pragma once

#include <optional>
#include <string>
#include <utility>

namespace eposp::can {

/// Why a trace could not be read or written: a message for the user, naming the file, line or
/// record where that applies.
struct TraceError {
    std::string message;
};

/// A value or the TraceError that explains its absence: the error-as-value that the trace
/// readers, parsers and file openers return.
template <typename T>
class TraceResult {
public:
    TraceResult(T value) : value_(std::move(value)) {}
    TraceResult(TraceError error) : error_(std::move(error)) {}

    bool ok() const { return value_.has_value(); }
    explicit operator bool() const { return ok(); }

    /// The value; asking a failed result for it is a programming error (bad_optional_access).
    T& value() & { return value_.value(); }
    const T& value() const& { return value_.value(); }
    T&& value() && { return std::move(value_).value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }

    /// Empty when ok().
    const std::string& error() const { return error_.message; }

private:
    std::optional<T> value_;
    TraceError error_;
};

} // namespace eposp::can
