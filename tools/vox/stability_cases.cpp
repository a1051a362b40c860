// vox bench stability's cases for ReSTIR and the irradiance cache, in the table's order: flicker
// on a still camera, the response to edits and to a dynamic object that starts moving, then the
// known failure cases of the thesis and the literature.
#include <algorithm>
#include <cstdio>
#include <fmt/format.h>

#include "commands.h"
#include "core/atomic_file.h"
#include "io/image_io.h"
#include "stability_bench.h"
#include "sweep_runner.h"
#include "world/world_edits.h"

namespace vox {

namespace {

using engine::lighting::LightingSettings;
using engine::lighting::Method;
using engine::render::FrameSettings;
using engine::render::Renderer;
using engine::world::Box;
using engine::world::Scene;

// 1. Flicker on a still camera, relative to an unbiased 16-sample estimate's own flicker.
engine::Status flickerCases(StabilityContext& c) {
    for (const std::string& world : kFlickerWorlds) {
        auto scene = loadWorld(world);
        if (!scene) return scene.error();
        LightingSettings ref;
        ref.method = Method::Reference;
        ref.referenceFilter =
            engine::lighting::ReferenceFilter::PixelCentre;  // the pixel the other methods shade
        ref.samplesPerFrame = 16;
        double base = flicker(c, *scene, ref, 1, 6, true);
        c.rows.push_back(fmt::format("| flicker: {} | reference 16 spp | {:.3f} (the yardstick) |",
                                     world, base));
        std::printf("flicker %-12s reference16 %.4f\n", world.c_str(), base);
        for (const char* method : {"restir", "restir-unbiased", "ris", "uniform"}) {
            double f = flicker(c, *scene, methodSettings(method), 12, 6, false);
            c.rows.push_back(fmt::format("| flicker: {} | {} | {:.3f} = {:.2f}x the reference's |",
                                         world, method, f, f / base));
            std::printf("flicker %-12s %-16s %.4f (%.2fx)\n", world.c_str(), method, f, f / base);
        }
    }
    return {};
}

// An edit of the Cornell box: `box` filled with material `to` (empty: cleared), starting from
// the box with `box` filled with `from` (empty: as it is).
struct CornellEdit {
    const char* name;
    Box box;
    const char* from;
    const char* to;
};
const Box kHalfLight{{72, 256, 72}, {136, 264, 200}};
const Box kLeftWall{{68, 8, 148}, {148, 168, 228}};
const CornellEdit kCornellEdits[] = {
    {"emitter switched off", kHalfLight, "", "white"},
    {"emitter switched on", kHalfLight, "white", "light"},
    {"wall removed", kLeftWall, "", ""},
};

// 2. Response after edits in the Cornell box.
engine::Status editCases(StabilityContext& c) {
    auto cornell = loadWorld("cornell");
    if (!cornell) return cornell.error();
    cornell->grid.clearDirty();
    auto material = [&](const char* name) {
        return *name ? *cornell->palette.find(name) : engine::world::kEmpty;
    };
    for (const CornellEdit& e : kCornellEdits) {
        Scene start = *cornell;
        if (*e.from) {
            fillBox(start.grid, e.box, material(e.from));
            start.grid.clearDirty();
        }
        const auto to = material(e.to);
        response(c, e.name, start, [&](Scene& s) { fillBox(s.grid, e.box, to); });
    }
    return {};
}

// A run's response curve and its row.
void addMovingRow(StabilityContext& c, const char* method, const MovingRun& run) {
    for (std::size_t i = 0; i < run.mae.size(); ++i)
        c.curves << fmt::format("{},{},{},{}\n", "object starts moving", method, i + 1, run.mae[i]);
    auto [frames, steady] = framesToSteady(run.mae);
    c.rows.push_back(fmt::format(
        "| response: dynamic object starts moving (3.7 voxels/frame) | {} | {} frame(s) to within "
        "10 % of steady state (steady MAE {:.3e}, first frame {:.3e}, largest {:.3e}) |",
        method, frames, steady, run.mae.front(),
        *std::max_element(run.mae.begin(), run.mae.end())));
    std::printf("%-28s %-52s recovered after %d frame(s); steady MAE %.3e, first frame %.3e\n",
                "object starts moving", method, frames, steady, run.mae.front());
}

// (d) A dynamic object starts moving: the fast crate of the thin-wall world, parked for 16
// frames, then off along its path; against each frame's own reference. ReSTIR alone: the
// image against the direct-light reference; with the cache: its indirect term against the
// path tracer's one-bounce indirect light (the cache's run is reused for the ghosting case).
engine::Status movingObjectCase(StabilityContext& c) {
    auto thinWall = loadThinWall();
    if (!thinWall) return thinWall.error();
    const Scene fast = fastCrate(*thinWall, false);
    const auto camera = fast.camera("outside");
    c.fastCacheRun = movingRun(c, "fast object", fast, camera, cacheLighting(5), true, 16, 32);
    MovingRun direct = movingRun(c, "fast object", fast, camera, LightingSettings{}, false, 16, 32);
    addMovingRow(c, "restir (image vs direct reference)", direct);
    addMovingRow(c, "restir + cache (indirect term vs 1-bounce indirect)", *c.fastCacheRun);
    return {};
}

// 3. An emitter seen at a grazing angle: a lamp lying on a floor; area mode's face choice by
// solid angle at the face centre is poor right next to it (fireflies).
engine::Status grazingEmitterCase(StabilityContext& c) {
    Scene s = simpleScene({64, 32, 64});
    fillBox(s.grid, Box{{0, 0, 0}, {64, 2, 64}}, 1);
    s.grid.set({32, 2, 32}, 2);
    s.cameras.push_back({"low", {32.0f, 14.0f, 6.0f}, {32.0f, 2.0f, 32.0f}, 60.0f});
    s.grid.clearDirty();
    auto ref = cachedReference(c.gpu, s, s.camera(), c.frame, 2048, 0, c.cache, "grazing");
    for (bool area : {true, false}) {
        LightingSettings l;
        l.area = area;
        Renderer r(c.gpu);
        for (int i = 0; i < 12; ++i) r.render(s, s.camera(), c.frame, l);
        std::vector<glm::vec4> img = r.readback().radiance;
        int fireflies = 0;
        for (std::size_t i = 0; i < img.size(); ++i) {
            float a = img[i].x + img[i].y + img[i].z, b = (*ref)[i].x + (*ref)[i].y + (*ref)[i].z;
            fireflies += a > 4.0f * b + 0.05f;
        }
        double err = maeOf(img, *ref, c.frame);
        c.rows.push_back(fmt::format(
            "| grazing emitter | restir {} | MAE {:.3e}, {} firefly pixel(s) (> 4x reference) of "
            "{} |",
            area ? "area" : "point", err, fireflies, img.size()));
        std::printf("grazing emitter restir %-5s MAE %.3e fireflies %d\n", area ? "area" : "point",
                    err, fireflies);
    }
    return {};
}

// Two rooms side by side, a one-voxel wall between them, a lamp in the west one.
Scene twoRooms() {
    Scene s = simpleScene({64, 32, 32});
    fillBox(s.grid, Box{{0, 0, 0}, {64, 2, 32}}, 1);
    fillBox(s.grid, Box{{32, 2, 0}, {33, 32, 32}}, 1);
    s.grid.set({12, 5, 16}, 2);
    s.cameras.push_back({"above", {32.0f, 70.0f, 16.0f}, {32.0f, 0.0f, 16.01f}, 50.0f});
    return s;
}

// Thin walls: a one-voxel wall between a lit and a dark room must not leak direct light.
engine::Status thinWallDirectCase(StabilityContext& c) {
    Scene s = twoRooms();
    s.grid.clearDirty();
    for (const char* method : {"restir", "reference"}) {
        LightingSettings l;
        if (std::string(method) == "reference") l.method = Method::Reference;
        Renderer r(c.gpu);
        for (int i = 0; i < 8; ++i) r.render(s, s.camera(), c.frame, l);
        auto img = r.readback();
        float leak = 0.0f;
        for (std::size_t i = 0; i < img.gbuffer.size(); ++i) {
            if (img.gbuffer[i].voxel.w == int(shared::FACE_POS_Y) && img.gbuffer[i].voxel.x > 32)
                leak = std::max(leak, img.radiance[i].x + img.radiance[i].y + img.radiance[i].z);
        }
        c.rows.push_back(fmt::format(
            "| thin wall (1 voxel), direct light | {} | largest radiance behind the wall: {:.3g} |",
            method, leak));
        std::printf("thin wall %-10s leak %.3g\n", method, leak);
    }
    return {};
}

// Lights removed while reservoirs point at them.
engine::Status removedLightCase(StabilityContext& c) {
    Scene s = twoRooms();
    s.grid.set({50, 5, 16}, 2);
    s.grid.clearDirty();
    Renderer r(c.gpu);
    LightingSettings l;
    for (int i = 0; i < 8; ++i) r.render(s, s.camera(), c.frame, l);
    s.grid.set({12, 5, 16}, engine::world::kEmpty);
    r.render(s, s.camera(), c.frame, l);
    auto img = r.readback();
    int lit = 0;
    for (std::size_t i = 0; i < img.gbuffer.size(); ++i) {
        if (img.gbuffer[i].voxel.w == int(shared::FACE_POS_Y) && img.gbuffer[i].voxel.x < 32)
            lit += img.radiance[i].x + img.radiance[i].y + img.radiance[i].z > 0.0f;
    }
    c.rows.push_back(fmt::format(
        "| light removed under live reservoirs | restir | {} pixel(s) still lit by it in the next "
        "frame |",
        lit));
    std::printf("removed light: %d pixel(s) lit in the next frame\n", lit);
    return {};
}

// The largest of the colour channels over an image.
float largest(const std::vector<glm::vec4>& img) {
    float m = 0.0f;
    for (const glm::vec4& p : img) m = std::max({m, p.x, p.y, p.z});
    return m;
}

// Thin walls with the irradiance cache: the sealed one-voxel room of worlds/thin_wall.toml
// in bright sun beside a lamp, the crate pressed against its west wall (t = 2.5 s). Both
// views every frame, so entries inside and outside the wall are live neighbours (the
// filter and the interpolation are where a leak would come from). Inside, the path
// tracer sees nothing at all.
engine::Status thinWallCacheCase(StabilityContext& c) {
    auto thinWall = loadThinWall();
    if (!thinWall) return thinWall.error();
    const auto inside = thinWall->camera("inside"), outside = thinWall->camera("outside");
    LightingSettings l;
    l.indirect = engine::lighting::Indirect::Cache;
    Renderer r(c.gpu);
    FrameSettings f = c.frame;
    f.timeSeconds = 2.5;
    Scene s = *thinWall;
    for (int i = 0; i < 32; ++i) {
        r.render(s, outside, f, l);
        r.render(s, inside, f, l);
    }
    std::vector<glm::vec4> in = r.readback().indirect;
    r.render(s, outside, f, l);
    std::vector<glm::vec4> outdoor = r.readback().indirect;
    const float insideMax = largest(in), outsideMax = largest(outdoor);
    double outsideMean = 0.0;
    for (const glm::vec4& p : outdoor) outsideMean += (p.x + p.y + p.z) / 3.0;
    outsideMean /= double(outdoor.size());
    LightingSettings ref;
    ref.method = Method::Reference;
    ref.bounces = 3;
    ref.samplesPerFrame = 16;
    Renderer rr(c.gpu);
    for (int i = 0; i < 16; ++i) rr.render(s, inside, f, ref);
    const float refInside = largest(rr.readback().radiance);
    c.rows.push_back(fmt::format(
        "| thin wall (1 voxel), indirect | restir + cache | largest indirect inside the sealed "
        "room: {:.3g} (outside: mean {:.3g}, largest {:.3g}) |",
        insideMax, outsideMean, outsideMax));
    c.rows.push_back(fmt::format(
        "| thin wall (1 voxel), indirect | reference, 3 bounces, 256 spp | largest radiance "
        "inside: {:.3g} |",
        refInside));
    std::printf(
        "thin wall cache: inside max %.3g, outside mean %.3g max %.3g; reference inside max "
        "%.3g\n",
        insideMax, outsideMean, outsideMax, refInside);
    // The figure: both views' indirect term at one scale (the outside's largest), and the
    // inside amplified 1000x.
    const float scale = std::max(outsideMax, 1e-6f);
    const auto [w, h] = std::pair{c.frame.width, c.frame.height};
    const engine::Status pictures[] = {
        engine::io::writePng(c.output + "/thin_wall_outside_indirect.png", w, h,
                             indirectImage(outdoor, scale)),
        engine::io::writePng(c.output + "/thin_wall_inside_indirect.png", w, h,
                             indirectImage(in, scale)),
        engine::io::writePng(c.output + "/thin_wall_inside_indirect_x1000.png", w, h,
                             indirectImage(in, scale / 1000.0f))};
    for (const engine::Status& written : pictures)
        if (!written) return written;
    return {};
}

// Fast dynamic objects (ghosting): the cache's indirect term on the fast crate's frames
// against the path tracer's, with the N^3 neighbourhood (5) and without (0) — it updates
// the dynamic voxels around the visible ones, so entries the object moves into are warm —
// and, for the error floor, the same crate parked.
engine::Status ghostingCase(StabilityContext& c) {
    auto thinWall = loadThinWall();
    if (!thinWall) return thinWall.error();
    const Scene fast = fastCrate(*thinWall, false);
    const auto camera = fast.camera("outside");
    if (!c.fastCacheRun)
        c.fastCacheRun = movingRun(c, "fast object", fast, camera, cacheLighting(5), true, 16, 32);
    MovingRun cacheN0 = movingRun(c, "fast object", fast, camera, cacheLighting(0), true, 16, 32);
    const Scene parked = fastCrate(*thinWall, true);
    MovingRun still = movingRun(c, "parked object", parked, camera, cacheLighting(5), true, 16, 32);
    engine::AtomicFile ghostingFile;
    if (engine::Status s = ghostingFile.open(std::filesystem::path(c.output) / "ghosting.csv"); !s)
        return s;
    std::ostream& ghosting = ghostingFile.stream();
    ghosting << "case,method,frame,mae,mae_object\n";
    const double floor = mean(still.mae, 5), floorObject = mean(still.maeObject, 5);
    for (const auto& [method, run] : {std::pair{"cache N=5 (5^3 neighbourhood)", &*c.fastCacheRun},
                                      std::pair{"cache N=0 (no neighbourhood)", &cacheN0},
                                      std::pair{"cache N=5 object parked", &still}}) {
        for (std::size_t i = 0; i < run->mae.size(); ++i)
            ghosting << fmt::format("fast object,{},{},{},{}\n", method, i + 1, run->mae[i],
                                    run->maeObject[i]);
        const double m = mean(run->mae, 5), mo = mean(run->maeObject, 5);
        c.rows.push_back(fmt::format(
            "| fast dynamic object (3.7 voxels/frame), indirect term | {} | MAE over frames 6–32 "
            "{:.3e} ({:.2f}x parked); on the object's pixels {:.3e} ({:.2f}x parked) |",
            method, m, m / floor, mo, mo / floorObject));
        std::printf(
            "fast object %-32s MAE %.3e (%.2fx parked), on the object %.3e (%.2fx parked)\n",
            method, m, m / floor, mo, mo / floorObject);
    }
    return ghostingFile.commit();
}

}  // namespace

engine::Status restirCases(StabilityContext& c) {
    using Case = engine::Status (*)(StabilityContext&);
    for (Case run : {flickerCases, editCases, movingObjectCase, grazingEmitterCase,
                     thinWallDirectCase, thinWallCacheCase, removedLightCase, ghostingCase}) {
        if (engine::Status s = run(c); !s) return s;
    }
    return {};
}

}  // namespace vox
