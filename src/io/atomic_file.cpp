#include "io/atomic_file.h"

#include "base/input_error.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace urbis {

void commitTemporary(const std::string& temporary, const std::string& path) {
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        throw InputError(path + ": cannot move the finished file into place", FailureKind::Output);
    }
}

void writeThroughTemporary(const std::string& path, const std::function<std::string(const std::string&)>& write) {
    const std::string temporary = path + ".tmp";
    const std::string failure = write(temporary);
    if (!failure.empty()) {
        std::error_code ec;
        std::filesystem::remove(temporary, ec);
        throw InputError(path + ": " + failure, FailureKind::Output);
    }
    commitTemporary(temporary, path);
}

void writeTextFileAtomically(const std::string& path, const std::string& text) {
    writeThroughTemporary(path, [&](const std::string& temporary) -> std::string {
        std::ofstream file(temporary, std::ios::binary);
        if (!file) return std::string("cannot write: ") + std::strerror(errno);
        file << text;
        return file.flush() ? "" : "failed to write";
    });
}

} // namespace urbis
