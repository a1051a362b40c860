// Running other programs — the scheduler's commands (sbatch, squeue, scontrol, GNU parallel) and
// vox itself for a job's tasks: the argument vector goes straight to exec, no shell, so paths
// with spaces or quotes need no quoting.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <sys/types.h>
#include <vector>

#include "core/error.h"

namespace vox {

struct ProgramExit {
    int exitCode = 0;  // when it exited
    int signal = 0;    // when a signal ended it (exitCode then -1)
    bool ok() const { return signal == 0 && exitCode == 0; }
};
// "exit 0", "exit 3", "killed by signal 9 (Killed)".
std::string describeExit(const ProgramExit& e);

// Starts `args` (args[0] a path, or a name looked up on PATH) with this process's stdin, stdout
// and stderr.
engine::Result<pid_t> startProgram(const std::vector<std::string>& args);
// Waits for a started program (through signals that interrupt the wait).
engine::Result<ProgramExit> waitForProgram(pid_t pid);

struct ProgramOutput {
    ProgramExit exit;
    std::string out;  // its standard output; its standard error goes to ours
};
// Runs `args` to the end and returns what it printed; `showErrors` false sends its standard error
// to /dev/null (a query whose complaints are expected, e.g. squeue on a purged job).
engine::Result<ProgramOutput> runProgram(const std::vector<std::string>& args,
                                         bool showErrors = true);

// `name` on PATH, if it is there and executable.
std::optional<std::filesystem::path> findOnPath(std::string_view name);

// This program's own executable (/proc/self/exe), for the commands a job's tasks run.
std::filesystem::path thisExecutable();

}  // namespace vox
