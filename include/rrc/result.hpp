// Result<T>: a value or an Error (numbered id + message). Runtime failures return one of these,
// after the message has already gone to the logger.
#pragma once
#include <rrc/log.hpp>

#include <cstdlib>
#include <string>
#include <utility>
#include <variant>

namespace rrc {

struct Error {
    LogId id;
    std::string message;
};

// Logs the error and returns it, for `return fail(...)` at the point of failure.
Error fail(LogId id, std::string message);

// Called when value() is taken from a failed Result: a programming mistake. Aborts.
[[noreturn]] void badResultAccess(const Error& error);

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : state_(std::move(value)) {}
    Result(Error error) : state_(std::move(error)) {}

    bool ok() const { return state_.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { check(); return std::get<0>(state_); }
    const T& value() const& { check(); return std::get<0>(state_); }
    T&& value() && { check(); return std::get<0>(std::move(state_)); }
    const Error& error() const { return std::get<1>(state_); }

private:
    void check() const { if (!ok()) badResultAccess(std::get<1>(state_)); }
    std::variant<T, Error> state_;
};

template <>
class [[nodiscard]] Result<void> {
public:
    Result() = default;
    Result(Error error) : error_(std::move(error)), ok_(false) {}
    bool ok() const { return ok_; }
    explicit operator bool() const { return ok_; }
    void value() const { if (!ok_) badResultAccess(error_); }
    const Error& error() const { return error_; }

private:
    Error error_{};
    bool ok_ = true;
};

} // namespace rrc
