// The points of `vox bench sweep`: every world × (the direct-light settings, then the indirect-
// light series), numbered in that order from 0, each measured against its world's cached
// reference with its frame counter restarted — so a point's errors do not depend on which points
// ran before it, in this process or another, and a job's tasks (sweep_job.h) give the same rows
// as one process. A world's points are measured in --seeds interleaved rounds (round r: every
// point with seed r, the order reversed every other round), which give the errors their seeds'
// min-max; then the direct-light points are timed again in the cost model's calibration rounds
// (metrics/cost_model.h kCostCalibrationRounds), and their cost is the model's (counted work at
// the fitted per-kind costs) with its interval.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "job_scheduler.h"
#include "lighting/lighting_settings.h"
#include "metrics/cost_model.h"
#include "thesis_scenes.h"

namespace engine::gpu {
class Context;
}

namespace vox {

struct SweepOptions {
    std::vector<std::string> worlds = kThesisScenes;
    std::string methods = "restir,restir-unbiased,ris,uniform";
    std::string candidates = "1,8,32";
    std::string modes = "point,area";
    std::string brickLights = "on,off";
    std::string rays = "1,4,16";
    std::string size = "128x72";
    std::uint32_t frames = 12;
    std::uint32_t referenceSpp = 1024;
    std::uint32_t seeds = 3;  // interleaved rounds per world: error spreads and cost intervals
    double costDrift =
        engine::metrics::kDefaultCostDrift;  // kinds' relative costs may differ between runs by
                                             // this factor (metrics/cost_model.h
                                             // kDefaultCostDrift): cost intervals include it
    // Indirect-light series (docs/ACCURACY.md): ReSTIR's defaults for the direct light plus
    // none | cache-K | reference, measured against a multi-bounce reference.
    std::string indirect = "none,cache-32,cache-128,reference,vct";
    std::uint32_t indirectBounces = 3;
    std::uint32_t indirectReferenceSpp = 512;
    std::string output = "out/sweep";
    job::JobOptions job;       // --scheduler …: points as the tasks of a job (sweep_job.h)
    std::string join, status;  // --join DIR, --status DIR
    // --job-task I: measure task I's points of the job in --output
    std::optional<std::uint32_t> jobTask;
};

std::vector<std::string> splitList(const std::string& s);

struct SweepPlan {
    glm::uvec2 size{0};
    std::vector<std::pair<std::string, engine::lighting::LightingSettings>> direct,
        indirect;  // labelled
    std::uint32_t pointsPerWorld() const { return std::uint32_t(direct.size() + indirect.size()); }
};
engine::Result<SweepPlan> planSweep(const SweepOptions& o);

// The CSV's first line; each point writes one line after it (none when it is skipped).
inline constexpr const char* kSweepCsvHeader =
    "scene,method,setting,emitters,total_ms,primary_ms,lighting_ms,mae,mse,rmae,indirect,reference_"
    "bounces,"
    "mean_ratio,seeds,cost_ms,cost_low,cost_high,mae_low,mae_high,mse_low,mse_high,front_mae,front_"
    "mse\n";

// Measures the points first..last that `wanted` accepts (all when it is empty), calling
// onPoint(point, line) for each in order; `line` is empty for a point that does not apply (brick
// lights off in a world without brick lights). References are rendered (and cached in
// OUTPUT/cache) only for the worlds and series the points need.
engine::Status measureSweepPoints(
    engine::gpu::Context& gpu, const SweepOptions& o, const SweepPlan& plan, std::uint32_t first,
    std::uint32_t last, const std::function<bool(std::uint32_t)>& wanted,
    const std::function<engine::Status(std::uint32_t, const std::string&)>& onPoint);

// Draws the charts of OUTPUT/sweep.csv (tools/plot_sweep.py); a note when matplotlib is missing.
void drawSweepCharts(const std::string& output);

}  // namespace vox
