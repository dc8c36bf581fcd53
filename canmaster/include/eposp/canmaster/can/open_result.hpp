#pragma once

#include <cassert>
#include <memory>
#include <string>
#include <utility>

namespace eposp::can {

/// What opening a backend gives: the object, or a message that says why it could not be opened
/// (no AF_CAN in this kernel, no such interface, address already in use, ...). Opening outside
/// resources fails for reasons the user fixes, so it is a value, not an exception.
template <class T>
class OpenResult {
public:
    static OpenResult success(std::unique_ptr<T> value) {
        assert(value);
        return OpenResult(std::move(value), {});
    }
    static OpenResult failure(std::string message) {
        return OpenResult(nullptr, std::move(message));
    }

    explicit operator bool() const { return value_ != nullptr; }
    T& operator*() const {
        assert(value_);
        return *value_;
    }
    T* operator->() const {
        assert(value_);
        return value_.get();
    }
    /// Hands over the opened object; the result is empty afterwards.
    std::unique_ptr<T> take() {
        assert(value_);
        return std::move(value_);
    }
    /// Why opening failed; empty on success.
    const std::string& error() const { return error_; }

private:
    OpenResult(std::unique_ptr<T> value, std::string error)
        : value_(std::move(value)), error_(std::move(error)) {}

    std::unique_ptr<T> value_;
    std::string error_;
};

} // namespace eposp::can
