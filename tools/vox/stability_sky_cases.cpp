// Sky light from discrete visibility fields (`--sky dvf`) under the same stresses: flicker of its
// sky term on a still camera, frames until an edit that opens a roof reaches a steady error
// against the brute-force sky term (`--sky reference`) of the opened room, and what the sealed,
// one-voxel-thin room of worlds/thin_wall.toml sees of the sky from inside (0 is right).
#include <algorithm>
#include <cstdio>
#include <fmt/format.h>

#include "commands.h"
#include "stability_bench.h"
#include "world/world_edits.h"

namespace vox {

namespace {

using engine::lighting::LightingSettings;
using engine::lighting::Sky;
using engine::render::Renderer;
using engine::world::Box;
using engine::world::Scene;

LightingSettings sky(Sky mode) {
    LightingSettings l;
    l.method = engine::lighting::Method::Uniform;  // the sky term is read alone
    l.sky = mode;
    return l;
}

std::vector<glm::vec4> skyTerm(StabilityContext& c, Renderer& r, Scene& scene,
                               const engine::world::CameraPreset& camera, Sky mode) {
    r.render(scene, camera, c.frame, sky(mode));
    return r.dvfSky().readSkyTerm();
}

engine::Status skyFlicker(StabilityContext& c) {
    for (const char* world : {"sandbox", "mountain"}) {
        auto scene = loadWorld(world);
        if (!scene) return scene.error();
        Renderer r(c.gpu);
        FlickerMeter meter(c.frame);
        for (int i = 0; i < 8; ++i) {
            std::vector<glm::vec4> img = skyTerm(c, r, *scene, scene->camera(), Sky::Dvf);
            if (i < 4) continue;  // the masks' first build spreads over a few frames
            meter.add(std::move(img));
        }
        const double f = meter.value();
        c.rows.push_back(
            fmt::format("| flicker: {} | restir + sky dvf (sky term) | {:.3f} |", world, f));
        std::printf("flicker %-12s dvf sky %.4f\n", world, f);
    }
    return {};
}

// The sealed room from inside: DVF and the brute-force rays both must see no sky.
void skySealedRoom(StabilityContext& c, Scene& room, const engine::world::CameraPreset& inside) {
    for (Sky mode : {Sky::Dvf, Sky::Reference}) {
        Renderer r(c.gpu);
        std::vector<glm::vec4> in;
        for (int i = 0; i < 4; ++i) in = skyTerm(c, r, room, inside, mode);
        float insideMax = 0.0f;
        for (const glm::vec4& p : in) insideMax = std::max({insideMax, p.x, p.y, p.z});
        const char* name = mode == Sky::Dvf ? "restir + sky dvf" : "restir + sky reference";
        c.rows.push_back(fmt::format(
            "| thin wall (1 voxel), sky | {} | largest sky term inside the sealed room: {:.3g} |",
            name, insideMax));
        std::printf("thin wall %-24s largest sky term inside %.3g\n", name, insideMax);
    }
}

// Response to an edit: the room's roof removed.
void skyRoofRemoved(StabilityContext& c, const Scene& room,
                    const engine::world::CameraPreset& inside) {
    const Box roof{{33, 25, 9}, {55, 26, 55}};
    Scene opened = room;
    fillBox(opened.grid, roof, engine::world::kEmpty);
    opened.grid.clearDirty();
    std::vector<glm::vec4> ref;
    {
        Renderer r(c.gpu);
        for (int i = 0; i < 16; ++i) ref = skyTerm(c, r, opened, inside, Sky::Reference);
    }
    Renderer r(c.gpu);
    Scene live = room;
    for (int i = 0; i < 4; ++i) skyTerm(c, r, live, inside, Sky::Dvf);
    fillBox(live.grid, roof, engine::world::kEmpty);
    std::vector<double> errors;
    for (int i = 0; i < 12; ++i)
        errors.push_back(maeOf(skyTerm(c, r, live, inside, Sky::Dvf), ref, c.frame));
    addResponse(c,
                {"roof removed", "restir + sky dvf (sky term)", "roof removed",
                 "restir + sky dvf (sky term vs brute-force sky rays)", "dvf sky"},
                errors, fmt::format("; reference mean {:.3e}", meanRadiance(ref)));
}

}  // namespace

engine::Status skyCases(StabilityContext& c) {
    if (engine::Status s = skyFlicker(c); !s) return s;
    auto thinWall = loadThinWall();
    if (!thinWall) return thinWall.error();
    thinWall->objects.clear();  // the room alone
    const engine::world::CameraPreset inside = thinWall->camera("inside");
    skySealedRoom(c, *thinWall, inside);
    skyRoofRemoved(c, *thinWall, inside);
    return {};
}

}  // namespace vox
