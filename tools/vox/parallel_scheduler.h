// The GNU parallel scheduler: `parallel --retries N` runs the tasks (-j at a time, here or on
// --hosts over ssh), retrying a failed one on a host where it has not failed yet — Flamenco's
// rule, which parallel has built in — then the join.
#pragma once

#include <memory>

#include "job_scheduler.h"

namespace vox::job {

std::unique_ptr<JobScheduler> makeParallelScheduler();

}  // namespace vox::job
