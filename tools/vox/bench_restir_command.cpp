// vox bench restir: ReSTIR's error at equal time against uniform light sampling and against RIS
// without reuse, per scene, in one run. Equal time: the baselines get as many shadow rays (or
// candidates) as fit in ReSTIR's measured frame time, from a linear fit of their own timings.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/atomic_file.h"
#include "commands.h"
#include "number_options.h"
#include "gpu/context.h"
#include "metrics/image_metrics.h"
#include "render/renderer.h"
#include "sweep_runner.h"

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
    std::string sampling = "power";    // ReSTIR's and RIS's candidates: power or regir
    std::uint32_t candidates = 32;     // ReSTIR's M
};

int runRestirBench(const RestirBenchOptions& o) {
    auto size = parseSize(o.size, "--size");
    if (!size) return fail(size.error());
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
    engine::AtomicFile jsonFile;
    if (engine::Status s = jsonFile.open(out); !s) return fail(s.error());
    std::ostream& json = jsonFile.stream();
    json << "{\"size\": [" << fs.width << ", " << fs.height << "], \"sampling\": \"" << o.sampling
         << "\", \"candidates\": " << o.candidates << ", \"device\": \"" << gpu.info().name
         << "\", \"reference_spp\": " << o.referenceSpp << ", \"scenes\": [\n";

    std::printf("\n%-12s %9s %11s | %9s %5s %11s %7s | %9s %5s %11s %7s\n", "scene", "restir ms", "restir MSE",
                "unif. ms", "rays", "uniform MSE", "ratio", "ris ms", "M", "ris MSE", "ratio");
    for (std::size_t w = 0; w < o.worlds.size(); ++w) {
        auto scene = loadWorld(o.worlds[w]);
        if (!scene) return fail(scene.error());
        engine::world::CameraPreset camera = scene->camera();

        auto cached = cachedReference(gpu, *scene, camera, fs, o.referenceSpp, 0, std::filesystem::path(o.output).parent_path() / "cache");
        if (!cached) return fail(cached.error());
        const std::vector<glm::vec4>& reference = *cached;
        auto measure = [&](const LightingSettings& l, std::uint32_t frames) {
            return measureSetting(gpu, *scene, camera, fs, l, frames, reference, "");
        };

        LightingSettings restir;  // defaults: biased, area, power, M = 32, temporal, spatial 5 x 30 px
        restir.restir.candidates = o.candidates;
        restir.regir.enabled = o.sampling == "regir" ? 1u : 0u;
        SweepPoint r = measure(restir, o.frames);

        // Fit time = base + slope x n for each baseline, then pick n for ReSTIR's time.
        auto equalTime = [&](LightingSettings l, std::uint32_t& n, std::uint32_t& (*knobOf)(LightingSettings&)) {
            std::uint32_t& knob = knobOf(l);
            knob = 1;
            double t1 = measure(l, 6).totalMs;
            knob = 8;
            double t8 = measure(l, 6).totalMs;
            double slope = std::max((t8 - t1) / 7.0, 1e-6);
            double base = t1 - slope;
            n = std::clamp<std::uint32_t>(std::uint32_t(std::lround((r.totalMs - base) / slope)), 1u, 4096u);
            knob = n;
            SweepPoint m = measure(l, 8);
            // One correction step: timings are noisy and not quite linear.
            double perUnit = std::max((m.totalMs - base) / double(n), 1e-6);
            std::uint32_t corrected =
                std::clamp<std::uint32_t>(std::uint32_t(std::lround((r.totalMs - base) / perUnit)), 1u, 4096u);
            if (corrected == n) return m;
            n = corrected;
            knob = n;
            return measure(l, 8);
        };
        LightingSettings uniform;
        uniform.method = Method::Uniform;
        uniform.byPower = false;
        std::uint32_t rays = 1, candidates = 1;
        SweepPoint u = equalTime(uniform, rays, [](LightingSettings& x) -> std::uint32_t& { return x.shadowRays; });
        LightingSettings ris;
        ris.method = Method::Ris;
        ris.restir.temporal = ris.restir.spatial = ris.restir.candidateVisibility = false;
        ris.regir.enabled = restir.regir.enabled;
        SweepPoint s = equalTime(ris, candidates, [](LightingSettings& x) -> std::uint32_t& { return x.restir.candidates; });

        std::printf("%-12s %9.2f %11.3e | %9.2f %5u %11.3e %6.1fx | %9.2f %5u %11.3e %6.1fx\n", scene->name.c_str(), r.totalMs,
                    r.mse, u.totalMs, rays, u.mse, u.mse / r.mse, s.totalMs, candidates, s.mse, s.mse / r.mse);
        json << "  {\"scene\": \"" << scene->name << "\", \"emitters\": " << r.emitters
             << ", \"restir\": {\"ms\": " << r.totalMs << ", \"mse\": " << r.mse << ", \"mae\": " << r.mae << "}"
             << ", \"uniform\": {\"rays\": " << rays << ", \"ms\": " << u.totalMs << ", \"mse\": " << u.mse
             << ", \"mae\": " << u.mae << "}, \"ris\": {\"candidates\": " << candidates << ", \"ms\": " << s.totalMs
             << ", \"mse\": " << s.mse << ", \"mae\": " << s.mae << "}, \"mse_ratio_uniform\": " << u.mse / r.mse
             << ", \"mse_ratio_ris\": " << s.mse / r.mse << "}" << (w + 1 < o.worlds.size() ? "," : "") << "\n";
    }
    json << "]}\n";
    if (engine::Status s = jsonFile.commit(); !s) return fail(s.error());
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
    cmd->add_option("--frames", o->frames, "Frames of ReSTIR history (the last half are measured)")->capture_default_str()
        ->check(numberIn(engine::wholeRange(4, 1000, "frames")));
    cmd->add_option("--ref-spp", o->referenceSpp, "Reference samples per pixel")->capture_default_str()
        ->check(numberIn(kSamplesRange));
    cmd->add_option("-o,--output", o->output, "JSON results file")->capture_default_str();
    cmd->add_option("--sampling", o->sampling, "ReSTIR's and RIS's candidates: power | regir")->capture_default_str()
        ->check(CLI::IsMember({"power", "regir"}));
    cmd->add_option("--candidates", o->candidates, "ReSTIR's candidates per pixel (M)")->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 1024, "candidates")));
    cmd->callback([o, &exitCode] { exitCode = runRestirBench(*o); });
}

}  // namespace vox
