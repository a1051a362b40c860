// Sky light from discrete visibility fields (`--sky dvf`, render/dvf_sky/) against its ground
// truth, the sky's direct light by brute-force cosine rays per pixel (`--sky reference`): the
// mean on two worlds, the per-pixel spread, a roof opened by an edit, and the masks against
// directions traced on the CPU.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

#include "core/hash.h"
#include "gpu/gpu_test_setup.h"
#include "render/dvf_sky/dvf_directions.h"
#include "world/scene_trace.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace gpu_testing;
using engine::lighting::Sky;

namespace {

constexpr std::uint32_t kSize = 64;

LightingSettings skyLighting(Sky sky) {
    LightingSettings l;
    l.method = Method::Uniform;  // no emitter in these tests' terms: the sky term is read alone
    l.sky = sky;
    return l;
}

// The sky term per pixel after `frames` frames.
std::vector<glm::vec4> skyTerm(Renderer& r, Scene& scene, Sky sky, int frames) {
    renderFrames(r, scene, skyLighting(sky), frame(kSize), frames);
    return r.dvfSky().readSkyTerm();
}

// The reference: 16 rays per pixel and frame, 16 frames = 256 rays per pixel.
std::vector<glm::vec4> referenceSky(Scene& scene) {
    Renderer r(context());
    return skyTerm(r, scene, Sky::Reference, 16);
}

struct Agreement {
    double meanDvf = 0.0, meanRef = 0.0;
    double withinTolerance = 0.0;  // fraction of lit pixels within the per-pixel tolerance
};

// Per-pixel tolerance: |dvf - ref| <= 0.25 ref + 0.02 in luminance (the reference's own noise at
// 256 rays is ~4 %; the rest is a mask shared by a cell's faces and 64 directions).
Agreement compare(const std::vector<glm::vec4>& dvf, const std::vector<glm::vec4>& ref) {
    Agreement a;
    std::size_t n = 0, ok = 0;
    for (std::size_t i = 0; i < dvf.size(); ++i) {
        const double d = luminance(dvf[i]), r = luminance(ref[i]);
        a.meanDvf += d;
        a.meanRef += r;
        if (r > 0.0 || d > 0.0) {
            ++n;
            if (std::abs(d - r) <= 0.25 * r + 0.02) ++ok;
        }
    }
    a.meanDvf /= double(dvf.size());
    a.meanRef /= double(ref.size());
    a.withinTolerance = n ? double(ok) / double(n) : 1.0;
    std::printf(
        "sky term: dvf mean %.5f, reference mean %.5f (%+.2f %%), %.1f %% of %zu pixels within "
        "tolerance\n",
        a.meanDvf, a.meanRef, 100.0 * (a.meanDvf / a.meanRef - 1.0), 100.0 * a.withinTolerance, n);
    return a;
}

// A room of 24 x 12 x 24 inside, walls and roof two voxels thick, on a ground slab, with a
// window in one wall: what sees the sky inside sees it through the window only.
Scene roomWithWindow(bool window, bool roof) {
    Scene scene = paletteScene(
        {48, 24, 48},
        {Material{"white", glm::vec3(0.7f)}, Material{"red", glm::vec3(0.7f, 0.2f, 0.15f)}}, false);
    fillBox(scene.grid, Box{{0, 0, 0}, {48, 2, 48}}, 1);
    fillBox(scene.grid, Box{{10, 2, 10}, {38, 16, 38}}, 2);
    fillBox(scene.grid, Box{{12, 2, 12}, {36, 14, 36}}, kEmpty);
    if (!roof) fillBox(scene.grid, Box{{12, 14, 12}, {36, 16, 36}}, kEmpty);
    if (window) fillBox(scene.grid, Box{{18, 5, 10}, {30, 11, 12}}, kEmpty);
    scene.sky.sunRadiance = glm::vec3(0.0f);  // the sky alone
    // Inside, looking at the floor and the far walls from above the window wall.
    scene.cameras.push_back(
        CameraPreset{"inside", {24.0f, 12.0f, 13.0f}, {24.0f, 3.0f, 30.0f}, 80.0f});
    scene.grid.clearDirty();
    return scene;
}

}  // namespace

class DvfSky : public GpuTest {};

// Sandbox terrain (hills, buildings with overhanging roofs): the DVF term's mean within 5 % of the
// reference's, and most pixels within the per-pixel tolerance.
TEST_F(DvfSky, TermMatchesReferenceOnSandbox) {
    Scene scene = loadWorld("sandbox");
    scene.sky.sunRadiance = glm::vec3(0.0f);
    Renderer r(context());
    const auto dvf = skyTerm(r, scene, Sky::Dvf, 4);
    const Agreement a = compare(dvf, referenceSky(scene));
    EXPECT_GT(a.meanRef, 0.01);
    EXPECT_NEAR(a.meanDvf / a.meanRef, 1.0, 0.05);
    EXPECT_GE(a.withinTolerance, 0.85);
}

// A room lit by the sky through a window only: DVF's hard case. The window covers one or two of
// a mask's 64 texels, and a bit is a dithered yes/no, so the few cells that see it carry a large
// quantisation noise: the mean is unbiased over many cells, but this view has few. Measured
// +1.7 % (docs/SKY.md); the test pins it within 10 % and the per-pixel tolerance.
TEST_F(DvfSky, TermInRoomWithWindowWithinItsKnownBound) {
    Scene scene = roomWithWindow(true, true);
    Renderer r(context());
    const auto dvf = skyTerm(r, scene, Sky::Dvf, 4);
    const auto ref = referenceSky(scene);
    const Agreement a = compare(dvf, ref);
    EXPECT_GT(a.meanRef, 0.005);
    EXPECT_NEAR(a.meanDvf / a.meanRef, 1.0, 0.10);
    EXPECT_GE(a.withinTolerance, 0.85);
}

// A closed room has no sky term inside; an edit that removes the roof lets the sky onto the
// floor in the edit's own frame (dvf.invalidate marks the directions towards the roof before
// dvf.build re-traces them, within the per-frame budget; no new slots are needed), and the term
// agrees with the reference of the opened room.
TEST_F(DvfSky, OpeningTheRoofLetsTheSkyIn) {
    Scene scene = roomWithWindow(false, true);
    Renderer r(context());
    const auto closed = skyTerm(r, scene, Sky::Dvf, 4);
    double closedMax = 0.0;
    for (const glm::vec4& p : closed) closedMax = std::max(closedMax, luminance(p));
    EXPECT_EQ(closedMax, 0.0) << "a closed room sees no sky";

    fillBox(scene.grid, Box{{12, 14, 12}, {36, 16, 36}}, kEmpty);
    const std::uint32_t slotsBefore = r.dvfSky().stats().usedSlots;
    const auto firstFrame = skyTerm(r, scene, Sky::Dvf, 1);  // the edit's frame: masks re-traced
    const std::uint32_t tracedMasks = r.dvfSky().stats().tracedMasks;
    const auto opened = skyTerm(r, scene, Sky::Dvf, 1);
    EXPECT_GT(meanLuminance(firstFrame), 0.0)
        << "the sky reaches the floor in the edit's own frame";
    std::printf("roof edit: %u of %u masks re-traced\n", tracedMasks, slotsBefore);
    EXPECT_LE(tracedMasks, slotsBefore);
    const Agreement a = compare(opened, referenceSky(scene));
    EXPECT_NEAR(a.meanDvf / a.meanRef, 1.0, 0.05);
}

// Every traced mask against the same directions traced on the CPU (world/scene_trace.h) from the
// same origins (random points of the cell's faces of the slot's orientation on the anchor's side,
// as build_masks.comp picks them): a bit is one dithered ray, so where every CPU ray through a
// texel is blocked the bit must be clear, where every one escapes it must be set, and over all
// texels the GPU's set bits must match the CPU's visible fraction (unweighted here, the GPU's
// weighted by cos x solid angle within a texel: equal within 5 % over many texels).
TEST_F(DvfSky, MasksMatchCpuTracedDirections) {
    Scene scene = loadWorld("sandbox");
    Renderer r(context());
    renderFrames(r, scene, skyLighting(Sky::Dvf), frame(48), 2);
    const auto slots = r.dvfSky().readSlots();
    const glm::ivec3 size = scene.grid.sizeInVoxels();
    auto inside = [&](glm::ivec3 v) {
        return glm::all(glm::greaterThanEqual(v, glm::ivec3(0))) &&
               glm::all(glm::lessThan(v, size));
    };
    engine::Rng rng(5);
    std::size_t masks = 0, clear = 0, clearAgreed = 0;
    double gpuBits = 0.0, cpuFraction = 0.0;
    for (const shared::DvfSlot& s : slots) {
        if (s.key == shared::DVF_EMPTY_KEY || !(s.state & shared::DVF_STATE_VALID)) continue;
        if (++masks > 150) break;
        const std::uint32_t face = (s.key - 1u) >> 29u;  // keys are the packed (cell, face) + 1
        const std::uint32_t axis = face >> 1u;
        glm::ivec3 n(0);
        n[axis] = (face & 1u) ? 1 : -1;
        // The anchor as dvf_sky.glsl's dvfAnchor unpacks it: the cell's lowest voxel plus the rank.
        const std::uint32_t packed = s.anchorRank & 0xFFFu;
        const glm::ivec3 cellMin(s.anchor);
        const glm::ivec3 anchor =
            cellMin + glm::ivec3(packed & 15u, (packed >> 4u) & 15u, packed >> 8u) - 1;
        // 16 origins as build_masks.comp's dvfOrigin picks them.
        std::vector<glm::vec3> origins;
        for (int i = 0; i < 16; ++i) {
            glm::ivec3 c = anchor;
            c[(axis + 1) % 3] = cellMin[(axis + 1) % 3] + rng.uniformInt(0, 7);
            c[(axis + 2) % 3] = cellMin[(axis + 2) % 3] + rng.uniformInt(0, 7);
            bool onFace = inside(c) && inside(c - n) && scene.grid.get(c) == kEmpty &&
                          scene.grid.get(c - n) != kEmpty;
            if (onFace && c != anchor) {
                const glm::vec3 from = glm::vec3(anchor) + 0.5f, to = glm::vec3(c) + 0.5f;
                const float dist = glm::length(to - from);
                onFace = !traceScene(scene.grid, nullptr, from, (to - from) / dist, dist).hit;
            }
            origins.push_back(glm::vec3(onFace ? c : anchor) + 0.5f - 0.5f * glm::vec3(n) +
                              glm::vec3(n) * 1e-3f);
        }
        for (std::uint32_t d = 0; d < shared::DVF_DIRECTIONS; ++d) {
            int escaped = 0;
            for (std::size_t i = 0; i < origins.size(); ++i) {
                const glm::vec2 uv((float(d % 8u) + (float(i % 4) + 0.5f) / 4.0f) / 8.0f,
                                   (float(d / 8u) + (float(i / 4) + 0.5f) / 4.0f) / 8.0f);
                if (!traceScene(scene.grid, nullptr, origins[i],
                                engine::render::dvfDirection(face, uv), 1e30f)
                         .hit)
                    ++escaped;
            }
            const bool gpu = ((d < 32u ? s.maskDirty.x : s.maskDirty.y) >> (d & 31u)) & 1u;
            gpuBits += gpu ? 1.0 : 0.0;
            cpuFraction += escaped / 16.0;
            if (escaped == 0 || escaped == 16) {
                ++clear;
                if (gpu == (escaped == 16)) ++clearAgreed;
            }
        }
    }
    std::printf(
        "masks: %zu, %zu of %zu clear texels agree; set bits %.0f, CPU visible texels %.1f\n",
        masks, clearAgreed, clear, gpuBits, cpuFraction);
    ASSERT_GT(masks, 20u);
    EXPECT_GE(double(clearAgreed), 0.98 * double(clear));
    EXPECT_NEAR(gpuBits / cpuFraction, 1.0, 0.05);
}

namespace {

// The path tracer's own sky light, independent of `--sky reference`: with no sun and no emitters,
// one bounce minus none is exactly the light the sky sends to the first surface (a cosine ray
// that escapes sees the sky; a ray that hits a surface finds nothing there to sample), at pixel
// centres like the G-buffer the sky term shades.
std::vector<glm::vec4> pathTracedSky(Scene& scene, std::uint32_t spp) {
    auto run = [&](std::uint32_t bounces) {
        Renderer r(context());
        LightingSettings l;
        l.method = Method::Reference;
        l.referenceFilter = engine::lighting::ReferenceFilter::PixelCentre;
        l.bounces = bounces;
        l.samplesPerFrame = 32;
        for (std::uint32_t i = 0; i < spp / 32; ++i)
            r.render(scene, scene.cameras.front(), frame(kSize), l);
        return r.readback().radiance;
    };
    std::vector<glm::vec4> sky = run(1);
    const std::vector<glm::vec4> none = run(0);
    for (std::size_t i = 0; i < sky.size(); ++i) sky[i] -= none[i];
    return sky;
}

// Sky light alone: no sun, no emission.
void skyOnly(Scene& scene) {
    scene.sky.sunRadiance = glm::vec3(0.0f);
    for (std::size_t id = 1; id < scene.palette.size(); ++id)
        scene.palette[MaterialId(id)].emissionStrength = 0.0f;
}

}  // namespace

// DVF sky light against the path tracer itself (not only against `--sky reference`) on three
// worlds: the sandbox's terrain and buildings, the dragon city's streets and a room without a
// roof. Mean within 5 % (measured -1.3 %, -2.2 %, -3.0 %).
// `--sky reference` agrees with the path tracer within 3 % on all (both are estimates of the
// same integral by different code).
TEST_F(DvfSky, TermMatchesThePathTracersSkyLight) {
    Scene sandbox = loadWorld("sandbox");
    Scene city = loadWorld("dragon_city");
    Scene room = roomWithWindow(false, false);
    for (Scene* scene : {&sandbox, &city, &room}) {
        skyOnly(*scene);
        Renderer r(context());
        const auto dvf =
            skyTerm(r, *scene, Sky::Dvf, 8);  // a still scene: the masks' first build is done
        const auto traced = pathTracedSky(*scene, 128);
        const auto reference = referenceSky(*scene);
        const double meanTraced = meanLuminance(traced);
        std::printf("%s: path tracer %.5f, dvf %.5f (%+.2f %%), --sky reference %.5f (%+.2f %%)\n",
                    scene->name.c_str(), meanTraced, meanLuminance(dvf),
                    100.0 * (meanLuminance(dvf) / meanTraced - 1.0), meanLuminance(reference),
                    100.0 * (meanLuminance(reference) / meanTraced - 1.0));
        ASSERT_GT(meanTraced, 0.005);
        EXPECT_NEAR(meanLuminance(dvf) / meanTraced, 1.0, 0.05);
        EXPECT_NEAR(meanLuminance(reference) / meanTraced, 1.0, 0.03);
    }
}

// Same inputs, same image: which pixel's face anchors a mask and the mask's random numbers do
// not depend on the order the GPU's threads ran in (the first version's window room moved
// between +15.7 % and -5 % from run to run).
TEST_F(DvfSky, SameSceneSameSkyTermEveryRun) {
    Scene scene = roomWithWindow(true, true);
    std::vector<glm::vec4> first;
    for (int run = 0; run < 3; ++run) {
        Renderer r(context());
        const auto term = skyTerm(r, scene, Sky::Dvf, 4);
        if (run == 0)
            first = term;
        else
            EXPECT_TRUE(term == first) << "run " << run << " differs";
    }
    // An all-dark (or all but dark) term would repeat trivially: through the window the sky
    // reaches the floor and the far walls. Measured: 81 % of the pixels lit, mean 0.008; the
    // test asks for more than half of each.
    const auto lit = std::count_if(first.begin(), first.end(),
                                   [](const glm::vec4& v) { return luminance(v) > 0.001; });
    const double litFraction = double(lit) / double(first.size());
    std::printf("sky term: %.1f %% of the pixels lit, mean %.5f\n", 100.0 * litFraction,
                meanLuminance(first));
    EXPECT_GT(litFraction, 0.5) << "of " << first.size() << " pixels";
    EXPECT_GT(meanLuminance(first), 0.004);
}
