// Running the real urbis command from tests, and a scratch folder per test.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace urbis::test {

struct CommandResult {
    int exitCode = -1;
    std::string out, err;
};

inline std::string readFile(const std::filesystem::path& path) {
    std::ifstream f(path, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

/// A fresh empty folder under the system temp dir, named after the running test.
inline std::filesystem::path scratchDir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / ("urbis_test_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

/// The urbis command under test: $URBIS_BIN where set (binaries carried to another machine, as
/// bench/gpu.sh runs them), else the one built beside the tests.
inline std::string urbisBinary() {
    const char* bin = std::getenv("URBIS_BIN");
    return bin && *bin ? bin : URBIS_BIN;
}

/// Runs `urbisBinary() args` in `dir`, capturing stdout and stderr; with `prefix`, through that
/// command (xvfb-run ...).
inline CommandResult runUrbis(const std::string& args, const std::filesystem::path& dir, const std::string& prefix = "") {
    std::string command = "cd '" + dir.string() + "' && " + prefix + " '" + urbisBinary() + "' " + args + " >stdout.txt 2>stderr.txt";
    int status = std::system(command.c_str());
    CommandResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = readFile(dir / "stdout.txt");
    r.err = readFile(dir / "stderr.txt");
    return r;
}

} // namespace urbis::test
