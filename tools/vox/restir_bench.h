// vox bench restir's parts (bench_restir_command.cpp has the story): its options, its rows (the
// lighting settings compared, restir_bench_rows.cpp), their measurement per scene
// (restir_bench_measure.cpp) and the JSON, CSV and markdown written from it
// (restir_bench_report.cpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "lighting/lighting_settings.h"
#include "metrics/cost_model.h"
#include "metrics/count_ladder.h"
#include "metrics/interleaved_rounds.h"
#include "render/frame_work.h"
#include "render/renderer.h"
#include "thesis_scenes.h"
#include "world/scene.h"

namespace engine::gpu {
class Context;
}

namespace vox {

struct RestirBenchOptions {
    std::vector<std::string> worlds = kThesisScenes;
    std::string size = "96x64";
    std::uint32_t frames = 12;
    std::uint32_t referenceSpp = 512;
    std::uint32_t seeds = 5;
    std::string rows = "restir,restir-unbiased,ris,uniform";
    std::string sampling;  // empty: the sampling knob's default
    std::vector<std::string> variants;
    std::string versus;       // empty: every ReSTIR row at defaults (one per --sampling value)
    double confidence = 0.9;  // of the verdicts' intervals; 5 seeds' min-max covers 93.75 %
    double noise = 0.05;      // a verdict's interval must exclude 1 by this much (criterion.rs's
                              // noise threshold): the cost model's own fit is 1-3 % off its points
    double costDrift = engine::metrics::kDefaultCostDrift;  // between-run movement of the kinds'
                                                            // relative costs (cost_model.h)
    std::string clock = "auto";  // gpu: fastest frame's GPU timestamps; cpu: the process's CPU
                                 // time; auto: cpu on a CPU device
    bool quick = false;
    std::string output =
        "out/bench_restir.json";  // and the summary CSV beside it (.csv), for vox bench recommend
    std::string markdown;
    std::string countsFrom;  // an earlier run's JSON: its equal-cost counts instead of this run's
};

// Equal-cost counts by (scene, row name), from --counts-from.
using PinnedCounts = std::map<std::pair<std::string, std::string>, double>;
engine::Result<PinnedCounts> readPinnedCounts(const std::string& path);

// Which knob a row scales to ReSTIR's cost (the cost model's, from counted work).
enum class EqualTime { None, ShadowRays, Candidates };

struct Row {
    std::string name;
    engine::lighting::LightingSettings lighting;
    EqualTime scale = EqualTime::None;
    std::string sampling;  // the sampling knob's value, for the recommendation
};

// A row's measurements at one count, per seed.
struct RungResult {
    std::vector<double> ms, mse, mae, meanRatio;
};

struct RowResult {
    // One per seed; a scaled row's are interpolated to its equal-cost count between the ladder's
    // two rungs (metrics/count_ladder.h): errors in log-log, time linearly.
    std::vector<double> ms, mse, mae, meanRatio;
    double equalCount = 0.0;                // shadow rays or candidates at equal cost (scaled rows)
    double fittedCount = 0.0;               // what this run's model gave (differs when pinned)
    std::uint32_t scaledTo = 0;             // equalCount rounded, for the tables
    engine::metrics::LadderBracket ladder;  // the rungs rendered
    RungResult rungs[2];                    // at ladder.low, ladder.high (scaled rows)
    engine::render::FrameWork work;         // one frame's, at equalCount (work is linear in it)
};

// The cost model's calibration: every calibration point timed in interleaved rounds.
constexpr engine::metrics::RoundsPlan kCostRounds = engine::metrics::kCostCalibrationRounds;

// A setting timed to calibrate the cost model: each row as given, and each scaled row at two
// counts of its scaled knob (so the model sees that knob's slope).
struct CalibrationPoint {
    std::string label;
    engine::lighting::LightingSettings lighting;
    engine::render::FrameWork work;
    std::vector<double> roundMs;  // its time in each interleaved round
};

// The rows: the default rows (per --sampling value for those that resample), then the variants.
engine::Result<std::vector<Row>> rowsOf(const RestirBenchOptions& o);
// The rows the others are divided by: --versus, else the ReSTIR rows at defaults.
engine::Result<std::vector<std::size_t>> versusOf(const RestirBenchOptions& o,
                                                  const std::vector<Row>& rows);
// The method, the knob scaled to equal time (`also`, may be empty) and the knobs that differ from
// the defaults, as options: what a row is, in the JSON and the CSV.
std::string settingsText(const engine::lighting::LightingSettings& l, std::string_view also = {});
// The method as the --method knob names it (restir-unbiased apart).
std::string methodName(const engine::lighting::LightingSettings& l);
// The sampling knob's value.
std::string samplingText(const engine::lighting::LightingSettings& l);
// `l` with the sampling knob at its default.
engine::lighting::LightingSettings withDefaultSampling(engine::lighting::LightingSettings l);

// What every scene's measurement shares.
struct RestirSetup {
    const RestirBenchOptions& options;
    const std::vector<Row>& rows;
    const std::vector<std::size_t>& versus;
    engine::gpu::Context& gpu;
    engine::render::FrameSettings frame;
    bool cpuClock;                         // a frame's time: CPU time, else the fastest GPU frame's
    std::filesystem::path cacheDir;        // the references, cached on disk
    const PinnedCounts* pinned = nullptr;  // --counts-from: counts that replace the fitted ones
};

struct SceneResults {
    std::vector<RowResult> rows;
    std::uint32_t emitters = 0;
    double targetMs = 0.0;                      // the yardstick's median time
    std::vector<CalibrationPoint> calibration;  // the first is the yardstick: the cost unit
    engine::metrics::CostModel model;           // per-kind costs, in the yardstick's time
    double costDrift = 0.0;                     // widens cost ratios (CostModel::ratio)
    std::vector<int> timedAs;  // per row: its calibration point when timed as it is, else -1
};

// Row i's cost over row v's with its interval, widened by the drift: measured in the calibration
// rounds when both were timed as they are (the unscaled rows), else under the scene's model.
engine::metrics::MedianInterval costRatio(const SceneResults& s, std::size_t i, std::size_t v);

// Progress over all scenes, rows and seeds, for the lines on stderr.
struct RestirProgress {
    std::size_t done = 0, total = 0;
};

// One scene: the cost model calibrated in interleaved rounds, the scaled rows set to the
// yardstick's cost under it, then every row per seed.
engine::Result<SceneResults> measureScene(const RestirSetup& setup, engine::world::Scene& scene,
                                          RestirProgress& progress);

}  // namespace vox
