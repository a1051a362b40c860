// `--status DIR`: where a job stands. Per task: its units done, missing, damaged or made with
// other settings (each unit checked on disk against its record), its state in the manifest and
// in the scheduler, its attempts; then the totals, the mean time per unit and an ETA, every
// host's failed runs, the join, and the first units that need attention with the reason.
#pragma once

#include <filesystem>

#include "core/json.h"
#include "job_scheduler.h"

namespace vox::job {

// Prints the status of the job in `dir`; returns the exit status (1 when there is no job).
int printJobStatus(const std::filesystem::path& dir);

// The view of schedulers without a queue to ask (GNU parallel, local): a task the manifest says
// is running is active while its process lives (checked when it runs on this host).
SchedulerView processView(const engine::Json& manifest);

}  // namespace vox::job
