// Who runs a job's tasks: Slurm (an sbatch array and a join job after it), GNU parallel (here or
// over ssh), or this process, one task after another. Each runs the same command per task,
// `vox job run DIR I` (job_task.h), and the job's join command after the last one.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/json.h"

namespace vox::job {

// The command-line options of a job, shared by the commands that split their work.
struct JobOptions {
    std::string scheduler;  // empty: no job, the command runs as one process as before
    std::uint32_t tasks = 4;
    std::uint32_t maxAttempts = 3;  // a task failing this many times is given up (Flamenco's rule)
    std::uint32_t throttle = 0;     // tasks at a time; 0: the scheduler's choice
    std::string partition;          // Slurm
    std::vector<std::string> sbatchOptions;
    std::string hosts;  // GNU parallel: --sshlogin list
};
void addJobOptions(CLI::App& cmd, JobOptions& o);

// The scheduler's own view of a task, for --status: "RUNNING on vm", "PENDING (Resources)".
struct SchedulerView {
    std::map<std::uint32_t, std::string> tasks;
    std::string join;                    // the join's state, when the scheduler runs it apart
    std::string error;                   // when it could not be asked ("squeue: …")
    std::vector<std::uint32_t> active;   // tasks pending or running there now
    std::vector<std::uint32_t> running;  // of those, the ones running
};

class JobScheduler {
public:
    virtual ~JobScheduler() = default;
    virtual std::string name() const = 0;
    // Runs (or submits) `tasks` of the job in `dir` and the join after them, recording in the
    // manifest what it submitted. Slurm returns once submitted; the others when all is done.
    virtual engine::Status run(const std::filesystem::path& dir,
                               const std::vector<std::uint32_t>& tasks,
                               const JobOptions& options) = 0;
    virtual SchedulerView view(const engine::Json& manifest) const = 0;
    // A task's run failed and it has attempts left: make the scheduler run it again. Slurm
    // requeues the array task; the others retry it themselves when the run reports failure.
    virtual engine::Status retry(std::uint32_t task) const = 0;
};

// "slurm", "parallel", "local"; an error names the choices.
engine::Result<std::unique_ptr<JobScheduler>> makeScheduler(const std::string& name);

// `vox job run DIR I`: the command each scheduler runs for task I.
std::vector<std::string> taskCommand(const std::filesystem::path& dir, const std::string& index);
// The manifest's join command ("join_command").
std::vector<std::string> joinCommand(const engine::Json& manifest);

}  // namespace vox::job
