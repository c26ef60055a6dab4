// Checking the command's output files before any work: format from the extension, folder, clashes.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

namespace urbis {

/// Throws before any work if `path` (given to `option`; empty: not asked for) cannot be
/// written as asked: a usage InputError when its extension (any case) is none of `extensions`
/// (".png", ".json", ...), since the format follows the extension; an output InputError when
/// its folder does not exist.
void checkOutputPath(const std::string& option, const std::string& path,
                     std::initializer_list<std::string_view> extensions);

/// Throws a usage InputError when two outputs (`optionA` = `a`, `optionB` = `b`) name the same
/// file, which the second write would replace.
void checkDistinctOutputs(const std::string& optionA, const std::string& a, const std::string& optionB,
                          const std::string& b);

} // namespace urbis
