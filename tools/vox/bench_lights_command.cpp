// vox bench lights: how a frame's time and error follow the number of lights and how they are
// spread (issue 38). The same floor and view with 10^3 .. 10^6 single-voxel lamps, laid out densely
// around the view or sparsely over the whole floor (light_scaling_worlds.h); per world and per
// --sampling value, ReSTIR's wall and CPU milliseconds per frame (host included) and its error
// against the path tracer (the restir bench's references and measurement, sweep_runner.h), over
// seeds, the sampling values rendered back to back and their order reversed on every other seed.
// MSE is the row's own: its MSE against the reference less the reference's own (estimated from a
// second, shorter path trace: referenceNoise). Equal time: MSE x CPU ms per frame, the
// work-normalised error (MSE falls as 1 / samples), per seed; its ratio to the better sampling says
// whether --sampling auto's choice (printed per world) loses by more than the seeds' spread. Writes
// lights.csv, passes.csv (median GPU ms per pass, for where the time goes) and the scene files;
// tools/plot_lights.py draws the chart.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <sstream>

#include "bench_setup.h"
#include "commands.h"
#include "gpu/context.h"
#include "light_scaling_worlds.h"
#include "lighting/lighting_knobs.h"
#include "metrics/image_metrics.h"
#include "metrics/seed_statistics.h"
#include "number_options.h"
#include "render/sampling_choice.h"
#include "sweep_runner.h"

namespace vox {

namespace {

using engine::lighting::LightingSettings;

struct LightsBenchOptions {
    std::vector<std::uint32_t> counts{1000, 10000, 100000, 1000000};
    std::vector<std::string> layouts{"dense", "sparse"};
    std::vector<std::string> sampling{"power", "regir"};
    std::string size = "64x64";
    std::uint32_t frames = 8;
    std::uint32_t referenceSpp = 256;
    std::uint32_t seeds = 3;
    std::string output = "out/bench_lights";
};

// One sampling value's measurements on one world, per seed.
struct ModeResult {
    std::string sampling;
    std::vector<double> wallMs, cpuMs, mse, rawMse, mae, relRmse, mseTime;
    std::map<std::string, std::vector<double>> passMs;
};

// The reference's own MSE against the truth, which every row's MSE against it includes: a second
// path trace with another seed and a quarter of the samples, b, differs from the reference, a, by
// MSE(a, b) = Var(a) + Var(b) = Var(a) (1 + spp_a / spp_b) (independent, unbiased, variance as
// 1 / spp). A row's MSE minus Var(a) is then its own error, which 64 spp on lamp fields would
// otherwise bury (two 64-spp references of the dense 10^3 world differ by MSE 18, ReSTIR's whole
// measured MSE there is 17).
double referenceNoise(engine::gpu::Context& gpu, engine::world::Scene& scene,
                      const engine::world::CameraPreset& camera,
                      const engine::render::FrameSettings& frame, std::uint32_t spp,
                      const std::vector<glm::vec4>& reference) {
    const std::uint32_t checkSpp = std::max(16u, spp / 4);
    engine::render::Renderer renderer(gpu);
    LightingSettings l;
    l.method = engine::lighting::Method::Reference;
    l.referenceFilter = engine::lighting::ReferenceFilter::PixelCentre;
    l.samplesPerFrame = 16;
    l.seed = 2;  // the cached reference's is 1
    for (std::uint32_t s = 0; s < checkSpp; s += l.samplesPerFrame)
        renderer.render(scene, camera, frame, l);
    const std::vector<glm::vec4> check = renderer.readback().radiance;
    auto e = engine::metrics::compareImages({check, frame.width, frame.height},
                                            {reference, frame.width, frame.height});
    return e ? e->mse / (1.0 + double(spp) / double(checkSpp)) : 0.0;
}

double meanOf(const std::vector<glm::vec4>& image) {
    double sum = 0.0;
    for (const glm::vec4& p : image) sum += (double(p.x) + p.y + p.z) / 3.0;
    return image.empty() ? 0.0 : sum / double(image.size());
}

engine::Result<LightingSettings> settingsFor(const std::string& sampling) {
    const auto* method = engine::lighting::knobForOption("method");
    const auto* knob = engine::lighting::knobForOption("sampling");
    const engine::lighting::KnobValue values[] = {{method, "restir", "--sampling"},
                                                  {knob, sampling, "--sampling"}};
    return engine::lighting::mergeLighting(LightingSettings{}, values);
}

std::string csvHeader() {
    return "layout,count,emitters,sampling,auto_choice,seeds,wall_ms,wall_ms_min,wall_ms_max,"
           "cpu_ms,cpu_ms_min,cpu_ms_max,mse,mse_min,mse_max,rel_rmse,mse_x_ms,mse_x_ms_min,"
           "mse_x_ms_max,vs_best,ref_mean,rel_rmse_equal_time,mae,mae_min,mae_max,mae_x_ms,"
           "per_cell,raw_mse,reference_mse\n";
}

int runLightsBench(const LightsBenchOptions& o) {
    auto bench = openBench(o.size);
    if (!bench) return fail(bench.error());
    std::vector<LightLayout> layouts;
    for (const std::string& l : o.layouts) {
        if (l != "dense" && l != "sparse")
            return fail(engine::makeError("--layouts: '{}' is not dense or sparse", l));
        layouts.push_back(l == "dense" ? LightLayout::Dense : LightLayout::Sparse);
    }
    std::vector<LightingSettings> modes;
    for (const std::string& s : o.sampling) {
        if (s == "auto")
            return fail(engine::makeError(
                "--sampling: auto is reported from the other rows (it renders as its choice)"));
        auto l = settingsFor(s);
        if (!l) return fail(l.error());
        modes.push_back(*l);
    }
    engine::gpu::Context& gpu = *bench->gpu;
    const std::filesystem::path out(o.output);
    std::printf("device   %s (%s)\n", gpu.info().name.c_str(), gpu.info().driver.c_str());
    engine::AtomicFile csv, passes;
    if (engine::Status s = openOutputFile(csv, out / "lights.csv"); !s) return fail(s.error());
    if (engine::Status s = openOutputFile(passes, out / "passes.csv"); !s) return fail(s.error());
    csv.stream() << csvHeader();
    passes.stream() << "layout,count,sampling,pass,gpu_ms\n";
    const auto started = std::chrono::steady_clock::now();
    for (LightLayout layout : layouts) {
        for (std::uint32_t count : o.counts) {
            const LightScalingWorld world = lightScalingWorld(layout, count);
            const std::filesystem::path file = out / "worlds" / (world.name + ".toml");
            engine::AtomicFile toml;
            if (engine::Status s = openOutputFile(toml, file); !s) return fail(s.error());
            toml.stream() << world.toml;
            if (engine::Status s = toml.commit(); !s) return fail(s.error());
            auto scene = loadWorld(file.string());
            if (!scene) return fail(scene.error());
            const engine::world::CameraPreset camera = scene->camera();
            auto reference = cachedReference(gpu, *scene, camera, bench->frame, o.referenceSpp, 0,
                                             out / "cache");
            if (!reference) return fail(reference.error());
            const double refMean = meanOf(*reference);
            std::fprintf(stderr, "%s: the reference's own noise (a second path trace) ...\n",
                         world.name.c_str());
            const double refNoise =
                referenceNoise(gpu, *scene, camera, bench->frame, o.referenceSpp, *reference);
            engine::render::Renderer renderer(gpu);
            std::vector<ModeResult> results(modes.size());
            for (std::uint32_t seed = 0; seed < o.seeds; ++seed) {
                for (std::size_t k = 0; k < modes.size(); ++k) {
                    const std::size_t m = seed % 2 == 0 ? k : modes.size() - 1 - k;
                    LightingSettings l = modes[m];
                    l.seed += seed * 104729u;
                    std::fprintf(stderr, "  %s: %s, seed %u/%u\n", world.name.c_str(),
                                 o.sampling[m].c_str(), seed + 1, o.seeds);
                    renderer.setFrameIndex(0);
                    SweepPoint p = measureSetting(renderer, *scene, camera, bench->frame, l,
                                                  o.frames, *reference, o.sampling[m]);
                    ModeResult& r = results[m];
                    r.sampling = o.sampling[m];
                    r.wallMs.push_back(p.wallMs);
                    r.cpuMs.push_back(p.cpuMs);
                    // The row's own error: its MSE against the reference less the reference's.
                    const double mse = std::max(p.mse - refNoise, 0.0);
                    r.mse.push_back(mse);
                    r.rawMse.push_back(p.mse);
                    r.mae.push_back(p.mae);
                    r.relRmse.push_back(refMean > 0.0 ? std::sqrt(mse) / refMean : 0.0);
                    r.mseTime.push_back(mse * p.cpuMs);
                    for (const auto& [pass, ms] : p.passMs) r.passMs[pass].push_back(ms);
                }
            }
            // What --sampling auto renders here: exactly one of the rows (its images are the
            // chosen row's, SamplingChoice tests), so it is reported, not rendered again.
            const engine::render::SamplingFacts facts = engine::render::samplingFacts(
                renderer.emitters(), scene->grid.sizeInVoxels(), LightingSettings{}.regir);
            const std::string choice = engine::render::autoChoosesRegir(facts) ? "regir" : "power";
            // The better row by median MSE x time; auto loses only if its choice's seeds all lie
            // above the better row's (the spreads do not overlap).
            std::size_t best = 0;
            for (std::size_t m = 1; m < results.size(); ++m) {
                if (engine::metrics::summarize(results[m].mseTime).median <
                    engine::metrics::summarize(results[best].mseTime).median)
                    best = m;
            }
            std::printf("\n%s: reference's own MSE %.2e (subtracted from the rows')\n",
                        world.name.c_str(), refNoise);
            std::printf(
                "%s: %u emitters, spread %.0f voxels = %.1f ReGIR cells of %.0f, %.1f "
                "per occupied cell; auto chooses %s\n",
                world.name.c_str(), facts.emitters, facts.spread, facts.spread / facts.regirCell,
                facts.regirCell, facts.perOccupiedCell, choice.c_str());
            for (std::size_t m = 0; m < results.size(); ++m) {
                const ModeResult& r = results[m];
                using engine::metrics::summarize;
                const auto wall = summarize(r.wallMs), cpu = summarize(r.cpuMs),
                           mse = summarize(r.mse), rel = summarize(r.relRmse),
                           mt = summarize(r.mseTime), mae = summarize(r.mae);
                // MAE x ms per seed: MAE falls as 1 / sqrt(samples), so its square times time.
                std::vector<double> maeTime;
                for (std::size_t i = 0; i < r.mae.size(); ++i)
                    maeTime.push_back(r.mae[i] * r.mae[i] * r.cpuMs[i]);
                const auto mat = summarize(maeTime);
                // 0 / 0 when both rows' MSE is under the reference's own: unresolved, not a ratio.
                const double bestMt = summarize(results[best].mseTime).median;
                const double vsBest = bestMt > 0.0 ? mt.median / bestMt : std::nan("");
                // The relative RMSE this sampling would reach in the first row's CPU time.
                const double equalMs = summarize(results[0].cpuMs).median;
                const double relEqual =
                    refMean > 0.0 && equalMs > 0.0 ? std::sqrt(mt.median / equalMs) / refMean : 0.0;
                std::printf(
                    "  %-6s wall %7.1f ms (%.1f–%.1f)  cpu %7.1f ms  MSE %.2e (%.2e–%.2e)  rel "
                    "RMSE %.3f (%.3f at %s's time)  MSE×ms ÷ best %.2f  MAE %.2e (%.2e–%.2e)%s\n",
                    r.sampling.c_str(), wall.median, wall.min, wall.max, cpu.median, mse.median,
                    mse.min, mse.max, rel.median, relEqual, results[0].sampling.c_str(), vsBest,
                    mae.median, mae.min, mae.max, r.sampling == choice ? "  <- auto" : "");
                csv.stream() << fmt::format(
                    "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},"
                    "{},{},{}\n",
                    layoutName(layout), count, facts.emitters, r.sampling, choice, o.seeds,
                    wall.median, wall.min, wall.max, cpu.median, cpu.min, cpu.max, mse.median,
                    mse.min, mse.max, rel.median, mt.median, mt.min, mt.max, vsBest, refMean,
                    relEqual, mae.median, mae.min, mae.max, mat.median, facts.perOccupiedCell,
                    summarize(r.rawMse).median, refNoise);
                for (const auto& [pass, ms] : r.passMs)
                    passes.stream() << fmt::format("{},{},{},{},{}\n", layoutName(layout), count,
                                                   r.sampling, pass, summarize(ms).median);
            }
            const auto chosen =
                std::find_if(results.begin(), results.end(),
                             [&](const ModeResult& r) { return r.sampling == choice; });
            if (chosen != results.end() && std::size_t(chosen - results.begin()) != best) {
                const auto a = engine::metrics::summarize(chosen->mseTime),
                           b = engine::metrics::summarize(results[best].mseTime);
                std::printf(
                    "  auto's %s: MSE×ms %.2fx the better row's; %s\n", choice.c_str(),
                    a.median / b.median,
                    a.min > b.max ? "worse beyond the seeds' spread" : "within the seeds' spread");
            }
        }
    }
    if (engine::Status s = csv.commit(); !s) return fail(s.error());
    if (engine::Status s = passes.commit(); !s) return fail(s.error());
    std::printf("\nwall time %.0f s\nwrote    %s\nwrote    %s\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(),
                (out / "lights.csv").string().c_str(), (out / "passes.csv").string().c_str());
    return 0;
}

}  // namespace

void addBenchLightsCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "lights", "Frame time and error against the path tracer as lights grow from 10^3 to 10^6");
    auto o = std::make_shared<LightsBenchOptions>();
    cmd->add_option("--counts", o->counts, "Lamp counts (comma-separated)")
        ->delimiter(',')
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 4194304, "lamps")));
    cmd->add_option("--layouts", o->layouts, "dense (around the view), sparse (over the floor)")
        ->delimiter(',')
        ->capture_default_str();
    cmd->add_option("--sampling", o->sampling,
                    "Values of the sampling knob to render (auto is reported as its choice)")
        ->delimiter(',')
        ->capture_default_str();
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--frames", o->frames, "Frames per point (the last half are measured)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(2, 1000, "frames")));
    cmd->add_option("--ref-spp", o->referenceSpp,
                    "Reference samples per pixel (cached beside the CSV)")
        ->capture_default_str()
        ->check(numberIn(kSamplesRange));
    cmd->add_option("--seeds", o->seeds, "Seeds per point: medians and spreads are over these")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 1000, "seeds")));
    cmd->add_option("-o,--output", o->output, "Output folder")->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runLightsBench(*o); });
}

}  // namespace vox
