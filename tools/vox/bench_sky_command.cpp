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

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

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
    scene.cameras.push_back(CameraPreset{"view", {40.0f, 90.0f, 40.0f}, {128.0f, 40.0f, 128.0f}, 60.0f});
    scene.grid.clearDirty();
    return scene;
}

int runSkyBench(const SkyBenchOptions& o) {
    auto size = parseSize(o.size, "--size");
    if (!size) return fail(size.error());
    engine::world::Scene scene;
    if (o.terrain > 0) {
        scene = terrainScene(o.terrain);
    } else {
        auto loaded = loadWorld(o.world);
        if (!loaded) return fail(loaded.error());
        scene = std::move(*loaded);
    }
    auto ctx = engine::gpu::Context::create({});
    if (!ctx) return fail(ctx.error());
    engine::render::Renderer renderer(**ctx);
    engine::render::FrameSettings frame;
    frame.width = size->x;
    frame.height = size->y;
    engine::lighting::LightingSettings lighting;  // ReSTIR, the default method
    lighting.sky = engine::lighting::Sky::Dvf;
    const engine::world::CameraPreset camera = scene.camera();

    // 1. The first build: frames until the queue is empty.
    double buildMs = 0.0;
    std::uint64_t buildRays = 0;
    int frames = 0;
    engine::render::FrameResult f;
    do {
        f = renderer.render(scene, camera, frame, lighting);
        buildMs += dvfMs(f);
        buildRays += f.sky.tracedRays;
        ++frames;
    } while ((f.sky.queued > 0 || frames < 2) && frames < 100);
    const std::uint32_t slots = f.sky.usedSlots;
    std::printf("world %s, %dx%d view: %u masks held (%.1f KiB of %.1f MiB table), first build %.2f ms GPU, %llu rays "
                "over %d frames\n",
                scene.name.c_str(), size->x, size->y, slots, slots * sizeof(shared::DvfSlot) / 1024.0,
                f.sky.tableBytes / 1048576.0, buildMs, static_cast<unsigned long long>(buildRays), frames);

    // 2. Single-voxel edits on the visible surface: put a voxel on top of a surface and take it away.
    const auto gbuffer = renderer.readback().gbuffer;
    engine::Rng rng(7);
    std::vector<double> editMs, editRays, editMasks;
    for (int i = 0; i < o.edits; ++i) {
        const auto& g = gbuffer[std::size_t(rng.uniformInt(0, int(gbuffer.size()) - 1))];
        if (g.voxel.w >= 6) {
            --i;
            continue;
        }
        glm::ivec3 n(0);
        n[g.voxel.w >> 1] = (g.voxel.w & 1) ? 1 : -1;
        const glm::ivec3 at = glm::ivec3(g.voxel) + n;
        if (!scene.grid.bounds().contains(at)) continue;
        const auto before = scene.grid.get(at);
        scene.grid.set(at, g.data.x);
        f = renderer.render(scene, camera, frame, lighting);
        editMs.push_back(dvfMs(f));
        editRays.push_back(f.sky.tracedRays);
        editMasks.push_back(f.sky.tracedMasks);
        scene.grid.set(at, before);
        renderer.render(scene, camera, frame, lighting);
    }
    std::printf("single-voxel edit: %.3f ms GPU, %.0f rays, %.0f masks re-traced (medians of %zu); %.0fx fewer rays "
                "than the first build\n",
                median(editMs), median(editRays), median(editMasks), editMs.size(), buildRays / std::max(median(editRays), 1.0));

    // 3. The frame with and without the sky term, masks built and nothing changing: first let
    // the edits' re-traces drain.
    for (int i = 0; i < 100 && renderer.render(scene, camera, frame, lighting).sky.queued > 0; ++i) {
    }
    auto steady = [&](engine::lighting::Sky sky, double& shadeMs) {
        engine::lighting::LightingSettings l = lighting;
        l.sky = sky;
        std::vector<double> total, shade;
        for (int i = 0; i < 6; ++i) {
            engine::render::FrameResult r = renderer.render(scene, camera, frame, l);
            if (i < 2) continue;  // warm-up
            total.push_back(r.totalMs());
            shade.push_back(r.passMsOf("dvf.shade"));
        }
        shadeMs = median(shade);
        return median(total);
    };
    double shadeMs = 0.0, unused = 0.0;
    const double withSky = steady(engine::lighting::Sky::Dvf, shadeMs);
    const double without = steady(engine::lighting::Sky::None, unused);
    std::printf("steady frame (restir): %.2f ms GPU with the DVF sky (dvf.shade %.2f ms), %.2f ms without: x%.2f\n", withSky,
                shadeMs, without, withSky / without);

    std::filesystem::path out(o.output);
    std::error_code ec;
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path(), ec);
    engine::AtomicFile jsonFile;
    if (engine::Status s = jsonFile.open(out); !s) return fail(s.error());
    jsonFile.stream() << "{\"world\": \"" << scene.name << "\", \"width\": " << size->x << ", \"height\": " << size->y
                      << ", \"masks\": " << slots << ", \"mask_bytes\": " << slots * sizeof(shared::DvfSlot)
                      << ", \"table_bytes\": " << f.sky.tableBytes << ", \"first_build_ms\": " << buildMs
                      << ", \"first_build_rays\": " << buildRays << ", \"first_build_frames\": " << frames
                      << ", \"edit_ms\": " << median(editMs) << ", \"edit_rays\": " << median(editRays)
                      << ", \"edit_masks\": " << median(editMasks) << ", \"frame_ms_sky\": " << withSky
                      << ", \"frame_ms_no_sky\": " << without << ", \"shade_ms\": " << shadeMs << "}\n";
    if (engine::Status s = jsonFile.commit(); !s) return fail(s.error());
    std::printf("wrote    %s\n", out.string().c_str());
    return 0;
}

}  // namespace

void addBenchSkyCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand("sky", "DVF sky light: first build vs single-voxel edit, memory, frame cost");
    auto o = std::make_shared<SkyBenchOptions>();
    cmd->add_option("world", o->world, "World name or scene file")->capture_default_str();
    cmd->add_option("--terrain", o->terrain, "Instead of a world: a generated N x 96 x N terrain, the same view for any N")
        ->check(numberIn(engine::wholeRange(0, 8192, "voxels")));
    cmd->add_option("--size", o->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--edits", o->edits, "Single-voxel edits to time")->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 1000, "edits")));
    cmd->add_option("-o,--output", o->output, "JSON results file")->capture_default_str();
    cmd->callback([o, &exitCode] { exitCode = runSkyBench(*o); });
}

}  // namespace vox
