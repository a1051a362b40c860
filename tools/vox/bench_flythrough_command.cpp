// vox bench flythrough: the irradiance cache against path-traced indirect light at equal time, on
// a moving camera — where the path tracer's accumulation restarts every frame and the cache's
// world-space history should win (issue 14; docs/ACCURACY.md). Each scene plays its flythrough
// (worlds/paths/<scene>_flythrough.toml) once per method, the methods' frames interleaved so they
// share the machine's drift: ReSTIR direct light plus
//   none   no indirect term (its error is the whole indirect light),
//   cache  the voxel-face irradiance cache,
//   path   N bounce paths per pixel per frame (--path-spp, one point each).
// Per frame: wall milliseconds of the whole Renderer::render (host work, uploads, submission and
// wait), and at every K-th frame after the warm-up the indirect term's MAE against the reference
// path tracer's converged indirect light at the same frame (with B bounces minus without, at the
// pixel centres the G-buffer shades). Results: a CSV per frame, a summary CSV, a markdown table;
// tools/plot_flythrough.py draws error against time per scene.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <memory>
#include <optional>
#include <string>

#include "bench_median.h"
#include "bench_setup.h"
#include "commands.h"
#include "core/atomic_file.h"
#include "gpu/context.h"
#include "lighting_options.h"
#include "metrics/image_metrics.h"
#include "number_options.h"
#include "progress_line.h"
#include "render/flythrough_player.h"
#include "scene/path_file.h"
#include "thesis_scenes.h"

namespace vox {

namespace {

namespace fs = std::filesystem;
using engine::lighting::Indirect;
using engine::lighting::LightingSettings;
using engine::lighting::Method;
using engine::render::FlythroughPlayer;
using engine::render::FrameSettings;
using engine::render::Renderer;
using engine::world::Flythrough;
using engine::world::Scene;
using Clock = std::chrono::steady_clock;

struct FlythroughOptions {
    std::vector<std::string> worlds = kThesisScenes;
    std::string size = "128x72";
    std::optional<std::uint32_t> frames;  // absent: the whole path
    std::uint32_t warmup = 30;
    std::uint32_t referenceEvery = 10;
    std::uint32_t referenceSpp = 256;
    std::vector<std::uint32_t> pathSpp{1, 4, 16, 64};
    // Cache runs: one per (fallback radius, ray budget) pair; an empty list: the cache's default.
    std::vector<std::uint32_t> cacheFallback;
    std::vector<std::uint32_t> cacheBudget;
    std::vector<std::string> cacheVariants;  // "NAME:--knob value ...": one more cache run each
    std::uint32_t bounces = 1;
    std::string output = "out/flythrough";
};

// One method's run through a scene: its own scene copy (the timeline edits it), renderer and
// player.
struct Run {
    std::string method;     // none | cache | path
    std::uint32_t spp = 0;  // path: paths per pixel per frame
    std::optional<std::uint32_t>
        fallback;  // cache: the gather's fallback radius, when the run sets it
    std::optional<std::uint32_t> budget;  // cache: the ray budget, when the run sets it
    std::string variant;                  // cache: a --cache-variant's name
    LightingSettings lighting;
    Scene scene;
    Flythrough fly;
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<FlythroughPlayer> player;
    std::vector<double> wallMs;  // measured frames
    std::vector<double> mae;     // reference frames
    std::string label() const {
        if (method == "path") return fmt::format("path {} spp", spp);
        std::string text = variant;
        if (fallback) text += fmt::format("{}fallback {}", text.empty() ? "" : ", ", *fallback);
        if (budget) text += fmt::format("{}budget {}", text.empty() ? "" : ", ", *budget);
        return text.empty() ? method : fmt::format("{} ({})", method, text);
    }
};

double mean(const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / double(v.size());
}

// The mean magnitude of the reference's indirect light (its noise can make a pixel negative): the
// MAE of no indirect term at all, so errors divided by it read as a fraction of the light.
double meanMagnitude(const std::vector<glm::vec4>& img) {
    double s = 0.0;
    for (const glm::vec4& p : img) s += (std::abs(p.x) + std::abs(p.y) + std::abs(p.z)) / 3.0;
    return img.empty() ? 0.0 : s / double(img.size());
}

// worlds/paths/<world>_flythrough.toml, from the working directory or the source tree.
engine::Result<fs::path> flythroughFile(const std::string& world) {
    const std::string file = fs::path(world).stem().string() + "_flythrough.toml";
    std::error_code ec;
    for (fs::path dir : {fs::path("worlds/paths"), fs::path(VOX_SOURCE_DIR) / "worlds/paths"}) {
        if (fs::is_regular_file(dir / file, ec)) return dir / file;
    }
    return engine::makeError("{}: no flythrough for this world (worlds/paths/{})", world, file);
}

// The reference path tracer's indirect light at a frame: (bounces) minus (direct only), both
// through the pixel centres with `spp` samples. Plays its own copies of the scene so the world
// is the frame's.
class ReferenceIndirect {
public:
    ReferenceIndirect(engine::gpu::Context& ctx, const Scene& scene, const Flythrough& fly,
                      double fps, std::uint32_t bounces, std::uint32_t spp)
        : mSpp(spp) {
        for (int i = 0; i < 2; ++i) {
            Side& s = mSides[i];
            s.scene = scene;
            s.fly = fly;
            (void)s.fly.timeline.bind(
                s.scene);  // the methods' copies bound the same path without error
            s.renderer = std::make_unique<Renderer>(ctx);
            s.player = std::make_unique<FlythroughPlayer>(*s.renderer, s.scene, s.fly, fps);
            s.lighting.method = Method::Reference;
            s.lighting.referenceFilter = engine::lighting::ReferenceFilter::PixelCentre;
            s.lighting.bounces = i == 0 ? bounces : 0;
            s.lighting.samplesPerFrame = std::min(spp, 32u);
        }
    }
    std::vector<glm::vec4> at(std::uint32_t frame, const FrameSettings& settings) {
        std::vector<glm::vec4> images[2];
        for (int i = 0; i < 2; ++i) {
            Side& s = mSides[i];
            auto f = s.player->render(frame, settings, s.lighting);
            FrameSettings still = settings;
            still.timeSeconds = f.time;
            for (std::uint32_t done = s.lighting.samplesPerFrame; done < mSpp;
                 done += s.lighting.samplesPerFrame) {
                s.renderer->render(s.scene, f.camera, still, s.lighting);
            }
            images[i] = s.renderer->readback().radiance;
        }
        for (std::size_t p = 0; p < images[0].size(); ++p) images[0][p] -= images[1][p];
        return images[0];
    }

private:
    struct Side {
        Scene scene;
        Flythrough fly;
        std::unique_ptr<Renderer> renderer;
        std::unique_ptr<FlythroughPlayer> player;
        LightingSettings lighting;
    };
    Side mSides[2];
    std::uint32_t mSpp;
};

// A scene's flythrough and how many of its frames are played.
struct ScenePath {
    Flythrough fly;
    double fps = 0.0;
    std::uint32_t count = 0;
};

engine::Result<ScenePath> scenePath(const std::string& world, const FlythroughOptions& o) {
    auto pathFile = flythroughFile(world);
    if (!pathFile) return pathFile.error();
    auto fly = engine::scene::loadFlythroughFile(*pathFile);
    if (!fly) return fly.error();
    const double fps = fly->fps;
    if (engine::Status s = fly->checkFrames(fps); !s) return s.error();
    const std::uint32_t count =
        o.frames ? std::min(*o.frames, fly->frameCount(fps)) : fly->frameCount(fps);
    if (count <= o.warmup) {
        return engine::makeError("{}: {} frames leave none after the {} warm-up frames",
                                 pathFile->string(), count, o.warmup);
    }
    return ScenePath{std::move(*fly), fps, count};
}

// The list's values, or one unset value for an empty list (the cache's default).
std::vector<std::optional<std::uint32_t>> orDefault(const std::vector<std::uint32_t>& values) {
    if (values.empty()) return {std::nullopt};
    return std::vector<std::optional<std::uint32_t>>(values.begin(), values.end());
}

// The runs of a scene, in the order they are played: no indirect term, the cache per (ray budget,
// fallback radius) and per --cache-variant, then the path tracer per --path-spp.
engine::Result<std::vector<Run>> makeRuns(const FlythroughOptions& o, const Scene& scene,
                                          const Flythrough& fly) {
    std::vector<Run> runs;
    auto addRun = [&](std::string method, std::uint32_t spp, Indirect indirect) -> engine::Status {
        Run r;
        r.method = std::move(method);
        r.spp = spp;
        r.lighting.indirect = indirect;
        r.lighting.cache.bounces = o.bounces;
        r.lighting.path.bounces = o.bounces;
        if (indirect == Indirect::Path) r.lighting.path.samples = spp;
        r.scene = scene;
        r.fly = fly;
        if (engine::Status bound = r.fly.timeline.bind(r.scene); !bound) return bound;
        runs.push_back(std::move(r));
        return {};
    };
    if (engine::Status s = addRun("none", 0, Indirect::None); !s) return s.error();
    for (const auto& budget : orDefault(o.cacheBudget)) {
        for (const auto& fallback : orDefault(o.cacheFallback)) {
            if (engine::Status s = addRun("cache", 0, Indirect::Cache); !s) return s.error();
            Run& r = runs.back();
            r.fallback = fallback;
            r.budget = budget;
            if (fallback) r.lighting.cache.fallbackRadius = *fallback;
            if (budget) r.lighting.cache.rayBudget = *budget;
        }
    }
    for (const std::string& v : o.cacheVariants) {
        if (engine::Status s = addRun("cache", 0, Indirect::Cache); !s) return s.error();
        const std::size_t colon = v.find(':');
        if (colon == std::string::npos || colon == 0)
            return engine::makeError("--cache-variant '{}': expected NAME:--knob value ...", v);
        auto values = knobValuesOf(v.substr(colon + 1),
                                   fmt::format("--cache-variant {}", v.substr(0, colon)));
        if (!values) return values.error();
        Run& r = runs.back();
        auto merged = engine::lighting::mergeLighting(r.lighting, *values);
        if (!merged) return merged.error();
        r.lighting = *merged;
        r.variant = v.substr(0, colon);
    }
    for (std::uint32_t spp : o.pathSpp) {
        if (engine::Status s = addRun("path", spp, Indirect::Path); !s) return s.error();
    }
    return runs;
}

// The outputs every scene adds to.
struct FlythroughOutputs {
    std::ostream& frames;
    std::ostream& summary;
    std::string table;
};

// Plays every run through frame i (measured after the warm-up) and, on a reference frame,
// compares its indirect term with the reference's.
engine::Status playFrame(std::vector<Run>& runs, std::uint32_t i, bool measured,
                         const std::vector<glm::vec4>* ref, double refMean,
                         const FrameSettings& frame, const std::string& scene,
                         std::ostream& frames) {
    for (Run& r : runs) {
        const auto start = Clock::now();
        r.player->render(i, frame, r.lighting);
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (!measured) continue;
        r.wallMs.push_back(ms);
        std::string maeText;
        if (ref) {
            const std::vector<glm::vec4> indirect = r.renderer->readback().indirect;
            auto e = engine::metrics::compareImages({indirect, frame.width, frame.height},
                                                    {*ref, frame.width, frame.height});
            if (!e) return e.error();
            r.mae.push_back(e->mae);
            maeText = fmt::format("{:.6g}", e->mae);
        }
        frames << fmt::format("{},{},{},{},{:.3f},{},{},\"{}\"\n", scene, r.method, r.spp, i, ms,
                              maeText, ref ? fmt::format("{:.6g}", refMean) : "", r.label());
    }
    return {};
}

void summarise(const std::vector<Run>& runs, double refMean, const std::string& scene,
               const FrameSettings& frame, const FlythroughOptions& o, FlythroughOutputs& out) {
    for (const Run& r : runs) {
        const double wall = mean(r.wallMs), mae = mean(r.mae);
        out.summary << fmt::format(
            "{},{},{},{:.3f},{:.3f},{:.6g},{:.4f},{:.6g},{},{},{}x{},{},{},{},{},\"{}\"\n", scene,
            r.method, r.spp, wall, median(r.wallMs), mae, mae / std::max(refMean, 1e-12), refMean,
            r.wallMs.size(), r.mae.size(), frame.width, frame.height, o.referenceSpp, o.bounces,
            r.fallback ? std::to_string(*r.fallback) : std::string(),
            r.budget ? std::to_string(*r.budget) : std::string(), r.variant);
        const std::string row =
            fmt::format("| {} | {} | {:.1f} | {:.4g} | {:.1f} % |\n", scene, r.label(), wall, mae,
                        100.0 * mae / std::max(refMean, 1e-12));
        out.table += row;
        std::printf("%s", row.c_str());
    }
    std::fflush(stdout);
}

// One scene: every run plays the flythrough, the runs' frames interleaved.
engine::Status benchScene(engine::gpu::Context& ctx, const std::string& world,
                          const FlythroughOptions& o, const FrameSettings& frame,
                          FlythroughOutputs& out) {
    auto loaded = loadWorld(world);
    if (!loaded) return loaded.error();
    auto path = scenePath(world, o);
    if (!path) return path.error();
    auto runs = makeRuns(o, *loaded, path->fly);
    if (!runs) return runs.error();
    for (Run& r : *runs) {  // after the vector stops moving: the players hold references
        r.renderer = std::make_unique<Renderer>(ctx);
        r.player = std::make_unique<FlythroughPlayer>(*r.renderer, r.scene, r.fly, path->fps);
    }
    ReferenceIndirect reference(ctx, *loaded, path->fly, path->fps, o.bounces, o.referenceSpp);
    std::vector<double> referenceMeans;
    const std::uint32_t count = path->count;
    ProgressLine progress(
        fmt::format("{} ({} frames x {} methods)", loaded->name, count, runs->size()), count);
    for (std::uint32_t i = 0; i < count; ++i) {
        const bool measured = i >= o.warmup;
        const bool referenceFrame = measured && (i - o.warmup) % o.referenceEvery == 0;
        std::vector<glm::vec4> ref;
        double refMean = 0.0;
        if (referenceFrame) {
            ref = reference.at(i, frame);
            refMean = meanMagnitude(ref);
            referenceMeans.push_back(refMean);
        }
        if (engine::Status s = playFrame(*runs, i, measured, referenceFrame ? &ref : nullptr,
                                         refMean, frame, loaded->name, out.frames);
            !s)
            return s;
        progress.update(i + 1, measured ? (referenceFrame ? "reference frame" : "") : "warm-up");
    }
    progress.finish();
    summarise(*runs, mean(referenceMeans), loaded->name, frame, o, out);
    return {};
}

int runFlythroughBench(const FlythroughOptions& o) {
    auto size = frameOfSize(o.size);
    if (!size) return fail(size.error());
    if (o.pathSpp.empty()) return fail(engine::makeError("--path-spp: give at least one count"));
    for (std::uint32_t s : o.pathSpp)
        if (s < 1 || s > 256) return fail(engine::makeError("--path-spp: {} is not in 1..256", s));
    auto ctx = createBenchGpu();
    if (!ctx) return fail(ctx.error());
    const fs::path out(o.output);
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec)
        return fail(engine::makeError("-o {}: cannot create folder: {}", o.output, ec.message()));
    const FrameSettings frame = *size;
    const auto& dev = (*ctx)->info();
    std::printf(
        "device %s (%s); %ux%u; reference %u spp, %u bounce(s); a reference every %u frames after "
        "%u\n",
        dev.name.c_str(), dev.driver.c_str(), frame.width, frame.height, o.referenceSpp, o.bounces,
        o.referenceEvery, o.warmup);
    std::fflush(stdout);

    engine::AtomicFile framesFile;
    if (engine::Status s = framesFile.open(out / "frames.csv"); !s) return fail(s.error());
    framesFile.stream() << "scene,method,spp,frame,wall_ms,indirect_mae,reference_mean_abs,label\n";
    engine::AtomicFile summaryFile;
    if (engine::Status s = summaryFile.open(out / "summary.csv"); !s) return fail(s.error());
    summaryFile.stream() << "scene,method,spp,wall_ms_mean,wall_ms_median,indirect_mae,relative_"
                            "mae,reference_mean_abs,frames,"
                            "reference_frames,size,reference_spp,bounces,cache_fallback,cache_"
                            "budget,cache_variant\n";
    FlythroughOutputs outputs{framesFile.stream(), summaryFile.stream(),
                              "| scene | method | wall ms/frame (mean) | indirect MAE | MAE / mean "
                              "\\|indirect\\| |\n|---|---|---|---|---|\n"};
    for (const std::string& world : o.worlds) {
        if (engine::Status s = benchScene(**ctx, world, o, frame, outputs); !s)
            return fail(s.error());
    }
    if (engine::Status s = framesFile.commit(); !s) return fail(s.error());
    if (engine::Status s = summaryFile.commit(); !s) return fail(s.error());
    if (engine::Status s = engine::writeFileAtomically(out / "table.md", outputs.table); !s)
        return fail(s.error());
    std::printf("\nwrote %s, %s and %s; chart: python3 tools/plot_flythrough.py %s\n",
                (out / "summary.csv").c_str(), (out / "frames.csv").c_str(),
                (out / "table.md").c_str(), (out / "summary.csv").c_str());
    return 0;
}

}  // namespace

void addBenchFlythroughCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand("flythrough",
                                     "Indirect light on a moving camera: irradiance cache vs "
                                     "path-traced bounces at equal wall time");
    auto o = std::make_shared<FlythroughOptions>();
    cmd->add_option("worlds", o->worlds, "Worlds, each with worlds/paths/<world>_flythrough.toml")
        ->capture_default_str();
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--frames", o->frames, "Frames of each path to play (default: all)")
        ->check(numberIn(kFrameCountRange));
    cmd->add_option("--warmup", o->warmup, "Frames played before measuring (the cache fills)")
        ->capture_default_str()
        ->check(numberIn(kWarmupRange));
    cmd->add_option("--reference-every", o->referenceEvery,
                    "Compare with the reference every K-th measured frame")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 100000, "frames")));
    cmd->add_option("--reference-spp", o->referenceSpp,
                    "Reference samples per pixel (with and without bounces)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 65536, "samples per pixel")));
    cmd->add_option("--path-spp", o->pathSpp,
                    "Path-traced indirect: paths per pixel per frame, one point each")
        ->delimiter(',')
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 256, "paths per pixel")));
    cmd->add_option("--cache-fallback", o->cacheFallback,
                    "Cache runs, one per gather fallback radius (voxels; 0 = off), e.g. 0,4 for "
                    "before and after")
        ->delimiter(',')
        ->check(numberIn(engine::wholeRange(0, 16, "voxels")));
    cmd->add_option("--cache-budget", o->cacheBudget,
                    "Cache runs, one per ray budget (0 = every visible entry every frame)")
        ->delimiter(',')
        ->check(numberIn(engine::wholeRange(0, 100000000, "rays")));
    cmd->add_option(
        "--cache-variant", o->cacheVariants,
        "One more cache run per value, NAME:--knob value ... (e.g. 'lod:--cache-lod-distance 24')");
    cmd->add_option("--bounces", o->bounces, "Bounces of the reference, the cache and the paths")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 8, "bounces")));
    cmd->add_option("-o,--output", o->output, "Output folder (summary.csv, frames.csv, table.md)")
        ->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runFlythroughBench(*o); });
}

}  // namespace vox
