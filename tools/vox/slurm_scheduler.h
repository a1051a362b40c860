// The Slurm scheduler: the tasks as one sbatch job array (--array=LIST[%throttle], --requeue,
// one log per task in DIR/job), and the join as a second job that starts only after every task
// succeeded (--dependency=afterok, --kill-on-invalid-dep=yes: cancelled if a task is given up).
// A task's run that fails with attempts left requeues its array task (scontrol requeue); Slurm
// starts it again after its requeue delay (slurm.conf AuthInfo cred_expire, 120 s by default).
// --status asks squeue for each task's state.
#pragma once

#include <memory>

#include "job_scheduler.h"

namespace vox::job {

std::unique_ptr<JobScheduler> makeSlurmScheduler();

}  // namespace vox::job
