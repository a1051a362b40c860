// The voxel-face irradiance cache against the path tracer's indirect light, and where such caches
// are known to fail: light leaking through thin walls, memory growing with the world, stale rays
// after edits.
#include <cmath>
#include <cstdlib>
#include <gtest/gtest.h>
#include <map>
#include <tuple>

#include "gpu/command_list.h"
#include "gpu/gpu_test_setup.h"
#include "io/image_io.h"
#include "metrics/image_metrics.h"
#include "render/irradiance_cache/cache_lod.h"
#include "scene/scene_file.h"
#include "world/scene_trace.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace gpu_testing;
using engine::lighting::Indirect;

namespace {

constexpr MaterialId kWhite = 1, kRed = 2, kLamp = 3, kGreen = 4;

// Under the default sun and sky.
Scene makeScene(glm::ivec3 size) {
    return paletteScene(
        size,
        {Material{"white", glm::vec3(0.75f)}, Material{"red", glm::vec3(0.8f, 0.15f, 0.1f)},
         Material{"lamp", glm::vec3(0.8f), glm::vec3(1.0f, 0.85f, 0.6f), 8.0f},
         Material{"green", glm::vec3(0.1f, 0.7f, 0.2f)}},
        false);
}

// An open courtyard: a floor, a red wall and a green wall in a corner, a pillar, sun and sky and
// one lamp. Most of its indirect light is the sun bouncing off the floor and the coloured walls.
Scene courtyard(glm::ivec3 size = {64, 40, 64}) {
    Scene scene = makeScene(size);
    fillBox(scene.grid, Box{{0, 0, 0}, {64, 4, 64}}, kWhite);
    fillBox(scene.grid, Box{{0, 4, 52}, {64, 30, 56}}, kRed);
    fillBox(scene.grid, Box{{52, 4, 0}, {56, 30, 52}}, kGreen);
    fillBox(scene.grid, Box{{24, 4, 24}, {30, 20, 30}}, kWhite);
    fillBox(scene.grid, Box{{10, 12, 40}, {12, 14, 42}}, kLamp);
    scene.sky.sunDirection = glm::normalize(glm::vec3(-0.5f, 1.0f, -0.6f));
    scene.cameras.push_back(
        CameraPreset{"corner", {8.0f, 26.0f, 6.0f}, {46.0f, 6.0f, 44.0f}, 70.0f});
    scene.grid.clearDirty();
    return scene;
}

LightingSettings cacheLighting(std::uint32_t bounces = 1) {
    LightingSettings l;
    l.method = Method::Preview;  // the direct term does not matter here: only the cache's own
                                 // output is compared
    l.indirect = Indirect::Cache;
    l.cache.bounces = bounces;
    return l;
}

std::vector<glm::vec4> cacheIndirect(Scene& scene, const LightingSettings& l, std::uint32_t size,
                                     int frames) {
    Renderer r(gpu_testing::context());
    return renderFrames(r, scene, l, frame(size), frames).indirect;
}

// The path tracer's indirect light: (bounces) minus (direct only), both converged.
FrameSettings frameAt(std::uint32_t size, double time) {
    FrameSettings f = frame(size);
    f.timeSeconds = time;
    return f;
}

// A 6^3 red ball that crosses the courtyard in `seconds` and stops there.
DynamicObject movingBall(double seconds) {
    DynamicObject ball;
    ball.name = "ball";
    ball.modelSize = {6, 6, 6};
    BrickGrid ballModel({8, 8, 8});
    fillBox(ballModel, Box{{0, 0, 0}, {6, 6, 6}}, kRed);
    ball.model = std::make_shared<const BrickGrid>(std::move(ballModel));
    ObjectKey from, to, rest;
    from.position = {14.0, 8.0, 20.0};
    to.time = seconds;
    to.position = {40.0, 8.0, 20.0};
    rest.time = seconds + 100.0;
    rest.position = to.position;
    ball.path = ObjectPath({from, to, rest}, false);
    return ball;
}

// The path tracer's indirect light (with `bounces` minus without) from `camera`, at pixel centres
// like the cache's gather.
std::vector<glm::vec4> referenceIndirectAt(Scene& scene, const engine::world::CameraPreset& camera,
                                           std::uint32_t size, std::uint32_t bounces,
                                           std::uint32_t spp, double time, std::uint32_t seed) {
    auto run = [&](std::uint32_t b) {
        Renderer r(gpu_testing::context());
        LightingSettings l;
        l.method = Method::Reference;
        l.referenceFilter =
            engine::lighting::ReferenceFilter::PixelCentre;  // the cache is gathered at pixel
                                                             // centres
        l.bounces = b;
        l.seed = seed;
        l.samplesPerFrame = 32;
        for (std::uint32_t i = 0; i < spp / 32; ++i)
            r.render(scene, camera, frameAt(size, time), l);
        return r.readback().radiance;
    };
    std::vector<glm::vec4> with = run(bounces), without = run(0);
    for (std::size_t i = 0; i < with.size(); ++i) with[i] -= without[i];
    return with;
}

std::vector<glm::vec4> referenceIndirect(Scene& scene, std::uint32_t size, std::uint32_t bounces,
                                         std::uint32_t spp, double time = 0.0,
                                         std::uint32_t seed = 1) {
    return referenceIndirectAt(scene, scene.camera(), size, bounces, spp, time, seed);
}

double meanOf(const std::vector<glm::vec4>& img) {
    double sum = 0.0;
    for (const glm::vec4& p : img) sum += (p.x + p.y + p.z) / 3.0;
    return sum / double(img.size());
}

// The cache's indirect term against the path tracer's, per pixel: the relative MAE of
// engine/metrics (|c - r| / (r + 0.01), averaged), the MAE as a fraction of the reference's mean,
// and the ratio of the means.
struct IndirectError {
    double rmae = 0.0, relativeMae = 0.0, meanRatio = 0.0;
};
IndirectError indirectError(const std::vector<glm::vec4>& cache, const std::vector<glm::vec4>& ref,
                            std::uint32_t w, std::uint32_t h) {
    auto e = engine::metrics::compareImages({cache, w, h}, {ref, w, h});
    EXPECT_TRUE(e);
    const double refMean = meanOf(ref);
    return {e ? e->rmae : 0.0, mae(cache, ref) / refMean, meanOf(cache) / refMean};
}

std::vector<glm::vec4> average(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
    std::vector<glm::vec4> out(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) out[i] = 0.5f * (a[i] + b[i]);
    return out;
}

// The converged cache (one bounce, defaults but K) with the lighting seed `seed`.
std::vector<glm::vec4> cacheIndirectSeeded(Scene& scene, const engine::world::CameraPreset& camera,
                                           std::uint32_t size, int frames, std::uint32_t directions,
                                           std::uint32_t seed, float maxRay = 0.0f,
                                           float lodDistance = 0.0f) {
    LightingSettings l = cacheLighting(1);
    l.cache.directions = directions;
    l.cache.lodDistance = lodDistance;
    if (maxRay > 0.0f) l.cache.maxRayLength = maxRay;
    if (const char* v = std::getenv("VOX_MEASURE_LIGHT_SAMPLES"))
        l.cache.lightSamples = std::uint32_t(std::strtoul(v, nullptr, 10));
    if (const char* v = std::getenv("VOX_MEASURE_BUDGET"))
        l.cache.rayBudget = std::uint32_t(std::strtoul(v, nullptr, 10));
    if (const char* v = std::getenv("VOX_MEASURE_NEIGHBOURHOOD"))
        l.cache.neighbourhood = std::uint32_t(std::strtoul(v, nullptr, 10));
    l.seed = seed;
    Renderer r(gpu_testing::context());
    for (int i = 0; i < frames; ++i) r.render(scene, camera, frameAt(size, 0.0), l);
    return r.readback().indirect;
}

std::uint32_t envOr(const char* name, std::uint32_t fallback) {
    const char* v = std::getenv(name);
    return v ? static_cast<std::uint32_t>(std::strtoul(v, nullptr, 10)) : fallback;
}

}  // namespace

class IrradianceCache : public GpuTest {};

// One bounce, with one object moving: the ball crosses the courtyard in the first half second and
// stops; after 96 frames the cache's indirect term is compared, per pixel, with the path tracer's
// at the final pose. The cache is biased by design (irradiance at voxel-face centres, filtered
// and interpolated, blended over time), so the bounds are on the relative MAE and on the mean.
TEST_F(IrradianceCache, OneBounceMatchesReference) {
    Scene scene = courtyard();
    scene.objects.push_back(movingBall(0.5));
    const std::uint32_t size = 48;
    Renderer r(gpu_testing::context());
    for (std::uint32_t i = 0; i < 96; ++i)
        r.render(scene, scene.camera(), frameAt(size, i / 60.0), cacheLighting(1));
    std::vector<glm::vec4> cache = r.readback().indirect;
    std::vector<glm::vec4> ref = referenceIndirect(scene, size, 1, 2048, 95 / 60.0);
    const double refMean = meanOf(ref), cacheMean = meanOf(cache), err = mae(cache, ref);
    std::printf(
        "one bounce: reference indirect mean %.5f, cache %.5f (%+.1f %%), MAE %.5f = %.1f %% of "
        "the mean\n",
        refMean, cacheMean, 100.0 * (cacheMean / refMean - 1.0), err, 100.0 * err / refMean);
    ASSERT_GT(refMean, 0.01);
    EXPECT_NEAR(cacheMean / refMean, 1.0, 0.10);
    EXPECT_LT(err / refMean, 0.25);
}

// More bounces read the cached irradiance at each ray's hit: closer to the multi-bounce reference
// than one bounce is.
TEST_F(IrradianceCache, MultiBounceApproachesMultiBounceReference) {
    Scene scene = courtyard();
    const std::uint32_t size = 48;
    std::vector<glm::vec4> ref = referenceIndirect(scene, size, 6, 2048);
    std::vector<glm::vec4> one = cacheIndirect(scene, cacheLighting(1), size, 64);
    std::vector<glm::vec4> many = cacheIndirect(scene, cacheLighting(4), size, 64);
    const double refMean = meanOf(ref);
    std::printf(
        "multi-bounce: reference mean %.5f; cache 1 bounce %.5f (MAE %.5f), 4 bounces %.5f (MAE "
        "%.5f)\n",
        refMean, meanOf(one), mae(one, ref), meanOf(many), mae(many, ref));
    EXPECT_LT(mae(many, ref), 0.8 * mae(one, ref));
    EXPECT_NEAR(meanOf(many) / refMean, 1.0, 0.15);
}

// A sealed, unlit room behind a one-voxel wall, with the sun and a lamp outside: no light may
// reach its inside surfaces through the cache's filter or interpolation — with every voxel its own
// entry, and with level of detail forced on everywhere (lod_distance 1: every face whose 2x2
// patch is open shares a coarse entry).
namespace {

struct ThinWallResult {
    double outsideMean = 0.0;
    float insideMax = 0.0f;
    float firstLookInsideMax = 0.0f;  // the first frame inside, after only the outside was seen
    std::uint32_t coarseEntries = 0;
};
ThinWallResult thinWall(float lodDistance) {
    Scene scene = makeScene({48, 32, 48});
    fillBox(scene.grid, Box{{0, 0, 0}, {48, 4, 48}}, kWhite);
    // The room: x in [24, 40), z in [8, 40), walls one voxel thick, a roof.
    fillBox(scene.grid, Box{{23, 4, 7}, {41, 20, 41}}, kWhite);
    fillBox(scene.grid, Box{{24, 4, 8}, {40, 19, 40}}, 0);
    fillBox(scene.grid, Box{{12, 10, 20}, {14, 12, 22}}, kLamp);
    // Look into the room through the camera placed inside it, and out at the lit side.
    scene.cameras.push_back(
        CameraPreset{"inside", {38.0f, 16.0f, 24.0f}, {24.0f, 6.0f, 24.0f}, 80.0f});
    scene.cameras.push_back(
        CameraPreset{"outside", {4.0f, 16.0f, 24.0f}, {23.0f, 6.0f, 24.0f}, 80.0f});
    scene.grid.clearDirty();

    Renderer r(gpu_testing::context());
    LightingSettings l = cacheLighting(1);
    l.cache.lodDistance = lodDistance;
    l.cache.fallbackRadius = 4;  // on (the default is off), so the first look inside tests it
    ThinWallResult out;
    // Both views every frame, so the inside and outside entries are both live and neighbours.
    for (int i = 0; i < 24; ++i) {
        r.render(scene, scene.camera("outside"), frame(48), l);
        out.coarseEntries = std::max(out.coarseEntries, r.irradianceCache().stats().coarseEntries);
        r.render(scene, scene.camera("inside"), frame(48), l);
        out.coarseEntries = std::max(out.coarseEntries, r.irradianceCache().stats().coarseEntries);
    }
    std::vector<glm::vec4> inside = r.readback().indirect;
    r.render(scene, scene.camera("outside"), frame(48), l);
    out.outsideMean = meanOf(r.readback().indirect);
    for (const glm::vec4& p : inside) out.insideMax = std::max({out.insideMax, p.x, p.y, p.z});
    // The gather's fallback: the room's voxels have no entries in the first frame inside, and the
    // nearest entries of the floor's plane are the lit ones outside, two voxels away under the
    // wall.
    Renderer first(gpu_testing::context());
    for (int i = 0; i < 12; ++i) first.render(scene, scene.camera("outside"), frame(48), l);
    first.render(scene, scene.camera("inside"), frame(48), l);
    for (const glm::vec4& p : first.readback().indirect)
        out.firstLookInsideMax = std::max({out.firstLookInsideMax, p.x, p.y, p.z});
    std::printf(
        "thin wall (lod_distance %g): indirect outside mean %.4f; inside max %.3g (first look "
        "%.3g); coarse entries %u\n",
        lodDistance, out.outsideMean, out.insideMax, out.firstLookInsideMax, out.coarseEntries);
    return out;
}

}  // namespace

TEST_F(IrradianceCache, ThinWallDoesNotLeak) {
    const ThinWallResult fine = thinWall(0.0f);
    EXPECT_GT(fine.outsideMean, 0.02);         // the cache works on the lit side
    EXPECT_EQ(fine.insideMax, 0.0f);           // and nothing crosses the wall
    EXPECT_EQ(fine.firstLookInsideMax, 0.0f);  // not even through the gather's fallback
    EXPECT_EQ(fine.coarseEntries, 0u);
    const ThinWallResult coarse = thinWall(1.0f);
    EXPECT_GT(coarse.coarseEntries, 100u);  // the floors and walls are mostly coarse
    EXPECT_GT(coarse.outsideMean, 0.02);
    EXPECT_EQ(coarse.insideMax, 0.0f);
    EXPECT_EQ(coarse.firstLookInsideMax, 0.0f);
}

// A moving camera: the voxels it sees for the first time have no entry in that frame (the visible
// set is the previous frame's), and with a ray budget some wait longer. The gather's fallback
// gives their pixels the nearest entries of the same face in their plane: non-zero, and close to
// what the converged cache shows there. Without it (fallback 0) those pixels read nothing.
TEST_F(IrradianceCache, NewlyVisibleVoxelsGetLightInTheirFirstFrame) {
    Scene scene = courtyard();
    const engine::world::CameraPreset before = scene.camera();
    engine::world::CameraPreset after =
        before;  // a step sideways and forwards: new voxels come into view
    after.position += glm::vec3(4.0f, 0.0f, 3.0f);
    after.target += glm::vec3(4.0f, 0.0f, 3.0f);
    const std::uint32_t size = 48;
    auto firstFrameAfterTheStep = [&](std::uint32_t fallback, FrameImages& images,
                                      std::vector<bool>& isNew) {
        Renderer r(gpu_testing::context());
        LightingSettings l = cacheLighting(1);
        l.cache.fallbackRadius = fallback;
        for (int i = 0; i < 24; ++i) r.render(scene, before, frame(size), l);
        r.render(scene, after, frame(size), l);
        images = r.readback();
        isNew.assign(images.gbuffer.size(), false);
        for (std::size_t p = 0; p < images.gbuffer.size(); ++p) {
            const shared::GBufferTexel& g = images.gbuffer[p];
            if (g.voxel.w >= 6 || (g.data.w & shared::GBUFFER_FLAG_DYNAMIC) != 0u) continue;
            isNew[p] = r.irradianceCache().directory().slotOf(
                           {glm::ivec3(g.voxel), shared::CACHE_SET_STATIC}) == ~0u;
        }
    };
    FrameImages with, without;
    std::vector<bool> isNew, isNewWithout;
    firstFrameAfterTheStep(4, with, isNew);
    firstFrameAfterTheStep(0, without, isNewWithout);
    ASSERT_EQ(isNew, isNewWithout);
    std::vector<glm::vec4> converged = cacheIndirectSeeded(scene, after, size, 48, 128, 1);

    std::uint32_t newPixels = 0, darkWith = 0, darkWithout = 0;
    double sumWith = 0.0, sumConverged = 0.0, absError = 0.0;
    for (std::size_t p = 0; p < isNew.size(); ++p) {
        const double c = (converged[p].x + converged[p].y + converged[p].z) / 3.0;
        if (!isNew[p] || c <= 0.0) continue;
        const double w = (with.indirect[p].x + with.indirect[p].y + with.indirect[p].z) / 3.0;
        const double wo =
            (without.indirect[p].x + without.indirect[p].y + without.indirect[p].z) / 3.0;
        ++newPixels;
        darkWith += w == 0.0;
        darkWithout += wo == 0.0;
        sumWith += w;
        sumConverged += c;
        absError += std::abs(w - c);
    }
    std::printf(
        "newly visible voxels: %u pixels; without an indirect term in their first frame: %u with "
        "the fallback, "
        "%u without; their mean %.4f against the converged cache's %.4f (%+.1f %%), MAE %.1f %% of "
        "it\n",
        newPixels, darkWith, darkWithout, sumWith / std::max(newPixels, 1u),
        sumConverged / std::max(newPixels, 1u), 100.0 * (sumWith / sumConverged - 1.0),
        100.0 * absError / sumConverged);
    ASSERT_GT(newPixels, 50u)
        << "the step must bring new voxels into view for this test to mean anything";
    EXPECT_GT(darkWithout, 0u) << "without the fallback some new pixels read nothing";
    EXPECT_EQ(darkWith, 0u);
    EXPECT_NEAR(sumWith / sumConverged, 1.0, 0.15);
    EXPECT_LT(absError / sumConverged, 0.3);
}

// Level of detail: on the courtyard's wide view, faces farther than 40 voxels along the view ray
// share coarse entries (one face of an open 2x2 patch): fewer entries, and an indirect term close
// to the fine cache's (same seed, both converged).
TEST_F(IrradianceCache, FarSurfacesShareCoarseEntries) {
    Scene scene = courtyard();
    const std::uint32_t size = 64;
    auto run = [&](float lodDistance, std::uint32_t& entries, std::uint32_t& coarse) {
        LightingSettings l = cacheLighting(1);
        l.cache.lodDistance = lodDistance;
        Renderer r(gpu_testing::context());
        for (int i = 0; i < 40; ++i) r.render(scene, scene.camera(), frame(size), l);
        entries = r.irradianceCache().stats().entries;
        coarse = r.irradianceCache().stats().coarseEntries;
        return r.readback().indirect;
    };
    std::uint32_t fineEntries = 0, lodEntries = 0, fineCoarse = 0, lodCoarse = 0;
    std::vector<glm::vec4> fine = run(0.0f, fineEntries, fineCoarse);
    std::vector<glm::vec4> lod = run(40.0f, lodEntries, lodCoarse);
    const double fineMean = meanOf(fine), lodMean = meanOf(lod), err = mae(lod, fine) / fineMean;
    std::printf(
        "lod: entries %u fine, %u with lod_distance 40 (%u coarse, %.2fx); indirect mean %.4f vs "
        "%.4f (%+.1f %%), "
        "MAE %.1f %% of the mean\n",
        fineEntries, lodEntries, lodCoarse, double(lodEntries) / fineEntries, fineMean, lodMean,
        100.0 * (lodMean / fineMean - 1.0), 100.0 * err);
    EXPECT_EQ(fineCoarse, 0u);
    EXPECT_GT(lodCoarse, 100u);
    // Measured: 0.55x the entries, mean -0.0 %, MAE 0.7 % of the mean.
    EXPECT_LT(lodEntries, fineEntries * 3 / 4);
    EXPECT_NEAR(lodMean / fineMean, 1.0, 0.03);
    EXPECT_LT(err, 0.05);
}

// A sealed, unlit room wider than 250 voxels (cornell's interior is 256): every ray of the cache
// must find the far wall. A ray cut short at its length limit counts as sky and lights the room.
TEST_F(IrradianceCache, LongRaysInALargeSealedRoomSeeNoSky) {
    Scene scene = makeScene({272, 272, 272});
    fillBox(scene.grid, Box{{0, 0, 0}, {272, 272, 272}}, kWhite);
    fillBox(scene.grid, Box{{4, 4, 4}, {268, 268, 268}}, 0);  // interior 264^3, walls 4 thick
    scene.sky.skyRadiance = glm::vec3(1.0f);
    scene.cameras.push_back(
        CameraPreset{"inside", {136.0f, 200.0f, 40.0f}, {136.0f, 4.0f, 200.0f}, 80.0f});
    scene.grid.clearDirty();
    LightingSettings l = cacheLighting(1);
    l.cache.directions = 32;
    std::vector<glm::vec4> inside = cacheIndirect(scene, l, 32, 4);
    float insideMax = 0.0f;
    for (const glm::vec4& p : inside) insideMax = std::max({insideMax, p.x, p.y, p.z});
    // The old limit (250 voxels, then the most a packed hit could hold) shows what the test
    // catches.
    l.cache.maxRayLength = 250.0f;
    const double cutShort = meanOf(cacheIndirect(scene, l, 32, 4));
    std::printf(
        "large sealed room: indirect max %.3g (rays of up to %.0f voxels); mean %.4f with rays cut "
        "at 250\n",
        insideMax, shared::CACHE_MAX_RAY_LENGTH, cutShort);
    EXPECT_EQ(insideMax, 0.0f);
    EXPECT_GT(cutShort, 0.01);
}

// Cache memory follows what the camera sees: the same view in a world four times larger (more
// content out of view) allocates the same entries and the same bytes.
TEST_F(IrradianceCache, MemoryDoesNotGrowWithTheWorld) {
    Scene small = courtyard();
    Scene large = makeScene({256, 40, 256});
    fillBox(large.grid, Box{{0, 0, 0}, {256, 4, 256}}, kWhite);
    fillBox(large.grid, Box{{0, 4, 52}, {64, 30, 56}}, kRed);
    fillBox(large.grid, Box{{52, 4, 0}, {56, 30, 52}}, kGreen);
    fillBox(large.grid, Box{{24, 4, 24}, {30, 20, 30}}, kWhite);
    fillBox(large.grid, Box{{10, 12, 40}, {12, 14, 42}}, kLamp);
    for (int i = 0; i < 12; ++i)
        fillBox(large.grid, Box{{100 + 12 * i, 4, 120}, {106 + 12 * i, 30, 200}},
                kRed);  // out of view
    large.sky = small.sky;
    large.cameras = small.cameras;
    large.grid.clearDirty();
    auto stats = [](Scene& scene) {
        Renderer r(gpu_testing::context());
        engine::render::FrameResult result;
        for (int i = 0; i < 3; ++i)
            result = r.render(scene, scene.camera(), frame(48), cacheLighting(1));
        return result.cache;
    };
    auto a = stats(small), b = stats(large);
    std::printf(
        "cache: %u entries, %llu bytes (64x40x64 world) vs %u entries, %llu bytes (256x40x256)\n",
        a.entries, static_cast<unsigned long long>(a.bytes), b.entries,
        static_cast<unsigned long long>(b.bytes));
    EXPECT_GT(a.entries, 100u);
    EXPECT_EQ(a.entries, b.entries);
    EXPECT_EQ(a.bytes, b.bytes);
}

// An edit re-traces the static rays of the entries within the maximum ray length of it, and no
// others; the changed light then reaches the cache.
TEST_F(IrradianceCache, EditsInvalidateOnlyNearbyStaticRays) {
    Scene scene = courtyard({64, 40, 128});  // empty beyond z = 64, out of view
    Renderer r(gpu_testing::context());
    LightingSettings l = cacheLighting(1);
    l.cache.maxRayLength = 16.0f;
    l.cache.rayBudget = 0;  // every visible entry every frame: the counts below are exact
    const std::uint32_t phases = l.cache.directions / l.cache.raysPerUpdate;
    engine::render::FrameResult first;
    for (std::uint32_t i = 0; i <= phases; ++i)
        first = r.render(scene, scene.camera(), frame(48), l);
    EXPECT_EQ(first.cache.traced, 0u) << "all K directions are cached after K/S updates";
    // More than 16 voxels from everything the camera sees: nothing to invalidate.
    scene.grid.set({8, 20, 120}, kWhite);
    auto far = r.render(scene, scene.camera(), frame(48), l).cache;
    EXPECT_EQ(far.invalidated, 0u);
    // In the middle of the courtyard: some entries, not all.
    scene.grid.set({32, 4, 32}, kWhite);
    auto near = r.render(scene, scene.camera(), frame(48), l).cache;
    std::printf("edit: %u of %u live entries re-trace (max ray length 16)\n", near.invalidated,
                near.entries);
    EXPECT_GT(near.invalidated, 0u);
    EXPECT_LT(near.invalidated, near.entries);
    EXPECT_EQ(near.traced, near.invalidated);
}

// The ray budget holds on the GPU: the rays the cache's shaders count (static traces, dynamic
// traces, divide-and-win checks) never exceed it, through warm-up, a moving object and an edit,
// and while entries wait it is mostly spent; without a budget the same frames trace far more.
TEST_F(IrradianceCache, RayBudgetHoldsOnTheGpu) {
    Scene scene = courtyard();
    scene.objects.push_back(movingBall(0.5));
    auto run = [&](std::uint32_t budget) {
        Scene copy = scene;
        Renderer r(gpu_testing::context());
        LightingSettings l = cacheLighting(1);
        l.cache.rayBudget = budget;
        l.cache.neighbourhood =
            5;  // the ball's 5^3 surroundings: demand far above the budget without one
        std::uint64_t most = 0, total = 0;
        std::uint32_t framesWaiting = 0;
        for (std::uint32_t i = 0; i < 40; ++i) {
            if (i == 20)
                fillBox(copy.grid, Box{{30, 4, 10}, {34, 12, 14}}, kWhite);  // an edit mid-way
            auto c = r.render(copy, copy.camera(), frameAt(48, i / 30.0), l).cache;
            EXPECT_LE(c.raysTraced, c.rays)
                << "frame " << i << ": the shaders traced more than the directory allowed";
            if (budget) EXPECT_LE(c.rays, budget) << "frame " << i;
            most = std::max(most, c.raysTraced);
            total += c.raysTraced;
            framesWaiting += c.waiting > 0;
        }
        return std::make_tuple(most, total, framesWaiting);
    };
    const std::uint32_t budget = 20000;
    auto [most, total, waiting] = run(budget);
    auto [mostFree, totalFree, waitingFree] = run(0);
    std::printf(
        "ray budget %u: most rays in a frame %llu, %llu in 40 frames, %u frames with entries "
        "waiting; "
        "without a budget: most %llu, total %llu\n",
        budget, static_cast<unsigned long long>(most), static_cast<unsigned long long>(total),
        waiting, static_cast<unsigned long long>(mostFree),
        static_cast<unsigned long long>(totalFree));
    EXPECT_LE(most, budget);
    // Charged for the faces the shaders trace (not six per voxel), the budget is spent, not just
    // held.
    EXPECT_GT(most, 3 * std::uint64_t(budget) / 4);
    EXPECT_GT(waiting, 0u) << "the budget must bind for this test to mean anything";
    EXPECT_GT(mostFree, 4 * std::uint64_t(budget));
    EXPECT_EQ(waitingFree, 0u);
}

// A lamp switched on in a dark room (no sun, no sky): the cache's indirect light reaches 90 % of
// its new steady state within a bounded number of frames. The bound: each visible entry needs one
// update that restarts it (re-tracing after the edit costs 2 S rays per face), and a second round
// so the filter sees its neighbours' new values — 2 ceil(entries * 12 S / budget) + 2 frames.
TEST_F(IrradianceCache, LampSwitchedOnReachesTheCacheWithinBoundedFrames) {
    Scene scene = makeScene({48, 32, 48});
    scene.sky.sunRadiance = glm::vec3(0.0f);
    scene.sky.skyRadiance = glm::vec3(0.0f);
    fillBox(scene.grid, Box{{0, 0, 0}, {48, 4, 48}}, kWhite);
    fillBox(scene.grid, Box{{0, 4, 44}, {48, 24, 48}}, kRed);
    fillBox(scene.grid, Box{{44, 4, 0}, {48, 24, 44}}, kGreen);
    fillBox(scene.grid, Box{{20, 4, 20}, {26, 14, 26}}, kWhite);
    const Box lamp{{28, 8, 32}, {32, 12, 36}};
    fillBox(scene.grid, lamp, kWhite);  // off: plain white for now
    scene.cameras.push_back(
        CameraPreset{"corner", {4.0f, 22.0f, 4.0f}, {40.0f, 6.0f, 40.0f}, 70.0f});
    scene.grid.clearDirty();
    Renderer r(gpu_testing::context());
    LightingSettings l = cacheLighting(1);
    l.cache.rayBudget = 50000;
    engine::render::FrameResult last;
    for (int i = 0; i < 16; ++i) last = r.render(scene, scene.camera(), frame(48), l);
    const double before = meanOf(r.readback().indirect);
    const std::uint32_t entries = last.cache.entries;

    fillBox(scene.grid, lamp, kLamp);  // switched on
    std::vector<double> means;
    for (int i = 0; i < 80; ++i) {
        r.render(scene, scene.camera(), frame(48), l);
        means.push_back(meanOf(r.readback().indirect));
    }
    double steady = 0.0;
    for (std::size_t i = means.size() - 10; i < means.size(); ++i) steady += means[i] / 10.0;
    std::size_t reached = means.size();
    for (std::size_t i = means.size(); i-- > 0;) {
        if (means[i] < before + 0.9 * (steady - before)) break;
        reached = i;
    }
    const std::uint32_t perEntry = 2 * shared::CACHE_FACES * l.cache.raysPerUpdate;
    const std::uint32_t bound =
        2 * ((entries * perEntry + l.cache.rayBudget - 1) / l.cache.rayBudget) + 2;
    std::printf(
        "lamp on: indirect mean %.4f before, %.4f steady; 90 %% reached after %zu frames and kept "
        "(bound %u: %u entries, budget %u rays); frames 1-4: %.4f %.4f %.4f %.4f\n",
        before, steady, reached + 1, bound, entries, l.cache.rayBudget, means[0], means[1],
        means[2], means[3]);
    EXPECT_EQ(before, 0.0);
    EXPECT_GT(steady, 0.005);
    EXPECT_LE(reached + 1, bound);
}

// ---- Dynamic objects ------------------------------------------------------------------------

namespace {

std::vector<std::uint32_t> readUints(const engine::gpu::Buffer& buffer) {
    engine::gpu::Context& ctx = gpu_testing::context();
    engine::gpu::Buffer host(ctx, engine::gpu::BufferKind::Readback, buffer.size(),
                             "test.readback");
    engine::gpu::CommandList cmd(ctx);
    cmd.begin();
    cmd.copyBuffer(buffer, host, {{0, 0, buffer.size()}});
    cmd.barrier();
    cmd.submitAndWait();
    auto view = host.view<std::uint32_t>();
    return {view.begin(), view.end()};
}

// The cache's rays as the shaders build them (shaders/irradiance_cache/irradiance_cache.glsl).
glm::vec3 rayOrigin(glm::ivec3 voxel, std::uint32_t face) {
    glm::vec3 o = glm::vec3(voxel) + 0.5f;
    o[face >> 1] += (face & 1u) ? shared::CACHE_RAY_OFFSET : -shared::CACHE_RAY_OFFSET;
    return o;
}
std::uint32_t packHit(glm::ivec3 origin, glm::vec3 d, const SceneHit& h) {
    if (!h.hit) return shared::CACHE_HIT_MISS;
    const glm::ivec3 sign(d.x < 0.0f ? -1 : 1, d.y < 0.0f ? -1 : 1, d.z < 0.0f ? -1 : 1);
    glm::uvec3 rel(glm::clamp((h.voxel - origin) * sign + 2, 0, 511));
    return rel.x | (rel.y << 9) | (rel.z << 18) | (h.face << 27) |
           (h.dynamicSet ? shared::CACHE_HIT_DYNAMIC : 0u);
}

}  // namespace

// Divide and win is exact: for every ray the cache traced this frame, "cached static hit + the
// dynamic grid traced alone" selects the same hit (voxel, face, set) as tracing both worlds from
// scratch — on the GPU in full-re-trace mode and on the CPU reference. With every voxel its own
// entry, and with coarse entries everywhere their patch is open (lod_distance 1).
// With `frames` > 8 (K / S), dynamic entries update again in phases whose static hits they cached
// (visibility_dynamic.comp): `reused` counts those in the last frame's list.
void expectDivideAndWinExact(float lodDistance, std::uint32_t frames = 5, double seconds = 2.4,
                             std::size_t* reused = nullptr) {
    Scene a = loadWorld("thin_wall.toml"), b = loadWorld("thin_wall.toml");
    Renderer divide(gpu_testing::context()), full(gpu_testing::context());
    LightingSettings ld = cacheLighting(1), lf = cacheLighting(1);
    ld.cache.lodDistance = lf.cache.lodDistance = lodDistance;
    // Enough rays that the last frame's list holds static (and coarse) entries besides the crate's
    // dynamic ones, which take up to half of any budget.
    ld.cache.rayBudget = lf.cache.rayBudget = 150000;
    // The 5^3 neighbourhood: more dynamic entries, so more of them re-read cached static hits and
    // face the crate (the default 3^3 leaves ~85 in the last list).
    ld.cache.neighbourhood = lf.cache.neighbourhood = 5;
    lf.cache.fullRetrace = true;
    // The crate slides to the wall over these frames (by 2.4 s): static rays cached early see it
    // arrive.
    for (std::uint32_t i = 0; i < frames; ++i) {
        const double time = seconds * i / (frames - 1);
        divide.render(a, a.camera("outside"), frameAt(64, time), ld);
        full.render(b, b.camera("outside"), frameAt(64, time), lf);
    }
    const auto& cd = divide.irradianceCache();
    const auto& cf = full.irradianceCache();
    ASSERT_EQ(std::vector<std::uint32_t>(cd.updateList().begin(), cd.updateList().end()),
              std::vector<std::uint32_t>(cf.updateList().begin(), cf.updateList().end()));
    const std::uint32_t S = cd.raysPerUpdate();
    const std::size_t rays = cd.updateList().size() * shared::CACHE_FACES * S;
    std::size_t dynamicEntries = 0;
    for (std::uint32_t slot : cd.updateList())
        dynamicEntries += cd.directory().entry(slot).voxel.w == int(shared::CACHE_SET_DYNAMIC);
    std::printf("%zu dynamic entries in the last update list\n", dynamicEntries);
    std::vector<std::uint32_t> hd = readUints(cd.selectedHits()), hf = readUints(cf.selectedHits());

    std::size_t traced = 0, dynamicHits = 0, gpuMismatch = 0, cpuMismatch = 0, coarse = 0;
    for (std::size_t item = 0; item < cd.updateList().size(); ++item) {
        const shared::CacheEntry& e = cd.directory().entry(cd.updateList()[item]);
        const glm::ivec3 v(e.voxel);
        coarse += e.coarse != 0;
        if (reused && e.voxel.w == int(shared::CACHE_SET_DYNAMIC) &&
            (e.flags & shared::CACHE_ENTRY_TRACE) == 0u)
            ++*reused;
        for (std::uint32_t face = 0; face < 6; ++face) {
            glm::ivec3 n = v;
            n[face >> 1] += (face & 1u) ? 1 : -1;
            bool exposed = a.grid.contains(n) ? a.grid.get(n) == kEmpty : true;
            if (e.voxel.w == int(shared::CACHE_SET_DYNAMIC) && exposed) {
                glm::ivec3 local = n - a.dynamic.origin;
                exposed = !a.dynamic.grid.contains(local) || a.dynamic.grid.get(local) == kEmpty;
            }
            glm::vec3 o = rayOrigin(v, face);
            if (e.coarse !=
                0) {  // one face of an open 2x2 patch; its rays start at the patch's centre
                exposed = e.coarse == 1 + face &&
                          engine::render::coarsePatchKey(a.grid, v, face).has_value();
                o[((face >> 1) + 1) % 3] += 0.5f;
                o[((face >> 1) + 2) % 3] += 0.5f;
            }
            if (!exposed) continue;  // a closed face has no rays: no pass writes or reads its hits
            for (std::uint32_t j = 0; j < S; ++j) {
                const std::size_t at = (item * shared::CACHE_FACES + face) * S + j;
                if (hd[at] != hf[at]) ++gpuMismatch;
                glm::vec3 d =
                    cd.rayDirection(v, std::uint32_t(e.voxel.w), face,
                                    cd.directionIndex(cd.updateList()[item], j), e.coarse);
                SceneHit h = traceScene(a.grid, &a.dynamic, o, d, shared::CACHE_MAX_RAY_LENGTH);
                ++traced;
                dynamicHits += h.hit && h.dynamicSet;
                if (hd[at] != packHit(v, d, h)) ++cpuMismatch;
            }
        }
    }
    std::printf(
        "divide and win (lod_distance %g): %zu rays of %zu entries (%zu coarse), %zu traced "
        "(exposed faces), "
        "%zu hit the crate; %zu differ from the GPU full re-trace, %zu from the CPU traceScene\n",
        lodDistance, rays, cd.updateList().size(), coarse, traced, dynamicHits, gpuMismatch,
        cpuMismatch);
    EXPECT_GT(dynamicHits, lodDistance > 0.0f ? 20u : 100u);
    if (lodDistance > 0.0f) EXPECT_GT(coarse, 100u);
    EXPECT_EQ(gpuMismatch, 0u);
    EXPECT_EQ(cpuMismatch, 0u);
}

TEST_F(IrradianceCache, DivideAndWinSelectsTheSameHitAsAFullRetrace) {
    expectDivideAndWinExact(0.0f);
    expectDivideAndWinExact(1.0f);
}

// Dynamic entries keep their static hits per phase too: after K / S updates they trace only the
// dynamic grid, and still select what a full re-trace selects — also on faces the crate covered
// when their phase was traced and has uncovered since.
TEST_F(IrradianceCache, DynamicEntriesReuseTheirStaticHitsExactly) {
    std::size_t reused = 0;
    expectDivideAndWinExact(0.0f, 12, 1.2, &reused);
    std::printf("dynamic entries that read cached static hits in the last frame: %zu\n", reused);
    EXPECT_GT(reused, 100u);
}

namespace {

// A world cut in two by a full-height one-voxel wall at x = 32, open to the sky on both sides;
// a crate (a dynamic object) on the west side is either pressed against the wall or far away.
Scene splitWorld(bool crateAtWall) {
    Scene scene = makeScene({64, 32, 64});
    fillBox(scene.grid, Box{{0, 0, 0}, {64, 4, 64}}, kWhite);
    fillBox(scene.grid, Box{{32, 4, 0}, {33, 32, 64}}, kWhite);
    fillBox(scene.grid, Box{{44, 4, 20}, {50, 12, 40}}, kRed);  // something to look at in the east
    scene.sky.sunDirection = glm::normalize(glm::vec3(0.3f, 1.0f, 0.4f));
    DynamicObject crate;
    crate.name = "crate";
    crate.modelSize = {8, 8, 8};
    BrickGrid crateModel({8, 8, 8});
    fillBox(crateModel, Box{{0, 0, 0}, {8, 8, 8}}, kGreen);
    crate.model = std::make_shared<const BrickGrid>(std::move(crateModel));
    ObjectKey key;
    key.position = crateAtWall ? glm::dvec3(28.0, 8.0, 32.0)
                               : glm::dvec3(6.0, 8.0, 8.0);  // x 24..31: touching the wall
    crate.path = ObjectPath({key}, false);
    scene.objects.push_back(std::move(crate));
    scene.cameras.push_back(
        CameraPreset{"east", {60.0f, 20.0f, 32.0f}, {34.0f, 6.0f, 32.0f}, 80.0f});
    scene.cameras.push_back(
        CameraPreset{"west", {2.0f, 20.0f, 32.0f}, {31.0f, 6.0f, 32.0f}, 80.0f});
    scene.grid.clearDirty();
    return scene;
}

}  // namespace

// No leaks from dynamic onto static: with the crate pressed against the west face of the wall,
// every static entry east of the wall holds bit for bit what it holds with the crate far away —
// while entries on the west side, which see the crate, do change.
TEST_F(IrradianceCache, ObjectAgainstAWallDoesNotChangeTheFarSide) {
    auto run = [](bool crateAtWall) {
        Scene scene = splitWorld(crateAtWall);
        Renderer r(gpu_testing::context());
        // Without a ray budget every visible entry updates every frame, so both runs update the
        // same entries: a budget would schedule them around the crate (a difference in when,
        // not a leak).
        LightingSettings l = cacheLighting(1);
        l.cache.rayBudget = 0;
        // The east view first, so east entries get the same slots (and random numbers) in both
        // runs.
        for (std::uint32_t i = 0; i < 16; ++i)
            r.render(scene, scene.camera(i % 2 ? "west" : "east"), frameAt(48, 0.0), l);
        std::vector<std::uint32_t> filtered = readUints(r.irradianceCache().filtered());
        std::map<std::uint64_t, glm::uvec4> byKey;  // static face values by (voxel, face)
        const auto& dir = r.irradianceCache().directory();
        for (std::uint32_t slot = 0; slot < dir.usedSlots(); ++slot) {
            const shared::CacheEntry& e = dir.entry(slot);
            if (e.voxel.w != int(shared::CACHE_SET_STATIC) ||
                dir.slotOf({glm::ivec3(e.voxel), 0}) != slot)
                continue;
            for (std::uint32_t f = 0; f < 6; ++f) {
                const std::uint32_t* v = &filtered[(slot * 6 + f) * 4];
                byKey[engine::render::packCacheKey({glm::ivec3(e.voxel), 0}) * 8 + f] = {
                    v[0], v[1], v[2], v[3]};
            }
        }
        return std::make_pair(byKey, r.irradianceCache().stats());
    };
    auto [far, farStats] = run(false);
    auto [near, nearStats] = run(true);
    std::size_t east = 0, eastChanged = 0, west = 0, westChanged = 0;
    for (const auto& [key, value] : near) {
        auto it = far.find(key);
        if (it == far.end()) continue;
        const int x = int((key / 8) & 0xFFFF);
        bool changed = it->second != value;
        if (x > 32) {
            ++east;
            eastChanged += changed;
        } else if (x < 32) {
            ++west;
            westChanged += changed;
        }
    }
    std::printf(
        "crate against the wall: east of it %zu static faces, %zu changed; west %zu, %zu changed\n",
        east, eastChanged, west, westChanged);
    EXPECT_GT(east, 1000u);
    EXPECT_EQ(eastChanged, 0u);
    EXPECT_GT(westChanged, 100u);
}

// Stability: a still camera watches an object cross the courtyard. The indirect term on static
// surfaces away from the object changes little from frame to frame; after the object has gone,
// its dynamic entries fade out within the cool-down.
TEST_F(IrradianceCache, StableAwayFromAMovingObjectAndFadesAfterItLeaves) {
    Scene scene = courtyard();
    DynamicObject ball;
    ball.name = "ball";
    ball.modelSize = {6, 6, 6};
    BrickGrid ballModel({8, 8, 8});
    fillBox(ballModel, Box{{0, 0, 0}, {6, 6, 6}}, kRed);
    ball.model = std::make_shared<const BrickGrid>(std::move(ballModel));
    ObjectKey k0, k1, k2, k3;
    k0.time = 0.0;
    k0.position = {14.0, 8.0, 20.0};
    k1.time = 1.0;
    k1.position = {40.0, 8.0, 20.0};
    k2.time = 1.01;  // then it is gone: far outside the world
    k2.position = {40.0, 300.0, 20.0};
    k3.time = 10.0;
    k3.position = {40.0, 300.0, 20.0};
    ball.path = ObjectPath({k0, k1, k2, k3}, false);
    scene.objects.push_back(std::move(ball));

    Renderer r(gpu_testing::context());
    const double dt = 1.0 / 60.0;
    std::vector<glm::vec4> prev;
    double changeSum = 0.0, meanSum = 0.0;
    int measured = 0;
    for (std::uint32_t i = 0; i <= 60; ++i) {  // one second with the object moving
        r.render(scene, scene.camera(), frameAt(48, i * dt), cacheLighting(1));
        if (i < 40) continue;  // let the static entries converge first
        auto images = r.readback();
        if (!prev.empty()) {
            for (std::size_t p = 0; p < images.indirect.size(); ++p) {
                const auto& g = images.gbuffer[p];
                if (g.voxel.w >= 6 || (g.data.w & shared::GBUFFER_FLAG_DYNAMIC)) continue;
                // Away from the object: more than 8 voxels from its box this frame.
                glm::dvec3 c = scene.objects[0].current.position;
                if (glm::length(glm::dvec3(glm::vec3(g.position)) - c) < 8.0 + 5.2) continue;
                changeSum += std::abs(images.indirect[p].x - prev[p].x) +
                             std::abs(images.indirect[p].y - prev[p].y) +
                             std::abs(images.indirect[p].z - prev[p].z);
                meanSum += images.indirect[p].x + images.indirect[p].y + images.indirect[p].z;
                ++measured;
            }
        }
        prev = images.indirect;
    }
    const double relativeChange = changeSum / meanSum;
    std::printf(
        "stability: mean |frame - previous| of the static indirect away from the object = %.2f %% "
        "of its mean\n",
        100.0 * relativeChange);
    EXPECT_GT(measured, 1000);
    EXPECT_LT(relativeChange, 0.03);

    // The object has left (t > 1.01 s): count frames until its dynamic entries are released.
    auto dynamicEntries = [&] {
        const auto& dir = r.irradianceCache().directory();
        std::uint32_t n = 0;
        for (std::uint32_t s = 0; s < dir.usedSlots(); ++s)
            n += dir.entry(s).voxel.w == int(shared::CACHE_SET_DYNAMIC) &&
                 dir.slotOf({glm::ivec3(dir.entry(s).voxel), 1}) == s;
        return n;
    };
    std::uint32_t frames = 0;
    std::uint32_t before = 0;
    for (std::uint32_t i = 61; i < 120; ++i) {
        r.render(scene, scene.camera(), frameAt(48, i * dt), cacheLighting(1));
        if (i == 61) before = dynamicEntries();
        if (dynamicEntries() == 0) break;
        ++frames;
    }
    std::printf(
        "fade: %u dynamic entries when the object left; all released %u frames later (cool-down "
        "0.3 s = 18 frames)\n",
        before, frames);
    EXPECT_GT(before, 0u);
    EXPECT_GE(frames, 16u);
    EXPECT_LE(frames, 20u);
}

// ---- Direct light at a subset of the bounce's hits ---------------------------------------------

// A closed room lit by a lamp and by the sun through a hole in its roof, with a red wall and a
// pillar that casts shadows: nearly all of its indirect light is direct light at the cache's
// hits (little sky), so an error in how the bounce samples that light shows in full.
Scene litRoom() {
    Scene scene = makeScene({40, 40, 40});
    fillBox(scene.grid, Box{{0, 0, 0}, {40, 40, 40}}, kWhite);
    fillBox(scene.grid, Box{{2, 2, 2}, {38, 38, 38}}, 0);
    fillBox(scene.grid, Box{{24, 38, 12}, {32, 40, 20}}, 0);  // the roof's hole
    fillBox(scene.grid, Box{{2, 2, 2}, {4, 38, 38}}, kRed);
    fillBox(scene.grid, Box{{16, 2, 20}, {22, 24, 26}}, kWhite);
    fillBox(scene.grid, Box{{8, 30, 28}, {12, 32, 32}}, kLamp);
    scene.sky.sunDirection = glm::normalize(glm::vec3(-0.5f, 1.0f, -0.6f));
    scene.cameras.push_back(
        CameraPreset{"inside", {34.0f, 20.0f, 34.0f}, {8.0f, 6.0f, 8.0f}, 80.0f});
    scene.grid.clearDirty();
    return scene;
}

// The bounce samples the direct light (sun and one emitter, each with a shadow ray) at only
// `light_samples` of each face update's lit hits, stratified and weighted by lit / samples, so the
// estimate's expectation is the same as sampling every hit: at convergence the cache with 4
// samples must match the one with every hit in the mean, and differ per pixel by little more
// than the extra noise. (Without the weight the mean is 66 % low.)
TEST_F(IrradianceCache, SampledBounceLightMatchesEveryHitAtConvergence) {
    Scene scene = litRoom();
    const std::uint32_t size = 48;
    LightingSettings every = cacheLighting(1), sampled = cacheLighting(1);
    every.cache.lightSamples = 0;
    sampled.cache.lightSamples = 4;
    std::vector<glm::vec4> all = cacheIndirect(scene, every, size, 96);
    std::vector<glm::vec4> four = cacheIndirect(scene, sampled, size, 96);
    const double ratio = meanOf(four) / meanOf(all), err = mae(four, all) / meanOf(all);
    std::printf(
        "bounce light at 4 hits of 16 against every hit, lit room, 96 frames at %ux%u: mean %.5f "
        "vs %.5f, ratio %.4f, "
        "MAE %.4f of the mean\n",
        size, size, meanOf(four), meanOf(all), ratio, err);
    ASSERT_GT(meanOf(all), 0.01);
    EXPECT_NEAR(ratio, 1.0, 0.02);  // measured 1.004
    EXPECT_LT(err, 0.10);  // measured 0.063: the noise of 4 light samples instead of up to 16
}

// ---- Structured bias of the direction sets -----------------------------------------------------

// Each entry's K directions are its own (a seeded rotation per (voxel, set) and lighting seed), so
// the error an entry's finite direction set leaves is independent of its neighbours' and of
// another seed's: averaging two seeds' converged caches halves its variance. With one direction
// set shared by every voxel (the old cache), a second seed changed only the sampling of the light
// at the hits, and the average was no better than either — the error was bias, in streaks.
TEST_F(IrradianceCache, DirectionErrorAveragesOutAcrossSeeds) {
    Scene scene = courtyard();
    const std::uint32_t size = 48;
    const int frames = 48;
    const engine::world::CameraPreset camera = scene.camera();
    std::vector<glm::vec4> ref = referenceIndirectAt(scene, camera, size, 1, 1024, 0.0, 1);
    std::vector<glm::vec4> one = cacheIndirectSeeded(scene, camera, size, frames, 32, 1);
    std::vector<glm::vec4> two = cacheIndirectSeeded(scene, camera, size, frames, 32, 2);
    IndirectError e1 = indirectError(one, ref, size, size),
                  e2 = indirectError(two, ref, size, size);
    IndirectError eAvg = indirectError(average(one, two), ref, size, size);
    std::printf(
        "seeds, K = 32, %d frames at %ux%u vs 1024 spp: relative MAE seed 1 %.4f, seed 2 %.4f, "
        "their average %.4f "
        "(%.2fx); MAE/mean %.4f %.4f -> %.4f; mean ratio %.4f %.4f\n",
        frames, size, size, e1.rmae, e2.rmae, eAvg.rmae, eAvg.rmae / (0.5 * (e1.rmae + e2.rmae)),
        e1.relativeMae, e2.relativeMae, eAvg.relativeMae, e1.meanRatio, e2.meanRatio);
    EXPECT_LT(
        eAvg.rmae,
        0.85 * 0.5 * (e1.rmae + e2.rmae));  // shared set: 0.0283 for both and their average (1.00x)
    EXPECT_LT(e1.rmae,
              0.022);  // one seed, the filter averaging independent neighbours (shared set: 0.0283)
    EXPECT_NEAR(e1.meanRatio, 1.0, 0.05);
}

// The direction sets stay cosine-distributed (E[cos theta] = 2/3, no tilt, unit length, z > 0)
// and differ per entry: neighbours, and one voxel under two seeds, get different sets, while the
// same key and seed always get the same one.
TEST_F(IrradianceCache, DirectionSetsAreCosineDistributedAndDifferPerEntry) {
    Scene scene = courtyard();
    Renderer r(gpu_testing::context());
    r.render(scene, scene.camera(), frame(16), cacheLighting(1));
    const auto& cache = r.irradianceCache();
    const std::uint32_t K =
        static_cast<std::uint32_t>(cache.directions().size() / shared::CACHE_DIRECTION_SETS);
    ASSERT_EQ(K, 128u);
    double worstTilt = 0.0, worstCos = 0.0;
    glm::dvec3 all(0.0);
    for (std::uint32_t set = 0; set < shared::CACHE_DIRECTION_SETS; ++set) {
        glm::dvec3 sum(0.0);
        for (std::uint32_t k = 0; k < K; ++k) {
            glm::vec3 d(cache.directions()[set * K + k]);
            EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
            EXPECT_GE(d.z, 0.0f);
            sum += glm::dvec3(d);
        }
        all += sum;
        sum /= double(K);
        worstTilt = std::max(worstTilt, glm::length(glm::dvec2(sum)));
        worstCos = std::max(worstCos, std::abs(sum.z - 2.0 / 3.0));
    }
    all /= double(K * shared::CACHE_DIRECTION_SETS);
    std::printf(
        "direction sets: %u of %u; worst |mean (x, y)| %.4f, worst |mean cos - 2/3| %.4f; over all "
        "sets %.4f and %.4f\n",
        shared::CACHE_DIRECTION_SETS, K, worstTilt, worstCos, glm::length(glm::dvec2(all)),
        std::abs(all.z - 2.0 / 3.0));
    // Independent cosine samples would give about 0.06 and 0.02 per set; stratified sets do better.
    EXPECT_LT(worstTilt, 0.05);
    EXPECT_LT(worstCos, 0.01);
    EXPECT_LT(glm::length(glm::dvec2(all)), 0.01);
    EXPECT_LT(std::abs(all.z - 2.0 / 3.0), 0.002);
    using engine::render::IrradianceCache;
    const glm::ivec3 v{20, 4, 20};
    EXPECT_EQ(IrradianceCache::directionRotation(v, 0, 1),
              IrradianceCache::directionRotation(v, 0, 1));
    EXPECT_NE(IrradianceCache::directionRotation(v, 0, 1),
              IrradianceCache::directionRotation(v, 0, 2));
    EXPECT_NE(IrradianceCache::directionRotation(v, 0, 1),
              IrradianceCache::directionRotation(v, 1, 1));
    EXPECT_NE(cache.rayDirection(v, 0, 3, 0), cache.rayDirection(v + glm::ivec3(1, 0, 0), 0, 3, 0));
}

// Not a test: the per-scene figures of docs/IRRADIANCE_CACHE.md — the converged cache's indirect
// term (one bounce) against the path tracer's (one bounce minus direct, two seeds averaged), on
// the thesis scenes and thin_wall. Run with --gtest_also_run_disabled_tests; VOX_MEASURE_SIZE,
// _FRAMES, _SPP (per reference seed), _K, _WORLD (one world), _MAX_RAY (the cache's ray length),
// _LOD, _LIGHT_SAMPLES, _BUDGET, _NEIGHBOURHOOD (cache knobs) and _CACHE (a folder keeping the
// references) change it.
TEST_F(IrradianceCache, DISABLED_MeasureScenes) {
    const std::uint32_t size = envOr("VOX_MEASURE_SIZE", 64),
                        frames = envOr("VOX_MEASURE_FRAMES", 64);
    const std::uint32_t spp = envOr("VOX_MEASURE_SPP", 1024), k = envOr("VOX_MEASURE_K", 128);
    const float maxRay = float(envOr("VOX_MEASURE_MAX_RAY", 0));
    const float lod = float(envOr("VOX_MEASURE_LOD", 0));  // the cache's lod_distance
    std::vector<std::string> worlds{"cornell", "mountain", "letters", "apartments", "thin_wall"};
    if (const char* w = std::getenv("VOX_MEASURE_WORLD")) worlds = {w};
    for (const std::string& name : worlds) {
        Scene scene = loadWorld(name);
        const engine::world::CameraPreset camera = scene.camera();
        // References are kept in VOX_MEASURE_CACHE (a folder) when set: the same for every run.
        auto reference = [&](std::uint32_t seed) {
            const char* dir = std::getenv("VOX_MEASURE_CACHE");
            const std::string file = dir ? std::string(dir) + "/" + name + "_" +
                                               std::to_string(size) + "_" + std::to_string(spp) +
                                               "_" + std::to_string(seed) + ".bin"
                                         : std::string();
            std::vector<glm::vec4> img(std::size_t(size) * size);
            if (!file.empty()) {
                if (std::FILE* f = std::fopen(file.c_str(), "rb")) {
                    const bool ok =
                        std::fread(img.data(), sizeof(glm::vec4), img.size(), f) == img.size();
                    std::fclose(f);
                    if (ok) return img;
                }
            }
            img = referenceIndirectAt(scene, camera, size, 1, spp, 0.0, seed);
            if (!file.empty()) {
                if (std::FILE* f = std::fopen(file.c_str(), "wb")) {
                    std::fwrite(img.data(), sizeof(glm::vec4), img.size(), f);
                    std::fclose(f);
                }
            }
            return img;
        };
        std::vector<glm::vec4> r1 = reference(1), r2 = reference(2);
        std::vector<glm::vec4> ref = average(r1, r2);
        // The reference's own noise: seed 2 against seed 1, halved for the average of both (1/sqrt
        // 2 per seed, 1/sqrt 2 again for the average).
        IndirectError noise = indirectError(r2, r1, size, size);
        std::vector<glm::vec4> c1 =
            cacheIndirectSeeded(scene, camera, size, int(frames), k, 1, maxRay, lod);
        std::vector<glm::vec4> c2 =
            cacheIndirectSeeded(scene, camera, size, int(frames), k, 2, maxRay, lod);
        IndirectError e1 = indirectError(c1, ref, size, size),
                      e2 = indirectError(c2, ref, size, size);
        IndirectError ea = indirectError(average(c1, c2), ref, size, size);
        // With the mean's error taken out: what is left is the per-pixel structure.
        std::vector<glm::vec4> scaled = c1;
        for (glm::vec4& p : scaled) p *= float(1.0 / e1.meanRatio);
        IndirectError es = indirectError(scaled, ref, size, size);
        if (const char* dir = std::getenv("VOX_MEASURE_DUMP")) {
            const float scale = float(4.0 * meanOf(ref));
            auto png = [&](const std::vector<glm::vec4>& img, const char* what) {
                std::vector<std::uint32_t> rgba(img.size());
                for (std::size_t i = 0; i < img.size(); ++i) {
                    glm::uvec3 c(glm::clamp(glm::vec3(img[i]) / scale, 0.0f, 1.0f) * 255.0f);
                    rgba[i] = c.x | (c.y << 8) | (c.z << 16) | 0xFF000000u;
                }
                (void)engine::io::writePng(std::string(dir) + "/" + name + "_" + what + ".png",
                                           size, size, rgba);
            };
            png(ref, "reference");
            png(c1, "cache");
            auto raw = [&](const std::vector<glm::vec4>& img,
                           const char* what) {  // for per-region analysis
                if (std::FILE* f = std::fopen(
                        (std::string(dir) + "/" + name + "_" + what + ".bin").c_str(), "wb")) {
                    std::fwrite(img.data(), sizeof(glm::vec4), img.size(), f);
                    std::fclose(f);
                }
            };
            raw(ref, "reference");
            raw(c1, "cache");
        }
        std::printf("MEASURE %s mean-corrected seed1 rmae %.4f mae/mean %.4f\n", name.c_str(),
                    es.rmae, es.relativeMae);
        std::printf("MEASURE lod_distance %g\n", lod);
        std::printf(
            "MEASURE %s K=%u frames=%u size=%u spp=2x%u ref-mean=%.5f | ref noise (seed 2 vs 1) "
            "rmae %.4f mae/mean %.4f | "
            "cache seed1 rmae %.4f mae/mean %.4f mean %.4f | seed2 rmae %.4f mae/mean %.4f mean "
            "%.4f | "
            "avg rmae %.4f mae/mean %.4f\n",
            name.c_str(), k, frames, size, spp, meanOf(ref), noise.rmae, noise.relativeMae, e1.rmae,
            e1.relativeMae, e1.meanRatio, e2.rmae, e2.relativeMae, e2.meanRatio, ea.rmae,
            ea.relativeMae);
        std::fflush(stdout);
    }
}
