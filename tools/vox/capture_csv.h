// A capture's CSV (columns in docs/CAPTURE.md): one row per written frame. A row is kept as its
// formatted counts plus its timings, so a job's task can record it in the manifest and the join
// write the very CSV one process would have written (capture_join.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/json.h"

namespace vox {

struct CaptureCsvRow {
    // frame .. upload_cells, formatted as written: pure functions of the inputs.
    std::vector<std::pair<std::string, std::string>> fields;
    std::vector<std::pair<std::string, double>>
        passMs;  // the GPU passes that ran, in order, each once
    double gpuTotalMs = 0.0, cpuEmitterUpdateMs = 0.0, wallMs = 0.0;
};

// Header and rows. The pass columns are the union over the rows in first-seen order (ReSTIR's
// temporal pass, for one, does not run on the first frame); a pass that did not run leaves its
// cell empty.
std::string captureCsvText(const std::vector<CaptureCsvRow>& rows);

// A row in a manifest's frame record, and back (numbers exactly: a double reads back the same).
engine::Json captureCsvRowJson(const CaptureCsvRow& row);
engine::Result<CaptureCsvRow> captureCsvRowFrom(const engine::Json& json);

}  // namespace vox
