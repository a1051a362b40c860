// The voxel-face irradiance cache against the path tracer's indirect light, and where such caches
// are known to fail: light leaking through thin walls, memory growing with the world, stale rays
// after edits.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu/gpu_test_context.h"
#include "render/renderer.h"
#include "world/world_edits.h"

using namespace engine::world;
using engine::lighting::Indirect;
using engine::lighting::LightingSettings;
using engine::lighting::Method;
using engine::render::FrameSettings;
using engine::render::Renderer;
using gpu_testing::GpuTest;

namespace {

constexpr MaterialId kWhite = 1, kRed = 2, kLamp = 3, kGreen = 4;

Scene makeScene(glm::ivec3 size) {
    Scene scene;
    scene.grid = BrickGrid(size);
    (void)scene.palette.add(Material{"white", glm::vec3(0.75f)});
    (void)scene.palette.add(Material{"red", glm::vec3(0.8f, 0.15f, 0.1f)});
    (void)scene.palette.add(Material{"lamp", glm::vec3(0.8f), glm::vec3(1.0f, 0.85f, 0.6f), 8.0f});
    (void)scene.palette.add(Material{"green", glm::vec3(0.1f, 0.7f, 0.2f)});
    return scene;
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
    scene.cameras.push_back(CameraPreset{"corner", {8.0f, 26.0f, 6.0f}, {46.0f, 6.0f, 44.0f}, 70.0f});
    scene.grid.clearDirty();
    return scene;
}

FrameSettings frame(std::uint32_t size) {
    FrameSettings f;
    f.width = size;
    f.height = size;
    return f;
}

LightingSettings cacheLighting(std::uint32_t bounces = 1) {
    LightingSettings l;
    l.method = Method::Preview;  // the direct term does not matter here: only the cache's own output is compared
    l.indirect = Indirect::Cache;
    l.cache.bounces = bounces;
    return l;
}

std::vector<glm::vec4> cacheIndirect(Scene& scene, const LightingSettings& l, std::uint32_t size, int frames) {
    Renderer r(gpu_testing::context());
    for (int i = 0; i < frames; ++i) r.render(scene, scene.camera(), frame(size), l);
    return r.readback().indirect;
}

// The path tracer's indirect light: (bounces) minus (direct only), both converged.
std::vector<glm::vec4> referenceIndirect(Scene& scene, std::uint32_t size, std::uint32_t bounces, std::uint32_t spp) {
    auto run = [&](std::uint32_t b) {
        Renderer r(gpu_testing::context());
        LightingSettings l;
        l.method = Method::Reference;
        l.bounces = b;
        l.samplesPerFrame = 32;
        for (std::uint32_t i = 0; i < spp / 32; ++i) r.render(scene, scene.camera(), frame(size), l);
        return r.readback().radiance;
    };
    std::vector<glm::vec4> with = run(bounces), without = run(0);
    for (std::size_t i = 0; i < with.size(); ++i) with[i] -= without[i];
    return with;
}

double meanOf(const std::vector<glm::vec4>& img) {
    double sum = 0.0;
    for (const glm::vec4& p : img) sum += (p.x + p.y + p.z) / 3.0;
    return sum / double(img.size());
}

double mae(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        sum += std::abs(a[i].x - b[i].x) + std::abs(a[i].y - b[i].y) + std::abs(a[i].z - b[i].z);
    return sum / (3.0 * double(a.size()));
}

}  // namespace

class IrradianceCache : public GpuTest {};

// One bounce: the cache's indirect term against the path tracer's, per pixel. The cache is biased
// by design (irradiance at voxel-face centres, filtered and interpolated), so the bound is on the
// relative MAE and on the mean.
TEST_F(IrradianceCache, OneBounceMatchesReference) {
    Scene scene = courtyard();
    const std::uint32_t size = 48;
    std::vector<glm::vec4> ref = referenceIndirect(scene, size, 1, 2048);
    std::vector<glm::vec4> cache = cacheIndirect(scene, cacheLighting(1), size, 64);
    const double refMean = meanOf(ref), cacheMean = meanOf(cache), err = mae(cache, ref);
    std::printf("one bounce: reference indirect mean %.5f, cache %.5f (%.1f %%), MAE %.5f = %.1f %% of the mean\n", refMean,
                cacheMean, 100.0 * (cacheMean / refMean - 1.0), err, 100.0 * err / refMean);
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
    std::printf("multi-bounce: reference mean %.5f; cache 1 bounce %.5f (MAE %.5f), 4 bounces %.5f (MAE %.5f)\n", refMean,
                meanOf(one), mae(one, ref), meanOf(many), mae(many, ref));
    EXPECT_LT(mae(many, ref), 0.8 * mae(one, ref));
    EXPECT_NEAR(meanOf(many) / refMean, 1.0, 0.15);
}

// A sealed, unlit room behind a one-voxel wall, with the sun and a lamp outside: no light may
// reach its inside surfaces through the cache's filter or interpolation.
TEST_F(IrradianceCache, ThinWallDoesNotLeak) {
    Scene scene = makeScene({48, 32, 48});
    fillBox(scene.grid, Box{{0, 0, 0}, {48, 4, 48}}, kWhite);
    // The room: x in [24, 40), z in [8, 40), walls one voxel thick, a roof.
    fillBox(scene.grid, Box{{23, 4, 7}, {41, 20, 41}}, kWhite);
    fillBox(scene.grid, Box{{24, 4, 8}, {40, 19, 40}}, 0);
    fillBox(scene.grid, Box{{12, 10, 20}, {14, 12, 22}}, kLamp);
    // Look into the room through the camera placed inside it, and out at the lit side.
    scene.cameras.push_back(CameraPreset{"inside", {38.0f, 16.0f, 24.0f}, {24.0f, 6.0f, 24.0f}, 80.0f});
    scene.cameras.push_back(CameraPreset{"outside", {4.0f, 16.0f, 24.0f}, {23.0f, 6.0f, 24.0f}, 80.0f});
    scene.grid.clearDirty();

    Renderer r(gpu_testing::context());
    LightingSettings l = cacheLighting(1);
    // Both views every frame, so the inside and outside entries are both live and neighbours.
    for (int i = 0; i < 24; ++i) {
        r.render(scene, scene.camera("outside"), frame(48), l);
        r.render(scene, scene.camera("inside"), frame(48), l);
    }
    std::vector<glm::vec4> inside = r.readback().indirect;
    r.render(scene, scene.camera("outside"), frame(48), l);
    std::vector<glm::vec4> outside = r.readback().indirect;
    float insideMax = 0.0f;
    for (const glm::vec4& p : inside) insideMax = std::max({insideMax, p.x, p.y, p.z});
    std::printf("thin wall: indirect outside mean %.4f; inside max %.3g\n", meanOf(outside), insideMax);
    EXPECT_GT(meanOf(outside), 0.02);  // the cache works on the lit side
    EXPECT_EQ(insideMax, 0.0f);        // and nothing crosses the wall
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
    for (int i = 0; i < 12; ++i) fillBox(large.grid, Box{{100 + 12 * i, 4, 120}, {106 + 12 * i, 30, 200}}, kRed);  // out of view
    large.sky = small.sky;
    large.cameras = small.cameras;
    large.grid.clearDirty();
    auto stats = [](Scene& scene) {
        Renderer r(gpu_testing::context());
        engine::render::FrameResult result;
        for (int i = 0; i < 3; ++i) result = r.render(scene, scene.camera(), frame(48), cacheLighting(1));
        return result.cache;
    };
    auto a = stats(small), b = stats(large);
    std::printf("cache: %u entries, %llu bytes (64x40x64 world) vs %u entries, %llu bytes (256x40x256)\n", a.entries,
                static_cast<unsigned long long>(a.bytes), b.entries, static_cast<unsigned long long>(b.bytes));
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
    engine::render::FrameResult first;
    for (int i = 0; i < 4; ++i) first = r.render(scene, scene.camera(), frame(48), l);
    EXPECT_EQ(first.cache.traced, 0u);
    // More than 16 voxels from everything the camera sees: nothing to invalidate.
    scene.grid.set({8, 20, 120}, kWhite);
    auto far = r.render(scene, scene.camera(), frame(48), l).cache;
    EXPECT_EQ(far.invalidated, 0u);
    // In the middle of the courtyard: some entries, not all.
    scene.grid.set({32, 4, 32}, kWhite);
    auto near = r.render(scene, scene.camera(), frame(48), l).cache;
    std::printf("edit: %u of %u live entries re-trace (max ray length 16)\n", near.invalidated, near.entries);
    EXPECT_GT(near.invalidated, 0u);
    EXPECT_LT(near.invalidated, near.entries);
    EXPECT_EQ(near.traced, near.invalidated);
}
