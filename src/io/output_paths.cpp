#include "io/output_paths.h"

#include "base/input_error.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace urbis {

void checkOutputPath(const std::string& option, const std::string& path,
                     std::initializer_list<std::string_view> extensions) {
    if (path.empty()) return;
    const std::filesystem::path file(path);
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (std::find(extensions.begin(), extensions.end(), extension) == extensions.end()) {
        std::string known;
        for (std::string_view e : extensions) known += (known.empty() ? "" : ", ") + std::string(e);
        throw InputError(option + " " + path + ": " +
                             (extension.empty() ? "no extension" : "cannot write '" + extension + "' files") +
                             " (the format follows the extension: " + known + ")",
                         FailureKind::Usage);
    }
    const std::filesystem::path parent = file.parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent))
        throw InputError(option + " " + path + ": the folder " + parent.string() + " does not exist", FailureKind::Output);
}

void checkDistinctOutputs(const std::string& optionA, const std::string& a, const std::string& optionB,
                          const std::string& b) {
    if (a.empty() || b.empty()) return;
    std::error_code ec;
    if (std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec))
        throw InputError(optionA + " and " + optionB + " are the same file " + a, FailureKind::Usage);
}

} // namespace urbis
