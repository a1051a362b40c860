#include "parallel_scheduler.h"

#include <cstdio>
#include <fmt/format.h>

#include "job_manifest.h"
#include "job_status.h"
#include "job_submit.h"
#include "subprocess.h"

namespace vox::job {

namespace {

class ParallelScheduler : public JobScheduler {
public:
    std::string name() const override { return "parallel"; }

    engine::Status run(const std::filesystem::path& dir, const std::vector<std::uint32_t>& tasks,
                       const JobOptions& o) override {
        if (!tasks.empty()) {
            auto parallel = findOnPath("parallel");
            if (!parallel)
                return engine::makeError(
                    "--scheduler parallel: GNU parallel is not on PATH (apt-get install parallel)");
            auto version = runProgram({parallel->string(), "--will-cite", "--version"});
            if (!version || version->out.find("GNU parallel") == std::string::npos)
                return engine::makeError(
                    "--scheduler parallel: {} is not GNU parallel (moreutils' parallel?)",
                    parallel->string());
            auto m = readManifest(dir);
            if (!m) return m.error();
            const std::uint32_t attempts =
                std::max(1u, std::uint32_t(m->get("max_attempts").number(1)));
            // --retries counts runs: a task that fails is run again, on a host where it has not
            // failed when there is one, until it has run `attempts` times.
            // -q: parallel quotes the command's words for the shell it runs them with.
            std::vector<std::string> args = {parallel->string(),
                                             "--will-cite",
                                             "-q",
                                             "--retries",
                                             std::to_string(attempts),
                                             "--joblog",
                                             (jobFolder(dir) / "parallel.log").string()};
            if (o.throttle > 0) args.insert(args.end(), {"-j", std::to_string(o.throttle)});
            if (!o.hosts.empty()) args.insert(args.end(), {"-S", o.hosts});
            for (const std::string& a : taskCommand(dir, "{}")) args.push_back(a);
            args.push_back(":::");
            for (std::uint32_t i : tasks) args.push_back(std::to_string(i));
            if (engine::Status s = recordSubmission(dir, "parallel", tasks, {}); !s) return s;
            std::printf("parallel %zu task(s), %u attempt(s) each; log %s\n", tasks.size(),
                        attempts, (jobFolder(dir) / "parallel.log").string().c_str());
            std::fflush(stdout);
            auto pid = startProgram(args);
            if (!pid) return pid.error();
            auto exit = waitForProgram(*pid);
            if (!exit) return exit.error();
            if (!exit->ok())
                return engine::makeError(
                    "{}: GNU parallel ended with {}: task(s) failed after {} attempt(s); "
                    "--status shows each run's result",
                    dir.string(), describeExit(*exit), attempts);
        }
        return runJoin(dir);
    }

    SchedulerView view(const engine::Json& manifest) const override {
        return processView(manifest);
    }

    engine::Status retry(std::uint32_t) const override { return {}; }  // parallel's --retries
};

}  // namespace

std::unique_ptr<JobScheduler> makeParallelScheduler() {
    return std::make_unique<ParallelScheduler>();
}

}  // namespace vox::job
