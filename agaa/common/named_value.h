#pragma once
// A setting's value and the word the command line, the settings table (agaa/method_settings.h)
// and the messages use for it: each enum's words are written once, next to the enum.

#include <stdexcept>
#include <string>

namespace agaa {

template <typename T> struct NamedValue {
    const char* name;
    T value;
};

// The value called `name` in `table`, or std::invalid_argument naming `what` and every word.
template <typename T, size_t N>
T namedValue(const char* what, const std::string& name, const NamedValue<T> (&table)[N]) {
    std::string names;
    for (const NamedValue<T>& entry : table) {
        if (name == entry.name) return entry.value;
        names += std::string(names.empty() ? "" : ", ") + entry.name;
    }
    throw std::invalid_argument(std::string(what) + " '" + name + "' is unknown (allowed: " + names + ")");
}

// The word for `value` in `table` ("" if it has none).
template <typename T, size_t N> const char* nameOf(T value, const NamedValue<T> (&table)[N]) {
    for (const NamedValue<T>& entry : table)
        if (entry.value == value) return entry.name;
    return "";
}

} // namespace agaa
