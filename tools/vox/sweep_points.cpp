#include "sweep_points.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <sstream>

#include "commands.h"
#include "gpu/context.h"
#include "lighting/emitter_list.h"
#include "lighting/lighting_knobs.h"
#include "metrics/cost_model.h"
#include "metrics/pareto_front.h"
#include "metrics/seed_statistics.h"
#include "render/frame_work.h"
#include "render/renderer.h"
#include "sweep_runner.h"

namespace vox {

using engine::lighting::LightingSettings;
using engine::lighting::Method;
using engine::metrics::MedianInterval;

std::vector<std::string> splitList(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    std::string item;
    while (std::getline(in, item, ',')) {
        if (!item.empty()) out.push_back(item);
    }
    return out;
}

namespace {

// The front's verdicts as vox bench restir's: 90 % (5 seeds' min-max covers 93.75 %), and a
// difference below 5 % in cost or error is none.
constexpr double kFrontConfidence = 0.9;
constexpr double kFrontNoise = 0.05;
// Cost intervals at the calibration's 97 %, as vox bench restir's: with the error verdict's, a
// "surely dominated" still holds at about 90 %.
constexpr double kCostConfidence = engine::metrics::kCostCalibrationRounds.confidence;

engine::Result<std::vector<std::uint32_t>> numbers(const std::string& s, const char* option) {
    std::vector<std::uint32_t> out;
    for (const std::string& item : splitList(s)) {
        char* end = nullptr;
        unsigned long v = std::strtoul(item.c_str(), &end, 10);
        if (!end || *end || v < 1 || v > 4096)
            return engine::makeError("{}: '{}' is not a number in 1..4096", option, item);
        out.push_back(std::uint32_t(v));
    }
    if (out.empty()) return engine::makeError("{}: empty list", option);
    return out;
}

// All settings of the sweep, labelled.
engine::Result<std::vector<std::pair<std::string, LightingSettings>>> settingsOf(
    const SweepOptions& o) {
    auto ms = numbers(o.candidates, "--candidates");
    if (!ms) return ms.error();
    auto rays = numbers(o.rays, "--rays");
    if (!rays) return rays.error();
    std::vector<std::pair<std::string, LightingSettings>> out;
    for (const std::string& method : splitList(o.methods)) {
        for (const std::string& mode : splitList(o.modes)) {
            if (mode != "point" && mode != "area")
                return engine::makeError("--modes: '{}' is not point or area", mode);
            for (const std::string& bricks : splitList(o.brickLights)) {
                if (bricks != "on" && bricks != "off")
                    return engine::makeError("--brick-lights: '{}' is not on or off", bricks);
                const std::vector<engine::lighting::KnobValue> values{
                    {engine::lighting::knobForOption("method"), method, "--methods"},
                    {engine::lighting::knobForOption("mode"), mode, "--modes"},
                    {engine::lighting::knobForOption("brick-lights"), bricks, "--brick-lights"}};
                auto base = engine::lighting::mergeLighting(LightingSettings{}, values);
                if (!base) return base.error();
                std::string tag =
                    fmt::format("{} {}{}", method, mode, bricks == "off" ? " voxels" : "");
                if (base->method == Method::Uniform) {
                    for (std::uint32_t n : *rays) {
                        LightingSettings l = *base;
                        l.shadowRays = n;
                        out.push_back({fmt::format("{} {} rays", tag, n), l});
                    }
                } else if (base->method == Method::Restir || base->method == Method::Ris) {
                    for (std::uint32_t m : *ms) {
                        LightingSettings l = *base;
                        l.restir.candidates = m;
                        out.push_back({fmt::format("{} M={}", tag, m), l});
                    }
                } else {
                    out.push_back({tag, *base});
                }
            }
        }
    }
    for (const auto& [tag, l] : out) {  // --candidates and --rays may leave the knobs' ranges
        if (engine::Status valid = engine::lighting::validate(l); !valid)
            return engine::makeError("{}: {}", tag, valid.error().message);
    }
    return out;
}

// The indirect-light series, labelled: ReSTIR (biased, area, M = 32: the defaults) for the
// direct light and, for the indirect light, nothing, the irradiance cache with K directions per
// face, or the path tracer with the same bounces as the reference it is measured against (one
// sample per pixel, restarted every frame). The cache reads its own irradiance at each ray's hit
// for the same number of bounces, so all three aim at the same converged image.
engine::Result<std::vector<std::pair<std::string, LightingSettings>>> indirectSettingsOf(
    const SweepOptions& o) {
    using engine::lighting::Indirect;
    std::vector<std::pair<std::string, LightingSettings>> out;
    for (const std::string& item : splitList(o.indirect)) {
        LightingSettings l;
        if (item == "none") {
            out.push_back({"indirect none (restir)", l});
        } else if (item == "reference") {
            l.method = Method::Reference;
            l.referenceFilter =
                engine::lighting::ReferenceFilter::PixelCentre;  // as the reference it is measured
                                                                 // against
            l.indirect = Indirect::Reference;
            l.bounces = o.indirectBounces;
            l.samplesPerFrame = 1;
            out.push_back(
                {fmt::format("indirect reference {} bounces 1 spp", o.indirectBounces), l});
        } else if (item.rfind("cache-", 0) == 0) {
            auto k = numbers(item.substr(6), "--indirect cache-K");
            if (!k) return k.error();
            l.indirect = Indirect::Cache;
            l.cache.directions = k->front();
            l.cache.raysPerUpdate = std::min(l.cache.raysPerUpdate, l.cache.directions);
            l.cache.bounces = o.indirectBounces;
            if (engine::Status valid = engine::lighting::validate(l); !valid)
                return engine::makeError("--indirect {}: {}", item, valid.error().message);
            out.push_back({fmt::format("indirect cache K={}", k->front()), l});
        } else if (item == "vct" || item == "vct-leaky") {
            // Voxel cone tracing (one bounce; the extra bounce with 2+ reference bounces), with its
            // leak mitigation on, or off (vct-leaky).
            l.indirect = Indirect::Vct;
            l.vct.leakMitigation = item == "vct";
            l.vct.extraBounce = o.indirectBounces > 1;
            out.push_back({item == "vct" ? "indirect vct" : "indirect vct no leak mitigation", l});
        } else {
            return engine::makeError(
                "--indirect: '{}' is not none, cache-K, vct, vct-leaky or reference", item);
        }
    }
    return out;
}

const char* indirectColumn(const LightingSettings& l) {
    return engine::lighting::indirectName(
        l.method == Method::Reference ? engine::lighting::Indirect::Reference : l.indirect);
}

// One point of a world measured over the rounds.
struct RoundsOfPoint {
    std::uint32_t index = 0;
    const std::string* label = nullptr;
    LightingSettings lighting;
    bool direct = true;
    std::vector<SweepPoint> rounds;
    std::vector<double> ms;          // the chosen clock's time per round
    MedianInterval cost;             // ms: the model's for a direct point, the clock's otherwise
    std::string frontMae, frontMse;  // metrics/pareto_front.h's status; empty for indirect points
    engine::render::FrameWork work;
};

double medianOf(const std::vector<SweepPoint>& v, double SweepPoint::*field) {
    std::vector<double> x;
    for (const SweepPoint& p : v) x.push_back(p.*field);
    return engine::metrics::summarize(x).median;
}

double passMedian(const std::vector<SweepPoint>& v, const char* pass) {
    std::vector<double> x;
    for (const SweepPoint& p : v) x.push_back(p.passMs.count(pass) ? p.passMs.at(pass) : 0.0);
    return engine::metrics::summarize(x).median;
}

// A point's line: the columns the sweep has always written (medians over the rounds), then the
// rounds, the cost with its interval and the errors' min-max over the seeds.
std::string pointLine(const RoundsOfPoint& r, std::uint32_t referenceBounces) {
    const SweepPoint& first = r.rounds.front();
    std::vector<double> mae, mse;
    for (const SweepPoint& p : r.rounds) {
        mae.push_back(p.mae);
        mse.push_back(p.mse);
    }
    const auto a = engine::metrics::summarize(mae), e = engine::metrics::summarize(mse);
    const double total = medianOf(r.rounds, &SweepPoint::totalMs);
    const double primary = passMedian(r.rounds, "primary_rays");
    const double tonemap = passMedian(r.rounds, "tonemap");
    return fmt::format(
        "{},{},\"{}\",{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", first.scene,
        first.method, first.label, first.emitters, total, primary, total - primary - tonemap,
        a.median, e.median, medianOf(r.rounds, &SweepPoint::rmae), indirectColumn(r.lighting),
        referenceBounces, medianOf(r.rounds, &SweepPoint::meanRatio), r.rounds.size(),
        r.cost.median, r.cost.low, r.cost.high, a.min, a.max, e.min, e.max, r.frontMae, r.frontMse);
}

// The cost of every point: the direct-light ones under the model fitted to their calibration
// rounds (`calibration[i]`: the i-th direct point's times), in ms of the first one's median time
// there; the indirect series (whose cache, cone and path work the counts do not cover) keep their
// time's median and interval over the seeds' rounds.
engine::metrics::CostModel costPoints(std::vector<RoundsOfPoint>& points,
                                      const std::vector<std::vector<double>>& calibration,
                                      double confidence, double drift) {
    std::vector<std::vector<double>> counts;
    std::vector<RoundsOfPoint*> direct;
    for (RoundsOfPoint& r : points) {
        if (!r.direct) {
            r.cost = engine::metrics::medianInterval(r.ms, confidence);
            continue;
        }
        direct.push_back(&r);
        counts.emplace_back(r.work.count.begin(), r.work.count.end());
    }
    if (direct.empty()) return {};
    engine::metrics::CostModel model =
        engine::metrics::fitCostModel(counts, calibration, 0, confidence);
    const double unitMs = engine::metrics::summarize(calibration[0]).median;
    for (std::size_t i = 0; i < direct.size(); ++i) {
        MedianInterval c = model.ratio(counts[i], counts[0], confidence, drift);
        direct[i]->cost = {c.low * unitMs, c.median * unitMs, c.high * unitMs, c.covered, c.count};
    }
    std::fprintf(stderr, "\n  cost model (%zu points, %zu rounds): worst point %.0f %% off it\n",
                 direct.size(), calibration[0].size(), 100.0 * model.worstResidual);
    return model;
}

// The direct-light Pareto fronts by MAE and by MSE with their verdicts (metrics/pareto_front.h):
// a point leaves a front only when another is surely no dearer (the pair's cost ratio over the
// rounds' fits, widened by the drift) and surely more accurate (per-seed error ratios, the seeds
// paired); members that another point may still dominate are "not resolved at this budget".
// Each point's status goes to its CSV line (front_mae, front_mse).
void classifyFronts(const std::string& scene, std::vector<RoundsOfPoint>& points,
                    const engine::metrics::CostModel& model, double drift) {
    std::vector<RoundsOfPoint*> direct;
    for (RoundsOfPoint& r : points) {
        if (r.direct) direct.push_back(&r);
    }
    if (direct.empty()) return;
    engine::metrics::FrontInput in;
    in.confidence = kFrontConfidence;
    in.noise = kFrontNoise;
    in.costRatio = [&](std::size_t q, std::size_t p) {
        return model.ratio(direct[q]->work.count, direct[p]->work.count, kCostConfidence, drift);
    };
    for (const char* key : {"MAE", "MSE"}) {
        const bool mae = key[1] == 'A';
        in.errors.clear();
        for (const RoundsOfPoint* r : direct) {
            std::vector<double> e;
            for (const SweepPoint& p : r->rounds) e.push_back(mae ? p.mae : p.mse);
            in.errors.push_back(std::move(e));
        }
        const std::vector<engine::metrics::FrontStatus> status = engine::metrics::paretoFront(in);
        std::vector<std::size_t> front;
        for (std::size_t i = 0; i < direct.size(); ++i) {
            (mae ? direct[i]->frontMae : direct[i]->frontMse) =
                engine::metrics::frontStatusName(status[i]);
            if (status[i] != engine::metrics::FrontStatus::Dominated) front.push_back(i);
        }
        std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) {
            return direct[a]->cost.median < direct[b]->cost.median;
        });
        std::printf(
            "%s: %s Pareto front (every point no other surely dominates; cost ms [interval], %s "
            "median [seeds' min–max]):\n",
            scene.c_str(), key, key);
        for (std::size_t i : front) {
            const RoundsOfPoint& r = *direct[i];
            const engine::metrics::SeedSummary e = engine::metrics::summarize(in.errors[i]);
            std::printf("  %-34s %8.2f [%.2f–%.2f]  %.3e [%.3e–%.3e]  %s\n", r.label->c_str(),
                        r.cost.median, r.cost.low, r.cost.high, e.median, e.min, e.max,
                        status[i] == engine::metrics::FrontStatus::Member
                            ? "member: resolved"
                            : "member: not resolved at this budget");
        }
    }
}

}  // namespace

engine::Result<SweepPlan> planSweep(const SweepOptions& o) {
    SweepPlan plan;
    auto size = parseSize(o.size, "--size");
    if (!size) return size.error();
    plan.size = *size;
    auto direct = settingsOf(o);
    if (!direct) return direct.error();
    plan.direct = std::move(*direct);
    auto indirect = indirectSettingsOf(o);
    if (!indirect) return indirect.error();
    plan.indirect = std::move(*indirect);
    return plan;
}

engine::Status measureSweepPoints(
    engine::gpu::Context& gpu, const SweepOptions& o, const SweepPlan& plan, std::uint32_t first,
    std::uint32_t last, const std::function<bool(std::uint32_t)>& wanted,
    const std::function<engine::Status(std::uint32_t, const std::string&)>& onPoint) {
    engine::render::FrameSettings fs;
    fs.width = plan.size.x;
    fs.height = plan.size.y;
    const std::filesystem::path cache = std::filesystem::path(o.output) / "cache";
    const std::uint32_t perWorld = plan.pointsPerWorld();
    const std::size_t total = std::size_t(perWorld) * o.worlds.size();
    for (std::uint32_t w = 0; w < o.worlds.size() && perWorld > 0; ++w) {
        const std::uint32_t worldFirst = w * perWorld, worldLast = worldFirst + perWorld - 1;
        bool any = false;
        for (std::uint32_t k = std::max(first, worldFirst); k <= std::min(last, worldLast) && !any;
             ++k)
            any = !wanted || wanted(k);
        if (!any) continue;
        auto scene = loadWorld(o.worlds[w]);
        if (!scene) return scene.error();
        engine::world::CameraPreset camera = scene->camera();
        // Brick lights on and off are the same lights in a scene without uniform emissive bricks.
        engine::lighting::EmitterList lights;
        lights.rebuild(*scene);
        bool hasBrickLights = false;
        for (const auto& e : lights.slots())
            hasBrickLights |= e.minCorner.w == 8 && (e.info.w & 1u);
        std::optional<std::vector<glm::vec4>> reference,
            withBounces;  // rendered or read when needed
        std::vector<RoundsOfPoint> points;
        std::vector<std::uint32_t> skipped;
        for (std::uint32_t k = std::max(first, worldFirst); k <= std::min(last, worldLast); ++k) {
            if (wanted && !wanted(k)) continue;
            const std::uint32_t j = k - worldFirst;
            const bool direct = j < plan.direct.size();
            const auto& [label, l] =
                direct ? plan.direct[j] : plan.indirect[j - plan.direct.size()];
            if (direct && !l.brickLights && !hasBrickLights) {
                skipped.push_back(k);
                continue;
            }
            std::optional<std::vector<glm::vec4>>& ref = direct ? reference : withBounces;
            if (!ref) {
                auto r = direct ? cachedReference(gpu, *scene, camera, fs, o.referenceSpp, 0, cache)
                                : cachedReference(gpu, *scene, camera, fs, o.indirectReferenceSpp,
                                                  o.indirectBounces, cache);
                if (!r) return r.error();
                ref = std::move(*r);
            }
            RoundsOfPoint r;
            r.index = k;
            r.label = &label;
            r.lighting = l;
            r.direct = direct;
            points.push_back(std::move(r));
        }
        // One renderer per world (its pipelines built once), its frame counter restarted for
        // every point; rounds interleaved, the order reversed every other round.
        engine::render::Renderer renderer(gpu);
        const bool cpuClock = gpu.info().type == "CPU";  // as vox bench restir's --clock auto
        for (std::uint32_t round = 0; round < o.seeds; ++round) {
            for (std::size_t n = 0; n < points.size(); ++n) {
                RoundsOfPoint& r = points[round % 2 == 0 ? n : points.size() - 1 - n];
                LightingSettings l = r.lighting;
                l.seed += round * 104729u;
                std::fprintf(stderr, "\r  [%u/%zu] %s: round %u/%u: %-40s", r.index + 1, total,
                             scene->name.c_str(), round + 1, o.seeds, r.label->c_str());
                renderer.setFrameIndex(0);
                SweepPoint p = measureSetting(renderer, *scene, camera, fs, l, o.frames,
                                              r.direct ? *reference : *withBounces, *r.label);
                r.ms.push_back(cpuClock ? p.cpuMs : p.fastestMs);
                r.work = engine::render::frameWork(l, plan.size, p.emitters);
                r.rounds.push_back(std::move(p));
            }
        }
        // The cost model gets rounds of its own, as vox bench restir's does: the seeds' rounds
        // are few, and a cost interval from 5 of them (their min-max) moved a front member's
        // verdict between runs of one build (docs/ACCURACY.md, "Four sweeps of one scene").
        std::vector<std::size_t> directPoints;
        for (std::size_t n = 0; n < points.size(); ++n) {
            if (points[n].direct) directPoints.push_back(n);
        }
        std::uint32_t calibrated = 0;
        const engine::metrics::InterleavedTimes calibration = engine::metrics::measureInterleaved(
            directPoints.size(),
            [&](std::size_t k) {
                const RoundsOfPoint& r = points[directPoints[k]];
                const auto& rounds = engine::metrics::kCostCalibrationRounds;
                const std::size_t round = calibrated++ / directPoints.size();
                const std::string which =
                    round < rounds.warmupRounds
                        ? std::string("warm-up")
                        : fmt::format("round {} ({} to {})", round + 1 - rounds.warmupRounds,
                                      rounds.minRounds, rounds.maxRounds);
                std::fprintf(stderr, "\r  %s: cost calibration %s: %-40s", scene->name.c_str(),
                             which.c_str(), r.label->c_str());
                renderer.setFrameIndex(0);
                SweepPoint p = measureSetting(renderer, *scene, camera, fs, r.lighting, o.frames,
                                              *reference, *r.label);
                return cpuClock ? p.cpuMs : p.fastestMs;
            },
            engine::metrics::kCostCalibrationRounds);
        const engine::metrics::CostModel model =
            costPoints(points, calibration.times, kCostConfidence, o.costDrift);
        classifyFronts(scene->name, points, model, o.costDrift);
        std::fflush(stdout);  // before the chart script's lines
        std::size_t next = 0, nextSkipped = 0;
        for (std::uint32_t k = std::max(first, worldFirst); k <= std::min(last, worldLast); ++k) {
            if (nextSkipped < skipped.size() && skipped[nextSkipped] == k) {
                ++nextSkipped;
                if (engine::Status s = onPoint(k, ""); !s) return s;
            } else if (next < points.size() && points[next].index == k) {
                const RoundsOfPoint& r = points[next++];
                if (engine::Status s = onPoint(k, pointLine(r, r.direct ? 0 : o.indirectBounces));
                    !s)
                    return s;
            }
        }
    }
    std::fprintf(stderr, "\n");
    return {};
}

void drawSweepCharts(const std::string& output) {
    const std::filesystem::path out(output);
    // The chart needs Debian's matplotlib; without it the CSV is still complete.
    std::string plot = fmt::format("/usr/bin/python3 {}/tools/plot_sweep.py {} {}", VOX_SOURCE_DIR,
                                   (out / "sweep.csv").string(), out.string());
    if (std::system(plot.c_str()) != 0)
        std::fprintf(stderr, "note: chart not drawn (needs python3-matplotlib)\n");
}

}  // namespace vox
