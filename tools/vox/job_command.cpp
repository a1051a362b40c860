// vox job: the commands of a job in a folder, whatever its kind (a capture, a sweep) —
// `run DIR I` is what a scheduler runs for task I (job_task.h); `status DIR` and `join DIR` are
// the same as the kind's own --status and --join.
#include <filesystem>

#include "commands.h"
#include "job_manifest.h"
#include "job_status.h"
#include "job_submit.h"
#include "job_task.h"

namespace vox {

void addJobCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand(
        "job",
        "A job split into tasks (vox capture/bench sweep --scheduler): run a task, "
        "status, join");
    cmd->require_subcommand(1);
    auto dir = std::make_shared<std::string>();
    auto index = std::make_shared<std::uint32_t>(0);

    auto* run =
        cmd->add_subcommand("run",
                            "Run task I of the job in DIR, recording its result and retrying it "
                            "(what a scheduler runs)");
    run->add_option("dir", *dir, "The job's folder")->required();
    run->add_option("index", *index, "The task")->required();
    run->callback([dir, index, &exitCode] { exitCode = job::runJobTask(*dir, *index); });

    auto* status = cmd->add_subcommand("status", "Where the job in DIR stands");
    status->add_option("dir", *dir, "The job's folder")->required();
    status->callback([dir, &exitCode] { exitCode = job::printJobStatus(*dir); });

    auto* join = cmd->add_subcommand("join", "Run the job's join (its single result)");
    join->add_option("dir", *dir, "The job's folder")->required();
    join->callback([dir, &exitCode] {
        engine::Status s = job::runJoin(*dir);
        exitCode = s ? 0 : fail(s.error());
    });
}

}  // namespace vox
