// vox bench cache: how the irradiance cache scales (issue 4, "Scaling"), all in one run so the
// figures compare as ratios on a drifting machine:
//   1. divide-and-win: the static set's visibility update re-tracing only the dynamic grid
//      against re-tracing both worlds, frames interleaved (the paper reports 2.7-5.9x);
//   2. cost against the number of camera-visible voxels (image sizes of one view);
//   3. memory and update time against world size: the same view in ever larger worlds.
#include <algorithm>
#include <cstdio>
#include <fmt/format.h>
#include <fstream>

#include "bench_median.h"
#include "bench_setup.h"
#include "commands.h"
#include "core/atomic_file.h"
#include "gpu/context.h"
#include "number_options.h"
#include "render/renderer.h"
#include "world/world_edits.h"

namespace vox {

namespace {

struct CacheBenchOptions {
    std::string worlds = "dragon_city,factory,thin_wall";
    std::string size = "128x96";
    std::uint32_t frames = 12;
    std::string output = "out/bench_cache.json";
};

double cacheMs(const engine::render::FrameResult& r) {
    double ms = 0.0;
    for (const auto& [name, t] : r.passMs)
        if (name.rfind("cache.", 0) == 0) ms += t;
    return ms;
}

engine::lighting::LightingSettings cacheLighting() {
    engine::lighting::LightingSettings l;
    l.method = engine::lighting::Method::Preview;  // the direct term is not what is measured
    l.indirect = engine::lighting::Indirect::Cache;
    l.cache.rayBudget =
        0;  // the cost of updating every visible entry, which the budget caps (vox bench frame)
    return l;
}

// Renders `frames` frames of a still view with the cache; returns the last frame and the median
// of the cache's per-frame milliseconds, leaving out the first two frames and the one-off static
// trace.
std::pair<engine::render::FrameResult, double> steadyCacheMs(engine::gpu::Context& ctx,
                                                             engine::world::Scene& scene,
                                                             engine::render::FrameSettings frame,
                                                             std::uint32_t frames) {
    engine::render::Renderer r(ctx);
    std::vector<double> ms;
    engine::render::FrameResult last;
    for (std::uint32_t i = 0; i < frames; ++i) {
        last = r.render(scene, scene.camera(), frame, cacheLighting());
        if (i >= 2) ms.push_back(cacheMs(last) - last.passMsOf("cache.trace_static"));
    }
    return {last, median(ms)};
}

// A street of buildings along x in a world of `size`, closed by a wall at x = 100: the camera
// sees the same voxels whatever the size; the rest of the world holds more of the same, out of
// view.
engine::world::Scene streetWorld(glm::ivec3 size) {
    using namespace engine::world;
    Scene scene;
    scene.name = fmt::format("street {}x{}x{}", size.x, size.y, size.z);
    scene.grid = BrickGrid(size);
    auto white = scene.palette.add(Material{"white", glm::vec3(0.75f)});
    auto brick = scene.palette.add(Material{"brick", glm::vec3(0.7f, 0.3f, 0.2f)});
    fillBox(scene.grid, Box{{0, 0, 0}, {size.x, 4, size.z}}, *white);
    for (int x = 0; x + 12 <= size.x; x += 16) {
        fillBox(scene.grid, Box{{x, 4, 4}, {x + 12, 24 + (x / 16 % 3) * 6, 20}}, *brick);
        fillBox(scene.grid, Box{{x, 4, 44}, {x + 12, 20 + (x / 16 % 2) * 8, 60}}, *white);
    }
    fillBox(scene.grid, Box{{100, 4, 0}, {104, 40, 64}},
            *brick);  // the end of the view; more world behind it
    scene.cameras.push_back(
        CameraPreset{"street", {2.0f, 14.0f, 32.0f}, {60.0f, 8.0f, 32.0f}, 70.0f});
    scene.grid.clearDirty();
    return scene;
}

// The three parts share one frame: each sets the image size it measures at, and the scene time
// the first part ends at carries on into the others.

// 1. Divide-and-win on worlds with dynamic objects, the two modes in alternate frames.
engine::Status divideAndWin(engine::gpu::Context& ctx, const CacheBenchOptions& o, glm::uvec2 size,
                            engine::render::FrameSettings& frame, std::string& json) {
    std::printf(
        "| static entries' visibility update | dynamic-only re-trace | full re-trace | speed-up "
        "|\n|---|---|---|---|\n");
    json += "  \"divide_and_win\": [";
    std::string worlds = o.worlds + ",";
    for (std::size_t at = 0, comma; (comma = worlds.find(',', at)) != std::string::npos;
         at = comma + 1) {
        const std::string name = worlds.substr(at, comma - at);
        if (name.empty()) continue;
        auto scene = loadWorld(name);
        if (!scene) return scene.error();
        frame.width = size.x;
        frame.height = size.y;
        engine::render::Renderer divide(ctx), full(ctx);
        auto lDivide = cacheLighting(), lFull = cacheLighting();
        lFull.cache.fullRetrace = true;
        std::vector<double> tDivide, tFull;
        engine::render::FrameResult last;
        for (std::uint32_t i = 0; i < o.frames + 2; ++i) {
            frame.timeSeconds = i / 30.0;
            last = divide.render(*scene, scene->camera(), frame, lDivide);
            auto f = full.render(*scene, scene->camera(), frame, lFull);
            if (i < 2) continue;  // the first frames trace the static rays
            tDivide.push_back(last.passMsOf("cache.visibility_static"));
            tFull.push_back(f.passMsOf("cache.visibility_static"));
        }
        const double a = median(tDivide), b = median(tFull);
        std::printf(
            "| %s: %u static entries (%u visible static, %u visible dynamic voxels) | %.2f ms | "
            "%.2f ms | %.2fx |\n",
            scene->name.c_str(), last.cache.updated - last.cache.dynamicEntries,
            last.cache.visibleStatic, last.cache.visibleDynamic, a, b, b / a);
        json += fmt::format(
            "{}{{\"world\": \"{}\", \"static_entries\": {}, \"dynamic_ms\": {:.3f}, "
            "\"full_ms\": {:.3f}, \"speedup\": {:.3f}}}",
            at ? ", " : "", scene->name, last.cache.updated - last.cache.dynamicEntries, a, b,
            b / a);
    }
    json += "],\n";
    return {};
}

// 2. Cost against the number of visible voxels: one view at growing image sizes.
void visibleVoxelsCost(engine::gpu::Context& ctx, const CacheBenchOptions& o,
                       engine::render::FrameSettings& frame, std::string& json) {
    engine::world::Scene scene = streetWorld({256, 64, 64});
    std::printf(
        "\n| image | visible voxels | cache entries updated | cache ms/frame | ms per 1000 entries "
        "|\n|---|---|---|---|---|\n");
    json += "  \"visible\": [";
    bool first = true;
    for (std::uint32_t w : {32u, 64u, 96u, 128u}) {
        frame.width = w;
        frame.height = w * 3 / 4;
        auto [last, m] = steadyCacheMs(ctx, scene, frame, o.frames);
        std::printf("| %ux%u | %u | %u | %.2f | %.2f |\n", frame.width, frame.height,
                    last.cache.visibleStatic, last.cache.updated, m,
                    1000.0 * m / std::max(1u, last.cache.updated));
        json += fmt::format("{}{{\"width\": {}, \"visible\": {}, \"ms\": {:.3f}}}",
                            first ? "" : ", ", frame.width, last.cache.visibleStatic, m);
        first = false;
    }
    json += "],\n";
}

// 3. The same view in larger worlds: cache memory and update time must not follow.
void worldSizeCost(engine::gpu::Context& ctx, const CacheBenchOptions& o, glm::uvec2 size,
                   engine::render::FrameSettings& frame, std::string& json) {
    std::printf(
        "\n| world | world bricks | cache entries | cache MiB | cache ms/frame "
        "|\n|---|---|---|---|---|\n");
    json += "  \"world_size\": [";
    bool first = true;
    frame.width = size.x;
    frame.height = size.y;
    for (int length : {128, 256, 512, 1024}) {
        engine::world::Scene scene = streetWorld({length, 64, 64});
        auto [last, m] = steadyCacheMs(ctx, scene, frame, o.frames);
        std::printf("| %s | %u | %u | %.2f | %.2f |\n", scene.name.c_str(), scene.grid.liveBricks(),
                    last.cache.entries, double(last.cache.bytes) / 1048576.0, m);
        json += fmt::format("{}{{\"length\": {}, \"entries\": {}, \"bytes\": {}, \"ms\": {:.3f}}}",
                            first ? "" : ", ", length, last.cache.entries, last.cache.bytes, m);
        first = false;
    }
    json += "]\n}\n";
}

int runCacheBench(const CacheBenchOptions& o) {
    auto size = parseSize(o.size, "--size");
    if (!size) return fail(size.error());
    auto ctx = createBenchGpu();
    if (!ctx) return fail(ctx.error());
    std::string json = "{\n";
    engine::render::FrameSettings frame;
    if (engine::Status s = divideAndWin(**ctx, o, *size, frame, json); !s) return fail(s.error());
    visibleVoxelsCost(**ctx, o, frame, json);
    worldSizeCost(**ctx, o, *size, frame, json);
    std::filesystem::create_directories(std::filesystem::path(o.output).parent_path());
    if (engine::Status s = engine::writeFileAtomically(o.output, json); !s) return fail(s.error());
    std::printf("\nwrote %s\n", o.output.c_str());
    return 0;
}

}  // namespace

void addBenchCacheCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "cache",
        "Irradiance cache: divide-and-win speed-up, cost vs visible voxels, memory vs world size");
    auto o = std::make_shared<CacheBenchOptions>();
    cmd->add_option("--worlds", o->worlds,
                    "Worlds with dynamic objects for the divide-and-win figure (comma-separated)")
        ->capture_default_str();
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--frames", o->frames,
                    "Frames per measurement (medians; the first two are skipped)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(4, 1000, "frames")));
    cmd->add_option("-o,--output", o->output, "JSON results")->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runCacheBench(*o); });
}

}  // namespace vox
