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

void writeTextFileAtomically(const std::string& path, const std::string& text) {
    std::string temporary = path + ".tmp";
    {
        std::ofstream file(temporary, std::ios::binary);
        if (!file) throw InputError(path + ": cannot write: " + std::strerror(errno), FailureKind::Output);
        file << text;
        if (!file.flush()) {
            std::error_code ec;
            std::filesystem::remove(temporary, ec);
            throw InputError(path + ": failed to write", FailureKind::Output);
        }
    }
    commitTemporary(temporary, path);
}

} // namespace urbis
