#include "ffmpeg_video.h"

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <sstream>
#include <vector>

#include "core/atomic_file.h"

extern char** environ;

namespace vox {

std::optional<std::filesystem::path> findFfmpeg() {
    const char* path = std::getenv("PATH");
    if (!path) return std::nullopt;
    std::stringstream dirs(path);
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        if (dir.empty()) continue;
        std::filesystem::path candidate = std::filesystem::path(dir) / "ffmpeg";
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return std::nullopt;
}

engine::Status encodeMp4(const std::filesystem::path& ffmpeg, const std::string& pattern,
                         std::uint32_t first, std::uint32_t count, double fps,
                         const std::filesystem::path& out) {
    return engine::replaceFileAtomically(
        out, [&](const std::filesystem::path& temp) -> engine::Status {
            // yuv420p for players that know nothing else; it needs even sizes, hence the pad.
            // Arguments go straight to exec: no shell, so no quoting trouble with odd paths.
            std::vector<std::string> args = {ffmpeg.string(),
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
            std::vector<char*> argv;
            for (auto& a : args) argv.push_back(a.data());
            argv.push_back(nullptr);
            pid_t pid = 0;
            int rc = posix_spawn(&pid, ffmpeg.c_str(), nullptr, nullptr, argv.data(), environ);
            if (rc != 0)
                return engine::makeError("{}: cannot start ffmpeg (error {})", ffmpeg.string(), rc);
            int status = 0;
            if (waitpid(pid, &status, 0) < 0)
                return engine::makeError("{}: lost the ffmpeg process", ffmpeg.string());
            if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
                return engine::makeError("{}: ffmpeg failed (exit status {})", out.string(),
                                         WIFEXITED(status) ? WEXITSTATUS(status) : -1);
            return {};
        });
}

}  // namespace vox
