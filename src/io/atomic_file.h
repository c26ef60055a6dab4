// Output files appear whole or not at all: written to a temporary beside the target, then renamed.
#pragma once

#include <string>

namespace urbis {

/// Renames `temporary` onto `path`; on failure removes the temporary and throws InputError naming `path`.
void commitTemporary(const std::string& temporary, const std::string& path);

/// Writes `text` to `path` through a temporary. Throws InputError naming the file on failure.
void writeTextFileAtomically(const std::string& path, const std::string& text);

} // namespace urbis
