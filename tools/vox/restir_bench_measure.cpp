// vox bench restir's measurement of one scene. Equal cost first: the cost model
// (metrics/cost_model.h) is calibrated on the rows and on each scaled row at two counts, all
// timed in interleaved rounds relative to the yardstick (the first versus row), so that a machine
// that slows down during a round slows every point of it alike; each scaled row's count is then
// the one whose counted work (render/frame_work.h) costs what the yardstick's does under the
// model: a count, not a clock reading. Then the seeds, every row of a seed back to back.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "metrics/seed_statistics.h"
#include "restir_bench.h"
#include "sweep_runner.h"

namespace vox {

namespace {

using engine::lighting::LightingSettings;
using engine::render::FrameWork;

// One scene's renderer, view and reference, shared by all its measurements.
struct SceneBench {
    const RestirSetup& setup;
    engine::world::Scene& scene;
    engine::world::CameraPreset camera;
    const std::vector<glm::vec4>& reference;
    engine::render::Renderer renderer;       // one per scene: pipelines built once
    std::vector<LightingSettings> settings;  // the rows', the scaled ones at their fitted counts
    std::uint32_t emitters = 0;

    // A frame's time. On lavapipe the device is this process's threads on cores other sessions
    // share: its CPU time is the work done, where GPU timestamps also count the waits for a core.
    double timeOf(const SweepPoint& p) const { return setup.cpuClock ? p.cpuMs : p.fastestMs; }
    SweepPoint measure(const LightingSettings& l, std::string label) {
        SweepPoint p = measureSetting(renderer, scene, camera, setup.frame, l, setup.options.frames,
                                      reference, std::move(label));
        emitters = p.emitters;
        return p;
    }
    double timeOf(const LightingSettings& l) { return timeOf(measure(l, "")); }
    FrameWork workOf(const LightingSettings& l) const {
        return engine::render::frameWork(l, {setup.frame.width, setup.frame.height}, emitters);
    }
};

std::uint32_t& scaledKnob(LightingSettings& l, EqualTime scale) {
    return scale == EqualTime::ShadowRays ? l.shadowRays : l.restir.candidates;
}

// The two counts a scaled knob is calibrated at: about the range equal cost lands in (uniform
// 4-12 rays, RIS 60-110 candidates in the runs of 2026-12-02/04).
std::pair<std::uint32_t, std::uint32_t> calibrationCounts(EqualTime scale) {
    return scale == EqualTime::ShadowRays ? std::pair{1u, 16u} : std::pair{8u, 128u};
}

// The points: the yardstick first (the cost unit), the other rows as given, the scaled rows at
// their two calibration counts; each setting once.
std::vector<CalibrationPoint> calibrationPoints(const SceneBench& b) {
    const std::vector<Row>& rows = b.setup.rows;
    std::vector<CalibrationPoint> points;
    auto add = [&](std::string label, const LightingSettings& l) {
        for (const CalibrationPoint& p : points) {
            if (p.lighting == l) return;
        }
        points.push_back({std::move(label), l, b.workOf(l), {}});
    };
    add(rows[b.setup.versus[0]].name, rows[b.setup.versus[0]].lighting);
    for (const Row& row : rows) {
        add(row.name, row.lighting);
        if (row.scale == EqualTime::None) continue;
        const auto [low, high] = calibrationCounts(row.scale);
        for (std::uint32_t n : {low, high}) {
            LightingSettings l = row.lighting;
            scaledKnob(l, row.scale) = n;
            add(fmt::format("{} {}={}", row.name, row.scale == EqualTime::ShadowRays ? "rays" : "M",
                            n),
                l);
        }
    }
    return points;
}

// The knobs' ranges.
std::uint32_t maxCount(EqualTime scale) { return scale == EqualTime::ShadowRays ? 4096u : 1024u; }

// The count of row i's scaled knob whose modelled cost is the yardstick's, unrounded (the rows
// are rendered at the ladder's rungs around it): cost is linear in it.
double equalCostCount(const SceneBench& b, const engine::metrics::CostModel& model, std::size_t i) {
    const Row& row = b.setup.rows[i];
    LightingSettings l = row.lighting;
    auto costAt = [&](std::uint32_t n) {
        scaledKnob(l, row.scale) = n;
        return model.cost(b.workOf(l).count);
    };
    const double target = model.cost(b.workOf(b.setup.rows[b.setup.versus[0]].lighting).count);
    const double slope = costAt(2) - costAt(1);
    const double base = costAt(1) - slope;
    const double maxN = maxCount(row.scale);
    if (!(slope > 0.0)) return maxN;
    return std::clamp((target - base) / slope, 1.0, maxN);
}

// Row i's settings at count n of its scaled knob.
LightingSettings atCount(const SceneBench& b, std::size_t i, std::uint32_t n) {
    LightingSettings l = b.settings[i];
    scaledKnob(l, b.setup.rows[i].scale) = n;
    return l;
}

void printModel(const SceneBench& b, const SceneResults& r) {
    using engine::render::WorkKind;
    const std::string& unit = b.setup.rows[b.setup.versus[0]].name;
    std::fprintf(
        stderr, "  %s: cost per million of each kind, in %s's frame time (%u rounds):\n",
        b.scene.name.c_str(), unit.c_str(),
        r.calibration[0].roundMs.size() > 0 ? unsigned(r.calibration[0].roundMs.size()) : 0u);
    for (std::size_t k = 0; k < engine::render::kWorkKinds; ++k) {
        const engine::metrics::MedianInterval& m = r.model.perKindInterval[k];
        std::fprintf(stderr, "    %-14s %.4f [%.4f–%.4f]\n",
                     std::string(engine::render::workKindName(WorkKind(k))).c_str(),
                     1e6 * r.model.perKind[k], 1e6 * m.low, 1e6 * m.high);
    }
    std::fprintf(stderr, "    worst point off the model by %.0f %%\n",
                 100.0 * r.model.worstResidual);
}

// Calibrates the model and sets the scaled rows' counts.
void fitEqualCost(SceneBench& b, SceneResults& results) {
    results.calibration = calibrationPoints(b);
    std::vector<CalibrationPoint>& points = results.calibration;
    std::fprintf(stderr, "  %s: calibrating the cost model on %zu settings, interleaved\n",
                 b.scene.name.c_str(), points.size());
    b.timeOf(points[0].lighting);  // the emitter count, for the counts
    for (CalibrationPoint& p : points) p.work = b.workOf(p.lighting);
    const engine::metrics::InterleavedTimes t = engine::metrics::measureInterleaved(
        points.size(), [&](std::size_t k) { return b.timeOf(points[k].lighting); }, kCostRounds);
    std::vector<std::vector<double>> counts;
    for (std::size_t k = 0; k < points.size(); ++k) {
        points[k].roundMs = t.times[k];
        counts.emplace_back(points[k].work.count.begin(), points[k].work.count.end());
    }
    results.model = engine::metrics::fitCostModel(counts, t.times, 0, kCostRounds.confidence);
    printModel(b, results);
    results.timedAs.assign(b.setup.rows.size(), -1);
    for (std::size_t i = 0; i < b.setup.rows.size(); ++i) {
        const Row& row = b.setup.rows[i];
        if (row.scale == EqualTime::None) {
            for (std::size_t k = 0; k < points.size(); ++k) {
                if (points[k].lighting == row.lighting) results.timedAs[i] = int(k);
            }
            continue;
        }
        const double fitted = equalCostCount(b, results.model, i);
        double n = fitted;
        if (b.setup.pinned) {
            auto it = b.setup.pinned->find({b.scene.name, row.name});
            if (it != b.setup.pinned->end()) n = it->second;
        }
        RowResult& r = results.rows[i];
        r.equalCount = n;
        r.fittedCount = fitted;
        r.scaledTo = std::uint32_t(std::lround(n));
        r.ladder = engine::metrics::ladderBracket(n, maxCount(row.scale));
        std::fprintf(
            stderr, "    %s: %.1f %s cost what %s does%s; rendered at %u and %u\n",
            row.name.c_str(), fitted, row.scale == EqualTime::ShadowRays ? "rays" : "candidates",
            b.setup.rows[b.setup.versus[0]].name.c_str(),
            n == fitted ? "" : fmt::format("; pinned to {:.1f} (--counts-from)", n).c_str(),
            r.ladder.low, r.ladder.high);
    }
}

// What one seed renders: each row once, a scaled row at each rung of its ladder.
struct Render {
    std::size_t row;
    int rung;  // 0: ladder.low (or the row as is), 1: ladder.high
};

std::vector<Render> rendersOf(const std::vector<Row>& rows, const SceneResults& results) {
    std::vector<Render> out;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        out.push_back({i, 0});
        if (rows[i].scale != EqualTime::None &&
            results.rows[i].ladder.high > results.rows[i].ladder.low)
            out.push_back({i, 1});
    }
    return out;
}

// A scaled row's per-seed values at its equal-cost count, from its rungs'.
void interpolateRungs(RowResult& r) {
    const RungResult& lo = r.rungs[0];
    const RungResult& hi = r.ladder.high > r.ladder.low ? r.rungs[1] : r.rungs[0];
    const double w = r.ladder.logWeight, lw = r.ladder.linearWeight;
    for (std::size_t s = 0; s < lo.mse.size(); ++s) {
        r.ms.push_back(engine::metrics::interpolateLinear(lo.ms[s], hi.ms[s], lw));
        r.mse.push_back(engine::metrics::interpolateLog(lo.mse[s], hi.mse[s], w));
        r.mae.push_back(engine::metrics::interpolateLog(lo.mae[s], hi.mae[s], w));
        r.meanRatio.push_back(engine::metrics::interpolateLog(lo.meanRatio[s], hi.meanRatio[s], w));
    }
}

// Every seed renders every row (and rung) back to back, the order reversed on every other seed.
void measureSeeds(SceneBench& b, SceneResults& results, RestirProgress& progress) {
    const std::vector<Row>& rows = b.setup.rows;
    const std::uint32_t seeds = b.setup.options.seeds;
    const std::vector<Render> renders = rendersOf(rows, results);
    for (std::uint32_t seed = 0; seed < seeds; ++seed) {
        for (std::size_t k = 0; k < renders.size(); ++k) {
            const Render& job = renders[seed % 2 == 0 ? k : renders.size() - 1 - k];
            const std::size_t i = job.row;  // A B .., .. B A: drift cancels
            RowResult& r = results.rows[i];
            LightingSettings l = b.settings[i];
            if (rows[i].scale != EqualTime::None)
                l = atCount(b, i, job.rung == 0 ? r.ladder.low : r.ladder.high);
            l.seed += seed * 104729u;  // far apart: memoryless rows step the seed per frame
            std::fprintf(
                stderr, "  [%zu/%zu] %s: %s%s, seed %u/%u\n", ++progress.done, progress.total,
                b.scene.name.c_str(), rows[i].name.c_str(),
                rows[i].scale == EqualTime::None
                    ? ""
                    : fmt::format(" at {}", job.rung == 0 ? r.ladder.low : r.ladder.high).c_str(),
                seed + 1, seeds);
            b.renderer.setFrameIndex(
                0);  // a point depends on its settings and seed alone, not on what ran before
            SweepPoint p = b.measure(l, rows[i].name);
            results.emitters = p.emitters;
            RungResult& out = rows[i].scale == EqualTime::None ? r.rungs[0] : r.rungs[job.rung];
            out.ms.push_back(b.timeOf(p));
            out.mse.push_back(p.mse);
            out.mae.push_back(p.mae);
            out.meanRatio.push_back(p.meanRatio);
        }
    }
    for (std::size_t i = 0; i < rows.size(); ++i) {
        RowResult& r = results.rows[i];
        if (rows[i].scale == EqualTime::None) {
            r.ms = r.rungs[0].ms;
            r.mse = r.rungs[0].mse;
            r.mae = r.rungs[0].mae;
            r.meanRatio = r.rungs[0].meanRatio;
        } else {
            interpolateRungs(r);
        }
    }
}

}  // namespace

engine::metrics::MedianInterval costRatio(const SceneResults& s, std::size_t i, std::size_t v) {
    const std::span<const double> a = s.rows[i].work.count, b = s.rows[v].work.count;
    const int ta = s.timedAs[i], tb = s.timedAs[v];
    if (ta < 0 || tb < 0) return s.model.ratio(a, b, kCostRounds.confidence, s.costDrift);
    // Both rows were timed as they are, in the same interleaved rounds: their measured ratio, not
    // the model's, which is fitted to all the points at once and misses single ones by a few per
    // cent each (unbiased ÷ biased ReSTIR on the mountain: 1.17 modelled, 1.06-1.10 measured). The
    // model is for the counts nobody timed. The drift widens it alike, and so does the model's
    // worst residual: how far single points stray from the kinds' costs, which moves a measured
    // ratio between runs as much as the kinds' drift does.
    engine::metrics::MedianInterval m = engine::metrics::medianInterval(
        engine::metrics::perSeedRatios(s.calibration[std::size_t(ta)].roundMs,
                                       s.calibration[std::size_t(tb)].roundMs),
        kCostRounds.confidence);
    return ta == tb ? m : s.model.widenByDrift(m, a, b, s.costDrift, s.model.worstResidual);
}

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
    fitEqualCost(b, results);
    results.costDrift = setup.options.costDrift;
    for (std::size_t i = 0; i < setup.rows.size(); ++i) {
        RowResult& r = results.rows[i];
        if (setup.rows[i].scale == EqualTime::None) {
            r.work = b.workOf(b.settings[i]);
            continue;
        }
        // Work is linear in the scaled count: the equal-cost count's is between the rungs'.
        const FrameWork lo = b.workOf(atCount(b, i, r.ladder.low)),
                        hi = b.workOf(atCount(b, i, r.ladder.high));
        for (std::size_t k = 0; k < lo.count.size(); ++k)
            r.work.count[k] =
                engine::metrics::interpolateLinear(lo.count[k], hi.count[k], r.ladder.linearWeight);
    }
    measureSeeds(b, results, progress);
    results.targetMs = engine::metrics::summarize(results.rows[setup.versus[0]].ms).median;
    return results;
}

}  // namespace vox
