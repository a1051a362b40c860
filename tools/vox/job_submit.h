// Submitting a job, or resuming the one already in its folder: the same command does both. A new
// job gets its manifest (job_manifest.h); an existing one is checked against the command — same
// kind, settings, units and task split, none of its tasks still pending or running — and only
// the tasks with a unit missing, damaged or made with other settings are run again, each with
// its attempts counted from zero. Then the scheduler runs them and the join.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/json.h"
#include "job_kind.h"
#include "job_scheduler.h"

namespace vox::job {

// A new manifest: `settings` (every input that changes a unit's result; hashed), units
// first..last split into options.tasks tasks, the command a task runs (`--job-task I` is
// appended) and the join's.
engine::Json newManifest(const JobKind& kind, const engine::Json& settings, std::uint32_t first,
                         std::uint32_t last, const JobOptions& options,
                         const std::vector<std::string>& taskCommand,
                         const std::vector<std::string>& joinCommand);

// Submits `fresh` or resumes the job in `dir`; prints what it does. Returns the exit status.
int submitJob(const std::filesystem::path& dir, const engine::Json& fresh, const JobKind& kind,
              const JobOptions& options);

// For the schedulers: records a submission (its tasks and the scheduler's ids) in the manifest.
engine::Status recordSubmission(const std::filesystem::path& dir, const std::string& scheduler,
                                const std::vector<std::uint32_t>& tasks, const engine::Json& ids);
// Runs the manifest's join command here and waits for it.
engine::Status runJoin(const std::filesystem::path& dir);

}  // namespace vox::job
