#include "ffmpeg_video.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <fstream>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "core/atomic_file.h"

extern char** environ;

namespace vox {

namespace fs = std::filesystem;

namespace {

// Runs the program; its stderr is collected into `errors`. The exit status, or -1 if it did not
// exit (a signal).
engine::Result<int> run(const std::vector<std::string>& args, std::string& errors) {
    int pipeFds[2];
    if (::pipe2(pipeFds, O_CLOEXEC) != 0)
        return engine::makeError("{}: cannot start: {}", args[0], std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipeFds[1], STDERR_FILENO);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, args[0].c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(pipeFds[1]);
    if (rc != 0) {
        ::close(pipeFds[0]);
        return engine::makeError("{}: cannot start: {}", args[0], std::strerror(rc));
    }
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(pipeFds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        errors.append(buffer, std::size_t(n));
    }
    ::close(pipeFds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return engine::makeError("{}: lost the process", args[0]);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The first line ffmpeg printed, with the temporary's name replaced by the file's.
std::string firstLine(const std::string& text, const fs::path& temporary, const fs::path& out) {
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line) && line.find_first_not_of(" \t\r") == std::string::npos) {
    }
    for (auto at = line.find(temporary.string()); at != std::string::npos;
         at = line.find(temporary.string()))
        line.replace(at, temporary.string().size(), out.string());
    return line;
}

// An MP4 is a sequence of boxes (ISO/IEC 14496-12 §4.2: a 32-bit size, or 1 and a 64-bit size
// after the type, or 0 for "to the end"); ffmpeg writes the index box `moov` last, after the
// frames. A file cut short (a full disk) fails to add up or has no `moov`: unplayable.
engine::Status checkMp4Complete(const fs::path& file, const fs::path& out) {
    std::ifstream in(file, std::ios::binary);
    std::error_code ec;
    const std::uint64_t size = fs::file_size(file, ec);
    if (!in || ec) return engine::makeError("{}: ffmpeg left no video", out.string());
    std::uint64_t at = 0;
    bool index = false;
    while (at < size) {
        unsigned char head[16] = {};
        in.seekg(std::streamoff(at));
        if (size - at < 8 || !in.read(reinterpret_cast<char*>(head), 8)) break;
        std::uint64_t box = std::uint64_t(head[0]) << 24 | std::uint64_t(head[1]) << 16 |
                            std::uint64_t(head[2]) << 8 | head[3];
        if (box == 1) {
            if (size - at < 16 || !in.read(reinterpret_cast<char*>(head + 8), 8)) break;
            box = 0;
            for (int i = 8; i < 16; ++i) box = box << 8 | head[i];
        } else if (box == 0) {
            box = size - at;
        }
        if (box < 8 || box > size - at) break;
        index |= std::string_view(reinterpret_cast<const char*>(head + 4), 4) == "moov";
        at += box;
    }
    if (at != size || !index)
        return engine::makeError(
            "{}: ffmpeg left an incomplete video ({}); the previous file is kept", out.string(),
            index ? fmt::format("cut short at byte {} of {}", at, size) : "no index box");
    return {};
}

}  // namespace

std::optional<fs::path> findFfmpeg() {
    const char* path = std::getenv("PATH");
    if (!path) return std::nullopt;
    std::stringstream dirs(path);
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        if (dir.empty()) continue;
        fs::path candidate = fs::path(dir) / "ffmpeg";
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return std::nullopt;
}

engine::Status encodeMp4(const fs::path& ffmpeg, const std::string& pattern, std::uint32_t first,
                         std::uint32_t count, double fps, const fs::path& out) {
    return engine::replaceFileAtomically(out, [&](const fs::path& temp) -> engine::Status {
        // yuv420p for players that know nothing else; it needs even sizes, hence the pad.
        // Arguments go straight to exec: no shell, so no quoting trouble with odd paths.
        const std::vector<std::string> args = {ffmpeg.string(),
                                               "-nostdin",
                                               "-y",
                                               "-loglevel",
                                               "error",
                                               "-framerate",
                                               fmt::format("{}", fps),
                                               "-start_number",
                                               std::to_string(first),
                                               "-i",
                                               pattern,
                                               "-frames:v",
                                               std::to_string(count),
                                               "-vf",
                                               "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                               "-c:v",
                                               "libx264",
                                               "-pix_fmt",
                                               "yuv420p",
                                               "-crf",
                                               "18",
                                               "-f",
                                               "mp4",
                                               temp.string()};
        std::string errors;
        auto status = run(args, errors);
        if (!status) return status.error();
        // ffmpeg (5.1) exits 0 when writing the video's end fails ("Error writing trailer of X: No
        // space left on device"); at -loglevel error anything it prints is an error.
        if (*status != 0 || !errors.empty()) {
            const std::string line = firstLine(errors, temp, out);
            return engine::makeError("{}: ffmpeg failed{}{}", out.string(),
                                     *status != 0 ? fmt::format(" (exit status {})", *status) : "",
                                     line.empty() ? "" : ": " + line);
        }
        return checkMp4Complete(temp, out);
    });
}

}  // namespace vox
