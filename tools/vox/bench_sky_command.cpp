// vox bench sky: the DVF sky term's costs (docs/PERFORMANCE.md). On a world and view:
//   - the masks' first build (every mask the view needs, from an empty table) against the
//     update after a single-voxel edit (only the directions through the edit re-traced), in
//     GPU ms of the DVF passes and in rays;
//   - the memory the view takes (slots held; the table is a fixed allocation);
//   - the frame with and without the sky term, once the masks are built.
// With --terrain N the world is a generated terrain of N x 96 x N voxels with the camera at the
// same place whatever N, for the memory-against-world-size figure.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "bench_median.h"
#include "bench_setup.h"
#include "commands.h"
#include "core/atomic_file.h"
#include "core/hash.h"
#include "gpu/context.h"
#include "number_options.h"
#include "render/renderer.h"
#include "world/generators.h"

namespace vox {

namespace {

struct SkyBenchOptions {
    std::string world = "sandbox";
    int terrain = 0;  // > 0: a generated N x 96 x N terrain instead of `world`
    std::string size = "256x256";
    int edits = 10;
    std::string output = "out/bench_sky.json";
};

double dvfMs(const engine::render::FrameResult& f) {
    return f.passMsOf("dvf.invalidate") + f.passMsOf("dvf.take_batch") + f.passMsOf("dvf.build");
}

engine::world::Scene terrainScene(int n) {
    using namespace engine::world;
    Scene scene;
    scene.name = "terrain_" + std::to_string(n);
    scene.grid = BrickGrid(glm::ivec3(n, 96, n));
    TerrainParams p;
    p.top = *scene.palette.add(Material{"grass", glm::vec3(0.22f, 0.42f, 0.12f)});
    p.soil = *scene.palette.add(Material{"dirt", glm::vec3(0.36f, 0.25f, 0.15f)});
    p.rock = *scene.palette.add(Material{"stone", glm::vec3(0.45f, 0.45f, 0.47f)});
    p.baseHeight = 40.0f;
    p.amplitude = 24.0f;
    p.seed = 3;
    generateTerrain(scene.grid, p);
    scene.cameras.push_back(
        CameraPreset{"view", {40.0f, 90.0f, 40.0f}, {128.0f, 40.0f, 128.0f}, 60.0f});
    scene.grid.clearDirty();
    return scene;
}

// The renderer, view and lighting every measurement of a run shares.
struct SkyBench {
    engine::world::Scene& scene;
    engine::render::Renderer& renderer;
    engine::render::FrameSettings frame;
    engine::lighting::LightingSettings lighting;  // ReSTIR, the default method, and the DVF sky
    engine::world::CameraPreset camera;

    engine::render::FrameResult render(const engine::lighting::LightingSettings& l) {
        return renderer.render(scene, camera, frame, l);
    }
    engine::render::FrameResult render() { return render(lighting); }
};

struct SkyResults {
    double buildMs = 0.0;
    std::uint64_t buildRays = 0;
    int buildFrames = 0;
    std::uint32_t slots = 0;  // the masks held after the first build
    // The last frame of the first build, then of the edits (the JSON's table size is its).
    engine::render::FrameResult last;
    std::vector<double> editMs, editRays, editMasks;
    double withSky = 0.0, without = 0.0, shadeMs = 0.0;
};

// 1. The first build: frames until the queue is empty.
void firstBuild(SkyBench& b, SkyResults& r) {
    engine::render::FrameResult& f = r.last;
    do {
        f = b.render();
        r.buildMs += dvfMs(f);
        r.buildRays += f.sky.tracedRays;
        ++r.buildFrames;
    } while ((f.sky.queued > 0 || r.buildFrames < 2) && r.buildFrames < 100);
    r.slots = f.sky.usedSlots;
}

// 2. Single-voxel edits on the visible surface: put a voxel on top of a surface and take it away.
void singleVoxelEdits(SkyBench& b, int edits, SkyResults& r) {
    const auto gbuffer = b.renderer.readback().gbuffer;
    engine::Rng rng(7);
    for (int i = 0; i < edits; ++i) {
        const auto& g = gbuffer[std::size_t(rng.uniformInt(0, int(gbuffer.size()) - 1))];
        if (g.voxel.w >= 6) {
            --i;
            continue;
        }
        glm::ivec3 n(0);
        n[g.voxel.w >> 1] = (g.voxel.w & 1) ? 1 : -1;
        const glm::ivec3 at = glm::ivec3(g.voxel) + n;
        if (!b.scene.grid.bounds().contains(at)) continue;
        const auto before = b.scene.grid.get(at);
        b.scene.grid.set(at, g.data.x);
        const engine::render::FrameResult& f = r.last = b.render();
        r.editMs.push_back(dvfMs(f));
        r.editRays.push_back(f.sky.tracedRays);
        r.editMasks.push_back(f.sky.tracedMasks);
        b.scene.grid.set(at, before);
        b.render();
    }
}

// 3. The frame with and without the sky term, masks built and nothing changing: first let
// the edits' re-traces drain.
void steadyFrames(SkyBench& b, SkyResults& r) {
    for (int i = 0; i < 100 && b.render().sky.queued > 0; ++i) {
    }
    auto steady = [&](engine::lighting::Sky sky, double& shadeMs) {
        engine::lighting::LightingSettings l = b.lighting;
        l.sky = sky;
        std::vector<double> total, shade;
        for (int i = 0; i < 6; ++i) {
            engine::render::FrameResult f = b.render(l);
            if (i < 2) continue;  // warm-up
            total.push_back(f.totalMs());
            shade.push_back(f.passMsOf("dvf.shade"));
        }
        shadeMs = median(shade);
        return median(total);
    };
    double unused = 0.0;
    r.withSky = steady(engine::lighting::Sky::Dvf, r.shadeMs);
    r.without = steady(engine::lighting::Sky::None, unused);
}

engine::Status writeJson(const std::filesystem::path& out, const engine::world::Scene& scene,
                         const engine::render::FrameSettings& frame, const SkyResults& r) {
    const std::uint32_t slots = r.slots;
    engine::AtomicFile jsonFile;
    if (engine::Status s = openOutputFile(jsonFile, out); !s) return s;
    jsonFile.stream() << "{\"world\": \"" << scene.name << "\", \"width\": " << frame.width
                      << ", \"height\": " << frame.height << ", \"masks\": " << slots
                      << ", \"mask_bytes\": " << slots * sizeof(shared::DvfSlot)
                      << ", \"table_bytes\": " << r.last.sky.tableBytes
                      << ", \"first_build_ms\": " << r.buildMs
                      << ", \"first_build_rays\": " << r.buildRays
                      << ", \"first_build_frames\": " << r.buildFrames
                      << ", \"edit_ms\": " << median(r.editMs)
                      << ", \"edit_rays\": " << median(r.editRays)
                      << ", \"edit_masks\": " << median(r.editMasks)
                      << ", \"frame_ms_sky\": " << r.withSky
                      << ", \"frame_ms_no_sky\": " << r.without << ", \"shade_ms\": " << r.shadeMs
                      << "}\n";
    return jsonFile.commit();
}

int runSkyBench(const SkyBenchOptions& o) {
    auto size = frameOfSize(o.size);
    if (!size) return fail(size.error());
    engine::world::Scene scene;
    if (o.terrain > 0) {
        scene = terrainScene(o.terrain);
    } else {
        auto loaded = loadWorld(o.world);
        if (!loaded) return fail(loaded.error());
        scene = std::move(*loaded);
    }
    auto ctx = createBenchGpu();
    if (!ctx) return fail(ctx.error());
    engine::render::Renderer renderer(**ctx);
    SkyBench b{scene, renderer, *size, {}, scene.camera()};
    b.lighting.sky = engine::lighting::Sky::Dvf;
    const engine::render::FrameSettings& frame = b.frame;
    SkyResults r;

    firstBuild(b, r);
    const std::uint32_t slots = r.slots;
    std::printf(
        "world %s, %dx%d view: %u masks held (%.1f KiB of %.1f MiB table), first build %.2f ms "
        "GPU, %llu rays "
        "over %d frames\n",
        scene.name.c_str(), frame.width, frame.height, slots,
        slots * sizeof(shared::DvfSlot) / 1024.0, r.last.sky.tableBytes / 1048576.0, r.buildMs,
        static_cast<unsigned long long>(r.buildRays), r.buildFrames);
    singleVoxelEdits(b, o.edits, r);
    std::printf(
        "single-voxel edit: %.3f ms GPU, %.0f rays, %.0f masks re-traced (medians of %zu); %.0fx "
        "fewer rays "
        "than the first build\n",
        median(r.editMs), median(r.editRays), median(r.editMasks), r.editMs.size(),
        r.buildRays / std::max(median(r.editRays), 1.0));
    steadyFrames(b, r);
    std::printf(
        "steady frame (restir): %.2f ms GPU with the DVF sky (dvf.shade %.2f ms), %.2f ms without: "
        "x%.2f\n",
        r.withSky, r.shadeMs, r.without, r.withSky / r.without);
    if (engine::Status s = writeJson(o.output, scene, frame, r); !s) return fail(s.error());
    std::printf("wrote    %s\n", std::filesystem::path(o.output).string().c_str());
    return 0;
}

}  // namespace

void addBenchSkyCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "sky", "DVF sky light: first build vs single-voxel edit, memory, frame cost");
    auto o = std::make_shared<SkyBenchOptions>();
    cmd->add_option("world", o->world, "World name or scene file")->capture_default_str();
    cmd->add_option("--terrain", o->terrain,
                    "Instead of a world: a generated N x 96 x N terrain, the same view for any N")
        ->check(numberIn(engine::wholeRange(0, 8192, "voxels")));
    cmd->add_option("--size", o->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--edits", o->edits, "Single-voxel edits to time")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 1000, "edits")));
    cmd->add_option("-o,--output", o->output, "JSON results file")->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runSkyBench(*o); });
}

}  // namespace vox
