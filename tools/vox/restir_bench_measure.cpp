// vox bench restir's measurement of one scene. Equal time first: each scaled row's count is
// fitted to the yardstick's time (the first versus row), the two measured back to back so that
// other work on the machine slows both; then all rows at their fitted settings in interleaved
// rounds (the verdicts' time ratios); then the seeds, every row of a seed back to back.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "metrics/seed_statistics.h"
#include "restir_bench.h"
#include "sweep_runner.h"

namespace vox {

namespace {

using engine::lighting::LightingSettings;

// One scene's renderer, view and reference, shared by all its measurements.
struct SceneBench {
    const RestirSetup& setup;
    engine::world::Scene& scene;
    engine::world::CameraPreset camera;
    const std::vector<glm::vec4>& reference;
    engine::render::Renderer renderer;       // one per scene: pipelines built once
    std::vector<LightingSettings> settings;  // the rows', the scaled ones at their fitted counts

    // A frame's time. On lavapipe the device is this process's threads on cores other sessions
    // share: its CPU time is the work done, where GPU timestamps also count the waits for a core.
    double timeOf(const SweepPoint& p) const { return setup.cpuClock ? p.cpuMs : p.fastestMs; }
    SweepPoint measure(const LightingSettings& l, std::string label) {
        return measureSetting(renderer, scene, camera, setup.frame, l, setup.options.frames,
                              reference, std::move(label));
    }
    double timeOf(const LightingSettings& l) { return timeOf(measure(l, "")); }
};

// A setting's time as a ratio to the yardstick's: the median of per-round ratios over
// interleaved rounds, so a machine that slows down during the fit slows both.
engine::metrics::MedianInterval ratioToYardstick(SceneBench& b, const LightingSettings& l) {
    const engine::metrics::RoundsPlan fitRounds{1, 6, 10, 0.95, 0.05};
    const LightingSettings* pair[2] = {&b.settings[b.setup.versus[0]], &l};
    auto t = engine::metrics::measureInterleaved(
        2, [&](std::size_t k) { return b.timeOf(*pair[k]); }, fitRounds);
    return t.ratioToFirst[1];
}

// Fits row i's scaled count to the yardstick's time; returns the count.
std::uint32_t fitEqualTime(SceneBench& b, std::size_t i) {
    const Row& row = b.setup.rows[i];
    const std::string& yardstick = b.setup.rows[b.setup.versus[0]].name;
    LightingSettings& l = b.settings[i];
    std::uint32_t& n = row.scale == EqualTime::ShadowRays ? l.shadowRays : l.restir.candidates;
    const std::uint32_t maxN =
        row.scale == EqualTime::ShadowRays ? 4096u : 1024u;  // the knobs' ranges
    std::fprintf(stderr, "  %s: %s: fitting its time to %s's\n", b.scene.name.c_str(),
                 row.name.c_str(), yardstick.c_str());
    // Fit ratio = base + slope x n from n = 1 and 16 (in units of the yardstick's time),
    // pick n for a ratio of 1, then up to three correction steps until within 10 %
    // (timings are not quite linear).
    n = 1;
    const double r1 = ratioToYardstick(b, l).median;
    n = 16;
    const double r16 = ratioToYardstick(b, l).median;
    const double slope = std::max((r16 - r1) / 15.0, 1e-3 * std::max(r1, 1e-3));
    const double base = r1 - slope;
    auto countFor = [&](double perUnit) {  // at least 1: the yardstick may be below the fitted base
        return std::uint32_t(std::clamp(std::round((1.0 - base) / perUnit), 1.0, double(maxN)));
    };
    std::fprintf(stderr, "    %s: time / %s's: %.3f at 1, %.3f at 16\n", row.name.c_str(),
                 yardstick.c_str(), r1, r16);
    n = countFor(slope);
    for (int step = 0; step < 3; ++step) {
        const engine::metrics::MedianInterval rn = ratioToYardstick(b, l);
        std::fprintf(stderr, "    %s: %u: %.3f (%.3f–%.3f) of %s's time\n", row.name.c_str(), n,
                     rn.median, rn.low, rn.high, yardstick.c_str());
        if (std::abs(rn.median - 1.0) < 0.1) break;
        std::uint32_t next = countFor(std::max((rn.median - base) / double(n), 1e-6));
        if (next == n) break;
        n = next;
    }
    return n;
}

// Every seed renders every row back to back, the order reversed on every other seed.
void measureSeeds(SceneBench& b, SceneResults& results, RestirProgress& progress) {
    const std::vector<Row>& rows = b.setup.rows;
    const std::uint32_t seeds = b.setup.options.seeds;
    for (std::uint32_t seed = 0; seed < seeds; ++seed) {
        for (std::size_t k = 0; k < rows.size(); ++k) {
            const std::size_t i =
                seed % 2 == 0 ? k : rows.size() - 1 - k;  // A B .., .. B A: drift cancels
            LightingSettings l = b.settings[i];
            l.seed += seed * 104729u;  // far apart: memoryless rows step the seed per frame
            std::fprintf(stderr, "  [%zu/%zu] %s: %s, seed %u/%u\n", ++progress.done,
                         progress.total, b.scene.name.c_str(), rows[i].name.c_str(), seed + 1,
                         seeds);
            b.renderer.setFrameIndex(
                0);  // a point depends on its settings and seed alone, not on what ran before
            SweepPoint p = b.measure(l, rows[i].name);
            results.emitters = p.emitters;
            RowResult& r = results.rows[i];
            r.ms.push_back(b.timeOf(p));
            r.mse.push_back(p.mse);
            r.mae.push_back(p.mae);
            r.meanRatio.push_back(p.meanRatio);
        }
    }
}

}  // namespace

engine::Result<SceneResults> measureScene(const RestirSetup& setup, engine::world::Scene& scene,
                                          RestirProgress& progress) {
    engine::world::CameraPreset camera = scene.camera();
    auto cached = cachedReference(setup.gpu, scene, camera, setup.frame, setup.options.referenceSpp,
                                  0, setup.cacheDir);
    if (!cached) return cached.error();
    SceneBench b{setup, scene, camera, *cached, engine::render::Renderer(setup.gpu), {}};
    for (const Row& row : setup.rows) b.settings.push_back(row.lighting);
    SceneResults results;
    results.rows.resize(setup.rows.size());
    for (std::size_t i = 0; i < setup.rows.size(); ++i) {
        if (setup.rows[i].scale != EqualTime::None) results.rows[i].scaledTo = fitEqualTime(b, i);
    }
    // The time ratios the verdicts use: all rows at their fitted settings, interleaved.
    std::fprintf(stderr, "  %s: timing every row in interleaved rounds\n", scene.name.c_str());
    const engine::metrics::InterleavedTimes rounds = engine::metrics::measureInterleaved(
        setup.rows.size(), [&](std::size_t i) { return b.timeOf(b.settings[i]); }, kCostRounds);
    for (std::size_t i = 0; i < setup.rows.size(); ++i) results.rows[i].roundMs = rounds.times[i];
    // Then the seeds: the per-seed time ratios compare measurements close in time.
    measureSeeds(b, results, progress);
    results.targetMs = engine::metrics::summarize(results.rows[setup.versus[0]].ms).median;
    return results;
}

}  // namespace vox
