// What differs between kinds of job (a capture's frames, a sweep's points): the name of a unit and
// how a unit's record and outputs are checked. Everything else — submitting, resuming, retrying,
// status — is the same code for every kind (job_submit.h, job_task.h, job_status.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/json.h"

namespace vox::job {

enum class UnitState { Done, Missing, Damaged, OtherSettings };

struct UnitCheck {
    UnitState state = UnitState::Missing;
    std::string why;  // for all but Done: "no record", "frame_00012.png: checksum differs", …
};

struct JobKind {
    std::string name;   // "capture": the manifest's "kind"
    std::string unit;   // "frame"
    std::string units;  // "frames": also the manifest's list of unit records
    // The outputs a unit's record names (files and their checksums), checked on disk; Done when
    // they are intact. Called only for records made with the job's settings and engine.
    UnitCheck (*checkOutputs)(const std::filesystem::path& dir, const engine::Json& manifest,
                              const engine::Json& record) = nullptr;
};

// The kinds there are; nullptr for an unknown name.
const JobKind* findJobKind(std::string_view name);

// Unit `unit` of the job in `dir`: no record = Missing; a record made with other settings or by
// another engine = OtherSettings; else the kind's check of its outputs.
UnitCheck checkUnit(const JobKind& kind, const std::filesystem::path& dir,
                    const engine::Json& manifest, std::uint32_t unit);

// "3, 7..12, 40": unit numbers (ascending) as ranges, for messages.
std::string unitRanges(const std::vector<std::uint32_t>& units);

}  // namespace vox::job
