// Lighting follows residency (issue 39 item 4): a region streamed into the grid
// (world/grid_streaming.h) is an edit to the renderer, so a lamp in a region that arrives lights
// its neighbourhood in the frame it arrives, and a region that leaves takes its light with it —
// through ReSTIR with ReGIR (direct light) and through the irradiance cache (indirect light),
// compared with the world loaded whole and with the world without that region.
#include <filesystem>
#include <gtest/gtest.h>

#include "gpu/gpu_test_setup.h"
#include "world/grid_streaming.h"
#include "world/region_store.h"
#include "world/store_region_source.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace gpu_testing;
namespace fs = std::filesystem;

namespace {

constexpr MaterialId kWhite = 1, kLamp = 2;
// Two regions side by side: A (x < 128) and B (x >= 128), the lamp in B by the border.
constexpr glm::ivec3 kWorld{256, 32, 64};
constexpr RegionKey kA{0, 0, 0}, kB{1, 0, 0};

Scene emptyWorld() {
    Scene scene =
        paletteScene(kWorld,
                     {Material{"white", glm::vec3(0.75f)},
                      Material{"lamp", glm::vec3(0.8f), glm::vec3(1.0f, 0.85f, 0.6f), 4.0f}},
                     true);
    scene.cameras.push_back(
        CameraPreset{"above", {112.0f, 48.0f, 2.0f}, {118.0f, 2.0f, 32.0f}, 60.0f});
    return scene;
}

Scene wholeWorld() {
    Scene scene = emptyWorld();
    fillBox(scene.grid, Box{{0, 0, 0}, {256, 2, 64}}, kWhite);
    fillBox(scene.grid, Box{{96, 2, 44}, {128, 24, 48}},
            kWhite);  // in A: bounces light to its floor
    fillBox(scene.grid, Box{{132, 8, 30}, {134, 10, 32}}, kLamp);
    scene.grid.clearDirty();
    return scene;
}

// The whole world as a store, as vox import writes it.
fs::path writeStore(const Scene& whole) {
    const fs::path path = fs::path(testing::TempDir()) /
                          ("vox_streaming_lighting_" + std::to_string(::getpid()) + ".db");
    fs::remove(path);
    auto store = RegionStore::openOrCreate(path, kWorld);
    EXPECT_TRUE(store.ok()) << store.error().message;
    StoreCommit c;
    for (RegionKey k : {kA, kB}) c.put.push_back(encodeRegion(snapshotRegion(whole.grid, k)));
    EXPECT_TRUE(store->commit(c).ok());
    return path;
}

std::unique_ptr<GridStreaming> streamFrom(const fs::path& store) {
    auto source = StoreRegionSource::open(store, 3);
    EXPECT_TRUE(source.ok()) << source.error().message;
    // Radius 20: only the region the eye is in, and B once the eye is within 20 voxels of it.
    return std::make_unique<GridStreaming>(std::make_unique<StoreRegionSource>(std::move(*source)),
                                           ResidencySettings{20.0f, std::uint64_t(1) << 30}, 4);
}

// The streaming of one frame with the loader drained first, so what was asked for arrives now.
GridStreamingReport streamNow(GridStreaming& s, glm::vec3 eye, Scene& scene) {
    s.update(eye, scene.grid);  // asks
    s.residency().waitIdle();
    return s.update(eye, scene.grid);  // takes in
}

const glm::vec3 kEyeInA{10.0f, 16.0f, 32.0f}, kEyeByB{120.0f, 16.0f, 32.0f};

// Floor pixels of region A within 28 voxels of the lamp: their count, how many are lit, and the
// mean luminance of `image` over them.
struct FloorLight {
    int pixels = 0, lit = 0;
    double mean = 0.0;
};
FloorLight floorNearLamp(const FrameImages& img, const std::vector<glm::vec4>& image) {
    FloorLight f;
    for (std::size_t i = 0; i < img.gbuffer.size(); ++i) {
        const shared::GBufferTexel& g = img.gbuffer[i];
        if (std::uint32_t(g.voxel.w) != shared::FACE_POS_Y || g.position.y > 2.5f ||
            g.position.x < 104.0f || g.position.x > 127.5f)
            continue;
        ++f.pixels;
        const double l = luminance(image[i]);
        f.lit += l > 0.0;
        f.mean += l;
    }
    if (f.pixels) f.mean /= f.pixels;
    return f;
}

}  // namespace

TEST(StreamingLighting, ALampArrivingLightsInItsFrameAndLeavingTakesItsLight) {
    Scene whole = wholeWorld();
    const fs::path store = writeStore(whole);
    Scene scene = emptyWorld();
    auto s = streamFrom(store);
    Renderer r(context());
    LightingSettings l;  // ReSTIR with temporal and spatial reuse, candidates from ReGIR
    l.regir.enabled = 1;
    l.regir.cellSize = 8.0f;

    streamNow(*s, kEyeInA, scene);
    ASSERT_TRUE(s->inGrid(kA));
    ASSERT_FALSE(s->inGrid(kB));
    FrameImages img;
    for (int f = 0; f < 4; ++f) {
        r.render(scene, scene.camera(), frame(64), l);
        s->update(kEyeInA, scene.grid);
    }
    img = r.readback();
    const FloorLight before = floorNearLamp(img, img.radiance);
    ASSERT_GT(before.pixels, 200);
    EXPECT_EQ(before.lit, 0) << "no lamp yet";
    EXPECT_EQ(r.emitters().aliveCount(), 0u);

    // B arrives: its lamp lights A's floor in this very frame, as in the world loaded whole.
    const GridStreamingReport in = streamNow(*s, kEyeByB, scene);
    EXPECT_EQ(in.arrived, 1u);
    ASSERT_TRUE(s->inGrid(kB));
    EXPECT_TRUE(scene.grid == whole.grid);
    r.render(scene, scene.camera(), frame(64), l);
    img = r.readback();
    const FloorLight arrived = floorNearLamp(img, img.radiance);
    Renderer wr(context());
    FrameImages wimg = renderFrames(wr, whole, l, frame(64), 1);
    const FloorLight loadedWhole = floorNearLamp(wimg, wimg.radiance);
    std::printf(
        "A's floor by the lamp: lit %d of %d pixels (mean %.4f) the frame B arrived; %d of "
        "%d (mean %.4f) the first frame of the world loaded whole\n",
        arrived.lit, arrived.pixels, arrived.mean, loadedWhole.lit, loadedWhole.pixels,
        loadedWhole.mean);
    EXPECT_GT(r.emitters().aliveCount(), 0u);
    EXPECT_EQ(r.emitters().aliveCount(), wr.emitters().aliveCount());
    EXPECT_GT(arrived.lit, arrived.pixels * 3 / 4);
    EXPECT_GT(arrived.mean, 0.5 * loadedWhole.mean);
    EXPECT_LT(arrived.mean, 2.0 * loadedWhole.mean);

    // B leaves: no light left behind in the very next frame, as in the world without B.
    s->residency().evict(kB);
    const GridStreamingReport out = s->update(kEyeInA, scene.grid);
    EXPECT_EQ(out.left, 1u);
    r.render(scene, scene.camera(), frame(64), l);
    img = r.readback();
    const FloorLight left = floorNearLamp(img, img.radiance);
    std::printf("A's floor by the lamp: lit %d of %d pixels the frame after B left\n", left.lit,
                left.pixels);
    EXPECT_EQ(r.emitters().aliveCount(), 0u);
    EXPECT_EQ(left.lit, 0);
    fs::remove(store);
}

// The irradiance cache sees a region arriving and leaving as an edit: its indirect light on A's
// floor after B arrives matches the world loaded whole after as many frames, and after B leaves
// it fades to under 5 % within 24 frames (the cache blends over frames: the bound in
// irradiance_cache_test.cpp), no slower than when the same change is made by an edit.
TEST(StreamingLighting, TheIrradianceCacheFollowsRegionsInAndOut) {
    Scene whole = wholeWorld();
    const fs::path store = writeStore(whole);
    Scene scene = emptyWorld();
    auto s = streamFrom(store);
    Renderer r(context());
    LightingSettings l;
    l.method = Method::Preview;  // only the cache's indirect term is compared
    l.indirect = engine::lighting::Indirect::Cache;
    l.cache.bounces = 1;
    l.cache.rayBudget = 50000;
    constexpr int kFrames = 24;

    streamNow(*s, kEyeInA, scene);
    FrameImages img = renderFrames(r, scene, l, frame(48), 4);
    EXPECT_EQ(floorNearLamp(img, img.indirect).lit, 0);

    streamNow(*s, kEyeByB, scene);
    ASSERT_TRUE(s->inGrid(kB));
    img = renderFrames(r, scene, l, frame(48), kFrames);
    const FloorLight arrived = floorNearLamp(img, img.indirect);
    Renderer wr(context());
    FrameImages wimg = renderFrames(wr, whole, l, frame(48), kFrames);
    const FloorLight loadedWhole = floorNearLamp(wimg, wimg.indirect);
    std::printf(
        "cache: A's floor indirect mean %.5f %d frames after B arrived, %.5f after as "
        "many frames of the world loaded whole\n",
        arrived.mean, kFrames, loadedWhole.mean);
    ASSERT_GT(loadedWhole.mean, 0.0);
    EXPECT_GT(arrived.mean, 0.7 * loadedWhole.mean);
    EXPECT_LT(arrived.mean, 1.3 * loadedWhole.mean);

    s->residency().evict(kB);
    EXPECT_EQ(s->update(kEyeInA, scene.grid).left, 1u);
    img = renderFrames(r, scene, l, frame(48), 1);
    const double firstFrame = floorNearLamp(img, img.indirect).mean;
    img = renderFrames(r, scene, l, frame(48), kFrames - 1);
    const FloorLight left = floorNearLamp(img, img.indirect);
    // The same change as an edit of the world loaded whole (B's voxels removed): what the cache
    // does for an edit.
    fillBox(whole.grid, Box{{128, 0, 0}, kWorld}, kEmpty);
    wimg = renderFrames(wr, whole, l, frame(48), kFrames);
    const FloorLight edited = floorNearLamp(wimg, wimg.indirect);
    std::printf(
        "cache: A's floor indirect mean %.5f the frame after B left, %.6f %d frames after; "
        "%.6f %d frames after B's voxels were removed by an edit\n",
        firstFrame, left.mean, kFrames, edited.mean, kFrames);
    EXPECT_LT(left.mean, 0.05 * arrived.mean) << "light left behind by an evicted region";
    EXPECT_TRUE(scene.grid == whole.grid) << "the eviction and the edit left different voxels";
    EXPECT_LE(left.mean, 1.5 * edited.mean + 1e-6) << "slower to fade than the same edit";
    fs::remove(store);
}
