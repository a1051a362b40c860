// `vox job run DIR I`: what a scheduler runs for task I of the job in DIR. It starts the task's
// command (the manifest's task_command and `--job-task I`) as a child process, so that when the
// child fails — an error, a crash, SIGKILL — this process is still there to record the run
// (host, result) and apply the retry rule, Flamenco's: a task that failed fewer than
// max_attempts times is run again (Slurm requeues it; GNU parallel and the local scheduler run
// it again), after that it is given up and --status reports it with every run's host and
// result. A SIGTERM (scancel, a time limit) stops the task without a retry: re-running the
// submitting command resumes it.
#pragma once

#include <cstdint>
#include <filesystem>

namespace vox::job {

// The exit status of the task's run: 0 when it is done.
int runJobTask(const std::filesystem::path& dir, std::uint32_t index);

}  // namespace vox::job
