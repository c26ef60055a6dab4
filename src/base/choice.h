// The choices of a scene file's key: each name the file may give, beside the value it stands for,
// in one table per key (the integrators, the light samplers, the sky models, ...). The reader, the
// writer, the command line and the panel list the names; the render looks the value up by name.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace urbis {

/// One name of a key's table and the value it stands for.
template <typename E>
struct Choice {
    const char* name;
    E value;
};

/// The name a table entry stands under: a Choice's name, or a plain name of a table of names alone.
template <typename E>
constexpr const char* choiceName(const Choice<E>& choice) {
    return choice.name;
}
constexpr const char* choiceName(const char* name) { return name; }

/// The value named `name` in `table`, or nullopt where no entry has that name.
template <typename E, size_t N>
constexpr std::optional<E> choiceNamed(const Choice<E> (&table)[N], std::string_view name) {
    for (const Choice<E>& choice : table)
        if (name == choice.name) return choice.value;
    return std::nullopt;
}

/// The name of `value` in `table`, or "" where no entry stands for it.
template <typename E, size_t N>
constexpr const char* nameOfChoice(const Choice<E> (&table)[N], E value) {
    for (const Choice<E>& choice : table)
        if (choice.value == value) return choice.name;
    return "";
}

} // namespace urbis
