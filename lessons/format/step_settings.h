// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The settings a lesson step or a question gives on top of its scene's.

#include "format/schema_value.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace rigidlab::lessons {

/// Settings a step sets on top of its scene's (its "settings", a question's "set"): values by
/// the key of their row in the run-time settings table (schema::settings(), scene_schema.h),
/// in the table's value types ("integrator": its name, "gravity": on or off). A key it does not
/// hold is the scene's.
class StepSettings {
public:
    /// The value given for `key`, or unset.
    schema::Value value(std::string_view key) const
    {
        const auto it = m_values.find(key);
        return it == m_values.end() ? schema::Value() : it->second;
    }
    /// The value for `key` as a T, when it is given (and is one).
    template <class T> std::optional<T> get(std::string_view key) const
    {
        const schema::Value v = value(key);
        if (const T* t = std::get_if<T>(&v))
            return *t;
        return std::nullopt;
    }
    bool has(std::string_view key) const { return m_values.find(key) != m_values.end(); }
    /// Gives `key` the value `v`; unset: the scene's again.
    void set(std::string_view key, const schema::Value& v)
    {
        if (std::holds_alternative<std::monostate>(v))
            m_values.erase(std::string(key));
        else
            m_values.insert_or_assign(std::string(key), v);
    }
    bool empty() const { return m_values.empty(); }

private:
    std::map<std::string, schema::Value, std::less<>> m_values;
};

} // namespace rigidlab::lessons
