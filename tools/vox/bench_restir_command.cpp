// vox bench restir: ReSTIR's error at equal time against uniform light sampling and against RIS
// without reuse, per scene, in one run. Equal time: the baselines get as many shadow rays (or
// candidates) as fit in ReSTIR's measured frame time, from a linear fit of their own timings.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "commands.h"
#include "gpu/context.h"
#include "metrics/image_metrics.h"
#include "render/renderer.h"

namespace vox {

namespace {

using engine::lighting::LightingSettings;
using engine::lighting::Method;

struct RestirBenchOptions {
    std::vector<std::string> worlds{"cornell", "mountain", "letters", "apartments"};
    std::string size = "128x72";
    std::uint32_t frames = 16;
    std::uint32_t referenceSpp = 1024;
    std::string output = "out/bench_restir.json";
};

struct Measured {
    double ms = 0.0;   // median GPU time per frame, upload excluded
    double mse = 0.0;  // against the reference, mean over the measured frames or seeds
    double mae = 0.0;
};

double frameMs(const engine::render::FrameResult& r) { return r.totalMs() - r.passMsOf("upload"); }

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// Renders `frames` frames of a still camera and measures the last half of them.
Measured measure(engine::gpu::Context& ctx, engine::world::Scene& scene, const engine::world::CameraPreset& camera,
                 const engine::render::FrameSettings& fs, LightingSettings l, std::uint32_t frames,
                 const std::vector<glm::vec4>& reference) {
    engine::render::Renderer renderer(ctx);
    std::vector<double> times;
    Measured m;
    int counted = 0;
    for (std::uint32_t i = 0; i < frames; ++i) {
        auto r = renderer.render(scene, camera, fs, l);
        if (i < frames / 2) continue;
        times.push_back(frameMs(r));
        auto img = renderer.readback();
        auto errors = engine::metrics::compareImages({img.radiance, fs.width, fs.height}, {reference, fs.width, fs.height});
        m.mse += errors->mse;
        m.mae += errors->mae;
        ++counted;
        if (l.method != Method::Restir) l.seed += 7919;  // independent frames for the memoryless methods
    }
    m.ms = median(times);
    m.mse /= counted;
    m.mae /= counted;
    return m;
}

int runRestirBench(const RestirBenchOptions& o) {
    auto size = parseSize(o.size, "--size");
    if (!size) return fail(size.error());
    if (o.frames < 4 || o.frames > 1000) return fail(engine::makeError("--frames must be in 4..1000"));
    auto ctx = engine::gpu::Context::create({});
    if (!ctx) return fail(ctx.error());
    engine::gpu::Context& gpu = **ctx;
    std::printf("device   %s (%s)\n", gpu.info().name.c_str(), gpu.info().driver.c_str());
    engine::render::FrameSettings fs;
    fs.width = (*size).x;
    fs.height = (*size).y;

    std::filesystem::path out(o.output);
    std::error_code ec;
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path(), ec);
    std::ofstream json(out);
    json << "{\"size\": [" << fs.width << ", " << fs.height << "], \"device\": \"" << gpu.info().name
         << "\", \"reference_spp\": " << o.referenceSpp << ", \"scenes\": [\n";

    std::printf("\n%-12s %9s %11s | %9s %5s %11s %7s | %9s %5s %11s %7s\n", "scene", "restir ms", "restir MSE",
                "unif. ms", "rays", "uniform MSE", "ratio", "ris ms", "M", "ris MSE", "ratio");
    for (std::size_t w = 0; w < o.worlds.size(); ++w) {
        auto scene = loadWorld(o.worlds[w]);
        if (!scene) return fail(scene.error());
        engine::world::CameraPreset camera = scene->camera();

        engine::render::Renderer refRenderer(gpu);
        LightingSettings ref;
        ref.method = Method::Reference;
        ref.samplesPerFrame = 16;
        for (std::uint32_t s = 0; s < o.referenceSpp; s += ref.samplesPerFrame) refRenderer.render(*scene, camera, fs, ref);
        std::vector<glm::vec4> reference = refRenderer.readback().radiance;

        LightingSettings restir;  // defaults: biased, area, power, M = 32, temporal, spatial 5 x 30 px
        Measured r = measure(gpu, *scene, camera, fs, restir, o.frames, reference);

        // Fit time = base + slope x n for each baseline, then pick n for ReSTIR's time.
        auto equalTime = [&](LightingSettings l, std::uint32_t& n, std::uint32_t LightingSettings::*knob) {
            l.*knob = 1;
            double t1 = measure(gpu, *scene, camera, fs, l, 6, reference).ms;
            l.*knob = 8;
            double t8 = measure(gpu, *scene, camera, fs, l, 6, reference).ms;
            double slope = std::max((t8 - t1) / 7.0, 1e-6);
            double base = t1 - slope;
            n = std::clamp<std::uint32_t>(std::uint32_t(std::lround((r.ms - base) / slope)), 1u, 4096u);
            l.*knob = n;
            Measured m = measure(gpu, *scene, camera, fs, l, 8, reference);
            // One correction step: timings are noisy and not quite linear.
            double perUnit = std::max((m.ms - base) / double(n), 1e-6);
            std::uint32_t corrected = std::clamp<std::uint32_t>(std::uint32_t(std::lround((r.ms - base) / perUnit)), 1u, 4096u);
            if (corrected == n) return m;
            n = corrected;
            l.*knob = n;
            return measure(gpu, *scene, camera, fs, l, 8, reference);
        };
        LightingSettings uniform;
        uniform.method = Method::Uniform;
        uniform.byPower = false;
        std::uint32_t rays = 1, candidates = 1;
        Measured u = equalTime(uniform, rays, &LightingSettings::shadowRays);
        LightingSettings ris;
        ris.method = Method::Ris;
        ris.temporal = ris.spatial = ris.candidateVisibility = false;
        Measured s = equalTime(ris, candidates, &LightingSettings::candidates);

        std::printf("%-12s %9.2f %11.3e | %9.2f %5u %11.3e %6.1fx | %9.2f %5u %11.3e %6.1fx\n", scene->name.c_str(), r.ms,
                    r.mse, u.ms, rays, u.mse, u.mse / r.mse, s.ms, candidates, s.mse, s.mse / r.mse);
        json << "  {\"scene\": \"" << scene->name << "\", \"emitters\": " << refRenderer.emitters().aliveCount()
             << ", \"restir\": {\"ms\": " << r.ms << ", \"mse\": " << r.mse << ", \"mae\": " << r.mae << "}"
             << ", \"uniform\": {\"rays\": " << rays << ", \"ms\": " << u.ms << ", \"mse\": " << u.mse
             << ", \"mae\": " << u.mae << "}, \"ris\": {\"candidates\": " << candidates << ", \"ms\": " << s.ms
             << ", \"mse\": " << s.mse << ", \"mae\": " << s.mae << "}, \"mse_ratio_uniform\": " << u.mse / r.mse
             << ", \"mse_ratio_ris\": " << s.mse / r.mse << "}" << (w + 1 < o.worlds.size() ? "," : "") << "\n";
    }
    json << "]}\n";
    if (!json) return fail(engine::makeError("{}: cannot write results", out.string()));
    std::printf("\nratio = baseline MSE / ReSTIR MSE at equal GPU time per frame (higher is better for ReSTIR)\n");
    std::printf("wrote    %s\n", out.string().c_str());
    return 0;
}

}  // namespace

void addBenchRestirCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand("restir", "ReSTIR's MSE at equal time vs uniform light sampling and RIS");
    auto o = std::make_shared<RestirBenchOptions>();
    cmd->add_option("worlds", o->worlds, "Worlds (default: the four thesis scenes)");
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--frames", o->frames, "Frames of ReSTIR history (the last half are measured)")->capture_default_str();
    cmd->add_option("--ref-spp", o->referenceSpp, "Reference samples per pixel")->capture_default_str();
    cmd->add_option("-o,--output", o->output, "JSON results file")->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runRestirBench(*o); });
}

}  // namespace vox
