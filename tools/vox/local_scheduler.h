// The local scheduler: the tasks one after another on this machine, each retried up to the job's
// max_attempts, then the join — a job's resume and checks without a cluster.
#pragma once

#include <memory>

#include "job_scheduler.h"

namespace vox::job {

std::unique_ptr<JobScheduler> makeLocalScheduler();

}  // namespace vox::job
