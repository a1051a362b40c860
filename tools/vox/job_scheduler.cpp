#include "job_scheduler.h"

#include "job_manifest.h"
#include "local_scheduler.h"
#include "number_options.h"
#include "parallel_scheduler.h"
#include "slurm_scheduler.h"
#include "subprocess.h"

namespace vox::job {

void addJobOptions(CLI::App& cmd, JobOptions& o) {
    cmd.add_option(
           "--scheduler", o.scheduler,
           "Split the work into tasks run by: slurm (an sbatch array and a join job), parallel "
           "(GNU "
           "parallel), local (here, one after another); resumes the job already in the folder")
        ->check(CLI::IsMember({"slurm", "parallel", "local"}));
    cmd.add_option("--tasks", o.tasks, "Tasks of a job (with --scheduler)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 100000, "tasks")));
    cmd.add_option("--max-attempts", o.maxAttempts, "Runs of a failing task before it is given up")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 100, "attempts")));
    cmd.add_option("--throttle", o.throttle,
                   "Tasks running at a time (slurm: --array=…%N; parallel: -j N)")
        ->check(numberIn(engine::wholeRange(1, 100000, "tasks")));
    cmd.add_option("--partition", o.partition, "Slurm partition of the tasks and the join");
    cmd.add_option("--sbatch-option", o.sbatchOptions,
                   "Passed to sbatch for the tasks and the join, e.g. "
                   "--sbatch-option=--time=2:00:00 (repeatable)")
        ->allow_extra_args(false);
    cmd.add_option("--hosts", o.hosts,
                   "GNU parallel: hosts to run on over ssh (-S host1,host2); each needs vox and "
                   "the output folder at the same paths");
}

engine::Result<std::unique_ptr<JobScheduler>> makeScheduler(const std::string& name) {
    if (name == "slurm") return makeSlurmScheduler();
    if (name == "parallel") return makeParallelScheduler();
    if (name == "local") return makeLocalScheduler();
    return engine::makeError("scheduler '{}': expected slurm, parallel or local", name);
}

std::vector<std::string> taskCommand(const std::filesystem::path& dir, const std::string& index) {
    return {thisExecutable().string(), "job", "run", std::filesystem::absolute(dir).string(),
            index};
}

std::vector<std::string> joinCommand(const engine::Json& manifest) {
    std::vector<std::string> out;
    for (const engine::Json& a : manifest.get("join_command").items()) out.push_back(a.string());
    return out;
}

}  // namespace vox::job
