#include "job_task.h"

#include <array>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>

#include "commands.h"
#include "job_manifest.h"
#include "job_scheduler.h"
#include "subprocess.h"

namespace vox::job {

namespace fs = std::filesystem;

namespace {

volatile std::sig_atomic_t gStopSignal = 0;
volatile pid_t gChild = 0;

// A stop request (scancel, a time limit, Ctrl-C) goes on to the task and is remembered: the run
// ends as stopped, not failed, and is not retried.
void forwardStop(int signal) {
    gStopSignal = signal;
    if (gChild > 0) kill(gChild, signal);
}

// Forwards stop requests while a task runs; the previous handlers return with it (the local
// scheduler runs tasks in this process, and a Ctrl-C between them must stop it as usual).
class StopForwarding {
public:
    StopForwarding() {
        gStopSignal = 0;
        struct sigaction stop {};
        stop.sa_handler = forwardStop;
        stop.sa_flags = SA_RESTART;  // the waits and writes go on after forwarding
        sigemptyset(&stop.sa_mask);
        for (std::size_t i = 0; i < kSignals.size(); ++i)
            sigaction(kSignals[i], &stop, &mPrevious[i]);
    }
    ~StopForwarding() {
        for (std::size_t i = 0; i < kSignals.size(); ++i)
            sigaction(kSignals[i], &mPrevious[i], nullptr);
    }
    StopForwarding(const StopForwarding&) = delete;
    StopForwarding& operator=(const StopForwarding&) = delete;

private:
    static constexpr std::array<int, 3> kSignals = {SIGTERM, SIGINT, SIGHUP};
    std::array<struct sigaction, 3> mPrevious{};
};

// The Slurm array task running this process, "12_3", when there is one.
std::string slurmTaskId() {
    const char* job = std::getenv("SLURM_ARRAY_JOB_ID");
    const char* task = std::getenv("SLURM_ARRAY_TASK_ID");
    if (job && task) return fmt::format("{}_{}", job, task);
    const char* plain = std::getenv("SLURM_JOB_ID");
    return plain ? plain : "";
}

}  // namespace

int runJobTask(const fs::path& dir, std::uint32_t index) {
    auto manifest = readManifest(dir);
    if (!manifest) return fail(manifest.error());
    const std::size_t taskCount = manifest->get("tasks").items().size();
    if (index >= taskCount)
        return fail(engine::makeError("{}: no task {} (the job has tasks 0..{})",
                                      manifestPath(dir).string(), index, taskCount - 1));
    auto scheduler = makeScheduler(manifest->get("scheduler").string());
    if (!scheduler) return fail(scheduler.error());
    std::vector<std::string> command;
    for (const engine::Json& a : manifest->get("task_command").items())
        command.push_back(a.string());
    if (command.empty())
        return fail(engine::makeError("{}: no task_command", manifestPath(dir).string()));
    command.push_back("--job-task");
    command.push_back(std::to_string(index));

    StopForwarding forwarding;

    auto pid = startProgram(command);
    if (!pid) return fail(pid.error());
    gChild = *pid;
    std::uint32_t attempt = 0, maxAttempts = 1;
    const std::string host = hostName(), started = utcNow(), slurm = slurmTaskId();
    engine::Status recorded = updateManifest(dir, [&](engine::Json& m) -> engine::Status {
        engine::Json& task = taskRecord(m, index);
        attempt = std::uint32_t(task.get("attempts").number()) + 1;
        maxAttempts = std::max(1u, std::uint32_t(m.get("max_attempts").number(1)));
        task["attempts"] = attempt;
        task["state"] = "running";
        engine::Json run;
        run["attempt"] = attempt;
        run["host"] = host;
        run["pid"] = double(*pid);
        if (!slurm.empty()) run["slurm"] = slurm;
        run["started"] = started;
        task["runs"].push(std::move(run));
        return {};
    });
    // Without the record the run still goes on: its frames record themselves.
    if (!recorded) std::fprintf(stderr, "vox: %s\n", recorded.error().message.c_str());
    std::printf("task %u: attempt %u of %u on %s (pid %ld)\n", index, attempt, maxAttempts,
                host.c_str(), long(*pid));
    std::fflush(stdout);

    auto exit = waitForProgram(*pid);
    gChild = 0;
    if (!exit) return fail(exit.error());
    const bool stopped = gStopSignal != 0;
    const bool retrying = !exit->ok() && !stopped && attempt < maxAttempts;
    const std::string state = exit->ok() ? "done"
                              : stopped  ? "stopped"
                              : retrying ? "retrying"
                                         : "failed";
    // A stop is a decision, not a failure of the task or its host: recorded apart.
    const std::string result =
        stopped ? fmt::format("stopped by signal {}", int(gStopSignal)) : describeExit(*exit);
    recorded = updateManifest(dir, [&](engine::Json& m) -> engine::Status {
        engine::Json& task = taskRecord(m, index);
        task["state"] = state;
        auto& runs = task["runs"].items();
        for (auto it = runs.rbegin(); it != runs.rend(); ++it) {
            if (it->get("pid").number() == double(*pid) && it->get("host").string() == host) {
                (*it)["ended"] = utcNow();
                (*it)["result"] = result;
                break;
            }
        }
        return {};
    });
    if (!recorded) std::fprintf(stderr, "vox: %s\n", recorded.error().message.c_str());
    if (exit->ok()) {
        std::printf("task %u: done\n", index);
        std::fflush(stdout);  // before what the next task or the join prints
        return 0;
    }
    if (stopped) {
        std::printf("task %u: %s; re-run the submitting command to resume it\n", index,
                    result.c_str());
        std::fflush(stdout);
        return 1;
    }
    if (!retrying) {
        std::printf("task %u: %s on attempt %u of %u: given up\n", index, result.c_str(), attempt,
                    maxAttempts);
        std::fflush(stdout);
        return 1;
    }
    std::printf("task %u: %s on attempt %u of %u: run again\n", index, result.c_str(), attempt,
                maxAttempts);
    std::fflush(stdout);
    if (engine::Status s = (*scheduler)->retry(index); !s) return fail(s.error());
    return 1;
}

}  // namespace vox::job
