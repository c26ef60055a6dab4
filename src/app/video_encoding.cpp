#include "app/video_encoding.h"

#include "base/input_error.h"
#include "io/atomic_file.h"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <string_view>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace urbis {

namespace {

/// The extension of `path` in lower case, with its dot.
std::string extensionOf(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

bool onPath(std::string_view program) {
    const char* path = std::getenv("PATH");
    std::string_view dirs = path ? path : "";
    while (!dirs.empty()) {
        const size_t colon = dirs.find(':');
        const std::filesystem::path candidate = std::filesystem::path(dirs.substr(0, colon)) / program;
        if (access(candidate.c_str(), X_OK) == 0) return true;
        dirs = colon == std::string_view::npos ? std::string_view() : dirs.substr(colon + 1);
    }
    return false;
}

/// Runs `args` (args[0] found on the PATH) and waits: its exit status, or -1 where it could not start.
int runProgram(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        execvp(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    if (waitpid(pid, &status, 0) < 0) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

void checkVideoOutput(const std::string& path, const std::string& framePattern) {
    const std::string ext = extensionOf(path);
    if (ext != ".mp4" && ext != ".gif") throw InputError("--video " + path + ": expected a .mp4 or .gif file", FailureKind::Usage);
    if (extensionOf(framePattern) != ".png")
        throw InputError("--video " + path + ": encodes .png frames (--out " + framePattern + ")", FailureKind::Usage);
    if (!onPath("ffmpeg"))
        throw InputError("--video " + path + ": ffmpeg is not on the PATH (Debian's ffmpeg package); "
                         "render the frames without --video, or install it", FailureKind::Usage);
}

void encodeVideo(const std::string& framePattern, const FrameRange& range, float fps, const std::string& path) {
    const bool gif = extensionOf(path) == ".gif";
    writeThroughTemporary(path, [&](const std::string& temporary) -> std::string {
        std::vector<std::string> args = {"ffmpeg", "-nostdin", "-loglevel", "error", "-y", "-framerate", std::to_string(fps),
                                         "-start_number", std::to_string(range.first), "-i", framePattern,
                                         "-frames:v", std::to_string(range.count())};
        if (gif) {
            // One palette made from all the frames: a GIF's 256 colours chosen for this sequence.
            args.insert(args.end(), {"-vf", "split[a][b];[a]palettegen[p];[b][p]paletteuse", "-f", "gif"});
        } else {
            // yuv420p and even sizes: what players and browsers decode.
            args.insert(args.end(), {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                     "-f", "mp4"});
        }
        args.push_back(temporary);
        const int status = runProgram(args);
        return status == 0 ? "" : "ffmpeg failed (exit status " + std::to_string(status) + ")";
    });
}

} // namespace urbis
