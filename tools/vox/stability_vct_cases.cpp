// Voxel cone tracing (`--indirect vct`) under the same stresses as the cache: flicker of its
// indirect term on a still camera, frames to recover after an edit and when an object starts
// moving (its indirect term against the path tracer's one-bounce indirect light), and its leak
// through the one-voxel walls of worlds/thin_wall.toml, with the leak mitigation on and off.
#include <algorithm>
#include <cstdio>
#include <fmt/format.h>

#include "commands.h"
#include "stability_bench.h"
#include "sweep_runner.h"
#include "world/world_edits.h"

namespace vox {

namespace {

using engine::lighting::LightingSettings;
using engine::render::FrameSettings;
using engine::render::Renderer;
using engine::world::Box;
using engine::world::Scene;

LightingSettings vct(bool mitigation) {
    LightingSettings l;
    l.indirect = engine::lighting::Indirect::Vct;
    l.vct.leakMitigation = mitigation;
    return l;
}

engine::Status vctFlicker(StabilityContext& c) {
    for (const std::string& world : kFlickerWorlds) {
        auto scene = loadWorld(world);
        if (!scene) return scene.error();
        Renderer r(c.gpu);
        FlickerMeter meter(c.frame);
        for (int i = 0; i < 6; ++i) {
            r.render(*scene, scene->camera(), c.frame, vct(true));
            meter.add(r.readback().indirect);
        }
        const double f = meter.value();
        c.rows.push_back(
            fmt::format("| flicker: {} | restir + vct (indirect term) | {:.3f} |", world, f));
        std::printf("flicker %-12s vct indirect %.4f\n", world.c_str(), f);
    }
    return {};
}

// The cones' indirect term against the path tracer's (one bounce minus direct light).
engine::Result<std::vector<glm::vec4>> indirectReference(StabilityContext& c, Scene scene,
                                                         const std::string& name) {
    const engine::world::CameraPreset camera = scene.camera();
    auto direct = cachedReference(c.gpu, scene, camera, c.frame, 256, 0, c.cache, name);
    if (!direct) return direct.error();
    auto bounce = cachedReference(c.gpu, scene, camera, c.frame, 256, 1, c.cache, name);
    if (!bounce) return bounce.error();
    for (std::size_t p = 0; p < direct->size(); ++p)
        (*bounce)[p] = glm::max((*bounce)[p] - (*direct)[p], glm::vec4(0.0f));
    return bounce;
}

// Response to an edit: a wall of the Cornell box removed.
engine::Status vctWallRemoved(StabilityContext& c) {
    auto cornell = loadWorld("cornell");
    if (!cornell) return cornell.error();
    cornell->grid.clearDirty();
    auto edit = [](Scene& s) {
        fillBox(s.grid, Box{{68, 8, 148}, {148, 168, 228}}, engine::world::kEmpty);
    };
    Scene edited = *cornell;
    edit(edited);
    edited.grid.clearDirty();
    auto ref = indirectReference(c, edited, "wall removed");
    if (!ref) return ref.error();
    Renderer r(c.gpu);
    Scene live = *cornell;
    for (int i = 0; i < 4; ++i) r.render(live, live.camera(), c.frame, vct(true));
    edit(live);
    std::vector<double> errors;
    for (int i = 0; i < 16; ++i) {
        r.render(live, live.camera(), c.frame, vct(true));
        errors.push_back(maeOf(r.readback().indirect, *ref, c.frame));
    }
    addResponse(c,
                {"wall removed", "restir + vct (indirect term)", "wall removed",
                 "restir + vct (indirect term vs 1-bounce indirect)", "vct"},
                errors);
    return {};
}

// A dynamic object starts moving (the fast crate, as for the cache).
engine::Status vctMovingObject(StabilityContext& c, const Scene& thinWall) {
    const Scene fast = fastCrate(thinWall, false);
    MovingRun run =
        movingRun(c, "fast object", fast, fast.camera("outside"), vct(true), true, 16, 32);
    addResponse(c,
                {"object starts moving", "restir + vct (indirect term)",
                 "dynamic object starts moving (3.7 voxels/frame)",
                 "restir + vct (indirect term vs 1-bounce indirect)", "vct"},
                run.mae,
                fmt::format(", largest {:.3e}", *std::max_element(run.mae.begin(), run.mae.end())));
    return {};
}

// The leak: the sealed room's inside (the path tracer and the cache see 0 there), against
// the outside's mean, at t = 2.5 s as for the cache.
engine::Status vctLeak(StabilityContext& c, Scene& thinWall) {
    FrameSettings f = c.frame;
    f.timeSeconds = 2.5;
    for (bool mitigation : {true, false}) {
        Renderer r(c.gpu);
        r.render(thinWall, thinWall.camera("outside"), f, vct(mitigation));
        const std::vector<glm::vec4> outdoor = r.readback().indirect;
        r.render(thinWall, thinWall.camera("inside"), f, vct(mitigation));
        const std::vector<glm::vec4> in = r.readback().indirect;
        float insideMax = 0.0f;
        for (const glm::vec4& p : in) insideMax = std::max({insideMax, p.x, p.y, p.z});
        const double inMean = meanRadiance(in), outMean = meanRadiance(outdoor);
        c.rows.push_back(fmt::format(
            "| thin wall (1 voxel), indirect | restir + vct, leak mitigation {} | mean indirect "
            "inside the sealed room: {:.3g} = {:.1f} % of the outside's mean {:.3g} (largest "
            "inside {:.3g}) |",
            mitigation ? "on" : "off", inMean, 100.0 * inMean / outMean, outMean, insideMax));
        std::printf(
            "thin wall vct (mitigation %s): inside mean %.3g (%.1f %% of outside %.3g), max "
            "%.3g\n",
            mitigation ? "on" : "off", inMean, 100.0 * inMean / outMean, outMean, insideMax);
    }
    return {};
}

}  // namespace

engine::Status vctCases(StabilityContext& c) {
    if (engine::Status s = vctFlicker(c); !s) return s;
    if (engine::Status s = vctWallRemoved(c); !s) return s;
    auto thinWall = loadThinWall();
    if (!thinWall) return thinWall.error();
    if (engine::Status s = vctMovingObject(c, *thinWall); !s) return s;
    return vctLeak(c, *thinWall);
}

}  // namespace vox
