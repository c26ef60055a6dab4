// Output files appear whole or not at all: written to a temporary beside the target, then renamed.
#pragma once

#include <functional>
#include <string>

namespace urbis {

/// Renames `temporary` onto `path`; on failure removes the temporary and throws InputError naming `path`.
void commitTemporary(const std::string& temporary, const std::string& path);

/// Writes `path` through the temporary `path`.tmp: `write(temporary)` writes the whole file there
/// and returns "" or what failed ("cannot write: Permission denied"). On failure the temporary is
/// removed and InputError "`path`: what failed" thrown; on success it is renamed onto `path`.
void writeThroughTemporary(const std::string& path, const std::function<std::string(const std::string&)>& write);

/// Writes `text` to `path` through a temporary. Throws InputError naming the file on failure.
void writeTextFileAtomically(const std::string& path, const std::string& text);

} // namespace urbis
