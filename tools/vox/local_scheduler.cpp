#include "local_scheduler.h"

#include <cstdio>
#include <fmt/format.h>

#include "job_kind.h"
#include "job_manifest.h"
#include "job_status.h"
#include "job_submit.h"
#include "job_task.h"
#include "subprocess.h"

namespace vox::job {

namespace {

class LocalScheduler : public JobScheduler {
public:
    std::string name() const override { return "local"; }

    engine::Status run(const std::filesystem::path& dir, const std::vector<std::uint32_t>& tasks,
                       const JobOptions&) override {
        if (engine::Status s = recordSubmission(dir, "local", tasks, {}); !s) return s;
        std::vector<std::uint32_t> failed;
        for (std::uint32_t i : tasks) {
            while (runJobTask(dir, i) != 0) {
                auto m = readManifest(dir);
                if (!m) return m.error();
                const std::string state = taskRecord(*m, i).get("state").string();
                if (state == "retrying") continue;
                // Ctrl-C or a SIGTERM stops the job, not just this task.
                if (state == "stopped")
                    return engine::makeError(
                        "{}: stopped at task {}; the same command resumes the job", dir.string(),
                        i);
                failed.push_back(i);  // given up; the other tasks go on (Flamenco's rule)
                break;
            }
        }
        if (!failed.empty())
            return engine::makeError("{}: task(s) {} failed; --status shows each run's result",
                                     dir.string(), unitRanges(failed));
        return runJoin(dir);
    }

    SchedulerView view(const engine::Json& manifest) const override {
        return processView(manifest);
    }

    engine::Status retry(std::uint32_t) const override { return {}; }  // run() runs it again
};

}  // namespace

std::unique_ptr<JobScheduler> makeLocalScheduler() { return std::make_unique<LocalScheduler>(); }

}  // namespace vox::job
