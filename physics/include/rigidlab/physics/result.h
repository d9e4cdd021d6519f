// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Errors the user can cause come back as a value with a message, never as an exception.

#include <string>
#include <utility>
#include <variant>

namespace rigidlab::physics {

struct Error {
    std::string message; ///< what is wrong, in words a user can act on
};

template <typename T> class Result {
public:
    Result(T value) : m_v(std::move(value)) {}
    Result(Error e) : m_v(std::move(e)) {}
    bool ok() const { return std::holds_alternative<T>(m_v); }
    explicit operator bool() const { return ok(); }
    const T& value() const& { return std::get<T>(m_v); }
    T&& value() && { return std::get<T>(std::move(m_v)); }
    const std::string& error() const { return std::get<Error>(m_v).message; }

private:
    std::variant<T, Error> m_v;
};

} // namespace rigidlab::physics
