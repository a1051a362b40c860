// A job: one long piece of work (a capture's frames, a sweep's points) split into tasks that a
// scheduler runs — a Slurm array, GNU parallel, or this machine one after another — then joined
// into the single result. Everything about it lives in its output folder:
//
//   DIR/job.json   the manifest: what the job is (settings and their hash, the engine that runs
//                  it, the commands of a task and of the join), its tasks (units, state, attempts,
//                  each run's host and result), the submissions, and one record per unit
//                  (a frame's checksum and CSV row; a point's CSV line) written by the task
//                  that made it. Format: docs/CAPTURE.md#the-job-manifest.
//   DIR/job/       the scripts a scheduler runs, their logs, and job.lock: every update of the
//                  manifest is a read-modify-write under that lock (core/exclusive_file_lock.h),
//                  written atomically, so readers (--status) need no lock and a killed writer
//                  leaves the previous manifest.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/json.h"

namespace vox::job {

inline constexpr const char* kManifestFormat = "vox job 1";

std::filesystem::path manifestPath(const std::filesystem::path& dir);  // DIR/job.json
std::filesystem::path jobFolder(const std::filesystem::path& dir);     // DIR/job

engine::Result<engine::Json> readManifest(const std::filesystem::path& dir);
// Under the job's lock: reads the manifest (null when there is none yet), lets `change` edit it,
// writes it back atomically. When `change` fails nothing is written and its error is returned.
engine::Status updateManifest(const std::filesystem::path& dir,
                              const std::function<engine::Status(engine::Json&)>& change);

// The units first..last in `tasks` contiguous slices, as even as can be (the first ones get one
// fewer when it does not divide).
struct TaskRange {
    std::uint32_t index = 0, first = 0, last = 0;
};
std::vector<TaskRange> splitUnits(std::uint32_t first, std::uint32_t last, std::uint32_t tasks);

// The manifest's record of task `index` (CHECKed to exist).
engine::Json& taskRecord(engine::Json& manifest, std::uint32_t index);
const engine::Json& taskRecord(const engine::Json& manifest, std::uint32_t index);
TaskRange taskRange(const engine::Json& task);

// The record of unit `unit` in the manifest's list `units` ("frames", "points"): null when the
// unit has none yet. setUnitRecord grows the list as needed.
const engine::Json& unitRecord(const engine::Json& manifest, const std::string& units,
                               std::uint32_t unit);
void setUnitRecord(engine::Json& manifest, const std::string& units, std::uint32_t unit,
                   engine::Json record);

// What a record and a manifest say about who made what.
std::string hostName();
std::string utcNow();  // "2026-12-04T21:58:24Z"
// "vox 0.1.0 (build fnv1a64:…)": the version and a checksum of this executable, shaders included
// (they are compiled into it), so frames made by another build are told apart.
const std::string& engineVersion();

}  // namespace vox::job
