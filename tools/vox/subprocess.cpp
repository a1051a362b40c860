#include "subprocess.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace vox {

namespace {

std::vector<char*> argvOf(std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    return argv;
}

engine::Result<pid_t> spawn(std::vector<std::string> args, posix_spawn_file_actions_t* actions) {
    if (args.empty()) return engine::makeError("no program to run");
    std::vector<char*> argv = argvOf(args);
    pid_t pid = 0;
    // posix_spawnp looks a bare name up on PATH, and a path as given.
    const int rc = posix_spawnp(&pid, args[0].c_str(), actions, nullptr, argv.data(), environ);
    if (rc != 0) return engine::makeError("{}: cannot start: {}", args[0], std::strerror(rc));
    return pid;
}

}  // namespace

std::string describeExit(const ProgramExit& e) {
    if (e.signal != 0)
        return fmt::format("killed by signal {} ({})", e.signal, strsignal(e.signal));
    return fmt::format("exit {}", e.exitCode);
}

engine::Result<pid_t> startProgram(const std::vector<std::string>& args) {
    return spawn(args, nullptr);
}

engine::Result<ProgramExit> waitForProgram(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno == EINTR) continue;
        return engine::makeError("lost process {}: {}", long(pid), std::strerror(errno));
    }
    ProgramExit e;
    if (WIFSIGNALED(status)) {
        e.signal = WTERMSIG(status);
        e.exitCode = -1;
    } else {
        e.exitCode = WEXITSTATUS(status);
    }
    return e;
}

engine::Result<ProgramOutput> runProgram(const std::vector<std::string>& args, bool showErrors) {
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0)
        return engine::makeError("cannot make a pipe: {}", std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    if (!showErrors)
        posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    auto pid = spawn(args, &actions);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    if (!pid) {
        close(fds[0]);
        return pid.error();
    }
    ProgramOutput result;
    char buffer[4096];
    while (true) {
        const ssize_t n = read(fds[0], buffer, sizeof buffer);
        if (n > 0) {
            result.out.append(buffer, std::size_t(n));
        } else if (n == 0 || errno != EINTR) {
            break;
        }
    }
    close(fds[0]);
    auto exit = waitForProgram(*pid);
    if (!exit) return exit.error();
    result.exit = *exit;
    return result;
}

std::optional<std::filesystem::path> findOnPath(std::string_view name) {
    const char* path = std::getenv("PATH");
    if (!path) return std::nullopt;
    std::stringstream dirs(path);
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        if (dir.empty()) continue;
        std::filesystem::path candidate = std::filesystem::path(dir) / name;
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return std::nullopt;
}

std::filesystem::path thisExecutable() {
    std::error_code ec;
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path("vox") : self;
}

}  // namespace vox
