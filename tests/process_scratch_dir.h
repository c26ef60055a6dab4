// A scratch folder per test process, removed when the process exits.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <unistd.h>

namespace urbis::test {

/// A directory of this test process under the test temp dir, removed at exit.
inline const std::filesystem::path& processScratchDir() {
    struct Dir {
        std::filesystem::path path;
        ~Dir() {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    };
    static const Dir dir{[] {
        const auto path = std::filesystem::path(testing::TempDir()) / ("urbis-osm-" + std::to_string(getpid()));
        std::filesystem::create_directories(path);
        return path;
    }()};
    return dir.path;
}

} // namespace urbis::test
