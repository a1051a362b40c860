// After an edit only dirty bricks and cells travel to the GPU, and the result is the same image
// a full re-upload gives.
#include <cstring>
#include <gtest/gtest.h>

#include "gpu/command_list.h"
#include "gpu/gpu_test_setup.h"
#include "gpu/uploader.h"
#include "shared/brick_grid.h"
#include "world/random_worlds.h"

using namespace engine::world;
using namespace gpu_testing;

namespace {

FrameSettings smallFrame() { return frame(96, 72); }

CameraPreset lookingAtWorld(const BrickGrid& grid) {
    CameraPreset c;
    glm::vec3 size(grid.sizeInVoxels());
    c.position = glm::vec3(-0.4f, 1.3f, -0.5f) * size;
    c.target = size * 0.5f;
    c.fovYDegrees = 50.0f;
    return c;
}

void expectSameImages(const FrameImages& a, const FrameImages& b) {
    ASSERT_EQ(a.rgba8.size(), b.rgba8.size());
    int differing = 0;
    for (std::size_t i = 0; i < a.rgba8.size(); ++i) {
        differing += a.rgba8[i] != b.rgba8[i] || a.gbuffer[i].voxel != b.gbuffer[i].voxel ||
                     a.gbuffer[i].data.x != b.gbuffer[i].data.x;
    }
    EXPECT_EQ(differing, 0);
}

}  // namespace

class Upload : public GpuTest {};

TEST_F(Upload, OnlyDirtyBricksAfterAnEditAndSameImageAsFullUpload) {
    BrickGrid grid({64, 48, 64});
    fillBox(grid, Box{{0, 0, 0}, {64, 16, 64}}, 1);     // homogeneous ground
    fillBox(grid, Box{{20, 16, 20}, {37, 30, 41}}, 2);  // a block that needs bricks at its edges
    grid.set({50, 16, 50}, 3);
    Scene scene = gpu_testing::sceneWith(std::move(grid));
    CameraPreset camera = lookingAtWorld(scene.grid);

    Renderer renderer(gpu_testing::context());
    auto first = renderer.render(scene, camera, smallFrame(), kPreview);
    EXPECT_TRUE(first.upload.full);
    EXPECT_EQ(first.upload.bricks, scene.grid.liveBricks());
    FrameImages before = renderer.readback();

    // Three edits: carve a homogeneous ground cell (new brick + cell change), paint a voxel of an
    // existing brick (brick only), add a voxel in empty air (new brick + cell change).
    scene.grid.set({4, 15, 4}, kEmpty);
    scene.grid.set({20, 16, 20}, 4);
    scene.grid.set({60, 40, 8}, 5);
    const std::size_t dirtyBricks = scene.grid.dirtyBricks().size();
    const std::size_t dirtyCells = scene.grid.dirtyCells().size();
    EXPECT_EQ(dirtyBricks, 3u);
    EXPECT_EQ(dirtyCells, 2u);

    auto second = renderer.render(scene, camera, smallFrame(), kPreview);
    EXPECT_FALSE(second.upload.full);
    EXPECT_EQ(second.upload.bricks, dirtyBricks);
    EXPECT_EQ(second.upload.cells, dirtyCells);
    EXPECT_TRUE(scene.grid.dirtyBricks().empty());
    FrameImages incremental = renderer.readback();

    // A fresh renderer uploads everything; its image must be the same.
    Renderer fresh(gpu_testing::context());
    auto full = fresh.render(scene, camera, smallFrame(), kPreview);
    EXPECT_TRUE(full.upload.full);
    expectSameImages(incremental, fresh.readback());

    // The edit did change what the camera sees (the test would be vacuous otherwise).
    int changed = 0;
    for (std::size_t i = 0; i < before.rgba8.size(); ++i)
        changed += before.rgba8[i] != incremental.rgba8[i];
    EXPECT_GT(changed, 0);

    // With nothing edited, nothing but the frame constants is uploaded.
    auto idle = renderer.render(scene, camera, smallFrame(), kPreview);
    EXPECT_EQ(idle.upload.bricks, 0u);
    EXPECT_EQ(idle.upload.cells, 0u);
}

TEST_F(Upload, CollapsingAndReusingBricksStaysConsistent) {
    BrickGrid grid({32, 32, 32});
    fillBox(grid, Box{{0, 0, 0}, {32, 8, 32}}, 1);
    Scene scene = gpu_testing::sceneWith(std::move(grid));
    CameraPreset camera = lookingAtWorld(scene.grid);
    Renderer renderer(gpu_testing::context());
    renderer.render(scene, camera, smallFrame(), kPreview);
    engine::Rng rng(3);
    for (int round = 0; round < 4; ++round) {
        // Carve and refill voxels so bricks split, collapse and get reused from the free list.
        for (int i = 0; i < 40; ++i) {
            glm::ivec3 p{rng.uniformInt(0, 31), rng.uniformInt(0, 12), rng.uniformInt(0, 31)};
            scene.grid.set(p,
                           scene.grid.get(p) == kEmpty ? MaterialId(rng.uniformInt(1, 4)) : kEmpty);
        }
        fillBox(scene.grid, Box{{0, 0, 0}, {16, 8, 16}}, 1);
        renderer.render(scene, camera, smallFrame(), kPreview);
        FrameImages incremental = renderer.readback();
        Renderer fresh(gpu_testing::context());
        fresh.render(scene, camera, smallFrame(), kPreview);
        expectSameImages(incremental, fresh.readback());
    }
}

// The traversal reads brick masks from a copy beside the top grid with room for the brick pages;
// an edit that needs a new page outgrows it, and the next sync builds the grid texels again —
// but uploads only the dirty bricks and is not a new world (streaming grows the pool this way
// every few frames; a whole upload there cleared the lighting's caches, issue 39).
TEST_F(Upload, MoreBrickPagesUploadTheGridTexelsAgain) {
    BrickGrid grid({256, 64, 256});
    fillBox(grid, Box{{0, 0, 0}, {256, 8, 256}}, 1);  // homogeneous ground, no bricks
    grid.set({8, 8, 8}, 2);
    Scene scene = gpu_testing::sceneWith(std::move(grid));
    CameraPreset camera = lookingAtWorld(scene.grid);
    Renderer renderer(gpu_testing::context());
    renderer.render(scene, camera, smallFrame(), kPreview);
    ASSERT_LT(scene.grid.brickCapacity(), shared::BRICK_PAGE_BRICKS);

    // One voxel in each of 32 x 5 x 32 cells: more bricks than one page holds.
    for (int z = 0; z < 256; z += 8) {
        for (int y = 16; y < 56; y += 8) {
            for (int x = 0; x < 256; x += 8)
                scene.grid.set({x + 2, y, z + 3}, MaterialId(1 + (x + z) % 4));
        }
    }
    ASSERT_GT(scene.grid.liveBricks(), shared::BRICK_PAGE_BRICKS);
    const std::size_t dirtyBricks = scene.grid.dirtyBricks().size();
    auto grown = renderer.render(scene, camera, smallFrame(), kPreview);
    EXPECT_FALSE(grown.upload.full);
    EXPECT_EQ(grown.upload.bricks, dirtyBricks);
    EXPECT_LT(grown.upload.bricks, scene.grid.liveBricks());
    FrameImages incremental = renderer.readback();
    Renderer fresh(gpu_testing::context());
    fresh.render(scene, camera, smallFrame(), kPreview);
    expectSameImages(incremental, fresh.readback());
}

// A whole new world is one burst of uploads (gigabytes for a large terrain). Queued whole, the
// host held a second copy of it plus a staging buffer as large: an 8192 x 256 x 8192 terrain
// peaked at 8.1 GB. Sent ahead in chunks, the host copy stays within one chunk, and what arrives
// is the same.
TEST_F(Upload, ALargeBurstIsSentInBoundedChunksAndArrivesWhole) {
    engine::gpu::Context& ctx = gpu_testing::context();
    constexpr std::uint64_t kChunk = 64 << 10;
    constexpr std::uint64_t kBytes = 1 << 20;
    engine::gpu::Uploader uploader(ctx, kChunk);
    engine::gpu::Buffer target(ctx, engine::gpu::BufferKind::Storage, kBytes, "test.target");
    engine::gpu::Buffer readback(ctx, engine::gpu::BufferKind::Readback, kBytes, "test.readback");
    std::vector<std::uint32_t> data(kBytes / 4);
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = std::uint32_t(i * 2654435761u);
    // In pieces of 3 KiB (not a divisor of the chunk), written out of order.
    constexpr std::uint64_t kPiece = 3 << 10;
    for (std::uint64_t at = 0; at < kBytes; at += 2 * kPiece)
        uploader.write(target, at, reinterpret_cast<const std::uint8_t*>(data.data()) + at,
                       std::min(kPiece, kBytes - at));
    for (std::uint64_t at = kPiece; at < kBytes; at += 2 * kPiece)
        uploader.write(target, at, reinterpret_cast<const std::uint8_t*>(data.data()) + at,
                       std::min(kPiece, kBytes - at));
    engine::gpu::CommandList cmd(ctx);
    cmd.begin();
    uploader.record(cmd);
    cmd.copyBuffer(target, readback, {{0, 0, kBytes}});
    cmd.submitAndWait();

    EXPECT_LE(uploader.peakQueuedBytes(), kChunk);
    EXPECT_GE(uploader.chunksSent(), kBytes / kChunk - 1);
    EXPECT_EQ(std::memcmp(readback.mapped(), data.data(), kBytes), 0);
}
