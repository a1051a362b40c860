// Expected failures (bad files, bad arguments, missing devices) travel as values: a Result holds
// either a value or an Error whose message already names the place ("worlds/a.toml:12: ...").
#pragma once

#include <fmt/format.h>
#include <string>
#include <utility>
#include <variant>

namespace engine {

struct Error {
    std::string message;
};

template <typename... Args>
Error makeError(fmt::format_string<Args...> format, Args&&... args) {
    return Error{fmt::format(format, std::forward<Args>(args)...)};
}

template <typename T>
class [[nodiscard]] Result {
public:
    Result(T value) : mData(std::move(value)) {}
    Result(Error error) : mData(std::move(error)) {}

    bool ok() const { return std::holds_alternative<T>(mData); }
    explicit operator bool() const { return ok(); }
    T& value() & { return std::get<T>(mData); }
    const T& value() const& { return std::get<T>(mData); }
    T&& value() && { return std::get<T>(std::move(mData)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const Error& error() const { return std::get<Error>(mData); }

private:
    std::variant<T, Error> mData;
};

// Result<void>: success or an Error.
class [[nodiscard]] Status {
public:
    Status() = default;
    Status(Error error) : mError(std::move(error)), mOk(false) {}
    bool ok() const { return mOk; }
    explicit operator bool() const { return mOk; }
    const Error& error() const { return mError; }

private:
    Error mError;
    bool mOk = true;
};

}  // namespace engine
