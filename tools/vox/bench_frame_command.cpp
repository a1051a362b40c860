// vox bench frame: what a frame costs as a player sees it (issue 14). For every world, image
// size, lighting row (ReSTIR + the irradiance cache, ReSTIR direct light only) and camera (the
// world's first preset held still, or a looping camera path), it renders warm-up frames and then
// measures: wall milliseconds per frame (median, p95) of the whole Renderer::render call — posing
// dynamic objects, uploads, the cache's host work, both submissions and their waits on the GPU —
// but not a readback, which a game does not need; GPU milliseconds per pass (median); rays per
// frame; cache entries updated per frame. Scene time advances at 30 fps in every configuration,
// so dynamic objects move as in play. Results: CSV + JSON in -o DIR, chart by
// tools/plot_frame.py, table in docs/PERFORMANCE.md ("Frame time").
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <sstream>

#include "bench_median.h"
#include "bench_setup.h"
#include "commands.h"
#include "core/atomic_file.h"
#include "frame_rays.h"
#include "gpu/context.h"
#include "lighting_options.h"
#include "number_options.h"
#include "progress_line.h"
#include "render/renderer.h"
#include "scene/path_file.h"

namespace vox {

namespace {

namespace fs = std::filesystem;

constexpr double kFps = 30.0;  // scene time per frame, and the camera paths' clock

struct FrameBenchOptions {
    std::string worlds = "sandbox,dragon_city,cornell";
    std::string sizes = "320x180,640x360";
    std::string indirect = "cache,none";
    std::string cameras = "still,moving";
    std::string paths;  // WORLD=PATH overrides of the moving camera's path
    std::uint32_t frames = 120;
    std::uint32_t warmup = 20;
    std::string output = "out/bench_frame";
    LightingOptions lighting;
};

// The moving camera of the worlds measured by default: closed loops without events.
const std::map<std::string, std::string> kDefaultPaths = {{"sandbox", "sandbox_orbit"},
                                                          {"dragon_city", "dragon_city_avenue"},
                                                          {"cornell", "cornell_sway"}};

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

// The smallest value at least 95 % of the frames do not exceed.
double p95(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::size_t(std::ceil(0.95 * double(v.size()))) - 1];
}

struct FrameSample {
    double wallMs = 0.0, gpuMs = 0.0;
    std::uint64_t rays = 0, cacheRays = 0;
    std::uint32_t cacheUpdated = 0, cacheTraced = 0;
    engine::render::FrameResult result;
};

struct Config {
    std::string world, indirect, camera, path;
    glm::uvec2 size{0};
    std::string label() const {
        return fmt::format("{} {}x{} {} {}", world, size.x, size.y, indirect, camera);
    }
};

struct ConfigResult {
    Config config;
    std::vector<FrameSample> frames;
    std::map<std::string, double> passMs;  // median per pass
    std::vector<std::string> passOrder;
    double wallMedian = 0.0, wallP95 = 0.0, gpuMedian = 0.0, hostMedian = 0.0;
    double rays = 0.0, cacheRays = 0.0, cacheUpdated = 0.0, cacheTraced = 0.0;
};

void summarise(ConfigResult& c) {
    std::map<std::string, std::vector<double>> perPass;
    std::vector<double> wall, gpu, host, rays, cacheRays, updated, traced;
    for (const FrameSample& f : c.frames) {
        for (const auto& [name, ms] : f.result.passMs) {
            if (!perPass.count(name)) c.passOrder.push_back(name);
            perPass[name].push_back(ms);
        }
        wall.push_back(f.wallMs);
        gpu.push_back(f.gpuMs);
        host.push_back(f.wallMs - f.gpuMs);
        rays.push_back(double(f.rays));
        cacheRays.push_back(double(f.cacheRays));
        updated.push_back(f.cacheUpdated);
        traced.push_back(f.cacheTraced);
    }
    // A pass that ran on only some frames counts as 0 ms on the others, so the medians per pass
    // stack up to about the median GPU total.
    for (auto& [name, v] : perPass) {
        v.resize(c.frames.size(), 0.0);
        c.passMs[name] = median(v);
    }
    c.wallMedian = median(wall);
    c.wallP95 = p95(wall);
    c.gpuMedian = median(gpu);
    c.hostMedian = median(host);
    c.rays = median(rays);
    c.cacheRays = median(cacheRays);
    c.cacheUpdated = median(updated);
    c.cacheTraced = median(traced);
}

engine::Result<ConfigResult> measure(engine::gpu::Context& ctx, const Config& config,
                                     const FrameBenchOptions& o, ProgressLine& progress,
                                     std::uint64_t& done) {
    auto scene = loadWorld(config.world);
    if (!scene) return scene.error();
    auto lighting = lightingSettings(o.lighting, &*scene);
    if (!lighting) return lighting.error();
    auto indirect = engine::lighting::parseIndirect(config.indirect);
    if (!indirect) return engine::makeError("--indirect-rows: {}", indirect.error().message);
    engine::lighting::LightingSettings l = *lighting;
    l.method = engine::lighting::Method::Restir;
    l.indirect = *indirect;

    std::optional<engine::world::Flythrough> fly;
    if (config.camera == "moving") {
        auto file = resolvePathFile(config.path);
        if (!file) return file.error();
        auto f = engine::scene::loadFlythroughFile(*file);
        if (!f) return f.error();
        if (f->camera.empty())
            return engine::makeError("{}: the path has no camera keys", file->string());
        fly = std::move(*f);
    }

    engine::render::Renderer renderer(ctx);
    engine::render::FrameSettings settings;
    settings.width = config.size.x;
    settings.height = config.size.y;
    ConfigResult out;
    out.config = config;
    const std::uint32_t total = o.warmup + o.frames;
    for (std::uint32_t i = 0; i < total; ++i) {
        settings.timeSeconds = double(i) / kFps;
        engine::world::CameraPreset camera = scene->camera();
        if (fly) {
            // The path loops (the default paths are closed loops), so any frame count fits.
            const double start = fly->camera.startTime(), length = fly->camera.endTime() - start;
            camera =
                fly->camera.at(start + (length > 0.0 ? std::fmod(double(i) / kFps, length) : 0.0));
        }
        const auto t0 = std::chrono::steady_clock::now();
        engine::render::FrameResult r = renderer.render(*scene, camera, settings, l);
        const double wallMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        ++done;
        if (i < o.warmup) {
            progress.update(done, fmt::format("{}: warm-up", config.label()));
            continue;
        }
        // Counting the surface pixels for the ray bound needs the G-buffer: read back outside
        // the timed call.
        const std::uint64_t pixels = std::uint64_t(config.size.x) * config.size.y;
        FrameSample s;
        s.wallMs = wallMs;
        s.gpuMs = r.totalMs();
        s.rays = rayBound(l, *scene, r, pixels, surfacePixels(renderer.readback()));
        if (r.cacheUsed) {
            s.cacheRays = r.cache.raysTraced;
            s.cacheUpdated = r.cache.updated;
            s.cacheTraced = r.cache.traced;
        }
        s.result = std::move(r);
        out.frames.push_back(std::move(s));
        progress.update(done, config.label());
    }
    summarise(out);
    return out;
}

// Passes in first-seen order over all configurations (the cache's passes run only with it).
std::vector<std::string> allPasses(const std::vector<ConfigResult>& results) {
    std::vector<std::string> passes;
    for (const ConfigResult& r : results)
        for (const std::string& p : r.passOrder)
            if (std::find(passes.begin(), passes.end(), p) == passes.end()) passes.push_back(p);
    return passes;
}

std::string summaryCsv(const std::vector<ConfigResult>& results) {
    const std::vector<std::string> passes = allPasses(results);
    std::string csv =
        "world,width,height,indirect,camera,path,frames,wall_median_ms,wall_p95_ms,gpu_median_ms,"
        "host_median_ms,"
        "rays,cache_rays,cache_updated,cache_traced";
    for (const std::string& p : passes) csv += ",gpu_" + p + "_ms";
    csv += "\n";
    for (const ConfigResult& r : results) {
        const Config& c = r.config;
        csv += fmt::format(
            "{},{},{},{},{},{},{},{:.3f},{:.3f},{:.3f},{:.3f},{:.0f},{:.0f},{:.0f},{:.0f}", c.world,
            c.size.x, c.size.y, c.indirect, c.camera, c.path, r.frames.size(), r.wallMedian,
            r.wallP95, r.gpuMedian, r.hostMedian, r.rays, r.cacheRays, r.cacheUpdated,
            r.cacheTraced);
        for (const std::string& p : passes) {
            auto it = r.passMs.find(p);
            csv += it == r.passMs.end() ? "," : fmt::format(",{:.3f}", it->second);
        }
        csv += "\n";
    }
    return csv;
}

std::string framesCsv(const std::vector<ConfigResult>& results) {
    std::string csv =
        "world,width,height,indirect,camera,frame,wall_ms,gpu_ms,rays,cache_rays,cache_updated\n";
    for (const ConfigResult& r : results) {
        const Config& c = r.config;
        for (std::size_t i = 0; i < r.frames.size(); ++i) {
            const FrameSample& f = r.frames[i];
            csv += fmt::format("{},{},{},{},{},{},{:.3f},{:.3f},{},{},{}\n", c.world, c.size.x,
                               c.size.y, c.indirect, c.camera, i, f.wallMs, f.gpuMs, f.rays,
                               f.cacheRays, f.cacheUpdated);
        }
    }
    return csv;
}

std::string json(const std::vector<ConfigResult>& results, const FrameBenchOptions& o,
                 const std::string& device) {
    std::string s = fmt::format(
        "{{\n  \"device\": \"{}\",\n  \"frames\": {},\n  \"warmup\": {},\n  \"fps\": {},\n"
        "  \"wall_includes\": \"the whole Renderer::render call: dynamic objects, uploads, cache "
        "host work, "
        "submissions and GPU waits; no readback\",\n  \"configs\": [",
        device, o.frames, o.warmup, kFps);
    for (std::size_t i = 0; i < results.size(); ++i) {
        const ConfigResult& r = results[i];
        const Config& c = r.config;
        std::string passes;
        for (const std::string& p : r.passOrder)
            passes +=
                fmt::format("{}\"{}\": {:.3f}", passes.empty() ? "" : ", ", p, r.passMs.at(p));
        s += fmt::format(
            "{}\n    {{\"world\": \"{}\", \"width\": {}, \"height\": {}, \"indirect\": \"{}\", "
            "\"camera\": \"{}\", "
            "\"path\": \"{}\", \"frames\": {}, \"wall_median_ms\": {:.3f}, \"wall_p95_ms\": "
            "{:.3f}, "
            "\"gpu_median_ms\": {:.3f}, \"host_median_ms\": {:.3f}, \"rays\": {:.0f}, "
            "\"cache_rays\": {:.0f}, "
            "\"cache_updated\": {:.0f}, \"cache_traced\": {:.0f}, \"pass_ms\": {{{}}}}}",
            i ? "," : "", c.world, c.size.x, c.size.y, c.indirect, c.camera, c.path,
            r.frames.size(), r.wallMedian, r.wallP95, r.gpuMedian, r.hostMedian, r.rays,
            r.cacheRays, r.cacheUpdated, r.cacheTraced, passes);
    }
    s += "\n  ]\n}\n";
    return s;
}

// The three most expensive passes, "cache.bounce 244, restir_initial 32, ...".
std::string topPasses(const ConfigResult& r) {
    std::vector<std::pair<double, std::string>> v;
    for (const auto& [name, ms] : r.passMs) v.push_back({ms, name});
    std::sort(v.rbegin(), v.rend());
    std::string out;
    for (std::size_t i = 0; i < v.size() && i < 3; ++i)
        out += fmt::format("{}{} {:.1f}", i ? ", " : "", v[i].second, v[i].first);
    return out;
}

engine::Status writeFile(const fs::path& file, const std::string& text) {
    return engine::writeFileAtomically(file, text);
}

// The configurations: every size, world, lighting row and camera. Sizes outermost: the small
// images of every world come first, so a run stopped early still compares the worlds (results
// are written after every configuration).
engine::Result<std::vector<Config>> configsOf(const FrameBenchOptions& o) {
    std::map<std::string, std::string> paths = kDefaultPaths;
    for (const std::string& item : splitList(o.paths)) {
        auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
            return engine::makeError("--paths: expected WORLD=PATH, got '{}'", item);
        paths[item.substr(0, eq)] = item.substr(eq + 1);
    }
    std::vector<Config> configs;
    for (const std::string& sizeText : splitList(o.sizes)) {
        auto size = parseSize(sizeText, "--sizes");
        if (!size) return size.error();
        for (const std::string& world : splitList(o.worlds)) {
            for (const std::string& indirect : splitList(o.indirect)) {
                if (auto ok = engine::lighting::parseIndirect(indirect); !ok)
                    return engine::makeError("--indirect-rows: {}", ok.error().message);
                for (const std::string& camera : splitList(o.cameras)) {
                    if (camera != "still" && camera != "moving")
                        return engine::makeError(
                            "--cameras: expected still and/or moving, got '{}'", camera);
                    Config c{world, indirect, camera, "", *size};
                    if (camera == "moving") {
                        auto it = paths.find(world);
                        // A world without a default path flies its own [path] (camera only).
                        c.path = it != paths.end() ? it->second : "";
                        if (c.path.empty()) {
                            auto scene = loadWorld(world);
                            if (!scene) return scene.error();
                            c.path = scene->sourcePath;
                        }
                    }
                    configs.push_back(c);
                }
            }
        }
    }
    if (configs.empty())
        return engine::makeError(
            "nothing to measure: --worlds, --sizes, --indirect-rows and --cameras must each name "
            "one");
    return configs;
}

void printTable(const std::vector<ConfigResult>& results) {
    std::printf(
        "\n| world | size | indirect | camera | wall median ms | wall p95 ms | GPU ms | host ms | "
        "rays/frame | "
        "cache entries updated | top passes (GPU ms) "
        "|\n|---|---|---|---|---:|---:|---:|---:|---:|---:|---|\n");
    for (const ConfigResult& r : results) {
        const Config& c = r.config;
        std::printf("| %s | %ux%u | %s | %s | %.1f | %.1f | %.1f | %.1f | %.2f M | %.0f | %s |\n",
                    c.world.c_str(), c.size.x, c.size.y, c.indirect.c_str(), c.camera.c_str(),
                    r.wallMedian, r.wallP95, r.gpuMedian, r.hostMedian, r.rays / 1e6,
                    r.cacheUpdated, topPasses(r).c_str());
    }
    std::printf("\n");
}

int runFrameBench(const FrameBenchOptions& o) {
    if (o.lighting.showSettings)
        return showSettings(splitList(o.worlds).empty() ? "" : splitList(o.worlds)[0], o.lighting);
    auto planned = configsOf(o);
    if (!planned) return fail(planned.error());
    const std::vector<Config>& configs = *planned;

    std::error_code ec;
    const fs::path dir(o.output);
    fs::create_directories(dir, ec);
    if (ec)
        return fail(engine::makeError("-o {}: cannot create folder: {}", o.output, ec.message()));
    auto ctx = createBenchGpu();
    if (!ctx) return fail(ctx.error());
    const auto& dev = (*ctx)->info();
    printDevice(**ctx);
    std::printf(
        "measure  %zu configurations, %u frames each after %u warm-up frames; scene time at %g "
        "fps\n",
        configs.size(), o.frames, o.warmup, kFps);
    std::printf(
        "wall     the whole Renderer::render call (host work, uploads, submissions, GPU waits; no "
        "readback)\n");
    std::fflush(stdout);

    auto writeResults = [&](const std::vector<ConfigResult>& results, bool say) -> engine::Status {
        for (const auto& [name, text] :
             {std::pair<std::string, std::string>{"frame.csv", summaryCsv(results)},
              {"frames.csv", framesCsv(results)},
              {"frame.json", json(results, o, dev.name)}}) {
            if (engine::Status s = writeFile(dir / name, text); !s) return s;
            if (say) std::printf("wrote %s\n", (dir / name).string().c_str());
        }
        return {};
    };
    std::vector<ConfigResult> results;
    ProgressLine progress("bench frame", std::uint64_t(configs.size()) * (o.warmup + o.frames));
    std::uint64_t done = 0;
    for (const Config& c : configs) {
        auto r = measure(**ctx, c, o, progress, done);
        if (!r) {
            progress.finish();
            return fail(r.error());
        }
        progress.note(fmt::format("{}: wall {:.1f} ms median, {:.1f} p95; GPU {:.1f} ms ({})",
                                  c.label(), r->wallMedian, r->wallP95, r->gpuMedian,
                                  topPasses(*r)));
        results.push_back(std::move(*r));
        // The results so far, so a long run stopped early keeps its finished configurations.
        if (engine::Status s = writeResults(results, false); !s) return fail(s.error());
    }
    const double seconds = progress.finish();

    printTable(results);
    if (engine::Status s = writeResults(results, true); !s) return fail(s.error());
    std::printf("chart: python3 tools/plot_frame.py %s/frame.json DIR  (%s in all)\n",
                dir.string().c_str(), formatDuration(seconds).c_str());
    if ((*ctx)->validationErrors() > 0) {
        std::fprintf(stderr, "vox: %u Vulkan validation error(s)\n", (*ctx)->validationErrors());
        return 1;
    }
    return 0;
}

}  // namespace

void addBenchFrameCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand("frame",
                                     "Frame time as a player sees it: wall ms per frame (median, "
                                     "p95), GPU ms per pass, rays, cache updates");
    auto o = std::make_shared<FrameBenchOptions>();
    cmd->add_option("--worlds", o->worlds, "Worlds (comma-separated)")->capture_default_str();
    cmd->add_option("--sizes", o->sizes, "Image sizes WIDTHxHEIGHT (comma-separated)")
        ->capture_default_str();
    cmd->add_option("--indirect-rows", o->indirect,
                    "Lighting rows: ReSTIR direct light plus this indirect light each (cache, "
                    "none; comma-separated)")
        ->capture_default_str();
    cmd->add_option("--cameras", o->cameras,
                    "still (the world's first camera) and/or moving (a looping path: "
                    "sandbox_orbit, dragon_city_avenue, "
                    "cornell_sway, else the world's own [path])")
        ->capture_default_str();
    cmd->add_option(
        "--paths", o->paths,
        "Moving-camera paths per world: WORLD=PATH,... (files or names in worlds/paths/)");
    cmd->add_option("--frames", o->frames, "Measured frames per configuration")
        ->capture_default_str()
        ->check(numberIn(kFrameCountRange));
    cmd->add_option("--warmup", o->warmup,
                    "Frames rendered before measuring (temporal history, cache)")
        ->capture_default_str()
        ->check(numberIn(kWarmupRange));
    cmd->add_option("-o,--output", o->output,
                    "Folder for frame.csv, frames.csv (per frame) and frame.json")
        ->capture_default_str();
    // The other knobs (e.g. --cache-rays) apply to every row; the rows set --method and --indirect.
    addLightingOptions(*cmd, o->lighting);
    cmd->callback([o, &exitCode] { exitCode = runFrameBench(*o); });
}

}  // namespace vox
