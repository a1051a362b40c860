#include "job_kind.h"

#include <fmt/format.h>

#include "capture_job.h"
#include "job_manifest.h"
#include "sweep_job.h"

namespace vox::job {

const JobKind* findJobKind(std::string_view name) {
    for (const JobKind* kind : {&captureJobKind(), &sweepJobKind()})
        if (kind->name == name) return kind;
    return nullptr;
}

UnitCheck checkUnit(const JobKind& kind, const std::filesystem::path& dir,
                    const engine::Json& manifest, std::uint32_t unit) {
    const engine::Json& record = unitRecord(manifest, kind.units, unit);
    if (record.isNull()) return {UnitState::Missing, "no record"};
    if (record.get("settings").string() != manifest.get("settings_hash").string())
        return {UnitState::OtherSettings,
                fmt::format("settings {}, the job's {}", record.get("settings").string(),
                            manifest.get("settings_hash").string())};
    if (record.get("engine").string() != manifest.get("engine").string())
        return {UnitState::OtherSettings,
                fmt::format("made by {}, the job's engine is {}", record.get("engine").string(),
                            manifest.get("engine").string())};
    return kind.checkOutputs ? kind.checkOutputs(dir, manifest, record)
                             : UnitCheck{UnitState::Done, {}};
}

std::string unitRanges(const std::vector<std::uint32_t>& units) {
    std::string out;
    for (std::size_t i = 0; i < units.size();) {
        std::size_t j = i;
        while (j + 1 < units.size() && units[j + 1] == units[j] + 1) ++j;
        out += fmt::format("{}{}", out.empty() ? "" : ", ", units[i]);
        if (j > i) out += fmt::format("..{}", units[j]);
        i = j + 1;
    }
    return out;
}

}  // namespace vox::job
