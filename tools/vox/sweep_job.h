// A sweep as a job (job_manifest.h): `vox bench sweep … --scheduler S --tasks N` splits its points
// (sweep_points.h) into N tasks; each measures the points of its slice not yet recorded and
// records each point's CSV line in the manifest; the join writes sweep.csv in point order and
// draws the charts, as one run would have. The references are cached in OUTPUT/cache, shared by
// the tasks (the first to need one renders it while the others wait for it).
#pragma once

#include <filesystem>

#include "job_kind.h"
#include "sweep_points.h"

namespace vox {

const job::JobKind& sweepJobKind();

int submitSweepJob(const SweepOptions& o);
int runSweepTask(const SweepOptions& o);
int joinSweep(const std::filesystem::path& dir);

}  // namespace vox
