// vox bench accuracy: every lighting method and setting against the converged reference on each
// scene, with per-pass GPU timings — the tables of docs/ACCURACY.md, laid out like the thesis's
// Tables 1-3 (kernel times per stage, and MAE/MSE per scene).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include "bench_setup.h"
#include "commands.h"
#include "core/atomic_file.h"
#include "gpu/context.h"
#include "metrics/image_metrics.h"
#include "number_options.h"
#include "render/renderer.h"
#include "sweep_runner.h"
#include "thesis_scenes.h"

namespace vox {

namespace {

using engine::lighting::LightingSettings;
using engine::lighting::Method;

struct AccuracyOptions {
    std::vector<std::string> worlds = kThesisScenes;
    std::string size = "160x96";
    std::uint32_t frames = 16;
    std::uint32_t referenceSpp = 1024;
    std::uint32_t bruteForceLimit = 2000;
    std::string output = "out/accuracy";
};

std::vector<std::pair<std::string, LightingSettings>> configurations(std::uint32_t emitters,
                                                                     std::uint32_t bruteForceLimit,
                                                                     bool hasBrickLights) {
    std::vector<std::pair<std::string, LightingSettings>> out;
    for (bool area : {false, true}) {
        for (std::uint32_t m : {1u, 8u, 16u, 32u}) {
            LightingSettings l;
            l.area = area;
            l.restir.candidates = m;
            out.push_back({fmt::format("ReSTIR biased, {}, M={}", area ? "area" : "point", m), l});
        }
        LightingSettings u;
        u.area = area;
        u.restir.unbiased = true;
        out.push_back({fmt::format("ReSTIR unbiased, {}, M=32", area ? "area" : "point"), u});
        if (hasBrickLights) {
            LightingSettings b;
            b.area = area;
            b.brickLights = false;
            out.push_back(
                {fmt::format("ReSTIR biased, {}, M=32, brick lights off", area ? "area" : "point"),
                 b});
        }
    }
    LightingSettings uniformCandidates;
    uniformCandidates.byPower = false;
    out.push_back({"ReSTIR biased, area, M=32, uniform candidates (thesis)", uniformCandidates});
    LightingSettings temporalOnly;
    temporalOnly.restir.spatial = false;
    out.push_back({"ReSTIR without spatial reuse, area, M=32", temporalOnly});
    LightingSettings ris;
    ris.method = Method::Ris;
    ris.restir.temporal = ris.restir.spatial = ris.restir.candidateVisibility = false;
    out.push_back({"RIS without reuse, area, M=32", ris});
    LightingSettings uniform;
    uniform.method = Method::Uniform;
    uniform.byPower = false;
    out.push_back({"Uniform light sampling, area, 1 ray", uniform});
    if (emitters <= bruteForceLimit) {
        LightingSettings brute;
        brute.method = Method::BruteForce;
        out.push_back({fmt::format("Brute force, area ({} rays)", emitters), brute});
    }
    return out;
}

int runAccuracy(const AccuracyOptions& o) {
    auto bench = openBench(o.size);
    if (!bench) return fail(bench.error());
    engine::gpu::Context& gpu = *bench->gpu;
    const engine::render::FrameSettings& fs = bench->frame;
    std::filesystem::create_directories(o.output);
    engine::AtomicFile mdFile;
    if (engine::Status s = mdFile.open(std::filesystem::path(o.output) / "accuracy_tables.md"); !s)
        return fail(s.error());
    std::ostream& md = mdFile.stream();
    engine::AtomicFile csvFile;
    if (engine::Status s = csvFile.open(std::filesystem::path(o.output) / "accuracy.csv"); !s)
        return fail(s.error());
    std::ostream& csv = csvFile.stream();
    csv << "scene,emitters,configuration,primary_ms,initial_ms,temporal_ms,spatial_ms,shade_ms,"
           "total_ms,mae,mse,mean_ratio\n";
    md << fmt::format(
        "Measured on {} ({}) at {}x{}, {} frames per setting (the last {} measured), reference {} "
        "spp.\n\n",
        gpu.info().name, gpu.info().driver, fs.width, fs.height, o.frames, o.frames - o.frames / 2,
        o.referenceSpp);
    for (const std::string& name : o.worlds) {
        auto scene = loadWorld(name);
        if (!scene) return fail(scene.error());
        engine::world::CameraPreset camera = scene->camera();
        auto cached = cachedReference(gpu, *scene, camera, fs, o.referenceSpp, 0,
                                      std::filesystem::path(o.output) / "cache");
        if (!cached) return fail(cached.error());
        const std::vector<glm::vec4>& reference = *cached;
        engine::lighting::EmitterList lights;
        lights.rebuild(*scene);
        std::uint32_t emitters = lights.aliveCount();
        bool brickLights = false;
        for (const auto& e : lights.slots()) brickLights |= e.minCorner.w == 8 && (e.info.w & 1u);
        auto configs = configurations(emitters, o.bruteForceLimit, brickLights);

        md << fmt::format("### {} — {} emissive voxels, {} emitters with brick lights on\n\n",
                          scene->name, scene->emissiveVoxels(), emitters);
        md << "| setting | primary | candidates | temporal | spatial | shading | total ms | MAE | "
              "MSE | mean ratio |\n";
        md << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
        for (std::size_t i = 0; i < configs.size(); ++i) {
            std::fprintf(stderr, "\r  %zu/%zu %-60s", i + 1, configs.size(),
                         configs[i].first.c_str());
            SweepPoint r = measureSetting(gpu, *scene, camera, fs, configs[i].second, o.frames,
                                          reference, configs[i].first);
            auto ms = [&](const char* pass) { return r.passMs.count(pass) ? r.passMs[pass] : 0.0; };
            double shading = ms("restir_shade") + ms("light_sampling");
            auto cell = [](double v) {
                return v > 0.0 ? fmt::format("{:.2f}", v) : std::string("–");
            };
            md << fmt::format(
                "| {} | {} | {} | {} | {} | {} | {:.2f} | {:.4e} | {:.4e} | {:.3f} |\n", r.label,
                cell(ms("primary_rays")), cell(ms("restir_initial")), cell(ms("restir_temporal")),
                cell(ms("restir_spatial")), cell(shading), r.totalMs, r.mae, r.mse, r.meanRatio);
            csv << fmt::format("{},{},\"{}\",{},{},{},{},{},{},{},{},{}\n", scene->name, r.emitters,
                               r.label, ms("primary_rays"), ms("restir_initial"),
                               ms("restir_temporal"), ms("restir_spatial"), shading, r.totalMs,
                               r.mae, r.mse, r.meanRatio);
        }
        std::fprintf(stderr, "\n");
        md << "\n";
    }
    if (engine::Status s = mdFile.commit(); !s) return fail(s.error());
    if (engine::Status s = csvFile.commit(); !s) return fail(s.error());
    std::printf("wrote    %s/accuracy_tables.md and accuracy.csv\n", o.output.c_str());
    return 0;
}

}  // namespace

void addBenchAccuracyCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "accuracy", "Every method and setting vs the reference: MAE, MSE, per-pass ms");
    auto o = std::make_shared<AccuracyOptions>();
    cmd->add_option("worlds", o->worlds, "Worlds (default: the four thesis scenes)");
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--frames", o->frames, "Frames per setting (the last half are measured)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(2, 1000, "frames")));
    cmd->add_option("--ref-spp", o->referenceSpp, "Reference samples per pixel")
        ->capture_default_str()
        ->check(numberIn(kSamplesRange));
    cmd->add_option("-o,--output", o->output, "Output folder (markdown tables and CSV)")
        ->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runAccuracy(*o); });
}

}  // namespace vox
